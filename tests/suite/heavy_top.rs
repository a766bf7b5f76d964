//! Issue 19's simulation of a heavy top (`HeavyTop`: Euler's equations about the fixed point
//! with the weight's moment, the angles read from the attitude), against the chapter's
//! results and an independent integration of the Eulerian-angle equations themselves.

use kinetics::numeric::integrators::adaptive::AdaptiveSettings;
use kinetics::numeric::integrators::dop853::Dop853;
use kinetics::numeric::integrators::ode::OdeSystem;
use kinetics::numeric::rigid_body::eulerian_angles::{AnglesAlongMotion, EulerianAngles};
use kinetics::numeric::rigid_body::exact_propagation::{simulate_choice, Choice, MethodUsed};
use kinetics::numeric::rigid_body::heavy_top::HeavyTop;
use kinetics::numeric::rigid_body::nutation_limits::nutation_limits;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{Method, Sampling};
use nalgebra::SVector;
use std::f64::consts::TAU;

/// The angles of every sample of `top` started at `start`, by `choice`.
fn angles(
    top: &HeavyTop,
    start: EulerianAngles,
    choice: Choice,
    sampling: &Sampling<f64>,
) -> (Vec<(f64, EulerianAngles)>, MethodUsed) {
    let problem = top.problem(&start).unwrap();
    let limits = nutation_limits(top, &start).unwrap();
    let mut along =
        AnglesAlongMotion::starting_at(start, 0.0, limits.phi_dot_band, limits.psi_dot_band);
    let mut out = Vec::new();
    let mut sink = |s: Sample<f64>| out.push((s.t, along.next(s.t, &s.orientation, &s.omega)));
    let (_, used) = simulate_choice(&problem, &choice, sampling, &mut sink, &mut |_| {}).unwrap();
    (out, used)
}

const TIGHT: Choice = Choice::Integrate(Method::Dop853 {
    rtol: 1e-12,
    atol: 1e-15,
    max_steps: 10_000_000,
});

fn start(theta: f64, theta_dot: f64, phi_dot: f64, psi_dot: f64) -> EulerianAngles {
    EulerianAngles {
        theta,
        phi: 0.2,
        psi: -0.4,
        theta_dot,
        phi_dot,
        psi_dot,
    }
}

/// θ̈ = 0 in `I′(θ̈ − φ̇² sin θ cos θ) + I φ̇ sin θ ω_z = W c sin θ` gives the spin of steady
/// precession: `ω_z = (I′ φ̇² cos θ + W c) / (I φ̇)`, and `ψ̇ = ω_z − φ̇ cos θ`.
#[test]
fn a_top_started_in_steady_precession_keeps_theta_to_1e9_over_100_periods() {
    let (i, i_t, wc) = (1.0, 2.0, 3.0);
    let top = HeavyTop::new(i, i_t, wc).unwrap();
    let (theta, phi_dot): (f64, f64) = (0.7, 1.5);
    let spin = (i_t * phi_dot * phi_dot * theta.cos() + wc) / (i * phi_dot);
    let steady = start(theta, 0.0, phi_dot, spin - phi_dot * theta.cos());
    let period = TAU / phi_dot;
    let sampling = Sampling::Every {
        interval: period / 50.0,
        end: 100.0 * period,
    };
    let (samples, _) = angles(&top, steady, TIGHT, &sampling);
    let worst = samples
        .iter()
        .map(|(_, a)| ((a.theta - theta) / theta).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-9, "θ drifts by {worst:e} (relative)");
    let (end, last) = samples.last().unwrap();
    let turns = (last.phi - steady.phi) / TAU;
    assert!(
        (turns - 100.0).abs() < 1e-7,
        "{turns} turns of precession by t = {end}"
    );
    // The predicted limits coincide.
    let limits = nutation_limits(&top, &steady).unwrap();
    assert!(limits.theta_max - limits.theta_min < 1e-12, "{limits:?}");
}

/// Torque-free with the vertical along H_O: `H_O = I′ φ̇ sin θ j + I ω_z k` is parallel to
/// `K = sin θ j + cos θ k` when `φ̇ = I ω_z / (I′ cos θ)` (§18.10). Integrated and exact, the
/// axis precesses at that rate, read both as φ̇ and as φ's growth.
#[test]
fn a_torque_free_body_precesses_at_i_omega_z_over_i_prime_cos_theta() {
    let (i, i_t, theta, spin): (f64, f64, f64, f64) = (1.0, 2.5, 0.5, 10.0);
    let top = HeavyTop::new(i, i_t, 0.0).unwrap();
    let precession = i * spin / (i_t * theta.cos());
    let free = start(theta, 0.0, precession, spin - precession * theta.cos());
    let sampling = Sampling::Every {
        interval: 0.01,
        end: 30.0,
    };
    for (choice, expected) in [
        (TIGHT, MethodUsed::Integrator),
        (Choice::Exact, MethodUsed::Exact),
    ] {
        let (samples, used) = angles(&top, free, choice, &sampling);
        assert_eq!(used, expected);
        for (t, a) in &samples {
            let rate = ((a.phi_dot - precession) / precession).abs();
            assert!(rate < 1e-10, "{used:?} t = {t}: φ̇ off by {rate:e}");
            let growth = (a.phi - free.phi) - precession * t;
            assert!(
                growth.abs() < 1e-10 * precession * t.max(1.0),
                "{used:?} t = {t}: φ off by {growth:e}"
            );
            assert!((a.theta - theta).abs() < 1e-10 * theta);
        }
    }
}

/// The local extrema of θ along the samples, each located on the cubic Hermite interpolant
/// of θ and θ̇ between the two samples around it (error O(h⁴)).
fn extrema(samples: &[(f64, EulerianAngles)]) -> Vec<f64> {
    let mut found = Vec::new();
    for pair in samples.windows(2) {
        let ((t0, a), (t1, b)) = (pair[0], pair[1]);
        if a.theta_dot * b.theta_dot > 0.0 || a.theta_dot == 0.0 {
            continue;
        }
        let h = t1 - t0;
        let (m0, m1) = (h * a.theta_dot, h * b.theta_dot);
        let slope = |s: f64| {
            (6.0 * s * s - 6.0 * s) * (a.theta - b.theta)
                + (3.0 * s * s - 4.0 * s + 1.0) * m0
                + (3.0 * s * s - 2.0 * s) * m1
        };
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if slope(mid) * m0 > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let s = 0.5 * (lo + hi);
        let value = (2.0 * s.powi(3) - 3.0 * s * s + 1.0) * a.theta
            + (s.powi(3) - 2.0 * s * s + s) * m0
            + (-2.0 * s.powi(3) + 3.0 * s * s) * b.theta
            + (s.powi(3) - s * s) * m1;
        found.push(value);
    }
    found
}

/// Started off steady precession (with a nod θ̇₀, or released with θ̇₀ = 0 and precessing too
/// slowly or too fast), the axis turns back exactly at the roots of the energy cubic.
#[test]
fn the_nutation_limits_match_the_turning_angles_of_the_cubic_to_1e8() {
    let top = HeavyTop::new(0.9, 1.6, 4.0).unwrap();
    for initial in [
        start(0.5, 0.3, 0.2, 20.0),
        start(0.9, -0.8, 1.0, 12.0),
        start(0.6, 0.0, 0.0, 15.0),
        start(1.1, 0.0, 2.5, 8.0),
    ] {
        let limits = nutation_limits(&top, &initial).unwrap();
        let sampling = Sampling::Every {
            interval: 1e-3,
            end: 8.0,
        };
        let (samples, _) = angles(&top, initial, TIGHT, &sampling);
        let turns = extrema(&samples);
        assert!(
            turns.len() >= 4,
            "{initial:?}: {} turning points",
            turns.len()
        );
        for theta in turns {
            let nearest = if (theta - limits.theta_min).abs() < (theta - limits.theta_max).abs() {
                limits.theta_min
            } else {
                limits.theta_max
            };
            let error = ((theta - nearest) / nearest).abs();
            assert!(
                error < 1e-8,
                "{initial:?}: turned at {theta}, predicted {limits:?} ({error:e})"
            );
        }
    }
}

/// The chapter's equations in the angles themselves, `y = (θ, φ, ψ, θ̇, φ̇, ψ̇)`:
/// `θ̈ = φ̇² sin θ cos θ − (I/I′) φ̇ ω_z sin θ + (W c/I′) sin θ`,
/// `φ̈ = ((I/I′) θ̇ ω_z − 2 θ̇ φ̇ cos θ) / sin θ` and `ψ̈ = φ̇ θ̇ sin θ − φ̈ cos θ`
/// (`ω_z = ψ̇ + φ̇ cos θ` constant).
struct AngleEquations {
    ratio: f64,
    weight: f64,
}

impl OdeSystem<f64, 6> for AngleEquations {
    fn derivative(&self, _t: f64, y: &SVector<f64, 6>) -> SVector<f64, 6> {
        let (theta, theta_dot, phi_dot, psi_dot) = (y[0], y[3], y[4], y[5]);
        let (s, c) = theta.sin_cos();
        let spin = psi_dot + phi_dot * c;
        let theta_ddot =
            phi_dot * phi_dot * s * c - self.ratio * phi_dot * spin * s + self.weight * s;
        let phi_ddot = (self.ratio * theta_dot * spin - 2.0 * theta_dot * phi_dot * c) / s;
        let psi_ddot = phi_dot * theta_dot * s - phi_ddot * c;
        SVector::from([theta_dot, phi_dot, psi_dot, theta_ddot, phi_ddot, psi_ddot])
    }
}

/// The quaternion simulation and the Eulerian-angle equations integrated apart agree on the
/// three angles of a nutating top (sampled often enough for φ and ψ to be unwrapped, compared
/// every half second).
#[test]
fn the_angles_agree_with_the_eulerian_angle_equations_integrated_directly() {
    let (i, i_t, wc) = (0.9, 1.6, 4.0);
    let top = HeavyTop::new(i, i_t, wc).unwrap();
    let initial = start(0.9, -0.8, 1.0, 12.0);
    let every = Sampling::Every {
        interval: 0.005,
        end: 5.0,
    };
    let (samples, _) = angles(&top, initial, TIGHT, &every);
    let equations = AngleEquations {
        ratio: i / i_t,
        weight: wc / i_t,
    };
    let y0 = SVector::from([
        initial.theta,
        initial.phi,
        initial.psi,
        initial.theta_dot,
        initial.phi_dot,
        initial.psi_dot,
    ]);
    let settings = AdaptiveSettings {
        rtol: 1e-13,
        atol: 1e-15,
        max_steps: 10_000_000,
    };
    let mut direct = Dop853::new(&equations, 0.0, y0, 5.0, settings).unwrap();
    for (t, a) in samples.iter().skip(100).step_by(100) {
        while direct.t() < *t {
            direct.step(&equations).unwrap();
        }
        let y = direct.dense_output(&equations, *t);
        let got = [a.theta, a.phi, a.psi, a.theta_dot, a.phi_dot, a.psi_dot];
        for (k, (g, w)) in got.iter().zip(y.iter()).enumerate() {
            assert!(
                (g - w).abs() < 1e-8 * w.abs().max(1.0),
                "t = {t}, component {k}: {g} against {w}"
            );
        }
    }
}

/// Sampled every half second, while ψ turns ~16 times in between, φ and ψ still count their
/// turns (from the bands of φ̇ and ψ̇ over the nutation): the same as sampled every 5 ms.
#[test]
fn sparse_samples_count_the_turns_from_the_bands_of_the_rates() {
    let top = HeavyTop::new(0.9, 1.6, 4.0).unwrap();
    let initial = start(0.9, -0.8, 1.0, 200.0);
    let limits = nutation_limits(&top, &initial).unwrap();
    let (phi_band, psi_band) = (limits.phi_dot_band.unwrap(), limits.psi_dot_band.unwrap());
    assert!(
        (psi_band.1 - psi_band.0) * 0.5 < std::f64::consts::PI,
        "{limits:?}"
    );
    let sparse = Sampling::Every {
        interval: 0.5,
        end: 5.0,
    };
    let dense = Sampling::Every {
        interval: 0.005,
        end: 5.0,
    };
    let (sparse, _) = angles(&top, initial, TIGHT, &sparse);
    let (dense, _) = angles(&top, initial, TIGHT, &dense);
    for (t, a) in sparse.iter().skip(1) {
        let (_, b) = dense.iter().find(|(u, _)| (u - t).abs() < 1e-9).unwrap();
        assert!(
            (a.phi - b.phi).abs() < 1e-8 && (a.psi - b.psi).abs() < 1e-7,
            "{t}: {a:?} {b:?}"
        );
        assert!(a.psi > 50.0 * t, "ψ counted its turns: {}", a.psi);
        assert!(
            phi_band.0 <= a.phi_dot && a.phi_dot <= phi_band.1,
            "{a:?} {phi_band:?}"
        );
        assert!(
            psi_band.0 <= a.psi_dot && a.psi_dot <= psi_band.1,
            "{a:?} {psi_band:?}"
        );
    }
}
