//! Exact solution of linear equations over the expression algebra (symbolic Gaussian
//! elimination): each equation is `expr = 0`, linear in the unknowns, with coefficients that
//! may hold any other symbols.

use super::error::AlgebraError;
use super::expr::Expr;
use super::symbol::Symbol;

/// Why a system has no unique solution.
#[derive(Debug, Clone, PartialEq)]
pub enum SolveError {
    Algebra(AlgebraError),
    /// An unknown appears in a product with another unknown or to a power.
    Nonlinear {
        equation: usize,
        term: String,
    },
    /// These unknowns are not determined by the equations.
    UnderDetermined(Vec<Symbol>),
    /// This equation (by index) contradicts the others: it reduces to `0 = residual`.
    Inconsistent {
        equation: usize,
        residual: String,
    },
}

impl From<AlgebraError> for SolveError {
    fn from(e: AlgebraError) -> SolveError {
        SolveError::Algebra(e)
    }
}

impl std::fmt::Display for SolveError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SolveError::Algebra(e) => write!(f, "{e}"),
            SolveError::Nonlinear { equation, term } => {
                write!(f, "equation {} is not linear in the unknowns (term {term})", equation + 1)
            }
            SolveError::UnderDetermined(u) => {
                let names: Vec<&str> = u.iter().map(|s| s.name()).collect();
                write!(f, "under-determined: the equations do not fix {}", names.join(", "))
            }
            SolveError::Inconsistent { equation, residual } => write!(
                f,
                "over-determined: equation {} contradicts the others (it reduces to 0 = {residual})",
                equation + 1
            ),
        }
    }
}

/// The unknowns a linear system determines, and those it leaves free.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    pub values: Vec<(Symbol, Expr)>,
    pub free: Vec<Symbol>,
}

/// Solves `equations[i] = 0` for `unknowns`. Returns the value of every unknown that the
/// system determines; the unknowns it leaves free are returned separately so the caller
/// can decide whether that matters.
pub fn solve_linear(equations: &[Expr], unknowns: &[Symbol]) -> Result<Solution, SolveError> {
    let n = unknowns.len();
    // Rows: coefficients of the unknowns, then the right side.
    let mut rows: Vec<(usize, Vec<Expr>)> = Vec::with_capacity(equations.len());
    for (index, eq) in equations.iter().enumerate() {
        let mut row = vec![Expr::zero(); n + 1];
        for group in eq.collect(unknowns)? {
            let term = &group.monomial;
            if term.is_one() {
                row[n] = -&group.coefficient;
            } else if let Some(k) = unknowns.iter().position(|u| Expr::sym(*u) == *term) {
                row[k] = group.coefficient.clone();
            } else {
                return Err(SolveError::Nonlinear {
                    equation: index,
                    term: term.to_string(),
                });
            }
        }
        rows.push((index, row));
    }
    let mut pivots: Vec<(usize, usize)> = Vec::new(); // (row, column)
    let mut next_row = 0;
    for col in 0..n {
        let Some(p) = (next_row..rows.len()).find(|&r| !rows[r].1[col].is_zero()) else {
            continue;
        };
        rows.swap(next_row, p);
        let pivot = rows[next_row].1[col].clone();
        let pivot_row = rows[next_row].1.clone();
        for (r, (_, row)) in rows.iter_mut().enumerate() {
            if r == next_row || row[col].is_zero() {
                continue;
            }
            let factor = row[col].checked_div(&pivot)?;
            for k in col..=n {
                if !pivot_row[k].is_zero() {
                    row[k] = (&row[k] - &(&factor * &pivot_row[k])).expand()?;
                }
            }
        }
        pivots.push((next_row, col));
        next_row += 1;
    }
    for (index, row) in &rows[next_row..] {
        if !row[n].is_zero() {
            return Err(SolveError::Inconsistent {
                equation: *index,
                residual: row[n].to_string(),
            });
        }
    }
    let mut solution = Vec::new();
    let mut free = Vec::new();
    for (col, u) in unknowns.iter().enumerate() {
        match pivots.iter().find(|&&(_, c)| c == col) {
            Some(&(r, _)) => {
                let row = &rows[r].1;
                if row[..n]
                    .iter()
                    .enumerate()
                    .any(|(k, e)| k != col && !e.is_zero())
                {
                    free.push(*u);
                } else {
                    solution.push((*u, row[n].checked_div(&row[col])?.expand()?));
                }
            }
            None => free.push(*u),
        }
    }
    Ok(Solution {
        values: solution,
        free,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::parse_expression;

    fn e(s: &str) -> Expr {
        parse_expression("t", s).unwrap()
    }

    #[test]
    fn solves_a_symbolic_system() {
        let (x, y) = (Symbol::new("x"), Symbol::new("y"));
        let Solution { values: sol, free } =
            solve_linear(&[e("a x + y - 3"), e("x - y - b")], &[x, y]).unwrap();
        assert!(free.is_empty());
        // x = (3 + b)/(a + 1): check by substitution.
        for eq in [e("a x + y - 3"), e("x - y - b")] {
            let back = eq
                .subs(&|s| sol.iter().find(|(u, _)| *u == s).map(|(_, v)| v.clone()))
                .unwrap();
            let at = |s: Symbol| Some(if s.name() == "a" { 2.0 } else { 5.0 });
            let residual: f64 = back.eval(&at).unwrap();
            assert!(residual.abs() < 1e-12);
        }
    }

    #[test]
    fn reports_under_and_over_determined_and_nonlinear() {
        let (x, y) = (Symbol::new("x"), Symbol::new("y"));
        let free = solve_linear(&[e("x + y - 1")], &[x, y]).unwrap().free;
        assert_eq!(free, vec![x, y]);
        assert!(matches!(
            solve_linear(&[e("x - 1"), e("x - 2")], &[x]),
            Err(SolveError::Inconsistent { equation: 1, .. })
        ));
        assert!(matches!(
            solve_linear(&[e("x y - 1")], &[x, y]),
            Err(SolveError::Nonlinear { .. })
        ));
    }
}
