//! `cancel`, `together` and `factor_terms`: the examples of issue 15 and, on random
//! rational functions, the value kept at random points in double-double.

use crate::common::expression_tree::{config, point, tree, Tree};
use kinetics::algebra::{AlgebraError, Expr, Symbol};
use kinetics::numeric::rounding_error::bounded;
use kinetics::numeric::scalar::double_double::DoubleDouble as Dd;
use kinetics::parse_expression;
use proptest::prelude::*;
use std::time::{Duration, Instant};

fn parse(text: &str) -> Expr {
    parse_expression("test", text).unwrap()
}

#[test]
fn sums_over_one_denominator_cancel() {
    assert_eq!(
        parse("m1*d/(m1+m2) + m2*d/(m1+m2)").cancel().unwrap(),
        parse("d")
    );
    assert_eq!(
        parse("m1*d/(m1+m2) + m2*d/(m1+m2)").together().unwrap(),
        parse("d")
    );
}

#[test]
fn a_difference_of_squares_over_its_factor_cancels() {
    assert_eq!(parse("(a^2-b^2)/(a-b)").cancel().unwrap(), parse("a + b"));
}

#[test]
fn a_reciprocal_of_reciprocals_is_one_fraction() {
    let e = parse("1/(1/a + 1/b)");
    assert_eq!(e.together().unwrap(), parse("a*b/(a + b)"));
    assert_eq!(e.cancel().unwrap(), parse("a*b/(a + b)"));
}

/// The free box struck at a corner: cancel gives the expanded parts; `factor_terms` of it
/// the textbook's structure, exactly.
#[test]
fn the_free_box_solution_in_lowest_terms() {
    let e = parse("F_2*Dt*b/(2*(-1/12*m*b^2 - 1/12*m*c^2))");
    let (p, q) = e.cancelled_parts().unwrap();
    assert_eq!(p, parse("-6*F_2*Dt*b"));
    assert_eq!(q, parse("m*b^2 + m*c^2"));
    let cancelled = e.cancel().unwrap();
    assert_eq!(cancelled, parse("-6*F_2*Dt*b/(m*b^2 + m*c^2)"));
    assert_eq!(
        cancelled.factor_terms().unwrap(),
        parse("-6*F_2*Dt*b/(m*(b^2 + c^2))")
    );
}

#[test]
fn common_factors_come_out_with_the_numbers_in_front() {
    assert_eq!(
        parse("-1/12*m*b^2 - 1/12*m*c^2").factor_terms().unwrap(),
        parse("-1/12*m*(b^2 + c^2)")
    );
    assert_eq!(
        parse("x/a + y/a").factor_terms().unwrap(),
        parse("(x + y)/a")
    );
    assert_eq!(
        parse("2*x*y + 4*x*z").factor_terms().unwrap(),
        parse("2*x*(y + 2*z)")
    );
    assert_eq!(
        parse("a*(b^2 - c^2) + d*(b + c)").factor_terms().unwrap(),
        parse("(b + c)*(a*b - a*c + d)")
    );
    // Not shorter with the gcd out: left as it is.
    let e = parse("a*(b + c) + b^2 + 2*b*c + c^2");
    assert_eq!(e.factor_terms().unwrap(), e);
}

#[test]
fn cancelled_parts_have_integer_coefficients_and_a_positive_denominator() {
    let (p, q) = parse("(x/2 + 1/3)/(1 - y)").cancelled_parts().unwrap();
    assert_eq!((p, q), (parse("-3*x - 2"), parse("6*y - 6")));
    assert_eq!(
        parse("0/(x + 1)").cancelled_parts().unwrap(),
        (parse("0"), parse("1"))
    );
}

#[test]
fn generators_are_functions_and_roots() {
    assert_eq!(
        parse("(sin(t)^2 - cos(t)^2)/(sin(t) + cos(t))")
            .cancel()
            .unwrap(),
        parse("sin(t) - cos(t)")
    );
    assert_eq!(parse("x^(3/2)/x").cancel().unwrap(), parse("sqrt(x)"));
    assert_eq!(
        parse("(a^2 + b^2)/sqrt(a^2 + b^2)").cancel().unwrap(),
        parse("(a^2 + b^2)/sqrt(a^2 + b^2)").cancel().unwrap(),
    );
}

#[test]
fn zero_denominators_are_refused() {
    assert_eq!(
        parse("1/((a+b)^2 - a^2 - 2*a*b - b^2)").cancel(),
        Err(AlgebraError::DivisionByZero)
    );
}

/// Large inputs finish well within a second or are refused quickly.
#[test]
fn large_inputs_are_bounded() {
    let within = |text: &str| {
        let start = Instant::now();
        let result = parse(text).cancel();
        assert!(
            start.elapsed() < Duration::from_secs(1),
            "{text} took {:?}",
            start.elapsed()
        );
        result
    };
    assert_eq!(within("(a+b)^999/(a+b)^998").unwrap(), parse("a + b"));
    assert_eq!(
        within("(a+b)^60/(a^2+2*a*b+b^2)^29").unwrap(),
        parse("a^2 + 2*a*b + b^2")
    );
    assert!(within("(a+b+c+d+e)^200/(a+b)").is_err());
    assert!(within("(a+b)^99999999/(a-b)").is_err());
}

const NAMES: [&str; 5] = ["a", "b", "m", "Dt", "theta"];

/// The value of `e` in double-double at `x`, none where it has none.
fn value(e: &Expr, x: &[f64]) -> Option<Dd> {
    e.eval(&|s: Symbol| {
        NAMES
            .iter()
            .position(|n| Symbol::new(n) == s)
            .map(|i| Dd::from(x[i]))
    })
    .ok()
}

/// `transformed` has the value of `t`'s expression at `x`, to about 24 digits of the
/// magnitude of the terms of both, beyond the bound on each side's own rounding in
/// double-double (a sum that cancels, such as `(b + 7/4)^6` multiplied out near b = −7/4,
/// loses digits that no transformation can keep).
fn keeps_value(
    t: &Tree,
    x: &[f64],
    transform: fn(&Expr) -> Result<Expr, AlgebraError>,
) -> Result<(), TestCaseError> {
    if t.value(x).is_none() {
        return Err(TestCaseError::reject("no reference value here"));
    }
    let Some(e) = t.build(&NAMES) else {
        return Err(TestCaseError::reject("divides by an exact zero"));
    };
    let Some(before) = value(&e, x) else {
        return Err(TestCaseError::reject("no value here"));
    };
    let after = match transform(&e) {
        Ok(after) => after,
        Err(AlgebraError::TooMuchWork { .. } | AlgebraError::TooLarge { .. }) => {
            return Err(TestCaseError::reject("too large"))
        }
        Err(err) => return Err(TestCaseError::fail(format!("{e}: {err}"))),
    };
    let Some(got) = value(&after, x) else {
        return Err(TestCaseError::fail(format!(
            "{e} -> {after}: no value at {x:?}"
        )));
    };
    let magnitude: f64 = e
        .terms()
        .iter()
        .chain(after.terms())
        .filter_map(|t| value(t, x))
        .map(|v| v.to_f64().abs())
        .sum();
    let rounding = |e: &Expr| {
        bounded(e, &|s: Symbol| {
            NAMES
                .iter()
                .position(|n| Symbol::new(n) == s)
                .map(|i| Dd::from(x[i]))
        })
        .map_or(0.0, |b| b.error)
    };
    let tolerance =
        1e-24 * (1.0 + before.to_f64().abs() + magnitude) + rounding(&e) + rounding(&after);
    let error = (got - before).to_f64().abs();
    prop_assert!(error <= tolerance, "{e} -> {after}: {before:?} vs {got:?}");
    Ok(())
}

proptest! {
    #![proptest_config(config(2_000))]

    #[test]
    fn cancel_keeps_the_value(t in tree(NAMES.len()), x in point(NAMES.len())) {
        keeps_value(&t, &x, Expr::cancel)?;
    }

    #[test]
    fn together_keeps_the_value(t in tree(NAMES.len()), x in point(NAMES.len())) {
        keeps_value(&t, &x, Expr::together)?;
    }

    #[test]
    fn factor_terms_keeps_the_value(t in tree(NAMES.len()), x in point(NAMES.len())) {
        keeps_value(&t, &x, Expr::factor_terms)?;
    }
}
