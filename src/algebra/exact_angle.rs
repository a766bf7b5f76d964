//! Exact values of `sin`, `cos` and `tan` at the multiples of 15° (`k π/12`).
//!
//! With `k` reduced modulo 24 (the period 2π; `tan` modulo 12, its period π):
//!
//! ```text
//! k            0   1             2    3      4      5             6
//! sin(kπ/12)   0   (√6 − √2)/4   1/2  √2/2   √3/2   (√6 + √2)/4   1
//! tan(kπ/12)   0   2 − √3        √3/3 1      √3     2 + √3        undefined
//! ```
//!
//! the other quadrants by `sin(π − x) = sin x`, `sin(π + x) = −sin x`, `tan(π − x) = −tan x`,
//! and `cos x = sin(x + π/2)`. The check is a look at the argument's one factor and a
//! remainder, so constructing a function of anything else costs nothing more.

use super::expr::Expr;
use super::function::Func;
use super::rational::Q;

/// What a function is at a multiple of 15°.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum ExactValue {
    /// Its exact value.
    Value(Expr),
    /// `tan` at an odd multiple of π/2: undefined.
    Pole,
}

/// `f(q π)` exactly, when `f` is `sin`, `cos` or `tan` and `q` a multiple of 1/12.
pub(super) fn at_multiple_of_pi(f: Func, q: &Q) -> Option<ExactValue> {
    let Q::Small(n, d) = *q else {
        return None;
    };
    if 12 % d != 0 {
        return None;
    }
    // q π = k π/12 with k taken modulo 24 (d divides 12, so 2d does not overflow).
    let k = n.rem_euclid(2 * d) * (12 / d);
    Some(match f {
        Func::Sin => ExactValue::Value(sine(k)),
        Func::Cos => ExactValue::Value(sine((k + 6) % 24)),
        Func::Tan => match tangent(k % 12) {
            Some(value) => ExactValue::Value(value),
            None => ExactValue::Pole,
        },
        Func::Abs | Func::Acos | Func::Atan => return None,
    })
}

/// `sin(k π/12)` for `0 ≤ k < 24`.
fn sine(k: i64) -> Expr {
    match k {
        12.. => -sine(k - 12),
        7.. => sine(12 - k),
        0 => Expr::zero(),
        1 => (sqrt(6) - sqrt(2)) / Expr::int(4),
        2 => Expr::rational(1, 2),
        3 => sqrt(2) / Expr::int(2),
        4 => sqrt(3) / Expr::int(2),
        5 => (sqrt(6) + sqrt(2)) / Expr::int(4),
        _ => Expr::one(),
    }
}

/// `tan(k π/12)` for `0 ≤ k < 12`; none at `k = 6` (π/2).
fn tangent(k: i64) -> Option<Expr> {
    Some(match k {
        7.. => -tangent(12 - k)?,
        0 => Expr::zero(),
        1 => Expr::int(2) - sqrt(3),
        2 => sqrt(3) / Expr::int(3),
        3 => Expr::one(),
        4 => sqrt(3),
        5 => Expr::int(2) + sqrt(3),
        _ => return None,
    })
}

/// `√n` of a positive integer that is not a square.
fn sqrt(n: i64) -> Expr {
    Expr::int(n)
        .checked_pow(&Expr::rational(1, 2))
        .expect("the square root of a positive integer")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each value against `f64` at every multiple of 15° in two turns either way.
    #[test]
    fn every_multiple_of_fifteen_degrees() {
        for k in -48..=48 {
            let q = Q::new(k, 12).unwrap();
            let x = k as f64 * std::f64::consts::PI / 12.0;
            for f in [Func::Sin, Func::Cos, Func::Tan] {
                match at_multiple_of_pi(f, &q).unwrap() {
                    ExactValue::Value(v) => {
                        let v: f64 = v.eval(&|_| None).unwrap();
                        assert!((v - f.eval(x)).abs() < 1e-12, "{f:?}({k}π/12)");
                    }
                    ExactValue::Pole => assert!(f == Func::Tan && k.rem_euclid(12) == 6),
                }
            }
        }
    }

    #[test]
    fn other_multiples_are_left() {
        assert!(at_multiple_of_pi(Func::Sin, &Q::new(1, 5).unwrap()).is_none());
        assert!(at_multiple_of_pi(Func::Abs, &Q::ONE).is_none());
    }
}
