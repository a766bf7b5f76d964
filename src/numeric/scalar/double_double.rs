//! Double-double arithmetic: a real number stored as the unevaluated sum `hi + lo` of two
//! `f64` with `|lo| <= ulp(hi)/2`, giving about 106 significant bits (~32 decimal digits).
//!
//! The operations are built from the error-free transformations
//! `a + b = s + e` (Knuth's two-sum) and `a * b = p + e` (two-product through a fused
//! multiply-add), following Hida, Li and Bailey, "Library for double-double and quad-double
//! arithmetic" (2000): addition and multiplication are accurate to a few units of 2^-106,
//! division and square root take one Newton correction of the `f64` estimate.
//!
//! Infinities and NaN come out of `+`, `−`, `×`, `÷` as from `f64` (the error-free
//! transformations alone would turn `∞ + 1` into NaN): each operation checks that its result
//! is finite and otherwise returns the `f64` operation on the leading parts. The check is a
//! predictable branch, but on the reference integrator's Taylor recurrences it costs about a
//! quarter more instructions (callgrind: 184.5M → 233.4M in `ReferenceMotion::advance_to`
//! for `kinetics bench work-precision --until 20 --budget-ms 0`).
//!
//! The type serves as the ground-truth scalar of the reference integrator, carries the
//! long-time phases of the exact torque-free motion, and, as a `num_traits::Float`
//! (`double_double_float`), evaluates the tape and `Expr::eval` to about 32 digits.

use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

/// A double-double number `hi + lo`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct DoubleDouble {
    pub(super) hi: f64,
    pub(super) lo: f64,
}

/// `a + b = s + e` exactly (Knuth).
pub(super) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `a + b = s + e` exactly, provided `|a| >= |b|` (Dekker).
pub(super) fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a * b = p + e` exactly (fused multiply-add).
pub(super) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl DoubleDouble {
    /// Zero.
    pub const ZERO: Self = Self { hi: 0.0, lo: 0.0 };
    /// One.
    pub const ONE: Self = Self { hi: 1.0, lo: 0.0 };
    /// π to double-double precision.
    pub const PI: Self = Self {
        hi: std::f64::consts::PI,
        lo: 1.224_646_799_147_353_2e-16,
    };
    /// Unit roundoff of the format, 2^-104 (a safe bound for the compound operations).
    pub const EPSILON: f64 = 4.930_380_657_631_324e-32;

    /// The exact value of an `f64`.
    pub const fn from_f64(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }

    /// The exact product of two `f64`.
    pub fn product(a: f64, b: f64) -> Self {
        let (hi, lo) = two_prod(a, b);
        Self { hi, lo }
    }

    /// The exact sum of two `f64`.
    pub fn sum(a: f64, b: f64) -> Self {
        let (hi, lo) = two_sum(a, b);
        Self { hi, lo }
    }

    /// The nearest `f64`.
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// Leading component.
    pub fn hi(self) -> f64 {
        self.hi
    }

    /// Trailing component (the rounding error of `hi`).
    pub fn lo(self) -> f64 {
        self.lo
    }

    /// Absolute value.
    pub fn abs(self) -> Self {
        if self.hi.is_sign_negative() {
            -self
        } else {
            self
        }
    }

    /// Square root by one Newton step on the `f64` root; `sqrt(±0) = ±0`, `sqrt(∞) = ∞`,
    /// negative input gives NaN.
    pub fn sqrt(self) -> Self {
        if self.hi == 0.0 || !self.hi.is_finite() || self.hi < 0.0 {
            return Self::from_f64(self.hi.sqrt());
        }
        let x = self.hi.sqrt();
        let residual = self - Self::product(x, x);
        Self::sum(x, residual.hi / (2.0 * x))
    }

    /// Largest integer not above the value.
    pub fn floor(self) -> Self {
        let hi = self.hi.floor();
        if hi == self.hi {
            let (hi, lo) = quick_two_sum(hi, self.lo.floor());
            Self { hi, lo }
        } else {
            Self::from_f64(hi)
        }
    }

    /// Nearest integer, halves rounded away from zero (as `f64::round`).
    pub fn round(self) -> Self {
        let half = Self::from_f64(0.5);
        if self.hi.is_sign_negative() {
            -(half - self).floor()
        } else {
            (self + half).floor()
        }
    }

    /// Multiplication by an `f64`.
    pub fn mul_f64(self, b: f64) -> Self {
        let (p, e) = two_prod(self.hi, b);
        let e = e + self.lo * b;
        let (hi, lo) = quick_two_sum(p, e);
        Self::checked(hi, lo, || self.hi * b)
    }

    /// The pair `hi + lo`, or, when `hi` is not finite (an infinite or NaN operand, or
    /// overflow, which the error-free transformations turn into NaN), the `f64` result of the
    /// operation on the leading parts, which says which of ±∞ or NaN it is.
    #[inline(always)]
    fn checked(hi: f64, lo: f64, leading: impl FnOnce() -> f64) -> Self {
        if hi.is_finite() {
            Self { hi, lo }
        } else {
            Self::non_finite(leading())
        }
    }

    #[cold]
    fn non_finite(x: f64) -> Self {
        Self::from_f64(x)
    }
}

impl From<f64> for DoubleDouble {
    fn from(x: f64) -> Self {
        Self::from_f64(x)
    }
}

impl Neg for DoubleDouble {
    type Output = Self;
    fn neg(self) -> Self {
        Self {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Add for DoubleDouble {
    type Output = Self;
    fn add(self, b: Self) -> Self {
        let (s, e) = two_sum(self.hi, b.hi);
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = quick_two_sum(s, e + t);
        let (hi, lo) = quick_two_sum(s, e + f);
        Self::checked(hi, lo, || self.hi + b.hi)
    }
}

impl Sub for DoubleDouble {
    type Output = Self;
    #[allow(clippy::suspicious_arithmetic_impl)]
    fn sub(self, b: Self) -> Self {
        self + (-b)
    }
}

impl Mul for DoubleDouble {
    type Output = Self;
    fn mul(self, b: Self) -> Self {
        let (p, e) = two_prod(self.hi, b.hi);
        let e = e + (self.hi * b.lo + self.lo * b.hi);
        let (hi, lo) = quick_two_sum(p, e);
        Self::checked(hi, lo, || self.hi * b.hi)
    }
}

impl Div for DoubleDouble {
    type Output = Self;
    fn div(self, b: Self) -> Self {
        let q1 = self.hi / b.hi;
        if !q1.is_finite() || b.hi.is_infinite() {
            // Division by zero or by infinity, an infinite or NaN operand, or overflow.
            return Self::from_f64(q1);
        }
        let r = self - b.mul_f64(q1);
        let q2 = r.hi / b.hi;
        let r = r - b.mul_f64(q2);
        let q3 = r.hi / b.hi;
        let (hi, lo) = quick_two_sum(q1, q2);
        Self { hi, lo } + Self::from_f64(q3)
    }
}

impl AddAssign for DoubleDouble {
    fn add_assign(&mut self, b: Self) {
        *self = *self + b;
    }
}

impl SubAssign for DoubleDouble {
    fn sub_assign(&mut self, b: Self) {
        *self = *self - b;
    }
}

impl PartialOrd for DoubleDouble {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        match self.hi.partial_cmp(&other.hi) {
            Some(Ordering::Equal) => self.lo.partial_cmp(&other.lo),
            ordering => ordering,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_third_times_three_is_one_to_double_double_precision() {
        let third = DoubleDouble::ONE / DoubleDouble::from_f64(3.0);
        let back = third * DoubleDouble::from_f64(3.0) - DoubleDouble::ONE;
        assert!(back.to_f64().abs() < 1e-31, "{back:?}");
        // The trailing part carries what f64 loses.
        assert!(third.lo() != 0.0);
    }

    #[test]
    fn square_root_of_two_squares_back() {
        let two = DoubleDouble::from_f64(2.0);
        let r = two.sqrt();
        assert!((r * r - two).to_f64().abs() < 1e-31);
        assert!((r.hi() - std::f64::consts::SQRT_2).abs() == 0.0);
    }

    #[test]
    fn sum_keeps_the_small_addend() {
        let x = DoubleDouble::ONE + DoubleDouble::from_f64(1e-20);
        let y = x - DoubleDouble::ONE;
        assert!((y.to_f64() - 1e-20).abs() < 1e-36);
    }

    #[test]
    fn round_uses_the_trailing_part() {
        let x = DoubleDouble::from_f64(2.5) - DoubleDouble::from_f64(1e-20);
        assert_eq!(x.round().to_f64(), 2.0);
        let y = DoubleDouble::from_f64(2.5) + DoubleDouble::from_f64(1e-20);
        assert_eq!(y.round().to_f64(), 3.0);
        let big = DoubleDouble::sum(1e20, 0.75);
        assert_eq!((big.round() - DoubleDouble::from_f64(1e20)).to_f64(), 1.0);
    }
}
