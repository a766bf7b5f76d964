//! The fuzzer's seeded pseudo-random numbers: proptest's `TestRng` (XorShift, already a
//! dev-dependency), so a run is repeated exactly by its `--seed`.

use proptest::prelude::Rng;
use proptest::test_runner::{RngAlgorithm, TestRng};

pub struct Random(TestRng);

impl Random {
    /// The stream of `seed` for worker `job` in its `generation` (a worker restarted after a
    /// crash or a hang continues with a new stream, not the input that ended it).
    pub fn new(seed: u64, job: u64, generation: u64) -> Random {
        let mut bytes = [0u8; 16];
        bytes[..8].copy_from_slice(&seed.to_le_bytes());
        bytes[8..].copy_from_slice(&(job << 32 | generation).to_le_bytes());
        // XorShift needs a state that is not all zero.
        bytes[15] |= 0x80;
        Random(TestRng::from_seed(RngAlgorithm::XorShift, &bytes))
    }

    /// A number in `0..n` (`n > 0`).
    pub fn below(&mut self, n: usize) -> usize {
        (self.0.next_u64() % n as u64) as usize
    }

    /// True with probability `1/n`.
    pub fn one_in(&mut self, n: usize) -> bool {
        self.below(n) == 0
    }

    /// One of `items` (not empty).
    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }

    /// A size from 1 to `max`, small sizes far more often than large ones.
    pub fn size(&mut self, max: usize) -> usize {
        let bits = usize::BITS - max.leading_zeros();
        let scale = 1usize << self.below(bits as usize + 1);
        1 + self.below(scale.min(max))
    }
}
