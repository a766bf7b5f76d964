//! A system that is linear in stages: the equations linear in the unknowns are solved first,
//! their values put into the others, which may then be linear in what is left. A gyroscope's
//! moment equation gives the precession rate φ̇, and `ΣF = m ā` then holds the pivot's
//! reaction beside `φ̇²`: linear once φ̇ is known.
//!
//! ```text
//! stage 1:  the equations linear in the unknowns   → the unknowns they determine
//! stage 2:  the rest, with those values put in     → ...
//! ```

use super::linear_solve::{solve_linear, Solution, SolveError};
use super::{Expr, Symbol};

/// Solves `equations[i] = 0` for `unknowns` in stages (see the module documentation). The
/// error is [`solve_linear`]'s when a stage determines nothing new: an equation not linear
/// in what is left (its index is the one in `equations`).
pub fn solve_linear_in_stages(
    equations: &[Expr],
    unknowns: &[Symbol],
) -> Result<Solution, SolveError> {
    let mut values: Vec<(Symbol, Expr)> = Vec::new();
    let mut pending: Vec<(usize, Expr)> = equations.iter().cloned().enumerate().collect();
    let mut left: Vec<Symbol> = unknowns.to_vec();
    loop {
        let mut linear = pending.clone();
        let first_error = loop {
            let system: Vec<Expr> = linear.iter().map(|(_, e)| e.clone()).collect();
            let wanted: Vec<Symbol> = left
                .iter()
                .copied()
                .filter(|u| system.iter().any(|e| e.contains(*u)))
                .collect();
            match solve_linear(&system, &wanted) {
                Ok(solution) => break Ok(solution),
                Err(SolveError::Nonlinear { equation, term }) => {
                    let index = linear.remove(equation).0;
                    if linear.is_empty() {
                        break Err(SolveError::Nonlinear {
                            equation: index,
                            term,
                        });
                    }
                }
                Err(SolveError::Inconsistent { equation, residual }) => {
                    break Err(SolveError::Inconsistent {
                        equation: linear[equation].0,
                        residual,
                    })
                }
                Err(e) => break Err(e),
            }
        };
        let solution = first_error?;
        let nonlinear_remain = linear.len() < pending.len();
        if !nonlinear_remain {
            values.extend(solution.values);
            let free: Vec<Symbol> = left
                .into_iter()
                .filter(|u| !values.iter().any(|(v, _)| v == u))
                .collect();
            return Ok(Solution { values, free });
        }
        if solution.values.is_empty() {
            // Nothing new: report the first equation left that is not linear.
            let rest: Vec<Expr> = pending.iter().map(|(_, e)| e.clone()).collect();
            return match solve_linear(&rest, &left) {
                Err(SolveError::Nonlinear { equation, term }) => Err(SolveError::Nonlinear {
                    equation: pending[equation].0,
                    term,
                }),
                other => other,
            };
        }
        let lookup = |s: Symbol| {
            solution
                .values
                .iter()
                .find(|(u, _)| *u == s)
                .map(|(_, v)| v.clone())
        };
        let used: Vec<usize> = linear.iter().map(|(k, _)| *k).collect();
        pending = pending
            .into_iter()
            .filter(|(k, _)| !used.contains(k))
            .map(|(k, e)| Ok((k, e.subs(&lookup)?.expand()?)))
            .collect::<Result<_, crate::algebra::AlgebraError>>()
            .map_err(SolveError::Algebra)?;
        left.retain(|u| !solution.values.iter().any(|(v, _)| v == u));
        values.extend(solution.values);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::parse_expression;

    fn e(t: &str) -> Expr {
        parse_expression("test", t).unwrap()
    }

    /// `m g L = I p s` gives p; then `R + m L p² = 0` gives R: by hand, R = −m L (m g L/(I s))².
    #[test]
    fn a_reaction_beside_the_square_of_a_rate_solved_first_is_found() {
        let equations = [e("R + m*L*p^2"), e("m*g*L - I*p*s")];
        let unknowns = [Symbol::new("R"), Symbol::new("p")];
        let solution = solve_linear_in_stages(&equations, &unknowns).unwrap();
        let value = |n: &str| {
            let s = Symbol::new(n);
            solution
                .values
                .iter()
                .find(|(u, _)| *u == s)
                .unwrap()
                .1
                .clone()
        };
        let expected = e("-m*L*(m*g*L/(I*s))^2");
        assert_eq!(
            (value("R") - expected).cancel().unwrap(),
            Expr::zero(),
            "R = {}",
            value("R")
        );
        assert!(solution.free.is_empty());
    }

    /// q = 4 is found, and p² = 4 stays: a polynomial this solver does not take.
    #[test]
    fn an_equation_that_stays_nonlinear_is_reported_at_its_index() {
        let equations = [e("q - 4"), e("p^2 - q")];
        let unknowns = [Symbol::new("p"), Symbol::new("q")];
        match solve_linear_in_stages(&equations, &unknowns) {
            Err(SolveError::Nonlinear { equation, .. }) => assert_eq!(equation, 1),
            other => panic!("expected nonlinear, got {other:?}"),
        }
    }
}
