//! The applied moment `ΣM_G` about the mass centre, in the form Euler's equations take it:
//! body-frame components `M(t, ω, q)`.
//!
//! A moment fixed in the body (a thruster) is used as is; a moment fixed in space (a
//! constant field) is rotated into the body frame, `M_body = q⁻¹ M_fixed q`.

use super::rigid_body_state::RigidBodyState;
use nalgebra::{RealField, Vector3};

/// Body-frame moment as a function of time and state, supplied by the caller.
pub type TorqueFunction<T> = dyn Fn(T, &RigidBodyState<T>) -> Vector3<T>;

/// The moment applied to the body.
pub enum Torque<T: RealField + Copy> {
    /// Torque-free motion.
    None,
    /// Constant moment with constant body-frame components.
    Body(Vector3<T>),
    /// Constant moment with constant fixed-frame components.
    Fixed(Vector3<T>),
    /// Any moment: body-frame components as a function of `t` and the state.
    Function(Box<TorqueFunction<T>>),
}

impl<T: RealField + Copy> Torque<T> {
    /// Body-frame components of the moment at time `t` in state `state`.
    pub fn body_moment(&self, t: T, state: &RigidBodyState<T>) -> Vector3<T> {
        self.body_moment_with(t, || *state)
    }

    /// [`Torque::body_moment`] with the state built only if the moment depends on it
    /// (building it normalises the quaternion, a large part of an evaluation's cost).
    pub(crate) fn body_moment_with(
        &self,
        t: T,
        state: impl FnOnce() -> RigidBodyState<T>,
    ) -> Vector3<T> {
        match self {
            Torque::None => Vector3::zeros(),
            Torque::Body(moment) => *moment,
            Torque::Fixed(moment) => state().orientation.inverse_transform_vector(moment),
            Torque::Function(function) => function(t, &state()),
        }
    }

    /// Whether the constant components are finite (a function can only be checked as it is
    /// evaluated).
    pub fn is_finite(&self) -> bool {
        match self {
            Torque::None | Torque::Function(_) => true,
            Torque::Body(moment) | Torque::Fixed(moment) => moment.iter().all(|v| v.is_finite()),
        }
    }
}

impl<T: RealField + Copy> std::fmt::Debug for Torque<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Torque::None => write!(f, "Torque::None"),
            Torque::Body(moment) => write!(f, "Torque::Body({moment:?})"),
            Torque::Fixed(moment) => write!(f, "Torque::Fixed({moment:?})"),
            Torque::Function(_) => write!(f, "Torque::Function(..)"),
        }
    }
}
