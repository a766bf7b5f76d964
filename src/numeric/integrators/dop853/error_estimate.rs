//! The error estimate of a DOP853 step, Hairer's combination of the embedded fifth- and
//! third-order estimates (Hairer, Nørsett & Wanner, *Solving Ordinary Differential
//! Equations I*, 2nd ed., section II.10):
//!
//! ```text
//! aᵢ  = h Σⱼ e⁵ⱼ kⱼᵢ / sᵢ                      fifth order
//! bᵢ  = (y₁ᵢ − yᵢ − h Σⱼ b̂ⱼ kⱼᵢ) / sᵢ          third order, h Σⱼ (bⱼ − b̂ⱼ) kⱼᵢ / sᵢ
//! sᵢ  = atol + rtol · max(|yᵢ|, |y₁ᵢ|)
//! err = Σaᵢ² / sqrt(n (Σaᵢ² + 0.01 Σbᵢ²))      the step is accepted when err ≤ 1
//! ```
//!
//! computed without overflow or underflow.

use super::tableau::{B_HAT_3, E5};
use crate::numeric::integrators::adaptive::scaled_norm::largest_magnitude;
use crate::numeric::integrators::ode::constant;
use nalgebra::{RealField, SVector};

/// Hairer's combined 5th/3rd-order error estimate of a step (≤ 1 means accept), in the
/// form `err = Σaᵢ² / sqrt(n (Σaᵢ² + 0.01 Σbᵢ²))` with `aᵢ = h err₅ᵢ / sᵢ` and
/// `bᵢ = h err₃ᵢ / sᵢ`: the formula of the parent module's doc with `|h|` taken inside
/// the sums (`h > 0`).
///
/// `err₅ᵢ/sᵢ` is a rate (per unit time), `1/h` for a step at its tolerance: for a body
/// spinning at 1e150 rad/s its square overflowed as soon as a trial step missed its
/// tolerance by a factor of about 1e4, and the estimate `inf/inf` cut the step by the
/// largest factor instead of by its error. The `aᵢ, bᵢ` are dimensionless and near 1 for
/// a step near acceptance; `h` multiplies the coefficients (not the sums, which for a slow
/// body's tiny derivatives could fall into subnormals first), and where their squares
/// overflow or vanish the `aᵢ, bᵢ` are divided by the largest before squaring, so no
/// estimate overflows or underflows.
pub(super) fn error_norm<T: RealField + Copy, const N: usize>(
    stages: &[SVector<T, N>],
    increment: &SVector<T, N>,
    weights: &SVector<T, N>,
    h: T,
) -> T {
    let mut err5 = SVector::<T, N>::zeros();
    for &(j, e) in &E5 {
        err5 += stages[j] * (constant::<T>(e) * h);
    }
    let mut err3 = *increment;
    for &(j, b) in &B_HAT_3 {
        err3 -= stages[j] * (constant::<T>(b) * h);
    }
    let (a, b) = (err5.component_div(weights), err3.component_div(weights));
    let (sum5, sum3) = (a.norm_squared(), b.norm_squared());
    if sum5 > T::zero() && sum5.is_finite() && sum3.is_finite() {
        // The usual case: squares of numbers near one. Rescaling them first (below)
        // costs two dozen divisions a step, 18% of an attitude run at rtol 1e-12.
        return sum5 / ((sum5 + sum3 * constant(0.01)) * constant(N as f64)).sqrt();
    }
    let largest = largest_magnitude(a.iter().chain(b.iter()));
    if largest == T::zero() || !largest.is_finite() {
        // A zero estimate is a perfect step; a non-finite one fails.
        return largest;
    }
    let sum5 = a.unscale(largest).norm_squared();
    let sum3 = b.unscale(largest).norm_squared();
    largest * sum5 / ((sum5 + sum3 * constant(0.01)) * constant(N as f64)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::super::tableau::EXTENDED_STAGES;
    use super::*;

    /// The error estimate is homogeneous of degree one in the stages: with the weights fixed
    /// and a zero increment, scaling every stage by `c` scales each `aᵢ, bᵢ`, and so the
    /// estimate, by `c`. With `c = 2^±600` their squares overflow or vanish, so the estimate
    /// must come from the rescaled path, and still be `c` times the plain one (to rounding;
    /// powers of two scale exactly).
    #[test]
    fn error_estimate_survives_squares_that_overflow_or_vanish() {
        let weights = SVector::<f64, 2>::new(1e-9, 0.5e-9);
        let h = 0.25;
        let stages: Vec<SVector<f64, 2>> = (0..EXTENDED_STAGES)
            .map(|j| SVector::<f64, 2>::new(0.3 + 0.01 * j as f64, -0.2 * j as f64))
            .collect();
        let zero = SVector::zeros();
        let plain = error_norm(&stages, &zero, &weights, h);
        assert!(plain.is_finite() && plain > 0.0, "{plain}");
        for c in [2f64.powi(600), 2f64.powi(-600)] {
            let scaled: Vec<SVector<f64, 2>> = stages.iter().map(|stage| stage * c).collect();
            let estimate = error_norm(&scaled, &zero, &weights, h);
            let expected = plain * c;
            assert!(
                ((estimate - expected) / expected).abs() < 1e-14,
                "c = {c:e}: {estimate:e} against {expected:e}"
            );
        }
    }
}
