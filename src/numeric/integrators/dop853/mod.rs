//! Dormand–Prince 8(5,3): the explicit Runge–Kutta pair of order 8 with a continuous
//! extension of order 7, after Hairer's `DOP853` (Hairer, Nørsett & Wanner, *Solving
//! Ordinary Differential Equations I*, 2nd ed., section II.10), for [`Adaptive`].
//!
//! A step of size `h` takes 12 stages and advances `y₁ = y + h Σ bᵢ kᵢ` (order 8). Two
//! embedded estimates, `err₅ = h Σ e⁵ᵢ kᵢ` (order 5) and `err₃ = h Σ (bᵢ − b̂ᵢ) kᵢ`
//! (order 3), are combined as in Hairer's code:
//!
//! ```text
//! sᵢ = atol + rtol · max(|yᵢ|, |y₁ᵢ|)
//! err = |h| Σ(err₅ᵢ/sᵢ)² / sqrt(n (Σ(err₅ᵢ/sᵢ)² + 0.01 Σ(err₃ᵢ/sᵢ)²))
//! ```
//!
//! The derivative at the end of an accepted step is the first stage of the next (FSAL).
//! Dense output: three more stages give a degree-7 polynomial on each accepted step.
//!
//! - `tableau.rs`: the coefficients (nodes, coupling, weights, error and dense-output rows)
//! - `error_estimate.rs`: the combined 5th/3rd-order error estimate
//! - `dense_output.rs`: the continuous extension on the last accepted step

mod dense_output;
mod error_estimate;
mod tableau;

use super::adaptive::{Adaptive, EmbeddedPair};
use nalgebra::{RealField, SVector};

/// The Dormand–Prince 8(5,3) pair, for [`Adaptive`].
#[derive(Debug, Clone, Copy, Default)]
pub struct DormandPrince853;

/// DOP853 integrating a system of `N` equations.
pub type Dop853<T, const N: usize> = Adaptive<DormandPrince853, T, N>;

impl EmbeddedPair for DormandPrince853 {
    const ORDER: u32 = 8;
    const STAGES: usize = tableau::STAGES;
    const C: &'static [f64] = &tableau::C;
    const A: &'static [&'static [(usize, f64)]] = &tableau::A;

    /// err^⅛ as three square roots, much cheaper than a power.
    fn error_root<T: RealField + Copy>(error: T) -> T {
        error.sqrt().sqrt().sqrt()
    }

    fn error_norm<T: RealField + Copy, const N: usize>(
        stages: &[SVector<T, N>],
        increment: &SVector<T, N>,
        weights: &SVector<T, N>,
        h: T,
    ) -> T {
        error_estimate::error_norm(stages, increment, weights, h)
    }

    fn continuous_extension<T: RealField + Copy, const N: usize>(
        stages: &[SVector<T, N>],
        y_old: &SVector<T, N>,
        y: &SVector<T, N>,
        h: T,
        coefficients: &mut Vec<SVector<T, N>>,
    ) {
        dense_output::continuous_extension(stages, y_old, y, h, coefficients);
    }

    fn interpolate<T: RealField + Copy, const N: usize>(
        coefficients: &[SVector<T, N>],
        y_old: &SVector<T, N>,
        theta: T,
    ) -> SVector<T, N> {
        dense_output::interpolate(coefficients, y_old, theta)
    }
}
