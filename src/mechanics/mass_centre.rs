//! The mass and mass centre of a body made of parts:
//!
//! ```text
//! m = Σ mᵢ,        r̄ = Σ mᵢ r̄ᵢ / m
//! ```
//!
//! where `r̄ᵢ` is the position of part i's mass centre from O. What `ΣF = m ā` needs of the
//! body when the moments are taken about a fixed point O (no inertia about G).

use super::derivation::{Derivation, Relation, Step};
use super::inertia::MassPart;
use crate::algebra::{AlgebraError, Axis, Expr, Vector};

/// The total mass and the position of the mass centre G from O.
#[derive(Debug, Clone, PartialEq)]
pub struct MassCentre {
    pub mass: Expr,
    pub centroid: Vector,
}

/// `m = Σ mᵢ` and `r̄ = Σ mᵢ r̄ᵢ / m`, with the step that shows them. A total mass that is
/// zero is refused ([`AlgebraError::DivisionByZero`]).
///
/// A rod of mass m₁ along x from O (centre at `a/2`) and a particle m₂ at `(a, b, 0)`:
/// `x̄ = (m₁ a/2 + m₂ a)/(m₁ + m₂)`, `ȳ = m₂ b/(m₁ + m₂)`.
///
/// ```
/// use kinetics::mechanics::{inertia::MassPart, mass_centre::mass_centre};
/// use kinetics::{parse_expression, Expr, InertiaTensor, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// let part = |m: &str, x: &str, y: &str| MassPart {
///     mass: hand(m),
///     position: Vector::new(hand(x), hand(y), Expr::zero()),
///     inertia: InertiaTensor::diagonal([(); 3].map(|_| Expr::zero())),
/// };
/// let (g, _steps) = mass_centre(&[part("m_1", "a/2", "0"), part("m_2", "a", "b")])?;
/// assert_eq!(g.mass, hand("m_1 + m_2"));
/// assert_eq!(g.centroid[0], hand("(m_1 a/2 + m_2 a)/(m_1 + m_2)"));
/// assert_eq!(g.centroid[1], hand("m_2 b/(m_1 + m_2)"));
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn mass_centre(parts: &[MassPart]) -> Result<(MassCentre, Derivation), AlgebraError> {
    let mass = Expr::add_all(parts.iter().map(|p| p.mass.clone())).expand()?;
    let first_moment = first_moment(parts);
    let centroid = Vector::from_iterator(
        first_moment
            .iter()
            .map(|x| x.checked_div(&mass)?.expand())
            .collect::<Result<Vec<_>, _>>()?,
    );
    let relations = [
        vec![Relation::new(Expr::symbol("m_body"), mass.clone(), Axis::X)],
        Relation::components("rbar", &centroid),
    ]
    .concat();
    let derivation = Derivation {
        name: "mass_centre".into(),
        title: "mass and mass centre".into(),
        steps: vec![Step::new(
            r"mass and mass centre of the body, $m = \Sigma m_i$, $\bar{\mathbf{r}} = \Sigma m_i \bar{\mathbf{r}}_i / m$",
            relations,
        )],
    };
    Ok((MassCentre { mass, centroid }, derivation))
}

/// `Σ mᵢ r̄ᵢ`, the first moment of the parts' masses about O (`m r̄`).
pub fn first_moment(parts: &[MassPart]) -> Vector {
    parts
        .iter()
        .fold(Vector::from_element(Expr::zero()), |acc, p| {
            acc + p.position.map(|x| &p.mass * &x)
        })
}
