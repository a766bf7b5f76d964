//! The stages of a DOP853 step from `(t, y)` of size `h`:
//!
//! ```text
//! kᵢ = f(t + cᵢh, y + h Σⱼ aᵢⱼ kⱼ)
//! ```
//!
//! with the coefficients of [`tableau`](super::tableau); the point of the row of the weights
//! `bⱼ` is the eighth-order solution `y₁`, whose increment the step adds to `y` with its
//! rounding carried ([`compensated`](crate::numeric::integrators::compensated)).

use super::{Adaptive, EmbeddedPair};
use crate::numeric::integrators::ode::{constant, OdeSystem};
use nalgebra::{RealField, SVector};

impl<P: EmbeddedPair, T: RealField + Copy, const N: usize> Adaptive<P, T, N> {
    /// `h Σⱼ aᵢⱼ kⱼ`, the increment of stage `i` of a step of size `h`.
    pub(super) fn stage_increment(&self, stage: usize, h: T) -> SVector<T, N> {
        let mut sum = SVector::<T, N>::zeros();
        for &(j, a) in P::A[stage] {
            sum += self.stages[j] * constant::<T>(a);
        }
        sum * h
    }

    /// Evaluates the stages `range` of a step of size `h` from `(t, y)`.
    pub(super) fn evaluate_stages<S: OdeSystem<T, N> + ?Sized>(
        &mut self,
        system: &S,
        range: std::ops::Range<usize>,
        t: T,
        y: &SVector<T, N>,
        h: T,
    ) {
        self.statistics.evaluations += range.len();
        for stage in range {
            let point = y + self.stage_increment(stage, h);
            self.stages[stage] = system.derivative(t + constant::<T>(P::C[stage]) * h, &point);
        }
    }
}
