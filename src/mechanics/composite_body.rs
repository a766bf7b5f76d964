//! A body made of parts: its mass, mass centre and centroidal inertia.
//!
//! ```text
//! m = Σ mᵢ,        r̄ = Σ mᵢ r̄ᵢ / m,
//! [Ī] = Σ [Īᵢ moved to O] − [a point mass m at r̄, about O]      (parallel-axis theorem)
//! ```
//!
//! Each part's centroidal tensor is moved to the common origin O, the tensors are added, and
//! the sum is moved back to the body's mass centre G. Products of inertia are the positive
//! integrals `∫xy dm` throughout.

use super::derivation::{Derivation, Relation, Step};
use super::inertia::InertiaTensor;
use crate::algebra::{AlgebraError, Axis, Expr, Vector};

/// A part of a body: its mass, the position of its mass centre from O, and its centroidal
/// inertia in the frame's axes.
#[derive(Debug, Clone, PartialEq)]
pub struct MassPart {
    pub mass: Expr,
    pub position: Vector,
    pub inertia: InertiaTensor,
}

/// The body as a whole: mass, position of the mass centre G from O, inertia about G.
#[derive(Debug, Clone, PartialEq)]
pub struct MassProperties {
    pub mass: Expr,
    pub centroid: Vector,
    pub inertia: InertiaTensor,
}

/// The mass, mass centre and centroidal inertia of the parts together, with the step that
/// shows them. A total mass that is zero is refused ([`AlgebraError::DivisionByZero`]): the
/// mass centre is `Σ mᵢ r̄ᵢ / m`.
pub fn composite_body(parts: &[MassPart]) -> Result<(MassProperties, Derivation), AlgebraError> {
    let mass = Expr::add_all(parts.iter().map(|p| p.mass.clone())).expand()?;
    let first_moment = parts
        .iter()
        .fold(Vector::from_element(Expr::zero()), |acc, p| {
            acc + p.position.map(|x| &p.mass * &x)
        });
    let centroid = Vector::from_iterator(
        first_moment
            .iter()
            .map(|x| x.checked_div(&mass)?.expand())
            .collect::<Result<Vec<_>, _>>()?,
    );
    let inertia = InertiaTensor::composite(parts, &mass, &centroid)?;
    let s = Expr::symbol;
    let relations = [
        vec![Relation::new(s("m_body"), mass.clone(), Axis::X)],
        Relation::components("rbar", &centroid),
        [("I_x", 0), ("I_y", 1), ("I_z", 2)]
            .map(|(n, k)| Relation::new(s(n), inertia.moments[k].clone(), Axis::X))
            .to_vec(),
        [("I_xy", 0), ("I_yz", 1), ("I_xz", 2)]
            .map(|(n, k)| Relation::new(s(n), inertia.products[k].clone(), Axis::X))
            .to_vec(),
    ]
    .concat();
    let derivation = Derivation {
        name: "body".into(),
        title: "mass, mass centre and centroidal inertia".into(),
        steps: vec![Step {
            title: "mass, mass centre and centroidal inertia of the body (products of inertia positive, ∫xy dm)".into(),
            relations,
        }],
    };
    Ok((
        MassProperties {
            mass,
            centroid,
            inertia,
        },
        derivation,
    ))
}
