//! Numerical evaluation over any `num_traits::Float` scalar: `f32`, `f64`, dual numbers for
//! exact partial derivatives, or a higher-precision type.

use super::error::AlgebraError;
use super::expr::{Expr, View};
use super::rational::Q;
use super::symbol::Symbol;
use num_traits::Float;

impl Expr {
    /// The value of the expression with each symbol's value from `value` (π's is π, never
    /// asked for). Fails for a
    /// symbol without a value, and for a result that is not finite: a division by zero
    /// when a divisor is zero (`1/x` at `x = 0`), [`AlgebraError::NotFinite`] otherwise
    /// (an overflow such as `10^400`, or a value that is not a number).
    ///
    /// ```
    /// use kinetics::algebra::{Expr, Symbol};
    /// let e = Expr::symbol("x").powi(2) / Expr::int(4);
    /// let v: f32 = e.eval(&|_| Some(3.0f32)).unwrap();
    /// assert_eq!(v, 2.25);
    /// ```
    pub fn eval<T: Float>(&self, value: &dyn Fn(Symbol) -> Option<T>) -> Result<T, AlgebraError> {
        let v = eval_unchecked(self, value)?;
        if v.is_finite() {
            Ok(v)
        } else if divides_by_zero(self, value) {
            Err(AlgebraError::DivisionByZero)
        } else {
            Err(AlgebraError::NotFinite {
                expression: self.to_string(),
                value: if v.is_nan() {
                    "NaN".into()
                } else {
                    "infinity".into()
                },
            })
        }
    }
}

/// Converts an exact rational to the scalar type, as exactly as the type allows: a ratio
/// of integers each exact in f64 as their quotient; in a type finer than f64 (double-double)
/// any ratio of 64-bit integers so, each integer taken whole (`10¹⁸/7¹⁸`, whose numerator
/// f64 cannot hold in one piece, to 32 digits, not 16); else the rational rounded once.
pub fn rational_to<T: Float>(q: &Q) -> T {
    let finer = T::epsilon() < T::from(f64::EPSILON).unwrap_or_else(T::nan);
    match q {
        Q::Small(n, d) if n.unsigned_abs() < (1 << 53) && *d < (1 << 53) => {
            let n = T::from(*n).unwrap_or_else(T::nan);
            let d = T::from(*d).unwrap_or_else(T::nan);
            n / d
        }
        Q::Small(n, d) if finer => integer_to::<T>(*n) / integer_to::<T>(*d),
        _ => T::from(q.to_f64()).unwrap_or_else(T::nan),
    }
}

/// A 64-bit integer in the scalar type as `high · 2³² + low`, each half exact in f64: the
/// whole integer where the type holds 64 bits.
fn integer_to<T: Float>(n: i64) -> T {
    let (high, low) = (n >> 32, n & 0xffff_ffff);
    let half = T::from(4_294_967_296.0).unwrap_or_else(T::nan);
    let part = |k: i64| T::from(k).unwrap_or_else(T::nan);
    part(high) * half + part(low)
}

/// Whether some negative power in `e` has a base whose value is zero (only asked once
/// the value is known not to be finite, so its cost is off the usual path).
fn divides_by_zero<T: Float>(e: &Expr, value: &dyn Fn(Symbol) -> Option<T>) -> bool {
    match e.view() {
        View::Num(_) | View::Sym(_) => false,
        View::Add(xs) | View::Mul(xs) => xs.iter().any(|x| divides_by_zero(x, value)),
        View::Pow(b, x) => {
            let negative = x.as_num().is_some_and(Q::is_negative);
            (negative && eval_unchecked(b, value).is_ok_and(|v| v.is_zero()))
                || divides_by_zero(b, value)
                || divides_by_zero(x, value)
        }
        View::Func(_, a) => divides_by_zero(a, value),
    }
}

fn eval_unchecked<T: Float>(
    e: &Expr,
    value: &dyn Fn(Symbol) -> Option<T>,
) -> Result<T, AlgebraError> {
    Ok(match e.view() {
        View::Num(q) => rational_to(q),
        View::Sym(s) if s.is_pi() => super::pi::pi_value(),
        View::Sym(s) => value(s).ok_or_else(|| AlgebraError::MissingValue(s.name().to_string()))?,
        View::Add(terms) => {
            let mut sum = T::zero();
            for t in terms {
                sum = sum + eval_unchecked(t, value)?;
            }
            sum
        }
        View::Mul(factors) => {
            let mut product = T::one();
            for f in factors {
                product = product * eval_unchecked(f, value)?;
            }
            product
        }
        View::Pow(b, x) => {
            let base = eval_unchecked(b, value)?;
            match x
                .as_num()
                .and_then(Q::to_i64)
                .and_then(|n| i32::try_from(n).ok())
            {
                Some(n) => base.powi(n),
                None => {
                    let half = x.as_num().is_some_and(|q| *q == Q::Small(1, 2));
                    if half {
                        base.sqrt()
                    } else {
                        base.powf(eval_unchecked(x, value)?)
                    }
                }
            }
        }
        View::Func(f, a) => f.eval(eval_unchecked(a, value)?),
    })
}

#[cfg(test)]
mod tests {
    use super::rational_to;
    use crate::algebra::rational::Q;
    use crate::numeric::scalar::double_double::DoubleDouble as Dd;

    /// In double-double a ratio of 64-bit integers is taken whole: 10¹⁸/7¹⁸ (10¹⁸ past 2⁵³)
    /// is the double-double quotient of its exact integers, not the f64 quotient; and
    /// (2⁶⁰ + 1)/3, three times over, comes back to 2⁶⁰ + 1, whose 1 an f64 loses.
    #[test]
    fn a_rational_of_large_integers_is_exact_in_double_double() {
        let seven_18 = 1_628_413_597_910_449_i64;
        let got: Dd = rational_to(&Q::Small(1_000_000_000_000_000_000, seven_18));
        let want = Dd::from_f64(1e18) / Dd::from_f64(seven_18 as f64);
        assert!(
            ((got - want) / want).abs().to_f64() < 1e-30,
            "{got:?} against {want:?}"
        );
        let n = (1_i64 << 60) + 1;
        let third: Dd = rational_to(&Q::Small(n, 3));
        let back = third * Dd::from_f64(3.0) - Dd::from_f64((1_u64 << 60) as f64);
        assert!((back - Dd::from_f64(1.0)).abs().to_f64() < 1e-6, "{back:?}");
    }
}
