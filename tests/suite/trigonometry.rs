//! Trigonometry (issue 15, item 3): `sin²θ + cos²θ = 1` in any multiple and combination,
//! the double angle where it is shorter, the exact values at the multiples of 15°, π and
//! the degree. Values are checked in double-double.

use kinetics::algebra::{AlgebraError, Expr, Func, Symbol};
use kinetics::numeric::scalar::double_double::DoubleDouble as Dd;
use kinetics::parse::parse_expression;
use proptest::prelude::*;

fn parse(text: &str) -> Expr {
    parse_expression("<test>", text).unwrap()
}

fn simplified(text: &str) -> Expr {
    parse(text).simplify_trig().unwrap()
}

/// The value in double-double with the symbols at fixed irrational-looking points.
fn value_at(e: &Expr, point: &dyn Fn(Symbol) -> Dd) -> Dd {
    e.eval(&|s| Some(point(s))).unwrap()
}

#[test]
fn the_issues_examples() {
    assert_eq!(simplified("sin(x)^2 + cos(x)^2"), parse("1"));
    assert_eq!(simplified("a*sin(x)^2 + a*cos(x)^2"), parse("a"));
    assert_eq!(simplified("3*sin(x)^2 + 3*cos(x)^2"), parse("3"));
    assert_eq!(simplified("1 - sin(x)^2"), parse("cos(x)^2"));
    assert_eq!(simplified("a - a*cos(x)^2"), parse("a*sin(x)^2"));
    assert_eq!(
        simplified("sin(t)^2*cos(p)^2 + cos(t)^2*cos(p)^2"),
        parse("cos(p)^2")
    );
    assert_eq!(
        simplified("cos(x)^4 + sin(x)^2*cos(x)^2"),
        parse("cos(x)^2")
    );
}

#[test]
fn inside_arguments_powers_and_denominators() {
    assert_eq!(simplified("a/(sin(x)^2 + cos(x)^2)"), parse("a"));
    assert_eq!(simplified("b/(m*(1 - cos(x)^2))"), parse("b/(m*sin(x)^2)"));
    assert_eq!(simplified("sin(sin(y)^2 + cos(y)^2)"), parse("sin(1)"));
    assert_eq!(
        simplified("(sin(x)^2 + cos(x)^2 + a)^3"),
        parse("(1 + a)^3")
    );
    assert_eq!(simplified("(1 - sin(x))*(1 + sin(x))"), parse("cos(x)^2"));
}

#[test]
fn double_angles_only_where_shorter() {
    assert_eq!(simplified("2*sin(x)*cos(x)"), parse("sin(2*x)"));
    assert_eq!(simplified("cos(x)^2 - sin(x)^2"), parse("cos(2*x)"));
    assert_eq!(simplified("1 - 2*sin(x)^2"), parse("cos(2*x)"));
    // `sin x cos x` alone is as long as `sin(2x)/2`: left as it is.
    assert_eq!(simplified("sin(x)*cos(x)"), parse("sin(x)*cos(x)"));
}

#[test]
fn negative_controls_stay() {
    for text in [
        "sin(t)^2 + cos(p)^2",
        "sin(x)^2 + cos(2*x)^2",
        "a*sin(x)^2 + b*cos(x)^2",
        "sin(x) + cos(x)",
        "tan(x)^2 + 1",
    ] {
        assert_eq!(simplified(text), parse(text), "{text}");
    }
}

/// A power past the largest rewritten is left as it is at once (`cos⁴⁰⁰⁰⁰⁰` would be
/// 200,001 terms); a sum whose rewriting would pass the bound on terms is refused.
#[test]
fn beyond_the_bound_an_error_not_a_hang() {
    let huge = parse("a*cos(x)^400000 + sin(x)");
    assert_eq!(huge.simplify_trig().unwrap(), huge);
    let many = (0..20_000)
        .map(|i| format!("x{i}*cos(t)^12"))
        .collect::<Vec<_>>()
        .join(" + ");
    let err = parse(&many).simplify_trig().unwrap_err();
    assert!(matches!(err, AlgebraError::TooLarge { .. }), "{err}");
}

/// Multiplying out is only tried: a product too large to expand stays as it is.
#[test]
fn a_product_too_large_to_multiply_out_stays() {
    let e = parse("(a + b + c + d + e + sin(x))^40");
    assert_eq!(e.simplify_trig().unwrap(), e);
}

#[test]
fn exact_values_in_degrees_and_pi() {
    for (text, exact) in [
        ("cos(90 deg)", "0"),
        ("sin(30 deg)", "1/2"),
        ("sin(30*deg)", "1/2"),
        ("cos(45 deg)", "sqrt(2)/2"),
        ("cos(pi/2)", "0"),
        ("sin(pi/6)", "1/2"),
        ("cos(pi/4)", "sqrt(2)/2"),
        ("sin(pi/12)", "(sqrt(6) - sqrt(2))/4"),
        ("tan(pi/3)", "sqrt(3)"),
        ("cos(13*pi/6)", "cos(pi/6)"),
        ("cos(13*pi/6)", "sqrt(3)/2"),
        ("sin(-pi/6)", "-1/2"),
        ("tan(-135 deg)", "1"),
    ] {
        assert_eq!(parse(text), parse(exact), "{text}");
    }
}

#[test]
fn tan_of_an_odd_multiple_of_a_right_angle_is_refused() {
    for text in [
        "tan(pi/2)",
        "tan(90 deg)",
        "tan(-270*deg)",
        "1 + tan(3*pi/2)",
    ] {
        let err = parse_expression("<test>", text).unwrap_err();
        assert!(err.message.contains("undefined"), "{text}: {}", err.message);
    }
}

/// Every multiple of 15° from 0° to 360°: sin, cos and tan exact, against double-double.
#[test]
fn every_multiple_of_fifteen_degrees() {
    for k in 0..=24i64 {
        let x = Dd::PI * Dd::from_f64(k as f64) / Dd::from_f64(12.0);
        for (name, f) in [("sin", Func::Sin), ("cos", Func::Cos), ("tan", Func::Tan)] {
            let text = format!("{name}({} deg)", 15 * k);
            if f == Func::Tan && k % 12 == 6 {
                assert!(parse_expression("<test>", &text).is_err(), "{text}");
                continue;
            }
            let e = parse(&text);
            assert!(e.symbols().is_empty(), "{text} is not exact: {e}");
            let got: Dd = e.eval(&|_| None).unwrap();
            let want = f.eval(x);
            let error = (got - want).abs().to_f64();
            assert!(error < 1e-29, "{text} = {e}: off by {error:e}");
            let in_f64: f64 = e.eval(&|_| None).unwrap();
            assert!((in_f64 - f.eval(x.to_f64())).abs() < 1e-14, "{text}");
        }
    }
}

#[test]
fn pi_is_a_constant() {
    let pi = Expr::pi();
    assert_eq!(pi.d_dt().unwrap(), Expr::zero());
    let v: Dd = pi.eval(&|_| None).unwrap();
    assert_eq!(v, Dd::PI);
    assert_eq!(kinetics::print::latex(&parse("2*pi*r")), r"2 \pi r");
}

/// A random trigonometric polynomial in two angles: terms `c · a^i · sinᵖx cosᵠx sinʳy cosˢy`.
fn trig_polynomial() -> impl Strategy<Value = String> {
    let term = (-3i64..=3, 0u32..=1, 0u32..=3, 0u32..=3, 0u32..=2, 0u32..=2);
    prop::collection::vec(term, 1..6).prop_map(|terms| {
        let written: Vec<String> = terms
            .iter()
            .map(|(c, i, p, q, r, s)| {
                format!("{c}*a^{i}*sin(x)^{p}*cos(x)^{q}*sin(y)^{r}*cos(y)^{s}")
            })
            .collect();
        written.join(" + ")
    })
}

fn point(a: f64, x: f64, y: f64) -> impl Fn(Symbol) -> Dd {
    move |s| {
        Dd::from_f64(match s.name() {
            "a" => a,
            "x" => x,
            _ => y,
        })
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2_000))]

    /// `simplify_trig` keeps the value (in double-double) and never grows the count.
    #[test]
    fn simplify_trig_keeps_the_value_and_never_grows(
        text in trig_polynomial(),
        a in -2.0f64..2.0,
        x in -4.0f64..4.0,
        y in -4.0f64..4.0,
    ) {
        let e = parse(&text);
        let s = e.simplify_trig().unwrap();
        prop_assert!(s.operation_count() <= e.operation_count(), "{e} -> {s}");
        let at = point(a, x, y);
        let (before, after) = (value_at(&e, &at), value_at(&s, &at));
        let scale = before.abs().to_f64().max(1.0);
        prop_assert!((before - after).abs().to_f64() < 1e-26 * scale, "{e} -> {s}");
    }
}

const SCENE: &str = "given M = 5 kg\ngiven R = 1 m\nbody sphere(R) mass M\n";

#[test]
fn a_scene_may_not_declare_pi_or_deg() {
    for (name, says) in [("pi", "constant"), ("deg", "degree")] {
        let text = format!("given {name} = 3\n{SCENE}find T");
        let err = kinetics::parse_scene("t.scene", &text).unwrap_err();
        assert!(err.message.contains(says), "{name}: {}", err.message);
        assert_eq!((err.line, err.column), (1, 7), "{name}");
    }
}

#[test]
fn a_scene_may_use_pi_and_deg() {
    let text =
        format!("given t1 = 1 s\n{SCENE}omega = 2*pi*k/t1 + sin(30 deg)*i/t1\nvbar = 0\nfind T");
    let scene = kinetics::parse_scene("t.scene", &text).unwrap();
    let omega = scene.omega.clone().unwrap();
    assert_eq!(omega[2], parse("2*pi/t1"));
    assert_eq!(omega[0], parse("1/(2*t1)"));
}

#[test]
fn a_given_angle_in_degrees_is_exact() {
    let text = format!("given theta = 90 deg\n{SCENE}find T");
    let scene = kinetics::parse_scene("t.scene", &text).unwrap();
    let theta = scene.exact_given(Symbol::new("theta")).unwrap();
    assert_eq!(theta, parse("pi/2"));
    assert_eq!(Expr::func(Func::Sin, theta), Expr::one());
}

/// A compiled tape takes π as the constant it is, not as an input.
#[test]
fn a_tape_holds_pi_as_a_constant() {
    let e = parse("2*pi*x");
    let tape = kinetics::numeric::Tape::compile(&[e], &[Symbol::new("x")]).unwrap();
    let mut out = [0.0];
    tape.eval(&[1.5], &mut out).unwrap();
    assert!((out[0] - 3.0 * std::f64::consts::PI).abs() < 1e-15);
}

mod random_expressions {
    use crate::common::expression_tree::{agrees, config, point, tree, values};
    use proptest::prelude::*;

    const NAMES: [&str; 4] = ["a", "b", "theta", "phi"];

    proptest! {
        #![proptest_config(config(2_000))]

        /// On random expressions (functions, powers, quotients), `simplify_trig` keeps the
        /// value of the tree and never grows the operation count.
        #[test]
        fn simplify_trig_on_any_expression(t in tree(NAMES.len()), x in point(NAMES.len())) {
            let Some(expected) = t.value(&x) else {
                return Err(TestCaseError::reject("no reference value"));
            };
            let Some(e) = t.build(&NAMES) else {
                return Err(TestCaseError::reject("division by an exact zero"));
            };
            let s = e.simplify_trig().unwrap();
            prop_assert!(s.operation_count() <= e.operation_count(), "{e} -> {s}");
            let checked = agrees(&s, expected, &values(&NAMES, &x));
            prop_assert!(checked.is_ok(), "{e} -> {s}: {}", checked.unwrap_err());
        }
    }
}

/// π is positive: `√(π²) = π`, `|2π| = 2π`.
#[test]
fn pi_is_positive() {
    let domains = kinetics::algebra::Domains::chapter_defaults();
    assert!(domains.is_positive(&parse("2*pi")));
}
