//! Verner's "most efficient" 9(8) pair (J. H. Verner, *Explicit Runge–Kutta pairs with lower
//! stage-order*, Numer. Algorithms 65 (2014) 555–577, and the coefficients on his site): 16
//! stages, the ninth-order solution propagated, the eighth-order one only for the error, and
//! a continuous extension of order 9 from ten more stages:
//!
//! ```text
//! y₁ = y + h Σⱼ bⱼ kⱼ                          (order 9)
//! err = ‖h Σⱼ b̃ⱼ kⱼ / s‖ / √n                   (b̃ = b̂ − b, the order-8 solution's difference)
//! y(t + θh) = y + h Σⱼ bⱼ(θ) kⱼ,  bⱼ(θ) = Σₘ γⱼₘ θᵐ (1 − θ)⁹⁻ᵐ   (order 9, m = 1 … 9)
//! ```
//!
//! Below tolerances of about 1e-8 it reaches a given error in fewer evaluations than DOP853
//! (DifferentialEquations.jl recommends it there; `kinetics bench work-precision` measures it). Of the 26
//! stages a step evaluates 15 new ones; stage 16 (`c = 1`, the weights `bⱼ`) is the
//! derivative at the step's end, the next step's first, and stages 17 … 25 are evaluated only
//! when a sample falls inside the step.
//!
//! - `tableau.rs`: the coefficients

mod tableau;

use super::adaptive::scaled_norm::scaled_norm;
use super::adaptive::{Adaptive, EmbeddedPair};
use super::ode::constant;
use nalgebra::{RealField, SVector};

/// Verner's 9(8) pair, for [`Adaptive`].
#[derive(Debug, Clone, Copy, Default)]
pub struct Verner98;

/// Verner's 9(8) integrator of a system of `N` equations.
pub type Vern9<T, const N: usize> = Adaptive<Verner98, T, N>;

impl EmbeddedPair for Verner98 {
    const ORDER: u32 = 9;
    const STAGES: usize = tableau::STAGES;
    const C: &'static [f64] = &tableau::C;
    const A: &'static [&'static [(usize, f64)]] = &tableau::A;

    /// `‖h Σⱼ b̃ⱼ kⱼ / s‖ / √n`, the root mean square of the scaled estimate, computed
    /// without overflow or underflow.
    fn error_norm<T: RealField + Copy, const N: usize>(
        stages: &[SVector<T, N>],
        _increment: &SVector<T, N>,
        weights: &SVector<T, N>,
        h: T,
    ) -> T {
        let mut error = SVector::<T, N>::zeros();
        for &(j, e) in &tableau::ERROR {
            error += stages[j] * (constant::<T>(e) * h);
        }
        let scaled = error.component_div(weights);
        let sum = scaled.norm_squared();
        if sum > T::zero() && sum.is_finite() {
            // The usual case: squares of numbers near one (rescaling costs N divisions).
            return (sum / constant(N as f64)).sqrt();
        }
        scaled_norm(&scaled) / constant::<T>(N as f64).sqrt()
    }

    /// `Qₘ = h Σⱼ γⱼₘ kⱼ`, m = 1 … 9.
    fn continuous_extension<T: RealField + Copy, const N: usize>(
        stages: &[SVector<T, N>],
        _y_old: &SVector<T, N>,
        _y: &SVector<T, N>,
        h: T,
        coefficients: &mut Vec<SVector<T, N>>,
    ) {
        coefficients.clear();
        coefficients.resize(9, SVector::zeros());
        for (j, row) in &tableau::INTERPOLANT {
            for (coefficient, &gamma) in coefficients.iter_mut().zip(row) {
                *coefficient += stages[*j] * (constant::<T>(gamma) * h);
            }
        }
    }

    /// `y + Σₘ θᵐ (1 − θ)⁹⁻ᵐ Qₘ`: positive weights, so nothing cancels.
    fn interpolate<T: RealField + Copy, const N: usize>(
        coefficients: &[SVector<T, N>],
        y_old: &SVector<T, N>,
        theta: T,
    ) -> SVector<T, N> {
        let complement = T::one() - theta;
        // θᵐ rising from m = 1, (1 − θ)⁹⁻ᵐ falling from the top.
        let mut complement_powers = [T::one(); 9];
        for m in (0..8).rev() {
            complement_powers[m] = complement_powers[m + 1] * complement;
        }
        let mut sum = SVector::<T, N>::zeros();
        let mut theta_power = T::one();
        for (coefficient, complement_power) in coefficients.iter().zip(complement_powers) {
            theta_power *= theta;
            sum += coefficient * (theta_power * complement_power);
        }
        y_old + sum
    }
}
