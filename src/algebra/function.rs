//! The elementary functions an expression may hold: `sin`, `cos`, `tan`, `abs`, the
//! inverse cosine `acos` (the trigonometric form of a cubic's three real roots) and the
//! inverse tangent `atan` (an angle from its tangent, tan θ = (I′/I) tan γ).
//! (`sqrt(x)` is the power `x^(1/2)`.)
//!
//! Construction applies the parity rules `sin(-x) = -sin x`, `cos(-x) = cos x`,
//! `tan(-x) = -tan x`, `|-x| = |x|`, `||x|| = |x|`, the values at zero and the exact values
//! at the multiples of 15° (`sin(π/6) = 1/2`, `cos(13π/6) = cos(π/6) = √3/2`; see
//! `exact_angle.rs`), another multiple of π brought into `[0, π]` (`cos(10π/9) = cos(8π/9)`),
//! and the inverse of the exact values: `acos x = kπ/12` when `x = cos(kπ/12)` exactly
//! (`acos(1/2) = π/3`), `cos(acos x) = x`; `atan(−x) = −atan x`, `atan x = kπ/12` when `x`
//! is exactly `tan(kπ/12)`, `tan(atan x) = x`, `cos(atan x) = 1/√(1 + x²)`,
//! `sin(atan x) = x/√(1 + x²)`. `tan` at an odd multiple of π/2 is undefined, and
//! `acos` of a number outside `[−1, 1]`: [`Func::checked_apply`] refuses them,
//! [`Func::apply`] leaves them as they are (`tan(π/2)`).

use super::error::AlgebraError;
use super::exact_angle::{at_multiple_of_pi, ExactValue};
use super::expr::{Expr, View};
use super::rational::Q;

/// An elementary function of one argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Func {
    Sin,
    Cos,
    Tan,
    Abs,
    /// The inverse cosine, valued in `[0, π]`.
    Acos,
    /// The inverse tangent, valued in `(−π/2, π/2)`.
    Atan,
}

impl Func {
    /// The function of this ASCII name (`sin`, `cos`, `tan`, `abs`, `acos` or `arccos`,
    /// `atan` or `arctan`).
    pub fn from_name(name: &str) -> Option<Func> {
        Some(match name {
            "sin" => Func::Sin,
            "cos" => Func::Cos,
            "tan" => Func::Tan,
            "abs" => Func::Abs,
            "acos" | "arccos" => Func::Acos,
            "atan" | "arctan" => Func::Atan,
            _ => return None,
        })
    }

    pub fn name(self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Abs => "abs",
            Func::Acos => "acos",
            Func::Atan => "atan",
        }
    }

    /// The name as a page prints it (`sin`, `arccos`): LaTeX's operator without its backslash.
    pub fn page_name(self) -> &'static str {
        match self {
            Func::Acos => "arccos",
            Func::Atan => "arctan",
            _ => self.name(),
        }
    }

    /// `f(arg)` in canonical form, or an error when `f` is undefined there (`tan(π/2)`,
    /// `acos 2`).
    pub fn checked_apply(self, arg: Expr) -> Result<Expr, AlgebraError> {
        let value = self.apply(arg);
        match value.view() {
            // The pole kept as tan(π/2) (`apply`); tan(π/7) is a value.
            View::Func(Func::Tan, a) if *a == Expr::pi() / Expr::int(2) => {
                Err(AlgebraError::Undefined(format!("tan({a})")))
            }
            View::Func(Func::Acos, a) if outside_unit_interval(a) => Err(AlgebraError::Undefined(
                format!("acos({a}), whose argument is not in [-1, 1]"),
            )),
            _ => Ok(value),
        }
    }

    /// `f(arg)` in canonical form (`tan` at an odd multiple of π/2 as `tan(π/2)`).
    pub fn apply(self, arg: Expr) -> Expr {
        if self == Func::Acos {
            return inverse_cosine(arg);
        }
        if let View::Func(Func::Acos, x) = arg.view() {
            if self == Func::Cos {
                return x.clone();
            }
        }
        if let View::Func(Func::Atan, x) = arg.view() {
            if let Some(value) = of_inverse_tangent(self, x) {
                return value;
            }
        }
        if self == Func::Atan {
            if let Some(angle) = exact_inverse(Func::Tan, &arg, |v| v.atan()) {
                return angle;
            }
        }
        if let Some(q) = arg.as_multiple_of_pi() {
            match at_multiple_of_pi(self, q) {
                Some(ExactValue::Value(value)) => return value,
                Some(ExactValue::Pole) => {
                    return Expr::func_node(Func::Tan, Expr::pi() / Expr::int(2))
                }
                None => {
                    if let Some(reduced) = reduced_angle(self, q) {
                        return reduced;
                    }
                }
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
                Func::Sin | Func::Tan | Func::Atan => -self.apply(positive),
                Func::Cos | Func::Abs => self.apply(positive),
                Func::Acos => unreachable!("acos returned above"),
            };
        }
        Expr::func_node(self, arg)
    }

    /// `f'(u)`, the derivative with respect to the argument, evaluated at `u`; an error where
    /// it is infinite (`acos' u = −1/√(1 − u²)` at `u = ±1`).
    pub fn derivative_at(self, u: &Expr) -> Result<Expr, AlgebraError> {
        Ok(match self {
            Func::Sin => Func::Cos.apply(u.clone()),
            Func::Cos => -Func::Sin.apply(u.clone()),
            Func::Tan => Expr::one() + Func::Tan.apply(u.clone()).powi(2),
            Func::Abs => u * &Func::Abs.apply(u.clone()).powi(-1),
            Func::Acos => -(Expr::one() - u.powi(2)).checked_pow(&Expr::rational(-1, 2))?,
            Func::Atan => (Expr::one() + u.powi(2)).checked_pow(&Expr::int(-1))?,
        })
    }

    /// The function on a floating-point scalar.
    pub fn eval<T: num_traits::Float>(self, x: T) -> T {
        match self {
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Abs => x.abs(),
            Func::Acos => x.acos(),
            Func::Atan => x.atan(),
        }
    }
}

/// Whether a constant (a number, `π`, `√2`, …) lies outside `[−1, 1]`: a rational exactly,
/// another when its value in floating point is beyond ±1 by more than rounding.
fn outside_unit_interval(x: &Expr) -> bool {
    match x.as_num() {
        Some(q) => q.abs() > Q::ONE,
        None => x.eval(&|_| None).is_ok_and(|v: f64| v.abs() > 1.0 + 1e-12),
    }
}

/// `sin`, `cos` or `tan` of `qπ` with the angle brought into `[0, π]` (`[0, π)` for `tan`)
/// when it is outside: `cos(10π/9) = cos(8π/9)`, `sin(10π/9) = −sin(8π/9)`,
/// `tan(10π/9) = tan(π/9)`; None when it is inside (or `q` is not a small fraction).
fn reduced_angle(f: Func, q: &Q) -> Option<Expr> {
    let Q::Small(n, d) = *q else {
        return None;
    };
    let period = if f == Func::Tan { d } else { 2 * d };
    let within = n.rem_euclid(period);
    let (angle, negated) = match f {
        Func::Tan => (within, false),
        Func::Sin | Func::Cos if within > d => (2 * d - within, f == Func::Sin),
        Func::Sin | Func::Cos => (within, false),
        Func::Abs | Func::Acos | Func::Atan => return None,
    };
    if angle == n {
        return None;
    }
    let value = f.apply(Expr::rational(angle, d) * Expr::pi());
    Some(if negated { -value } else { value })
}

/// `acos x`: the angle `kπ/12` (`0 ≤ k ≤ 12`) when `x` is exactly its cosine, else `acos x`
/// kept as it is.
fn inverse_cosine(x: Expr) -> Expr {
    exact_inverse(Func::Cos, &x, |v| match v.abs() <= 1.0 {
        true => v.acos(),
        false => f64::NAN,
    })
    .unwrap_or_else(|| Expr::func_node(Func::Acos, x))
}

/// The angle `kπ/12` whose `f` (cos or tan) is exactly `x`: only the `k` nearest
/// `inverse(x)` in floating point is tried exactly (a constant `x`; one with symbols is no
/// such value).
fn exact_inverse(f: Func, x: &Expr, inverse: fn(f64) -> f64) -> Option<Expr> {
    let value: f64 = x.eval(&|_| None).ok()?;
    let turns = inverse(value) * 12.0 / std::f64::consts::PI;
    if !turns.is_finite() {
        return None;
    }
    let angle = Expr::rational(turns.round() as i64, 12) * Expr::pi();
    (f.apply(angle.clone()) == *x).then_some(angle)
}

/// `f(atan x)` without the inverse: `tan(atan x) = x`, `cos(atan x) = 1/√(1 + x²)`,
/// `sin(atan x) = x/√(1 + x²)` (the angle is in (−π/2, π/2), where the cosine is positive).
fn of_inverse_tangent(f: Func, x: &Expr) -> Option<Expr> {
    let secant = || {
        (Expr::one() + x.powi(2))
            .expand()
            .ok()?
            .checked_pow(&Expr::rational(-1, 2))
            .ok()
    };
    match f {
        Func::Tan => Some(x.clone()),
        Func::Cos => secant(),
        Func::Sin => Some(x * &secant()?),
        Func::Abs | Func::Acos | Func::Atan => None,
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

    /// `acos` at the cosines of the multiples of 15° is the angle, `cos(acos x) = x`, a
    /// number outside [−1, 1] is refused, and elsewhere it stays `acos x`.
    #[test]
    fn inverse_cosine() {
        let pi = Expr::pi;
        let half = Expr::rational(1, 2);
        assert_eq!(Func::Acos.apply(half.clone()), pi() / Expr::int(3));
        assert_eq!(Func::Acos.apply(-half), Expr::rational(2, 3) * pi());
        let root3_over_2 = Expr::int(3).checked_pow(&Expr::rational(1, 2)).unwrap() / Expr::int(2);
        assert_eq!(Func::Acos.apply(root3_over_2), pi() / Expr::int(6));
        assert_eq!(Func::Acos.apply(Expr::int(-1)), pi());
        assert_eq!(Func::Acos.apply(Expr::zero()), pi() / Expr::int(2));
        let third = Func::Acos.apply(Expr::rational(1, 3));
        assert!(matches!(third.view(), View::Func(Func::Acos, _)));
        assert_eq!(Func::Cos.apply(third.clone()), Expr::rational(1, 3));
        let value: f64 = third.eval(&|_| None).unwrap();
        assert!((value - (1.0f64 / 3.0).acos()).abs() < 1e-15);
        assert!(Func::Acos.checked_apply(Expr::rational(3, 2)).is_err());
        assert!(Func::Acos.checked_apply(Expr::pi()).is_err());
        let root2 = Expr::int(2).checked_pow(&Expr::rational(1, 2)).unwrap();
        assert!(Func::Acos.checked_apply(root2.clone()).is_err());
        assert!(Func::Acos.checked_apply(root2 / Expr::int(2)).is_ok());
        assert!(Func::Acos.derivative_at(&Expr::one()).is_err());
    }

    /// `atan` at the tangents of the multiples of 15° is the angle, odd, undone by `tan`, and
    /// its sine and cosine are algebraic: cos(atan x) = 1/√(1 + x²), sin = x/√(1 + x²).
    #[test]
    fn inverse_tangent() {
        let x = Expr::symbol("x");
        assert_eq!(Func::Atan.apply(Expr::one()), Expr::pi() / Expr::int(4));
        assert_eq!(Func::Atan.apply(Expr::zero()), Expr::zero());
        let root3 = Expr::int(3).checked_pow(&Expr::rational(1, 2)).unwrap();
        assert_eq!(Func::Atan.apply(-root3), -Expr::pi() / Expr::int(3));
        let atan_x = Func::Atan.apply(x.clone());
        assert_eq!(Func::Atan.apply(-x.clone()), -atan_x.clone());
        assert_eq!(Func::Tan.apply(atan_x.clone()), x);
        let secant = (Expr::one() + x.powi(2))
            .checked_pow(&Expr::rational(-1, 2))
            .unwrap();
        assert_eq!(Func::Cos.apply(atan_x.clone()), secant);
        assert_eq!(Func::Sin.apply(atan_x.clone()), &x * &secant);
        let value: f64 = Func::Atan
            .apply(Expr::rational(1, 2))
            .eval(&|_| None)
            .unwrap();
        assert!((value - 0.5f64.atan()).abs() < 1e-15);
        let slope: f64 = Func::Atan
            .derivative_at(&Expr::int(2))
            .unwrap()
            .eval(&|_| None)
            .unwrap();
        assert_eq!(slope, 0.2);
    }

    /// An angle that is a multiple of π outside [0, π] is brought into it.
    #[test]
    fn angles_brought_into_the_first_half_turn() {
        let at = |f: Func, n: i64, d: i64| f.apply(Expr::rational(n, d) * Expr::pi());
        assert_eq!(at(Func::Cos, 10, 9), at(Func::Cos, 8, 9));
        assert_eq!(at(Func::Cos, -4, 9), at(Func::Cos, 4, 9));
        assert_eq!(at(Func::Sin, 10, 9), -at(Func::Sin, 8, 9));
        assert_eq!(at(Func::Sin, 20, 9), at(Func::Sin, 2, 9));
        assert_eq!(at(Func::Tan, 10, 9), at(Func::Tan, 1, 9));
        assert!(matches!(
            at(Func::Cos, 8, 9).view(),
            View::Func(Func::Cos, _)
        ));
        for (n, d) in [(10, 9), (-4, 9), (20, 9), (23, 7)] {
            for f in [Func::Sin, Func::Cos, Func::Tan] {
                let x = n as f64 / d as f64 * std::f64::consts::PI;
                let value: f64 = at(f, n, d).eval(&|_| None).unwrap();
                assert!((value - f.eval(x)).abs() < 1e-14, "{f:?} {n}/{d}");
            }
        }
    }
}
