//! Breaking a relation's right-hand side into lines (`print::broken`): the lines are the
//! unbroken rendering cut between terms (joined, they give it back, modulo spaces), every
//! later line starts with its sign, and any width, however small, gives lines (never a
//! panic, never an empty line).

use crate::common::expression_tree::{config, tree};
use kinetics::print::{self, Notation, PAGE_WIDTH_EM};
use kinetics::{Axis, Expr, Vector};
use proptest::prelude::*;

const NAMES: [&str; 6] = ["w_x", "I_xy", "m_1", "L_2", "theta", "Dt"];

fn without_spaces(s: &str) -> String {
    s.chars().filter(|c| !c.is_whitespace()).collect()
}

/// Checks the lines of `e` broken at `width` in `notation`.
fn check_lines(e: &Expr, notation: Notation, width: f64) -> Result<(), TestCaseError> {
    let lines = print::broken(e, Axis::Y, notation, 3.0, width);
    let unbroken = print::render(e, notation, Axis::Y);
    prop_assert!(
        !lines.is_empty() && lines.iter().all(|l| !l.is_empty()),
        "{lines:?}"
    );
    for later in &lines[1..] {
        prop_assert!(
            later.starts_with("+ ") || later.starts_with("- "),
            "{later}"
        );
    }
    // A term taken apart inside big parentheses (LaTeX only) is the same product reordered.
    if !lines
        .iter()
        .any(|l| l.contains(r"bigl(") || l.contains(r"biggl("))
    {
        prop_assert_eq!(without_spaces(&lines.concat()), without_spaces(&unbroken));
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(300))]

    #[test]
    fn lines_join_back_to_the_unbroken_rendering(
        terms in prop::collection::vec(tree(NAMES.len()), 1..8),
        width in prop_oneof![Just(0.0), 5.0..40.0],
    ) {
        let sum = terms
            .iter()
            .filter_map(|t| t.build(&NAMES))
            .fold(Expr::int(0), |a, b| a + b);
        check_lines(&sum, Notation::Text, width)?;
        check_lines(&sum, Notation::Latex, width)?;
    }
}

/// The bent rod's `H_z` numerator: a fraction over a long sum, too wide alone, is written
/// as the fraction of its other factors before the sum in big parentheses.
#[test]
fn a_term_too_wide_alone_is_taken_apart_in_latex() {
    let h = kinetics::parse_expression(
        "h",
        "(m_1^2*L_1^2 + 4*m_1*m_2*L_1^2 + 4*m_1*m_2*L_2^2 + m_2^2*L_2^2)*w_z/(12*(m_1 + m_2))",
    )
    .expect("parses");
    let lines = print::broken(&h, Axis::Z, Notation::Latex, 2.0, 12.0);
    assert!(lines.len() > 1, "{lines:?}");
    assert!(
        lines[0].starts_with(r"\frac{\omega_z}{12 (m_1 + m_2)} \bigl("),
        "{lines:?}"
    );
    assert!(
        lines.last().is_some_and(|l| l.ends_with(r"\bigr)")),
        "{lines:?}"
    );
    // In text the line stays long.
    let text = print::broken(&h, Axis::Z, Notation::Text, 2.0, 12.0);
    assert_eq!(text, vec![print::text_about(&h, Axis::Z)]);
}

/// A long vector has a line for each component; a short one stays on one line.
#[test]
fn a_long_vector_has_a_line_for_each_component() {
    let long = kinetics::parse_expression(
        "c",
        "m_1*L_1^2*w_x/3 + m_2*L_2^2*w_x/12 + m_1*m_2*L_1*L_2*w_y/(m_1 + m_2) - m_2*L_1*L_2*w_z/4",
    )
    .expect("parses");
    let v = Vector::new(long.clone(), long.clone(), long);
    let lines = print::broken_vector(&v, Notation::Latex, 2.0, PAGE_WIDTH_EM);
    assert!(lines.len() >= 3, "{lines:?}");
    assert!(
        lines[1..]
            .iter()
            .all(|l| l.starts_with("+ ") || l.starts_with("- ")),
        "{lines:?}"
    );
    let short = Vector::new(Expr::symbol("w_x"), Expr::int(0), Expr::symbol("w_z"));
    assert_eq!(
        print::broken_vector(&short, Notation::Latex, 2.0, PAGE_WIDTH_EM),
        vec![print::vector(&short, Notation::Latex)]
    );
}
