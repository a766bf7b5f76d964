//! Steele, Lea and Flood's splitmix64 (*Fast splittable pseudorandom number generators*,
//! OOPSLA 2014): a 64-bit state advanced by the golden-ratio constant, each output a mix of
//! the state. Deterministic in its seed, so what is drawn with it (a checker's sample points,
//! a figure's label placing) is the same on every run.

/// The generator; its state is the seed until the first draw.
#[derive(Debug, Clone)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1): the top 53 bits over 2⁵³.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in 0 … n − 1 (n > 0; the bias of the remainder is below n/2⁶⁴).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }
}
