//! The elementary functions an expression may hold: `sin`, `cos`, `tan`, `abs`.
//! (`sqrt(x)` is the power `x^(1/2)`.)
//!
//! Construction applies the parity rules `sin(-x) = -sin x`, `cos(-x) = cos x`,
//! `tan(-x) = -tan x`, `|-x| = |x|`, `||x|| = |x|`, the values at zero and the exact values
//! at the multiples of 15° (`sin(π/6) = 1/2`, `cos(13π/6) = cos(π/6) = √3/2`; see
//! `exact_angle.rs`). `tan` at an odd multiple of π/2 is undefined: [`Func::checked_apply`]
//! refuses it, [`Func::apply`] leaves it as `tan(π/2)`.

use super::error::AlgebraError;
use super::exact_angle::{at_multiple_of_pi, ExactValue};
use super::expr::{Expr, View};

/// An elementary function of one argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Func {
    Sin,
    Cos,
    Tan,
    Abs,
}

impl Func {
    /// The function of this ASCII name (`sin`, `cos`, `tan`, `abs`).
    pub fn from_name(name: &str) -> Option<Func> {
        Some(match name {
            "sin" => Func::Sin,
            "cos" => Func::Cos,
            "tan" => Func::Tan,
            "abs" => Func::Abs,
            _ => return None,
        })
    }

    pub fn name(self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Abs => "abs",
        }
    }

    /// `f(arg)` in canonical form, or an error when `f` is undefined there (`tan(π/2)`).
    pub fn checked_apply(self, arg: Expr) -> Result<Expr, AlgebraError> {
        let value = self.apply(arg);
        match value.view() {
            View::Func(Func::Tan, a) if a.as_multiple_of_pi().is_some() => {
                Err(AlgebraError::Undefined(format!("tan({a})")))
            }
            _ => Ok(value),
        }
    }

    /// `f(arg)` in canonical form (`tan` at an odd multiple of π/2 as `tan(π/2)`).
    pub fn apply(self, arg: Expr) -> Expr {
        if let Some(q) = arg.as_multiple_of_pi() {
            match at_multiple_of_pi(self, q) {
                Some(ExactValue::Value(value)) => return value,
                Some(ExactValue::Pole) => {
                    return Expr::func_node(Func::Tan, Expr::pi() / Expr::int(2))
                }
                None => {}
            }
        }
        if let Some(q) = arg.as_num() {
            match self {
                Func::Abs => return Expr::num(q.abs()),
                Func::Sin | Func::Tan if q.is_zero() => return Expr::zero(),
                Func::Cos if q.is_zero() => return Expr::one(),
                _ => {}
            }
        }
        if let View::Func(Func::Abs, _) = arg.view() {
            if self == Func::Abs {
                return arg;
            }
        }
        let (coeff, _) = arg.coeff_and_factors();
        if coeff.is_negative() && !matches!(arg.view(), View::Add(_)) {
            // The positive argument goes through the rules again: `|-|x|| = ||x|| = |x|`.
            let positive = -arg;
            return match self {
                Func::Sin | Func::Tan => -self.apply(positive),
                Func::Cos | Func::Abs => self.apply(positive),
            };
        }
        Expr::func_node(self, arg)
    }

    /// `f'(u)`, the derivative with respect to the argument, evaluated at `u`.
    pub fn derivative_at(self, u: &Expr) -> Expr {
        match self {
            Func::Sin => Func::Cos.apply(u.clone()),
            Func::Cos => -Func::Sin.apply(u.clone()),
            Func::Tan => Expr::one() + Func::Tan.apply(u.clone()).powi(2),
            Func::Abs => u * &Func::Abs.apply(u.clone()).powi(-1),
        }
    }

    /// The function on a floating-point scalar.
    pub fn eval<T: num_traits::Float>(self, x: T) -> T {
        match self {
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Abs => x.abs(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A negative argument is made positive by the parity rules and then simplified like
    /// any other: `|-|a|| = |a|`, and `cos(-|a|) = cos |a|`, `sin(-|a|) = -sin |a|`.
    #[test]
    fn parity_then_the_other_rules() {
        let abs_a = Func::Abs.apply(Expr::symbol("a"));
        assert_eq!(Func::Abs.apply(-&abs_a), abs_a);
        assert_eq!(
            Func::Cos.apply(-&abs_a),
            Expr::func_node(Func::Cos, abs_a.clone())
        );
        assert_eq!(
            Func::Sin.apply(Expr::int(-2) * &abs_a),
            -Expr::func_node(Func::Sin, Expr::int(2) * &abs_a)
        );
    }
}
