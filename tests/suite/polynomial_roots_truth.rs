//! The exact real roots of cubics and quartics in one unknown against a ground truth
//! computed elsewhere: `tests/data/polynomial_roots.txt`, written by
//! `benches/compare/polynomial_roots.py` (mpmath's roots at 50 digits; the file's header
//! gives the line format). Each case is solved by `solve_system` with the values of its
//! other symbols as the sign oracle and no unknown that must be positive (the reading and the
//! solve are `benches/support/polynomial_roots.rs`, shared with `benches/roots.rs`). Then:
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
use kinetics::algebra::polynomial_solve::Solutions;
use kinetics::algebra::View;
use std::collections::BTreeMap;

#[path = "../../benches/support/polynomial_roots.rs"]
mod polynomial_roots;

use polynomial_roots::{corpus, Case};

/// Relative (absolute below 1) agreement of a root with the truth.
const TOLERANCE: f64 = 1e-9;

/// The most memory one solve may hold at its peak.
const MAX_PEAK_BYTES: isize = 64 << 20;

impl Case {
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
