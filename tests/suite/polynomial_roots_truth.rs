//! The exact real roots of cubics and quartics in one unknown against a ground truth
//! computed elsewhere: `tests/data/polynomial_roots.txt`, written by
//! `benches/compare/polynomial_roots.py` (mpmath's roots at 50 digits; the file's header
//! gives the line format). Each case is solved by `solve_system` with the values of its
//! other symbols as the sign oracle and no unknown that must be positive. Then:
//!
//! - there are as many branches as distinct real roots, each branch's value evaluated in f64
//!   at the values is one of them, `|got − root| ≤ 10⁻⁹ max(1, |root|)`, one to one;
//! - no dropped root is real: each either fails to evaluate to a finite f64 (a complex
//!   value) or equals none of the real roots;
//! - each solve holds a bounded amount of memory at its peak (the corpus runs in bounded
//!   memory; no wall-clock time is asserted);
//! - each root put back into the polynomial leaves `|Σ tₖ| ≤ 10⁻⁹ Σ |tₖ|`, `tₖ` its terms
//!   evaluated in f64.
//!
//! A failure lists every case that fails, with its line, kind and polynomial, and how many
//! cases of each kind pass.

use crate::common::counting_allocator::peak_during;
use kinetics::algebra::polynomial_solve::{solve_system, Solutions, SolveContext, SolveError};
use kinetics::algebra::{Expr, Symbol, View};
use kinetics::parse::parse_expression;
use std::cmp::Ordering;
use std::collections::BTreeMap;

const CORPUS: &str = include_str!("../data/polynomial_roots.txt");

/// Relative (absolute below 1) agreement of a root with the truth.
const TOLERANCE: f64 = 1e-9;

/// The most memory one solve may hold at its peak.
const MAX_PEAK_BYTES: isize = 64 << 20;

/// One line of the corpus.
struct Case {
    line: usize,
    kind: String,
    text: String,
    polynomial: Expr,
    unknown: Symbol,
    values: Vec<(Symbol, f64)>,
    roots: Vec<f64>,
}

impl Case {
    fn value(&self, s: Symbol) -> Option<f64> {
        self.values.iter().find(|(t, _)| *t == s).map(|(_, v)| *v)
    }

    /// `e` in f64 at the values, and `x` for the unknown when given.
    fn eval(&self, e: &Expr, x: Option<f64>) -> Option<f64> {
        let value = |s: Symbol| {
            if s == self.unknown {
                x
            } else {
                self.value(s)
            }
        };
        e.eval(&value).ok().filter(|v: &f64| v.is_finite())
    }

    /// The sign at the values: zero below 1e-12, unknown below 1e-9 (as polynomial_solve.rs).
    fn sign(&self, e: &Expr) -> Option<Ordering> {
        let v = self.eval(e, None)?;
        match v.abs() {
            a if a < 1e-12 => Some(Ordering::Equal),
            a if a < 1e-9 => None,
            _ => v.partial_cmp(&0.0),
        }
    }

    fn solve(&self) -> Result<Solutions, SolveError> {
        let sign = |e: &Expr| self.sign(e);
        let context = SolveContext {
            sign: &sign,
            positive: &|_| false,
        };
        solve_system(
            std::slice::from_ref(&self.polynomial),
            &[self.unknown],
            &context,
        )
    }

    /// The index of the true root `v` agrees with, if any.
    fn truth_matching(&self, v: f64) -> Option<usize> {
        self.roots
            .iter()
            .position(|&r| (v - r).abs() <= TOLERANCE * r.abs().max(1.0))
    }

    /// Each branch's root in f64, in the branches' order.
    fn branch_roots(&self, solved: &Solutions) -> Result<Vec<f64>, String> {
        solved
            .branches
            .iter()
            .map(|branch| match branch.as_slice() {
                [(u, value)] if *u == self.unknown => self
                    .eval(value, None)
                    .ok_or_else(|| format!("the root {value} is not a real number")),
                _ => Err(format!("a branch is not one value of x: {branch:?}")),
            })
            .collect()
    }

    /// The roots agree with the truth one to one and no real root is dropped.
    fn check_roots(&self, solved: &Solutions) -> Result<(), String> {
        if solved.branches.len() != self.roots.len() {
            return Err(format!(
                "{} branches for {} real roots {:?}: {:?}",
                solved.branches.len(),
                self.roots.len(),
                self.roots,
                solved.branches
            ));
        }
        let mut matched = vec![false; self.roots.len()];
        for v in self.branch_roots(solved)? {
            match self.truth_matching(v) {
                Some(i) if !matched[i] => matched[i] = true,
                Some(i) => return Err(format!("{v} is the root {} twice", self.roots[i])),
                None => return Err(format!("{v} is none of the roots {:?}", self.roots)),
            }
        }
        for dropped in &solved.dropped {
            if let Some(v) = self.eval(&dropped.value, None) {
                if self.truth_matching(v).is_some() {
                    return Err(format!(
                        "the real root {} = {v} is dropped: {}",
                        dropped.value, dropped.reason
                    ));
                }
            }
        }
        Ok(())
    }

    /// Each root put back leaves a residual small beside the polynomial's terms.
    fn check_residuals(&self, solved: &Solutions) -> Result<(), String> {
        let expanded = self.polynomial.expand().map_err(|e| e.to_string())?;
        let terms = match expanded.view() {
            View::Add(terms) => terms.to_vec(),
            _ => vec![expanded.clone()],
        };
        for x in self.branch_roots(solved)? {
            let values: Option<Vec<f64>> = terms.iter().map(|t| self.eval(t, Some(x))).collect();
            let values = values.ok_or_else(|| format!("a term is not finite at x = {x}"))?;
            let residual: f64 = values.iter().sum();
            let scale: f64 = values.iter().map(|t| t.abs()).sum();
            if residual.abs() > TOLERANCE * scale {
                return Err(format!(
                    "at x = {x} the residual {residual:e} is more than {TOLERANCE:e} of Σ|terms| = {scale:e}"
                ));
            }
        }
        Ok(())
    }
}

fn corpus() -> Vec<Case> {
    CORPUS
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
        .map(|(n, l)| {
            let line = n + 1;
            let fields: Vec<&str> = l.split(" | ").collect();
            let [kind, text, unknown, values, roots] = fields.as_slice() else {
                panic!("polynomial_roots.txt:{line}: five fields expected: {l}");
            };
            let number = |s: &str| -> f64 {
                s.trim().parse().unwrap_or_else(|e| {
                    panic!("polynomial_roots.txt:{line}: {s:?} is not a number: {e}")
                })
            };
            let values = match *values {
                "-" => Vec::new(),
                list => list
                    .split(", ")
                    .map(|pair| {
                        let (name, value) = pair.split_once('=').unwrap_or_else(|| {
                            panic!("polynomial_roots.txt:{line}: {pair:?} is not name=value")
                        });
                        (Symbol::new(name), number(value))
                    })
                    .collect(),
            };
            let roots = match *roots {
                "none" => Vec::new(),
                list => list.split(", ").map(number).collect(),
            };
            Case {
                line,
                kind: kind.to_string(),
                text: text.to_string(),
                polynomial: parse_expression(&format!("polynomial_roots.txt:{line}"), text)
                    .unwrap_or_else(|d| panic!("{}", d.render())),
                unknown: Symbol::new(unknown),
                values,
                roots,
            }
        })
        .collect()
}

/// Runs `check` on every case's solution; fails listing each case that fails and the
/// number of cases of each kind that pass.
fn every_case(check: impl Fn(&Case, &Solutions) -> Result<(), String>) {
    let cases = corpus();
    assert!(cases.len() >= 80, "{} cases", cases.len());
    let mut failures = Vec::new();
    let mut by_kind: BTreeMap<&str, (usize, usize)> = BTreeMap::new();
    for case in &cases {
        let mut solved = None;
        let peak = peak_during(|| solved = Some(case.solve()));
        let outcome = match solved.expect("the solve ran") {
            _ if peak > MAX_PEAK_BYTES => Err(format!("held {peak} bytes at its peak")),
            Ok(solved) => check(case, &solved),
            Err(e) => Err(format!("not solved: {e}")),
        };
        let count = by_kind.entry(&case.kind).or_default();
        count.1 += 1;
        match outcome {
            Ok(()) => count.0 += 1,
            Err(why) => failures.push(format!(
                "line {} ({}) {} = 0: {why}",
                case.line, case.kind, case.text
            )),
        }
    }
    let summary: Vec<String> = by_kind
        .iter()
        .map(|(kind, (passed, total))| format!("{kind}: {passed}/{total}"))
        .collect();
    assert!(
        failures.is_empty(),
        "{} of {} cases fail:\n{}\npassing by kind:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n"),
        summary.join("\n")
    );
}

#[test]
fn the_real_roots_are_mpmaths_one_to_one() {
    every_case(Case::check_roots);
}

#[test]
fn each_root_put_back_leaves_a_small_residual() {
    every_case(Case::check_residuals);
}
