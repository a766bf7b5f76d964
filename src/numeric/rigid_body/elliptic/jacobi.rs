//! The Jacobi elliptic functions `sn, cn, dn` and the amplitude `am`, set up once for a
//! parameter ([`JacobiFunctions`]) and evaluated at many arguments.
//!
//! The argument is first reduced to `[0, K]` (`sn, cn` change sign over each half period
//! `2K`), and on `(K/2, K]` measured from `K` (`v = K − u`), so that cn and dn keep their last
//! bits where they are small. Then, for a nome `q = exp(−πK'/K)` up to 0.2 (m up to about
//! 0.96), the theta series of `theta.rs`: a sine and a cosine, and five or fewer terms.
//! Closer to m = 1 the descending Landen transformation (arithmetic–geometric mean, A&S 16.4):
//!
//! ```text
//! a₀ = 1, b₀ = √m', c₀ = √m;   aₙ₊₁ = (aₙ + bₙ)/2, bₙ₊₁ = √(aₙbₙ), cₙ₊₁ = (aₙ − bₙ)/2
//! φ_N = 2^N a_N u,   φₙ₋₁ = (φₙ + asin((cₙ/aₙ) sin φₙ))/2
//! sn = sin φ₀,   cn = cos φ₀,   dn = √(cn² + m' sn²)
//! ```
//!
//! with the reflection `sn(u) = cn(v)/dn(v)`, `cn(u) = √m' sn(v)/dn(v)`, `dn(u) = √m'/dn(v)`
//! on `(K/2, K]`. `K = π/(2 a_N)` and `K'` come from the same mean, of `1, √m'` and of `1, √m`.
//! (Where both branches of the Landen path meet, at u ≈ K/2 with cn ≈ dn ≈ m'^{1/4}, their
//! relative error can reach ε/m'^{1/4} as m → 1; the absolute error stays a few ulps.)

use super::parameter::EllipticParameter;
use super::theta::{ThetaSeries, MAX_NOME};
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
#[derive(Debug, Clone)]
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

/// The Jacobi functions of one parameter, set up once: the quarter period `K` and how the
/// reduced argument is evaluated.
#[derive(Debug, Clone)]
pub struct JacobiFunctions {
    mc: f64,
    quarter_period: f64,
    evaluation: Evaluation,
}

/// The theta series of the nome where it is small enough, else the Landen chain.
#[derive(Debug, Clone)]
enum Evaluation {
    Theta(ThetaSeries),
    /// Boxed: 32 levels of the mean, five times the series' size.
    Landen(Box<LandenChain>),
}

impl JacobiFunctions {
    /// The functions of parameter `m`.
    pub fn new(parameter: &EllipticParameter) -> JacobiFunctions {
        let mc = parameter.complement();
        let chain = LandenChain::new(parameter);
        let quarter_period = chain.quarter_period();
        // K' = K(m'), from the mean of 1 and √m; q = exp(−πK'/K), 0 at m = 0.
        let nome = EllipticParameter::from_complement(parameter.m())
            .ok()
            .map(|complementary| LandenChain::new(&complementary).quarter_period())
            .map(|k_prime| (-PI * k_prime / quarter_period).exp())
            .filter(|q| mc > 0.0 && *q <= MAX_NOME);
        let evaluation = match nome {
            Some(q) => Evaluation::Theta(ThetaSeries::new(q)),
            None => Evaluation::Landen(Box::new(chain)),
        };
        JacobiFunctions {
            mc,
            quarter_period,
            evaluation,
        }
    }

    /// `sn, cn, dn, am` of `u`; the functions have period `4K` (sn, cn) and `2K` (dn) and
    /// `am(u + 2K) = am(u) + π`. At `m' = 0` they are `tanh, sech, sech, gd`.
    pub fn at(&self, u: f64) -> Jacobi {
        let (sn, cn, dn, half_periods) = self.reduced(u);
        // sn and cn of the reduced argument, signs restored: its amplitude is in [−π/2, π/2].
        let parity = half_period_sign(half_periods);
        Jacobi {
            sn,
            cn,
            dn,
            am: half_periods * PI + (parity * sn).atan2(parity * cn),
        }
    }

    /// `(sn, cn, dn)` of `u`, without the amplitude (one arctangent less).
    pub fn sn_cn_dn(&self, u: f64) -> (f64, f64, f64) {
        let (sn, cn, dn, _) = self.reduced(u);
        (sn, cn, dn)
    }

    /// `sn, cn, dn` of `u` and the number `j` of half periods `2K` taken off it.
    fn reduced(&self, u: f64) -> (f64, f64, f64, f64) {
        if self.mc == 0.0 {
            let sech = 1.0 / u.cosh();
            return (u.tanh(), sech, sech, 0.0);
        }
        let k = self.quarter_period;
        // u = 2K·j + r, r in [−K, K]: sn, cn change sign with odd j.
        let j = (u / (2.0 * k)).round();
        let r = u - 2.0 * k * j;
        let parity = half_period_sign(j);
        let (sign, v) = (r.signum(), r.abs().min(k));
        let (sn, cn, dn) = match &self.evaluation {
            Evaluation::Theta(theta) => {
                // z = πv/(2K) in [0, π/2], from the nearer end.
                let (s, c) = if v <= k / 2.0 {
                    (FRAC_PI_2 * v / k).sin_cos()
                } else {
                    let (s, c) = (FRAC_PI_2 * (k - v) / k).sin_cos();
                    (c, s)
                };
                theta.sn_cn_dn(s, c, self.mc)
            }
            Evaluation::Landen(chain) if v <= k / 2.0 => {
                let (sn, cn) = chain.sn_cn(v);
                (sn, cn, (cn * cn + self.mc * sn * sn).sqrt())
            }
            Evaluation::Landen(chain) => {
                let (sn_w, cn_w) = chain.sn_cn(k - v);
                let dn_w = (cn_w * cn_w + self.mc * sn_w * sn_w).sqrt();
                let root_mc = self.mc.sqrt();
                (cn_w / dn_w, root_mc * sn_w / dn_w, root_mc / dn_w)
            }
        };
        (parity * sign * sn, parity * cn, dn, j)
    }
}

/// `(−1)ʲ` for a whole number of half periods `j`: the sign sn and cn take on over them (an
/// integer's parity, not `rem_euclid`, which costs a division in software).
pub fn half_period_sign(j: f64) -> f64 {
    if (j as i64) % 2 == 0 {
        1.0
    } else {
        -1.0
    }
}

/// `sn, cn, dn, am` of `u` with parameter `m` (one argument; [`JacobiFunctions`] sets up
/// once for many).
pub fn jacobi(u: f64, parameter: &EllipticParameter) -> Jacobi {
    JacobiFunctions::new(parameter).at(u)
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

    /// Against mpmath's `ellipfun` at 30 digits (at the very doubles given), where the theta
    /// series serve (q from 0.007 to 0.18): within 1e-15 from 0 to past K, on both sides of
    /// K/2. (Farther out the reduction by 2K in doubles adds an ulp of K per half period,
    /// 1.1e-15 at u = −7.5, m = 0.5; the torque-free motion reduces in double-double.)
    #[test]
    fn agree_with_mpmath_to_1e15() {
        // mpmath's digits as printed (√½ among them, at u = K for m = ½).
        #[allow(clippy::excessive_precision, clippy::approx_constant)]
        let cases: [(f64, f64, [f64; 3]); 28] = [
            (
                0.1,
                0.3,
                [
                    0.29509812430436883315,
                    0.95546695234950082525,
                    0.99563633406139027267,
                ],
            ),
            (
                0.1,
                0.5374804495734065,
                [
                    0.50987612090170959287,
                    0.86024783715753986314,
                    0.98691571784698136005,
                ],
            ),
            (
                0.1,
                0.8062206743601097,
                [
                    0.71635676830393805908,
                    0.69773417610515396378,
                    0.97400374642529676486,
                ],
            ),
            (
                0.1,
                1.2415798385145689,
                [
                    0.93847200409799659765,
                    0.34535532068333601572,
                    0.95494870529910086146,
                ],
            ),
            (
                0.1,
                1.6124413477202193,
                [
                    0.99999999999999999955,
                    9.4868339322036875544e-10,
                    0.94868329805051379965,
                ],
            ),
            (
                0.1,
                1.6124413487202194,
                [1.0, 1.6675446914628293993e-17, 0.9486832980505137996],
            ),
            (
                0.1,
                2.9,
                [
                    0.31866752714944354491,
                    -0.94786655555540024614,
                    0.99490959424163051244,
                ],
            ),
            (
                0.5,
                0.3,
                [
                    0.29341273316845537748,
                    0.95598586182778707744,
                    0.97824050417436120533,
                ],
            ),
            (
                0.5,
                0.6180248924337907,
                [
                    0.56457945531766096954,
                    0.82537872436428433831,
                    0.91685605157876698741,
                ],
            ),
            (
                0.5,
                0.9270373386506859,
                [
                    0.76536686473017953204,
                    0.64359425290558263832,
                    0.84089641525371454823,
                ],
            ),
            (
                0.5,
                1.4276375015220564,
                [
                    0.95353334527296963143,
                    0.30128750298102256906,
                    0.73850326994961223511,
                ],
            ),
            (
                0.5,
                1.854074676301372,
                [
                    0.99999999999999999975,
                    7.0710671252921727409e-10,
                    0.70710678118654752458,
                ],
            ),
            (
                0.5,
                1.8540746773013719,
                [1.0, 2.9845638206717699127e-17, 0.7071067811865475244],
            ),
            (
                0.5,
                2.9,
                [
                    0.69605171392003982629,
                    -0.71799165144796428609,
                    0.87049181832713828096,
                ],
            ),
            (
                0.9,
                0.3,
                [
                    0.2917320478186184853,
                    0.95650008482778259369,
                    0.96093869265838170209,
                ],
            ),
            (
                0.9,
                0.8593640377827244,
                [
                    0.7022344664160164374,
                    0.71194575227148639987,
                    0.74577481772963574241,
                ],
            ),
            (
                0.9,
                1.2890460566740867,
                [
                    0.87163462910095413955,
                    0.49015617241042891006,
                    0.56234132519034905082,
                ],
            ),
            (
                0.9,
                1.9851309272780933,
                [
                    0.98056360235193135704,
                    0.19620148251887251638,
                    0.36694075757313072549,
                ],
            ),
            (
                0.9,
                2.5780921123481733,
                [
                    0.99999999999999999995,
                    3.1622774353184873847e-10,
                    0.31622776601683793334,
                ],
            ),
            (
                0.9,
                2.5780921133481733,
                [1.0, -4.8649791875223486734e-17, 0.3162277660168379332],
            ),
            (
                0.9,
                2.9,
                [
                    0.9946607832063695248,
                    -0.103198480372976252,
                    0.33103615167555704328,
                ],
            ),
            (
                0.95,
                0.3,
                [
                    0.29152229331961082475,
                    0.95656403470843225609,
                    0.95878256913274714081,
                ],
            ),
            (
                0.95,
                0.9694457494815174,
                [
                    0.75247711746243843611,
                    0.65861839307403162471,
                    0.67977148977479825385,
                ],
            ),
            (
                0.95,
                1.454168624222276,
                [
                    0.90402212493303678555,
                    0.42748566950432014434,
                    0.47287080450158792643,
                ],
            ),
            (
                0.95,
                2.239419681302305,
                [
                    0.98717210209200836628,
                    0.15965976591253480638,
                    0.27242738263376378287,
                ],
            ),
            (
                0.95,
                2.908337247444552,
                [
                    0.99999999999999999997,
                    2.2360684035021900329e-10,
                    0.22360679774997896975,
                ],
            ),
            (
                0.95,
                2.908337248444552,
                [1.0, 2.4098930629866770144e-17, 0.22360679774997896964],
            ),
            (
                0.95,
                2.9,
                [
                    0.99999826221946218213,
                    0.0018642848644331532447,
                    0.22361418063296649258,
                ],
            ),
        ];
        for (m, u, expected) in cases {
            let functions = JacobiFunctions::new(&EllipticParameter::new(m).unwrap());
            let (sn, cn, dn) = functions.sn_cn_dn(u);
            for (name, value, truth) in [
                ("sn", sn, expected[0]),
                ("cn", cn, expected[1]),
                ("dn", dn, expected[2]),
            ] {
                assert!(
                    (value - truth).abs() <= 1e-15,
                    "m = {m}, u = {u}: {name} {value:e} against {truth:e}"
                );
            }
        }
    }
}
