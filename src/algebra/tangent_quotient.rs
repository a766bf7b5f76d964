//! `tan x = sin x / cos x`: an expression with every tangent written as the quotient, so
//! that the identities of sines and cosines (`sin² + cos² = 1`, the double angles) reach it.

use super::error::AlgebraError;
use super::expr::{Expr, View};
use super::function::Func;

impl Expr {
    /// This expression with each `tan(x)` replaced by `sin(x) / cos(x)` (arguments first).
    /// Fails only where a cosine is zero exactly (`tan(π/2)` kept as written).
    ///
    /// ```
    /// use kinetics::parse_expression;
    /// let e = parse_expression("", "tan(t)^2 + 1").unwrap();
    /// let q = parse_expression("", "sin(t)^2/cos(t)^2 + 1").unwrap();
    /// assert_eq!(e.tangents_as_quotients().unwrap(), q);
    /// ```
    pub fn tangents_as_quotients(&self) -> Result<Expr, AlgebraError> {
        Ok(match self.view() {
            View::Num(_) | View::Sym(_) => self.clone(),
            View::Add(terms) => Expr::add_all(
                terms
                    .iter()
                    .map(Expr::tangents_as_quotients)
                    .collect::<Result<Vec<_>, _>>()?,
            ),
            View::Mul(factors) => Expr::mul_all(
                factors
                    .iter()
                    .map(Expr::tangents_as_quotients)
                    .collect::<Result<Vec<_>, _>>()?,
            ),
            View::Pow(b, e) => b.tangents_as_quotients()?.checked_pow(e)?,
            View::Func(Func::Tan, a) => {
                let a = a.tangents_as_quotients()?;
                let cosine = Func::Cos.apply(a.clone());
                &Func::Sin.apply(a) * &cosine.checked_pow(&Expr::int(-1))?
            }
            View::Func(f, a) => Expr::func(f, a.tangents_as_quotients()?),
        })
    }
}
