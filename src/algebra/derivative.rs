//! Derivatives: `d/dt` through time-dependent symbols (`w_x` → `wdot_x`, chain rule through
//! the functions) and the partial derivative with respect to one symbol.
//!
//! Both use the same rules: `(u + v)' = u' + v'`, `(u v)' = u' v + u v'`,
//! `(u^c)' = c u^(c-1) u'` for a constant exponent `c`, `f(u)' = f'(u) u'`.

use super::error::AlgebraError;
use super::expr::{Expr, View};
use super::symbol::Symbol;

impl Expr {
    /// The time derivative. Symbols that depend on time (kinematic ones, see
    /// [`Symbol::is_time_dependent`]) become their dotted forms; all others are constant.
    ///
    /// ```
    /// use kinetics::algebra::Expr;
    /// let h = Expr::symbol("I_x") * Expr::symbol("w_x");
    /// assert_eq!(h.d_dt().unwrap(), Expr::symbol("I_x") * Expr::symbol("wdot_x"));
    /// ```
    pub fn d_dt(&self) -> Result<Expr, AlgebraError> {
        differentiate(self, &|s: Symbol| {
            if s.is_time_dependent() {
                Expr::sym(s.dot())
            } else {
                Expr::zero()
            }
        })
    }

    /// The partial derivative with respect to `x`.
    pub fn diff(&self, x: Symbol) -> Result<Expr, AlgebraError> {
        differentiate(self, &|s: Symbol| {
            if s == x {
                Expr::one()
            } else {
                Expr::zero()
            }
        })
    }
}

fn differentiate(e: &Expr, atom: &dyn Fn(Symbol) -> Expr) -> Result<Expr, AlgebraError> {
    Ok(match e.view() {
        View::Num(_) => Expr::zero(),
        View::Sym(s) => atom(s),
        View::Add(terms) => Expr::add_all(
            terms
                .iter()
                .map(|t| differentiate(t, atom))
                .collect::<Result<Vec<_>, _>>()?,
        ),
        View::Mul(factors) => {
            let mut terms = Vec::with_capacity(factors.len());
            for (i, f) in factors.iter().enumerate() {
                let df = differentiate(f, atom)?;
                if df.is_zero() {
                    continue;
                }
                let others = factors
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| j != i)
                    .map(|(_, g)| g.clone());
                terms.push(Expr::mul_all(std::iter::once(df).chain(others)));
            }
            Expr::add_all(terms)
        }
        View::Pow(base, exponent) => {
            if !differentiate(exponent, atom)?.is_zero() {
                return Err(AlgebraError::TimeDependentExponent(e.to_string()));
            }
            let db = differentiate(base, atom)?;
            if db.is_zero() {
                return Ok(Expr::zero());
            }
            let lowered = base.checked_pow(&(exponent - &Expr::one()))?;
            Expr::mul_all([exponent.clone(), lowered, db])
        }
        View::Func(f, arg) => {
            let da = differentiate(arg, atom)?;
            if da.is_zero() {
                return Ok(Expr::zero());
            }
            &f.derivative_at(arg)? * &da
        }
    })
}
