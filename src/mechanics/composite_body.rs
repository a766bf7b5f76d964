//! A body made of parts: its mass, mass centre and centroidal inertia.
//!
//! ```text
//! m = Σ mᵢ,        r̄ = Σ mᵢ r̄ᵢ / m,
//! [Ī] = Σ [Īᵢ moved to O] − [a point mass m at r̄, about O]      (parallel-axis theorem)
//! ```
//!
//! Each part's centroidal tensor is moved to the common origin O, the tensors are added, and
//! the sum is moved back to the body's mass centre G. Products of inertia are the positive
//! integrals `∫xy dm` throughout. A body of several parts shows each part's contribution
//! about G (`Īᵢ` moved by `r̄ᵢ − r̄`) in a table before the sums.

use super::derivation::{Derivation, Step};
use super::inertia::{InertiaTensor, MassPart};
use super::mass_centre::{mass_centre, MassCentre};
use super::parts_table::{parts_table, Columns};
use crate::algebra::{AlgebraError, Expr, Vector};

/// The body as a whole: mass, position of the mass centre G from O, inertia about G.
#[derive(Debug, Clone, PartialEq)]
pub struct MassProperties {
    pub mass: Expr,
    pub centroid: Vector,
    pub inertia: InertiaTensor,
}

/// The step of a body of several parts: the parallel-axis sums its relations are.
const PARTS_TITLE: &str = r"mass, mass centre and centroidal inertia: $\bar{I}_x = \Sigma(\bar{I}_{x'} + m((y - \bar{y})^2 + (z - \bar{z})^2))$, $\bar{I}_{xy} = \Sigma(\bar{I}_{x'y'} + m(x - \bar{x})(y - \bar{y}))$ ($I_{xy} = \int xy\,dm$)";

/// The step of a body of one part, whose inertia is its shape's.
const ONE_PART_TITLE: &str = r"mass, mass centre and centroidal inertia ($I_{xy} = \int xy\,dm$)";

/// The mass, mass centre and centroidal inertia of the parts together, with the step that
/// shows them. A total mass that is zero is refused ([`AlgebraError::DivisionByZero`]): the
/// mass centre is `Σ mᵢ r̄ᵢ / m`.
///
/// Two particles of mass m at `(a, 0, 0)` and `(0, b, 0)`: G is midway, at `(a/2, b/2, 0)`,
/// and from G they sit at `±(a/2, -b/2, 0)`, so `I_x = 2m(b/2)² = m b²/2`, `I_y = m a²/2`,
/// `I_z = m(a² + b²)/2` and `I_xy = Σ m x y = 2m(a/2)(-b/2) = -m a b/2`.
///
/// ```
/// use kinetics::mechanics::{composite_body::composite_body, inertia::MassPart};
/// use kinetics::{parse_expression, Expr, InertiaTensor, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// let particle = |x: &str, y: &str| MassPart {
///     mass: hand("m"),
///     position: Vector::new(hand(x), hand(y), Expr::zero()),
///     inertia: InertiaTensor::diagonal([(); 3].map(|_| Expr::zero())),
/// };
/// let (body, _steps) = composite_body(&[particle("a", "0"), particle("0", "b")])?;
/// assert_eq!(body.mass, hand("2 m"));
/// assert_eq!(body.centroid, Vector::new(hand("a/2"), hand("b/2"), Expr::zero()));
/// let moments = ["m b^2/2", "m a^2/2", "m (a^2 + b^2)/2"].map(hand);
/// assert_eq!(body.inertia.moments, moments);
/// assert_eq!(body.inertia.products, ["-m a b/2", "0", "0"].map(hand));
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn composite_body(parts: &[MassPart]) -> Result<(MassProperties, Derivation), AlgebraError> {
    let (MassCentre { mass, centroid }, centre) = mass_centre(parts)?;
    let inertia = InertiaTensor::composite(parts, &mass, &centroid)?;
    // The table lists what a student looks up for each part, its mass, position and own
    // centroidal moments and products; the relations are their sums by the parallel-axis
    // theorem (each part's contribution about G in full is longer than the sum itself).
    let own: Vec<InertiaTensor> = parts.iter().map(|p| p.inertia.clone()).collect();
    let relations = [centre.result().to_vec(), inertia.relations()].concat();
    let derivation = Derivation {
        name: "body".into(),
        title: "mass, mass centre and centroidal inertia".into(),
        steps: vec![Step {
            vectors: Vec::new(),
            table: parts_table(parts, &own, Columns::OwnCentroidal),
            title: if parts.len() > 1 {
                PARTS_TITLE.into()
            } else {
                ONE_PART_TITLE.into()
            },
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
