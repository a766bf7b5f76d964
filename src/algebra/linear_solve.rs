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
    /// What is left after elimination is a polynomial in `unknown` of a degree above four.
    DegreeTooHigh {
        unknown: Symbol,
        degree: u32,
    },
    /// An unknown enters other than as a power with a whole exponent (`sin u`, `√u`).
    NotPolynomial {
        unknown: Symbol,
        term: String,
    },
    /// No unknown leaves the others linear, so no single polynomial in one unknown is
    /// reached (the term is the first that is not linear).
    NoSinglePolynomial {
        term: String,
    },
    /// Several unknowns enter only through sin, cos and tan of themselves; one unknown angle
    /// is solved at a time.
    SeveralAngles(Vec<Symbol>),
    /// The roots of the polynomial in `unknown` are not written exactly by the solver.
    RootsNotExact {
        unknown: Symbol,
        reason: String,
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
            SolveError::DegreeTooHigh { unknown, degree } => write!(
                f,
                "the equations reduce to a polynomial of degree {degree} in {}; only polynomials of degree up to 4 are solved exactly",
                unknown.name()
            ),
            SolveError::NotPolynomial { unknown, term } => write!(
                f,
                "{} enters the equations other than in whole powers (in {term}), so no polynomial in it can be solved",
                unknown.name()
            ),
            SolveError::NoSinglePolynomial { term } => write!(
                f,
                "the equations are not linear in the unknowns (term {term}), and no one unknown leaves the others linear, so they do not reduce to a polynomial in one unknown"
            ),
            SolveError::SeveralAngles(angles) => {
                let names: Vec<&str> = angles.iter().map(|s| s.name()).collect();
                let (last, rest) = names.split_last().unwrap_or((&"", &[]));
                let all = if rest.len() == 1 { "both" } else { "all" };
                write!(
                    f,
                    "the unknowns {} and {last} {all} enter through sin and cos: kinetics solves for one unknown angle at a time",
                    rest.join(", ")
                )
            }
            SolveError::RootsNotExact { unknown, reason } => write!(
                f,
                "the roots of the polynomial in {} are not written exactly: {reason}",
                unknown.name()
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
    let reduced = eliminate(equations, unknowns)?;
    // A residual that holds an unknown (in sin θ, say) is an equation left in the unknowns,
    // no contradiction: the system is not linear in them.
    let (left_in_unknowns, contradictions): (Vec<_>, Vec<_>) = reduced
        .residuals()
        .partition(|(_, residual)| unknowns.iter().any(|u| residual.contains(*u)));
    if let Some((equation, residual)) = contradictions.first() {
        return Err(SolveError::Inconsistent {
            equation: *equation,
            residual: residual.to_string(),
        });
    }
    if let Some((equation, residual)) = left_in_unknowns.first() {
        return Err(SolveError::Nonlinear {
            equation: *equation,
            term: residual.to_string(),
        });
    }
    Ok(reduced.solution(unknowns)?)
}

/// A system after Gauss–Jordan elimination: each pivot row holds one unknown with a
/// non-zero coefficient and no other pivot unknown; the rows past the pivots have zero
/// coefficients, and each says `0 = right side`.
pub(in crate::algebra) struct Reduced {
    /// (index of the equation it came from, coefficients of the unknowns then the right side).
    rows: Vec<(usize, Vec<Expr>)>,
    /// (row, column) of each pivot, in column order.
    pivots: Vec<(usize, usize)>,
}

/// Eliminates the unknowns from `equations[i] = 0`, each linear in them: their coefficients
/// may hold any other symbols (a parameter of the system, such as an unknown solved apart),
/// and functions of the unknowns (`sin θ`), as parameters.
pub(in crate::algebra) fn eliminate(
    equations: &[Expr],
    unknowns: &[Symbol],
) -> Result<Reduced, SolveError> {
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
    Ok(Reduced { rows, pivots })
}

impl Reduced {
    /// The rows past the pivots whose right side is not zero: (index of the equation,
    /// right side), each a condition `0 = right side` the elimination leaves.
    pub(in crate::algebra) fn residuals(&self) -> impl Iterator<Item = (usize, &Expr)> {
        self.rows[self.pivots.len()..]
            .iter()
            .filter_map(|(index, row)| row.last().filter(|r| !r.is_zero()).map(|r| (*index, r)))
    }

    /// The pivots' coefficients (the expressions divided by).
    pub(in crate::algebra) fn pivot_coefficients(&self) -> impl Iterator<Item = &Expr> {
        self.pivots.iter().map(|&(r, c)| &self.rows[r].1[c])
    }

    /// The value of each unknown whose pivot row holds no other unknown, and the unknowns
    /// left free (no pivot, or a pivot row that holds a free unknown).
    pub(in crate::algebra) fn solution(
        &self,
        unknowns: &[Symbol],
    ) -> Result<Solution, AlgebraError> {
        let n = unknowns.len();
        let mut solution = Vec::new();
        let mut free = Vec::new();
        for (col, u) in unknowns.iter().enumerate() {
            match self.pivots.iter().find(|&&(_, c)| c == col) {
                Some(&(r, _)) => {
                    let row = &self.rows[r].1;
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
        // An unknown inside sin is no coefficient: not a contradiction `0 = sin(x) - 1`.
        assert!(matches!(
            solve_linear(&[e("sin(x) - 1"), e("y - 2")], &[x, y]),
            Err(SolveError::Nonlinear { equation: 0, .. })
        ));
    }
}
