//! Dense output of DOP853: the seventh-order continuous extension on the last accepted step
//! `[t_old, t_old + h]` (Hairer, Nørsett & Wanner, *Solving Ordinary Differential Equations I*,
//! 2nd ed., section II.10; Hairer's `CONTD8`). Three more stages `k₁₃ … k₁₅` give, with
//! `θ = (t − t_old)/h`,
//!
//! ```text
//! y(t) = y_old + θ(F₀ + (1−θ)(F₁ + θ(F₂ + (1−θ)(F₃ + θ(F₄ + (1−θ)(F₅ + θF₆))))))
//! F₀ = y − y_old,  F₁ = h f_old − F₀,  F₂ = 2F₀ − h (f + f_old),  F₃₊ᵣ = h Σⱼ dᵣⱼ kⱼ
//! ```

use super::tableau::{D, D_STAGES, STAGES};
use crate::numeric::integrators::ode::constant;
use nalgebra::{RealField, SVector};

/// The seven vector coefficients `F₀ … F₆` of the interpolant, every stage evaluated.
pub(super) fn continuous_extension<T: RealField + Copy, const N: usize>(
    stages: &[SVector<T, N>],
    y_old: &SVector<T, N>,
    y: &SVector<T, N>,
    h: T,
    coefficients: &mut Vec<SVector<T, N>>,
) {
    let delta = y - y_old;
    let (f_old, f) = (stages[0], stages[STAGES]);
    coefficients.clear();
    coefficients.push(delta);
    coefficients.push(f_old * h - delta);
    coefficients.push(delta * constant::<T>(2.0) - (f + f_old) * h);
    for d in &D {
        let mut sum = SVector::<T, N>::zeros();
        for (&j, &coefficient) in D_STAGES.iter().zip(d) {
            sum += stages[j] * constant::<T>(coefficient);
        }
        coefficients.push(sum * h);
    }
}

/// `y_old + θ(F₀ + (1−θ)(F₁ + θ(F₂ + …)))` at the fraction `θ` of the step.
pub(super) fn interpolate<T: RealField + Copy, const N: usize>(
    coefficients: &[SVector<T, N>],
    y_old: &SVector<T, N>,
    theta: T,
) -> SVector<T, N> {
    let complement = T::one() - theta;
    let mut sum = coefficients[6];
    for (k, coefficient) in coefficients[..6].iter().enumerate().rev() {
        let factor = if k % 2 == 1 { theta } else { complement };
        sum = coefficient + sum * factor;
    }
    y_old + sum * theta
}
