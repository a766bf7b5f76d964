//! Vectors written with unit vectors: `a i + b j + c k` ↔ the components `(a, b, c)`; and a
//! vector of expressions multiplied out component by component.

use super::error::AlgebraError;
use super::expr::Expr;
use super::symbol::{Role, Symbol};
use super::Vector;

/// The unit vectors `i`, `j`, `k` as expressions.
pub fn unit_vectors() -> [Expr; 3] {
    ["i", "j", "k"].map(Expr::symbol)
}

/// Whether the expression is written with unit vectors.
pub fn has_unit_vectors(e: &Expr) -> bool {
    e.symbols().iter().any(|s| s.role() == Role::UnitVector)
}

/// The components of `a i + b j + c k`. Fails when a term has no unit vector or more than
/// one (a scalar added to a vector, or a product of unit vectors).
pub fn components(e: &Expr) -> Result<Vector, AlgebraError> {
    let is_unit = |s: Symbol| s.role() == Role::UnitVector;
    let mut out = Vector::from_element(Expr::zero());
    for group in e.collect_by(&is_unit)? {
        let index = unit_vectors().iter().position(|u| *u == group.monomial);
        match index {
            Some(k) => out[k] = &out[k] + &group.coefficient,
            None if group.monomial.is_one() => {
                return Err(AlgebraError::NotAVector(format!(
                    "the term {} has no unit vector: a scalar cannot be added to a vector",
                    group.coefficient
                )))
            }
            None => {
                return Err(AlgebraError::NotAVector(format!(
                    "{} multiplies unit vectors; write vector sums like a*i + b*j + c*k",
                    group.monomial
                )))
            }
        }
    }
    Ok(out)
}

/// Each component expanded (multiplied out and gathered), or the expansion's error.
pub fn expand_each(v: &Vector) -> Result<Vector, AlgebraError> {
    Ok(Vector::new(v[0].expand()?, v[1].expand()?, v[2].expand()?))
}
