//! Symbol domains and the radicals and absolute values they simplify: each example of
//! `Expr::simplify_radicals`'s documentation, the chapter's default domains, negative
//! controls (a sign never dropped for a symbol that may be negative), and a property: the
//! simplified form has the value of the expression at random points where the positive
//! symbols are positive, in double-double.

use crate::common::expression_tree::{point, tree};
use kinetics::algebra::{AlgebraError, Domain, Domains, Expr, Func, Symbol};
use kinetics::numeric::scalar::double_double::DoubleDouble as Dd;
use kinetics::parse::parse_expression;
use num_traits::Float;
use proptest::prelude::*;

fn parsed(text: &str) -> Expr {
    parse_expression("test", text).expect("the test's expression parses")
}

/// `text` simplified with the chapter's default domains, printed.
fn simplified(text: &str) -> String {
    parsed(text)
        .simplify_radicals(&Domains::chapter_defaults())
        .expect("within the bound")
        .to_string()
}

#[test]
fn the_documented_examples() {
    let cases = [
        ("sqrt(a^2)", "a"),
        ("sqrt(4 a^2 b)", "2*a*sqrt(b)"),
        ("(a^2)^(1/2)", "a"),
        ("abs(m)", "m"),
        ("((a+b)^2)^(1/2)", "a + b"),
        ("(x^2)^(1/2)", "abs(x)"),
        ("(a^3)^(1/3)", "a"),
        ("sqrt(8)", "2*sqrt(2)"),
        ("sqrt(L^2 + r^2)", "sqrt(L^2 + r^2)"),
        ("1/sqrt(a^2 b^2)", "1/(a*b)"),
        ("abs(-a - b)", "a + b"),
        ("abs(x)^2", "x^2"),
        ("sqrt(x^4)", "x^2"),
        ("sqrt(x^2 y)", "sqrt(y)*abs(x)"),
    ];
    for (input, expected) in cases {
        assert_eq!(simplified(input), expected, "{input}");
    }
}

/// A symbol that may be negative keeps its sign: `√(x²) = |x|`, never `x`.
#[test]
fn negative_controls() {
    for (input, expected) in [
        ("sqrt(x^2)", "abs(x)"),
        ("abs(w_x)", "abs(w_x)"),
        ("sqrt(I_xy^2)", "abs(I_xy)"),
        ("abs(a - b)", "abs(a - b)"),
        ("sqrt(a^3)", "a^(3/2)"),
        ("(x^3)^(1/3)", "(x^3)^(1/3)"),
        ("abs(sin(theta))", "abs(sin(theta))"),
    ] {
        assert_eq!(simplified(input), expected, "{input}");
    }
}

#[test]
fn chapter_defaults() {
    let domains = Domains::chapter_defaults();
    let positive = [
        "m", "m_1", "L", "l", "r", "R", "a", "b", "c", "d", "h", "e", "r_1", "I", "I_x", "I_y",
        "I_z", "I_G", "I_x'", "Ibar_x", "I_xx", "t", "Dt",
    ];
    let real = [
        "x", "y", "z", "xbar", "x_1", "w_x", "v_x", "H_x", "F_x", "r_x", "a_x", "I_xy", "I_yz",
        "I_xz'", "theta", "beta", "w", "alpha", "phi", "wdot_x", "F", "M", "g",
    ];
    for name in positive {
        assert_eq!(
            domains.domain(Symbol::new(name)),
            Domain::Positive,
            "{name}"
        );
    }
    for name in real {
        assert_eq!(domains.domain(Symbol::new(name)), Domain::Real, "{name}");
    }
}

#[test]
fn a_declaration_overrides_the_default() {
    let mut domains = Domains::chapter_defaults();
    domains.declare(Symbol::new("x"), Domain::Positive);
    domains.declare(Symbol::new("a"), Domain::Real);
    let simplify = |text: &str| {
        parsed(text)
            .simplify_radicals(&domains)
            .unwrap()
            .to_string()
    };
    assert_eq!(simplify("sqrt(x^2)"), "x");
    assert_eq!(simplify("sqrt(a^2)"), "abs(a)");
}

#[test]
fn what_is_provably_positive() {
    let domains = Domains::chapter_defaults();
    for text in [
        "2",
        "m",
        "a + b",
        "m/(a^2 + x^2)",
        "sqrt(a)",
        "abs(m - 2 a) + 1",
        "a^x",
    ] {
        assert!(domains.is_positive(&parsed(text)), "{text}");
    }
    for text in [
        "0",
        "-m",
        "x",
        "a - b",
        "x^2",
        "abs(x)",
        "cos(theta)",
        "x^a",
    ] {
        assert!(!domains.is_positive(&parsed(text)), "{text}");
    }
}

/// An input past the bound is an error, not a long walk: `e_(k+1) = sin(e_k) cos(e_k)`
/// shares its subtrees, so its tree doubles at each step without the memory doing so.
#[test]
fn beyond_the_bound_is_an_error() {
    let mut e = Expr::symbol("theta");
    for _ in 0..22 {
        e = Expr::func(Func::Sin, e.clone()) * Expr::func(Func::Cos, e);
    }
    assert!(matches!(
        e.simplify_radicals(&Domains::chapter_defaults()),
        Err(AlgebraError::TooLargeToSimplify(_))
    ));
}

/// The symbols of the random expressions: `a`, `b` and `m` positive, the others real.
const NAMES: [&str; 6] = ["a", "b", "m", "x", "w_x", "theta"];

fn dd_value(e: &Expr, x: &[f64]) -> Option<Dd> {
    let value = |s: Symbol| {
        NAMES
            .iter()
            .position(|n| Symbol::new(n) == s)
            .map(|i| Dd::from_f64(x[i]))
    };
    e.eval(&value).ok().filter(|v| v.is_finite())
}

proptest! {
    #![proptest_config(crate::common::expression_tree::config(5_000))]

    /// Where the expression has a real value, the simplified form has the same, with the
    /// positive symbols positive.
    #[test]
    fn simplify_radicals_keeps_the_value(t in tree(NAMES.len()), x in point(NAMES.len())) {
        let mut x = x;
        for v in &mut x[..3] {
            *v = v.abs();
        }
        let Some(e) = t.build(&NAMES) else {
            return Err(TestCaseError::reject("divides by an exact zero"));
        };
        if t.value(&x).is_none() || t.near_kink(&x) {
            return Err(TestCaseError::reject("no value, or near a kink"));
        }
        let Some(expected) = dd_value(&e, &x) else {
            return Err(TestCaseError::reject("no value in double-double"));
        };
        let simple = e.simplify_radicals(&Domains::chapter_defaults()).unwrap();
        let got = dd_value(&simple, &x);
        let magnitude = e.terms().iter().filter_map(|t| dd_value(t, &x)).map(Dd::abs).fold(Dd::from_f64(0.0), |s, v| s + v);
        let tolerance = Dd::from_f64(1e-20) * (Dd::from_f64(1.0) + expected.abs() + magnitude);
        prop_assert!(
            got.is_some_and(|g| (g - expected).abs() <= tolerance),
            "{} -> {}: {:?} against {:?}", e, simple, got.map(Dd::to_f64), expected.to_f64()
        );
    }
}

/// A scene declares its givens' domains by their units: kg, m, s, N and kg·m² positive,
/// unless written `real` or given a negative value; the chapter's defaults for the rest.
#[test]
fn a_scene_declares_domains_by_unit() {
    let text = "given m = 2 kg\ngiven L : m\ngiven x = 0.2 m real\ngiven y : m real\n\
                given z = -0.1 m\ngiven w = 1 rad/s\ngiven P = 10 N\ngiven I_xy : kg*m^2\n\
                body rod(L) mass m\nfixed point\nomega = w*k\nfind T\n";
    let scene = kinetics::scene::parse_scene("domains.scene", text)
        .unwrap_or_else(|d| panic!("{}", d.render()));
    let domains = scene.domains();
    for (name, domain) in [
        ("m", Domain::Positive),
        ("L", Domain::Positive),
        ("P", Domain::Positive),
        ("I_xy", Domain::Positive),
        ("x", Domain::Real),
        ("y", Domain::Real),
        ("z", Domain::Real),
        ("w", Domain::Real),
        ("b", Domain::Positive),
        ("F_x", Domain::Real),
    ] {
        assert_eq!(domains.domain(Symbol::new(name)), domain, "{name}");
    }
    let simplify = |text: &str| {
        parsed(text)
            .simplify_radicals(&domains)
            .unwrap()
            .to_string()
    };
    assert_eq!(simplify("sqrt(P^2 L^2)"), "P*L");
    assert_eq!(simplify("sqrt(x^2)"), "abs(x)");
}

/// `real` on a given that is real already is a mistake, refused at the word.
#[test]
fn real_on_a_real_given_is_refused_where_it_stands() {
    for (line, column) in [("given w = 3 rad/s real", 19), ("given k_1 = 0.5 real", 17)] {
        let text = format!("given m = 2 kg\n{line}\n");
        let d = kinetics::scene::parse_scene("real.scene", &text).expect_err(line);
        assert_eq!((d.line, d.column), (2, column), "{}", d.render());
        assert!(d.message.contains("is real already"), "{}", d.render());
    }
}
