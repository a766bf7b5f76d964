//! Simulation of a rigid body under Euler's equations: integrate `(ω, q)` from the initial
//! state and hand the body's state to a [`SampleSink`] at each requested time.
//!
//! Everything is validated before the first step: the inertia
//! ([`BodyInertia::validate`]), the initial state and constant torques (finite), the method's
//! parameters and the sample times (finite, strictly increasing, not before the start).
//! Every sample is checked before it is handed on: a state, kinetic energy or |H| that is
//! not finite stops the simulation with an error naming it, never an `inf` in the output.
//! Samples are produced one at a time and never stored, so memory does not depend on their
//! number.
//!
//! Methods, each behind one `Propagator` (the state a method carries between sample
//! times; adding a method is one [`Method`] variant and one `Propagator`):
//! * [`Method::Rk4`]: classical Runge–Kutta; between two sample times it takes equal steps
//!   no longer than `step`, landing on each sample time.
//! * [`Method::Dop853`], [`Method::Vern9`]: adaptive Dormand–Prince 8(5,3) and Verner 9(8);
//!   samples come from their dense output, so the step sequence does not depend on the
//!   sampling.
//! * [`Method::Splitting`]: the structure-preserving Lie–Poisson splitting (torque-free, or a
//!   moment that does not depend on `ω`: constant, or a function of time or attitude), second
//!   or fourth order, equal steps like `Rk4`.

use super::euler_rhs::EulerRhs;
use super::inertia::BodyInertia;
use super::sample_sink::{Sample, SampleSink};
use super::state::{RigidBodyState, STATE_DIMENSION};
use super::torque::Torque;
use crate::numeric::error::NumericError;
use crate::numeric::integrators::adaptive::{
    Adaptive, AdaptiveSettings, EmbeddedPair, DEFAULT_MAX_STEPS,
};
use crate::numeric::integrators::compensated::CompensatedVector;
use crate::numeric::integrators::dop853::DormandPrince853;
use crate::numeric::integrators::ode::{constant, to_f64};
use crate::numeric::integrators::rk4::rk4_step;
use crate::numeric::integrators::splitting::{LiePoissonSplitting, SplittingOrder, SplittingState};
use crate::numeric::integrators::vern9::Verner98;
use nalgebra::{RealField, UnitQuaternion};

/// Most steps (or samples) a simulation may be asked for.
const MAX_COUNT: f64 = 1e15;
/// The kinetic energy as an error names it.
pub const KINETIC_ENERGY: &str = "the kinetic energy T = ½ωᵀ[I]ω";
/// The magnitude of the angular momentum as an error names it.
pub const ANGULAR_MOMENTUM: &str = "the angular momentum |H_G| = |[I]ω|";
/// Progress is reported when the fraction done has grown by this much.
const PROGRESS_RESOLUTION: f64 = 1e-3;

/// A rigid body, the moment on it and where it starts.
#[derive(Debug)]
pub struct Problem<T: RealField + Copy> {
    /// Inertia in body axes (principal moments or the full tensor).
    pub inertia: BodyInertia<T>,
    /// Moment about the mass centre.
    pub torque: Torque<T>,
    /// `(ω, q)` at `start_time`.
    pub initial: RigidBodyState<T>,
    /// Time of the initial state.
    pub start_time: T,
}

/// How to integrate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method<T> {
    /// Classical fourth-order Runge–Kutta with steps of at most `step`.
    Rk4 { step: T },
    /// Adaptive DOP853 with relative and absolute tolerances and a budget of steps.
    Dop853 { rtol: T, atol: T, max_steps: usize },
    /// Adaptive Verner 9(8), the same settings as `Dop853`.
    Vern9 { rtol: T, atol: T, max_steps: usize },
    /// Lie–Poisson splitting of the given order with steps of at most `step`.
    Splitting { step: T, order: SplittingOrder },
}

impl<T> Method<T> {
    /// DOP853 with the default step budget [`DEFAULT_MAX_STEPS`].
    pub fn dop853(rtol: T, atol: T) -> Self {
        Method::Dop853 {
            rtol,
            atol,
            max_steps: DEFAULT_MAX_STEPS,
        }
    }

    /// Verner's 9(8) pair with the default step budget [`DEFAULT_MAX_STEPS`].
    pub fn vern9(rtol: T, atol: T) -> Self {
        Method::Vern9 {
            rtol,
            atol,
            max_steps: DEFAULT_MAX_STEPS,
        }
    }
}

/// When to sample.
#[derive(Debug, Clone, PartialEq)]
pub enum Sampling<T> {
    /// At `start_time + k·interval` for every `k ≥ 0` up to `end` (inclusive).
    Every { interval: T, end: T },
    /// At these times: finite, strictly increasing, none before the start.
    Times(Vec<T>),
}

/// What a simulation did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SimulationStatistics {
    /// Samples handed to the sink.
    pub samples: usize,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (adaptive methods only).
    pub rejected_steps: usize,
    /// Evaluations of the right-hand side of Euler's equations (zero for the splitting).
    pub evaluations: usize,
}

/// Integrates `problem` with `method`, handing a [`Sample`] to `sink` at each time of
/// `sampling` (the first may be the start itself) and the fraction done to `progress`
/// (non-decreasing, at most about a thousand calls, the last one `1.0`).
///
/// ```
/// use kinetics::numeric::rigid_body::inertia::BodyInertia;
/// use kinetics::numeric::rigid_body::state::RigidBodyState;
/// use kinetics::numeric::rigid_body::sample_sink::Sample;
/// use kinetics::numeric::rigid_body::simulate::{simulate, Method, Problem, Sampling};
/// use kinetics::numeric::rigid_body::torque::Torque;
/// use nalgebra::{UnitQuaternion, Vector3};
///
/// let problem = Problem {
///     inertia: BodyInertia::Principal(Vector3::new(1.0, 2.0, 3.0)),
///     torque: Torque::None,
///     initial: RigidBodyState::new(Vector3::new(1.0, 1.0, 1.0), UnitQuaternion::identity()),
///     start_time: 0.0,
/// };
/// // Torque-free: T = ½ Σ I_i ω_i² stays at its initial ½ (1 + 2 + 3) = 3.
/// let mut energy_error: f64 = 0.0;
/// let mut record = |s: Sample<f64>| energy_error = energy_error.max((s.kinetic_energy - 3.0).abs());
/// let statistics = simulate(
///     &problem,
///     &Method::dop853(1e-10, 1e-12),
///     &Sampling::Every { interval: 0.1, end: 10.0 },
///     &mut record,
///     &mut |_fraction| {},
/// )
/// .unwrap();
/// assert_eq!(statistics.samples, 101);
/// assert!(energy_error < 1e-9);
/// ```
pub fn simulate<T, K>(
    problem: &Problem<T>,
    method: &Method<T>,
    sampling: &Sampling<T>,
    sink: &mut K,
    progress: &mut dyn FnMut(f64),
) -> Result<SimulationStatistics, NumericError>
where
    T: RealField + Copy,
    K: SampleSink<T> + ?Sized,
{
    simulate_with(
        problem,
        &|end| propagator(problem, method, end),
        sampling,
        sink,
        progress,
    )
}

/// [`simulate`] with the propagator built by `make` from the last sample time: the
/// one driver behind every method, the integrators here and the exact solution.
pub(crate) fn simulate_with<'a, T, K>(
    problem: &Problem<T>,
    make: &dyn Fn(T) -> Result<Box<dyn Propagator<T> + 'a>, NumericError>,
    sampling: &Sampling<T>,
    sink: &mut K,
    progress: &mut dyn FnMut(f64),
) -> Result<SimulationStatistics, NumericError>
where
    T: RealField + Copy,
    K: SampleSink<T> + ?Sized,
{
    validate_problem(problem)?;
    let times = SampleTimes::new(sampling, problem.start_time)?;
    let mut propagator = make(times.last())?;
    let span = times.last() - problem.start_time;
    let mut reported = f64::NEG_INFINITY;
    for k in 0..times.len() {
        let t = times.time(k);
        let state = propagator.advance_to(t)?;
        if !state.is_finite() {
            return Err(NumericError::NonFinite { t: to_f64(t) });
        }
        let omega = state.omega;
        let kinetic_energy = problem.inertia.kinetic_energy(&omega);
        let angular_momentum_magnitude = problem.inertia.angular_momentum_magnitude(&omega);
        for (quantity, value) in [
            (KINETIC_ENERGY, kinetic_energy),
            (ANGULAR_MOMENTUM, angular_momentum_magnitude),
        ] {
            if !value.is_finite() {
                return Err(NumericError::SampleOverflow {
                    quantity,
                    t: to_f64(t),
                });
            }
        }
        sink.accept(Sample {
            t,
            omega,
            orientation: state.orientation,
            kinetic_energy,
            angular_momentum_magnitude,
        })?;
        let fraction = if k + 1 == times.len() {
            1.0
        } else {
            to_f64((t - problem.start_time) / span)
        };
        if fraction - reported >= PROGRESS_RESOLUTION || fraction == 1.0 {
            progress(fraction);
            reported = fraction;
        }
    }
    Ok(SimulationStatistics {
        samples: times.len(),
        ..propagator.statistics()
    })
}

fn invalid(what: &str, reason: impl Into<String>) -> NumericError {
    NumericError::InvalidInput {
        what: what.to_string(),
        reason: reason.into(),
    }
}

fn validate_problem<T: RealField + Copy>(problem: &Problem<T>) -> Result<(), NumericError> {
    problem.inertia.validate()?;
    if !problem.initial.is_finite() {
        return Err(invalid(
            "initial state",
            format!(
                "ω = {:?}, q = {:?} must be finite",
                problem.initial.omega.map(to_f64),
                problem.initial.orientation.coords.map(to_f64)
            ),
        ));
    }
    if problem.initial.orientation.norm() == T::zero() {
        return Err(invalid(
            "initial state",
            "the attitude quaternion is zero; it must be a rotation (unit quaternion)",
        ));
    }
    if !problem.torque.is_finite() {
        return Err(invalid(
            "torque",
            format!("{:?} must be finite", problem.torque),
        ));
    }
    if !problem.start_time.is_finite() {
        return Err(invalid("start time", "must be finite"));
    }
    Ok(())
}

/// The validated sample times, produced on demand.
enum SampleTimes<'a, T> {
    Every { start: T, interval: T, count: usize },
    Times(&'a [T]),
}

impl<'a, T: RealField + Copy> SampleTimes<'a, T> {
    fn new(sampling: &'a Sampling<T>, start: T) -> Result<Self, NumericError> {
        match sampling {
            Sampling::Every { interval, end } => {
                let (interval, end) = (*interval, *end);
                if !(interval.is_finite() && interval > T::zero()) {
                    return Err(invalid(
                        "sample interval",
                        format!("{} must be finite and positive", to_f64(interval)),
                    ));
                }
                if !(end.is_finite() && end >= start) {
                    return Err(invalid(
                        "sample end time",
                        format!(
                            "{} must be finite and not before the start {}",
                            to_f64(end),
                            to_f64(start)
                        ),
                    ));
                }
                // Tolerate rounding in (end − start)/interval so that `end` itself is kept.
                let intervals = (to_f64((end - start) / interval) * (1.0 + 1e-12)).floor();
                if intervals >= MAX_COUNT {
                    return Err(invalid(
                        "sampling",
                        format!("{intervals:e} samples is more than {MAX_COUNT:e}"),
                    ));
                }
                Ok(SampleTimes::Every {
                    start,
                    interval,
                    count: intervals as usize + 1,
                })
            }
            Sampling::Times(times) => {
                let Some(&first) = times.first() else {
                    return Err(invalid("sample times", "the list is empty"));
                };
                if let Some(k) = times.iter().position(|t| !t.is_finite()) {
                    return Err(invalid(
                        "sample times",
                        format!("time number {k} is {}, not finite", to_f64(times[k])),
                    ));
                }
                if first < start {
                    return Err(invalid(
                        "sample times",
                        format!(
                            "the first time {} is before the start {}",
                            to_f64(first),
                            to_f64(start)
                        ),
                    ));
                }
                if let Some(k) = times.windows(2).position(|w| w[1] <= w[0]) {
                    return Err(invalid(
                        "sample times",
                        format!(
                            "must be strictly increasing, but time number {} is {} after {}",
                            k + 1,
                            to_f64(times[k + 1]),
                            to_f64(times[k])
                        ),
                    ));
                }
                Ok(SampleTimes::Times(times))
            }
        }
    }

    fn len(&self) -> usize {
        match self {
            SampleTimes::Every { count, .. } => *count,
            SampleTimes::Times(times) => times.len(),
        }
    }

    fn time(&self, k: usize) -> T {
        match self {
            SampleTimes::Every {
                start, interval, ..
            } => *start + *interval * constant::<T>(k as f64),
            SampleTimes::Times(times) => times[k],
        }
    }

    fn last(&self) -> T {
        self.time(self.len() - 1)
    }
}

/// A method's state between sample times.
pub(crate) trait Propagator<T: RealField + Copy> {
    /// Integrates up to `t` (not before the previous call's time) and returns the state.
    fn advance_to(&mut self, t: T) -> Result<RigidBodyState<T>, NumericError>;
    /// Steps and evaluations so far (`samples` left at zero).
    fn statistics(&self) -> SimulationStatistics;
}

fn propagator<'a, T: RealField + Copy>(
    problem: &'a Problem<T>,
    method: &Method<T>,
    end: T,
) -> Result<Box<dyn Propagator<T> + 'a>, NumericError> {
    let start = problem.start_time;
    // A quaternion that is nearly unit (rounded input) is made exactly so.
    let initial = RigidBodyState::new(
        problem.initial.omega,
        UnitQuaternion::new_normalize(problem.initial.orientation.into_inner()),
    );
    match *method {
        Method::Rk4 { step } => {
            validate_fixed_step(step, end - start)?;
            Ok(Box::new(FixedStepPropagator {
                stepper: Rk4Stepper {
                    rhs: EulerRhs::new(problem.inertia, &problem.torque)?,
                    y: CompensatedVector::new(initial.to_vector()),
                },
                t: start,
                max_step: step,
                steps: 0,
            }))
        }
        Method::Splitting { step, order } => {
            validate_fixed_step(step, end - start)?;
            let splitting = LiePoissonSplitting::new(&problem.inertia, &problem.torque, order)?;
            Ok(Box::new(FixedStepPropagator {
                stepper: SplittingStepper {
                    state: splitting.to_splitting_state(start, &initial),
                    splitting,
                },
                t: start,
                max_step: step,
                steps: 0,
            }))
        }
        Method::Dop853 {
            rtol,
            atol,
            max_steps,
        } => adaptive_propagator::<DormandPrince853, T>(
            problem,
            initial,
            end,
            AdaptiveSettings {
                rtol,
                atol,
                max_steps,
            },
        ),
        Method::Vern9 {
            rtol,
            atol,
            max_steps,
        } => adaptive_propagator::<Verner98, T>(
            problem,
            initial,
            end,
            AdaptiveSettings {
                rtol,
                atol,
                max_steps,
            },
        ),
    }
}

/// The propagator of an adaptive pair `P` from `initial` up to `end`.
fn adaptive_propagator<'a, P: EmbeddedPair + 'a, T: RealField + Copy>(
    problem: &'a Problem<T>,
    initial: RigidBodyState<T>,
    end: T,
    settings: AdaptiveSettings<T>,
) -> Result<Box<dyn Propagator<T> + 'a>, NumericError> {
    settings.validate()?;
    let rhs = EulerRhs::new(problem.inertia, &problem.torque)?;
    let (start, y0) = (problem.start_time, initial.to_vector());
    let integrator = if end > start {
        Some(Adaptive::<P, T, STATE_DIMENSION>::new(
            &rhs, start, y0, end, settings,
        )?)
    } else {
        None
    };
    Ok(Box::new(AdaptivePropagator {
        rhs,
        integrator,
        initial,
    }))
}

fn validate_fixed_step<T: RealField + Copy>(step: T, span: T) -> Result<(), NumericError> {
    if !(step.is_finite() && step > T::zero()) {
        return Err(invalid(
            "step",
            format!("{} must be finite and positive", to_f64(step)),
        ));
    }
    if to_f64(span / step) >= MAX_COUNT {
        return Err(invalid(
            "step",
            format!(
                "{} over {} would take more than {MAX_COUNT:e} steps",
                to_f64(step),
                to_f64(span)
            ),
        ));
    }
    Ok(())
}

/// The number and size of equal steps no longer than `max_step` that cover `[from, to]`
/// (a rounding excess of 1e-12 relative does not cost an extra step).
fn equal_steps<T: RealField + Copy>(from: T, to: T, max_step: T) -> (usize, T) {
    let span = to - from;
    if span <= T::zero() {
        return (0, T::zero());
    }
    let count = (to_f64(span / max_step) * (1.0 - 1e-12)).ceil().max(1.0) as usize;
    (count, span / constant::<T>(count as f64))
}

/// A method that advances the state by steps of a given size (RK4, the splitting).
trait FixedStep<T: RealField + Copy> {
    /// Right-hand-side evaluations a step costs (the splitting's flows are exact: none).
    const EVALUATIONS_PER_STEP: usize;
    /// One step of size `h` from the step's exact time `time`.
    fn step(&mut self, time: T, h: T);
    fn state(&self) -> RigidBodyState<T>;
}

/// Equal steps of at most `max_step` to each sample time, each from its exact step time
/// `t₀ + k h` (not an accumulated sum of `h`).
struct FixedStepPropagator<T: RealField + Copy, S: FixedStep<T>> {
    stepper: S,
    t: T,
    max_step: T,
    steps: usize,
}

impl<T: RealField + Copy, S: FixedStep<T>> Propagator<T> for FixedStepPropagator<T, S> {
    fn advance_to(&mut self, t: T) -> Result<RigidBodyState<T>, NumericError> {
        let (count, h) = equal_steps(self.t, t, self.max_step);
        for k in 0..count {
            self.stepper.step(self.t + h * constant::<T>(k as f64), h);
        }
        self.steps += count;
        self.t = t;
        Ok(self.stepper.state())
    }

    fn statistics(&self) -> SimulationStatistics {
        SimulationStatistics {
            steps: self.steps,
            evaluations: S::EVALUATIONS_PER_STEP * self.steps,
            ..Default::default()
        }
    }
}

struct Rk4Stepper<'a, T: RealField + Copy> {
    rhs: EulerRhs<'a, T>,
    y: CompensatedVector<T, STATE_DIMENSION>,
}

impl<T: RealField + Copy> FixedStep<T> for Rk4Stepper<'_, T> {
    const EVALUATIONS_PER_STEP: usize = 4;

    fn step(&mut self, time: T, h: T) {
        rk4_step(&self.rhs, time, &mut self.y, h);
    }

    fn state(&self) -> RigidBodyState<T> {
        RigidBodyState::from_vector(self.y.value())
    }
}

struct SplittingStepper<'a, T: RealField + Copy> {
    splitting: LiePoissonSplitting<'a, T>,
    state: SplittingState<T>,
}

impl<T: RealField + Copy> FixedStep<T> for SplittingStepper<'_, T> {
    const EVALUATIONS_PER_STEP: usize = 0;

    fn step(&mut self, time: T, h: T) {
        // The clock restarts from the exact step time, as RK4's does.
        self.state.time = time;
        self.splitting.step(&mut self.state, h);
    }

    fn state(&self) -> RigidBodyState<T> {
        self.splitting.to_rigid_body_state(&self.state)
    }
}

struct AdaptivePropagator<'a, P: EmbeddedPair, T: RealField + Copy> {
    rhs: EulerRhs<'a, T>,
    /// `None` when the only sample is at the start.
    integrator: Option<Adaptive<P, T, STATE_DIMENSION>>,
    initial: RigidBodyState<T>,
}

impl<P: EmbeddedPair, T: RealField + Copy> Propagator<T> for AdaptivePropagator<'_, P, T> {
    fn advance_to(&mut self, t: T) -> Result<RigidBodyState<T>, NumericError> {
        let Some(integrator) = &mut self.integrator else {
            return Ok(self.initial);
        };
        while integrator.t() < t {
            integrator.step(&self.rhs)?;
        }
        Ok(RigidBodyState::from_vector(
            &integrator.dense_output(&self.rhs, t),
        ))
    }

    fn statistics(&self) -> SimulationStatistics {
        let counts = self
            .integrator
            .as_ref()
            .map(|integrator| integrator.statistics())
            .unwrap_or_default();
        SimulationStatistics {
            samples: 0,
            steps: counts.accepted_steps,
            rejected_steps: counts.rejected_steps,
            evaluations: counts.evaluations,
        }
    }
}
