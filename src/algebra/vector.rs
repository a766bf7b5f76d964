//! Vectors written with unit vectors: `a i + b j + c k` ↔ the components `(a, b, c)`; and a
//! vector of expressions multiplied out component by component.

use super::error::AlgebraError;
use super::expr::{Expr, View};
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

/// The components of `a i + b j + c k`. Fails, without multiplying anything out, when a
/// unit vector is inside a power or a function (`(3 v - i)^2`, `sin(i)`); and when a term
/// has no unit vector or more than one (a scalar added to a vector, or a product of unit
/// vectors). The messages name no term: the terms are multiplied out, not as written, so
/// the caller points at the text instead.
pub fn components(e: &Expr) -> Result<Vector, AlgebraError> {
    let is_unit = |s: Symbol| s.role() == Role::UnitVector;
    if holds_a_vector_inside(e) {
        return Err(AlgebraError::NotAVector(
            "a power or a function of a vector has no meaning; write the components".into(),
        ));
    }
    let mut out = Vector::from_element(Expr::zero());
    for group in e.collect_by(&is_unit)? {
        let index = unit_vectors().iter().position(|u| *u == group.monomial);
        match index {
            Some(k) => out[k] = &out[k] + &group.coefficient,
            None if group.monomial.is_one() => {
                return Err(AlgebraError::NotAVector(
                    "a term has no unit vector: a scalar cannot be added to a vector".into(),
                ))
            }
            None => {
                return Err(AlgebraError::NotAVector(
                    "a term multiplies unit vectors; write vector sums like a*i + b*j + c*k".into(),
                ))
            }
        }
    }
    Ok(out)
}

/// Whether a unit vector occurs inside a power or a function of `e` (not only in the
/// products and sums a vector is written with).
fn holds_a_vector_inside(e: &Expr) -> bool {
    match e.view() {
        View::Num(_) | View::Sym(_) => false,
        View::Add(xs) | View::Mul(xs) => xs.iter().any(holds_a_vector_inside),
        View::Pow(..) | View::Func(..) => has_unit_vectors(e),
    }
}

/// Each component expanded (multiplied out and gathered), or the expansion's error.
pub fn expand_each(v: &Vector) -> Result<Vector, AlgebraError> {
    Ok(Vector::new(v[0].expand()?, v[1].expand()?, v[2].expand()?))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A power of a vector is refused at once, however large (nothing is multiplied out),
    /// and no message quotes a multiplied-out term.
    #[test]
    fn powers_of_vectors_are_refused_without_expanding() {
        let (v, i) = (Expr::symbol("v"), Expr::symbol("i"));
        let power = (Expr::int(3) * &v - &i).powi(600);
        let err = components(&power).unwrap_err().to_string();
        assert!(err.contains("power or a function of a vector"), "{err}");
        let scalar = (Expr::int(3) * &v + Expr::one()).powi(40) + &i;
        let err = components(&scalar).unwrap_err().to_string();
        assert!(
            err.contains("has no unit vector") && !err.contains('3'),
            "{err}"
        );
        let v = components(&(Expr::int(2) * &i + Expr::symbol("k"))).unwrap();
        assert_eq!(v[0], Expr::int(2));
        assert_eq!(v[2], Expr::one());
    }
}
