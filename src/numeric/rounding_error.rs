//! An expression evaluated in double-double with a bound on its rounding error: running
//! error analysis to first order (Higham, *Accuracy and Stability of Numerical Algorithms*,
//! §3.3). Each node's computed value `v̂` carries a bound `e ≥ |v̂ − v|`, propagated by the
//! derivative of the operation and increased by its own rounding, a few units `u = 2⁻¹⁰⁴`
//! of its result:
//!
//! ```text
//! Σ xᵢ       e = Σ eᵢ + n u Σ |xᵢ|
//! x y        e = e_x |y| + |x| e_y + u |v|             (a product, factor by factor)
//! b^n        e = |n| |b|^(n−1) e_b + (2 log₂|n| + 2) u |v|   (n whole: by squaring)
//! b^y        e = |y| |b|^(y−1) e_b + |v| |ln |b|| e_y + (c + |y ln |b||) u |v|
//! sin, cos   e = e_a + c u (1 + |a|)      tan: (1 + v²)(e_a + c u (1 + |a|))      |a|: e_a
//! ```
//!
//! The value is the one `Expr::eval` computes (a whole power by squaring, `½` by a square
//! root, any other through exp and ln), but for an integer, taken without a division. A
//! symbol's value is taken as exact (the check's second opinion draws values a double-double
//! holds; a solution's numbers have the givens substituted exactly before); a
//! number is exact when it is an integer below 2⁵³, within `u` when its numerator and
//! denominator are (`rational_to` divides them), else within an `f64` rounding. A bound
//! that overflows or is not a number says nothing: the caller's comparison with it fails.

use crate::algebra::{rational_to, Expr, Func, Symbol, View, Q};
use crate::numeric::scalar::double_double::DoubleDouble;
use num_traits::Float;

/// The unit roundoff of double-double.
const U: f64 = DoubleDouble::EPSILON;

/// Units of roundoff an elementary function (exp, ln, sin, cos) or a power may add.
const ELEMENTARY: f64 = 8.0;

/// A computed value and a bound on its rounding error.
#[derive(Debug, Clone, Copy)]
pub struct Bounded {
    pub value: DoubleDouble,
    pub error: f64,
}

/// `e` evaluated in double-double with each symbol's value from `value`, and a bound on
/// the rounding error; None when a symbol has no value or a value is not finite.
pub fn bounded(e: &Expr, value: &dyn Fn(Symbol) -> Option<DoubleDouble>) -> Option<Bounded> {
    let result = match e.view() {
        View::Num(q) => number(q),
        View::Sym(s) if s.is_pi() => Bounded {
            value: DoubleDouble::PI,
            error: U * std::f64::consts::PI,
        },
        View::Sym(s) => Bounded {
            value: value(s)?,
            error: 0.0,
        },
        View::Add(terms) => {
            let (mut sum, mut error, mut magnitude) = (DoubleDouble::ZERO, 0.0, 0.0);
            for t in terms {
                let t = bounded(t, value)?;
                sum += t.value;
                error += t.error;
                magnitude += t.value.abs().to_f64();
            }
            Bounded {
                value: sum,
                error: error + terms.len() as f64 * U * magnitude,
            }
        }
        View::Mul(factors) => {
            let mut product = Bounded {
                value: DoubleDouble::ONE,
                error: 0.0,
            };
            for f in factors {
                product = product.times(bounded(f, value)?);
            }
            product
        }
        View::Pow(b, y) => power(bounded(b, value)?, y, value)?,
        View::Func(f, a) => function(f, bounded(a, value)?),
    };
    result.value.is_finite().then_some(result)
}

/// A number in double-double (an integer below 2⁵³ exactly, else as `rational_to`
/// converts it), and the error of that conversion.
fn number(q: &Q) -> Bounded {
    let (value, units) = match q {
        Q::Small(n, 1) if n.unsigned_abs() < 1 << 53 => (DoubleDouble::from_f64(*n as f64), 0.0),
        Q::Small(n, d) if n.unsigned_abs() < 1 << 53 && *d < 1 << 53 => (rational_to(q), U),
        _ => (rational_to(q), f64::EPSILON),
    };
    Bounded {
        value,
        error: units * value.abs().to_f64(),
    }
}

impl Bounded {
    /// `x y`, its error `e_x |y| + |x| e_y` and one rounding.
    fn times(self, other: Bounded) -> Bounded {
        let value = self.value * other.value;
        let error = scaled(self.error, || other.value.abs().to_f64())
            + scaled(other.error, || self.value.abs().to_f64())
            + U * value.abs().to_f64();
        Bounded { value, error }
    }
}

/// `b^y`, computed as `Expr::eval` does (by squaring for a whole exponent, a square root
/// for ½, else through exp and ln).
fn power(
    base: Bounded,
    y: &Expr,
    value: &dyn Fn(Symbol) -> Option<DoubleDouble>,
) -> Option<Bounded> {
    let whole = y
        .as_num()
        .and_then(Q::to_i64)
        .and_then(|n| i32::try_from(n).ok());
    let b = base.value.abs().to_f64();
    if let Some(n) = whole {
        let v = base.value.powi(n);
        let squarings = 2.0 * f64::from(32 - n.unsigned_abs().leading_zeros()) + 2.0;
        return Some(Bounded {
            value: v,
            error: scaled(base.error, || f64::from(n.unsigned_abs()) * b.powi(n - 1))
                + squarings * U * v.abs().to_f64(),
        });
    }
    let exponent = bounded(y, value)?;
    let v = match y.as_num() {
        Some(q) if *q == Q::Small(1, 2) => base.value.sqrt(),
        _ => base.value.powf(exponent.value),
    };
    let (y, magnitude, log) = (exponent.value.to_f64(), v.abs().to_f64(), b.ln().abs());
    Some(Bounded {
        value: v,
        error: scaled(base.error, || y.abs() * b.powf(y - 1.0))
            + scaled(exponent.error, || magnitude * log)
            + (ELEMENTARY + (y * log).abs()) * U * magnitude,
    })
}

/// `f(a)`: the argument's error times the derivative's size, and the function's rounding
/// (its argument reduction grows with `|a|`).
fn function(f: Func, a: Bounded) -> Bounded {
    let v = f.eval(a.value);
    let own = ELEMENTARY * U * (1.0 + a.value.abs().to_f64());
    let error = match f {
        Func::Sin | Func::Cos => a.error + own,
        Func::Tan => (1.0 + v.to_f64().powi(2)) * (a.error + own),
        Func::Abs => a.error,
        // |acos'(a)| = 1/√(1 − a²)
        Func::Acos => (a.error + own) / (1.0 - a.value.to_f64().powi(2)).sqrt(),
        // |atan'(a)| = 1/(1 + a²); no argument reduction, so its own rounding is relative
        // to its value, |atan| < π/2, whatever the size of a.
        Func::Atan => {
            let a2 = a.value.to_f64().powi(2);
            a.error / (1.0 + a2) + ELEMENTARY * U * (1.0 + v.abs().to_f64())
        }
    };
    Bounded { value: v, error }
}

/// `error · factor`, zero when the error is (the factor is not computed then, and an
/// infinite or undefined factor times an exact value adds nothing).
fn scaled(error: f64, factor: impl FnOnce() -> f64) -> f64 {
    if error == 0.0 {
        0.0
    } else {
        error * factor()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::parse_expression;

    fn at(text: &str, x: f64) -> Bounded {
        let e = parse_expression("test", text).expect("parses");
        bounded(&e, &|_| Some(DoubleDouble::from_f64(x))).expect("finite")
    }

    /// atan of a huge argument is near π/2 with a bound as small as its value's rounding
    /// (a bound growing with the argument made atan(5e16) "zero within its bound").
    #[test]
    fn inverse_tangent_of_a_huge_argument() {
        let b = at("atan(x)", 5e16);
        assert!((b.value.to_f64() - std::f64::consts::FRAC_PI_2).abs() < 1e-16);
        assert!(b.error < 1e-28, "{}", b.error);
    }

    /// The bound holds the actual error where the exact value is known, and is small
    /// where nothing cancels.
    #[test]
    fn the_bound_holds_the_error() {
        for (text, x, exact) in [
            ("(x - 1)^9 - (x^9 - 9 x^8 + 36 x^7 - 84 x^6 + 126 x^5 - 126 x^4 + 84 x^3 - 36 x^2 + 9 x - 1)", 1.0 + 1.0 / 1024.0, 0.0),
            ("sin(x)^2 + cos(x)^2", 2.5, 1.0),
            ("sqrt(x^2)/x", 0.7, 1.0),
            ("(1/3) x - x/3", 1.5, 0.0),
        ] {
            let b = at(text, x);
            let error = (b.value - DoubleDouble::from_f64(exact)).abs().to_f64();
            assert!(error <= b.error, "{text}: error {error:e}, bound {:e}", b.error);
            assert!(b.error < 1e-25, "{text}: bound {:e}", b.error);
        }
    }

    /// Cancellation shows in the bound: the terms of (x − y)⁹ expanded are near 6⁹ while
    /// its value is near 10⁻¹⁸.
    #[test]
    fn cancellation_widens_the_bound() {
        let e = parse_expression("test", "(x - 1)^9")
            .unwrap()
            .expand()
            .unwrap();
        let b = bounded(&e, &|_| Some(DoubleDouble::from_f64(1.0 + 1.0 / 128.0))).unwrap();
        assert!(b.error > 1e-30 && b.error > 1e-12 * b.value.abs().to_f64());
    }
}
