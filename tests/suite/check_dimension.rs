//! Dimensions of a claim (issue 16, item 5): every written term of both sides has one
//! dimension; the first term that has another, or none at all (`sin(w_x)`, `(m + w_x) v`),
//! is named with its text and span. The claims are built here term by term, as the claim
//! reader gives them: each term's span in the source, its value, the derived names of a side.

use kinetics::algebra::Symbol;
use kinetics::check::dimension::{odd_term, OddTerm};
use kinetics::parse::claim::{Claim, ClaimSide, WrittenTerm};
use kinetics::parse::parse_expression;
use kinetics::scene::units::Dimension;

/// The derived names the test claims use, with their values.
const DERIVED: [(&str, &str); 3] = [
    ("T", "1/2 m vbar_x^2 + 1/2 I_x w_x^2"),
    ("H_x", "I_x w_x - I_xy w_y - I_xz w_z"),
    ("H_O", "I_x w_x i + I_y w_y j + I_z w_z k"),
];

/// The dimensions of the test's symbols; any other symbol is free (unknown).
fn dimension_of_symbol(s: Symbol) -> Option<Dimension> {
    Some(match s.name() {
        "m" => Dimension::MASS,
        "I_x" | "I_y" | "I_z" | "I_xy" | "I_xz" => Dimension::INERTIA,
        "w_x" | "w_y" | "w_z" => Dimension::ANGULAR_VELOCITY,
        "wdot_x" => Dimension::ANGULAR_ACCELERATION,
        "v" | "vbar_x" => Dimension::VELOCITY,
        "L" => Dimension::LENGTH,
        "theta" => Dimension::NONE,
        _ => return None,
    })
}

/// One side of `source` whose terms are `terms` (each as written, its sign included),
/// found in `source` from byte `from` on; returns the side and where it ends.
fn side(source: &str, from: usize, terms: &[&str]) -> (ClaimSide, usize) {
    let mut at = from;
    let mut written = Vec::new();
    let mut resolved = Vec::new();
    for text in terms {
        let start = at + source[at..].find(text).expect("the term is in the source");
        at = start + text.len();
        let unsigned = text.trim_start_matches(['+', ' ']);
        let mut value = Vec::new();
        for token in unsigned.split(' ') {
            match DERIVED.iter().find(|(name, _)| *name == token) {
                Some((name, derived)) => {
                    if !resolved.iter().any(|r| r == name) {
                        resolved.push(name.to_string());
                    }
                    value.push(format!("({derived})"));
                }
                None => value.push(token.to_string()),
            }
        }
        let value = value.join(" ");
        let value = parse_expression("test", &value).expect("the test's term parses");
        written.push(WrittenTerm {
            value,
            span: (start, at),
        });
    }
    let value = written.iter().map(|t| t.value.clone()).sum();
    let span = (written[0].span.0, at);
    let side = ClaimSide {
        value,
        span,
        terms: written,
        resolved,
    };
    (side, at)
}

/// The claim `source`, its terms on each side as written.
fn claim(source: &str, lhs: &[&str], rhs: &[&str]) -> Claim {
    let (lhs, end) = side(source, 0, lhs);
    let equals = end + source[end..].find('=').expect("the claim has =");
    let (rhs, _) = side(source, equals + 1, rhs);
    Claim { lhs, rhs }
}

/// The odd term of the claim `source` with those terms.
fn odd(source: &str, lhs: &[&str], rhs: &[&str]) -> Option<OddTerm> {
    odd_term(&claim(source, lhs, rhs), source, &dimension_of_symbol)
}

/// kg·m²/s, the unit of angular momentum.
const ANGULAR_MOMENTUM: Dimension = Dimension::new(1, 2, -1);

/// kg·m/s, the unit of linear momentum.
const MOMENTUM: Dimension = Dimension::new(1, 1, -1);

#[test]
fn homogeneous_claims_have_no_odd_term() {
    for (source, lhs, rhs) in [
        (
            "T = 1/2 m vbar_x^2 + 1/2 I_x w_x^2",
            &["T"][..],
            &["1/2 m vbar_x^2", "+ 1/2 I_x w_x^2"][..],
        ),
        (
            "H_x = I_x w_x - I_xy w_y - I_xz w_z",
            &["H_x"],
            &["I_x w_x", "- I_xy w_y", "- I_xz w_z"],
        ),
        (
            "2 T = m vbar_x^2 + I_x w_x^2",
            &["2 T"],
            &["m vbar_x^2", "+ I_x w_x^2"],
        ),
        (
            "T = pi m v^2 cos(theta)^2",
            &["T"],
            &["pi m v^2 cos(theta)^2"],
        ),
        (
            "H_O = I_x w_x i + I_y w_y j + I_z w_z k",
            &["H_O"],
            &["I_x w_x i", "+ I_y w_y j", "+ I_z w_z k"],
        ),
    ] {
        assert_eq!(odd(source, lhs, rhs), None, "{source}");
    }
}

#[test]
fn an_odd_term_is_named_with_its_text_and_span() {
    let source = "T = 1/2 m v^2 + I_x w_x";
    let odd = odd(source, &["T"], &["1/2 m v^2", "+ I_x w_x"]).expect("I_x w_x is odd");
    let start = source.find("I_x w_x").unwrap();
    assert_eq!(odd.text, "I_x w_x");
    assert_eq!(odd.span, (start, start + "I_x w_x".len()));
    assert_eq!(&source[odd.span.0..odd.span.1], odd.text);
    assert_eq!(odd.dimension, Some(ANGULAR_MOMENTUM));
    assert_eq!(odd.expected, Dimension::MOMENT);
    assert_eq!(
        odd.reason, "is in kg·m²/s where the other terms are in N·m",
        "{odd:?}"
    );
}

#[test]
fn the_first_odd_term_in_writing_order_is_named_with_its_sign() {
    let source = "H_x = I_x w_x - m v - I_xz w_z - L m v";
    let lhs = ["H_x"];
    let rhs = ["I_x w_x", "- m v", "- I_xz w_z", "- L m v"];
    let odd = odd(source, &lhs, &rhs).expect("m v is odd");
    assert_eq!(odd.text, "- m v");
    assert_eq!(odd.dimension, Some(MOMENTUM));
    assert_eq!(odd.expected, ANGULAR_MOMENTUM);
}

#[test]
fn a_function_of_a_dimensioned_quantity_is_odd_in_itself() {
    let source = "T = 1/2 m v^2 sin(w_x)";
    let odd = odd(source, &["T"], &["1/2 m v^2 sin(w_x)"]).expect("sin(w_x) is odd");
    assert_eq!(odd.text, "1/2 m v^2 sin(w_x)");
    assert_eq!(odd.dimension, None);
    assert_eq!(odd.expected, Dimension::MOMENT);
    assert_eq!(
        odd.reason,
        "the argument of sin must have no unit, but w_x is in rad/s"
    );
}

#[test]
fn a_sum_of_two_kinds_of_quantity_is_odd_in_itself() {
    let source = "H_x = (m + w_x) v + I_x w_x";
    let odd = odd(source, &["H_x"], &["(m + w_x) v", "+ I_x w_x"]).expect("m + w_x is odd");
    assert_eq!(odd.text, "(m + w_x) v");
    assert_eq!(odd.dimension, None);
    assert_eq!(odd.expected, ANGULAR_MOMENTUM);
    assert!(odd.reason.contains("cannot add"), "{}", odd.reason);
    assert!(odd.reason.contains("(kg)"), "{}", odd.reason);
    assert!(odd.reason.contains("(rad/s)"), "{}", odd.reason);
}

#[test]
fn a_term_odd_in_itself_is_named_when_no_term_has_a_dimension() {
    let odd = odd("sin(L) = 0", &["sin(L)"], &["0"]).expect("sin(L) is odd");
    assert_eq!(odd.dimension, None);
    assert_eq!(odd.expected, Dimension::NONE);
    assert_eq!(
        odd.reason,
        "the argument of sin must have no unit, but L is in m"
    );
}

#[test]
fn a_vector_term_has_the_dimension_of_its_components() {
    let source = "H_O = I_x w_x i + m v j";
    let component = odd(source, &["H_O"], &["I_x w_x i", "+ m v j"]).expect("m v j is odd");
    assert_eq!(component.text, "m v j");
    assert_eq!(component.dimension, Some(MOMENTUM));
    assert_eq!(component.expected, ANGULAR_MOMENTUM);
    let source = "H_O = (I_x w_x) i + (m v) j";
    let inconsistent = odd(source, &["H_O"], &["(I_x w_x) i + (m v) j"]).expect("odd");
    assert_eq!(inconsistent.dimension, None);
}

#[test]
fn a_tie_is_decided_by_the_side_holding_a_derived_name_else_by_the_left() {
    // One term against one: the left decides.
    let odd_mv = odd("I_x w_x = m v", &["I_x w_x"], &["m v"]).expect("a tie");
    assert_eq!(
        (odd_mv.text.as_str(), odd_mv.expected),
        ("m v", ANGULAR_MOMENTUM)
    );
    let odd_iw = odd("m v = I_x w_x", &["m v"], &["I_x w_x"]).expect("a tie");
    assert_eq!(
        (odd_iw.text.as_str(), odd_iw.expected),
        ("I_x w_x", MOMENTUM)
    );
    // T is derived, so its side decides, on the right as on the left.
    for (source, lhs, rhs) in [("m v = T", "m v", "T"), ("T = m v", "T", "m v")] {
        let odd = odd(source, &[lhs], &[rhs]).expect("a tie");
        assert_eq!(odd.text, "m v", "{source}");
        assert_eq!(odd.expected, Dimension::MOMENT, "{source}");
        assert_eq!(odd.reason, "is in N·s where the other term is in N·m");
    }
    // Two against two: the first term of the left side decides.
    let source = "m v + I_x w_x = m v + I_x w_x";
    let odd = odd(source, &["m v", "+ I_x w_x"], &["m v", "+ I_x w_x"]).expect("a tie");
    assert_eq!(odd.text, "I_x w_x");
    assert_eq!(odd.expected, MOMENTUM);
}

/// The side that alone names a derived quantity has its dimension, however many terms the
/// other side has: `T = m v + L m w_x` is odd in its right side (a student's slip is there),
/// not in `T`.
#[test]
fn a_derived_name_decides_over_the_majority() {
    let source = "T = m v + L m w_x";
    let odd = odd(source, &["T"], &["m v", "+ L m w_x"]).expect("the right side is odd");
    assert_eq!(odd.text, "m v");
    assert_eq!(odd.dimension, Some(MOMENTUM));
    assert_eq!(odd.expected, Dimension::MOMENT);
}

#[test]
fn terms_with_free_symbols_and_zero_terms_are_not_judged() {
    for (source, lhs, rhs) in [
        (
            "T = 1/2 m v^2 + q w_x",
            &["T"][..],
            &["1/2 m v^2", "+ q w_x"][..],
        ),
        ("T = q", &["T"], &["q"]),
        ("q m = I_x w_x", &["q m"], &["I_x w_x"]),
        ("sin(q) = 0", &["sin(q)"], &["0"]),
        ("0 = T - 1/2 m v^2", &["0"], &["T", "- 1/2 m v^2"]),
        ("0 = 0", &["0"], &["0"]),
    ] {
        assert_eq!(odd(source, lhs, rhs), None, "{source}");
    }
    // A free symbol does not hide an odd term elsewhere.
    let source = "T = q + I_x w_x + m v^2";
    let odd = odd(source, &["T"], &["q", "+ I_x w_x", "+ m v^2"]).expect("I_x w_x is odd");
    assert_eq!(odd.text, "I_x w_x");
}

#[test]
fn a_span_outside_the_source_names_the_term_by_its_value() {
    let mut claim = claim("T = I_x w_x", &["T"], &["I_x w_x"]);
    claim.rhs.terms[0].span = (100, 200);
    let odd = odd_term(&claim, "T = I_x w_x", &dimension_of_symbol).expect("odd");
    assert_eq!(odd.span, (100, 200));
    assert_eq!(odd.text, claim.rhs.terms[0].value.to_string());
}
