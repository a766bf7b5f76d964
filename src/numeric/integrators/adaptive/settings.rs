//! Tolerances and step budget of an adaptive integration: the relative and absolute tolerances of the weights
//! `sᵢ = atol + rtol · max(|yᵢ|, |y₁ᵢ|)` the error estimate is measured in, and the most steps
//! one integration may take. `rtol ≥ 10 ε` (a tighter tolerance is below the rounding of
//! the step itself), `atol ≥ 0`.

use crate::numeric::error::NumericError;
use crate::numeric::integrators::ode::{constant, to_f64};
use nalgebra::RealField;

/// Default budget of steps (accepted and rejected) of one integration: about half a second
/// of a rigid body's integration (0.45 µs a step), some 100,000 turns at the default
/// tolerance, so that a run answers or is refused within a second.
/// A larger budget only lets a run the user did not mean take longer (a spin of 5e6 rad/s
/// for 1 s took 7.5 million steps, 3.6 s); a looser `rtol` or a shorter interval is the way.
pub const DEFAULT_MAX_STEPS: usize = 1_000_000;

/// Tolerances and step budget of an [`Adaptive`](super::Adaptive) integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdaptiveSettings<T> {
    /// Relative tolerance; at least 10 machine epsilons of the scalar.
    pub rtol: T,
    /// Absolute tolerance, non-negative.
    pub atol: T,
    /// Most steps (accepted and rejected) one integration may take.
    pub max_steps: usize,
}

impl<T: RealField + Copy> AdaptiveSettings<T> {
    /// Tolerances with the [`DEFAULT_MAX_STEPS`] budget.
    pub fn new(rtol: T, atol: T) -> Self {
        Self {
            rtol,
            atol,
            max_steps: DEFAULT_MAX_STEPS,
        }
    }

    /// Checks the tolerances: `rtol ≥ 10 ε` and finite, `atol ≥ 0` and finite, at least
    /// one step allowed.
    pub fn validate(&self) -> Result<(), NumericError> {
        let invalid = |what: &str, reason: String| {
            Err(NumericError::InvalidInput {
                what: what.to_string(),
                reason,
            })
        };
        let smallest_rtol = T::default_epsilon() * constant(10.0);
        if !self.rtol.is_finite() || self.rtol < smallest_rtol {
            return invalid(
                "rtol",
                format!(
                    "{} must be finite and at least 10 machine epsilons ({:e})",
                    to_f64(self.rtol),
                    to_f64(smallest_rtol)
                ),
            );
        }
        if !self.atol.is_finite() || self.atol < T::zero() {
            return invalid(
                "atol",
                format!("{} must be finite and non-negative", to_f64(self.atol)),
            );
        }
        if self.max_steps == 0 {
            return invalid("max_steps", "at least one step must be allowed".to_string());
        }
        Ok(())
    }
}
