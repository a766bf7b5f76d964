//! Elementary functions in double-double arithmetic, accurate to a few units of 2^-106
//! relative (about 1e-31) unless stated otherwise. Each reduces its argument exactly (or
//! to well below 2^-106) and sums a Taylor series in double-double, or takes one Newton
//! step from the `f64` value (which doubles its 53 correct bits):
//!
//! * `exp x = 2^k (1 + s)`: `k = round(x / ln 2)`, `r = x − k ln 2` with ln 2 in three parts
//!   (so `k ln 2` is exact to 2^-150 relative), `s = expm1(r / 512)` by Taylor, then nine
//!   doublings `s ← 2s + s²` (`(1+s)² − 1` without cancellation). [`DoubleDouble::exp_m1`] is
//!   the same `s` when `k = 0`, so it keeps relative accuracy for small `x`.
//! * `ln x = k ln 2 + 2 atanh u`, `x = 2^k m`, `m ∈ [1/√2, √2)`, `u = (m − 1)/(m + 1)`,
//!   `|u| ≤ 0.172`, `atanh u = u + u³/3 + u⁵/5 + …`; [`DoubleDouble::ln_1p`] takes
//!   `u = x/(2 + x)` directly for `|x| < 0.4` (`|u| < 0.25`), so it keeps relative accuracy.
//! * `sin`, `cos`: `k = round(x / (π/2))` (a double-double integer), `r = x − k π/2` with
//!   π/2 in three parts, then the Taylor series of `sin r` and `cos r` for `|r| ≤ π/4` and
//!   the quadrant's signs. The reduction's absolute error is about `2^-106|r| + |x|·2^-160`,
//!   below 2^-100 for `|x| < 2^60 ≈ 1.2e18`. Beyond, the pair falls back to the `f64`
//!   functions of `hi` with the first-order correction for `lo` (`sin hi + lo cos hi`):
//!   finite, but accurate only to about 1e-16. Relative accuracy holds near the zeros of
//!   `sin` and `cos` too.
//! * `atan2(y, x)`: `z₀` = the `f64` `atan2`, then one Newton step on `sin z = y/ρ` (or on
//!   `cos z = x/ρ`, whichever is better conditioned), `ρ = √(x² + y²)`.
//! * `sqrt`: one Newton step (see [`DoubleDouble::sqrt`]); `cbrt` likewise.
//! * `powi`: binary powering; the rounding of a partial power is raised with it, so the
//!   relative error grows like `|n|` roundings, about `(|n| + 2)·2^-105`.
//! * `powf(x, y) = exp(y ln x)`: the absolute error of `y ln x` becomes a relative error, so
//!   the accuracy is about `(1 + |y ln x|)·2^-105` (1e-29 for a result near 1e300).
//! * `sinh`, `cosh`, `tanh`, `asinh`, `acosh`, `atanh`, `asin`, `acos`, `atan`, `exp2`, `log2`,
//!   `log10`, `hypot` are built from the above in forms without cancellation (for example
//!   `sinh x = e(e + 2)/(2(e + 1))` with `e = expm1 x`, `asinh x = ln_1p(x + x²/(1 + √(1 + x²)))`);
//!   each is accurate to a few times the error of the functions it calls, except `exp2`
//!   (the product `x ln 2` is rounded: relative error about `(1 + |x|)·2^-105`).
//!
//! Special values follow `f64`: NaN in gives NaN, `exp(∞) = ∞`, `ln 0 = −∞`, `ln(−1)` NaN,
//! `sin ∞` NaN; overflow gives ±∞ and underflow 0.

use super::double_double::{two_prod, DoubleDouble};
use super::double_double_constants::{FRAC_PI_2_PARTS, LN_2_PARTS};

type Dd = DoubleDouble;

/// Above this `exp` overflows (`ln f64::MAX ≈ 709.78`).
const EXP_OVERFLOW: f64 = 709.79;
/// Below this `exp` underflows to zero (`ln 2^-1075 ≈ −745.13`).
const EXP_UNDERFLOW: f64 = -745.2;
/// A series stops when its term is below this fraction of the sum (2^-110).
const SERIES_TOLERANCE: f64 = 7.7e-34;
/// No series here needs more terms (atanh at |u| = 0.25 needs 27); the bound only makes
/// termination certain.
const MAX_SERIES_TERMS: usize = 64;
/// Beyond this `|x|` the reduction of `sin`, `cos` by three-part π/2 is no longer exact
/// enough (2^60).
const TRIGONOMETRIC_LARGE: f64 = (1u64 << 60) as f64;
/// Beyond this `sinh`, `cosh` drop `e^-|x|` (below 2^-110 relative of `e^|x|`) and `tanh` is ±1.
const HYPERBOLIC_LARGE: f64 = 40.0;
/// Beyond this `asinh` and `acosh` use `ln(2x)` (the next term, `1/(4x²)`, is below 2^-500).
const INVERSE_HYPERBOLIC_LARGE: f64 = 1e150;

/// `2^k` for any `k` an `f64` can scale by in two steps.
fn scale_by_power_of_two(x: Dd, k: i32) -> Dd {
    let half = k / 2;
    let step = |x: Dd, e: i32| {
        let factor = 2f64.powi(e);
        Dd::from_parts(x.hi * factor, x.lo * factor)
    };
    step(step(x, half), k - half)
}

/// The binary exponent `e` of a finite non-zero `f64`: `2^e ≤ |x| < 2^(e+1)`.
fn binary_exponent(x: f64) -> i32 {
    if x.abs() < f64::MIN_POSITIVE {
        return binary_exponent(x * 2f64.powi(64)) - 64;
    }
    ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023
}

/// `x − k·c` for an integer-valued `k` and a constant `c` given in three parts: the two
/// leading products are exact (`two_prod`) and are subtracted one at a time, so the
/// cancellation between `x` and `k·c` costs nothing; the error is about
/// `2^-106·|x − k·c| + |k|·2^-160`.
fn minus_multiple(x: Dd, k: f64, parts: &[f64; 3]) -> Dd {
    let (p0, e0) = two_prod(k, parts[0]);
    let (p1, e1) = two_prod(k, parts[1]);
    x - Dd::from_f64(p0) - Dd::from_f64(p1) - Dd::from_f64(e0) - Dd::from_f64(e1 + k * parts[2])
}

/// `atanh u = u + u³/3 + u⁵/5 + …` for `|u| ≤ 0.25` (at most 27 terms).
fn atanh_series(u: Dd) -> Dd {
    let u2 = u * u;
    let mut power = u;
    let mut sum = u;
    for n in 1..MAX_SERIES_TERMS {
        power = power * u2;
        let term = power / Dd::from_f64((2 * n + 1) as f64);
        sum += term;
        if term.hi.abs() <= SERIES_TOLERANCE * sum.hi.abs() {
            break;
        }
    }
    sum
}

/// `(sin r, cos r)` by Taylor series for `|r| ≤ π/4`.
fn sin_cos_series(r: Dd) -> (Dd, Dd) {
    let r2 = r * r;
    let (mut sin, mut sin_term) = (r, r);
    let (mut cos, mut cos_term) = (Dd::ONE, Dd::ONE);
    for n in 1..MAX_SERIES_TERMS {
        let k = (2 * n) as f64;
        cos_term = -(cos_term * r2) / Dd::from_f64((k - 1.0) * k);
        sin_term = -(sin_term * r2) / Dd::from_f64(k * (k + 1.0));
        cos += cos_term;
        sin += sin_term;
        if sin_term.hi.abs() <= SERIES_TOLERANCE * sin.hi.abs()
            && cos_term.hi.abs() <= SERIES_TOLERANCE * cos.hi.abs()
        {
            break;
        }
    }
    (sin, cos)
}

impl DoubleDouble {
    /// `(k, s)` with `exp x = 2^k (1 + s)` for finite `x` within the `exp` range.
    fn exp_reduced(self) -> (i32, Dd) {
        let k = (self.hi / LN_2_PARTS[0]).round();
        let r = minus_multiple(self, k, &LN_2_PARTS);
        // r/512 is exact; its Taylor series needs about ten terms (|r/512| ≤ 6.8e-4).
        let small = Dd::from_parts(r.hi / 512.0, r.lo / 512.0);
        let mut term = small;
        let mut s = small;
        for n in 2..MAX_SERIES_TERMS {
            term = term * small / Dd::from_f64(n as f64);
            s += term;
            if term.hi.abs() <= SERIES_TOLERANCE * s.hi.abs() {
                break;
            }
        }
        for _ in 0..9 {
            s = Dd::from_parts(2.0 * s.hi, 2.0 * s.lo) + s * s;
        }
        (k as i32, s)
    }

    /// `eˣ`.
    pub fn exp(self) -> Self {
        if self.hi.is_nan() || self.hi > EXP_OVERFLOW || self.hi < EXP_UNDERFLOW {
            return Self::from_f64(self.hi.exp());
        }
        let (k, s) = self.exp_reduced();
        scale_by_power_of_two(Dd::ONE + s, k)
    }

    /// `eˣ − 1`, relatively accurate for small `x`.
    pub fn exp_m1(self) -> Self {
        if self.hi.is_nan() || self.hi > EXP_OVERFLOW || self.hi < EXP_UNDERFLOW {
            return Self::from_f64(self.hi.exp_m1());
        }
        match self.exp_reduced() {
            (0, s) => s,
            // |x| > ln2 / 2: eˣ − 1 has no cancellation.
            (k, s) => scale_by_power_of_two(Dd::ONE + s, k) - Dd::ONE,
        }
    }

    /// Natural logarithm.
    pub fn ln(self) -> Self {
        if self.hi <= 0.0 || self.hi.is_nan() || self.hi.is_infinite() {
            return Self::from_f64(self.hi.ln());
        }
        let mut k = binary_exponent(self.hi);
        let mut m = scale_by_power_of_two(self, -k);
        if m.hi > std::f64::consts::SQRT_2 {
            m = Dd::from_parts(m.hi * 0.5, m.lo * 0.5);
            k += 1;
        }
        let ln_m = atanh_series((m - Dd::ONE) / (m + Dd::ONE)).mul_f64(2.0);
        // k ln 2 + ln m, the terms of like sign or |k ln 2| ≥ 2|ln m|: no cancellation.
        -minus_multiple(-ln_m, k as f64, &LN_2_PARTS)
    }

    /// `ln(1 + x)`, relatively accurate for small `x`.
    pub fn ln_1p(self) -> Self {
        if self.hi.abs() < 0.4 {
            atanh_series(self / (Dd::from_f64(2.0) + self)).mul_f64(2.0)
        } else {
            (Dd::ONE + self).ln()
        }
    }

    /// `(sin x, cos x)`.
    pub fn sin_cos(self) -> (Self, Self) {
        if !self.hi.is_finite() {
            return (Self::from_f64(f64::NAN), Self::from_f64(f64::NAN));
        }
        if self.hi.abs() <= std::f64::consts::FRAC_PI_4 {
            return sin_cos_series(self);
        }
        if self.hi.abs() >= TRIGONOMETRIC_LARGE {
            let (sin, cos) = self.hi.sin_cos();
            return (
                Dd::from_f64(sin) + Dd::from_f64(cos * self.lo),
                Dd::from_f64(cos) - Dd::from_f64(sin * self.lo),
            );
        }
        // k = k_hi + k_lo, both integer-valued f64 (the floor of a double-double is).
        let k = (self * Dd::FRAC_2_PI).round();
        let r = minus_multiple(
            minus_multiple(self, k.hi, &FRAC_PI_2_PARTS),
            k.lo,
            &FRAC_PI_2_PARTS,
        );
        let quadrant = (k.hi.rem_euclid(4.0) + k.lo.rem_euclid(4.0)) as u32 % 4;
        let (sin, cos) = sin_cos_series(r);
        match quadrant {
            0 => (sin, cos),
            1 => (cos, -sin),
            2 => (-sin, -cos),
            _ => (-cos, sin),
        }
    }

    /// `sin x`.
    pub fn sin(self) -> Self {
        self.sin_cos().0
    }

    /// `cos x`.
    pub fn cos(self) -> Self {
        self.sin_cos().1
    }

    /// `tan x = sin x / cos x`.
    pub fn tan(self) -> Self {
        let (sin, cos) = self.sin_cos();
        sin / cos
    }

    /// The angle of the point `(x, y)` = `(other, self)`, in `[−π, π]`.
    pub fn atan2(self, other: Self) -> Self {
        let (y, x) = (self, other);
        if y.hi.is_nan() || x.hi.is_nan() {
            return Self::from_f64(f64::NAN);
        }
        let z0 = y.hi.atan2(x.hi);
        if y.hi == 0.0 || x.hi == 0.0 || y.hi.is_infinite() || x.hi.is_infinite() {
            // The angle is ±0 or a multiple of π/4: take that multiple in double-double.
            return if z0 == 0.0 {
                Self::from_f64(z0)
            } else {
                Dd::FRAC_PI_4.mul_f64((z0 / std::f64::consts::FRAC_PI_4).round())
            };
        }
        // Scale both by the same power of two so x² + y² neither overflows nor underflows.
        let e = binary_exponent(y.hi.abs().max(x.hi.abs()));
        let (y, x) = (scale_by_power_of_two(y, -e), scale_by_power_of_two(x, -e));
        let rho = (x * x + y * y).sqrt();
        let (sin_target, cos_target) = (y / rho, x / rho);
        let z = Dd::from_f64(z0);
        let (sin, cos) = z.sin_cos();
        if cos_target.hi.abs() > sin_target.hi.abs() {
            z + (sin_target - sin) / cos
        } else {
            z - (cos_target - cos) / sin
        }
    }

    /// `atan x`.
    pub fn atan(self) -> Self {
        self.atan2(Dd::ONE)
    }

    /// `asin x` for `|x| ≤ 1` (NaN otherwise), as `atan2(x, √((1 − x)(1 + x)))`.
    pub fn asin(self) -> Self {
        if self.abs() > Dd::ONE {
            return Self::from_f64(f64::NAN);
        }
        self.atan2(((Dd::ONE - self) * (Dd::ONE + self)).sqrt())
    }

    /// `acos x` for `|x| ≤ 1` (NaN otherwise), as `atan2(√((1 − x)(1 + x)), x)`.
    pub fn acos(self) -> Self {
        if self.abs() > Dd::ONE {
            return Self::from_f64(f64::NAN);
        }
        ((Dd::ONE - self) * (Dd::ONE + self)).sqrt().atan2(self)
    }

    /// `xⁿ` by binary powering; `x⁰ = 1`.
    pub fn powi(self, n: i32) -> Self {
        let mut base = self;
        let mut remaining = n.unsigned_abs();
        let mut result = Dd::ONE;
        while remaining > 0 {
            if remaining & 1 == 1 {
                result = result * base;
            }
            remaining >>= 1;
            if remaining > 0 {
                base = base * base;
            }
        }
        if n < 0 {
            Dd::ONE / result
        } else {
            result
        }
    }

    /// `xʸ`: `powi` for an integer `y` that fits `i32`, otherwise `exp(y ln |x|)` with the
    /// sign of an odd integer power; non-finite or zero operands as `f64::powf`.
    pub fn powf(self, y: Self) -> Self {
        let (x, integral) = (self, y.floor() == y);
        if !x.hi.is_finite() || !y.hi.is_finite() || x.hi == 0.0 || y.hi == 0.0 {
            return Self::from_f64(x.hi.powf(y.hi));
        }
        if integral && y.lo == 0.0 && y.hi.abs() <= i32::MAX as f64 {
            return x.powi(y.hi as i32);
        }
        if x.hi > 0.0 {
            return (y * x.ln()).exp();
        }
        if !integral {
            return Self::from_f64(f64::NAN);
        }
        let odd = (y.hi.rem_euclid(2.0) + y.lo.rem_euclid(2.0)) % 2.0 == 1.0;
        let magnitude = (y * (-x).ln()).exp();
        if odd {
            -magnitude
        } else {
            magnitude
        }
    }

    /// Cube root by one Newton step on the `f64` root.
    pub fn cbrt(self) -> Self {
        if self.hi == 0.0 || !self.hi.is_finite() {
            return Self::from_f64(self.hi.cbrt());
        }
        let r = Dd::from_f64(self.hi.cbrt());
        r + (self - r * r * r) / (r * r).mul_f64(3.0)
    }

    /// `√(x² + y²)` without overflow or underflow of the squares.
    pub fn hypot(self, other: Self) -> Self {
        let (x, y) = (self.abs(), other.abs());
        if x.hi.is_infinite() || y.hi.is_infinite() {
            return Self::from_f64(f64::INFINITY);
        }
        if x.hi.is_nan() || y.hi.is_nan() {
            return Self::from_f64(f64::NAN);
        }
        let largest = x.hi.max(y.hi);
        if largest == 0.0 {
            return Dd::ZERO;
        }
        let e = binary_exponent(largest);
        let (x, y) = (scale_by_power_of_two(x, -e), scale_by_power_of_two(y, -e));
        scale_by_power_of_two((x * x + y * y).sqrt(), e)
    }

    /// `sinh x`: `e(e + 2)/(2(e + 1))`, `e = expm1 |x|`, then the sign; `e^|x|/2` for large `|x|`.
    pub fn sinh(self) -> Self {
        let a = self.abs();
        let magnitude = if a.hi > HYPERBOLIC_LARGE {
            (a - Dd::LN_2).exp()
        } else {
            let e = a.exp_m1();
            e * (e + Dd::from_f64(2.0)) / (e + Dd::ONE).mul_f64(2.0)
        };
        if self.hi.is_sign_negative() {
            -magnitude
        } else {
            magnitude
        }
    }

    /// `cosh x = (eˣ + e⁻ˣ)/2`; `e^|x|/2` for large `|x|`.
    pub fn cosh(self) -> Self {
        let a = self.abs();
        if a.hi > HYPERBOLIC_LARGE {
            return (a - Dd::LN_2).exp();
        }
        let e = a.exp();
        (e + Dd::ONE / e).mul_f64(0.5)
    }

    /// `tanh x = e/(e + 2)`, `e = expm1(2x)`; ±1 for `|x| > 40` (exact to 2^-110).
    pub fn tanh(self) -> Self {
        if self.hi.is_nan() {
            return self;
        }
        if self.hi.abs() > HYPERBOLIC_LARGE {
            return Self::from_f64(1f64.copysign(self.hi));
        }
        let e = self.mul_f64(2.0).exp_m1();
        e / (e + Dd::from_f64(2.0))
    }

    /// `asinh x = ln_1p(|x| + x²/(1 + √(1 + x²)))` with the sign of `x`; `ln 2|x|` for huge `|x|`.
    pub fn asinh(self) -> Self {
        let a = self.abs();
        let magnitude = if a.hi > INVERSE_HYPERBOLIC_LARGE || a.hi.is_nan() {
            a.ln() + Dd::LN_2
        } else {
            let square = a * a;
            (a + square / (Dd::ONE + (Dd::ONE + square).sqrt())).ln_1p()
        };
        if self.hi.is_sign_negative() {
            -magnitude
        } else {
            magnitude
        }
    }

    /// `acosh x = ln_1p(t + √(t(t + 2)))`, `t = x − 1`, for `x ≥ 1` (NaN otherwise).
    pub fn acosh(self) -> Self {
        if self.hi.is_nan() || self < Dd::ONE {
            return Self::from_f64(f64::NAN);
        }
        if self.hi > INVERSE_HYPERBOLIC_LARGE {
            return self.ln() + Dd::LN_2;
        }
        let t = self - Dd::ONE;
        (t + (t * (t + Dd::from_f64(2.0))).sqrt()).ln_1p()
    }

    /// `atanh x = ½ ln_1p(2x/(1 − x))` for `|x| ≤ 1` (±∞ at ±1, NaN beyond).
    pub fn atanh(self) -> Self {
        if self.abs() > Dd::ONE || self.hi.is_nan() {
            return Self::from_f64(f64::NAN);
        }
        if self.hi.abs() < 0.2 {
            return atanh_series(self);
        }
        (self.mul_f64(2.0) / (Dd::ONE - self)).ln_1p().mul_f64(0.5)
    }
}
