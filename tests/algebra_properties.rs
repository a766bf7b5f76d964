//! Property tests over random expressions: canonical construction, expansion and
//! collection keep the value; printing as text and parsing back gives the same canonical
//! form; the canonical form is idempotent.

use kinetics::algebra::{Expr, Func, Symbol};
use kinetics::parse::parse_expression;
use kinetics::print;
use proptest::prelude::*;

const NAMES: [&str; 6] = ["a", "b", "w_x", "I_xy", "m", "Dt"];

/// A random expression tree, evaluated directly (without the algebra) as the reference.
#[derive(Debug, Clone)]
enum Tree {
    Int(i64),
    Var(usize),
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    DivVar(Box<Tree>, usize),
    Pow(Box<Tree>, u8),
    Neg(Box<Tree>),
    Sin(Box<Tree>),
}

fn tree() -> impl Strategy<Value = Tree> {
    let leaf = prop_oneof![
        (-4i64..5).prop_map(Tree::Int),
        (0..NAMES.len()).prop_map(Tree::Var)
    ];
    leaf.prop_recursive(5, 40, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Add(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Sub(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Mul(Box::new(a), Box::new(b))),
            (inner.clone(), 0..NAMES.len()).prop_map(|(a, v)| Tree::DivVar(Box::new(a), v)),
            (inner.clone(), 0u8..4).prop_map(|(a, n)| Tree::Pow(Box::new(a), n)),
            inner.clone().prop_map(|a| Tree::Neg(Box::new(a))),
            inner.prop_map(|a| Tree::Sin(Box::new(a))),
        ]
    })
}

fn build(t: &Tree) -> Expr {
    match t {
        Tree::Int(n) => Expr::int(*n),
        Tree::Var(i) => Expr::symbol(NAMES[*i]),
        Tree::Add(a, b) => build(a) + build(b),
        Tree::Sub(a, b) => build(a) - build(b),
        Tree::Mul(a, b) => build(a) * build(b),
        Tree::DivVar(a, v) => build(a) / Expr::symbol(NAMES[*v]),
        Tree::Pow(a, n) => build(a).powi(*n as i64),
        Tree::Neg(a) => -build(a),
        Tree::Sin(a) => Expr::func(Func::Sin, build(a)),
    }
}

fn reference(t: &Tree, x: &[f64; 6]) -> f64 {
    match t {
        Tree::Int(n) => *n as f64,
        Tree::Var(i) => x[*i],
        Tree::Add(a, b) => reference(a, x) + reference(b, x),
        Tree::Sub(a, b) => reference(a, x) - reference(b, x),
        Tree::Mul(a, b) => reference(a, x) * reference(b, x),
        Tree::DivVar(a, v) => reference(a, x) / x[*v],
        Tree::Pow(a, n) => reference(a, x).powi(*n as i32),
        Tree::Neg(a) => -reference(a, x),
        Tree::Sin(a) => reference(a, x).sin(),
    }
}

fn value(e: &Expr, x: &[f64; 6]) -> f64 {
    e.eval(&|s: Symbol| NAMES.iter().position(|n| Symbol::new(n) == s).map(|i| x[i]))
        .expect("every symbol has a value and divisors are non-zero")
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

fn point() -> impl Strategy<Value = [f64; 6]> {
    // Values away from zero so that the symbolic divisors are safe.
    let v = prop_oneof![0.3f64..1.7, -1.7f64..-0.3];
    [v.clone(), v.clone(), v.clone(), v.clone(), v.clone(), v]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn canonical_form_keeps_the_value(t in tree(), x in point()) {
        let e = build(&t);
        prop_assert!(close(value(&e, &x), reference(&t, &x)), "{e}");
    }

    #[test]
    fn expanding_and_collecting_keep_the_value(t in tree(), x in point()) {
        let e = build(&t);
        let expanded = e.expand().unwrap();
        prop_assert!(close(value(&expanded, &x), reference(&t, &x)), "{expanded}");
        let by_w = [Symbol::new("w_x"), Symbol::new("a")];
        let collected: Expr = e
            .collect(&by_w)
            .unwrap()
            .into_iter()
            .map(|g| g.monomial * g.coefficient)
            .sum();
        prop_assert!(close(value(&collected, &x), reference(&t, &x)), "{collected}");
    }

    #[test]
    fn text_parses_back_to_the_same_canonical_form(t in tree()) {
        let e = build(&t);
        let printed = print::text(&e);
        let back = parse_expression("printed", &printed).unwrap();
        prop_assert_eq!(back.expand().unwrap(), e.expand().unwrap(), "printed as {}", printed);
    }

    #[test]
    fn canonical_form_is_idempotent(t in tree()) {
        let e = build(&t);
        let expanded = e.expand().unwrap();
        prop_assert_eq!(expanded.expand().unwrap(), expanded.clone());
        prop_assert_eq!(Expr::add_all(e.terms().to_vec()), e.clone());
        prop_assert_eq!(Expr::mul_all(e.factors().to_vec()), e);
    }

    #[test]
    fn latex_has_no_plus_minus_and_balanced_braces(t in tree()) {
        let latex = print::latex(&build(&t));
        prop_assert!(!latex.contains("+ -"), "{}", latex);
        prop_assert_eq!(latex.matches('{').count(), latex.matches('}').count());
    }
}

#[test]
fn polynomials_equal_exactly_when_expansions_are_identical() {
    let p = |s: &str| parse_expression("t", s).unwrap().expand().unwrap();
    assert_eq!(p("(a + b)^2"), p("a^2 + 2 a b + b^2"));
    assert_eq!(p("(a + b)/m"), p("a/m + b/m"));
    assert_ne!(p("(a + b)^2"), p("a^2 + b^2"));
    assert_eq!(p("0.1 + 0.2"), p("3/10"));
}
