//! Errors of the numerical layer.

use crate::mechanics::validation::PhysicsError;
use thiserror::Error;

/// Why a numerical computation was refused before it started or stopped before it ended.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum NumericError {
    /// The body cannot exist (negative mass, inertia violating the triangle inequality, ...).
    #[error(transparent)]
    Physics(#[from] PhysicsError),
    /// An argument that is not physical but is still out of range (a negative step, an end
    /// time before the start, a non-finite initial value).
    #[error("{what}: {reason}")]
    InvalidInput { what: String, reason: String },
    /// The closed form of torque-free motion asked of a body whose loads have a moment
    /// about G.
    #[error(
        "method exact: the closed form exists only for a torque-free body; use dop853, vern9, rk4 or splitting"
    )]
    NotTorqueFree,
    /// An adaptive integrator used up its budget of steps before reaching the end time.
    #[error(
        "integration stopped at t = {t} after {max_steps} steps (the step limit); loosen the tolerance or shorten the interval"
    )]
    StepLimit { max_steps: usize, t: f64 },
    /// An adaptive integrator's step is so small, well into its budget, that the rest of
    /// the interval would take far more steps than the budget allows: given up early.
    #[error(
        "integration stopped at t = {t} after {steps} steps: at the step it needs there, the rest of the interval would take about {needed:.0e} steps"
    )]
    StepBudgetHopeless { steps: usize, t: f64, needed: f64 },
    /// The step size an adaptive integrator needs fell below the resolution of `t`: the
    /// solution is singular there or the right-hand side is not finite.
    #[error(
        "step size {step:e} underflows at t = {t}: the solution is singular there or the torque is not finite"
    )]
    StepSizeUnderflow { t: f64, step: f64 },
    /// The state became infinite or NaN (for instance a torque function returned NaN).
    #[error("the state is no longer finite at t = {t}; check the torque")]
    NonFinite { t: f64 },
    /// A quantity of a sample (the kinetic energy, |H|) is beyond the range of the numbers
    /// (or NaN) although the state is finite: it is not printed as `inf`.
    #[error("{quantity} overflows at t = {t} s")]
    SampleOverflow { quantity: &'static str, t: f64 },
    /// A sample sink refused a sample (for instance it could not write it).
    #[error("the sample sink failed: {reason}")]
    Sink { reason: String },
    /// A tape could not be compiled to machine code (an unsupported host, or a code
    /// generator failure); only with the `jit` feature.
    #[error("native compilation of the tape failed: {reason}")]
    NativeCode { reason: String },
}
