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
use super::mass_centre::{first_moment, mass_centre, MassCentre};
use super::parts_table::parts_table;
use crate::algebra::{AlgebraError, Expr, Vector};

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
    // Each part's offset from G over one denominator, r̄ᵢ − r̄ = (m r̄ᵢ − Σ mⱼ r̄ⱼ)/m, so that
    // its contribution reads in lowest terms.
    let moment = first_moment(parts);
    let per_mass = mass.powi(-1);
    let about_g = parts
        .iter()
        .map(|p| {
            let offset = p
                .position
                .iter()
                .zip(moment.iter())
                .map(|(x, first)| Ok(&(&mass * x - first).expand()? * &per_mass))
                .collect::<Result<Vec<_>, AlgebraError>>()?;
            Ok(p.inertia
                .parallel_axis(&p.mass, &Vector::from_iterator(offset)))
        })
        .collect::<Result<Vec<_>, AlgebraError>>()?;
    let relations = [centre.result().to_vec(), inertia.relations()].concat();
    let derivation = Derivation {
        name: "body".into(),
        title: "mass, mass centre and centroidal inertia".into(),
        steps: vec![Step {
            table: parts_table(parts, &about_g),
            title: r"mass, mass centre and centroidal inertia of the body (products of inertia positive, $\int xy\,dm$)".into(),
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
