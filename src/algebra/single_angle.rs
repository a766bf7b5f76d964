//! An expression in single angles: every tangent as the quotient and every double angle
//! multiplied out,
//!
//! ```text
//! tan x = sin x / cos x,    sin 2x = 2 sin x cos x,    cos 2x = cos²x − sin²x
//! ```
//!
//! so that two forms of one value written with different angles (`½ sin 2θ` and
//! `sin θ cos θ`, `tan β` and `sin β / cos β`) meet as the same terms: the checker's exact
//! route multiplies them out, and its diagnosis compares them term by term.

use super::error::AlgebraError;
use super::expr::{Expr, View};
use super::function::Func;
use super::rational::Q;

impl Expr {
    /// This expression with each `tan x` replaced by `sin x / cos x` and each `sin 2x`,
    /// `cos 2x` by its single-angle form (arguments first). Fails only where a cosine is
    /// zero exactly (`tan(π/2)` kept as written).
    ///
    /// ```
    /// use kinetics::parse_expression;
    /// let e = parse_expression("", "tan(t)^2 + sin(2 t)").unwrap();
    /// let single = parse_expression("", "sin(t)^2/cos(t)^2 + 2 sin(t) cos(t)").unwrap();
    /// assert_eq!(e.in_single_angles().unwrap(), single);
    /// ```
    pub fn in_single_angles(&self) -> Result<Expr, AlgebraError> {
        single_angles(self, Tangents::AsQuotients)
    }

    /// This expression with each `sin 2x`, `cos 2x` in its single-angle form, tangents kept
    /// as written (the diagnosis lists a term as the student wrote it: `L tan θ`).
    pub fn double_angles_multiplied_out(&self) -> Result<Expr, AlgebraError> {
        single_angles(self, Tangents::Kept)
    }
}

/// Whether a tangent is written as the quotient.
#[derive(Clone, Copy, PartialEq)]
enum Tangents {
    AsQuotients,
    Kept,
}

fn single_angles(e: &Expr, tangents: Tangents) -> Result<Expr, AlgebraError> {
    let each = |e: &Expr| single_angles(e, tangents);
    Ok(match e.view() {
        View::Num(_) | View::Sym(_) => e.clone(),
        View::Add(terms) => Expr::add_all(terms.iter().map(each).collect::<Result<Vec<_>, _>>()?),
        View::Mul(factors) => {
            Expr::mul_all(factors.iter().map(each).collect::<Result<Vec<_>, _>>()?)
        }
        View::Pow(b, exponent) => each(b)?.checked_pow(exponent)?,
        View::Func(Func::Tan, a) if tangents == Tangents::Kept => Func::Tan.apply(each(a)?),
        View::Func(f, a) => single_angle(f, each(a)?)?,
    })
}

/// `f(a)` in single angles, `a` already so.
fn single_angle(f: Func, a: Expr) -> Result<Expr, AlgebraError> {
    let half = half_of_double(&a);
    Ok(match (f, half) {
        (Func::Tan, _) => {
            let cosine = single_angle(Func::Cos, a.clone())?;
            &single_angle(Func::Sin, a)? * &cosine.checked_pow(&Expr::int(-1))?
        }
        (Func::Sin, Some(x)) => Expr::int(2) * Func::Sin.apply(x.clone()) * Func::Cos.apply(x),
        (Func::Cos, Some(x)) => Func::Cos.apply(x.clone()).powi(2) - Func::Sin.apply(x).powi(2),
        _ => f.apply(a),
    })
}

/// `x` when `a` is `2x` (a product of symbols whose numeric coefficient is 2; `sin 2` is
/// left as a number).
fn half_of_double(a: &Expr) -> Option<Expr> {
    let double = a.as_num().is_none() && a.coefficient() == &Q::from(2);
    double.then(|| a / &Expr::int(2))
}
