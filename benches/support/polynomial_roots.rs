//! The corpus `tests/data/polynomial_roots.txt` of cubics and quartics in one unknown with
//! their real roots by mpmath at 50 digits (written by `benches/compare/polynomial_roots.py`,
//! whose documentation and the file's header give the line format), and each case's solve
//! by `solve_system` with the values of its other symbols as the sign oracle and no unknown
//! that must be positive. Shared by the truth test (`tests/suite/polynomial_roots_truth.rs`)
//! and the benchmark (`benches/roots.rs`), so that both solve the same cases the same way.

use kinetics::algebra::polynomial_solve::{solve_system, Solutions, SolveContext, SolveError};
use kinetics::algebra::{Expr, Symbol};
use kinetics::parse::parse_expression;
use std::cmp::Ordering;

const CORPUS: &str = include_str!("../../tests/data/polynomial_roots.txt");

/// One line of the corpus.
pub struct Case {
    pub line: usize,
    pub kind: String,
    pub text: String,
    pub polynomial: Expr,
    pub unknown: Symbol,
    pub values: Vec<(Symbol, f64)>,
    /// The distinct real roots, ascending.
    pub roots: Vec<f64>,
}

impl Case {
    fn value(&self, s: Symbol) -> Option<f64> {
        self.values.iter().find(|(t, _)| *t == s).map(|(_, v)| *v)
    }

    /// `e` in f64 at the values, and `x` for the unknown when given.
    pub fn eval(&self, e: &Expr, x: Option<f64>) -> Option<f64> {
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

    /// `polynomial = 0` solved for the unknown, the values telling the signs.
    pub fn solve(&self) -> Result<Solutions, SolveError> {
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
}

/// Every case of the corpus, in the file's order; a malformed line panics with its number.
pub fn corpus() -> Vec<Case> {
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
