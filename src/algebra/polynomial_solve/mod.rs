//! Exact solution of equations `expr = 0` in which one unknown may enter polynomially (the
//! `φ̇²` of a top's steady precession), the others linearly.
//!
//! A linear system is [`solve_linear`]'s (one branch). Otherwise one unknown `u` is taken
//! as a parameter: the first, in the order given, that leaves the system linear in the
//! others. Gauss–Jordan elimination of the others (their coefficients may hold `u`) leaves
//! conditions `0 = rᵢ(u)`; the numerator of `r₁` in lowest terms (or the gcd of the
//! numerators, when several are left) is a polynomial `p(u) = Σ aₖ uᵏ` whose coefficients
//! are free of the unknowns. Its common factor in the givens is divided out when its sign is
//! known (it cannot then be zero), and its real roots are found exactly for a degree up to
//! four (`roots.rs`). Each root is put back into the eliminated system, giving one branch;
//! a root is dropped, with the reason, when it makes a pivot of the elimination or a value's
//! denominator zero, or makes an unknown that must be positive negative or zero.

mod cardano;
mod ferrari;
mod quadratic;
mod rational_roots;
mod roots;
mod square_free;
mod surd;
pub mod unknown_angle;

use super::error::AlgebraError;
use super::expr::Expr;
use super::linear_solve::{eliminate, solve_linear, Reduced, Solution};
use super::polynomial_gcd;
use super::rational::Q;
use super::symbol::Symbol;
use std::cmp::Ordering;

pub use super::linear_solve::SolveError;

/// What the problem knows that the algebra does not.
pub struct SolveContext<'a> {
    /// The sign of an expression in the givens: proved from the domains, or from the givens'
    /// values; None when it cannot be told.
    pub sign: &'a dyn Fn(&Expr) -> Option<Ordering>,
    /// Whether an unknown must be positive (a mass, a length, ...): a root proved negative or
    /// zero is dropped.
    pub positive: &'a dyn Fn(Symbol) -> bool,
}

impl SolveContext<'_> {
    /// The sign of `e`: a number's own, else what [`SolveContext::sign`] tells.
    fn sign_of(&self, e: &Expr) -> Option<Ordering> {
        match e.as_num() {
            Some(q) => Some(q.cmp(&Q::ZERO)),
            None => (self.sign)(e),
        }
    }
}

/// A root that was found and ruled out, with the reason in words (e.g. "complex: the
/// discriminant ... is negative", "negative, but m_1 is a mass", "makes the denominator ...
/// zero").
#[derive(Debug, Clone, PartialEq)]
pub struct DroppedRoot {
    pub unknown: Symbol,
    pub value: Expr,
    pub reason: String,
    /// The reason as a page shows it.
    pub condition: Condition,
}

/// Why a root is dropped, for a page: `words` (a title: words, mathematics in `$…$`) about
/// the relation `lhs = rhs` (the discriminant and its value, the value that must be
/// positive, the divisor that vanishes).
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    pub words: String,
    pub lhs: Expr,
    pub rhs: Expr,
}

/// The real solutions of a system, the roots ruled out, and the unknowns left free.
#[derive(Debug, Clone, PartialEq)]
pub struct Solutions {
    /// Each real solution: every solved unknown's value. One branch when the system is linear.
    pub branches: Vec<Vec<(Symbol, Expr)>>,
    pub dropped: Vec<DroppedRoot>,
    /// Unknowns the equations leave free (as linear_solve's Solution::free).
    pub free: Vec<Symbol>,
    /// The univariate polynomial that was solved, when there was one: (unknown, polynomial as
    /// an Expr equal to 0), for the worked solution to show.
    pub polynomial: Option<(Symbol, Expr)>,
    /// Unknowns eliminated to reach that polynomial, in order, each's value in the unknowns
    /// left (`psidot = w cos γ − phidot cos θ`), for the worked solution to show.
    pub eliminated: Vec<(Symbol, Expr)>,
}

/// Solves `equations[i] = 0` for `unknowns` (see the module documentation).
pub fn solve_system(
    equations: &[Expr],
    unknowns: &[Symbol],
    context: &SolveContext,
) -> Result<Solutions, SolveError> {
    let first_nonlinear = match solve_linear(equations, unknowns) {
        Ok(Solution { values, free }) => {
            return Ok(Solutions {
                branches: vec![values],
                dropped: Vec::new(),
                free,
                polynomial: None,
                eliminated: Vec::new(),
            })
        }
        Err(SolveError::Nonlinear { term, .. }) => term,
        Err(e) => return Err(e),
    };
    for &u in unknowns {
        if !equations.iter().any(|e| e.contains(u)) {
            continue;
        }
        let others: Vec<Symbol> = unknowns.iter().copied().filter(|&s| s != u).collect();
        match eliminate(equations, &others) {
            Ok(reduced) => {
                return Parametric {
                    u,
                    unknowns,
                    others: &others,
                    reduced,
                    context,
                }
                .solve()
            }
            Err(SolveError::Nonlinear { .. }) => continue,
            Err(e) => return Err(e),
        }
    }
    Err(SolveError::NoSinglePolynomial {
        term: first_nonlinear,
    })
}

/// Every solved unknown's value in one solution.
type Branch = Vec<(Symbol, Expr)>;

/// The system eliminated in all unknowns but `u`, which its coefficients may hold.
struct Parametric<'a> {
    u: Symbol,
    unknowns: &'a [Symbol],
    others: &'a [Symbol],
    reduced: Reduced,
    context: &'a SolveContext<'a>,
}

impl Parametric<'_> {
    fn solve(&self) -> Result<Solutions, SolveError> {
        let Solution { values, mut free } = self.reduced.solution(self.others)?;
        let Some(polynomial) = self.polynomial()? else {
            // Nothing fixes u: it is free, and so is every unknown whose value holds it.
            let (fixed, with_u): (Vec<_>, Vec<_>) =
                values.into_iter().partition(|(_, v)| !v.contains(self.u));
            free.push(self.u);
            free.extend(with_u.into_iter().map(|(s, _)| s));
            return Ok(Solutions {
                branches: vec![fixed],
                dropped: Vec::new(),
                free: self.in_given_order(free),
                polynomial: None,
                eliminated: Vec::new(),
            });
        };
        let found = roots::real_roots(&polynomial, self.u, self.context)?;
        let mut dropped = found.dropped;
        let mut branches: Vec<(Expr, Branch)> = Vec::new();
        for root in found.real {
            match self.branch(&root, &values)? {
                Ok(branch) => branches.push((root, branch)),
                Err((reason, condition)) => dropped.push(DroppedRoot {
                    unknown: self.u,
                    value: root,
                    reason,
                    condition,
                }),
            }
        }
        let branches = self.ascending(branches)?;
        Ok(Solutions {
            branches,
            dropped,
            free: self.in_given_order(free),
            polynomial: Some((self.u, polynomial.expr(self.u))),
            eliminated: Vec::new(),
        })
    }

    /// The polynomial the conditions left by the elimination reduce to, or none when they
    /// leave none (then `u` is free).
    fn polynomial(&self) -> Result<Option<roots::Polynomial>, SolveError> {
        let mut common: Option<(usize, Expr)> = None;
        for (equation, residual) in self.reduced.residuals() {
            let (numerator, _) = residual.cancelled_parts()?;
            let numerator = match common {
                None => numerator,
                Some((_, previous)) => polynomial_gcd(&previous, &numerator)?,
            };
            if !numerator.contains(self.u) {
                return Err(SolveError::Inconsistent {
                    equation,
                    residual: residual.to_string(),
                });
            }
            common = Some((equation, numerator));
        }
        let Some((equation, numerator)) = common else {
            return Ok(None);
        };
        roots::Polynomial::of(&numerator, equation, self.u, self.unknowns, self.context).map(Some)
    }

    /// The values of all unknowns at `u = root`, or why the root is ruled out.
    fn branch(
        &self,
        root: &Expr,
        values: &[(Symbol, Expr)],
    ) -> Result<Result<Branch, (String, Condition)>, AlgebraError> {
        let others: Vec<&Expr> = values
            .iter()
            .map(|(_, v)| v)
            .chain(self.reduced.pivot_coefficients())
            .collect();
        let surd = surd::QuadraticSurd::of(root, &others);
        let at_root = |e: &Expr| -> Result<Expr, AlgebraError> {
            match &surd {
                Some(surd) => surd.value_at(e, self.u, root),
                None => exact(&e.subs(&|s| (s == self.u).then(|| root.clone()))?),
            }
        };
        let vanishes_at_root = |e: &Expr| -> Result<bool, AlgebraError> {
            let value = at_root(e)?;
            Ok(value.is_zero() || self.context.sign_of(&value) == Some(Ordering::Equal))
        };
        for pivot in self.reduced.pivot_coefficients() {
            if pivot.contains(self.u) && vanishes_at_root(pivot)? {
                return Ok(Err((
                    format!("makes the coefficient {pivot} that the elimination divides by zero"),
                    Condition {
                        words: "it makes a coefficient the elimination divides by zero".into(),
                        lhs: pivot.clone(),
                        rhs: Expr::zero(),
                    },
                )));
            }
        }
        let mut branch = Vec::with_capacity(values.len() + 1);
        for &s in self.unknowns {
            let value = if s == self.u {
                root.clone()
            } else if let Some((_, v)) = values.iter().find(|(t, _)| *t == s) {
                let (_, denominator) = v.cancelled_parts()?;
                if denominator.contains(self.u) && vanishes_at_root(&denominator)? {
                    return Ok(Err((
                        format!("makes the denominator {denominator} zero"),
                        Condition {
                            words: "it makes a denominator zero".into(),
                            lhs: denominator,
                            rhs: Expr::zero(),
                        },
                    )));
                }
                at_root(v)?
            } else {
                continue;
            };
            if (self.context.positive)(s) {
                let named = if s == self.u {
                    String::new()
                } else {
                    format!("gives {} = {value}, ", s.name())
                };
                let sign = match self.context.sign_of(&value) {
                    Some(Ordering::Less) => "negative",
                    Some(Ordering::Equal) => "zero",
                    _ => "",
                };
                if !sign.is_empty() {
                    return Ok(Err((
                        format!("{named}{sign}, but {} must be positive", s.name()),
                        Condition {
                            words: format!("${}$ would be {sign}; it must be positive", s.latex()),
                            lhs: Expr::sym(s),
                            rhs: value,
                        },
                    )));
                }
            }
            branch.push((s, value));
        }
        Ok(Ok(branch))
    }

    /// The branches in ascending order of their roots when every pair can be ordered by the
    /// sign of its difference, else as found.
    fn ascending(&self, branches: Vec<(Expr, Branch)>) -> Result<Vec<Branch>, AlgebraError> {
        let mut order = Vec::new();
        for i in 0..branches.len() {
            for j in i + 1..branches.len() {
                // The roots' difference as it is, and in lowest terms only when its sign is
                // not told so (the exact form can show a zero that rounding hides).
                let difference = &branches[j].0 - &branches[i].0;
                let sign = match self.context.sign_of(&difference) {
                    Some(o) if o != Ordering::Equal => Some(o),
                    _ => self.context.sign_of(&exact(&difference)?),
                };
                match sign {
                    Some(o) if o != Ordering::Equal => order.push(((i, j), o)),
                    _ => return Ok(branches.into_iter().map(|(_, b)| b).collect()),
                }
            }
        }
        // Each root's rank: how many roots are below it.
        let rank = |k: usize| {
            order
                .iter()
                .filter(|&&((i, j), o)| {
                    (j == k && o == Ordering::Greater) || (i == k && o == Ordering::Less)
                })
                .count()
        };
        let mut ranked: Vec<(usize, Branch)> = (0..branches.len())
            .map(rank)
            .zip(branches.into_iter().map(|(_, b)| b))
            .collect();
        ranked.sort_by_key(|(r, _)| *r);
        Ok(ranked.into_iter().map(|(_, b)| b).collect())
    }

    /// `symbols` in the order of the unknowns.
    fn in_given_order(&self, symbols: Vec<Symbol>) -> Vec<Symbol> {
        self.unknowns
            .iter()
            .copied()
            .filter(|s| symbols.contains(s))
            .collect()
    }
}

/// `e` expanded and in lowest terms: the form in which a root put back is compared with
/// zero (a square root squared is its radicand once expanded).
fn exact(e: &Expr) -> Result<Expr, AlgebraError> {
    e.expand()?.cancel()
}
