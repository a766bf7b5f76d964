//! [`num_traits::Float`] for [`DoubleDouble`] (with `Num`, `Zero`, `One`, `NumCast`,
//! `ToPrimitive` and `Rem`), so the compiled tape and `Expr::eval` run in double-double:
//! the difference between an `f64` and a double-double evaluation estimates the `f64`
//! rounding error.
//!
//! ```
//! use kinetics::algebra::{Expr, Symbol};
//! use kinetics::numeric::scalar::double_double::DoubleDouble;
//! use kinetics::numeric::Tape;
//! use num_traits::Float;
//!
//! // (x + 1)² − x² − 2x = 1, a cancellation that f64 loses for large x.
//! let x = Expr::symbol("x");
//! let e = (&x + &Expr::int(1)).powi(2) - x.powi(2) - Expr::int(2) * &x;
//! let tape = Tape::compile(&[e], &[Symbol::new("x")]).unwrap();
//! let mut out = [DoubleDouble::ZERO];
//! tape.eval::<DoubleDouble>(&[DoubleDouble::from_f64(1e12)], &mut out).unwrap();
//! assert_eq!(out[0], DoubleDouble::ONE);
//! assert!((DoubleDouble::from_f64(2.0).sqrt().powi(2) - DoubleDouble::from_f64(2.0)).abs()
//!     < DoubleDouble::from_f64(1e-31));
//! ```
//!
//! Accuracy of the elementary functions: see `double_double_elementary`. The rest:
//! * `epsilon()` is 2^-104, a bound on the relative error of one arithmetic operation
//!   (the format has at least 106 significant bits, more when `lo` has trailing zeros).
//! * `max_value()` is `f64::MAX + 2^970 − 2^917`, the largest pair whose sum rounds to
//!   `f64::MAX`; `min_positive_value()` is 2^-969, the smallest magnitude at which `lo` still
//!   holds 53 bits below `hi` (smaller non-zero values are classed subnormal: precision is lost).
//! * `integer_decode` gives the value rounded to 64 significant bits (the `u64` mantissa
//!   cannot hold more): `sign · mantissa · 2^exponent`, exact for zero, subnormal and `f64`
//!   values.
//! * `mul_add(a, b)` is `self·a + b`, two roundings of 2^-106 rather than one.
//! * `%` is `a − b·trunc(a/b)` with the sign of `a`: exact when `b` is an `f64` and the
//!   quotient below 2^53, otherwise with an absolute error of about `|a|·2^-105`.
//! * Conversions (`NumCast::from`) are exact from `f32`, `f64` and integers below 2^106 in
//!   magnitude (larger `i128`/`u128` are rounded to about 2^-106); from another
//!   double-double they go through `f64` (or an integer when the `f64` is one above 2^53).
//!   `to_i64` and the other integer conversions truncate toward zero exactly.

use super::double_double::{quick_two_sum, DoubleDouble};
use crate::numeric::error::NumericError;
use num_traits::{Float, Num, NumCast, One, ToPrimitive, Zero};
use std::num::FpCategory;
use std::ops::Rem;

type Dd = DoubleDouble;

/// 2^-969 (biased exponent 1023 − 969).
const MIN_POSITIVE: f64 = f64::from_bits(54 << 52);
/// The trailing part of the largest pair, `2^970 − 2^917`.
const MAX_LO: f64 = 9.979_201_547_673_598e291;

impl Zero for DoubleDouble {
    fn zero() -> Self {
        Dd::ZERO
    }
    fn is_zero(&self) -> bool {
        self.hi == 0.0
    }
}

impl One for DoubleDouble {
    fn one() -> Self {
        Dd::ONE
    }
}

impl Rem for DoubleDouble {
    type Output = Self;
    fn rem(self, b: Self) -> Self {
        if !self.hi.is_finite() || b.hi == 0.0 || b.hi.is_nan() {
            return Dd::from_f64(f64::NAN);
        }
        if b.hi.is_infinite() {
            return self;
        }
        let r = self - b * (self / b).trunc();
        // A quotient rounded up to the next integer leaves a remainder of the wrong sign.
        if !r.is_zero() && r.hi.is_sign_negative() != self.hi.is_sign_negative() {
            r + if r.hi.is_sign_negative() == b.hi.is_sign_negative() {
                -b
            } else {
                b
            }
        } else {
            r
        }
    }
}

impl Num for DoubleDouble {
    type FromStrRadixErr = NumericError;

    /// Parses `[+-]digits[.digits]` in `radix` (2 to 36), with an exponent `e±n` in radix
    /// 10, or `inf`, `infinity`, `nan`. The digits are accumulated exactly while they fit 106
    /// bits and the result is scaled by one power of the radix `r^n` (binary powering). The
    /// powers of ten are exact up to 10^45 (`2^n 5^n`, with `5^45 < 2^106`), so a decimal of
    /// up to 31 significant digits with such an exponent is read to a few units of 2^-106;
    /// larger powers add their own rounding (12 units of 2^-106 measured at 10^-280). Below
    /// 2^-969 the trailing part is subnormal and precision is lost.
    fn from_str_radix(text: &str, radix: u32) -> Result<Self, NumericError> {
        let refuse = |reason: &str| NumericError::InvalidInput {
            what: format!("double-double literal '{text}'"),
            reason: reason.to_string(),
        };
        if !(2..=36).contains(&radix) {
            return Err(refuse("the radix must be between 2 and 36"));
        }
        let (negative, body) = match text.as_bytes().first() {
            Some(b'-') => (true, &text[1..]),
            Some(b'+') => (false, &text[1..]),
            _ => (false, text),
        };
        let magnitude = match body.to_ascii_lowercase().as_str() {
            "inf" | "infinity" => Dd::from_f64(f64::INFINITY),
            "nan" => Dd::from_f64(f64::NAN),
            _ => {
                let (mantissa, exponent) = match body.find(['e', 'E']) {
                    Some(at) if radix == 10 => (
                        &body[..at],
                        body[at + 1..]
                            .parse::<i32>()
                            .map_err(|_| refuse("the exponent is not an integer"))?,
                    ),
                    _ => (body, 0),
                };
                let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
                if whole.is_empty() && fraction.is_empty() {
                    return Err(refuse("there are no digits"));
                }
                let base = Dd::from_f64(radix as f64);
                let mut value = Dd::ZERO;
                for c in whole.chars().chain(fraction.chars()) {
                    let digit = c
                        .to_digit(radix)
                        .ok_or_else(|| refuse(&format!("'{c}' is not a digit in radix {radix}")))?;
                    value = value * base + Dd::from_f64(digit as f64);
                }
                let scale = i32::try_from(fraction.chars().count())
                    .ok()
                    .and_then(|digits| exponent.checked_sub(digits))
                    .ok_or_else(|| refuse("the exponent is out of range"))?;
                if value.is_zero() {
                    value
                } else if scale < 0 {
                    value / base.powi(-scale)
                } else {
                    value * base.powi(scale)
                }
            }
        };
        Ok(if negative { -magnitude } else { magnitude })
    }
}

impl ToPrimitive for DoubleDouble {
    fn to_i64(&self) -> Option<i64> {
        self.to_i128().and_then(|v| i64::try_from(v).ok())
    }
    fn to_u64(&self) -> Option<u64> {
        self.to_i128().and_then(|v| u64::try_from(v).ok())
    }
    /// The value truncated toward zero, if it fits.
    fn to_i128(&self) -> Option<i128> {
        let t = Float::trunc(*self);
        // Both parts of an integer-valued pair are integers; hi < 2^127 converts exactly.
        if !(t.hi >= -(2f64.powi(127)) && t.hi < 2f64.powi(127)) {
            return None;
        }
        (t.hi as i128).checked_add(t.lo as i128)
    }
    fn to_u128(&self) -> Option<u128> {
        let t = Float::trunc(*self);
        if !(t.hi >= 0.0 && t.hi < 2f64.powi(128)) {
            return None;
        }
        // hi ≥ 2^127 only with lo ≤ 0, so the sum stays within u128.
        let lo = t.lo as i128;
        let hi = t.hi as u128;
        if lo >= 0 {
            hi.checked_add(lo as u128)
        } else {
            hi.checked_sub(lo.unsigned_abs())
        }
    }
    fn to_f64(&self) -> Option<f64> {
        Some(DoubleDouble::to_f64(*self))
    }
    fn to_f32(&self) -> Option<f32> {
        Some(DoubleDouble::to_f64(*self) as f32)
    }
}

/// The exact (or, beyond 2^106, nearest) pair of an integer.
fn from_i128(n: i128) -> Dd {
    let hi = n as f64;
    // |n − hi| ≤ ulp(hi)/2 ≤ 2^73, an exact f64 below 2^53, rounded above (n ≥ 2^106).
    let rest = if hi.abs() >= 2f64.powi(127) {
        0.0
    } else {
        n.wrapping_sub(hi as i128) as f64
    };
    let (hi, lo) = quick_two_sum(hi, rest);
    Dd::from_parts(hi, lo)
}

impl NumCast for DoubleDouble {
    /// Integers through `i128`/`u128` (exact up to 2^106), floats through `f64` (exact).
    fn from<N: ToPrimitive>(n: N) -> Option<Self> {
        let float = n.to_f64()?;
        if float.is_finite() && float.fract() == 0.0 && float.abs() >= 2f64.powi(53) {
            if let Some(i) = n.to_i128() {
                return Some(from_i128(i));
            }
            if let Some(u) = n.to_u128() {
                let half = from_i128((u / 2) as i128).mul_f64(2.0);
                return Some(half + Dd::from_f64((u % 2) as f64));
            }
        }
        Some(Dd::from_f64(float))
    }
}

impl Float for DoubleDouble {
    fn nan() -> Self {
        Dd::from_f64(f64::NAN)
    }
    fn infinity() -> Self {
        Dd::from_f64(f64::INFINITY)
    }
    fn neg_infinity() -> Self {
        Dd::from_f64(f64::NEG_INFINITY)
    }
    fn neg_zero() -> Self {
        Dd::from_f64(-0.0)
    }
    fn min_value() -> Self {
        -Self::max_value()
    }
    fn min_positive_value() -> Self {
        Dd::from_f64(MIN_POSITIVE)
    }
    fn epsilon() -> Self {
        Dd::from_f64(Dd::EPSILON)
    }
    fn max_value() -> Self {
        Dd::from_parts(f64::MAX, MAX_LO)
    }
    fn is_nan(self) -> bool {
        self.hi.is_nan()
    }
    fn is_infinite(self) -> bool {
        self.hi.is_infinite()
    }
    fn is_finite(self) -> bool {
        self.hi.is_finite()
    }
    fn is_normal(self) -> bool {
        self.classify() == FpCategory::Normal
    }
    fn classify(self) -> FpCategory {
        match self.hi.classify() {
            FpCategory::Normal if self.hi.abs() < MIN_POSITIVE => FpCategory::Subnormal,
            category => category,
        }
    }
    fn floor(self) -> Self {
        Dd::floor(self)
    }
    fn ceil(self) -> Self {
        -Dd::floor(-self)
    }
    fn round(self) -> Self {
        Dd::round(self)
    }
    fn trunc(self) -> Self {
        if self.hi.is_sign_negative() {
            Float::ceil(self)
        } else {
            Dd::floor(self)
        }
    }
    fn fract(self) -> Self {
        self - Float::trunc(self)
    }
    fn abs(self) -> Self {
        Dd::abs(self)
    }
    fn signum(self) -> Self {
        Dd::from_f64(self.hi.signum())
    }
    fn is_sign_positive(self) -> bool {
        self.hi.is_sign_positive()
    }
    fn is_sign_negative(self) -> bool {
        self.hi.is_sign_negative()
    }
    fn mul_add(self, a: Self, b: Self) -> Self {
        self * a + b
    }
    fn recip(self) -> Self {
        Dd::ONE / self
    }
    fn powi(self, n: i32) -> Self {
        Dd::powi(self, n)
    }
    fn powf(self, n: Self) -> Self {
        Dd::powf(self, n)
    }
    fn sqrt(self) -> Self {
        Dd::sqrt(self)
    }
    fn exp(self) -> Self {
        Dd::exp(self)
    }
    fn exp2(self) -> Self {
        Dd::exp(self * Dd::LN_2)
    }
    fn ln(self) -> Self {
        Dd::ln(self)
    }
    fn log(self, base: Self) -> Self {
        Dd::ln(self) / Dd::ln(base)
    }
    fn log2(self) -> Self {
        Dd::ln(self) * Dd::LOG2_E
    }
    fn log10(self) -> Self {
        Dd::ln(self) * Dd::LOG10_E
    }
    fn to_degrees(self) -> Self {
        self * Dd::DEGREES_PER_RADIAN
    }
    fn to_radians(self) -> Self {
        self * Dd::RADIANS_PER_DEGREE
    }
    fn max(self, other: Self) -> Self {
        if self.is_nan() || other > self {
            other
        } else {
            self
        }
    }
    fn min(self, other: Self) -> Self {
        if self.is_nan() || other < self {
            other
        } else {
            self
        }
    }
    fn abs_sub(self, other: Self) -> Self {
        if self.is_nan() || other.is_nan() {
            return Self::nan();
        }
        Float::max(self - other, Dd::ZERO)
    }
    fn cbrt(self) -> Self {
        Dd::cbrt(self)
    }
    fn hypot(self, other: Self) -> Self {
        Dd::hypot(self, other)
    }
    fn sin(self) -> Self {
        Dd::sin(self)
    }
    fn cos(self) -> Self {
        Dd::cos(self)
    }
    fn tan(self) -> Self {
        Dd::tan(self)
    }
    fn asin(self) -> Self {
        Dd::asin(self)
    }
    fn acos(self) -> Self {
        Dd::acos(self)
    }
    fn atan(self) -> Self {
        Dd::atan(self)
    }
    fn atan2(self, other: Self) -> Self {
        Dd::atan2(self, other)
    }
    fn sin_cos(self) -> (Self, Self) {
        Dd::sin_cos(self)
    }
    fn exp_m1(self) -> Self {
        Dd::exp_m1(self)
    }
    fn ln_1p(self) -> Self {
        Dd::ln_1p(self)
    }
    fn sinh(self) -> Self {
        Dd::sinh(self)
    }
    fn cosh(self) -> Self {
        Dd::cosh(self)
    }
    fn tanh(self) -> Self {
        Dd::tanh(self)
    }
    fn asinh(self) -> Self {
        Dd::asinh(self)
    }
    fn acosh(self) -> Self {
        Dd::acosh(self)
    }
    fn atanh(self) -> Self {
        Dd::atanh(self)
    }
    /// `sign · mantissa · 2^exponent` with the value rounded to the 64-bit mantissa.
    fn integer_decode(self) -> (u64, i16, i8) {
        let (mantissa, exponent, sign) = self.hi.integer_decode();
        if self.lo == 0.0 || !self.hi.is_finite() {
            return (mantissa, exponent, sign);
        }
        // hi = sign·mantissa·2^exponent with a 53-bit mantissa; widen it to 64 bits and add
        // lo (|lo| ≤ 2^(exponent−1)) in units of 2^(exponent−11), rounded to nearest.
        let (wide, unit) = (mantissa << 11, exponent - 11);
        // lo·2^-unit in two exact scalings (one factor could overflow).
        let shift = -<i32 as From<i16>>::from(unit);
        let scaled = self.lo * 2f64.powi(shift / 2) * 2f64.powi(shift - shift / 2);
        let lo_units = scaled.round() * <f64 as From<i8>>::from(sign);
        let widened = (wide as i128 + lo_units as i128) as u64;
        (widened, unit, sign)
    }
}
