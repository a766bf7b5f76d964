//! Euler's equations of a rigid body as a first-order ODE in the state `(ω, q)`:
//!
//! ```text
//! [I] ω̇ = M(t, ω, q) − ω × ([I] ω)        (body frame; ΣM_G = Ḣ_G in a rotating frame)
//! q̇     = ½ q ⊗ (0, ω)                     (attitude, r_fixed = q * r_body)
//! ```
//!
//! For principal moments the first line is the chapter's cyclic form
//! `ΣM_x = I_x ω̇_x − (I_y − I_z) ω_y ω_z` and its permutations; for a full constant tensor
//! `[I]⁻¹` is computed once. The attitude equation is linear in `q`, so a drift of `|q|`
//! only rescales `q`: the torque is evaluated with `q` normalised, and
//! [`OdeSystem::project`] renormalises after each step.

use super::inertia::BodyInertia;
use super::state::{raw_quaternion, RigidBodyState, STATE_DIMENSION};
use super::torque::Torque;
use crate::numeric::error::NumericError;
use crate::numeric::integrators::ode::{constant, OdeSystem};
use nalgebra::{Matrix3, Quaternion, RealField, SVector, Vector3};

/// `[I]⁻¹` in the cheapest form the inertia allows.
#[derive(Debug, Clone, Copy)]
enum InverseInertia<T: RealField + Copy> {
    Principal(Vector3<T>),
    Tensor(Matrix3<T>),
}

/// Right-hand side of Euler's equations with the attitude kinematics.
#[derive(Debug)]
pub struct EulerRhs<'a, T: RealField + Copy> {
    inertia: BodyInertia<T>,
    inverse: InverseInertia<T>,
    torque: &'a Torque<T>,
}

impl<'a, T: RealField + Copy> EulerRhs<'a, T> {
    /// Validates the inertia (see [`BodyInertia::validate`]) and inverts it.
    pub fn new(inertia: BodyInertia<T>, torque: &'a Torque<T>) -> Result<Self, NumericError> {
        inertia.validate()?;
        let inverse = match inertia {
            BodyInertia::Principal(moments) => {
                InverseInertia::Principal(moments.map(|m| m.recip()))
            }
            // [I]⁻¹ = ([I]/s)⁻¹/s with s the largest entry: the determinant of a tiny but
            // valid tensor (s³ ≈ 1e-909) would underflow to zero unscaled.
            BodyInertia::Tensor(tensor) => {
                let scale = tensor.amax();
                let scaled = tensor.unscale(scale).try_inverse();
                InverseInertia::Tensor(scaled.map(|inverse| inverse.unscale(scale)).ok_or_else(
                    || NumericError::InvalidInput {
                        what: "inertia".to_string(),
                        reason: "the inertia tensor is singular".to_string(),
                    },
                )?)
            }
        };
        Ok(Self {
            inertia,
            inverse,
            torque,
        })
    }

    /// Angular acceleration `ω̇ = [I]⁻¹ (M − ω × [I] ω)`.
    pub fn angular_acceleration(&self, t: T, state: &RigidBodyState<T>) -> Vector3<T> {
        self.solve_euler(&state.omega, self.torque.body_moment(t, state))
    }

    /// `[I]⁻¹ (M − ω × [I] ω)` for a given moment.
    fn solve_euler(&self, omega: &Vector3<T>, moment: Vector3<T>) -> Vector3<T> {
        let net = moment - omega.cross(&self.inertia.angular_momentum(omega));
        match &self.inverse {
            InverseInertia::Principal(reciprocal) => net.component_mul(reciprocal),
            InverseInertia::Tensor(inverse) => inverse * net,
        }
    }
}

impl<T: RealField + Copy> OdeSystem<T, STATE_DIMENSION> for EulerRhs<'_, T> {
    fn derivative(&self, t: T, y: &SVector<T, STATE_DIMENSION>) -> SVector<T, STATE_DIMENSION> {
        let omega = y.fixed_rows::<3>(0).into_owned();
        let moment = self
            .torque
            .body_moment_with(t, || RigidBodyState::from_vector(y));
        let omega_dot = self.solve_euler(&omega, moment);
        let q_dot = (raw_quaternion(y) * Quaternion::from_imag(omega)).coords * constant::<T>(0.5);
        SVector::from([
            omega_dot.x,
            omega_dot.y,
            omega_dot.z,
            q_dot.x,
            q_dot.y,
            q_dot.z,
            q_dot.w,
        ])
    }

    fn project(&self, y: &mut SVector<T, STATE_DIMENSION>) {
        let norm = y.fixed_rows::<4>(3).norm();
        y.fixed_rows_mut::<4>(3).unscale_mut(norm);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Matrix3;

    /// A valid tensor of a tiny body (entries ~1e-303) inverts: its determinant, ~1e-909,
    /// would underflow to zero unscaled. `[I]⁻¹ ([I] ω) = ω` with no moment and ω ∥ e_x.
    #[test]
    fn a_tiny_inertia_tensor_inverts() {
        let tiny = 1e-303;
        let tensor = Matrix3::new(4.0, -1.0, 0.0, -1.0, 4.0, 0.0, 0.0, 0.0, 5.0) * tiny;
        let torque = Torque::Body(tensor * Vector3::new(1.0, 2.0, 3.0));
        let rhs = EulerRhs::new(BodyInertia::Tensor(tensor), &torque).expect("invertible");
        let alpha = rhs.solve_euler(&Vector3::zeros(), tensor * Vector3::new(1.0, 2.0, 3.0));
        assert!(
            (alpha - Vector3::new(1.0, 2.0, 3.0)).norm() < 1e-14,
            "{alpha}"
        );
    }
}
