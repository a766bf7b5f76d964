//! The Jacobi elliptic functions `sn, cn, dn` and the amplitude `am` by the descending Landen
//! transformation (arithmetic–geometric mean, A&S 16.4):
//!
//! ```text
//! a₀ = 1, b₀ = √m', c₀ = √m;   aₙ₊₁ = (aₙ + bₙ)/2, bₙ₊₁ = √(aₙbₙ), cₙ₊₁ = (aₙ − bₙ)/2
//! φ_N = 2^N a_N u,   φₙ₋₁ = (φₙ + asin((cₙ/aₙ) sin φₙ))/2
//! sn = sin φ₀,   cn = cos φ₀,   dn = √(cn² + m' sn²)
//! ```
//!
//! The argument is first reduced to `[0, K]` with the quarter-period `K = π/(2 a_N)` from the
//! same mean, and on `(K/2, K]` the reflection `sn(u) = cn(v)/dn(v)`, `cn(u) = √m' sn(v)/dn(v)`,
//! `dn(u) = √m'/dn(v)`, `v = K − u`, keeps cn and dn accurate to their last bits where they are
//! small. (Where both branches meet, at u ≈ K/2 with cn ≈ dn ≈ m'^{1/4}, their relative error
//! can reach ε/m'^{1/4} as m → 1; the absolute error stays a few ulps.)

use super::parameter::EllipticParameter;
use std::f64::consts::{FRAC_PI_2, PI};

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
        chain.b[0] = parameter.complement().sqrt();
        chain.c[0] = parameter.m().sqrt();
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
    let mc = parameter.complement();
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::rigid_body::elliptic::legendre_integrals::{
        complete_first_kind, incomplete_first_kind,
    };
    use crate::numeric::rigid_body::elliptic::test_points::{parameters, samples};

    #[test]
    fn pythagorean_identities_hold() {
        for (p, u) in samples() {
            let f = jacobi(u, &p);
            assert!((f.sn * f.sn + f.cn * f.cn - 1.0).abs() < 4.0 * f64::EPSILON);
            let d = f.dn * f.dn + p.m() * f.sn * f.sn - 1.0;
            assert!(d.abs() < 4.0 * f64::EPSILON, "m={} u={u}: {d}", p.m());
            assert!((f.am.sin() - f.sn).abs() < 4.0 * f64::EPSILON * (1.0 + u.abs()));
        }
    }

    #[test]
    fn derivatives_match_central_differences() {
        // d sn/du = cn dn, d cn/du = −sn dn, d dn/du = −m sn cn, d am/du = dn.
        let h = 1e-5;
        for (p, u) in samples() {
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
}
