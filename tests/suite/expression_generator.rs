//! The random expressions of the property tests (`common/expression_tree.rs`) cover what
//! their documentation claims, and at most points they have a reference value, so that
//! the properties check what they say rather than skip it.

use crate::common::expression_tree::{point, tree, Tree};
use kinetics::algebra::Func;
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;

const NAMES: [&str; 7] = ["a", "b", "w_x", "I_xy", "m", "Dt", "theta"];

/// How many trees and points are drawn (with a fixed seed).
const SAMPLES: usize = 2000;

/// Trees with a point each, and whether the case is kept: the tree builds and has a
/// reference value at the point.
fn samples() -> Vec<(Tree, bool)> {
    let mut runner = TestRunner::deterministic();
    let strategy = (tree(NAMES.len()), point(NAMES.len()));
    (0..SAMPLES)
        .map(|_| {
            let (t, x) = strategy
                .new_tree(&mut runner)
                .expect("a tree is drawn")
                .current();
            let kept = t.build(&NAMES).is_some() && t.value(&x).is_some();
            (t, kept)
        })
        .collect()
}

/// At least 80% of the cases are kept (the properties allow one case skipped for every
/// four checked, so they fail before this would).
#[test]
fn most_cases_have_a_reference_value() {
    let kept = samples().iter().filter(|(_, kept)| *kept).count();
    let fraction = kept as f64 / SAMPLES as f64;
    assert!(fraction >= 0.8, "only {kept} of {SAMPLES} cases kept");
}

/// A feature of a tree: its name, and whether a node has it.
type Feature = (&'static str, Box<dyn Fn(&Tree) -> bool>);

/// Among the kept cases, each feature occurs in at least 5% of the trees: non-integer
/// rationals, decimals, each function, square roots and other rational powers, negative
/// powers, and division by sums and by other compound expressions.
#[test]
fn kept_trees_hold_every_feature() {
    let kept: Vec<Tree> = samples()
        .into_iter()
        .filter_map(|(t, kept)| kept.then_some(t))
        .collect();
    let function = |f: Func| move |t: &Tree| matches!(t, Tree::Func(g, _) if *g == f);
    let features: Vec<Feature> = vec![
        (
            "a non-integer rational",
            Box::new(|t| matches!(t, Tree::Num(p, q) if p % q != 0)),
        ),
        (
            "a decimal",
            Box::new(|t| matches!(t, Tree::Num(p, 10) if p % 10 != 0)),
        ),
        ("sin", Box::new(function(Func::Sin))),
        ("cos", Box::new(function(Func::Cos))),
        ("tan", Box::new(function(Func::Tan))),
        ("abs", Box::new(function(Func::Abs))),
        ("sqrt", Box::new(|t| matches!(t, Tree::Pow(_, 1, 2)))),
        (
            "another rational power",
            Box::new(|t| matches!(t, Tree::Pow(_, p, q) if *q != 1 && (*p, *q) != (1, 2))),
        ),
        (
            "a negative power",
            Box::new(|t| matches!(t, Tree::Pow(_, p, _) if *p < 0)),
        ),
        (
            "division by a sum",
            Box::new(
                |t| matches!(t, Tree::Div(_, b) if matches!(**b, Tree::Add(..) | Tree::Sub(..))),
            ),
        ),
        (
            "division by a product, power or function",
            Box::new(|t| {
                matches!(t, Tree::Div(_, b)
                    if matches!(**b, Tree::Mul(..) | Tree::Div(..) | Tree::Pow(..) | Tree::Func(..)))
            }),
        ),
    ];
    let mut report = String::new();
    let mut rare = Vec::new();
    for (name, holds) in &features {
        let count = kept.iter().filter(|t| t.any(holds.as_ref())).count();
        let fraction = count as f64 / kept.len() as f64;
        report.push_str(&format!("{name}: {:.1}%\n", 100.0 * fraction));
        if fraction < 0.05 {
            rare.push(*name);
        }
    }
    assert!(rare.is_empty(), "too rare: {rare:?}\n{report}");
}
