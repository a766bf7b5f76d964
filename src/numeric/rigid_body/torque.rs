//! The applied moment `ΣM_G` about the mass centre, in the form Euler's equations take it:
//! body-frame components `M(t, ω, q)`.
//!
//! A moment fixed in the body (a thruster) is used as is; a moment fixed in space (a
//! constant field) is rotated into the body frame, `M_body = q⁻¹ M_fixed q`.
//!
//! A moment given as a function says what it depends on, because the splitting integrator
//! can apply a moment exactly only while it is constant along the kick `Ḣ = M` (attitude
//! and time frozen): [`Torque::Time`] and [`Torque::Attitude`] qualify, a general
//! [`Torque::Function`] of `ω` does not.

use super::state::RigidBodyState;
use nalgebra::{RealField, UnitQuaternion, Vector3};

/// Body-frame moment as a function of time and state, supplied by the caller.
pub type TorqueFunction<T> = dyn Fn(T, &RigidBodyState<T>) -> Vector3<T>;
/// Body-frame moment as a function of time alone.
pub type TimeTorqueFunction<T> = dyn Fn(T) -> Vector3<T>;
/// Body-frame moment as a function of time and attitude `q` (body → fixed), not of `ω`.
pub type AttitudeTorqueFunction<T> = dyn Fn(T, &UnitQuaternion<T>) -> Vector3<T>;

/// The moment applied to the body.
pub enum Torque<T: RealField + Copy> {
    /// Torque-free motion.
    None,
    /// Constant moment with constant body-frame components.
    Body(Vector3<T>),
    /// Constant moment with constant fixed-frame components.
    Fixed(Vector3<T>),
    /// Body-frame components as a function of `t` alone (a programmed thruster, a
    /// time-varying couple carried by the body).
    Time(Box<TimeTorqueFunction<T>>),
    /// Body-frame components as a function of `t` and the attitude, not of `ω` (a moment
    /// fixed in space that varies in time, a gravity-gradient moment).
    Attitude(Box<AttitudeTorqueFunction<T>>),
    /// Any moment: body-frame components as a function of `t` and the state, `ω` included.
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
            Torque::Time(function) => function(t),
            Torque::Attitude(function) => function(t, &state().orientation),
            Torque::Function(function) => function(t, &state()),
        }
    }

    /// Whether the constant components are finite (a function can only be checked as it is
    /// evaluated).
    pub fn is_finite(&self) -> bool {
        match self {
            Torque::None | Torque::Time(_) | Torque::Attitude(_) | Torque::Function(_) => true,
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
            Torque::Time(_) => write!(f, "Torque::Time(..)"),
            Torque::Attitude(_) => write!(f, "Torque::Attitude(..)"),
            Torque::Function(_) => write!(f, "Torque::Function(..)"),
        }
    }
}
