//! Legendre's elliptic integrals of the first and third kinds in Carlson's symmetric forms
//! (B. C. Carlson, Numer. Algorithms 10 (1995); DLMF §19.25):
//!
//! ```text
//! K(m)         = R_F(0, m', 1)
//! Π(n|m)       = K(m) + (n/3) R_J(0, m', 1, 1 − n)
//! F(φ|m)       = sin φ · R_F(cos²φ, Δ², 1)                       Δ² = cos²φ + m' sin²φ
//! Π(n; φ|m)    = F(φ|m) + (n/3) sin³φ · R_J(cos²φ, Δ², 1, 1 − n sin²φ)
//! ```
//!
//! for `φ ∈ [−π/2, π/2]`; any other amplitude is reduced by `F(φ + π) = F(φ) + 2K` and
//! `Π(n; φ + π|m) = Π(n; φ|m) + 2Π(n|m)`. `Δ² = 1 − m sin²φ` is formed from `m'`, a sum of
//! non-negative terms, so nothing cancels as m → 1.

use super::carlson::{carlson_rf, carlson_rj, EllipticScalar};
use super::parameter::EllipticParameter;
use std::f64::consts::PI;

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
    let reduced = first_kind_from_sines(s, c, (c * c + parameter.complement() * s * s).sqrt());
    if j == 0.0 {
        reduced
    } else {
        2.0 * j * complete_first_kind(parameter.complement()) + reduced
    }
}

/// Incomplete elliptic integral of the third kind
/// `Π(n; φ|m) = ∫₀^φ dθ / ((1 − n sin²θ) √(1 − m sin²θ))`, for `n < 1` and any real `φ`
/// (`Π(n; φ + π|m) = Π(n; φ|m) + 2Π(n|m)`).
pub fn incomplete_third_kind(n: f64, phi: f64, parameter: &EllipticParameter) -> f64 {
    let (j, s, c) = reduce_amplitude(phi);
    let reduced = third_kind_from_sines(n, s, c, (c * c + parameter.complement() * s * s).sqrt());
    if j == 0.0 {
        reduced
    } else {
        2.0 * j * complete_third_kind(n, parameter.complement()) + reduced
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::rigid_body::elliptic::carlson::{carlson_rc, carlson_rd};
    use crate::numeric::rigid_body::elliptic::jacobi::jacobi;
    use crate::numeric::rigid_body::elliptic::test_points::{parameters, samples};
    use crate::numeric::scalar::double_double::DoubleDouble;
    use std::f64::consts::FRAC_PI_2;

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
    fn first_kind_inverts_the_amplitude() {
        for (p, u) in samples() {
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
}
