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
///
/// A compound pendulum: a body turning about the fixed axis z through O, G at `r̄ = L i`,
/// its weight `-m g j` at G and the pin's reaction A at O. With `ā = -L w² i + L α j` and
/// `Ḣ_G = I_z α k`: `ΣF = m ā` gives `A_x = -m L w²`, `A_y - m g = m L α`, `A_z = 0`, and
/// `ΣM_O = Ḣ_G + r̄ × m ā` gives `-m g L = I_z α + m L² α` (its x and y read `0 = 0`).
///
/// ```
/// use kinetics::mechanics::equations_of_motion::{equations_of_motion, Loads, MomentCentre};
/// use kinetics::mechanics::{composite_body::MassProperties, resultant::AppliedForce};
/// use kinetics::{parse_expression, Expr, InertiaTensor, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// let vector = |x: &str, y: &str, z: &str| Vector::new(hand(x), hand(y), hand(z));
/// let (l_i, origin) = (vector("L", "0", "0"), vector("0", "0", "0"));
/// let (weight, pin) = (vector("0", "-m g", "0"), vector("A_x", "A_y", "A_z"));
/// let forces = [
///     AppliedForce { value: &weight, point: &l_i },
///     AppliedForce { value: &pin, point: &origin },
/// ];
/// let body = MassProperties {
///     mass: hand("m"),
///     centroid: l_i.clone(),
///     inertia: InertiaTensor::principal(),
/// };
/// let motion = equations_of_motion(
///     &body,
///     &vector("-L w^2", "L alpha", "0"),
///     &vector("0", "0", "I_z alpha"),
///     Loads { forces: &forces, couples: &[] },
///     MomentCentre::FixedPoint,
/// )?;
/// let residuals: Vec<Expr> = motion
///     .result()
///     .iter()
///     .map(|r| r.residual().expand().unwrap())
///     .collect();
/// let by_hand = [
///     "A_x + m L w^2",
///     "A_y - m g - m L alpha",
///     "A_z",
///     "-m g L - I_z alpha - m L^2 alpha",
/// ];
/// assert_eq!(residuals, by_hand.map(hand));
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
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
            table: None,
            title: format!(
                r"equations of motion: $\Sigma\mathbf{{F}} = m\bar{{\mathbf{{a}}}}$ ($x, y, z$), then $\Sigma\mathbf{{M}}_{point} = \dot{{\mathbf{{H}}}}_G + \bar{{\mathbf{{r}}}} \times m\bar{{\mathbf{{a}}}}$ ($x, y, z$)"
            ),
            relations: [
                Relation::nonzero_components(&forces, &ma),
                Relation::nonzero_components(&moments, &rate),
            ]
            .concat(),
        }],
    })
}
