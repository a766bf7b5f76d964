//! Dense output of DOP853: the seventh-order continuous extension on the last accepted step
//! `[t_old, t_old + h]` (Hairer, Nørsett & Wanner, *Solving Ordinary Differential Equations I*,
//! 2nd ed., section II.10; Hairer's `CONTD8`). Three more stages `k₁₃ … k₁₅` give, with
//! `θ = (t − t_old)/h`,
//!
//! ```text
//! y(t) = y_old + θ(F₀ + (1−θ)(F₁ + θ(F₂ + (1−θ)(F₃ + θ(F₄ + (1−θ)(F₅ + θF₆))))))
//! F₀ = y − y_old,  F₁ = h f_old − F₀,  F₂ = 2F₀ − h (f + f_old),  F₃₊ᵣ = h Σⱼ dᵣⱼ kⱼ
//! ```
//!
//! The extra stages are evaluated only when a sample falls inside the step.

use super::tableau::{D, D_STAGES, EXTENDED_STAGES, STAGES};
use super::Dop853;
use crate::numeric::integrators::ode::{constant, OdeSystem};
use nalgebra::{RealField, SVector};

impl<T: RealField + Copy, const N: usize> Dop853<T, N> {
    /// The solution at `t` inside the last accepted step `[t_old, t_now]`, from the
    /// seventh-order continuous extension (times outside are clamped to the step). Before
    /// the first step it is the initial state.
    pub fn dense_output<S: OdeSystem<T, N> + ?Sized>(&mut self, system: &S, t: T) -> SVector<T, N> {
        if t == self.t() || self.statistics.accepted_steps == 0 {
            return *self.y();
        }
        let coefficients = match self.dense {
            Some(coefficients) => coefficients,
            None => {
                let coefficients = self.continuous_extension(system);
                self.dense = Some(coefficients);
                coefficients
            }
        };
        let h = self.last_step;
        let theta = ((t - self.t_old) / h).max(T::zero()).min(T::one());
        let complement = T::one() - theta;
        // y_old + θ(F₀ + (1−θ)(F₁ + θ(F₂ + (1−θ)(F₃ + θ(F₄ + (1−θ)(F₅ + θF₆))))))
        let mut sum = coefficients[6];
        for (k, coefficient) in coefficients[..6].iter().enumerate().rev() {
            let factor = if k % 2 == 1 { theta } else { complement };
            sum = coefficient + sum * factor;
        }
        self.y_old + sum * theta
    }

    /// The three extra stages and the seven vector coefficients of the interpolant.
    fn continuous_extension<S: OdeSystem<T, N> + ?Sized>(
        &mut self,
        system: &S,
    ) -> [SVector<T, N>; 7] {
        let h = self.last_step;
        let (t_old, y_old) = (self.t_old, self.y_old);
        self.evaluate_stages(system, STAGES + 1..EXTENDED_STAGES, t_old, &y_old, h);
        let delta = self.y() - self.y_old;
        let f_old = self.stages[0];
        let mut coefficients = [SVector::<T, N>::zeros(); 7];
        coefficients[0] = delta;
        coefficients[1] = f_old * h - delta;
        coefficients[2] = delta * constant::<T>(2.0) - (self.derivative + f_old) * h;
        for (row, d) in D.iter().enumerate() {
            let mut sum = SVector::<T, N>::zeros();
            for (&j, &coefficient) in D_STAGES.iter().zip(d) {
                sum += self.stages[j] * constant::<T>(coefficient);
            }
            coefficients[3 + row] = sum * h;
        }
        coefficients
    }
}
