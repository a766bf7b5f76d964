//! `simplify`, the shortest form: the issue's inputs through the binary, the bound on a
//! large input, and on random expressions the value kept (in double-double) and the
//! operation count never grown.

use crate::common::binary::kinetics;
use crate::common::expression_tree::{config, point, tree};
use kinetics::algebra::{Domains, Expr, Symbol};
use kinetics::numeric::scalar::double_double::DoubleDouble as Dd;
use kinetics::parse_expression;
use proptest::prelude::*;

fn simplified(input: &str) -> String {
    let (code, stdout, stderr) = kinetics(&["simplify", input]);
    assert_eq!(code, 0, "{input}: {stderr}");
    stdout.trim().to_string()
}

/// The five inputs of the issue, each with the value it names, as `kinetics simplify`
/// prints them.
#[test]
fn the_issues_inputs_give_what_a_person_would_write() {
    assert_eq!(simplified("m1*d/(m1+m2) + m2*d/(m1+m2)"), "d");
    assert_eq!(simplified("(a^2-b^2)/(a-b)"), "a + b");
    assert_eq!(simplified("1/(1/a + 1/b)"), "a*b/(a + b)");
    assert_eq!(simplified("sin(x)^2 + cos(x)^2"), "1");
    assert_eq!(simplified("sqrt(a^2)"), "a");
}

/// A denominator is written without a leading minus or a fraction inside it.
#[test]
fn no_minus_or_fraction_below_the_bar() {
    assert_eq!(simplified("a*w_x/(-L^2 - r^2/4)"), "-4*a*w_x/(4*L^2 + r^2)");
}

#[test]
fn the_free_box_unknown_is_in_lowest_terms_with_its_factor_pulled_out() {
    assert_eq!(
        simplified("F_2*Dt*b/(2*(-1/12*m*b^2 - 1/12*m*c^2))"),
        "-6*F_2*Dt*b/(m*(b^2 + c^2))"
    );
}

#[test]
fn domains_trigonometry_and_exact_angles_take_part() {
    assert_eq!(simplified("a*sin(t)^2 + a*cos(t)^2"), "a");
    assert_eq!(simplified("sqrt(4*a^2*b)"), "2*a*sqrt(b)");
    assert_eq!(simplified("abs(m)"), "m");
    assert_eq!(simplified("(a^2)^(1/2)"), "a");
    assert_eq!(simplified("sqrt(x^2)"), "abs(x)");
    assert_eq!(simplified("abs(w_x)"), "abs(w_x)");
    assert_eq!(simplified("cos(90 deg)"), "0");
    assert_eq!(simplified("sin(30 deg)"), "1/2");
    assert_eq!(simplified("2*sin(t)*cos(t)"), "sin(2*t)");
}

/// Sums of different kinematic parts stay term by term, as the textbook writes them; a
/// mass property is factored, its numbers in front.
#[test]
fn kinematic_groups_stay_apart_and_mass_properties_are_factored() {
    assert_eq!(simplified("1/2*m*v^2 + 1/2*I*w^2"), "1/2*m*v^2 + 1/2*I*w^2");
    assert_eq!(simplified("1/12*m*b^2 + 1/12*m*c^2"), "1/12*m*(b^2 + c^2)");
    assert_eq!(
        simplified("m_1*L/(2*(m_1 + m_2)) + m_2*L/(m_1 + m_2)"),
        "L*(m_1 + 2*m_2)/(2*(m_1 + m_2))"
    );
    assert_eq!(
        simplified("(m_1^2 + 4*m_1*m_2)/(12*m_1 + 12*m_2)"),
        "m_1*(m_1 + 4*m_2)/(12*(m_1 + m_2))"
    );
}

/// A sum below the line that holds an angle (a top's θ̈, φ̈ solved from its equations) is
/// the coefficient's, not the kinematic part's: each rate's coefficient reduces on its own.
/// By hand, −¼ m r² sin θ − m L² sin θ = −¼ m (r² + 4L²) sin θ, so
/// −m r² ψ̇ θ̇/(2 · that) = 2 r² ψ̇ θ̇/((r² + 4L²) sin θ) and 2 m L² φ̇ θ̇ cos θ/that =
/// −8 L² φ̇ θ̇ cos θ/((r² + 4L²) sin θ).
#[test]
fn a_denominator_holding_an_angle_reduces_with_the_coefficient() {
    let denominator = "(-1/4*m*r^2*sin(theta) - m*L^2*sin(theta))";
    assert_eq!(
        simplified(&format!(
            "-m*r^2*psidot*thetadot/(2*{denominator}) + 2*m*L^2*phidot*thetadot*cos(theta)/{denominator}"
        )),
        "2*r^2*psidot*thetadot/((4*L^2 + r^2)*sin(theta)) - 8*L^2*phidot*thetadot*cos(theta)/((4*L^2 + r^2)*sin(theta))"
    );
}

#[test]
fn canonical_and_expanded_forms_remain_on_request() {
    let (_, canonical, _) = kinetics(&["simplify", "--canonical", "(a^2-b^2)/(a-b)"]);
    assert_eq!(canonical.trim(), "(a^2 - b^2)/(a - b)");
    let (_, expanded, _) = kinetics(&["simplify", "--expand", "(a+b)^2"]);
    assert_eq!(expanded.trim(), "a^2 + 2*a*b + b^2");
}

/// A power far past the bounds of expansion is still answered (by its canonical form or a
/// cancellation that needs no expansion), never a hang; a huge flat sum likewise.
#[test]
fn inputs_beyond_the_bounds_are_answered_without_expanding() {
    assert_eq!(simplified("(a+b)^999/(a+b)^998"), "a + b");
    assert_eq!(
        simplified("(a+b)^9223372036854775808"),
        "(a + b)^9223372036854775808"
    );
    let sum = (0..10_000).map(|i| format!("x{i} + ")).collect::<String>() + "y";
    let (code, stdout, _) = kinetics(&["simplify", &sum]);
    assert_eq!(code, 0);
    assert!(stdout.contains("x_9999"));
}

/// The value of an expression at a point in double-double; none near a pole.
fn value_at(e: &Expr, names: &[&str], x: &[f64]) -> Option<Dd> {
    let at = |s: Symbol| {
        names
            .iter()
            .position(|n| Symbol::new(n) == s)
            .map(|i| Dd::from(x[i]))
    };
    e.eval(&at).ok()
}

/// Real names (`x`, `y`, angles) take any sign; positive names (masses, lengths) are
/// given positive values, as the chapter's domains promise.
const REAL: [&str; 3] = ["x", "y", "theta"];
const POSITIVE: [&str; 3] = ["m", "L", "b"];

fn check(
    names: &[&str],
    t: &crate::common::expression_tree::Tree,
    x: &[f64],
) -> Result<(), TestCaseError> {
    if t.value(x).is_none() {
        return Err(TestCaseError::reject("no reference value"));
    }
    let Some(e) = t.build(names) else {
        return Err(TestCaseError::reject("division by an exact zero"));
    };
    let s = e.simplify(&Domains::chapter_defaults()).unwrap();
    prop_assert!(s.operation_count() <= e.operation_count(), "{e} -> {s}");
    let (Some(before), Some(after)) = (value_at(&e, names, x), value_at(&s, names, x)) else {
        return Err(TestCaseError::reject("not finite in double-double"));
    };
    let scale = 1.0 + before.abs().to_f64();
    let difference = (before - after).abs().to_f64();
    prop_assert!(
        difference <= 1e-20 * scale,
        "{e} -> {s}: {before:?} and {after:?} at {x:?}"
    );
    Ok(())
}

proptest! {
    #![proptest_config(config(1_000))]

    #[test]
    fn simplify_keeps_the_value_of_real_symbols(t in tree(REAL.len()), x in point(REAL.len())) {
        check(&REAL, &t, &x)?;
    }

    #[test]
    fn simplify_keeps_the_value_of_positive_symbols(t in tree(POSITIVE.len()), x in point(POSITIVE.len())) {
        let x: Vec<f64> = x.iter().map(|v| v.abs()).collect();
        check(&POSITIVE, &t, &x)?;
    }
}

#[test]
fn the_parsed_and_the_built_free_box_agree() {
    let e = parse_expression("<test>", "F_2*Dt*b/(2*(-1/12*m*b^2 - 1/12*m*c^2))").unwrap();
    let s = e.simplify(&Domains::chapter_defaults()).unwrap();
    let expected = parse_expression("<test>", "-6*F_2*Dt*b/(m*(b^2 + c^2))").unwrap();
    assert_eq!(s, expected);
    assert!(s.operation_count() < e.operation_count());
}
