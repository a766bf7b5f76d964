//! The equations of motion of a rigid body in three dimensions (§18.5, §18.7):
//!
//! ```text
//! ΣF   = m ā                           (x, y, z)
//! ΣM_G = Ḣ_G                           about the mass centre G
//! ΣM_O = Ḣ_O                           about a fixed point O, Ḣ_O from [I_O] (§18.7)
//! ΣM_O = Ḣ_G + r̄ × m ā                about a fixed point O, the rate taken about G
//! ```
//!
//! where `r̄` is the position of G from O. Components that read `0 = 0` are left out.

use super::derivation::{Derivation, Relation, Step};
use super::linear_momentum::effective_force;
use super::mass_centre::MassCentre;
use super::resultant::{resultant_force, resultant_moment, AppliedForce};
use crate::algebra::vector::expand_each;
use crate::algebra::vector_products::cross;
use crate::algebra::{AlgebraError, Expr, Vector};

/// The point the moments are taken about, and the rate of angular momentum they equal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MomentCentre {
    /// The mass centre G: `ΣM_G = Ḣ_G`.
    MassCentre,
    /// The fixed point O, the origin, with the rate about O: `ΣM_O = Ḣ_O` (the textbook's
    /// route with `[I_O]`).
    FixedPoint,
    /// The fixed point O with the rate about G: `ΣM_O = Ḣ_G + r̄ × m ā` (the centroidal
    /// route, kept when a scene asks for it).
    FixedPointThroughMassCentre,
}

/// The loads on the body: forces at their points, and couples.
#[derive(Debug, Clone, Copy)]
pub struct Loads<'a> {
    pub forces: &'a [AppliedForce<'a>],
    pub couples: &'a [Vector],
}

/// `ΣF = m ā` and the moment equations about the chosen centre, given the body's mass and
/// mass centre, the acceleration `abar` of its mass centre and `rate`, the rate of its
/// angular momentum: `Ḣ_O` for [`MomentCentre::FixedPoint`], `Ḣ_G` otherwise.
///
/// A compound pendulum: a body turning about the fixed axis z through O, G at `r̄ = L i`,
/// its weight `-m g j` at G and the pin's reaction A at O. With `ā = -L w² i + L α j` and
/// `Ḣ_O = (I_z + m L²) α k` (the moment of inertia about O): `ΣF = m ā` gives
/// `A_x = -m L w²`, `A_y - m g = m L α`, `A_z = 0`, and `ΣM_O = Ḣ_O` gives
/// `-m g L = (I_z + m L²) α` (its x and y read `0 = 0`). Through G,
/// `ΣM_O = Ḣ_G + r̄ × m ā` with `Ḣ_G = I_z α k` gives the same.
///
/// ```
/// use kinetics::mechanics::equations_of_motion::{equations_of_motion, Loads, MomentCentre};
/// use kinetics::mechanics::{mass_centre::MassCentre, resultant::AppliedForce};
/// use kinetics::{parse_expression, Expr, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// let vector = |x: &str, y: &str, z: &str| Vector::new(hand(x), hand(y), hand(z));
/// let (l_i, origin) = (vector("L", "0", "0"), vector("0", "0", "0"));
/// let (weight, pin) = (vector("0", "-m g", "0"), vector("A_x", "A_y", "A_z"));
/// let forces = [
///     AppliedForce { value: &weight, point: &l_i },
///     AppliedForce { value: &pin, point: &origin },
/// ];
/// let body = MassCentre { mass: hand("m"), centroid: l_i.clone() };
/// let abar = vector("-L w^2", "L alpha", "0");
/// let loads = Loads { forces: &forces, couples: &[] };
/// let residuals = |rate: &Vector, about: MomentCentre| -> Vec<Expr> {
///     let motion = equations_of_motion(&body, &abar, rate, loads, about).unwrap();
///     motion.result().iter().map(|r| r.residual().expand().unwrap()).collect()
/// };
/// let by_hand = [
///     "A_x + m L w^2",
///     "A_y - m g - m L alpha",
///     "A_z",
///     "-m g L - I_z alpha - m L^2 alpha",
/// ]
/// .map(hand);
/// let hdot_o = vector("0", "0", "(I_z + m L^2) alpha");
/// assert_eq!(residuals(&hdot_o, MomentCentre::FixedPoint), by_hand);
/// let hdot_g = vector("0", "0", "I_z alpha");
/// assert_eq!(residuals(&hdot_g, MomentCentre::FixedPointThroughMassCentre), by_hand);
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn equations_of_motion(
    body: &MassCentre,
    abar: &Vector,
    rate: &Vector,
    loads: Loads,
    about: MomentCentre,
) -> Result<Derivation, AlgebraError> {
    let origin = Vector::from_element(Expr::zero());
    let forces = resultant_force(loads.forces)?;
    let ma = effective_force(&body.mass, abar)?;
    let (reference, moment_rate, title) = match about {
        MomentCentre::MassCentre => (
            &body.centroid,
            rate.clone(),
            r"equations of motion: $\Sigma\mathbf{F} = m\bar{\mathbf{a}}$ ($x, y, z$), then $\Sigma\mathbf{M}_G = \dot{\mathbf{H}}_G$ ($x, y, z$)",
        ),
        MomentCentre::FixedPoint => (
            &origin,
            rate.clone(),
            r"equations of motion: $\Sigma\mathbf{F} = m\bar{\mathbf{a}}$ ($x, y, z$), then $\Sigma\mathbf{M}_O = \dot{\mathbf{H}}_O$ ($x, y, z$)",
        ),
        MomentCentre::FixedPointThroughMassCentre => (
            &origin,
            expand_each(&(rate + cross(&body.centroid, &ma)))?,
            r"equations of motion: $\Sigma\mathbf{F} = m\bar{\mathbf{a}}$ ($x, y, z$), then $\Sigma\mathbf{M}_O = \dot{\mathbf{H}}_G + \bar{\mathbf{r}} \times m\bar{\mathbf{a}}$ ($x, y, z$)",
        ),
    };
    let moments = resultant_moment(loads.forces, loads.couples, reference)?;
    Ok(Derivation {
        name: "motion".into(),
        title: "equations of motion".into(),
        steps: vec![Step::new(
            title,
            [
                Relation::nonzero_components(&forces, &ma),
                Relation::nonzero_components(&moments, &moment_rate),
            ]
            .concat(),
        )],
    })
}
