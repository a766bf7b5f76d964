//! Arithmetic at a root `u = A + B√X` of a quadratic: an expression in `u` put in as
//! `(p + q√X)/r` in lowest terms, with `p`, `q`, `r` free of `√X`.
//!
//! `√X` is written as a placeholder symbol `s`; the expression at the root is a fraction
//! `N(s)/D(s)` in lowest terms, and each part is reduced by `s² = X` to `n₀ + n₁s` and
//! `d₀ + d₁s`. The denominator is made free of the root by its conjugate:
//! `(n₀ + n₁s)/(d₀ + d₁s) = ((n₀d₀ − n₁d₁X) + (n₁d₀ − n₀d₁)s)/(d₀² − d₁²X)`, so `2/(3 + √5)`
//! is `(3 − √5)/2` and the value is zero exactly when its numerator is.

use crate::algebra::error::AlgebraError;
use crate::algebra::expr::{Expr, View};
use crate::algebra::rational::Q;
use crate::algebra::symbol::Symbol;

/// The one square root `√X` a root holds.
pub(super) struct QuadraticSurd {
    radicand: Expr,
    placeholder: Symbol,
}

impl QuadraticSurd {
    /// The square root in `root`, when it holds exactly one radicand under powers `X^(n/2)`
    /// and no other power with a fractional exponent; none otherwise (a cube root, nested
    /// roots, a rational root). The placeholder is a name none of `root` and `others` holds.
    pub(super) fn of(root: &Expr, others: &[&Expr]) -> Option<QuadraticSurd> {
        let mut radicands = Vec::new();
        if !fractional_powers(root, &mut radicands) {
            return None;
        }
        let [radicand] = radicands.as_slice() else {
            return None;
        };
        let mut name = String::from("radical");
        let taken = |s: Symbol| root.contains(s) || others.iter().any(|e| e.contains(s));
        while taken(Symbol::new(&name)) {
            name.push('\'');
        }
        Some(QuadraticSurd {
            radicand: radicand.clone(),
            placeholder: Symbol::new(&name),
        })
    }

    /// `e` at `u = root` (module documentation); `e` holds no placeholder (see [`Self::of`]).
    pub(super) fn value_at(&self, e: &Expr, u: Symbol, root: &Expr) -> Result<Expr, AlgebraError> {
        let root = self.with_placeholder(root)?;
        let (n, d) = e
            .subs(&|s| (s == u).then(|| root.clone()))?
            .cancelled_parts()?;
        let ((n0, n1), (d0, d1)) = (self.reduced(&n)?, self.reduced(&d)?);
        let s = Expr::sym(self.placeholder);
        let norm = (&(&d0 * &d0) - &(&(&d1 * &d1) * &self.radicand)).expand()?;
        let (numerator, denominator) = if d1.is_zero() || norm.is_zero() {
            (&n0 + &(&n1 * &s), &d0 + &(&d1 * &s))
        } else {
            let rational = &(&n0 * &d0) - &(&(&n1 * &d1) * &self.radicand);
            let radical = &(&n1 * &d0) - &(&n0 * &d1);
            (&rational + &(&radical * &s), norm)
        };
        self.without_placeholder(&numerator.checked_div(&denominator)?.cancel()?)
    }

    /// `p(s)` (a polynomial) as `(p₀, p₁)` with `p = p₀ + p₁s` once `s² = X`.
    fn reduced(&self, p: &Expr) -> Result<(Expr, Expr), AlgebraError> {
        let (mut even, mut odd) = (Vec::new(), Vec::new());
        for group in p.collect(&[self.placeholder])? {
            let k = if group.monomial.is_one() {
                0
            } else {
                let exponent = group.monomial.base_and_exponent().1;
                exponent.as_num().and_then(Q::to_i64).unwrap_or(1)
            };
            let term = &group.coefficient * &self.radicand.powi(k.div_euclid(2));
            if k.rem_euclid(2) == 0 {
                even.push(term);
            } else {
                odd.push(term);
            }
        }
        Ok((Expr::add_all(even).expand()?, Expr::add_all(odd).expand()?))
    }

    /// `e` with each `X^(n/2)` written `sⁿ`.
    fn with_placeholder(&self, e: &Expr) -> Result<Expr, AlgebraError> {
        let each = |operands: &[Expr]| -> Result<Vec<Expr>, AlgebraError> {
            operands.iter().map(|o| self.with_placeholder(o)).collect()
        };
        Ok(match e.view() {
            View::Num(_) | View::Sym(_) => e.clone(),
            View::Add(terms) => Expr::add_all(each(terms)?),
            View::Mul(factors) => Expr::mul_all(each(factors)?),
            View::Func(f, argument) => Expr::func(f, self.with_placeholder(argument)?),
            View::Pow(base, exponent) => match half_integer(exponent) {
                Some(n) if *base == self.radicand => Expr::sym(self.placeholder).powi(n),
                _ => self
                    .with_placeholder(base)?
                    .checked_pow(&self.with_placeholder(exponent)?)?,
            },
        })
    }

    /// `e` with `s` back as `√X`.
    fn without_placeholder(&self, e: &Expr) -> Result<Expr, AlgebraError> {
        let radical = self.radicand.checked_pow(&Expr::rational(1, 2))?;
        e.subs(&|s| (s == self.placeholder).then(|| radical.clone()))
    }
}

/// `n` for an exponent `n/2` with `n` odd.
fn half_integer(exponent: &Expr) -> Option<i64> {
    let q = exponent.as_num()?;
    (q.denom() == Q::int(2)).then(|| (q * &Q::int(2)).to_i64())?
}

/// Gathers the bases of powers `X^(n/2)` into `radicands` (each once); false when a power
/// with another fractional exponent, or a square root inside a radicand, is found.
fn fractional_powers(e: &Expr, radicands: &mut Vec<Expr>) -> bool {
    match e.view() {
        View::Num(_) | View::Sym(_) => true,
        View::Add(operands) | View::Mul(operands) => {
            operands.iter().all(|o| fractional_powers(o, radicands))
        }
        View::Func(_, argument) => fractional_powers(argument, radicands),
        View::Pow(base, exponent) => {
            let mut inner = Vec::new();
            let plain = fractional_powers(base, &mut inner) && inner.is_empty();
            match exponent.as_num() {
                Some(q) if q.is_integer() => fractional_powers(base, radicands),
                Some(_) if half_integer(exponent).is_some() && plain => {
                    if !radicands.contains(base) {
                        radicands.push(base.clone());
                    }
                    true
                }
                _ => false,
            }
        }
    }
}
