//! Jacobi elliptic functions and Legendre's elliptic integrals through Carlson's symmetric
//! forms.
//!
//! Integrals (B. C. Carlson, "Numerical computation of real or complex elliptic integrals",
//! Numer. Algorithms 10 (1995); DLMF §19.25, §19.36):
//!
//! ```text
//! R_F(x,y,z)   = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z))
//! R_J(x,y,z,p) = 3/2 ∫₀^∞ dt / ((t+p) √((t+x)(t+y)(t+z)))
//! K(m)         = R_F(0, m', 1)
//! F(φ|m)       = sin φ · R_F(cos²φ, Δ², 1)                       Δ² = cos²φ + m' sin²φ
//! Π(n; φ|m)    = F(φ|m) + (n/3) sin³φ · R_J(cos²φ, Δ², 1, 1 − n sin²φ)
//! ```
//!
//! each evaluated by the duplication theorem (`R(x,y,z) = R((x+λ)/4, (y+λ)/4, (z+λ)/4)`,
//! `λ = √x√y + √y√z + √z√x`) until the arguments agree, then a fifth-order Taylor series.
//! `Δ² = 1 − m sin²φ` is formed as `cos²φ + m' sin²φ`, a sum of non-negative terms, so the
//! parameter is carried as the pair (m, m' = 1 − m) and nothing cancels as m → 1. The
//! symmetric forms are generic over [`EllipticScalar`] so the complete integrals are also
//! available in double-double precision.
//!
//! Jacobi functions use the descending Landen transformation (arithmetic–geometric mean,
//! A&S 16.4): `φ_N = 2^N a_N u`, `φ_{n−1} = (φ_n + asin((c_n/a_n) sin φ_n))/2`,
//! `sn = sin φ₀`, `cn = cos φ₀`, `dn = √(cn² + m' sn²)`. The argument is first reduced to
//! `[0, K]` with the quarter-period `K = π/(2 a_N)` from the same mean, and on `(K/2, K]`
//! the reflection `sn(u) = cn(v)/dn(v)`, `cn(u) = √m' sn(v)/dn(v)`, `dn(u) = √m'/dn(v)`,
//! `v = K − u`, keeps cn and dn accurate to their last bits where they are small. (Where
//! both branches meet, at u ≈ K/2 with cn ≈ dn ≈ m'^{1/4}, their relative error can reach
//! ε/m'^{1/4} as m → 1; the absolute error stays a few ulps.)

use crate::numeric::error::NumericError;
use crate::numeric::scalar::double_double::DoubleDouble;
use std::f64::consts::{FRAC_PI_2, PI};
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

/// The parameter `m = k²` of the elliptic functions with its complement `m' = 1 − m`,
/// each known to full relative precision.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticParameter {
    m: f64,
    mc: f64,
}

impl EllipticParameter {
    /// The parameter `m` in `[0, 1]`.
    pub fn new(m: f64) -> Result<Self, NumericError> {
        Self::check(m, "parameter m")?;
        Ok(Self { m, mc: 1.0 - m })
    }

    /// The parameter given by its complement `m' = 1 − m` in `[0, 1]` (use this when m is
    /// close to 1: `m'` then keeps its digits).
    pub fn from_complement(mc: f64) -> Result<Self, NumericError> {
        Self::check(mc, "complementary parameter m'")?;
        Ok(Self { m: 1.0 - mc, mc })
    }

    fn check(value: f64, what: &str) -> Result<(), NumericError> {
        if value.is_finite() && (0.0..=1.0).contains(&value) {
            Ok(())
        } else {
            Err(NumericError::InvalidInput {
                what: what.to_string(),
                reason: format!("{value} is not in [0, 1]"),
            })
        }
    }

    /// `m`.
    pub fn m(&self) -> f64 {
        self.m
    }

    /// `m' = 1 − m`.
    pub fn complement(&self) -> f64 {
        self.mc
    }
}

/// Complete elliptic integral of the first kind `K(m) = R_F(0, m', 1)` in any scalar
/// (`m'` given directly); infinite at `m' = 0`.
pub fn complete_first_kind<T: EllipticScalar>(mc: T) -> T {
    if mc == T::of(0.0) {
        return T::of(f64::INFINITY);
    }
    carlson_rf(T::of(0.0), mc, T::of(1.0))
}

/// Complete elliptic integral of the third kind
/// `Π(n|m) = K(m) + (n/3) R_J(0, m', 1, 1 − n)`, for `n < 1` and `m' > 0`.
pub fn complete_third_kind<T: EllipticScalar>(n: T, mc: T) -> T {
    let one = T::of(1.0);
    complete_first_kind(mc) + n / T::of(3.0) * carlson_rj(T::of(0.0), mc, one, one - n)
}

/// The Jacobi elliptic functions of one argument, with the amplitude `am(u)` (`sn = sin am`,
/// `cn = cos am`, `d am/du = dn`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jacobi {
    pub sn: f64,
    pub cn: f64,
    pub dn: f64,
    pub am: f64,
}

/// The quarter-period `K` and the Landen chain `(a_n, b_n, c_n)` of the arithmetic–geometric
/// mean of `1` and `√m'` (`a_n² − c_n² = b_n²`).
struct LandenChain {
    a: [f64; 32],
    b: [f64; 32],
    c: [f64; 32],
    len: usize,
}

impl LandenChain {
    fn new(parameter: &EllipticParameter) -> Self {
        let mut chain = LandenChain {
            a: [1.0; 32],
            b: [0.0; 32],
            c: [0.0; 32],
            len: 1,
        };
        chain.b[0] = parameter.mc.sqrt();
        chain.c[0] = parameter.m.sqrt();
        while chain.c[chain.len - 1] > f64::EPSILON * chain.a[chain.len - 1] && chain.len < 32 {
            let (a, b) = (chain.a[chain.len - 1], chain.b[chain.len - 1]);
            chain.a[chain.len] = (a + b) / 2.0;
            chain.b[chain.len] = (a * b).sqrt();
            chain.c[chain.len] = (a - b) / 2.0;
            chain.len += 1;
        }
        chain
    }

    fn quarter_period(&self) -> f64 {
        FRAC_PI_2 / self.a[self.len - 1]
    }

    /// `(sn, cn)` of `u` by the backward Landen recursion. The step
    /// `asin(r sin φ)`, `r = c_n/a_n`, is taken as `atan2(r sin φ, √(cos²φ + (b_n/a_n)² sin²φ))`:
    /// `1 − r² = (b_n/a_n)²` exactly, so nothing cancels when r is close to 1 (m → 1).
    fn sn_cn(&self, u: f64) -> (f64, f64) {
        let last = self.len - 1;
        let mut phi = (2.0f64).powi(last as i32) * self.a[last] * u;
        for n in (1..=last).rev() {
            let (s, c) = phi.sin_cos();
            let (r, rc) = (self.c[n] / self.a[n], self.b[n] / self.a[n]);
            let step = (r * s).atan2((c * c + rc * rc * s * s).sqrt());
            phi = (phi + step) / 2.0;
        }
        phi.sin_cos()
    }
}

/// `sn, cn, dn, am` of `u` with parameter `m`; the functions have period `4K` (sn, cn) and
/// `2K` (dn) and `am(u + 2K) = am(u) + π`. At `m' = 0` they are `tanh, sech, sech, gd`.
pub fn jacobi(u: f64, parameter: &EllipticParameter) -> Jacobi {
    let mc = parameter.mc;
    if mc == 0.0 {
        let sech = 1.0 / u.cosh();
        let tanh = u.tanh();
        return Jacobi {
            sn: tanh,
            cn: sech,
            dn: sech,
            am: tanh.atan2(sech),
        };
    }
    let chain = LandenChain::new(parameter);
    let k = chain.quarter_period();
    // u = 2K·j + r, r in [−K, K]: sn, cn change sign with odd j, am gains jπ.
    let j = (u / (2.0 * k)).round();
    let r = u - 2.0 * k * j;
    let parity = if j.rem_euclid(2.0) == 0.0 { 1.0 } else { -1.0 };
    let (sign, v) = (r.signum(), r.abs().min(k));
    let (sn, cn, dn) = if v <= k / 2.0 {
        let (sn, cn) = chain.sn_cn(v);
        (sn, cn, (cn * cn + mc * sn * sn).sqrt())
    } else {
        let (sn_w, cn_w) = chain.sn_cn(k - v);
        let dn_w = (cn_w * cn_w + mc * sn_w * sn_w).sqrt();
        let root_mc = mc.sqrt();
        (cn_w / dn_w, root_mc * sn_w / dn_w, root_mc / dn_w)
    };
    Jacobi {
        sn: parity * sign * sn,
        cn: parity * cn,
        dn,
        am: j * PI + sign * sn.atan2(cn),
    }
}

/// Splits `φ = jπ + φ_r` with `φ_r ∈ [−π/2, π/2]`, returning `(j, sin φ_r, cos φ_r)`.
fn reduce_amplitude(phi: f64) -> (f64, f64, f64) {
    let j = (phi / PI).round();
    let (s, c) = (phi - j * PI).sin_cos();
    (j, s, c)
}

/// `F(φ|m) = sin φ · R_F(cos²φ, Δ², 1)` for `φ ∈ [−π/2, π/2]` given by `sin φ`, `|cos φ|` and
/// `Δ = √(1 − m sin²φ)`. At `φ = am u`, `|u| <= K`, these are `sn u, cn u, dn u`: the
/// integral then follows u without the loss that recovering φ near ±π/2 would cost when
/// m' is small (F has slope 1/Δ in φ but 1 in u).
pub fn first_kind_from_sines(sin: f64, cos: f64, delta: f64) -> f64 {
    sin * carlson_rf(cos * cos, delta * delta, 1.0)
}

/// `Π(n; φ|m) = F(φ|m) + (n/3) sin³φ R_J(cos²φ, Δ², 1, 1 − n sin²φ)` for `n < 1` and
/// `φ ∈ [−π/2, π/2]`, from the same three numbers as [`first_kind_from_sines`].
pub fn third_kind_from_sines(n: f64, sin: f64, cos: f64, delta: f64) -> f64 {
    let (c2, d2) = (cos * cos, delta * delta);
    sin * carlson_rf(c2, d2, 1.0)
        + n / 3.0 * sin * sin * sin * carlson_rj(c2, d2, 1.0, 1.0 - n * sin * sin)
}

/// Incomplete elliptic integral of the first kind `F(φ|m) = ∫₀^φ dθ/√(1 − m sin²θ)`, for any
/// real `φ` (`F(φ + π) = F(φ) + 2K`).
pub fn incomplete_first_kind(phi: f64, parameter: &EllipticParameter) -> f64 {
    let (j, s, c) = reduce_amplitude(phi);
    let reduced = first_kind_from_sines(s, c, (c * c + parameter.mc * s * s).sqrt());
    if j == 0.0 {
        reduced
    } else {
        2.0 * j * complete_first_kind(parameter.mc) + reduced
    }
}

/// Incomplete elliptic integral of the third kind
/// `Π(n; φ|m) = ∫₀^φ dθ / ((1 − n sin²θ) √(1 − m sin²θ))`, for `n < 1` and any real `φ`
/// (`Π(n; φ + π|m) = Π(n; φ|m) + 2Π(n|m)`).
pub fn incomplete_third_kind(n: f64, phi: f64, parameter: &EllipticParameter) -> f64 {
    let (j, s, c) = reduce_amplitude(phi);
    let reduced = third_kind_from_sines(n, s, c, (c * c + parameter.mc * s * s).sqrt());
    if j == 0.0 {
        reduced
    } else {
        2.0 * j * complete_third_kind(n, parameter.mc) + reduced
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parameters() -> Vec<EllipticParameter> {
        let mut list: Vec<_> = [0.0, 1e-9, 0.1, 0.5, 0.9, 0.999]
            .iter()
            .map(|&m| EllipticParameter::new(m).unwrap())
            .collect();
        list.extend(
            [1e-6, 1e-12, 1e-300]
                .iter()
                .map(|&mc| EllipticParameter::from_complement(mc).unwrap()),
        );
        list
    }

    fn arguments(k: f64) -> Vec<f64> {
        let mut list = vec![0.0, 0.3, -0.7, 1.3, 2.9, -7.5, 40.0];
        list.extend([0.5 * k, k, 1.5 * k, 3.0 * k, -0.9 * k]);
        list
    }

    #[test]
    fn special_values_of_the_complete_integrals() {
        assert!((complete_first_kind(1.0) - FRAC_PI_2).abs() <= 2.0 * f64::EPSILON);
        // K(1/2) = Γ(1/4)² / (4√π).
        let gamma_quarter = 3.625_609_908_221_908_f64;
        let k_half = gamma_quarter * gamma_quarter / (4.0 * PI.sqrt());
        assert!((complete_first_kind(0.5) - k_half).abs() < 4.0 * f64::EPSILON);
        // K(m) → ln(4/√m') as m' → 0.
        let mc = 1e-300_f64;
        let k = complete_first_kind(mc);
        assert!((k - (4.0 / mc.sqrt()).ln()).abs() < 1e-13 * k);
        // Π(0|m) = K(m) and Π(n|0) = π/(2√(1−n)).
        assert!((complete_third_kind(0.0, 0.3) - complete_first_kind(0.3)).abs() < 1e-15);
        let n = -3.0;
        assert!((complete_third_kind(n, 1.0) - FRAC_PI_2 / (1.0 - n).sqrt()).abs() < 1e-15);
        // R_C(0, 1/4) = π and R_D(0, 2, 1) = 3 Γ(3/4)² / √(2π).
        assert!((carlson_rc(0.0, 0.25) - PI).abs() < 4e-16);
        let gamma_three_quarters = 1.225_416_702_465_177_6_f64;
        let expected = 3.0 * gamma_three_quarters.powi(2) / (2.0 * PI).sqrt();
        assert!((carlson_rd(0.0, 2.0, 1.0) - expected).abs() < 1e-15);
    }

    #[test]
    fn double_double_complete_integral_agrees_with_the_legendre_relation() {
        // Legendre: E K' + E' K − K K' = π/2 at m = 1/2 reads 2EK − K² = π/2 with
        // E = R_F − (m/3) R_D(0, m', 1); checked to double-double precision.
        let half = DoubleDouble::from_f64(0.5);
        let k = complete_first_kind(half);
        let rd = carlson_rd(DoubleDouble::ZERO, half, DoubleDouble::ONE);
        let e = k - half * rd / DoubleDouble::from_f64(3.0);
        let lhs = DoubleDouble::from_f64(2.0) * e * k - k * k;
        let rhs = DoubleDouble::PI * half;
        assert!((lhs - rhs).abs().to_f64() < 1e-30, "{:?}", lhs - rhs);
    }

    #[test]
    fn pythagorean_identities_hold() {
        for p in parameters() {
            let k = complete_first_kind(p.complement());
            for u in arguments(k.min(30.0)) {
                let f = jacobi(u, &p);
                assert!((f.sn * f.sn + f.cn * f.cn - 1.0).abs() < 4.0 * f64::EPSILON);
                let d = f.dn * f.dn + p.m() * f.sn * f.sn - 1.0;
                assert!(d.abs() < 4.0 * f64::EPSILON, "m={} u={u}: {d}", p.m());
                assert!((f.am.sin() - f.sn).abs() < 4.0 * f64::EPSILON * (1.0 + u.abs()));
            }
        }
    }

    #[test]
    fn derivatives_match_central_differences() {
        // d sn/du = cn dn, d cn/du = −sn dn, d dn/du = −m sn cn, d am/du = dn.
        let h = 1e-5;
        for p in parameters() {
            let k = complete_first_kind(p.complement());
            for u in arguments(k.min(30.0)) {
                let (a, b, f) = (jacobi(u + h, &p), jacobi(u - h, &p), jacobi(u, &p));
                let d = |x: f64, y: f64| (x - y) / (2.0 * h);
                let tol = 1e-9;
                assert!(
                    (d(a.sn, b.sn) - f.cn * f.dn).abs() < tol,
                    "m={} u={u}",
                    p.m()
                );
                assert!(
                    (d(a.cn, b.cn) + f.sn * f.dn).abs() < tol,
                    "m={} u={u} {} {}",
                    p.m(),
                    d(a.cn, b.cn),
                    -f.sn * f.dn
                );
                assert!((d(a.dn, b.dn) + p.m() * f.sn * f.cn).abs() < tol);
                assert!((d(a.am, b.am) - f.dn).abs() < tol);
            }
        }
    }

    #[test]
    fn first_kind_inverts_the_amplitude() {
        for p in parameters() {
            let k = complete_first_kind(p.complement());
            for u in arguments(k.min(30.0)) {
                // F has slope 1/dn at am(u): a rounding of am is magnified by 1/dn.
                let f = jacobi(u, &p);
                if f.dn < 1e-6 {
                    // am is within rounding of ±π/2 and F is not resolved there.
                    continue;
                }
                let back = incomplete_first_kind(f.am, &p);
                let tol = 8.0 * f64::EPSILON * (u.abs() + f.am.abs() / f.dn).max(1.0);
                assert!((back - u).abs() < tol, "m={} u={u} back={back}", p.m());
            }
        }
    }

    #[test]
    fn quarter_period_is_where_sn_reaches_one() {
        for p in parameters().into_iter().filter(|p| p.complement() > 0.0) {
            let k = complete_first_kind(p.complement());
            let f = jacobi(k, &p);
            assert!((f.sn - 1.0).abs() < 2.0 * f64::EPSILON);
            assert!(f.cn.abs() < 1e-15);
            assert!((f.dn - p.complement().sqrt()).abs() < 4.0 * f64::EPSILON * f.dn);
            // fl(π/2) misses π/2 by δ = cos(fl(π/2)) ≈ 6e-17, and F has slope 1/√m' there.
            if p.complement() > 1e-20 {
                let f_quarter = incomplete_first_kind(FRAC_PI_2, &p);
                let miss = FRAC_PI_2.cos() / p.complement().sqrt();
                assert!((f_quarter - k).abs() < 4.0 * f64::EPSILON * k + miss);
            }
        }
    }

    #[test]
    fn third_kind_derivative_holds_across_the_reduction_of_the_amplitude() {
        // dΠ/dφ = 1 / ((1 − n sin²φ) √(1 − m sin²φ)); the five-point difference at φ = π/2
        // straddles the switch from Π(φ_r) to 2Π(n|m) + Π(φ_r − π).
        let slope = |n: f64, phi: f64, p: &EllipticParameter| {
            // The integrand varies on the scale min(√m', √(1−n), 1/√(1−n)).
            let q = (1.0 - n).sqrt();
            let h = 5e-3 * p.complement().sqrt().min(q).min(1.0 / q);
            let f = |x: f64| incomplete_third_kind(n, x, p);
            (8.0 * (f(phi + h) - f(phi - h)) - (f(phi + 2.0 * h) - f(phi - 2.0 * h))) / (12.0 * h)
        };
        for p in parameters().into_iter().filter(|p| p.complement() > 1e-7) {
            for n in [-40.0, -1.5, -1e-3, 0.0, 0.4, 0.9] {
                for phi in [0.0, 0.4, 1.2, FRAC_PI_2, 2.0, -4.0, 3.0 * FRAC_PI_2] {
                    let d = slope(n, phi, &p);
                    let s2 = phi.sin().powi(2);
                    let exact = 1.0 / ((1.0 - n * s2) * (1.0 - p.m() * s2).sqrt());
                    assert!(
                        (d - exact).abs() < 1e-8 * exact,
                        "m={} n={n} phi={phi}: {d} vs {exact}",
                        p.m()
                    );
                }
            }
        }
    }

    #[test]
    fn integrals_from_jacobi_functions_follow_the_argument_near_the_quarter_period() {
        // m' = 1e-18: near u = K, am(u) is within one rounding of π/2 while F has slope
        // 1/√m' = 1e9 in φ; from (sn, cn, dn) the integral still returns u, and the
        // third-kind integral matches its derivative 1/(1 − n sn²) in u.
        let p = EllipticParameter::from_complement(1e-18).unwrap();
        let k = complete_first_kind(p.complement());
        let n = -1.5;
        let at = |u: f64| {
            let f = jacobi(u, &p);
            (
                first_kind_from_sines(f.sn, f.cn, f.dn),
                third_kind_from_sines(n, f.sn, f.cn, f.dn),
                f,
            )
        };
        // Near K/2, cn ≈ dn ≈ m'^{1/4} carry a relative error up to ε/m'^{1/4}.
        let tol = 8.0 * f64::EPSILON * k + 4.0 * f64::EPSILON / p.complement().powf(0.25);
        for u in [0.5 * k, k - 2.0, k - 1e-3, k] {
            let (first, third, f) = at(u);
            assert!((first - u).abs() < tol, "u={u}: {first}");
            let h = 1e-4;
            let slope = (at(u - h).1 - at(u - 2.0 * h).1) / h;
            let mid = jacobi(u - 1.5 * h, &p);
            let expected = 1.0 / (1.0 - n * mid.sn * mid.sn);
            assert!(
                (slope - expected).abs() < 1e-7,
                "u={u}: {slope} vs {expected}"
            );
            assert!(third.is_finite() && f.dn > 0.0);
        }
    }

    #[test]
    fn out_of_range_parameter_is_an_error() {
        assert!(EllipticParameter::new(1.5).is_err());
        assert!(EllipticParameter::new(f64::NAN).is_err());
        assert!(EllipticParameter::from_complement(-1e-3).is_err());
    }
}
