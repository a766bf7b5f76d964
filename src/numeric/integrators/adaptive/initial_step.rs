//! The starting step of an adaptive integration: Hairer's `HINIT` (Hairer, Nørsett & Wanner, *Solving Ordinary
//! Differential Equations I*, 2nd ed., section II.4), run in the problem's own time unit `τ`:
//!
//! ```text
//! τ  = d₀/d₁,  d₀ = ‖y₀‖,  d₁ = ‖f₀‖     (1/d₁ if d₀ ≤ 1e-5; t_end − t₀ if not finite, > 0)
//! h₀ = min(0.01 d₀/(d₁τ), (t_end − t₀)/τ)           (1e-6 for the first if d₀ or d₁τ ≤ 1e-5)
//! d₂ = ‖f(t₀ + h₀τ, y₀ + h₀τ f₀) − f₀‖ / (h₀τ)
//! h  = min(100 h₀, (0.01 / max(d₁τ, d₂τ²))^(1/p), (t_end − t₀)/τ) · τ    p the pair's order
//!                                     (max(1e-6, 1e-3 h₀) for the second if max ≤ 1e-15)
//! ```
//!
//! with the weighted norms `‖v‖ = sqrt(Σ(vᵢ/sᵢ)²)`, `sᵢ = atol + rtol |y₀ᵢ|`, each computed
//! without overflow or underflow.

use super::scaled_norm::scaled_norm;
use super::{Adaptive, EmbeddedPair};
use crate::numeric::integrators::ode::{constant, OdeSystem};
use nalgebra::{RealField, SVector};

impl<P: EmbeddedPair, T: RealField + Copy, const N: usize> Adaptive<P, T, N> {
    /// Error-scaled norm `sqrt(Σ(vᵢ/sᵢ)²)` with weights `sᵢ = atol + rtol |yᵢ|`, computed
    /// without overflow or underflow (see [`scaled_norm`]): for a derivative the ratios are
    /// rates, `1/rtol` times the problem's frequency, and for a body spinning at 1e150 rad/s
    /// their squares overflowed (a zero first step).
    fn weighted_norm(&self, v: &SVector<T, N>, y: &SVector<T, N>) -> T {
        scaled_norm(&v.zip_map(y, |vi, yi| {
            vi / (self.settings.atol + self.settings.rtol * yi.abs())
        }))
    }

    /// Hairer's starting step (`HINIT`), measured in the problem's own time unit `τ`.
    ///
    /// `HINIT` compares the weighted norms `d₁ = ‖f₀‖` (per unit time) and
    /// `d₂ ≈ ‖y''‖` (per unit time squared) with absolute constants and falls back to an
    /// absolute `1e-6`, all in the caller's unit of time. For a body spinning at 1e150 rad/s
    /// `d₂` is about 1e311 s⁻², not representable, and the first step was zero (a step-size
    /// underflow at `t = 0`); at 1e-150 rad/s the start was `1e-6` s against a natural step
    /// near 1e149 s, and climbing to it took about two hundred extra steps (577 instead of
    /// 379 for the body of `tests/suite/simulate_extreme_momentum.rs`). Here the same rules run in
    /// the unit `τ`:
    /// * `τ = d₀/d₁`, with `d₀ = ‖y₀‖`: the time in which the initial rate changes the state
    ///   by its own weighted size (Hairer's trial step is `0.01 τ` already);
    /// * `τ = 1/d₁` when the state is below its tolerances (`d₀ ≤ 1e-5`): the time to move by
    ///   one tolerance;
    /// * `τ = t_end − t₀` when nothing moves (`d₁ = 0`) or `τ` is not representable.
    ///
    /// In that unit `d₁τ`, `d₂τ²` and the steps are the same numbers whatever the problem's
    /// time scale (exactly so when it is scaled by a power of two, with `atol = 0`), and for a
    /// problem whose natural unit is the caller's the rules are Hairer's: make the explicit
    /// Euler step's change and the estimated second derivative's contribution small, bounded
    /// by the whole interval.
    pub(super) fn initial_step<S: OdeSystem<T, N> + ?Sized>(&mut self, system: &S) -> T {
        let max_step = self.t_end - self.t();
        let state_norm = self.weighted_norm(self.y(), self.y());
        let derivative_norm = self.weighted_norm(&self.derivative, self.y());
        let tiny = constant::<T>(1e-5);
        let own_unit = if state_norm > tiny {
            state_norm / derivative_norm
        } else {
            derivative_norm.recip()
        };
        let unit = if own_unit.is_finite() && own_unit > T::zero() {
            own_unit
        } else {
            max_step
        };
        // Hairer's HINIT on the quantities in the unit `τ`; steps `h` are in that unit.
        let max_step_in_unit = max_step / unit;
        let derivative_norm = derivative_norm * unit;
        let mut h = if derivative_norm <= tiny || state_norm <= tiny {
            constant(1e-6)
        } else {
            state_norm / derivative_norm * constant(0.01)
        };
        h = h.min(max_step_in_unit);
        let euler = self.y() + self.derivative * (h * unit);
        let derivative_after = system.derivative(self.t() + h * unit, &euler);
        self.statistics.evaluations += 1;
        // ‖Δf‖ / (h τ) is the second derivative per unit time squared; times τ².
        let second = self.weighted_norm(&(derivative_after - self.derivative), self.y()) * unit / h;
        let scale = second.max(derivative_norm);
        let by_second = if scale <= constant(1e-15) {
            (h * constant(1e-3)).max(constant(1e-6))
        } else {
            (constant::<T>(0.01) / scale).powf(constant(1.0 / f64::from(P::ORDER)))
        };
        (h * constant(100.0)).min(by_second).min(max_step_in_unit) * unit
    }
}
