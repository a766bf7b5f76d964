//! The state of a rotating rigid body: angular velocity `ω` in the body frame and the unit
//! quaternion `q` of the attitude, with `r_fixed = q r_body q⁻¹` (written `q * r_body`).
//!
//! The explicit integrators work on the packed vector
//! `y = (ω_x, ω_y, ω_z, q_i, q_j, q_k, q_w)`; the quaternion part of `y` may drift off the
//! unit sphere between projections and is normalised whenever a state is unpacked.

use nalgebra::{Quaternion, RealField, SVector, UnitQuaternion, Vector3, Vector4};

/// Number of scalars in the packed state `(ω, q)`.
pub const STATE_DIMENSION: usize = 7;

/// Angular velocity (body frame) and attitude of a rigid body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBodyState<T: RealField + Copy> {
    /// Angular velocity `ω` in body-frame components.
    pub omega: Vector3<T>,
    /// Attitude: maps body-frame components to fixed-frame ones, `r_fixed = q * r_body`.
    pub orientation: UnitQuaternion<T>,
}

impl<T: RealField + Copy> RigidBodyState<T> {
    /// A state from its angular velocity and attitude.
    pub fn new(omega: Vector3<T>, orientation: UnitQuaternion<T>) -> Self {
        Self { omega, orientation }
    }

    /// Packs the state as `(ω, q_i, q_j, q_k, q_w)`.
    pub fn to_vector(&self) -> SVector<T, STATE_DIMENSION> {
        let q = self.orientation.coords;
        SVector::from([self.omega.x, self.omega.y, self.omega.z, q.x, q.y, q.z, q.w])
    }

    /// Unpacks `(ω, q_i, q_j, q_k, q_w)`, normalising the quaternion.
    pub fn from_vector(y: &SVector<T, STATE_DIMENSION>) -> Self {
        Self {
            omega: y.fixed_rows::<3>(0).into_owned(),
            orientation: UnitQuaternion::new_normalize(raw_quaternion(y)),
        }
    }

    /// Whether every component is a finite number.
    pub fn is_finite(&self) -> bool {
        self.omega.iter().all(|v| v.is_finite())
            && self.orientation.coords.iter().all(|v| v.is_finite())
    }
}

/// The (possibly non-unit) quaternion part of a packed state.
pub(crate) fn raw_quaternion<T: RealField + Copy>(
    y: &SVector<T, STATE_DIMENSION>,
) -> Quaternion<T> {
    Quaternion::from(Vector4::new(y[3], y[4], y[5], y[6]))
}
