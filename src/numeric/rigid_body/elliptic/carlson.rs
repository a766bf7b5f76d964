//! Carlson's symmetric elliptic integrals (B. C. Carlson, "Numerical computation of real or
//! complex elliptic integrals", Numer. Algorithms 10 (1995); DLMF §19.16, §19.36):
//!
//! ```text
//! R_F(x,y,z)   = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z))
//! R_J(x,y,z,p) = 3/2 ∫₀^∞ dt / ((t+p) √((t+x)(t+y)(t+z)))
//! R_D(x,y,z)   = R_J(x,y,z,z),   R_C(x,y) = R_F(x,y,y)
//! ```
//!
//! each evaluated by the duplication theorem (`R(x,y,z) = R((x+λ)/4, (y+λ)/4, (z+λ)/4)`,
//! `λ = √x√y + √y√z + √z√x`) until the arguments agree to the precision of the scalar, then
//! a fifth-order Taylor series about their mean. They are generic over [`EllipticScalar`], so
//! the complete integrals are also available in double-double.

use crate::numeric::scalar::double_double::DoubleDouble;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The arithmetic Carlson's duplication algorithm needs.
pub trait EllipticScalar:
    Copy
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The value of an `f64`.
    fn of(x: f64) -> Self;
    /// Square root of a non-negative value.
    fn sqrt(self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// Relative rounding error of the arithmetic.
    fn epsilon() -> f64;
}

impl EllipticScalar for f64 {
    fn of(x: f64) -> Self {
        x
    }
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    fn abs(self) -> Self {
        f64::abs(self)
    }
    fn epsilon() -> f64 {
        f64::EPSILON / 2.0
    }
}

impl EllipticScalar for DoubleDouble {
    fn of(x: f64) -> Self {
        DoubleDouble::from_f64(x)
    }
    fn sqrt(self) -> Self {
        DoubleDouble::sqrt(self)
    }
    fn abs(self) -> Self {
        DoubleDouble::abs(self)
    }
    fn epsilon() -> f64 {
        DoubleDouble::EPSILON
    }
}

fn max_of<T: EllipticScalar>(values: &[T]) -> T {
    values
        .iter()
        .copied()
        .fold(T::of(0.0), |a, b| if b > a { b } else { a })
}

/// One duplication step: the arguments move to `(v + λ)/4` with `λ = Σ √v_i √v_j`.
fn duplicate<T: EllipticScalar, const N: usize>(values: &mut [T; N], roots: &[T; 3]) -> T {
    let lambda = roots[0] * roots[1] + roots[1] * roots[2] + roots[2] * roots[0];
    for v in values.iter_mut() {
        *v = (*v + lambda) * T::of(0.25);
    }
    lambda
}

/// Carlson's `R_F(x, y, z)` for non-negative arguments, at most one of them zero.
pub fn carlson_rf<T: EllipticScalar>(x: T, y: T, z: T) -> T {
    let mut v = [x, y, z, (x + y + z) / T::of(3.0)];
    let a0 = v[3];
    let tolerance = (3.0 * T::epsilon()).powf(-1.0 / 6.0);
    let q = max_of(&[(a0 - x).abs(), (a0 - y).abs(), (a0 - z).abs()]) * T::of(tolerance);
    let mut scale = T::of(1.0);
    while q * scale >= v[3].abs() {
        let roots = [v[0].sqrt(), v[1].sqrt(), v[2].sqrt()];
        duplicate(&mut v, &roots);
        scale = scale * T::of(0.25);
    }
    let a = v[3];
    let xx = (a0 - x) * scale / a;
    let yy = (a0 - y) * scale / a;
    let zz = -(xx + yy);
    let e2 = xx * yy - zz * zz;
    let e3 = xx * yy * zz;
    let series = T::of(1.0) - e2 / T::of(10.0) + e3 / T::of(14.0) + e2 * e2 / T::of(24.0)
        - T::of(3.0) * e2 * e3 / T::of(44.0);
    series / a.sqrt()
}

/// The common closing series of `R_D` and `R_J` (Carlson 1995, eq. 2.7–2.8).
fn rj_series<T: EllipticScalar>(e2: T, e3: T, e4: T, e5: T) -> T {
    T::of(1.0) - T::of(3.0) * e2 / T::of(14.0)
        + e3 / T::of(6.0)
        + T::of(9.0) * e2 * e2 / T::of(88.0)
        - T::of(3.0) * e4 / T::of(22.0)
        - T::of(9.0) * e2 * e3 / T::of(52.0)
        + T::of(3.0) * e5 / T::of(26.0)
}

/// Carlson's `R_D(x, y, z) = R_J(x, y, z, z)` for `x, y >= 0` (not both zero), `z > 0`.
pub fn carlson_rd<T: EllipticScalar>(x: T, y: T, z: T) -> T {
    let mut v = [x, y, z, (x + y + T::of(3.0) * z) / T::of(5.0)];
    let a0 = v[3];
    let tolerance = (T::epsilon() / 4.0).powf(-1.0 / 6.0);
    let q = max_of(&[(a0 - x).abs(), (a0 - y).abs(), (a0 - z).abs()]) * T::of(tolerance);
    let mut scale = T::of(1.0);
    let mut sum = T::of(0.0);
    while q * scale >= v[3].abs() {
        let roots = [v[0].sqrt(), v[1].sqrt(), v[2].sqrt()];
        let lambda = roots[0] * roots[1] + roots[1] * roots[2] + roots[2] * roots[0];
        sum = sum + scale / (roots[2] * (v[2] + lambda));
        duplicate(&mut v, &roots);
        scale = scale * T::of(0.25);
    }
    let a = v[3];
    let xx = (a0 - x) * scale / a;
    let yy = (a0 - y) * scale / a;
    let zz = -(xx + yy) / T::of(3.0);
    let xy = xx * yy;
    let z2 = zz * zz;
    let e2 = xy - T::of(6.0) * z2;
    let e3 = (T::of(3.0) * xy - T::of(8.0) * z2) * zz;
    let e4 = T::of(3.0) * (xy - z2) * z2;
    let e5 = xy * z2 * zz;
    scale * rj_series(e2, e3, e4, e5) / (a * a.sqrt()) + T::of(3.0) * sum
}

/// Carlson's `R_C(x, y) = R_F(x, y, y)` for `x >= 0`, `y > 0`, by its own duplication.
pub fn carlson_rc<T: EllipticScalar>(x: T, y: T) -> T {
    let a0 = (x + y + y) / T::of(3.0);
    let tolerance = (3.0 * T::epsilon()).powf(-1.0 / 8.0);
    let q = (a0 - x).abs() * T::of(tolerance);
    let s0 = y - a0;
    let (mut x, mut y, mut a) = (x, y, a0);
    let mut scale = T::of(1.0);
    while q * scale >= a.abs() {
        let lambda = T::of(2.0) * x.sqrt() * y.sqrt() + y;
        x = (x + lambda) * T::of(0.25);
        y = (y + lambda) * T::of(0.25);
        a = (a + lambda) * T::of(0.25);
        scale = scale * T::of(0.25);
    }
    let s = s0 * scale / a;
    let coefficients = [
        1.0,
        0.0,
        3.0 / 10.0,
        1.0 / 7.0,
        3.0 / 8.0,
        9.0 / 22.0,
        159.0 / 208.0,
        9.0 / 8.0,
    ];
    let series = coefficients
        .iter()
        .rev()
        .fold(T::of(0.0), |acc, &c| acc * s + T::of(c));
    series / a.sqrt()
}

/// Carlson's `R_J(x, y, z, p)` for `x, y, z >= 0` (at most one zero) and `p > 0`.
pub fn carlson_rj<T: EllipticScalar>(x: T, y: T, z: T, p: T) -> T {
    let mut v = [x, y, z, p, (x + y + z + p + p) / T::of(5.0)];
    let a0 = v[4];
    let delta = (p - x) * (p - y) * (p - z);
    let tolerance = (T::epsilon() / 4.0).powf(-1.0 / 6.0);
    let q = max_of(&[
        (a0 - x).abs(),
        (a0 - y).abs(),
        (a0 - z).abs(),
        (a0 - p).abs(),
    ]) * T::of(tolerance);
    let mut scale = T::of(1.0);
    let mut sum = T::of(0.0);
    while q * scale >= v[4].abs() {
        let roots = [v[0].sqrt(), v[1].sqrt(), v[2].sqrt()];
        let root_p = v[3].sqrt();
        let d = (root_p + roots[0]) * (root_p + roots[1]) * (root_p + roots[2]);
        let e = delta * scale * scale * scale / (d * d);
        sum = sum + scale / d * carlson_rc(T::of(1.0), T::of(1.0) + e);
        duplicate(&mut v, &roots);
        scale = scale * T::of(0.25);
    }
    let a = v[4];
    let xx = (a0 - x) * scale / a;
    let yy = (a0 - y) * scale / a;
    let zz = (a0 - z) * scale / a;
    let pp = -(xx + yy + zz) / T::of(2.0);
    let p2 = pp * pp;
    let xyz = xx * yy * zz;
    let e2 = xx * yy + xx * zz + yy * zz - T::of(3.0) * p2;
    let e3 = xyz + T::of(2.0) * e2 * pp + T::of(4.0) * p2 * pp;
    let e4 = (T::of(2.0) * xyz + e2 * pp + T::of(3.0) * p2 * pp) * pp;
    let e5 = xyz * p2;
    scale * rj_series(e2, e3, e4, e5) / (a * a.sqrt()) + T::of(6.0) * sum
}
