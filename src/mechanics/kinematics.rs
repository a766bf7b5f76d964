//! Velocity and acceleration of points of a rigid body (the kinematics the chapter uses):
//!
//! ```text
//! v_P = v_A + ω × r_{P/A}
//! α   = (ω̇)_Oxyz + Ω × ω                      (ω's rates seen in a frame turning at Ω)
//! ā   = α × r̄ + ω × (ω × r̄)                   (O fixed, r̄ the position of G from O)
//! ```

use super::derivation::{Derivation, Relation, Step};
use crate::algebra::vector::expand_each;
use crate::algebra::vector_products::cross;
use crate::algebra::{AlgebraError, Vector};

/// `v_P = v_A + ω × r_{P/A}`: the velocity of the body point at `relative` from A.
pub fn velocity_of_point(
    velocity_of_a: &Vector,
    omega: &Vector,
    relative: &Vector,
) -> Result<Vector, AlgebraError> {
    expand_each(&(velocity_of_a + cross(omega, relative)))
}

/// `v̄ = ω × r̄` for a body turning about the fixed point O.
pub fn velocity_of_mass_centre(
    omega: &Vector,
    centroid: &Vector,
) -> Result<Derivation, AlgebraError> {
    let vbar = expand_each(&cross(omega, centroid))?;
    Ok(Derivation {
        name: "vbar".into(),
        title: "velocity of the mass centre".into(),
        steps: vec![Step {
            table: None,
            title: r"velocity of the mass centre, $\bar{\mathbf{v}} = \boldsymbol{\omega} \times \bar{\mathbf{r}}$ ($O$ fixed)".into(),
            relations: Relation::components("vbar", &vbar),
        }],
    })
}

/// `α = (ω̇)_frame + Ω × ω` and `ā = α × r̄ + ω × (ω × r̄)` for a body turning about the
/// fixed point O; `omega_dot` holds the rates of ω's components seen in the frame, which
/// turns at `frame_rate` (Ω).
pub fn acceleration_of_mass_centre(
    omega: &Vector,
    omega_dot: &Vector,
    frame_rate: &Vector,
    centroid: &Vector,
) -> Result<Derivation, AlgebraError> {
    let alpha = expand_each(&(omega_dot + cross(frame_rate, omega)))?;
    let abar = expand_each(&(cross(&alpha, centroid) + cross(omega, &cross(omega, centroid))))?;
    Ok(Derivation {
        name: "abar".into(),
        title: "acceleration of the mass centre".into(),
        steps: vec![Step {
            table: None,
            title: r"acceleration of the mass centre, $\bar{\mathbf{a}} = \boldsymbol{\alpha} \times \bar{\mathbf{r}} + \boldsymbol{\omega} \times (\boldsymbol{\omega} \times \bar{\mathbf{r}})$, $\boldsymbol{\alpha} = (\dot{\boldsymbol{\omega}})_{\text{frame}} + \boldsymbol{\Omega} \times \boldsymbol{\omega}$".into(),
            relations: [
                Relation::components("alpha", &alpha),
                Relation::components("abar", &abar),
            ]
            .concat(),
        }],
    })
}
