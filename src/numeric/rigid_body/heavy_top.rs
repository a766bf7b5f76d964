//! A heavy symmetric top (or gyroscope) about its fixed point O, as a problem for the
//! simulation driver: Euler's equations about O in principal axes, moments `(I′, I′, I)`
//! (transverse, transverse, axial, all about O), under the moment of its weight.
//!
//! The weight `W` acts at the mass centre `G`, a distance `c` from O along the axis `z`
//! (`c < 0`: G below O, a gyroscopic pendulum), so with the vertical `K` in body components
//!
//! ```text
//! M_O = r_G × (−W K) = c k × (−W K) = W c (K_y, −K_x, 0)
//! ```
//!
//! which in the frame Oxyz of §18.9 (`K = sin θ j + cos θ k`) is the chapter's
//! `ΣM_O = W c sin θ i`. Integrated this way the motion has no Eulerian-angle singularity at
//! `θ = 0`; the angles are read from the attitude afterwards
//! ([`AnglesAlongMotion`](super::eulerian_angles::AnglesAlongMotion)). Without a weight
//! (`W c = 0`) the moment is [`Torque::None`], so the exact torque-free method applies.

use super::eulerian_angles::EulerianAngles;
use super::inertia::{require_invertible, BodyInertia};
use super::simulate::Problem;
use super::state::RigidBodyState;
use super::torque::Torque;
use crate::mechanics::validation::validate_principal_moments;
use crate::numeric::error::NumericError;
use nalgebra::Vector3;
use std::f64::consts::PI;

/// An axisymmetric body with a fixed point on its axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeavyTop {
    /// `I`, the moment about the axis.
    axial: f64,
    /// `I′`, the moment about a transverse axis through O.
    transverse: f64,
    /// `W c`, the weight times the distance of G from O along the axis.
    weight_arm: f64,
}

impl HeavyTop {
    /// A top with axial moment `I`, transverse moment `I′` (about O) and `W c`. Refused:
    /// moments that no body has (not positive, or `I > 2 I′`, the triangle inequality
    /// about O), and a `W c` that is not finite.
    pub fn new(axial: f64, transverse: f64, weight_arm: f64) -> Result<Self, NumericError> {
        let moments = Vector3::new(transverse, transverse, axial);
        validate_principal_moments(&moments)?;
        require_invertible(&moments)?;
        if !weight_arm.is_finite() {
            return Err(NumericError::InvalidInput {
                what: "W c".into(),
                reason: format!("{weight_arm} is not finite"),
            });
        }
        Ok(Self {
            axial,
            transverse,
            weight_arm,
        })
    }

    /// `I`.
    pub fn axial(&self) -> f64 {
        self.axial
    }

    /// `I′`.
    pub fn transverse(&self) -> f64 {
        self.transverse
    }

    /// `W c`.
    pub fn weight_arm(&self) -> f64 {
        self.weight_arm
    }

    /// The moment of the weight about O in body axes, `W c (K_y, −K_x, 0)`.
    pub fn torque(&self) -> Torque<f64> {
        let weight_arm = self.weight_arm;
        if weight_arm == 0.0 {
            return Torque::None;
        }
        Torque::Attitude(Box::new(move |_, q| {
            let vertical = q.inverse_transform_vector(&Vector3::z());
            Vector3::new(vertical.y, -vertical.x, 0.0) * weight_arm
        }))
    }

    /// The top started at `initial` at time 0. Refused: an angle or rate that is not
    /// finite, and θ outside `[0, π]` (the angle between the vertical and the axis).
    pub fn problem(&self, initial: &EulerianAngles) -> Result<Problem<f64>, NumericError> {
        validate_start(initial)?;
        Ok(Problem {
            inertia: BodyInertia::Principal(Vector3::new(
                self.transverse,
                self.transverse,
                self.axial,
            )),
            torque: self.torque(),
            initial: RigidBodyState::new(initial.angular_velocity(), initial.attitude()),
            start_time: 0.0,
        })
    }
}

/// The start as [`HeavyTop::problem`] takes it.
pub(crate) fn validate_start(initial: &EulerianAngles) -> Result<(), NumericError> {
    if !initial.is_finite() {
        return Err(NumericError::InvalidInput {
            what: "initial Eulerian angles".into(),
            reason: format!("{initial:?} must be finite"),
        });
    }
    if !(0.0..=PI).contains(&initial.theta) {
        return Err(NumericError::InvalidInput {
            what: "theta".into(),
            reason: format!(
                "θ = {} rad is the angle between the vertical and the axis: it lies in [0, π]",
                initial.theta
            ),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Released with ψ = 0 the body axes are Oxyz, so the moment is the chapter's
    /// `W c sin θ i`.
    #[test]
    fn the_weight_turns_the_axis_down_about_the_line_of_nodes() {
        let top = HeavyTop::new(2.0, 3.0, 5.0).unwrap();
        let start = EulerianAngles {
            theta: 0.6,
            phi: 1.1,
            psi: 0.0,
            theta_dot: 0.0,
            phi_dot: 0.0,
            psi_dot: 0.0,
        };
        let problem = top.problem(&start).unwrap();
        let moment = problem.torque.body_moment(0.0, &problem.initial);
        let chapter = Vector3::new(5.0 * 0.6f64.sin(), 0.0, 0.0);
        assert!((moment - chapter).norm() < 1e-15, "{moment}");
    }

    #[test]
    fn impossible_tops_and_starts_are_refused() {
        assert!(HeavyTop::new(7.0, 3.0, 1.0).is_err(), "I > 2 I′");
        assert!(HeavyTop::new(1.0, -3.0, 1.0).is_err());
        assert!(HeavyTop::new(1.0, 3.0, f64::NAN).is_err());
        let top = HeavyTop::new(1.0, 3.0, 1.0).unwrap();
        let mut start = EulerianAngles {
            theta: -0.1,
            phi: 0.0,
            psi: 0.0,
            theta_dot: 0.0,
            phi_dot: 0.0,
            psi_dot: 1.0,
        };
        let error = top.problem(&start).unwrap_err().to_string();
        assert!(error.contains("[0, π]"), "{error}");
        start.theta = 0.1;
        start.psi_dot = f64::INFINITY;
        assert!(top.problem(&start).is_err());
    }
}
