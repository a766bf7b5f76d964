//! The MathML printer: each construct of the layout as MathML Core writes it, and, for
//! random expressions, MathML that is well-formed XML made only of MathML Core elements.

use crate::common::expression_tree::{tree, Tree};
use kinetics::algebra::{Axis, Expr, Vector};
use kinetics::parse::parse_expression;
use kinetics::print::{self, Notation};
use proptest::prelude::*;

/// The elements the printer may write: MathML Core's, which Chromium lays out natively.
const ELEMENTS: [&str; 13] = [
    "mi", "mn", "mo", "mrow", "mfrac", "msup", "msub", "msubsup", "msqrt", "mroot", "mover",
    "mspace", "mtext",
];

fn mathml(text: &str) -> String {
    print::mathml(&parse_expression("test", text).expect("the test's expression parses"))
}

/// `<msub>` of a letter and a subscript of letters, as the printer writes it.
fn sub(base: &str, subscript: &str) -> String {
    let letters: String = subscript.chars().map(|c| format!("<mi>{c}</mi>")).collect();
    format!("<msub><mrow><mi>{base}</mi></mrow><mrow>{letters}</mrow></msub>")
}

const TIMES: &str = "<mo>&#x2062;</mo>";

/// Parentheses of the text's size, around what holds no fraction.
const OPEN: &str = r#"<mrow><mo stretchy="false">(</mo>"#;
const CLOSE: &str = r#"<mo stretchy="false">)</mo></mrow>"#;

#[test]
fn symbols_with_subscripts() {
    assert_eq!(mathml("m"), "<mi>m</mi>");
    assert_eq!(mathml("I_xy"), sub("I", "xy"));
    assert_eq!(mathml("w_x"), sub("ω", "x"));
}

#[test]
fn a_sum_with_a_true_minus() {
    assert_eq!(
        mathml("I_x*w_x - I_xy*w_y"),
        format!(
            "<mrow><mrow>{}{TIMES}{}</mrow><mo>\u{2212}</mo><mrow>{}{TIMES}{}</mrow></mrow>",
            sub("I", "x"),
            sub("ω", "x"),
            sub("I", "xy"),
            sub("ω", "y")
        )
    );
    assert_eq!(mathml("-a"), "<mo>\u{2212}</mo><mi>a</mi>");
}

#[test]
fn fractions() {
    assert_eq!(
        mathml("1/2*m*v^2"),
        format!(
            "<mrow><mfrac><mn>1</mn><mn>2</mn></mfrac>{TIMES}<mi>m</mi>{TIMES}\
             <msup><mrow><mi>v</mi></mrow><mrow><mn>2</mn></mrow></msup></mrow>"
        )
    );
    assert_eq!(
        mathml("3*M/(2*m)"),
        format!(
            "<mrow><mfrac><mrow><mn>3</mn>{TIMES}<mi>M</mi></mrow>\
             <mrow><mn>2</mn>{TIMES}<mi>m</mi></mrow></mfrac></mrow>"
        )
    );
    // A lone sum below the bar needs no parentheses.
    assert_eq!(
        mathml("1/(a + b)"),
        "<mrow><mfrac><mrow><mn>1</mn></mrow><mrow><mrow><mi>a</mi><mo>+</mo><mi>b</mi></mrow>\
         </mrow></mfrac></mrow>"
    );
}

#[test]
fn powers_of_subscripted_symbols_and_of_powers() {
    assert_eq!(
        mathml("w_x^2"),
        "<msubsup><mrow><mi>ω</mi></mrow><mrow><mi>x</mi></mrow><mrow><mn>2</mn></mrow></msubsup>"
    );
    assert_eq!(
        mathml("(w_x^2)^(3/2)"),
        format!(
            "<msup>{OPEN}<msubsup><mrow><mi>ω</mi></mrow><mrow><mi>x</mi></mrow>\
             <mrow><mn>2</mn></mrow></msubsup>{CLOSE}<mrow><mfrac><mn>3</mn><mn>2</mn>\
             </mfrac></mrow></msup>"
        )
    );
}

#[test]
fn parentheses_around_a_group() {
    assert_eq!(
        mathml("-(I_y - I_z)*w_y*w_z"),
        format!(
            "<mo>\u{2212}</mo><mrow>{OPEN}<mrow>{}<mo>\u{2212}</mo>{}</mrow>{CLOSE}{TIMES}{}{TIMES}{}</mrow>",
            sub("I", "y"),
            sub("I", "z"),
            sub("ω", "y"),
            sub("ω", "z")
        )
    );
}

#[test]
fn a_thin_space_after_a_name_of_several_letters() {
    // `F Δt b`, never `FΔtb`: the b is not part of the interval's name.
    assert_eq!(
        mathml("F*Dt*b"),
        format!(
            "<mrow><mi>F</mi>{TIMES}<mrow><mi mathvariant=\"normal\">Δ</mi><mi>t</mi></mrow>\
             <mspace width=\"0.1667em\"/>{TIMES}<mi>b</mi></mrow>"
        )
    );
}

#[test]
fn parentheses_grow_around_a_fraction() {
    // As `\left( … \right)`: a vector's component and a factor holding a fraction.
    let v: Vector = Vector::new(
        Expr::symbol("a") / Expr::symbol("b") + Expr::symbol("c"),
        Expr::int(0),
        Expr::int(0),
    );
    let printed = print::vector(&v, Notation::MathMl);
    assert!(printed.starts_with("<mrow><mo>(</mo>"), "{printed}");
    assert!(printed.contains("<mo>)</mo></mrow>"), "{printed}");
    let power = mathml("(a/b + c)^2");
    assert!(power.contains("<mrow><mo>(</mo>"), "{power}");
    assert!(!power.contains("stretchy"), "{power}");
}

#[test]
fn functions_roots_and_absolute_values() {
    assert_eq!(
        mathml("sin(beta)"),
        "<mrow><mi>sin</mi><mo>&#x2061;</mo><mi>β</mi></mrow>"
    );
    assert_eq!(
        mathml("cos(a + b)"),
        format!(
            "<mrow><mi>cos</mi><mo>&#x2061;</mo>{OPEN}<mrow><mi>a</mi><mo>+</mo><mi>b</mi>\
             </mrow>{CLOSE}</mrow>"
        )
    );
    // The power of a function stands on its name, and a thin space follows its argument.
    assert_eq!(
        mathml("sin(beta)^2*cos(beta)"),
        format!(
            "<mrow><mrow><msup><mi>sin</mi><mrow><mn>2</mn></mrow></msup><mo>&#x2061;</mo>\
             <mi>β</mi></mrow><mspace width=\"0.1667em\"/>{TIMES}<mrow><mi>cos</mi>\
             <mo>&#x2061;</mo><mi>β</mi></mrow></mrow>"
        )
    );
    assert_eq!(mathml("sqrt(x)"), "<msqrt><mi>x</mi></msqrt>");
    assert_eq!(
        mathml("(a + b)^(1/3)"),
        "<mroot><mrow><mi>a</mi><mo>+</mo><mi>b</mi></mrow><mn>3</mn></mroot>"
    );
    assert_eq!(
        mathml("abs(a - b)"),
        "<mrow><mo>|</mo><mrow><mi>a</mi><mo>\u{2212}</mo><mi>b</mi></mrow><mo>|</mo></mrow>"
    );
}

#[test]
fn bars_dots_and_capital_greek() {
    let bar_v = "<mover accent=\"true\"><mrow><mi>v</mi></mrow><mo>\u{af}</mo></mover>";
    assert_eq!(
        mathml("vbar_x"),
        format!("<msub><mrow>{bar_v}</mrow><mrow><mi>x</mi></mrow></msub>")
    );
    assert_eq!(
        mathml("wdot_y"),
        "<msub><mrow><mover accent=\"true\"><mrow><mi>ω</mi></mrow><mo>\u{2d9}</mo></mover>\
         </mrow><mrow><mi>y</mi></mrow></msub>"
    );
    assert_eq!(
        mathml("Dt"),
        "<mrow><mi mathvariant=\"normal\">Δ</mi><mi>t</mi></mrow>"
    );
    assert_eq!(
        mathml("SumM_x"),
        format!(
            "<mrow><mi mathvariant=\"normal\">Σ</mi>{}</mrow>",
            sub("M", "x")
        )
    );
}

#[test]
fn vectors_with_bold_unit_vectors() {
    let v: Vector = Vector::new(Expr::symbol("a"), Expr::int(1), Expr::int(0));
    assert_eq!(
        print::vector(&v, Notation::MathMl),
        format!("<mi>a</mi>{TIMES}<mi>\u{1d422}</mi><mo>+</mo><mi>\u{1d423}</mi>")
    );
    let w: Vector = Vector::new(
        Expr::symbol("a") - Expr::symbol("b"),
        Expr::int(0),
        Expr::int(0),
    );
    assert_eq!(
        print::vector(&w, Notation::MathMl),
        format!(
            "{OPEN}<mrow><mi>a</mi><mo>\u{2212}</mo><mi>b</mi></mrow>{CLOSE}\
             {TIMES}<mi>\u{1d422}</mi>"
        )
    );
    let zero: Vector = Vector::new(Expr::int(0), Expr::int(0), Expr::int(0));
    assert_eq!(print::vector(&zero, Notation::MathMl), "<mn>0</mn>");
}

#[test]
fn the_same_order_as_latex() {
    // Inertia groups are ordered from the equation's axis: the first moment in a group is
    // the same in MathML as in LaTeX, about every axis.
    let e = parse_expression("test", "(I_x - I_y + I_z)*w_z*w_x").unwrap();
    for axis in [Axis::X, Axis::Y, Axis::Z] {
        let latex = print::latex_about(&e, axis);
        let mathml = print::render(&e, Notation::MathMl, axis);
        let first = |text: &str, before: &str| {
            let at = text.find(before).map(|at| at + before.len());
            at.and_then(|at| text[at..].chars().next())
        };
        assert_eq!(
            first(&latex, "I_"),
            first(&mathml, "<mi>I</mi></mrow><mrow><mi>"),
            "{latex}\n{mathml}"
        );
    }
}

/// Why `xml` is not well-formed XML of MathML Core elements, if it is not.
fn malformed(xml: &str) -> Option<String> {
    let mut open: Vec<&str> = Vec::new();
    let mut rest = xml;
    while let Some(at) = rest.find(['<', '&', '>']) {
        let tail = &rest[at..];
        if let Some(entity) = tail.strip_prefix('&') {
            let Some(end) = entity.find(';').filter(|&n| n <= 8) else {
                return Some("a bare '&'".into());
            };
            let name = &entity[..end];
            let known = matches!(name, "amp" | "lt" | "gt" | "quot" | "apos")
                || name
                    .strip_prefix("#x")
                    .is_some_and(|h| !h.is_empty() && h.chars().all(|c| c.is_ascii_hexdigit()));
            if !known {
                return Some(format!("unknown entity &{name};"));
            }
            rest = &entity[end + 1..];
            continue;
        }
        let Some(tag) = tail.strip_prefix('<') else {
            return Some("a '>' outside a tag".into());
        };
        let Some(end) = tag.find('>') else {
            return Some("an unclosed tag".into());
        };
        let (inside, after) = (&tag[..end], &tag[end + 1..]);
        rest = after;
        if let Some(name) = inside.strip_prefix('/') {
            if open.pop() != Some(name) {
                return Some(format!("</{name}> closes nothing open"));
            }
            continue;
        }
        let empty = inside.ends_with('/');
        let inside = inside.trim_end_matches('/');
        let (name, attributes) = inside.split_once(' ').unwrap_or((inside, ""));
        if !ELEMENTS.contains(&name) {
            return Some(format!("<{name}> is not MathML Core's"));
        }
        let mut attributes = attributes.trim();
        while !attributes.is_empty() {
            let Some((key, value)) = attributes.split_once("=\"") else {
                return Some(format!("an attribute without a quoted value in <{inside}>"));
            };
            let Some((_, next)) = value.split_once('"') else {
                return Some(format!("an unclosed attribute value in <{inside}>"));
            };
            if key.is_empty() || !key.chars().all(|c| c.is_ascii_alphabetic()) {
                return Some(format!("an attribute named '{key}'"));
            }
            attributes = next.trim_start();
        }
        if !empty {
            open.push(name);
        }
    }
    (!open.is_empty()).then(|| format!("<{}> never closed", open.join("> <")))
}

#[test]
fn the_checker_finds_malformed_mathml() {
    assert_eq!(malformed("<mi>a</mi><mspace width=\"1em\"/>"), None);
    for bad in [
        "<mi>a",
        "<mi>a</mn>",
        "<mi>a & b</mi>",
        "<div></div>",
        "<mi x=1>a</mi>",
        "a > b",
    ] {
        assert!(malformed(bad).is_some(), "{bad}");
    }
}

const NAMES: [&str; 7] = ["a", "b", "w_x", "I_xy", "vbar_x", "Dt", "theta"];

proptest! {
    #![proptest_config(crate::common::expression_tree::config(2_000))]

    /// Whatever the expression, its MathML is well-formed XML of MathML Core elements.
    #[test]
    fn mathml_is_well_formed(t in tree(NAMES.len())) {
        let Some(e) = Tree::build(&t, &NAMES) else {
            return Err(TestCaseError::reject("divides by an exact zero"));
        };
        for axis in [Axis::X, Axis::Y, Axis::Z] {
            let mathml = print::render(&e, Notation::MathMl, axis);
            prop_assert_eq!(malformed(&mathml), None, "{}", mathml);
        }
    }
}
