//! The reading `sin-for-cos`: `sin θ` written where `cos θ` belongs, or back. With `C` and
//! `K` the sums of the differing claimed and correct terms, `C` with `sin` and `cos`
//! exchanged everywhere is `K` (and `C` holds at least one of them).

use super::comparison::Differences;
use super::words::term;
use crate::algebra::{AlgebraError, Expr, Func, View};

/// `sin-for-cos` (module documentation).
pub(super) fn sin_for_cos(d: &Differences) -> Option<String> {
    let (claimed, correct) = d.sides()?;
    if !has_sin_or_cos(claimed) || exchanged(claimed).ok().as_ref() != Some(correct) {
        return None;
    }
    Some(format!(
        "sin and cos are exchanged: {} is written where the correct form has {}",
        term(claimed),
        term(correct)
    ))
}

/// `e` with every `sin` a `cos` and every `cos` a `sin`.
fn exchanged(e: &Expr) -> Result<Expr, AlgebraError> {
    Ok(match e.view() {
        View::Num(_) | View::Sym(_) => e.clone(),
        View::Add(terms) => {
            Expr::add_all(terms.iter().map(exchanged).collect::<Result<Vec<_>, _>>()?)
        }
        View::Mul(factors) => Expr::mul_all(
            factors
                .iter()
                .map(exchanged)
                .collect::<Result<Vec<_>, _>>()?,
        ),
        View::Pow(base, exponent) => exchanged(base)?.checked_pow(&exchanged(exponent)?)?,
        View::Func(f, arg) => {
            let f = match f {
                Func::Sin => Func::Cos,
                Func::Cos => Func::Sin,
                other => other,
            };
            f.checked_apply(exchanged(arg)?)?
        }
    })
}

fn has_sin_or_cos(e: &Expr) -> bool {
    match e.view() {
        View::Num(_) | View::Sym(_) => false,
        View::Add(xs) | View::Mul(xs) => xs.iter().any(has_sin_or_cos),
        View::Pow(base, exponent) => has_sin_or_cos(base) || has_sin_or_cos(exponent),
        View::Func(Func::Sin | Func::Cos, _) => true,
        View::Func(_, arg) => has_sin_or_cos(arg),
    }
}
