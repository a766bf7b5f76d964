//! Property tests of the printers and the parser over random expressions (see
//! `common/expression_tree.rs` for what they hold): the text printer's output parses back to
//! the same expression; what a person types parses to the expression the operators build;
//! the LaTeX is well formed.

use crate::common::expression_tree::{agrees, point, tree, values, Tree};
use kinetics::algebra::{Expr, Func, View};
use kinetics::parse::parse_expression;
use kinetics::print;
use proptest::prelude::*;

/// The symbols of the random expressions: lengths, a kinematic symbol and angle (which the
/// printer groups by), inertia, mass and an interval.
const NAMES: [&str; 7] = ["a", "b", "w_x", "I_xy", "m", "Dt", "theta"];

/// Cases each property checks.
const CASES: u32 = 20_000;

/// The expression of a tree; the case is skipped when building it divides by an exact zero.
fn built(t: &Tree) -> Result<Expr, TestCaseError> {
    t.build(&NAMES)
        .ok_or_else(|| TestCaseError::reject("divides by an exact zero"))
}

/// The expression with the sign of each sum under a function or a negative whole power
/// taken out, so that the sum starts (in canonical order) with a positive term:
/// `sin(-a - b)` becomes `-sin(a + b)`, `1/(-a - b)` becomes `-1/(a + b)`.
///
/// The algebra leaves that sign where it finds it. A number times a sum is distributed,
/// but the number times a product holding a sum is not, so `((-1)(a + 1)) a` built by the
/// operators is `a (-a - 1)` while the parser, which reads the nested product as one,
/// gives `-a (a + 1)`. Expanding makes the two equal, except where the sum stands under a
/// function or in a denominator, where the expanded form does not decide equality
/// (ARCHITECTURE.md, invariants: it decides it for polynomials and monomial denominators).
fn up_to_the_signs_of_sums(e: &Expr) -> Expr {
    let negative_sum =
        |e: &Expr| matches!(e.view(), View::Add(_)) && e.terms()[0].coefficient().is_negative();
    match e.view() {
        View::Num(_) | View::Sym(_) => e.clone(),
        View::Add(terms) => Expr::add_all(terms.iter().map(up_to_the_signs_of_sums)),
        View::Mul(factors) => Expr::mul_all(factors.iter().map(up_to_the_signs_of_sums)),
        View::Pow(base, exponent) => {
            let base = up_to_the_signs_of_sums(base);
            let whole = exponent.as_num().and_then(|q| q.to_i64());
            match whole {
                Some(n) if n < 0 && negative_sum(&base) => Expr::int(-1).powi(n) * (-base).powi(n),
                _ => base.checked_pow(exponent).unwrap(),
            }
        }
        View::Func(f, arg) => {
            let arg = up_to_the_signs_of_sums(arg);
            match (f, negative_sum(&arg)) {
                (Func::Sin | Func::Tan | Func::Atan, true) => -Expr::func(f, -arg),
                (Func::Cos | Func::Abs, true) => Expr::func(f, -arg),
                (Func::Acos, true) | (_, false) => Expr::func(f, arg),
            }
        }
    }
}

/// Whether a sum stands under a negative power somewhere in `e`.
fn has_sum_denominator(e: &Expr) -> bool {
    match e.view() {
        View::Num(_) | View::Sym(_) => false,
        View::Add(xs) | View::Mul(xs) => xs.iter().any(has_sum_denominator),
        View::Pow(base, exponent) => {
            let negative = exponent.as_num().is_some_and(|q| q.is_negative());
            (negative && matches!(base.view(), View::Add(_))) || has_sum_denominator(base)
        }
        View::Func(_, arg) => has_sum_denominator(arg),
    }
}

proptest! {
    #![proptest_config(crate::common::expression_tree::config(CASES))]

    /// The printed text parses back to the same expression, compared after expanding
    /// both. Not compared directly because the printer groups a canonical sum the way a
    /// textbook does: `a*w_x + b*w_x` is printed `(a + b)*w_x`, which parses back to a
    /// product, a different canonical form of the same expression. Expanding multiplies
    /// the group out again, and the expanded form is the one that decides equality
    /// (ARCHITECTURE.md, invariants). Where expanding would not undo a grouping (a sum in
    /// a denominator, a sum under a function that groups with a leading minus), the
    /// printer does not group (`print/layout/`, rules 5 and 6), so the expanded forms
    /// agree for every expression.
    #[test]
    fn text_parses_back_to_the_same_expression(t in tree(NAMES.len())) {
        let e = built(&t)?;
        let printed = print::text(&e);
        let back = parse_expression("printed", &printed);
        prop_assert!(back.is_ok(), "{} does not parse: {:?}", printed, back.err());
        let back = back.unwrap();
        prop_assert_eq!(back.expand().unwrap(), e.expand().unwrap(), "printed as {}", printed);
    }

    /// What a person types (decimals, fractions, products by juxtaposition, `sqrt`, the
    /// functions) parses to the expression the operators build: the same expanded form up
    /// to the signs of sums under functions and negative powers (see
    /// [`up_to_the_signs_of_sums`]). Where a sum stands under a negative power, the
    /// expanded form does not decide equality (the algebra does not cancel `2b - 4` against
    /// `1/(b - 2)`, which the parser may meet as `(b - 2) 2/(b - 2)`), and there the two
    /// must have the same value at a random point instead. Parsing fails, with a located
    /// error, exactly when building divides by zero or takes the tangent at its pole.
    #[test]
    fn typed_input_parses_to_the_built_expression(
        t in tree(NAMES.len()),
        x in point(NAMES.len()),
    ) {
        let input = t.input(&NAMES);
        match (parse_expression("typed", &input), t.build(&NAMES)) {
            (Ok(parsed), Some(e)) => {
                let parsed = up_to_the_signs_of_sums(&parsed.expand().unwrap());
                let e = up_to_the_signs_of_sums(&e.expand().unwrap());
                if parsed != e {
                    prop_assert!(
                        has_sum_denominator(&parsed) || has_sum_denominator(&e),
                        "typed {}: {} against {}", input, parsed, e
                    );
                    let Some(expected) = t.value(&x) else {
                        return Err(TestCaseError::reject("no reference value at this point"));
                    };
                    for side in [&parsed, &e] {
                        let checked = agrees(side, expected, &values(&NAMES, &x));
                        prop_assert!(checked.is_ok(), "typed {}: {}: {}", input, side, checked.unwrap_err());
                    }
                }
            }
            (Err(d), None) => {
                let refused = d.to_string();
                let why = ["division by zero", "the tangent of an odd multiple of 90°"];
                prop_assert!(why.iter().any(|w| refused.contains(w)), "{}", d)
            }
            (Ok(parsed), None) => {
                prop_assert!(false, "{} parses to {} but divides by zero", input, parsed)
            }
            (Err(d), Some(e)) => prop_assert!(false, "{} is {} but does not parse: {}", input, e, d),
        }
    }

    /// The LaTeX never writes `+ -` and its braces balance.
    #[test]
    fn latex_has_no_plus_minus_and_balanced_braces(t in tree(NAMES.len())) {
        let latex = print::latex(&built(&t)?);
        prop_assert!(!latex.contains("+ -"), "{}", latex);
        prop_assert_eq!(latex.matches('{').count(), latex.matches('}').count(), "{}", latex);
    }
}
