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

/// Which method to use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Choice {
    /// The exact solution when the body is torque-free, otherwise DOP853 at this tolerance.
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
        return Err(NumericError::InvalidInput {
            what: "method exact".into(),
            reason:
                "the closed form exists only for a torque-free body; use dop853, rk4 or splitting"
                    .into(),
        });
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
