//! The inertia of the body in its own frame, as the numerical layer uses it: either the
//! principal moments `(I_x', I_y', I_z')` or the full tensor in the chapter's convention
//! `[[I_x, -I_xy, -I_xz], [-I_xy, I_y, -I_yz], [-I_xz, -I_yz, I_z]]`.
//!
//! `H = [I] ω` and `T = ½ ωᵀ [I] ω`. Euler's equations need `[I]⁻¹`, so on top of the
//! physical admissibility checks a body whose smallest principal moment is zero (an ideal
//! slender rod) is refused.

use crate::mechanics::principal_axes::principal_axes;
use crate::mechanics::validation::{
    validate_inertia_tensor, validate_principal_moments, INERTIA_RELATIVE_TOLERANCE,
};
use crate::numeric::error::NumericError;
use crate::numeric::integrators::ode::{constant, to_f64};
use nalgebra::{Matrix3, RealField, Rotation3, Vector3};

/// Inertia of a rigid body about its mass centre (or a fixed point), in body-frame axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BodyInertia<T: RealField + Copy> {
    /// Principal moments `(I_x', I_y', I_z')`: the body axes are principal axes.
    Principal(Vector3<T>),
    /// The full tensor, chapter convention (products of inertia enter with a minus sign).
    Tensor(Matrix3<T>),
}

/// Principal moments and the rotation from the principal frame to the body frame, in the
/// working scalar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalFrame<T: RealField + Copy> {
    /// Principal moments `(I_x', I_y', I_z')`.
    pub moments: Vector3<T>,
    /// Columns: the principal axes in body-frame components (`r_body = R r_principal`).
    pub rotation: Rotation3<T>,
}

/// Euler's equations divide by the principal moments: each must be positive, above
/// [`INERTIA_RELATIVE_TOLERANCE`] times their sum (a body on a line has no defined spin about
/// its own axis). The moments are assumed admissible already.
pub fn require_invertible(moments: &Vector3<f64>) -> Result<(), NumericError> {
    let smallest = moments.min();
    if smallest <= INERTIA_RELATIVE_TOLERANCE * moments.sum() {
        return Err(NumericError::InvalidInput {
            what: "inertia".to_string(),
            reason: format!(
                "the smallest principal moment is {smallest:e}; Euler's equations need an \
                 invertible inertia tensor (every principal moment positive)"
            ),
        });
    }
    Ok(())
}

/// The initial values of a torque-free body in principal axes: admissible, invertible moments
/// and a finite angular velocity and orientation.
pub fn validate_free_body(
    moments: &Vector3<f64>,
    omega0: &Vector3<f64>,
    q0: &nalgebra::UnitQuaternion<f64>,
) -> Result<(), NumericError> {
    crate::mechanics::validation::validate_principal_moments(moments)?;
    require_invertible(moments)?;
    let not_finite = |what: &str, value: String| NumericError::InvalidInput {
        what: what.into(),
        reason: format!("{value} is not finite"),
    };
    if omega0.iter().any(|w| !w.is_finite()) {
        return Err(not_finite(
            "initial angular velocity",
            format!("{omega0:?}"),
        ));
    }
    if q0.coords.iter().any(|c| !c.is_finite()) {
        return Err(not_finite("initial orientation", format!("{q0:?}")));
    }
    Ok(())
}

impl<T: RealField + Copy> BodyInertia<T> {
    /// Checks that the body can exist (finite, triangle inequality, positive semidefinite)
    /// and that `[I]` is invertible (smallest principal moment above
    /// [`INERTIA_RELATIVE_TOLERANCE`] times the trace).
    pub fn validate(&self) -> Result<(), NumericError> {
        let moments = match self {
            BodyInertia::Principal(moments) => {
                let moments = moments.map(to_f64);
                validate_principal_moments(&moments)?;
                moments
            }
            BodyInertia::Tensor(tensor) => {
                let tensor = tensor.map(to_f64);
                validate_inertia_tensor(&tensor)?;
                tensor.symmetric_eigenvalues()
            }
        };
        require_invertible(&moments)
    }

    /// Angular momentum `H = [I] ω`, body-frame components.
    pub fn angular_momentum(&self, omega: &Vector3<T>) -> Vector3<T> {
        match self {
            BodyInertia::Principal(moments) => moments.component_mul(omega),
            BodyInertia::Tensor(tensor) => tensor * omega,
        }
    }

    /// `|H_G| = |[I] ω|`, scaled by its largest component before squaring, so that a
    /// magnitude near the top of the range (4e299) does not overflow in its squares.
    pub fn angular_momentum_magnitude(&self, omega: &Vector3<T>) -> T {
        let h = self.angular_momentum(omega);
        let largest = h.amax();
        if largest == T::zero() || !largest.is_finite() {
            return largest;
        }
        (h / largest).norm() * largest
    }

    /// Kinetic energy of rotation `T = ½ ω · [I] ω`.
    pub fn kinetic_energy(&self, omega: &Vector3<T>) -> T {
        omega.dot(&self.angular_momentum(omega)) * constant(0.5)
    }

    /// The principal frame: the identity for [`BodyInertia::Principal`], otherwise
    /// [`principal_axes`] of the tensor (computed in f64). Validate first.
    pub fn principal_frame(&self) -> Result<PrincipalFrame<T>, NumericError> {
        match self {
            BodyInertia::Principal(moments) => Ok(PrincipalFrame {
                moments: *moments,
                rotation: Rotation3::identity(),
            }),
            BodyInertia::Tensor(tensor) => {
                let axes = principal_axes(&tensor.map(to_f64))?;
                Ok(PrincipalFrame {
                    moments: axes.moments.map(constant),
                    rotation: Rotation3::from_matrix_unchecked(
                        axes.rotation.matrix().map(constant),
                    ),
                })
            }
        }
    }
}
