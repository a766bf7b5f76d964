//! The diagnosis of a claim that differs (`check::diagnosis::diagnose`): the terms that are
//! wrong, missing or extra, and the named reading of the slip. For each reading, chapter
//! formulas with the slip (the name and the three lists expected) and a difference the rule
//! must not claim; then the precedence of overlapping rules, claims with denominators, the
//! notes' three slips, the algebra's bounds, and two properties over random expressions.

use crate::common::expression_tree::{agrees, config, point, tree, values, Tree};
use kinetics::algebra::Expr;
use kinetics::check::diagnosis::{diagnose, Diagnosis, READINGS};
use kinetics::parse_expression;
use proptest::prelude::*;

fn expr(text: &str) -> Expr {
    parse_expression("", text).unwrap_or_else(|e| panic!("{text}: {e:?}"))
}

fn sorted(terms: impl IntoIterator<Item = Expr>) -> Vec<Expr> {
    let mut terms: Vec<Expr> = terms.into_iter().collect();
    terms.sort();
    terms
}

/// The differences a case expects: wrong terms (claimed, correct), missing and extra terms.
struct Expected<'a> {
    wrong: &'a [(&'a str, &'a str)],
    missing: &'a [&'a str],
    extra: &'a [&'a str],
}

const NONE: Expected = Expected {
    wrong: &[],
    missing: &[],
    extra: &[],
};

/// Diagnoses `claimed` against `correct` and checks the reading's name and the three lists
/// (each compared as a set of expressions); returns the diagnosis for its explanation.
fn check(claimed: &str, correct: &str, reading: Option<&str>, expected: Expected) -> Diagnosis {
    let d = diagnose(&expr(claimed), &expr(correct)).unwrap();
    let case = format!("{claimed}  against  {correct}: {d:?}");
    assert_eq!(d.reading.as_ref().map(|r| r.name), reading, "{case}");
    let wrong = sorted(
        d.wrong
            .iter()
            .map(|w| Expr::add_all([w.claimed.clone(), -&w.correct])),
    );
    let wrong_expected = sorted(expected.wrong.iter().map(|(c, k)| expr(c) - expr(k)));
    assert_eq!(
        wrong, wrong_expected,
        "wrong terms (claimed - correct) of {case}"
    );
    for w in &d.wrong {
        assert_eq!(w.claimed.monomial(), w.correct.monomial(), "{case}");
    }
    assert_eq!(
        sorted(d.missing.iter().cloned()),
        sorted(expected.missing.iter().map(|t| expr(t))),
        "missing terms of {case}"
    );
    assert_eq!(
        sorted(d.extra.iter().cloned()),
        sorted(expected.extra.iter().map(|t| expr(t))),
        "extra terms of {case}"
    );
    d
}

/// The explanation without the backticks that mark its expressions (checked apart, in
/// `expressions_in_an_explanation_are_marked`).
fn explanation(d: &Diagnosis) -> String {
    d.reading
        .as_ref()
        .expect("a reading")
        .explanation
        .replace('`', "")
}

// The chapter's general-body formulas (`kinetics derive --general`).
const H_X: &str = "I_x*w_x - I_xy*w_y - I_xz*w_z";
const H_Y: &str = "-I_xy*w_x + I_y*w_y - I_yz*w_z";
const T_FIXED_POINT: &str = "1/2*I_x*w_x^2 + 1/2*I_y*w_y^2 + 1/2*I_z*w_z^2 - I_xy*w_x*w_y \
                             - I_yz*w_y*w_z - I_xz*w_z*w_x";
const T_PRINCIPAL: &str = "1/2*(I_x*w_x^2 + I_y*w_y^2 + I_z*w_z^2)";
const EULER_X: &str = "I_x*wdot_x - I_xy*wdot_y - I_xz*wdot_z - I_yz*w_y^2 + I_yz*w_z^2 \
                       - I_xz*w_x*w_y - (I_y - I_z)*w_y*w_z + I_xy*w_z*w_x";
const EULER_X_PRINCIPAL: &str = "I_x*wdot_x - (I_y - I_z)*w_y*w_z";
const FIXED_AXIS_X: &str = "-I_xz*alpha + I_yz*w^2";

#[test]
fn the_table_holds_every_reading_once() {
    let mut names = READINGS.to_vec();
    names.sort();
    names.dedup();
    assert_eq!(names.len(), 10);
    let first = |name| READINGS.iter().position(|n| *n == name).unwrap();
    assert!(first("cyclic-order") < first("sign-flipped"));
    assert!(first("product-sign-convention") < first("scaled"));
    assert!(first("scaled") < first("factor-off"));
}

#[test]
fn scaled() {
    let d = check(
        "I_x*w_x^2 + I_y*w_y^2 + I_z*w_z^2 - 2*I_xy*w_x*w_y - 2*I_yz*w_y*w_z - 2*I_xz*w_z*w_x",
        T_FIXED_POINT,
        Some("scaled"),
        Expected {
            wrong: &[
                ("I_x*w_x^2", "1/2*I_x*w_x^2"),
                ("I_y*w_y^2", "1/2*I_y*w_y^2"),
                ("I_z*w_z^2", "1/2*I_z*w_z^2"),
                ("-2*I_xy*w_x*w_y", "-I_xy*w_x*w_y"),
                ("-2*I_yz*w_y*w_z", "-I_yz*w_y*w_z"),
                ("-2*I_xz*w_z*w_x", "-I_xz*w_z*w_x"),
            ],
            ..NONE
        },
    );
    assert_eq!(explanation(&d), "the whole side is 2 times the correct one");
    // A side of one term with the wrong sign is that term's sign flipped, not a scaled side.
    let d = check(
        "-1/2*I*w^2",
        "1/2*I*w^2",
        Some("sign-flipped"),
        Expected {
            wrong: &[("-1/2*I*w^2", "1/2*I*w^2")],
            ..NONE
        },
    );
    assert!(explanation(&d).starts_with("the sign of"), "{d:?}");
}

#[test]
fn scaled_is_not_claimed_when_one_term_is_right() {
    check(
        "I_x*w_x^2 + 1/2*I_y*w_y^2 + 1/2*I_z*w_z^2",
        T_PRINCIPAL,
        Some("factor-off"),
        Expected {
            wrong: &[("I_x*w_x^2", "1/2*I_x*w_x^2")],
            ..NONE
        },
    );
}

#[test]
fn sign_flipped() {
    let d = check(
        "-I_x*wdot_x - (I_y - I_z)*w_y*w_z",
        EULER_X_PRINCIPAL,
        Some("sign-flipped"),
        Expected {
            wrong: &[("-I_x*wdot_x", "I_x*wdot_x")],
            ..NONE
        },
    );
    assert_eq!(
        explanation(&d),
        "the sign of -I_x*wdot_x is flipped (the correct term is I_x*wdot_x)"
    );
    // H_O's x component with r̄ × m v̄ the wrong way round: two signs flipped.
    let d = check(
        "m*zbar*vbar_y - m*ybar*vbar_z + I_x*w_x - I_xy*w_y - I_xz*w_z",
        "-m*zbar*vbar_y + m*ybar*vbar_z + I_x*w_x - I_xy*w_y - I_xz*w_z",
        Some("sign-flipped"),
        Expected {
            wrong: &[
                ("m*zbar*vbar_y", "-m*zbar*vbar_y"),
                ("-m*ybar*vbar_z", "m*ybar*vbar_z"),
            ],
            ..NONE
        },
    );
    assert!(explanation(&d).starts_with("the signs of "), "{d:?}");
}

#[test]
fn sign_flipped_is_not_claimed_beside_a_missing_term() {
    check(
        "L*w2",
        "-r*w1 - L*w2",
        None,
        Expected {
            wrong: &[("L*w_2", "-L*w_2")],
            missing: &["-r*w_1"],
            ..NONE
        },
    );
}

#[test]
fn factor_off() {
    let d = check(
        "m*vbar^2 + 1/2*I*w^2",
        "1/2*m*vbar^2 + 1/2*I*w^2",
        Some("factor-off"),
        Expected {
            wrong: &[("m*vbar^2", "1/2*m*vbar^2")],
            ..NONE
        },
    );
    assert_eq!(
        explanation(&d),
        "the term m*vbar^2 is 2 times the correct one (the correct term is 1/2*m*vbar^2)"
    );
    check(
        "I_x*wdot_x - I_xy*wdot_y - I_xz*wdot_z - 1/2*I_yz*w_y^2 + I_yz*w_z^2 \
         - I_xz*w_x*w_y - (I_y - I_z)*w_y*w_z + I_xy*w_z*w_x",
        EULER_X,
        Some("factor-off"),
        Expected {
            wrong: &[("-1/2*I_yz*w_y^2", "-I_yz*w_y^2")],
            ..NONE
        },
    );
}

#[test]
fn factor_off_is_not_claimed_for_two_terms_off() {
    check(
        "I_x*w_x^2 + I_y*w_y^2 + 1/2*I_z*w_z^2",
        T_PRINCIPAL,
        None,
        Expected {
            wrong: &[
                ("I_x*w_x^2", "1/2*I_x*w_x^2"),
                ("I_y*w_y^2", "1/2*I_y*w_y^2"),
            ],
            ..NONE
        },
    );
}

#[test]
fn swapped_subscripts() {
    let d = check(
        "I_x*w_x - I_xy*w_y - I_yz*w_z",
        H_X,
        Some("swapped-subscripts"),
        Expected {
            missing: &["-I_xz*w_z"],
            extra: &["-I_yz*w_z"],
            ..NONE
        },
    );
    assert_eq!(explanation(&d), "I_yz is written where I_xz belongs");
    let d = check(
        "-I_xy*w_z + I_y*w_y - I_yz*w_z",
        H_Y,
        Some("swapped-subscripts"),
        Expected {
            missing: &["-I_xy*w_x"],
            extra: &["-I_xy*w_z"],
            ..NONE
        },
    );
    assert_eq!(explanation(&d), "w_z is written where w_x belongs");
    // Two transpositions fit (w_x <-> w_z, I_xy <-> I_yz): either is a true reading.
    let d = check(
        "-I_xy*w_z + I_y*w_y - I_yz*w_x",
        H_Y,
        Some("swapped-subscripts"),
        Expected {
            missing: &["-I_xy*w_x", "-I_yz*w_z"],
            extra: &["-I_xy*w_z", "-I_yz*w_x"],
            ..NONE
        },
    );
    assert!(
        ["w_x and w_z are exchanged", "I_xy and I_yz are exchanged"]
            .contains(&explanation(&d).as_str()),
        "{d:?}"
    );
    check(
        "-I_yz*alpha + I_xz*w^2",
        FIXED_AXIS_X,
        Some("swapped-subscripts"),
        Expected {
            missing: &["-I_xz*alpha", "I_yz*w^2"],
            extra: &["-I_yz*alpha", "I_xz*w^2"],
            ..NONE
        },
    );
}

#[test]
fn swapped_subscripts_needs_subscripts() {
    // x and y are lengths without subscripts: not a swap of subscripts.
    check(
        "m*x*w_z",
        "m*y*w_z",
        None,
        Expected {
            missing: &["m*y*w_z"],
            extra: &["m*x*w_z"],
            ..NONE
        },
    );
}

#[test]
fn cyclic_order() {
    // The gyroscopic term's moments' difference reversed.
    let d = check(
        "I_x*wdot_x - (I_z - I_y)*w_y*w_z",
        EULER_X_PRINCIPAL,
        Some("cyclic-order"),
        Expected {
            wrong: &[
                ("I_y*w_y*w_z", "-I_y*w_y*w_z"),
                ("-I_z*w_y*w_z", "I_z*w_y*w_z"),
            ],
            ..NONE
        },
    );
    assert_eq!(
        explanation(&d),
        "the difference of the moments of inertia is reversed: -(I_z - I_y)*w_y*w_z where \
         the correct form has -(I_y - I_z)*w_y*w_z"
    );
    check(
        "I_x*wdot_x - I_xy*wdot_y - I_xz*wdot_z - I_yz*w_y^2 + I_yz*w_z^2 \
         - I_xz*w_x*w_y - (I_z - I_y)*w_y*w_z + I_xy*w_z*w_x",
        EULER_X,
        Some("cyclic-order"),
        Expected {
            wrong: &[
                ("I_y*w_y*w_z", "-I_y*w_y*w_z"),
                ("-I_z*w_y*w_z", "I_z*w_y*w_z"),
            ],
            ..NONE
        },
    );
    // The y equation's gyroscopic term written in the x equation.
    let d = check(
        "I_x*wdot_x - (I_z - I_x)*w_z*w_x",
        EULER_X_PRINCIPAL,
        Some("cyclic-order"),
        Expected {
            missing: &["-I_y*w_y*w_z", "I_z*w_y*w_z"],
            extra: &["-I_z*w_z*w_x", "I_x*w_z*w_x"],
            ..NONE
        },
    );
    assert!(explanation(&d).contains("x->y, y->z, z->x"), "{d:?}");
    // The whole z equation permuted the other way.
    check(
        "I_y*wdot_y - (I_z - I_x)*w_z*w_x",
        "I_z*wdot_z - (I_x - I_y)*w_x*w_y",
        Some("cyclic-order"),
        Expected {
            missing: &["I_z*wdot_z", "-I_x*w_x*w_y", "I_y*w_x*w_y"],
            extra: &["I_y*wdot_y", "-I_z*w_z*w_x", "I_x*w_z*w_x"],
            ..NONE
        },
    );
}

#[test]
fn cyclic_order_is_not_claimed_for_a_sum_of_moments_or_one_moved_symbol() {
    // Both moments' terms flipped, but they are a sum, not a difference.
    check(
        "I_x*wdot_x + (I_y + I_z)*w_y*w_z",
        "I_x*wdot_x - (I_y + I_z)*w_y*w_z",
        Some("sign-flipped"),
        Expected {
            wrong: &[
                ("I_y*w_y*w_z", "-I_y*w_y*w_z"),
                ("I_z*w_y*w_z", "-I_z*w_y*w_z"),
            ],
            ..NONE
        },
    );
    // x -> y moves one symbol only: a swap, not a cyclic order.
    check(
        "m*vbar_x",
        "m*vbar_y",
        Some("swapped-subscripts"),
        Expected {
            missing: &["m*vbar_y"],
            extra: &["m*vbar_x"],
            ..NONE
        },
    );
}

#[test]
fn product_sign_convention() {
    let d = check(
        "I_x*w_x + I_xy*w_y + I_xz*w_z",
        H_X,
        Some("product-sign-convention"),
        Expected {
            wrong: &[("I_xy*w_y", "-I_xy*w_y"), ("I_xz*w_z", "-I_xz*w_z")],
            ..NONE
        },
    );
    assert!(
        explanation(&d).contains("-I_xy and -I_xz off the diagonal"),
        "{d:?}"
    );
    let d = check(
        "I_x*w_x - I_xy*w_y + I_xz*w_z",
        H_X,
        Some("product-sign-convention"),
        Expected {
            wrong: &[("I_xz*w_z", "-I_xz*w_z")],
            ..NONE
        },
    );
    assert_eq!(
        explanation(&d),
        "the product of inertia in I_xz*w_z has the wrong sign: the chapter's inertia \
         tensor has -I_xz off the diagonal (the correct term is -I_xz*w_z)"
    );
}

#[test]
fn product_sign_convention_needs_a_product_of_inertia_in_every_differing_term() {
    check(
        "-I_x*w_x + I_xy*w_y - I_xz*w_z",
        H_X,
        Some("sign-flipped"),
        Expected {
            wrong: &[("-I_x*w_x", "I_x*w_x"), ("I_xy*w_y", "-I_xy*w_y")],
            ..NONE
        },
    );
}

#[test]
fn sin_for_cos() {
    let d = check(
        "m*g*L*sin(theta)",
        "m*g*L*cos(theta)",
        Some("sin-for-cos"),
        Expected {
            missing: &["m*g*L*cos(theta)"],
            extra: &["m*g*L*sin(theta)"],
            ..NONE
        },
    );
    assert!(
        explanation(&d).starts_with("sin and cos are exchanged"),
        "{d:?}"
    );
    check(
        "r*w^2*sin(theta) - r*alpha*cos(theta)",
        "r*w^2*cos(theta) - r*alpha*sin(theta)",
        Some("sin-for-cos"),
        Expected {
            missing: &["r*w^2*cos(theta)", "-r*alpha*sin(theta)"],
            extra: &["r*w^2*sin(theta)", "-r*alpha*cos(theta)"],
            ..NONE
        },
    );
    check(
        "phidot*sin(theta)^2 + psidot*cos(theta)",
        "phidot*sin(theta)*cos(theta) + psidot*cos(theta)",
        None,
        Expected {
            missing: &["phidot*sin(theta)*cos(theta)"],
            extra: &["phidot*sin(theta)^2"],
            ..NONE
        },
    );
}

#[test]
fn sin_for_cos_is_not_claimed_for_tan() {
    check(
        "L*tan(theta)",
        "L*sin(theta)",
        None,
        Expected {
            missing: &["L*sin(theta)"],
            extra: &["L*tan(theta)"],
            ..NONE
        },
    );
}

#[test]
fn repeated_term() {
    check(
        "I_x*w_x^2 + I_x*w_x^2 + I_z*w_z^2",
        "I_x*w_x^2 + I_y*w_y^2 + I_z*w_z^2",
        Some("repeated-term"),
        Expected {
            wrong: &[("2*I_x*w_x^2", "I_x*w_x^2")],
            missing: &["I_y*w_y^2"],
            ..NONE
        },
    );
    check(
        "3/2*I_x*w_x^2 - I_xy*w_x*w_y - I_yz*w_y*w_z - I_xz*w_z*w_x",
        T_FIXED_POINT,
        Some("repeated-term"),
        Expected {
            wrong: &[("3/2*I_x*w_x^2", "1/2*I_x*w_x^2")],
            missing: &["1/2*I_y*w_y^2", "1/2*I_z*w_z^2"],
            ..NONE
        },
    );
}

#[test]
fn repeated_term_needs_the_missing_terms_to_be_its_images() {
    check(
        "3/2*I_x*w_x^2",
        "1/2*I_x*w_x^2 + 1/2*I_y*w_y^2 + 1/2*m*v^2",
        None,
        Expected {
            wrong: &[("3/2*I_x*w_x^2", "1/2*I_x*w_x^2")],
            missing: &["1/2*I_y*w_y^2", "1/2*m*v^2"],
            ..NONE
        },
    );
}

#[test]
fn missing_term() {
    let d = check(
        "I_x*wdot_x",
        EULER_X_PRINCIPAL,
        Some("missing-term"),
        Expected {
            missing: &["-I_y*w_y*w_z", "I_z*w_y*w_z"],
            ..NONE
        },
    );
    assert_eq!(
        explanation(&d),
        "the terms -I_y*w_y*w_z and I_z*w_y*w_z are missing"
    );
    check(
        T_PRINCIPAL,
        T_FIXED_POINT,
        Some("missing-term"),
        Expected {
            missing: &["-I_xy*w_x*w_y", "-I_yz*w_y*w_z", "-I_xz*w_z*w_x"],
            ..NONE
        },
    );
    check(
        "0",
        "I_z*alpha",
        Some("missing-term"),
        Expected {
            missing: &["I_z*alpha"],
            ..NONE
        },
    );
}

#[test]
fn missing_term_is_not_claimed_beside_a_wrong_term() {
    check(
        "2*I_x*wdot_x",
        EULER_X_PRINCIPAL,
        None,
        Expected {
            wrong: &[("2*I_x*wdot_x", "I_x*wdot_x")],
            missing: &["-I_y*w_y*w_z", "I_z*w_y*w_z"],
            ..NONE
        },
    );
}

#[test]
fn extra_term() {
    let d = check(
        "I_z*alpha + I_xz*w^2",
        "I_z*alpha",
        Some("extra-term"),
        Expected {
            extra: &["I_xz*w^2"],
            ..NONE
        },
    );
    assert_eq!(
        explanation(&d),
        "the term I_xz*w^2 is not in the correct form"
    );
    check(
        "I_x*w_x - I_xy*w_y - I_xz*w_z + m*ybar*vbar_z - m*zbar*vbar_y",
        H_X,
        Some("extra-term"),
        Expected {
            extra: &["m*ybar*vbar_z", "-m*zbar*vbar_y"],
            ..NONE
        },
    );
}

#[test]
fn extra_term_is_not_claimed_beside_a_wrong_term() {
    check(
        "2*I_z*alpha + I_xz*w^2",
        "I_z*alpha",
        None,
        Expected {
            wrong: &[("2*I_z*alpha", "I_z*alpha")],
            extra: &["I_xz*w^2"],
            ..NONE
        },
    );
}

#[test]
fn precedence_between_overlapping_rules() {
    // Reversed moments also read as a swap I_y <-> I_z and as two flipped signs.
    check(
        "-(I_z - I_y)*w_y*w_z",
        "-(I_y - I_z)*w_y*w_z",
        Some("cyclic-order"),
        Expected {
            wrong: &[
                ("I_y*w_y*w_z", "-I_y*w_y*w_z"),
                ("-I_z*w_y*w_z", "I_z*w_y*w_z"),
            ],
            ..NONE
        },
    );
    // Every product of inertia flipped is also the whole side times -1.
    check(
        "I_xz*alpha - I_yz*w^2",
        FIXED_AXIS_X,
        Some("product-sign-convention"),
        Expected {
            wrong: &[("I_xz*alpha", "-I_xz*alpha"), ("-I_yz*w^2", "I_yz*w^2")],
            ..NONE
        },
    );
    // A one-term side twice what it should be is that term's factor off (scaled needs two
    // terms or more, each off by the one factor).
    check(
        "I*w^2",
        "1/2*I*w^2",
        Some("factor-off"),
        Expected {
            wrong: &[("I*w^2", "1/2*I*w^2")],
            ..NONE
        },
    );
}

#[test]
fn a_claim_with_a_denominator() {
    // Scene-like results: rational coefficients, a length below the line.
    check(
        "m*r^3*w_1/(2*L)",
        "m*r^3*w_1/(4*L)",
        Some("factor-off"),
        Expected {
            wrong: &[("m*r^3*w_1/(2*L)", "m*r^3*w_1/(4*L)")],
            ..NONE
        },
    );
    check(
        "m*L*r*w_1 - m*r^3*w_1/(4*L)",
        "m*L*r*w_1 + m*r^3*w_1/(4*L)",
        Some("sign-flipped"),
        Expected {
            wrong: &[("-m*r^3*w_1/(4*L)", "m*r^3*w_1/(4*L)")],
            ..NONE
        },
    );
    // A sum below the line, written in two forms: compared over one denominator.
    check(
        "m_2*d/(m_1 + m_2)",
        "m_1*d/(m_1 + m_2)",
        Some("swapped-subscripts"),
        Expected {
            missing: &["m_1*d/(m_1 + m_2)"],
            extra: &["m_2*d/(m_1 + m_2)"],
            ..NONE
        },
    );
    check(
        "x/(2*a + 2*b) + y/(a + b)",
        "x/(2*(a + b)) + 2*y/(a + b)",
        Some("factor-off"),
        Expected {
            wrong: &[("y/(a + b)", "2*y/(a + b)")],
            ..NONE
        },
    );
}

/// The notes' slip in the kinetic energy of sample problem 18.2: `I_x ω_x²` three times.
#[test]
fn the_notes_kinetic_energy_with_one_term_three_times() {
    let d = check(
        "1/2*(I_x*w_x^2 + I_x*w_x^2 + I_x*w_x^2)",
        T_PRINCIPAL,
        Some("repeated-term"),
        Expected {
            wrong: &[("3/2*I_x*w_x^2", "1/2*I_x*w_x^2")],
            missing: &["1/2*I_y*w_y^2", "1/2*I_z*w_z^2"],
            ..NONE
        },
    );
    assert_eq!(
        explanation(&d),
        "1/2*I_x*w_x^2 is written 3 times where the correct form has 1/2*I_x*w_x^2, \
         1/2*I_y*w_y^2 and 1/2*I_z*w_z^2"
    );
}

/// The notes' `j` component of `H_O` in sample problem 18.2 with the wrong sign. The claim
/// is one written product, and every term of its expansion is flipped: the whole side is
/// -1 times the correct one, so it reads as `scaled` (tried before `sign-flipped`, which is
/// for some terms flipped and the rest right).
#[test]
fn the_notes_angular_momentum_with_a_wrong_sign() {
    let d = check(
        "m*(L^2 + 1/4*r^2)*(r*w_1/L)",
        "-m*(L^2 + 1/4*r^2)*(r*w_1/L)",
        Some("scaled"),
        Expected {
            wrong: &[
                ("m*L*r*w_1", "-m*L*r*w_1"),
                ("m*r^3*w_1/(4*L)", "-m*r^3*w_1/(4*L)"),
            ],
            ..NONE
        },
    );
    assert_eq!(
        explanation(&d),
        "the whole side has the wrong sign: it is -1 times the correct one"
    );
}

/// The notes' cross product `(w1 i + w2 j) × (L i − r j) = (L w2 − r w1) k`: the correct
/// `k` component is `−r w1 − L w2`, so the sign of `L w2` is flipped.
#[test]
fn the_notes_cross_product() {
    let d = check(
        "L*w2 - r*w1",
        "-r*w1 - L*w2",
        Some("sign-flipped"),
        Expected {
            wrong: &[("L*w_2", "-L*w_2")],
            ..NONE
        },
    );
    assert_eq!(
        explanation(&d),
        "the sign of L*w_2 is flipped (the correct term is -L*w_2)"
    );
}

#[test]
fn an_expression_past_the_algebras_bounds_is_its_error() {
    let huge = expr("(a + b + c)^100000");
    assert!(diagnose(&huge, &expr("a")).is_err());
    assert!(diagnose(&expr("a"), &huge).is_err());
}

#[test]
fn many_differing_terms_stay_a_sentence() {
    let claimed: Vec<String> = (1..=40).map(|i| format!("m_{i}*x_{i}")).collect();
    let d = diagnose(&expr(&claimed.join(" + ")), &Expr::zero()).unwrap();
    assert_eq!(d.extra.len(), 40);
    let reading = d.reading.expect("extra-term");
    assert_eq!(reading.name, "extra-term");
    assert!(reading.explanation.contains("and 34 more"), "{reading:?}");
}

/// Symbols of the random expressions: subscripted ones that the subscript rules permute.
const NAMES: [&str; 5] = ["I_x", "I_xy", "w_y", "m", "theta"];

fn built(t: &Tree) -> Result<Expr, TestCaseError> {
    t.build(&NAMES)
        .ok_or_else(|| TestCaseError::reject("divides by an exact zero"))
}

proptest! {
    #![proptest_config(config(300))]

    /// Never a panic; when the algebra answers, the lists account for the whole residual:
    /// claimed − correct = Σ wrong claimed + Σ extra − Σ wrong correct − Σ missing, in value
    /// at a random point (where both trees have a reference value).
    #[test]
    fn the_differences_are_the_residual(
        a in tree(NAMES.len()),
        b in tree(NAMES.len()),
        x in point(NAMES.len()),
    ) {
        let (claimed, correct) = (built(&a)?, built(&b)?);
        let Ok(d) = diagnose(&claimed, &correct) else {
            return Ok(());
        };
        let (Some(va), Some(vb)) = (a.value(&x), b.value(&x)) else {
            return Ok(());
        };
        let differences = Expr::add_all(
            d.wrong
                .iter()
                .flat_map(|w| [w.claimed.clone(), -&w.correct])
                .chain(d.extra.iter().cloned())
                .chain(d.missing.iter().map(|m| -m)),
        );
        let checked = agrees(&differences, va - vb, &values(&NAMES, &x));
        prop_assert!(checked.is_ok(), "{d:?}: {}", checked.unwrap_err());
    }

    /// A nonzero multiple `k ≠ 1` of any expression reads as `scaled` by `k` (one term: as
    /// its sign flipped or its factor off).
    #[test]
    fn a_multiple_reads_as_scaled(
        b in tree(NAMES.len()),
        k in prop::sample::select(vec![(-1, 1), (2, 1), (1, 2), (-3, 4)]),
    ) {
        let correct = built(&b)?;
        prop_assume!(!correct.is_zero());
        let claimed = Expr::rational(k.0, k.1) * &correct;
        let Ok(d) = diagnose(&claimed, &correct) else {
            return Ok(());
        };
        let name = d.reading.as_ref().map(|r| r.name);
        let one_term = d.wrong.len() == 1;
        prop_assert!(
            name == Some("scaled") && !one_term
                || name == Some("sign-flipped") && one_term && k == (-1, 1)
                || name == Some("factor-off") && one_term && k != (-1, 1)
                || name == Some("product-sign-convention") && k == (-1, 1),
            "{d:?}"
        );
    }
}

/// Every expression an explanation names stands between backticks and reads back as the
/// term it names, so a report can typeset it: here the notes' cross product's flipped sign.
#[test]
fn expressions_in_an_explanation_are_marked() {
    let read = |text: &str| parse_expression("test", text).expect("reads");
    let d = diagnose(&read("-r*w1 + L*w2"), &read("-r*w1 - L*w2")).expect("diagnosed");
    let text = &d.reading.as_ref().expect("a reading").explanation;
    assert_eq!(
        text,
        "the sign of `L*w_2` is flipped (the correct term is `-L*w_2`)"
    );
    let marked: Vec<&str> = text.split('`').skip(1).step_by(2).collect();
    assert_eq!(marked.len(), 2, "{text}");
    assert_eq!(read(marked[0]), read("L w2"));
    assert_eq!(read(marked[1]), read("-L w2"));
}
