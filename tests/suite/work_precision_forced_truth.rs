//! The ground truth of the forced bodies in `kinetics bench work-precision` is the
//! double-double Taylor reference under the body's
//! [`HarmonicMoment`](kinetics::numeric::integrators::harmonic_moment::HarmonicMoment) ([`truth`]). This checks
//! it against an integration that shares none of its code and carries ~32 digits too:
//! classical RK4 written out here in double-double arithmetic, on the equations read from
//! each [`Case`] directly (principal moments, `ω₀`, `q₀ = 1`, the body-frame moment of its
//! [`Load`] evaluated in `f64`, as the integrators do):
//!
//! ```text
//! I₁ ω̇₁ = (I₂ − I₃) ω₂ ω₃ + M₁(t)   (and cyclically),    q̇ = ½ q ⊗ (0, ω)
//! ```
//!
//! RK4 runs at steps `h`, `h/2`, `h/4` (powers of two, so every step lands on the sample
//! times `k = 1, 2, …` s exactly). Richardson: for a method of order 4 the differences of
//! successive runs `d(h) = |y_h − y_{h/2}|` fall sixteenfold when the step halves (checked
//! without reference to the truth, so the runs are in the asymptotic regime), and
//! `y* = y_{h/2} + (y_{h/2} − y_h)/15` removes the leading error term. The two extrapolations
//! from `(h, h/2)` and `(h/2, h/4)` differ by the error of the first (measured 2.2e-13 at
//! most); the second's is some 32 times smaller, and the truth agrees with it to
//! [`TRUTH_BOUND`] in both of the study's errors, max `|Δω|` and the attitude angle, over the
//! study's default horizon and sample times.
//!
//! What it proves: the forced-body errors the study prints are errors of the methods down to
//! [`TRUTH_BOUND`], and the reference integrates the stated problem (a wrong recurrence, a
//! moment applied in the wrong frame or at the wrong time, would show here). What it does
//! not: that the moment functions are the ones intended, since both sides read the same
//! [`Case`].

use kinetics::numeric::scalar::double_double::DoubleDouble as Dd;
use kinetics::numeric::work_precision::study::{cases, truth, Case, Load};
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// The study's default horizon (`kinetics bench work-precision` without `--until`), sampled
/// as the study samples it: at `UNTIL · k / 100`, here the whole seconds.
const UNTIL: usize = 100;

/// Steps per second of the coarsest of the three RK4 runs.
const COARSEST_STEPS_PER_SECOND: usize = 512;

/// Largest disagreement allowed between the truth and the finer extrapolated RK4, in `|Δω|`
/// (rad/s) and in attitude angle (rad). Measured at `t ≤ 100 s`: `|Δω|` 1.4e-15 (forced) and
/// 2.5e-15 (time-forced), attitude 7.2e-15 and 2.5e-15. (The former truth, DOP853 at
/// `rtol = 1e-14` in `f64`, was off by up to 1.1e-12.)
const TRUTH_BOUND: f64 = 5e-14;

/// Largest disagreement allowed between the two extrapolations, the error of the coarser.
/// Measured: `|Δω|` 4.3e-14 (forced) and 5.5e-14 (time-forced), attitude 2.2e-13 and 6.6e-14.
const EXTRAPOLATION_BOUND: f64 = 1e-12;

/// `(ω, q)` with `q = (w, x, y, z)`, in double-double.
#[derive(Clone, Copy)]
struct State {
    omega: [Dd; 3],
    quaternion: [Dd; 4],
}

impl State {
    /// `self + c · rate`.
    fn plus(&self, rate: &State, c: Dd) -> State {
        State {
            omega: std::array::from_fn(|i| self.omega[i] + rate.omega[i] * c),
            quaternion: std::array::from_fn(|i| self.quaternion[i] + rate.quaternion[i] * c),
        }
    }

    fn omega_f64(&self) -> Vector3<f64> {
        Vector3::from(self.omega.map(Dd::to_f64))
    }

    fn attitude(&self) -> UnitQuaternion<f64> {
        let [w, x, y, z] = self.quaternion.map(Dd::to_f64);
        UnitQuaternion::new_normalize(Quaternion::new(w, x, y, z))
    }
}

/// Body-frame moment of the case at time `t` (a function of time is evaluated in `f64`;
/// every stage time of these runs is a multiple of a power of two, exact in `f64`).
fn moment(case: &Case, t: Dd) -> [Dd; 3] {
    let m = match case.load {
        Load::None => Vector3::zeros(),
        Load::Constant(m) => m,
        Load::Harmonic(moment) => moment.at(t.to_f64()),
    };
    [m[0], m[1], m[2]].map(Dd::from_f64)
}

/// Right-hand side: Euler's equations in principal axes and `q̇ = ½ q ⊗ (0, ω)`.
fn rate(case: &Case, t: Dd, y: &State) -> State {
    let inertia = [0, 1, 2].map(|i| Dd::from_f64(case.moments[i]));
    let m = moment(case, t);
    let w = y.omega;
    let omega = std::array::from_fn(|i| {
        let (j, l) = ((i + 1) % 3, (i + 2) % 3);
        ((inertia[j] - inertia[l]) * w[j] * w[l] + m[i]) / inertia[i]
    });
    let [a0, a1, a2, a3] = y.quaternion;
    let [b1, b2, b3] = w;
    let half = Dd::from_f64(0.5);
    let quaternion = [
        (Dd::ZERO - (a1 * b1 + a2 * b2 + a3 * b3)) * half,
        (a0 * b1 + a2 * b3 - a3 * b2) * half,
        (a0 * b2 + a3 * b1 - a1 * b3) * half,
        (a0 * b3 + a1 * b2 - a2 * b1) * half,
    ];
    State { omega, quaternion }
}

/// Classical RK4 with `steps_per_second` equal steps a second, the state at `t = 1, …, UNTIL`.
fn rk4(case: &Case, steps_per_second: usize) -> Vec<State> {
    let h = Dd::from_f64(1.0 / steps_per_second as f64);
    let half = h * Dd::from_f64(0.5);
    let sixth = h / Dd::from_f64(6.0);
    let two = Dd::from_f64(2.0);
    let mut y = State {
        omega: [0, 1, 2].map(|i| Dd::from_f64(case.omega0[i])),
        quaternion: [Dd::ONE, Dd::ZERO, Dd::ZERO, Dd::ZERO],
    };
    let mut t = Dd::ZERO;
    let mut samples = Vec::with_capacity(UNTIL);
    for _ in 0..UNTIL {
        for _ in 0..steps_per_second {
            let k1 = rate(case, t, &y);
            let k2 = rate(case, t + half, &y.plus(&k1, half));
            let k3 = rate(case, t + half, &y.plus(&k2, half));
            let k4 = rate(case, t + h, &y.plus(&k3, h));
            y = State {
                omega: std::array::from_fn(|i| {
                    y.omega[i]
                        + (k1.omega[i] + two * k2.omega[i] + two * k3.omega[i] + k4.omega[i])
                            * sixth
                }),
                quaternion: std::array::from_fn(|i| {
                    y.quaternion[i]
                        + (k1.quaternion[i]
                            + two * k2.quaternion[i]
                            + two * k3.quaternion[i]
                            + k4.quaternion[i])
                            * sixth
                }),
            };
            t += h;
        }
        samples.push(y);
    }
    samples
}

/// Richardson's extrapolation of a fourth-order method, sample by sample:
/// `y* = y_{h/2} + (y_{h/2} − y_h)/15`.
fn extrapolate(coarse: &[State], fine: &[State]) -> Vec<State> {
    let fifteen = Dd::from_f64(15.0);
    coarse
        .iter()
        .zip(fine)
        .map(|(c, f)| State {
            omega: std::array::from_fn(|i| f.omega[i] + (f.omega[i] - c.omega[i]) / fifteen),
            quaternion: std::array::from_fn(|i| {
                f.quaternion[i] + (f.quaternion[i] - c.quaternion[i]) / fifteen
            }),
        })
        .collect()
}

/// Max over the samples of `|Δω|` and of the attitude angle between `a` and `b`.
fn distance(a: &[State], b: &[State]) -> (f64, f64) {
    let omega = a
        .iter()
        .zip(b)
        .map(|(x, y)| {
            let d: [Dd; 3] = std::array::from_fn(|i| x.omega[i] - y.omega[i]);
            Vector3::from(d.map(Dd::to_f64)).norm()
        })
        .fold(0.0, f64::max);
    let attitude = a
        .iter()
        .zip(b)
        .map(|(x, y)| x.attitude().angle_to(&y.attitude()))
        .fold(0.0, f64::max);
    (omega, attitude)
}

#[test]
fn the_forced_truth_agrees_with_an_independent_double_double_rk4_extrapolated() {
    let forced: Vec<Case> = cases()
        .into_iter()
        .filter(|c| !matches!(c.load, Load::None))
        .collect();
    assert!(!forced.is_empty(), "the study has a forced body");
    let times: Vec<f64> = (1..=UNTIL).map(|k| k as f64).collect();
    for case in &forced {
        let (truth, source) = truth(case, &times).unwrap();
        assert!(source.contains("Taylor"), "{}: {source}", case.name);
        let runs = [1, 2, 4].map(|k| rk4(case, k * COARSEST_STEPS_PER_SECOND));

        let d_coarse = distance(&runs[0], &runs[1]);
        let d_fine = distance(&runs[1], &runs[2]);
        for (what, coarse, fine) in [
            ("|Δω|", d_coarse.0, d_fine.0),
            ("attitude", d_coarse.1, d_fine.1),
        ] {
            let ratio = coarse / fine;
            assert!(
                (14.0..=18.0).contains(&ratio),
                "{}: {what} differences {coarse:e}, {fine:e} fall {ratio}-fold, not ~16",
                case.name
            );
        }

        let first = extrapolate(&runs[0], &runs[1]);
        let best = extrapolate(&runs[1], &runs[2]);
        let (w, a) = distance(&first, &best);
        assert!(
            w < EXTRAPOLATION_BOUND && a < EXTRAPOLATION_BOUND,
            "{}: the extrapolations differ by {w:e} in ω, {a:e} in attitude",
            case.name
        );

        let omega = best
            .iter()
            .zip(&truth)
            .map(|(x, t)| (x.omega_f64() - t.omega).norm())
            .fold(0.0, f64::max);
        let attitude = best
            .iter()
            .zip(&truth)
            .map(|(x, t)| x.attitude().angle_to(&t.orientation))
            .fold(0.0, f64::max);
        assert!(
            omega < TRUTH_BOUND && attitude < TRUTH_BOUND,
            "{}: {source} is off the extrapolated RK4 by {omega:e} (ω), {attitude:e} (attitude)",
            case.name
        );
    }
}
