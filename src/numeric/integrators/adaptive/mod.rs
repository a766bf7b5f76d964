//! Adaptive explicit Runge–Kutta integration with an embedded error estimate and dense
//! output, one driver for every pair ([`EmbeddedPair`]): DOP853
//! ([`dop853`](super::dop853)) and Verner's 9(8) ([`vern9`](super::vern9)).
//!
//! A step of size `h` takes the pair's stages `kᵢ = f(t + cᵢh, y + h Σⱼ aᵢⱼ kⱼ)` and
//! advances `y₁ = y + h Σ bᵢ kᵢ`, the increment added with its rounding carried
//! ([`compensated`](super::compensated)); so is the time. The pair measures the step's error
//! `err` in the weights `sᵢ = atol + rtol · max(|yᵢ|, |y₁ᵢ|)` (Hairer, Nørsett & Wanner,
//! *Solving Ordinary Differential Equations I*, 2nd ed., sections II.4 and II.10):
//!
//! ```text
//! accept when err ≤ 1;   h_next = h / clamp(err^(1/p) / 0.9, 1/6, 3)     p the pair's order
//! ```
//!
//! and after a rejection the next step may not grow. The derivative at the end of an
//! accepted step is the first stage of the next (and a stage of the dense output). The
//! initial step follows Hairer's `HINIT`, measured in the problem's own time unit so that a
//! body spinning at 1e150 or 1e-150 rad/s starts as one spinning at 1 rad/s; the norms and
//! the error estimates are scaled before squaring. Samples inside a step come from the
//! pair's continuous extension, whose extra stages are evaluated only when a sample falls
//! inside the step. Integration runs forward in time; stages see the true time `t + cᵢh`.
//!
//! - `settings.rs`: tolerances and step budget, validated
//! - `initial_step.rs`: the starting step (`HINIT`) in the problem's own time unit
//! - `stages.rs`: the stages `kᵢ` of a step
//! - `step.rs`: one accepted step: accept or reject, the next step size
//! - `scaled_norm.rs`: norms without overflow or underflow
//!
//! This file holds the pair's description and the integrator's state between steps.

mod initial_step;
pub(super) mod scaled_norm;
mod settings;
mod stages;
mod step;

pub use settings::{AdaptiveSettings, DEFAULT_MAX_STEPS};

use super::compensated::{Compensated, CompensatedVector};
use super::ode::{to_f64, OdeSystem};
use crate::numeric::error::NumericError;
use nalgebra::{RealField, SVector};

/// An embedded Runge–Kutta pair with a continuous extension: its coefficients, its error
/// estimate and its dense output. Stages are numbered from 0; stage [`STAGES`](Self::STAGES)
/// is the derivative at the end of the step (`c = 1`, row `STAGES` of `A` the weights `bⱼ`),
/// and the stages after it serve the dense output alone.
pub trait EmbeddedPair {
    /// Order of the propagated solution: the controller takes `err^(1/ORDER)`.
    const ORDER: u32;
    /// Stages a step evaluates, the first being the derivative at its start.
    const STAGES: usize;
    /// Nodes `cᵢ` of every stage, dense-output stages included.
    const C: &'static [f64];
    /// Coupling coefficients, row by row as `(j, aᵢⱼ)`; row `STAGES` holds the `bⱼ`.
    const A: &'static [&'static [(usize, f64)]];

    /// `err^(1/ORDER)`, the controller's measure of a step's error.
    fn error_root<T: RealField + Copy>(error: T) -> T {
        error.powf(nalgebra::convert(1.0 / f64::from(Self::ORDER)))
    }

    /// The step's error in units of the tolerance (accepted when ≤ 1), from the stages, the
    /// increment `y₁ − y` and the weights `sᵢ = atol + rtol · max(|yᵢ|, |y₁ᵢ|)`.
    fn error_norm<T: RealField + Copy, const N: usize>(
        stages: &[SVector<T, N>],
        increment: &SVector<T, N>,
        weights: &SVector<T, N>,
        h: T,
    ) -> T;

    /// The coefficients of the continuous extension on a step of size `h` from `y_old` to
    /// `y` (every stage evaluated), written into `coefficients`.
    fn continuous_extension<T: RealField + Copy, const N: usize>(
        stages: &[SVector<T, N>],
        y_old: &SVector<T, N>,
        y: &SVector<T, N>,
        h: T,
        coefficients: &mut Vec<SVector<T, N>>,
    );

    /// The solution at the fraction `θ ∈ [0, 1]` of the step, from its coefficients.
    fn interpolate<T: RealField + Copy, const N: usize>(
        coefficients: &[SVector<T, N>],
        y_old: &SVector<T, N>,
        theta: T,
    ) -> SVector<T, N>;
}

/// Counters of an integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct AdaptiveStatistics {
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
pub struct Adaptive<P: EmbeddedPair, T: RealField + Copy, const N: usize> {
    pair: std::marker::PhantomData<P>,
    settings: AdaptiveSettings<T>,
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
    /// Every stage of the last step, the dense output's included (`P::C.len()` of them).
    stages: Vec<SVector<T, N>>,
    /// Coefficients of the continuous extension of the last step; empty until a sample
    /// needs them.
    dense: Vec<SVector<T, N>>,
    last_rejected: bool,
    statistics: AdaptiveStatistics,
}

impl<P: EmbeddedPair, T: RealField + Copy, const N: usize> Adaptive<P, T, N> {
    /// Prepares an integration of `system` from `(t0, y0)` forward to `t_end > t0`.
    pub fn new<S: OdeSystem<T, N> + ?Sized>(
        system: &S,
        t0: T,
        y0: SVector<T, N>,
        t_end: T,
        settings: AdaptiveSettings<T>,
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
            pair: std::marker::PhantomData,
            settings,
            t_end,
            t: Compensated::new(t0),
            y: CompensatedVector::new(y0),
            derivative,
            step: T::zero(),
            t_old: t0,
            y_old: y0,
            last_step: T::zero(),
            stages: vec![SVector::zeros(); P::C.len()],
            dense: Vec::new(),
            last_rejected: false,
            statistics: AdaptiveStatistics {
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
    pub fn statistics(&self) -> AdaptiveStatistics {
        self.statistics
    }

    /// The solution at `t` inside the last accepted step `[t_old, t_now]`, from the pair's
    /// continuous extension (times outside are clamped to the step). Before the first step
    /// it is the initial state.
    pub fn dense_output<S: OdeSystem<T, N> + ?Sized>(&mut self, system: &S, t: T) -> SVector<T, N> {
        if t == self.t() || self.statistics.accepted_steps == 0 {
            return *self.y();
        }
        let h = self.last_step;
        if self.dense.is_empty() {
            let (t_old, y_old) = (self.t_old, self.y_old);
            self.evaluate_stages(system, P::STAGES + 1..P::C.len(), t_old, &y_old, h);
            let y = *self.y();
            P::continuous_extension(&self.stages, &self.y_old, &y, h, &mut self.dense);
        }
        let theta = ((t - self.t_old) / h).max(T::zero()).min(T::one());
        P::interpolate(&self.dense, &self.y_old, theta)
    }
}
