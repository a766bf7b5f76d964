//! `sn, cn, dn` from Jacobi's theta functions (DLMF 22.2.4), for a parameter fixed once and
//! many arguments: a sine and cosine a point, and a few terms of four series in the nome
//! `q = exp(−πK'/K)`:
//!
//! ```text
//! z = πu/(2K),  s = sin z,  c = cos z,  y = cos 2z = c² − s²
//! θ₁(z) = 2q^¼ s Σₙ wₙ U₂ₙ(c),   θ₂(z) = 2q^¼ c Σₙ wₙ U₂ₙ(s),   wₙ = (−1)ⁿ q^(n(n+1))
//! θ₃(z) = 1 + 2 Σₙ q^(n²) Tₙ(y),  θ₄(z) = 1 + 2 Σₙ (−1)ⁿ q^(n²) Tₙ(y)
//! sn = A θ₁/θ₄,  cn = B θ₂/θ₄,  dn = √(cn² + m' sn²)
//! ```
//!
//! (`U₂ₙ(cos z) = sin((2n+1)z)/sin z` and `(−1)ⁿU₂ₙ(sin z) = cos((2n+1)z)/cos z` are
//! Chebyshev polynomials, so `s` and `c` stand outside the sums and `sn`, `cn` keep their
//! relative accuracy where they are small; the larger of the two is then completed from
//! `sn² + cn² = 1`.) The constants `A, B` are fixed by `sn(K) = cn(0) = 1`, from the same
//! series at `z = π/2` and `z = 0`, whose terms are all positive there but for `θ₄(0)`'s,
//! so nothing cancels at `q ≤` [`MAX_NOME`].
//! The terms run while `q^(n²)` exceeds a quarter ulp: five for `q = 0.2`.

/// The largest nome the series serve (m up to about 0.96); beyond it `θ₄(0)` is small and
/// comes from cancelling terms, and the Landen transformation is used instead.
pub(super) const MAX_NOME: f64 = 0.2;
/// Room for the terms of any series (`0.2^(n²)` is below a quarter ulp from n = 5).
const MAX_TERMS: usize = 8;

/// The four series of one nome, with their normalising constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct ThetaSeries {
    /// `wₙ = (−1)ⁿ q^(n(n+1))`, n = 0 … terms − 1.
    odd: [f64; MAX_TERMS],
    /// `q^(n²)`, n = 1 … terms (index n − 1).
    even: [f64; MAX_TERMS],
    terms: usize,
    /// `A, B` of the module documentation (with the factors 2q^¼ taken in).
    sn_scale: f64,
    cn_scale: f64,
}

impl ThetaSeries {
    /// The series of the nome `q` in `[0, MAX_NOME]`.
    pub(super) fn new(q: f64) -> ThetaSeries {
        let mut series = ThetaSeries {
            odd: [0.0; MAX_TERMS],
            even: [0.0; MAX_TERMS],
            terms: 1,
            sn_scale: 1.0,
            cn_scale: 1.0,
        };
        series.odd[0] = 1.0;
        for n in 1..MAX_TERMS {
            let n_f = n as f64;
            let even = q.powf(n_f * n_f);
            if even < f64::EPSILON / 4.0 {
                break;
            }
            series.even[n - 1] = even;
            let odd = q.powf(n_f * (n_f + 1.0));
            series.odd[n] = if n % 2 == 0 { odd } else { -odd };
            series.terms = n + 1;
        }
        // At z = π/2 (s = 1, c = 0): Σ wₙ U₂ₙ(0) = Σ q^(n(n+1)) and θ₄(π/2) = θ₃(0).
        let odd_at_zero: f64 = series.odd.iter().map(|w| w.abs()).sum();
        let (theta3, theta4) = series.theta34(1.0);
        series.sn_scale = theta3 / odd_at_zero;
        series.cn_scale = theta4 / odd_at_zero;
        series
    }

    /// `(sn, cn, dn)` at `z ∈ [0, π/2]` given by `s = sin z`, `c = cos z`, with parameter
    /// complement `mc`. The smaller of sn and cn comes from its series, to its relative
    /// precision however small; the larger (at least 1/√2) from `sn² + cn² = 1`, and dn from
    /// `dn² = cn² + m' sn²`, sums without cancellation, so the identities hold to an ulp.
    pub(super) fn sn_cn_dn(&self, s: f64, c: f64, mc: f64) -> (f64, f64, f64) {
        let reciprocal = 1.0 / self.theta4(c * c - s * s);
        let sn = self.sn_scale * s * self.odd_sum(c) * reciprocal;
        let cn = self.cn_scale * c * self.odd_sum(s) * reciprocal;
        let (sn, cn) = if sn <= cn {
            (sn, (1.0 - sn * sn).sqrt())
        } else {
            ((1.0 - cn * cn).sqrt(), cn)
        };
        (sn, cn, (cn * cn + mc * sn * sn).sqrt())
    }

    /// `Σₙ wₙ U₂ₙ(x)`.
    fn odd_sum(&self, x: f64) -> f64 {
        // U₀ = 1, U₁ = 2x, Uₖ₊₁ = 2x Uₖ − Uₖ₋₁; the even ones are wanted.
        let two_x = 2.0 * x;
        let (mut previous, mut current) = (1.0, two_x);
        let mut sum = self.odd[0];
        for w in &self.odd[1..self.terms] {
            // U₂ₙ from U₂ₙ₋₂ (previous) and U₂ₙ₋₁ (current), and U₂ₙ₊₁ for the next term.
            let even = two_x * current - previous;
            let odd = two_x * even - current;
            sum += w * even;
            (previous, current) = (even, odd);
        }
        sum
    }

    /// `θ₄(z)` from `y = cos 2z`.
    fn theta4(&self, y: f64) -> f64 {
        self.theta34(y).1
    }

    /// `(θ₃(z), θ₄(z))` from `y = cos 2z`.
    fn theta34(&self, y: f64) -> (f64, f64) {
        // T₀ = 1, T₁ = y, Tₖ₊₁ = 2y Tₖ − Tₖ₋₁.
        let (mut previous, mut current) = (1.0, y);
        let (mut even, mut alternating) = (0.0, 0.0);
        for (n, v) in self.even[..self.terms - 1].iter().enumerate() {
            let term = v * current;
            even += term;
            alternating += if n % 2 == 0 { -term } else { term };
            (previous, current) = (current, 2.0 * y * current - previous);
        }
        (1.0 + 2.0 * even, 1.0 + 2.0 * alternating)
    }
}
