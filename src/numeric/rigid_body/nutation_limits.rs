//! The conserved quantities of a heavy symmetric top and the two angles its axis nutates
//! between (§18.9, the full equations).
//!
//! The top conserves its spin `ω_z = ψ̇ + φ̇ cos θ`, its momentum about the vertical
//! `p_φ = I′ φ̇ sin²θ + I ω_z cos θ` and its energy
//! `E = ½ I′ (θ̇² + φ̇² sin²θ) + ½ I ω_z² + W c cos θ`. With `u = cos θ`,
//! `θ̇² sin²θ = u̇²` and `φ̇ = (p_φ − I ω_z u) / (I′ (1 − u²))`, the energy reads
//!
//! ```text
//! u̇² = f(u) = (2E′/I′ − 2Wc u/I′)(1 − u²) − ((p_φ − I ω_z u)/I′)²,   E′ = E − ½ I ω_z²
//! ```
//!
//! The axis moves where `f ≥ 0`; it turns back at the roots of `f` on either side of the
//! start `u₀`. `f(±1) = −((p_φ ∓ I ω_z)/I′)² ≤ 0` and `f(u₀) = θ̇₀² sin²θ₀ ≥ 0`, so each
//! side has its root in `[−1, 1]`. To keep the small differences exact, `f` is written in
//! `d = u − u₀` from the initial values (`A = θ̇₀² + φ̇₀² sin²θ₀`, `P = φ̇₀ sin²θ₀`,
//! `b = I ω_z / I′`, `β = 2 W c / I′`, so `2E′/I′ = A + β u₀` and `p_φ/I′ − b u = P − b d`):
//!
//! ```text
//! f = (A − β d)(sin²θ₀ − 2 u₀ d − d²) − (P − b d)²
//!   = β d³ + (2β u₀ − A − b²) d² + (2 P b − 2 A u₀ − β sin²θ₀) d + θ̇₀² sin²θ₀
//! ```
//!
//! Started with `θ̇₀ = 0`, `d = 0` is a root and the other turning point is a root of the
//! quadratic `f/d` on the side where `f/d` starts positive; `f/d` at 0 is zero exactly for
//! steady precession (`I′ φ̇² cos θ − I ω_z φ̇ + W c = 0`), whose limits coincide. Each root
//! is found by bisection within its bracket, to the rounding of `f`.
//!
//! Between the turning angles the rates stay in bands: `φ̇ = (a − b u)/(1 − u²)` with
//! `a = p_φ/I′`, and `ψ̇ = ω_z − u φ̇`, extreme at the ends of `[cos θ_max, cos θ_min]` or
//! where their derivatives vanish, `b u² − 2a u + b = 0` and `a u² − 2b u + a = 0`. So
//! over a time `Δt` φ grows by between `φ̇_min Δt` and `φ̇_max Δt`: what counts its turns
//! between two samples however far apart, when the band is narrower than `2π/Δt`.

use super::eulerian_angles::EulerianAngles;
use super::heavy_top::{validate_start, HeavyTop};
use crate::numeric::error::NumericError;

/// What the motion conserves, and the angles the axis turns back at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NutationLimits {
    /// `ω_z = ψ̇ + φ̇ cos θ` (rad/s).
    pub spin: f64,
    /// `p_φ = I′ φ̇ sin²θ + I ω_z cos θ`, the momentum about the vertical.
    pub vertical_momentum: f64,
    /// `E = ½ I′ (θ̇² + φ̇² sin²θ) + ½ I ω_z² + W c cos θ`.
    pub energy: f64,
    /// The smallest θ the axis reaches (rad).
    pub theta_min: f64,
    /// The largest θ (rad).
    pub theta_max: f64,
    /// `(φ̇_min, φ̇_max)` over the nutation; `None` when the axis reaches the vertical
    /// (`1 − u² = 0`, where φ̇ has no bound the formula can give).
    pub phi_dot_band: Option<(f64, f64)>,
    /// `(ψ̇_min, ψ̇_max)` over the nutation; `None` as for φ̇.
    pub psi_dot_band: Option<(f64, f64)>,
}

/// The least and greatest of `rate(u)` for `u` in `[u_low, u_high]`: at the ends and at the
/// roots of `p u² − 2 q u + p = 0` between them. `None` when an end is `±1`.
fn band(u_low: f64, u_high: f64, p: f64, q: f64, rate: impl Fn(f64) -> f64) -> Option<(f64, f64)> {
    if u_low <= -1.0 || u_high >= 1.0 {
        return None;
    }
    let mut candidates = vec![u_low, u_high];
    // p u² − 2 q u + p = 0: u = (q ± √(q² − p²))/p, the smaller root as p/(q ± √…).
    let discriminant = q * q - p * p;
    if p != 0.0 && discriminant >= 0.0 {
        let big = q + q.signum() * discriminant.sqrt();
        candidates.push(big / p);
        if big != 0.0 {
            candidates.push(p / big);
        }
    }
    let values: Vec<f64> = candidates
        .into_iter()
        .filter(|u| (u_low..=u_high).contains(u))
        .map(rate)
        .collect();
    let low = values.iter().copied().fold(f64::INFINITY, f64::min);
    let high = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (low.is_finite() && high.is_finite()).then_some((low, high))
}

/// The conserved quantities of `top` started at `initial` and its turning angles.
pub fn nutation_limits(
    top: &HeavyTop,
    initial: &EulerianAngles,
) -> Result<NutationLimits, NumericError> {
    validate_start(initial)?;
    let (sin0, u0) = initial.theta.sin_cos();
    let sin0_sq = sin0 * sin0;
    let (i, i_t, wc) = (top.axial(), top.transverse(), top.weight_arm());
    let spin = initial.axial_rate();
    let (theta_dot, phi_dot) = (initial.theta_dot, initial.phi_dot);
    let a = theta_dot * theta_dot + phi_dot * phi_dot * sin0_sq;
    let p = phi_dot * sin0_sq;
    let b = i * spin / i_t;
    let beta = 2.0 * wc / i_t;
    let cubic = [
        theta_dot * theta_dot * sin0_sq,
        2.0 * p * b - 2.0 * a * u0 - beta * sin0_sq,
        2.0 * beta * u0 - a - b * b,
        beta,
    ];
    let (low, high) = (-1.0 - u0, 1.0 - u0);
    let (d_min, d_max) = if cubic[0] > 0.0 {
        let f = |d: f64| horner(&cubic, d);
        (root_between(&f, low, 0.0), root_between(&f, high, 0.0))
    } else {
        // f = d g(d): the turning point at the start, the other where g changes sign.
        let quadratic = [cubic[1], cubic[2], cubic[3]];
        let g = |d: f64| horner(&quadratic, d);
        match cubic[1] {
            slope if slope > 0.0 => (0.0, root_between(&g, high, 0.0)),
            slope if slope < 0.0 => (root_between(&|d| -g(d), low, 0.0), 0.0),
            _ => (0.0, 0.0),
        }
    };
    let theta = |d: f64| match d {
        0.0 => initial.theta,
        _ => (u0 + d).clamp(-1.0, 1.0).acos(),
    };
    let non_finite = |what: &str| NumericError::InvalidInput {
        what: what.into(),
        reason: "is beyond the range of f64; check the moments and the rates".into(),
    };
    let energy = 0.5 * i_t * a + 0.5 * i * spin * spin + wc * u0;
    let vertical_momentum = i_t * p + i * spin * u0;
    if !energy.is_finite() {
        return Err(non_finite("the energy E"));
    }
    if !vertical_momentum.is_finite() || !cubic.iter().all(|c| c.is_finite()) {
        return Err(non_finite("the momentum about the vertical p_φ"));
    }
    let (u_low, u_high) = ((u0 + d_min).max(-1.0), (u0 + d_max).min(1.0));
    let a_phi = vertical_momentum / i_t;
    let phi_dot = |u: f64| (a_phi - b * u) / ((1.0 - u) * (1.0 + u));
    Ok(NutationLimits {
        spin,
        vertical_momentum,
        energy,
        theta_min: theta(d_max),
        theta_max: theta(d_min),
        phi_dot_band: band(u_low, u_high, b, a_phi, phi_dot),
        psi_dot_band: band(u_low, u_high, a_phi, b, |u| spin - u * phi_dot(u)),
    })
}

/// `c₀ + c₁ d + c₂ d² + …`.
fn horner(coefficients: &[f64], d: f64) -> f64 {
    coefficients.iter().rev().fold(0.0, |sum, c| sum * d + c)
}

/// A root of `h` between `outside` (where `h ≤ 0`, or at `outside` itself if `h` is not)
/// and `inside` (where `h > 0`), by bisection down to adjacent numbers.
fn root_between(h: &dyn Fn(f64) -> f64, outside: f64, inside: f64) -> f64 {
    if h(outside) > 0.0 {
        // Rounding where the root is the end of the range (the axis reaches the vertical).
        return outside;
    }
    let (mut out, mut inn) = (outside, inside);
    loop {
        let middle = 0.5 * (out + inn);
        if middle == out || middle == inn {
            return middle;
        }
        if h(middle) > 0.0 {
            inn = middle;
        } else {
            out = middle;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cubic in `d` is the chapter's `f(u)` at `u = u₀ + d`: both forms evaluated from
    /// E, p_φ and ω_z as defined, at several `u`.
    #[test]
    fn the_cubic_in_d_is_the_energy_equation() {
        let top = HeavyTop::new(0.8, 1.7, 2.3).unwrap();
        let start = EulerianAngles {
            theta: 0.9,
            phi: 0.0,
            psi: 0.0,
            theta_dot: 0.6,
            phi_dot: 1.4,
            psi_dot: 9.0,
        };
        let limits = nutation_limits(&top, &start).unwrap();
        let (i, i_t, wc) = (0.8, 1.7, 2.3);
        let e_prime = limits.energy - 0.5 * i * limits.spin * limits.spin;
        let f = |u: f64| {
            (2.0 * e_prime / i_t - 2.0 * wc * u / i_t) * (1.0 - u * u)
                - ((limits.vertical_momentum - i * limits.spin * u) / i_t).powi(2)
        };
        // f vanishes at the turning angles and equals u̇² = θ̇² sin²θ at the start.
        for theta in [limits.theta_min, limits.theta_max] {
            assert!(
                f(theta.cos()).abs() < 1e-12,
                "f(cos {theta}) = {}",
                f(theta.cos())
            );
        }
        let u_dot_sq = (0.6 * 0.9f64.sin()).powi(2);
        assert!((f(0.9f64.cos()) - u_dot_sq).abs() < 1e-12);
        assert!(
            limits.theta_min < 0.9 && 0.9 < limits.theta_max,
            "{limits:?}"
        );
    }

    /// Released at rest in θ (θ̇₀ = 0) with a slow precession, the axis falls: the start is
    /// the smallest angle.
    #[test]
    fn a_top_released_too_slowly_precessing_falls_from_its_start() {
        let top = HeavyTop::new(0.8, 1.7, 2.3).unwrap();
        let start = EulerianAngles {
            theta: 0.5,
            phi: 0.0,
            psi: 0.0,
            theta_dot: 0.0,
            phi_dot: 0.0,
            psi_dot: 40.0,
        };
        let limits = nutation_limits(&top, &start).unwrap();
        assert_eq!(limits.theta_min, 0.5);
        assert!(limits.theta_max > 0.5, "{limits:?}");
    }
}
