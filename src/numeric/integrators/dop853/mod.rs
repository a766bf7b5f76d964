//! Dormand–Prince 8(5,3): the explicit Runge–Kutta pair of order 8 with adaptive step size
//! control and a continuous extension of order 7, after Hairer's `DOP853` (Hairer, Nørsett
//! & Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., section II.10).
//!
//! A step of size `h` takes 12 stages `kᵢ = f(t + cᵢh, y + h Σⱼ aᵢⱼ kⱼ)` and advances
//! `y₁ = y + h Σ bᵢ kᵢ` (order 8). Two embedded estimates, `err₅ = h Σ e⁵ᵢ kᵢ` (order 5)
//! and `err₃ = h Σ (bᵢ − b̂ᵢ) kᵢ` (order 3), are combined as in Hairer's code:
//!
//! ```text
//! sᵢ = atol + rtol · max(|yᵢ|, |y₁ᵢ|)
//! err = |h| Σ(err₅ᵢ/sᵢ)² / sqrt(n (Σ(err₅ᵢ/sᵢ)² + 0.01 Σ(err₃ᵢ/sᵢ)²))
//! ```
//!
//! The step is accepted when `err ≤ 1`; the next step is `h / clamp(err^⅛ / 0.9, 1/6, 3)`,
//! and after a rejection it may not grow. The derivative at the end of an accepted step is
//! the first stage of the next (FSAL). The initial step follows Hairer's `HINIT`, measured in
//! the problem's own time unit so that a body spinning at 1e150 or 1e-150 rad/s starts as one
//! spinning at 1 rad/s; the norms and the error estimate are scaled before squaring.
//!
//! Dense output: three more stages give a degree-7 polynomial on each accepted step, so
//! samples at any time inside the step are interpolated to the accuracy of the method.
//! They are evaluated only when a sample falls inside the step. Integration runs forward
//! in time; stages see the true time `t + cᵢh`, so time-dependent right-hand sides are
//! handled exactly as autonomous ones.
//!
//! - `tableau.rs`: the coefficients (nodes, coupling, weights, error and dense-output rows)
//! - `settings.rs`: tolerances and step budget, validated
//! - `initial_step.rs`: the starting step (`HINIT`) in the problem's own time unit
//! - `stages.rs`: the stages `kᵢ` of a step
//! - `step.rs`: one accepted step: accept or reject, the next step size
//! - `error_estimate.rs`: the combined 5th/3rd-order error estimate
//! - `dense_output.rs`: the continuous extension on the last accepted step
//! - `scaled_norm.rs`: norms without overflow or underflow
//!
//! This file holds the integrator's state between steps.

mod dense_output;
mod error_estimate;
mod initial_step;
mod scaled_norm;
mod settings;
mod stages;
mod step;
mod tableau;

pub use settings::{Dop853Settings, DEFAULT_MAX_STEPS};

use super::compensated::{Compensated, CompensatedVector};
use super::ode::{to_f64, OdeSystem};
use crate::numeric::error::NumericError;
use nalgebra::{RealField, SVector};
use tableau::EXTENDED_STAGES;

/// Counters of an integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Dop853Statistics {
    /// Steps whose error estimate passed.
    pub accepted_steps: usize,
    /// Steps retried with a smaller size.
    pub rejected_steps: usize,
    /// Evaluations of the right-hand side, dense-output stages included.
    pub evaluations: usize,
}

/// The integrator between steps: the current point, the last accepted step (kept for dense
/// output) and the controller's memory.
#[derive(Debug, Clone)]
pub struct Dop853<T: RealField + Copy, const N: usize> {
    settings: Dop853Settings<T>,
    t_end: T,
    /// The time and state, each a sum of steps with its rounding carried.
    t: Compensated<T>,
    y: CompensatedVector<T, N>,
    /// `f(t, y)`, the first stage of the next step.
    derivative: SVector<T, N>,
    /// Proposed size of the next step.
    step: T,
    /// Start, state and size of the last accepted step.
    t_old: T,
    y_old: SVector<T, N>,
    last_step: T,
    stages: [SVector<T, N>; EXTENDED_STAGES],
    /// Coefficients of the continuous extension of the last step, once computed.
    dense: Option<[SVector<T, N>; 7]>,
    last_rejected: bool,
    statistics: Dop853Statistics,
}

impl<T: RealField + Copy, const N: usize> Dop853<T, N> {
    /// Prepares an integration of `system` from `(t0, y0)` forward to `t_end > t0`.
    pub fn new<S: OdeSystem<T, N> + ?Sized>(
        system: &S,
        t0: T,
        y0: SVector<T, N>,
        t_end: T,
        settings: Dop853Settings<T>,
    ) -> Result<Self, NumericError> {
        settings.validate()?;
        if !(t0.is_finite() && t_end.is_finite() && t_end > t0) {
            return Err(NumericError::InvalidInput {
                what: "time interval".to_string(),
                reason: format!(
                    "from {} to {}: both must be finite and the end after the start",
                    to_f64(t0),
                    to_f64(t_end)
                ),
            });
        }
        let derivative = system.derivative(t0, &y0);
        let mut integrator = Self {
            settings,
            t_end,
            t: Compensated::new(t0),
            y: CompensatedVector::new(y0),
            derivative,
            step: T::zero(),
            t_old: t0,
            y_old: y0,
            last_step: T::zero(),
            stages: [SVector::zeros(); EXTENDED_STAGES],
            dense: None,
            last_rejected: false,
            statistics: Dop853Statistics {
                evaluations: 1,
                ..Default::default()
            },
        };
        integrator.step = integrator.initial_step(system);
        Ok(integrator)
    }

    /// Current time.
    pub fn t(&self) -> T {
        self.t.value()
    }

    /// Current state.
    pub fn y(&self) -> &SVector<T, N> {
        self.y.value()
    }

    /// Steps and evaluations so far.
    pub fn statistics(&self) -> Dop853Statistics {
        self.statistics
    }
}
