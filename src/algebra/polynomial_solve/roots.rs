//! The real roots of a polynomial `p(u) = Σ aₖ uᵏ` of degree up to four, exactly. Once the
//! power `uᵐ` (the root `0`) is pulled out: its square-free part `p/gcd(p, p′)` (each root once), numeric coefficients' rational roots
//! first (`rational_roots.rs`), then what is left, numbers or symbols, by its degree:
//! `u = −a₀/a₁`, the quadratic formula `u = (−a₁ ± √(a₁² − 4a₂a₀))/(2a₂)`, a biquadratic
//! `a₄u⁴ + a₂u² + a₀` by the quadratic formula in `u²` (`quadratic.rs`), a cubic by
//! Cardano's formula or its trigonometric form (`cardano.rs`), a quartic by Ferrari's method
//! (`ferrari.rs`). Where the number of real roots depends on a sign the context cannot tell
//! (symbols without values), the roots are refused ([`SolveError::RootsNotExact`]).

use super::cardano::cubic;
use super::ferrari::quartic;
use super::quadratic::{biquadratic, quadratic};
use super::rational_roots::rational_roots;
use super::square_free::{square_free, square_free_numeric};
use super::{DroppedRoot, SolveContext, SolveError};
use crate::algebra::expr::Expr;
use crate::algebra::polynomial_gcd;
use crate::algebra::rational::Q;
use crate::algebra::symbol::Symbol;
use std::cmp::Ordering;

/// `uᵐ · Σ aₖ uᵏ` with `a₀ ≠ 0` and a degree up to four.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Polynomial {
    /// `m`: the multiplicity of the root `0`.
    zero_root: u32,
    /// `a₀ … a_d`, free of the unknowns, `a₀` and `a_d` not zero.
    coefficients: Vec<Expr>,
}

/// Real roots, each once, and the roots ruled out.
#[derive(Debug, Default)]
pub(super) struct Found {
    pub real: Vec<Expr>,
    pub dropped: Vec<DroppedRoot>,
}

impl Found {
    pub(super) fn extend(&mut self, other: Found) {
        for r in other.real {
            if !self.real.contains(&r) {
                self.real.push(r);
            }
        }
        self.dropped.extend(other.dropped);
    }
}

impl Polynomial {
    /// The polynomial in `u` of `numerator` (expanded, no denominator), its common factor in
    /// the givens divided out when its sign is known, the leading coefficient made positive
    /// when its sign is known, a coefficient the givens' values make zero left out (an
    /// equation `0 = a₀` that is left is a contradiction of `equation`). Refused when `u` enters other than in whole powers, or another
    /// unknown enters, or the degree (past the root 0) is above four.
    pub(super) fn of(
        numerator: &Expr,
        equation: usize,
        u: Symbol,
        unknowns: &[Symbol],
        context: &SolveContext,
    ) -> Result<Polynomial, SolveError> {
        let mut powers: Vec<(u32, Expr)> = Vec::new();
        for group in numerator.collect(&[u])? {
            let power = if group.monomial.is_one() {
                Some(0)
            } else {
                let (base, exponent) = group.monomial.base_and_exponent();
                exponent
                    .as_num()
                    .and_then(Q::to_i64)
                    .and_then(|k| u32::try_from(k).ok())
                    .filter(|_| base.as_symbol() == Some(u))
            };
            let term = || (&group.coefficient * &group.monomial).to_string();
            let Some(power) = power else {
                return Err(SolveError::NotPolynomial {
                    unknown: u,
                    term: term(),
                });
            };
            if let Some(&w) = unknowns.iter().find(|&&w| group.coefficient.contains(w)) {
                return Err(SolveError::NotPolynomial {
                    unknown: w,
                    term: term(),
                });
            }
            powers.push((power, group.coefficient));
        }
        // A coefficient the givens' values make zero is no term of this problem's polynomial
        // (cos θ at θ = 90°): the leading one would be divided by, the lowest is a root 0.
        let vanishes = |a: &Expr| context.sign_of(a) == Some(Ordering::Equal);
        let lowest_kept = |powers: &[(u32, Expr)]| powers.iter().map(|(k, _)| *k).min();
        while powers.len() > 1 {
            let highest = powers.iter().map(|(k, _)| *k).max();
            let lowest = lowest_kept(&powers);
            match powers
                .iter()
                .position(|(k, a)| Some(*k) == highest && vanishes(a))
            {
                Some(at) => powers.remove(at),
                None => match powers
                    .iter()
                    .position(|(k, a)| Some(*k) == lowest && vanishes(a))
                {
                    Some(at) => powers.remove(at),
                    None => break,
                },
            };
        }
        if !powers.iter().any(|(k, _)| *k > 0) {
            return Err(SolveError::Inconsistent {
                equation,
                residual: numerator.to_string(),
            });
        }
        let lowest = lowest_kept(&powers).unwrap_or(0);
        let degree = powers.iter().map(|(k, _)| *k).max().unwrap_or(0) - lowest;
        if degree > 4 {
            return Err(SolveError::DegreeTooHigh { unknown: u, degree });
        }
        let mut coefficients = vec![Expr::zero(); degree as usize + 1];
        for (k, a) in powers {
            coefficients[(k - lowest) as usize] = a;
        }
        let mut divisor = Expr::zero();
        for a in &coefficients {
            divisor = polynomial_gcd(&divisor, a)?;
        }
        let leading_sign = context.sign_of(&coefficients[degree as usize]);
        if leading_sign == Some(Ordering::Less) {
            divisor = -divisor;
        }
        let known =
            |e: &Expr| matches!(context.sign_of(e), Some(Ordering::Less | Ordering::Greater));
        if divisor.as_num().is_some_and(|q| !q.is_zero()) || known(&divisor) {
            for a in coefficients.iter_mut() {
                *a = a.checked_div(&divisor)?.cancel()?;
            }
        }
        Ok(Polynomial {
            zero_root: lowest,
            coefficients,
        })
    }

    /// `uᵐ Σ aₖ uᵏ` as an expression (equal to zero).
    pub(super) fn expr(&self, u: Symbol) -> Expr {
        let u = Expr::sym(u);
        let sum = Expr::add_all(
            self.coefficients
                .iter()
                .enumerate()
                .map(|(k, a)| a * &u.powi(k as i64)),
        );
        &u.powi(i64::from(self.zero_root)) * &sum
    }
}

/// The real roots of `p` in `u` (module documentation), each once, and those ruled out as
/// complex.
pub(super) fn real_roots(
    p: &Polynomial,
    u: Symbol,
    context: &SolveContext,
) -> Result<Found, SolveError> {
    let mut found = Found::default();
    if p.zero_root > 0 {
        found.real.push(Expr::zero());
    }
    found.extend(distinct_real_roots(&p.coefficients, u, context)?);
    Ok(found)
}

/// The real roots of `Σ aₖ uᵏ` (`a₀ ≠ 0`, lowest power first, degree up to four) of its
/// square-free part, by the module documentation.
pub(super) fn distinct_real_roots(
    coefficients: &[Expr],
    u: Symbol,
    context: &SolveContext,
) -> Result<Found, SolveError> {
    let mut found = Found::default();
    let numbers: Option<Vec<Q>> = coefficients.iter().map(|a| a.as_num().cloned()).collect();
    let a = match numbers {
        Some(numbers) => {
            let (rational, rest) = rational_roots(&numbers);
            found.real.extend(rational.into_iter().map(Expr::num));
            square_free_numeric(&rest)
                .into_iter()
                .map(Expr::num)
                .collect()
        }
        None => square_free(coefficients, u)?,
    };
    let rest = match a.as_slice() {
        [] | [_] => Found::default(),
        [a0, a1] => Found {
            real: vec![(-a0).checked_div(a1)?.cancel()?],
            dropped: Vec::new(),
        },
        [c, b, a] => quadratic(a, b, c, u, context)?,
        [c, odd1, b, odd3, a] if odd1.is_zero() && odd3.is_zero() => {
            biquadratic(a, b, c, u, context)?
        }
        [d, c, b, a] => cubic(&[d.clone(), c.clone(), b.clone(), a.clone()], u, context)?,
        [e, d, c, b, a] => quartic(
            &[e.clone(), d.clone(), c.clone(), b.clone(), a.clone()],
            u,
            context,
        )?,
        _ => {
            return Err(SolveError::DegreeTooHigh {
                unknown: u,
                degree: a.len() as u32 - 1,
            })
        }
    };
    found.extend(rest);
    Ok(found)
}
