//! Dual numbers `a + b ε` with `ε² = 0`, a `num_traits::Float` scalar that carries an exact
//! first derivative through any evaluation: `f(a + ε) = f(a) + f'(a) ε`.
//!
//! ```
//! use kinetics::numeric::Dual;
//! use num_traits::Float;
//! let x = Dual::variable(0.5f64);
//! let y = (x * x).sin();                // d/dx sin(x²) = 2x cos(x²)
//! assert!((y.eps - 2.0 * 0.5 * 0.25f64.cos()).abs() < 1e-15);
//! ```

use num_traits::{Float, FromPrimitive, Num, NumCast, One, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::num::FpCategory;
use std::ops::{Add, Div, Mul, Neg, Rem, Sub};

/// A value and its derivative with respect to one chosen input.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dual<T> {
    pub re: T,
    pub eps: T,
}

impl<T: Float> Dual<T> {
    /// A constant: derivative zero.
    pub fn constant(re: T) -> Self {
        Dual { re, eps: T::zero() }
    }

    /// The input being differentiated with respect to: derivative one.
    pub fn variable(re: T) -> Self {
        Dual { re, eps: T::one() }
    }

    /// `f(self)` given `f(re)` and `f'(re)` (the chain rule).
    fn chain(self, value: T, derivative: T) -> Self {
        Dual {
            re: value,
            eps: derivative * self.eps,
        }
    }
}

impl<T: Float> Add for Dual<T> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Dual {
            re: self.re + o.re,
            eps: self.eps + o.eps,
        }
    }
}

impl<T: Float> Sub for Dual<T> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Dual {
            re: self.re - o.re,
            eps: self.eps - o.eps,
        }
    }
}

impl<T: Float> Mul for Dual<T> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Dual {
            re: self.re * o.re,
            eps: self.eps * o.re + self.re * o.eps,
        }
    }
}

impl<T: Float> Div for Dual<T> {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        Dual {
            re: self.re / o.re,
            eps: (self.eps * o.re - self.re * o.eps) / (o.re * o.re),
        }
    }
}

impl<T: Float> Rem for Dual<T> {
    type Output = Self;
    fn rem(self, o: Self) -> Self {
        // x mod y = x - y·trunc(x/y); trunc is piecewise constant.
        let q = (self.re / o.re).trunc();
        Dual {
            re: self.re % o.re,
            eps: self.eps - o.eps * q,
        }
    }
}

impl<T: Float> Neg for Dual<T> {
    type Output = Self;
    fn neg(self) -> Self {
        Dual {
            re: -self.re,
            eps: -self.eps,
        }
    }
}

impl<T: Float> PartialOrd for Dual<T> {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        self.re.partial_cmp(&o.re)
    }
}

impl<T: Float> Zero for Dual<T> {
    fn zero() -> Self {
        Dual::constant(T::zero())
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.eps.is_zero()
    }
}

impl<T: Float> One for Dual<T> {
    fn one() -> Self {
        Dual::constant(T::one())
    }
}

impl<T: Float> Num for Dual<T> {
    type FromStrRadixErr = T::FromStrRadixErr;
    fn from_str_radix(s: &str, radix: u32) -> Result<Self, Self::FromStrRadixErr> {
        T::from_str_radix(s, radix).map(Dual::constant)
    }
}

impl<T: Float> ToPrimitive for Dual<T> {
    fn to_i64(&self) -> Option<i64> {
        self.re.to_i64()
    }
    fn to_u64(&self) -> Option<u64> {
        self.re.to_u64()
    }
    fn to_f64(&self) -> Option<f64> {
        self.re.to_f64()
    }
}

impl<T: Float> NumCast for Dual<T> {
    fn from<N: ToPrimitive>(n: N) -> Option<Self> {
        T::from(n).map(Dual::constant)
    }
}

impl<T: Float> FromPrimitive for Dual<T> {
    fn from_i64(n: i64) -> Option<Self> {
        T::from(n).map(Dual::constant)
    }
    fn from_u64(n: u64) -> Option<Self> {
        T::from(n).map(Dual::constant)
    }
    fn from_f64(n: f64) -> Option<Self> {
        T::from(n).map(Dual::constant)
    }
}

/// Functions that are piecewise constant: derivative zero.
macro_rules! constant_pieces {
    ($($f:ident),*) => {
        $(fn $f(self) -> Self { Dual::constant(self.re.$f()) })*
    };
}

/// Predicates and constants answered by the value part.
macro_rules! on_value {
    ($($f:ident -> $t:ty),*) => {
        $(fn $f(self) -> $t { self.re.$f() })*
    };
}

macro_rules! constants {
    ($($f:ident),*) => {
        $(fn $f() -> Self { Dual::constant(T::$f()) })*
    };
}

impl<T: Float> Float for Dual<T> {
    constants!(
        nan,
        infinity,
        neg_infinity,
        neg_zero,
        min_value,
        min_positive_value,
        max_value,
        epsilon
    );
    constant_pieces!(floor, ceil, round, trunc, signum);
    on_value!(is_nan -> bool, is_infinite -> bool, is_normal -> bool, classify -> FpCategory,
              is_sign_positive -> bool, is_sign_negative -> bool, integer_decode -> (u64, i16, i8));

    fn is_finite(self) -> bool {
        self.re.is_finite() && self.eps.is_finite()
    }
    fn fract(self) -> Self {
        Dual {
            re: self.re.fract(),
            eps: self.eps,
        }
    }
    fn abs(self) -> Self {
        if self.re < T::zero() {
            -self
        } else {
            self
        }
    }
    fn mul_add(self, a: Self, b: Self) -> Self {
        self * a + b
    }
    fn recip(self) -> Self {
        self.chain(self.re.recip(), -(self.re * self.re).recip())
    }
    fn powi(self, n: i32) -> Self {
        let d = if n == 0 {
            T::zero()
        } else {
            T::from(n).unwrap_or_else(T::nan) * self.re.powi(n - 1)
        };
        self.chain(self.re.powi(n), d)
    }
    fn powf(self, n: Self) -> Self {
        let value = self.re.powf(n.re);
        let d_base = if n.re.is_zero() {
            T::zero()
        } else {
            n.re * self.re.powf(n.re - T::one()) * self.eps
        };
        let d_exp = if n.eps.is_zero() {
            T::zero()
        } else {
            value * self.re.ln() * n.eps
        };
        Dual {
            re: value,
            eps: d_base + d_exp,
        }
    }
    fn sqrt(self) -> Self {
        let r = self.re.sqrt();
        self.chain(r, (r + r).recip())
    }
    fn exp(self) -> Self {
        let e = self.re.exp();
        self.chain(e, e)
    }
    fn exp2(self) -> Self {
        let e = self.re.exp2();
        self.chain(e, e * T::from(2.0f64.ln()).unwrap_or_else(T::nan))
    }
    fn ln(self) -> Self {
        self.chain(self.re.ln(), self.re.recip())
    }
    fn log(self, base: Self) -> Self {
        self.ln() / base.ln()
    }
    fn log2(self) -> Self {
        self.ln() / Dual::constant(T::from(2.0f64.ln()).unwrap_or_else(T::nan))
    }
    fn log10(self) -> Self {
        self.ln() / Dual::constant(T::from(10.0f64.ln()).unwrap_or_else(T::nan))
    }
    fn max(self, o: Self) -> Self {
        if self.re >= o.re {
            self
        } else {
            o
        }
    }
    fn min(self, o: Self) -> Self {
        if self.re <= o.re {
            self
        } else {
            o
        }
    }
    fn abs_sub(self, o: Self) -> Self {
        if self.re > o.re {
            self - o
        } else {
            Self::zero()
        }
    }
    fn cbrt(self) -> Self {
        let c = self.re.cbrt();
        self.chain(c, (T::from(3.0).unwrap_or_else(T::nan) * c * c).recip())
    }
    fn hypot(self, o: Self) -> Self {
        (self * self + o * o).sqrt()
    }
    fn sin(self) -> Self {
        self.chain(self.re.sin(), self.re.cos())
    }
    fn cos(self) -> Self {
        self.chain(self.re.cos(), -self.re.sin())
    }
    fn tan(self) -> Self {
        let t = self.re.tan();
        self.chain(t, T::one() + t * t)
    }
    fn asin(self) -> Self {
        self.chain(
            self.re.asin(),
            (T::one() - self.re * self.re).sqrt().recip(),
        )
    }
    fn acos(self) -> Self {
        self.chain(
            self.re.acos(),
            -(T::one() - self.re * self.re).sqrt().recip(),
        )
    }
    fn atan(self) -> Self {
        self.chain(self.re.atan(), (T::one() + self.re * self.re).recip())
    }
    fn atan2(self, o: Self) -> Self {
        let r2 = self.re * self.re + o.re * o.re;
        Dual {
            re: self.re.atan2(o.re),
            eps: (o.re * self.eps - self.re * o.eps) / r2,
        }
    }
    fn sin_cos(self) -> (Self, Self) {
        (self.sin(), self.cos())
    }
    fn exp_m1(self) -> Self {
        self.chain(self.re.exp_m1(), self.re.exp())
    }
    fn ln_1p(self) -> Self {
        self.chain(self.re.ln_1p(), (T::one() + self.re).recip())
    }
    fn sinh(self) -> Self {
        self.chain(self.re.sinh(), self.re.cosh())
    }
    fn cosh(self) -> Self {
        self.chain(self.re.cosh(), self.re.sinh())
    }
    fn tanh(self) -> Self {
        let t = self.re.tanh();
        self.chain(t, T::one() - t * t)
    }
    fn asinh(self) -> Self {
        self.chain(
            self.re.asinh(),
            (self.re * self.re + T::one()).sqrt().recip(),
        )
    }
    fn acosh(self) -> Self {
        self.chain(
            self.re.acosh(),
            (self.re * self.re - T::one()).sqrt().recip(),
        )
    }
    fn atanh(self) -> Self {
        self.chain(self.re.atanh(), (T::one() - self.re * self.re).recip())
    }
}
