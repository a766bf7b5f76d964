//! Property tests of the algebra over random expressions (see `common/expression_tree.rs`
//! for what they hold): building an expression in canonical form, expanding it and
//! collecting it keep its value at random points; the canonical and the expanded form are
//! idempotent.
//!
//! Points where the reference value is not a real number or is near a pole are skipped;
//! each property fails if it has to skip more than a quarter as many points as it checks.

use crate::common::expression_tree::{agrees, point, tree, values, Tree};
use kinetics::algebra::{Expr, Symbol, View};
use kinetics::parse::parse_expression;
use proptest::prelude::*;

/// The symbols of the random expressions: lengths, a kinematic symbol and an angle,
/// inertia, mass and an interval.
const NAMES: [&str; 7] = ["a", "b", "w_x", "I_xy", "m", "Dt", "theta"];

/// Cases each property checks.
const CASES: u32 = 20_000;

/// The expression of a tree and its reference value at `x`; the case is skipped when the
/// reference has no value there, and fails when the algebra cannot build an expression
/// whose reference value exists (it divided by an exact zero that is not zero).
fn expression_and_value(t: &Tree, x: &[f64]) -> Result<(Expr, f64), TestCaseError> {
    let Some(expected) = t.value(x) else {
        return Err(TestCaseError::reject("no reference value at this point"));
    };
    match t.build(&NAMES) {
        Some(e) => Ok((e, expected)),
        None => Err(TestCaseError::fail(format!(
            "division by an exact zero, but the reference value is {expected}"
        ))),
    }
}

/// The expression rebuilt from its parts, bottom up, through the public constructors.
fn rebuilt(e: &Expr) -> Expr {
    match e.view() {
        View::Num(_) | View::Sym(_) => e.clone(),
        View::Add(terms) => Expr::add_all(terms.iter().map(rebuilt)),
        View::Mul(factors) => Expr::mul_all(factors.iter().map(rebuilt)),
        View::Pow(base, exponent) => rebuilt(base)
            .checked_pow(&rebuilt(exponent))
            .expect("a canonical power is not zero to a negative power"),
        View::Func(f, arg) => Expr::func(f, rebuilt(arg)),
    }
}

proptest! {
    #![proptest_config(crate::common::expression_tree::config(CASES))]

    /// The canonical form built by the operators has the value of the tree it was built
    /// from, computed without the algebra.
    #[test]
    fn canonical_form_keeps_the_value(t in tree(NAMES.len()), x in point(NAMES.len())) {
        let (e, expected) = expression_and_value(&t, &x)?;
        let checked = agrees(&e, expected, &values(&NAMES, &x));
        prop_assert!(checked.is_ok(), "{}: {}", e, checked.unwrap_err());
    }

    /// Expanding, and collecting by `w_x` and `a` then summing the groups, keep the value.
    #[test]
    fn expanding_and_collecting_keep_the_value(
        t in tree(NAMES.len()),
        x in point(NAMES.len()),
    ) {
        let (e, expected) = expression_and_value(&t, &x)?;
        let value = values(&NAMES, &x);
        let expanded = e.expand().unwrap();
        let checked = agrees(&expanded, expected, &value);
        prop_assert!(checked.is_ok(), "expanded {}: {}", expanded, checked.unwrap_err());
        let by = [Symbol::new("w_x"), Symbol::new("a")];
        let collected: Expr = e
            .collect(&by)
            .unwrap()
            .into_iter()
            .map(|g| g.monomial * g.coefficient)
            .sum();
        let checked = agrees(&collected, expected, &value);
        prop_assert!(checked.is_ok(), "collected {}: {}", collected, checked.unwrap_err());
    }

    /// Making a canonical expression canonical again changes nothing: rebuilding it from
    /// its parts through the constructors, summing its terms, multiplying its factors;
    /// and expanding an expanded expression changes nothing.
    #[test]
    fn canonical_form_is_idempotent(t in tree(NAMES.len())) {
        let Some(e) = t.build(&NAMES) else {
            return Err(TestCaseError::reject("divides by an exact zero"));
        };
        prop_assert_eq!(rebuilt(&e), e.clone());
        prop_assert_eq!(Expr::add_all(e.terms().to_vec()), e.clone());
        prop_assert_eq!(Expr::mul_all(e.factors().to_vec()), e.clone());
        let expanded = e.expand().unwrap();
        prop_assert_eq!(expanded.expand().unwrap(), expanded.clone());
        prop_assert_eq!(rebuilt(&expanded), expanded);
    }
}

/// Polynomials (and expressions with monomial denominators) are equal exactly when their
/// expansions are identical, and decimals are exact rationals.
#[test]
fn polynomials_equal_exactly_when_expansions_are_identical() {
    let p = |s: &str| parse_expression("t", s).unwrap().expand().unwrap();
    assert_eq!(p("(a + b)^2"), p("a^2 + 2 a b + b^2"));
    assert_eq!(p("(a + b)/m"), p("a/m + b/m"));
    assert_ne!(p("(a + b)^2"), p("a^2 + b^2"));
    assert_eq!(p("0.1 + 0.2"), p("3/10"));
}
