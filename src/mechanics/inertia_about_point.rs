//! The moments and products of inertia of a body about a fixed point O (§18.7–18.8), the
//! axes through O parallel to the frame's: each part's centroidal tensor moved to O by the
//! parallel-axis theorem, then their sum,
//!
//! ```text
//! I_x  = Σ (Ī_x' + m(ȳ² + z̄²)),      I_y  = Σ (Ī_y' + m(z̄² + x̄²)),      I_z  = Σ (Ī_z' + m(x̄² + ȳ²))
//! I_xy = Σ (Ī_x'y' + m x̄ ȳ),         I_yz = Σ (Ī_y'z' + m ȳ z̄),         I_xz = Σ (Ī_x'z' + m x̄ z̄)
//! ```
//!
//! with `(x̄, ȳ, z̄)` each part's mass centre from O and the products the positive integrals
//! `∫xy dm`. A body of several parts shows each part's contribution in a table first.

use super::derivation::{Derivation, Step};
use super::inertia::{InertiaTensor, MassPart};
use super::parts_table::{parts_table, Columns};
use crate::algebra::AlgebraError;

/// `[I_O]` of the parts together, with the step that shows the parts and the sums.
///
/// A bent rod: arm OA (mass m₁, length a) along x from O, arm AB (mass m₂, length b) along
/// y from A. About O, `I_x = m₂b²/3`, `I_y = m₁a²/3 + m₂a²`, `I_z = m₁a²/3 + m₂(a² + b²/3)`
/// and `I_xy = m₂ a b/2` (AB's centre at `(a, b/2, 0)`).
///
/// ```
/// use kinetics::mechanics::inertia_about_point::inertia_about_fixed_point;
/// use kinetics::mechanics::inertia::MassPart;
/// use kinetics::{parse_expression, Expr, InertiaTensor, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// let arm = |m: &str, x: &str, y: &str, moments: [&str; 3]| MassPart {
///     mass: hand(m),
///     position: Vector::new(hand(x), hand(y), Expr::zero()),
///     inertia: InertiaTensor::diagonal(moments.map(hand)),
/// };
/// let oa = arm("m_1", "a/2", "0", ["0", "m_1 a^2/12", "m_1 a^2/12"]);
/// let ab = arm("m_2", "a", "b/2", ["m_2 b^2/12", "0", "m_2 b^2/12"]);
/// let (about_o, derivation) = inertia_about_fixed_point(&[oa, ab])?;
/// let moments = ["m_2 b^2/3", "m_1 a^2/3 + m_2 a^2", "m_1 a^2/3 + m_2 (a^2 + b^2/3)"];
/// assert_eq!(about_o.moments, moments.map(hand));
/// assert_eq!(about_o.products, ["m_2 a b/2", "0", "0"].map(hand));
/// let table = derivation.steps[0].table.as_ref().expect("two parts: a table");
/// assert_eq!(table.rows.len(), 2);
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn inertia_about_fixed_point(
    parts: &[MassPart],
) -> Result<(InertiaTensor, Derivation), AlgebraError> {
    let about_o = parts
        .iter()
        .map(|p| p.inertia.parallel_axis(&p.mass, &p.position).expanded())
        .collect::<Result<Vec<_>, _>>()?;
    let total = about_o
        .iter()
        .fold(InertiaTensor::zero(), |sum, part| sum.add(part))
        .expanded()?;
    let step = Step {
        vectors: Vec::new(),
        title: r"inertia about $O$ by parallel axes, $I_x = \Sigma(\bar{I}_{x'} + m(\bar{y}^2 + \bar{z}^2))$, $I_{xy} = \Sigma(\bar{I}_{x'y'} + m\bar{x}\bar{y})$".into(),
        table: parts_table(parts, &about_o, Columns::AboutPoint),
        relations: total.relations(),
    };
    Ok((
        total,
        Derivation {
            name: "I_O".into(),
            title: "moments and products of inertia about O".into(),
            steps: vec![step],
        },
    ))
}
