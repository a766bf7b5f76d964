//! One accepted step of an adaptive pair and the step-size controller (Hairer, Nørsett &
//! Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., sections II.4 and II.10):
//!
//! ```text
//! accept when err ≤ 1;   h_next = h / clamp(err^(1/p) / 0.9, 1/6, 3)     p the pair's order
//! ```
//!
//! after a rejection the next step may not grow, and a rejected step is retried with
//! `h / min(err^(1/p) / 0.9, 3)` (the largest cut for a non-finite estimate). The last step ends
//! exactly at `t_end`; the derivative at the end of an accepted step is the first stage of
//! the next (FSAL).

use super::{Adaptive, EmbeddedPair};
use crate::numeric::error::NumericError;
use crate::numeric::integrators::compensated::Compensated;
use crate::numeric::integrators::ode::{constant, to_f64, OdeSystem};
use nalgebra::RealField;

/// Step-size controller: safety factor and the bounds of the step-size ratio.
const SAFETY: f64 = 0.9;
const MIN_RATIO: f64 = 1.0 / 3.0;
const MAX_RATIO: f64 = 6.0;

/// A run is given up as hopeless, after a hundredth of its budget of steps (and at least
/// a hundred steps, for the step to settle), when the rest of the interval at the step it
/// takes now would need a thousand times the whole budget (a spin of 1e150 rad/s took the
/// full budget, 4 s, to fail).
const HOPELESS_AFTER: usize = 100;
const HOPELESS_MIN_STEPS: usize = 100;
const HOPELESS_FACTOR: f64 = 1000.0;

impl<P: EmbeddedPair, T: RealField + Copy, const N: usize> Adaptive<P, T, N> {
    /// Takes one accepted step, never past the end time; rejected attempts are retried
    /// with a smaller step.
    pub fn step<S: OdeSystem<T, N> + ?Sized>(&mut self, system: &S) -> Result<(), NumericError> {
        if self.t() >= self.t_end {
            return Err(NumericError::InvalidInput {
                what: "step".to_string(),
                reason: format!(
                    "the integration already reached its end {}",
                    to_f64(self.t_end)
                ),
            });
        }
        self.dense.clear();
        self.stages[0] = self.derivative;
        let uround = T::default_epsilon();
        loop {
            let attempts = self.statistics.accepted_steps + self.statistics.rejected_steps;
            if attempts >= self.settings.max_steps {
                return Err(NumericError::StepLimit {
                    max_steps: self.settings.max_steps,
                    t: to_f64(self.t()),
                });
            }
            let resolvable = self.step.abs() * constant(0.1) > self.t().abs() * uround;
            if !resolvable || !self.step.is_finite() {
                return Err(NumericError::StepSizeUnderflow {
                    t: to_f64(self.t()),
                    step: to_f64(self.step),
                });
            }
            let remaining = self.t_end - self.t();
            if attempts >= (self.settings.max_steps / HOPELESS_AFTER).max(HOPELESS_MIN_STEPS)
                && remaining
                    > self.step.abs() * constant(HOPELESS_FACTOR * self.settings.max_steps as f64)
            {
                return Err(NumericError::StepBudgetHopeless {
                    steps: attempts,
                    t: to_f64(self.t()),
                    needed: to_f64(remaining / self.step.abs()),
                });
            }
            let last = self.step * constant(1.01) >= remaining;
            let h = if last { remaining } else { self.step };
            let (t, y) = (self.t(), *self.y());
            self.evaluate_stages(system, 1..P::STAGES, t, &y, h);
            let increment = self.stage_increment(P::STAGES, h);
            let mut y_new = self.y.plus(&increment);
            let weights = y.zip_map(y_new.value(), |y, y_new| {
                self.settings.atol + self.settings.rtol * y.abs().max(y_new.abs())
            });
            let error = P::error_norm(&self.stages, &increment, &weights, h);
            let error_root = P::error_root(error);
            if error <= T::one() {
                let ratio = (error_root / constant(SAFETY))
                    .max(constant(1.0 / MAX_RATIO))
                    .min(constant(1.0 / MIN_RATIO));
                let mut next = h / ratio;
                if self.last_rejected {
                    next = next.min(h);
                }
                y_new.map_value(|y| system.project(y));
                let t_new = if last {
                    Compensated::new(self.t_end)
                } else {
                    self.t.plus(h)
                };
                let derivative = system.derivative(t_new.value(), y_new.value());
                self.statistics.evaluations += 1;
                self.statistics.accepted_steps += 1;
                self.stages[P::STAGES] = derivative;
                self.t_old = self.t();
                self.y_old = *self.y();
                self.last_step = h;
                self.t = t_new;
                self.y = y_new;
                self.derivative = derivative;
                self.step = next;
                self.last_rejected = false;
                if !self.y().iter().all(|v| v.is_finite()) {
                    return Err(NumericError::NonFinite {
                        t: to_f64(self.t()),
                    });
                }
                return Ok(());
            }
            // Rejected (a non-finite estimate counts as a failure by the largest factor).
            let ratio = if error.is_finite() {
                (error_root / constant(SAFETY)).min(constant(1.0 / MIN_RATIO))
            } else {
                constant(1.0 / MIN_RATIO)
            };
            self.step = h / ratio;
            self.last_rejected = true;
            self.statistics.rejected_steps += 1;
        }
    }
}
