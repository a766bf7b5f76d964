//! Units of expressions with rational exponents (issue 15, item 5): a root of a quantity
//! is in the root of its unit when that unit's exponents divide (`sqrt(a^2 + b^2)` of
//! lengths is a length, its reciprocal per metre); a root that would need a fractional
//! exponent (`sqrt(a)` of a length) is refused, at the text that holds it.

use kinetics::algebra::Symbol;
use kinetics::parse::parse_expression;
use kinetics::scene::parse_scene;
use kinetics::scene::units::{dimension_of, Dimension, Dimensions};

/// The dimension of `text` where `a`, `b` are lengths, `m` a mass and `t` a time.
fn dimension(text: &str) -> Result<Dimension, String> {
    let dims: Dimensions = [
        ("a", Dimension::LENGTH),
        ("b", Dimension::LENGTH),
        ("m", Dimension::MASS),
        ("t", Dimension::TIME),
    ]
    .into_iter()
    .map(|(n, d)| (Symbol::new(n), d))
    .collect();
    let e = parse_expression("test", text).expect("the test's expression parses");
    dimension_of(&e, &dims).map_err(|err| err.to_string())
}

#[test]
fn roots_whose_exponents_divide_have_a_unit() {
    let per_metre = Dimension::new(0, -1, 0);
    for (text, expected) in [
        ("sqrt(a^2 + b^2)", Dimension::LENGTH),
        ("1/sqrt(a^2 + b^2)", per_metre),
        ("(a^2 + b^2)^(-1/2)", per_metre),
        ("(a^3)^(1/3)", Dimension::LENGTH),
        ("(a^3 + a b^2)^(2/3)", Dimension::new(0, 2, 0)),
        ("sqrt(m^2 a^2/t^2)", Dimension::new(1, 1, -1)),
        ("a/sqrt(a^2 + b^2)", Dimension::NONE),
        ("sqrt(2)", Dimension::NONE),
        ("(a/b)^(1/3)", Dimension::NONE),
    ] {
        assert_eq!(dimension(text), Ok(expected), "{text}");
    }
}

#[test]
fn a_fractional_exponent_of_a_unit_is_refused() {
    for text in ["sqrt(a)", "(a^2 m)^(1/3)", "m^(3/2)", "1/sqrt(a t)"] {
        let err = dimension(text).expect_err(text);
        assert!(
            err.contains("would not be a whole power of a unit"),
            "{text}: {err}"
        );
    }
}

const SCENE_HEAD: &str =
    "given m = 2 kg\ngiven a = 0.3 m\ngiven b = 0.4 m\ngiven P = 10 N\ngiven w = 2 rad/s\n";

#[test]
fn a_scene_takes_a_diagonal_and_its_reciprocal() {
    let text = format!(
        "{SCENE_HEAD}body rod(sqrt(a^2 + b^2)) mass m\nfixed point\nomega = w*k\nforce F = P*b/sqrt(a^2 + b^2)*i at (0, 0, (a^3)^(1/3))\nfind T\n"
    );
    if let Err(d) = parse_scene("diagonal.scene", &text) {
        panic!("{}", d.render());
    }
}

#[test]
fn a_scene_refuses_the_root_of_a_length_where_it_stands() {
    let text = format!("{SCENE_HEAD}body rod(sqrt(a)) mass m\nfind T\n");
    let d = parse_scene("root.scene", &text).expect_err("sqrt of a length has no unit");
    assert_eq!(d.line, 6, "{}", d.render());
    assert!(
        d.message.contains("whole power of a unit"),
        "{}",
        d.render()
    );
}
