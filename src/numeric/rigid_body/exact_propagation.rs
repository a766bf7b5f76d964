//! The simulation driver's exact method, and `auto`: a torque-free body is not integrated
//! step by step when a closed form exists.
//!
//! For a body given by its full tensor, the motion is computed in the principal frame and
//! rotated back: with `R` taking principal to body axes, `ω_body = R ω_p` and
//! `q_body = q_p R⁻¹` (so that `q_body r_body = q_p r_p`).

use super::inertia::BodyInertia;
use super::sample_sink::SampleSink;
use super::simulate::{simulate_with, Method, Problem, Propagator, Sampling, SimulationStatistics};
use super::state::RigidBodyState;
use super::torque::Torque;
use super::torque_free::TorqueFree;
use crate::numeric::error::NumericError;
use nalgebra::{Rotation3, UnitQuaternion};

/// Below this relative tolerance `auto` integrates with Verner's 9(8) pair rather than
/// DOP853: DifferentialEquations.jl's rule, and where `kinetics bench work-precision` finds it
/// reaching the same error in less time.
pub const VERNER_BELOW_RTOL: f64 = 1e-9;

/// Which method to use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Choice {
    /// The exact solution when the body is torque-free, otherwise DOP853 at this tolerance
    /// (Verner's 9(8) pair below [`VERNER_BELOW_RTOL`]).
    Auto { rtol: f64 },
    /// The closed-form torque-free motion (an error when there is a torque).
    Exact,
    /// One of the integrators.
    Integrate(Method<f64>),
}

/// The method actually used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MethodUsed {
    Exact,
    Integrator,
}

struct ExactPropagator {
    motion: TorqueFree,
    principal_to_body: Rotation3<f64>,
    start: f64,
}

impl Propagator<f64> for ExactPropagator {
    fn advance_to(&mut self, t: f64) -> Result<RigidBodyState<f64>, NumericError> {
        let tau = t - self.start;
        let omega = self.principal_to_body * self.motion.omega(tau);
        let back = UnitQuaternion::from_rotation_matrix(&self.principal_to_body.inverse());
        Ok(RigidBodyState::new(
            omega,
            self.motion.orientation(tau) * back,
        ))
    }

    fn statistics(&self) -> SimulationStatistics {
        SimulationStatistics::default()
    }
}

fn exact(problem: &Problem<f64>) -> Result<Box<dyn Propagator<f64> + '_>, NumericError> {
    if !matches!(problem.torque, Torque::None) {
        return Err(NumericError::NotTorqueFree);
    }
    let (moments, principal_to_body) = match problem.inertia {
        BodyInertia::Principal(m) => (m, Rotation3::identity()),
        BodyInertia::Tensor(_) => {
            let frame = problem.inertia.principal_frame()?;
            (frame.moments, frame.rotation)
        }
    };
    let q0 = problem.initial.orientation * UnitQuaternion::from_rotation_matrix(&principal_to_body);
    let omega0 = principal_to_body.inverse() * problem.initial.omega;
    Ok(Box::new(ExactPropagator {
        motion: TorqueFree::new(moments, omega0, q0)?,
        principal_to_body,
        start: problem.start_time,
    }))
}

/// Simulates with the chosen method; `Auto` takes the exact solution for a torque-free body.
///
/// A torque-free symmetric body, `I = (1, 1, 2)`, `ω₀ = (1, 0, 1)`: Euler's equations give
/// `ω̇_z = 0`, `ω̇_x = -ω_y`, `ω̇_y = ω_x`, so `ω = (cos t, sin t, 1)`; `|H| = √(1 + 4)` and
/// `T = ½(1 + 2) = 1.5` stay constant.
///
/// ```
/// use kinetics::{
///     simulate_choice, BodyInertia, Choice, MethodUsed, Problem, RigidBodyState, Sample, Sampling,
///     Torque,
/// };
/// use nalgebra::{UnitQuaternion, Vector3};
///
/// let problem = Problem {
///     inertia: BodyInertia::Principal(Vector3::new(1.0, 1.0, 2.0)),
///     torque: Torque::None,
///     initial: RigidBodyState::new(Vector3::new(1.0, 0.0, 1.0), UnitQuaternion::identity()),
///     start_time: 0.0,
/// };
/// let times = Sampling::Times(vec![0.0, std::f64::consts::FRAC_PI_2, std::f64::consts::PI]);
/// let mut samples = Vec::new();
/// let mut sink = |s: Sample<f64>| samples.push(s);
/// let auto = Choice::Auto { rtol: 1e-10 };
/// let (_, used) = simulate_choice(&problem, &auto, &times, &mut sink, &mut |_| {})?;
/// assert_eq!(used, MethodUsed::Exact);
/// for (s, omega) in samples.iter().zip([(1.0, 0.0, 1.0), (0.0, 1.0, 1.0), (-1.0, 0.0, 1.0)]) {
///     assert!((s.omega - Vector3::new(omega.0, omega.1, omega.2)).norm() < 1e-12);
///     assert!((s.angular_momentum_magnitude - 5f64.sqrt()).abs() < 1e-12);
///     assert!((s.kinetic_energy - 1.5).abs() < 1e-12);
/// }
/// # Ok::<(), kinetics::NumericError>(())
/// ```
///
/// Under a moment `Auto` integrates. A constant `M = 2 k` on a body with `I = (2, 3, 4)`
/// spinning at `ω₀ = k` about a principal axis: `I_z ω̇_z = M`, so `ω_z = 1 + t/2`.
///
/// ```
/// use kinetics::{
///     simulate_choice, BodyInertia, Choice, MethodUsed, Problem, RigidBodyState, Sample, Sampling,
///     Torque,
/// };
/// use nalgebra::{UnitQuaternion, Vector3};
///
/// let problem = Problem {
///     inertia: BodyInertia::Principal(Vector3::new(2.0, 3.0, 4.0)),
///     torque: Torque::Body(Vector3::new(0.0, 0.0, 2.0)),
///     initial: RigidBodyState::new(Vector3::z(), UnitQuaternion::identity()),
///     start_time: 0.0,
/// };
/// let mut worst: f64 = 0.0;
/// let exact = |t: f64| Vector3::new(0.0, 0.0, 1.0 + t / 2.0);
/// let mut sink = |s: Sample<f64>| worst = worst.max((s.omega - exact(s.t)).norm());
/// let every = Sampling::Every { interval: 0.5, end: 2.0 };
/// let auto = Choice::Auto { rtol: 1e-10 };
/// let (statistics, used) = simulate_choice(&problem, &auto, &every, &mut sink, &mut |_| {})?;
/// assert_eq!((used, statistics.samples), (MethodUsed::Integrator, 5));
/// assert!(worst < 1e-9);
/// # Ok::<(), kinetics::NumericError>(())
/// ```
pub fn simulate_choice<K: SampleSink<f64> + ?Sized>(
    problem: &Problem<f64>,
    choice: &Choice,
    sampling: &Sampling<f64>,
    sink: &mut K,
    progress: &mut dyn FnMut(f64),
) -> Result<(SimulationStatistics, MethodUsed), NumericError> {
    let method = match *choice {
        Choice::Exact => None,
        Choice::Auto { .. } if matches!(problem.torque, Torque::None) => None,
        Choice::Auto { rtol } if rtol < VERNER_BELOW_RTOL => Some(Method::vern9(rtol, rtol * 1e-3)),
        Choice::Auto { rtol } => Some(Method::dop853(rtol, rtol * 1e-3)),
        Choice::Integrate(m) => Some(m),
    };
    match method {
        None => Ok((
            simulate_with(problem, &|_| exact(problem), sampling, sink, progress)?,
            MethodUsed::Exact,
        )),
        Some(m) => Ok((
            super::simulate::simulate(problem, &m, sampling, sink, progress)?,
            MethodUsed::Integrator,
        )),
    }
}
