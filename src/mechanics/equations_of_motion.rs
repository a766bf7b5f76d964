//! The equations of motion of a rigid body in three dimensions (§18.5):
//!
//! ```text
//! ΣF   = m ā                           (x, y, z)
//! ΣM_P = Ḣ_G + r̄_{G/P} × m ā          (x, y, z)
//! ```
//!
//! about P = G (then `r̄_{G/P} = 0` and `ΣM_G = Ḣ_G`), or about a fixed point O, where
//! `r̄_{G/O} = r̄`. Components that read `0 = 0` are left out.

use super::composite_body::MassProperties;
use super::derivation::{Derivation, Relation, Step};
use super::linear_momentum::effective_force;
use super::resultant::{resultant_force, resultant_moment, AppliedForce};
use crate::algebra::vector::expand_each;
use crate::algebra::vector_products::cross;
use crate::algebra::{AlgebraError, Expr, Vector};

/// The point the moments are taken about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MomentCentre {
    /// The mass centre G.
    MassCentre,
    /// The fixed point O, the origin.
    FixedPoint,
}

/// The loads on the body: forces at their points, and couples.
#[derive(Debug, Clone, Copy)]
pub struct Loads<'a> {
    pub forces: &'a [AppliedForce<'a>],
    pub couples: &'a [Vector],
}

/// `ΣF = m ā` and `ΣM_P = Ḣ_G + r̄_{G/P} × m ā`, given the body, the acceleration `abar` of
/// its mass centre and the rate `hdot_g` of its angular momentum about G.
pub fn equations_of_motion(
    body: &MassProperties,
    abar: &Vector,
    hdot_g: &Vector,
    loads: Loads,
    about: MomentCentre,
) -> Result<Derivation, AlgebraError> {
    let (point, reference) = match about {
        MomentCentre::MassCentre => ("G", body.centroid.clone()),
        MomentCentre::FixedPoint => ("O", Vector::from_element(Expr::zero())),
    };
    let forces = resultant_force(loads.forces)?;
    let moments = resultant_moment(loads.forces, loads.couples, &reference)?;
    let ma = effective_force(&body.mass, abar)?;
    let rate = expand_each(&(hdot_g + cross(&(&body.centroid - &reference), &ma)))?;
    Ok(Derivation {
        name: "motion".into(),
        title: "equations of motion".into(),
        steps: vec![Step {
            title: format!(
                "equations of motion: ΣF = m ā (x, y, z), then ΣM_{point} = Ḣ_G + r̄ × m ā (x, y, z)"
            ),
            relations: [
                Relation::nonzero_components(&forces, &ma),
                Relation::nonzero_components(&moments, &rate),
            ]
            .concat(),
        }],
    })
}
