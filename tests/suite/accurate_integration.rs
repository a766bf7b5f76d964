//! Accuracy for a thousand periods (issue 36): both adaptive pairs (DOP853 and Verner's
//! 9(8)) follow the closed form as their tolerance tightens, Verner's steps grow as the ninth
//! root of the tolerance, and its
//! dense output between steps is as accurate as its steps; the compensated sums keep the
//! fixed-step methods and DOP853 from losing accuracy to round-off near the separatrix.
//!
//! Truth is the closed-form torque-free motion ([`TorqueFree`], Jacobi elliptic functions),
//! which shares no code with the integrators and agrees with the double-double Taylor
//! reference to 1e-15 on these bodies (`torque_free.rs`).

use kinetics::numeric::integrators::splitting::SplittingOrder;
use kinetics::numeric::rigid_body::inertia::BodyInertia;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{
    simulate, Method, Problem, Sampling, SimulationStatistics,
};
use kinetics::numeric::rigid_body::state::RigidBodyState;
use kinetics::numeric::rigid_body::torque::Torque;
use kinetics::numeric::rigid_body::torque_free::TorqueFree;
use nalgebra::{UnitQuaternion, Vector3};

const MOMENTS: [f64; 3] = [1.0, 2.0, 3.0];

fn free_body(omega: [f64; 3]) -> Problem<f64> {
    Problem {
        inertia: BodyInertia::Principal(Vector3::from(MOMENTS)),
        torque: Torque::None,
        initial: RigidBodyState::new(Vector3::from(omega), UnitQuaternion::identity()),
        start_time: 0.0,
    }
}

/// The largest `|Δω|` against the closed form over the samples of a run, and its counts.
fn error_against_closed_form(
    omega: [f64; 3],
    method: Method<f64>,
    sampling: Sampling<f64>,
) -> (f64, SimulationStatistics) {
    let exact = TorqueFree::new(
        Vector3::from(MOMENTS),
        Vector3::from(omega),
        UnitQuaternion::identity(),
    )
    .unwrap();
    let mut worst = 0.0f64;
    let statistics = simulate(
        &free_body(omega),
        &method,
        &sampling,
        &mut |s: Sample<f64>| worst = worst.max((s.omega - exact.omega(s.t)).norm()),
        &mut |_| {},
    )
    .unwrap();
    (worst, statistics)
}

fn at_the_end(end: f64) -> Sampling<f64> {
    Sampling::Times(vec![end])
}

#[test]
fn both_pairs_follow_the_closed_form_as_their_tolerance_tightens() {
    for (name, make) in [
        ("dop853", Method::dop853 as fn(f64, f64) -> Method<f64>),
        ("vern9", Method::vern9),
    ] {
        let mut previous = f64::INFINITY;
        for rtol in [1e-6, 1e-8, 1e-10, 1e-12] {
            let method = make(rtol, rtol * 1e-2);
            let (error, _) = error_against_closed_form([1.0; 3], method, at_the_end(10.0));
            println!("{name} rtol {rtol:e}: error {error:e}");
            assert!(
                error < 100.0 * rtol,
                "{name} rtol {rtol:e}: error {error:e}"
            );
            assert!(
                error < previous / 10.0,
                "{name}: error {error:e} after {previous:e}"
            );
            previous = error;
        }
    }
}

/// A pair of order p takes steps proportional to rtol^(1/p): from rtol 1e-8 to 1e-12 the
/// count grows by 10^(4/9) = 2.78 for order 9 (DOP853's order 8: 3.16; order 7: 3.59).
#[test]
fn vern9_steps_grow_as_the_ninth_root_of_the_tolerance() {
    let steps = |method| {
        error_against_closed_form([1.0; 3], method, at_the_end(100.0))
            .1
            .steps
    };
    let growth = |make: fn(f64, f64) -> Method<f64>| {
        steps(make(1e-12, 1e-14)) as f64 / steps(make(1e-8, 1e-10)) as f64
    };
    let (vern9, dop853) = (growth(Method::vern9), growth(Method::dop853));
    println!("steps from rtol 1e-8 to 1e-12: vern9 ×{vern9:.3}, dop853 ×{dop853:.3}");
    assert!((2.4..3.0).contains(&vern9), "vern9 ×{vern9}");
    assert!((2.9..3.4).contains(&dop853), "dop853 ×{dop853}");
}

/// Samples every millisecond, twenty or more inside each step, from the order-9 interpolant
/// (in Bernstein form: the published powers of θ lose three digits to cancellation).
#[test]
fn vern9_dense_output_between_steps_is_as_accurate_as_its_steps() {
    let every = Sampling::Every {
        interval: 1e-3,
        end: 10.0,
    };
    let (between, statistics) =
        error_against_closed_form([1.0; 3], Method::vern9(1e-13, 1e-15), every);
    let (ends, _) =
        error_against_closed_form([1.0; 3], Method::vern9(1e-13, 1e-15), at_the_end(10.0));
    println!(
        "vern9 dense output: {} samples over {} steps, error {between:e} (at the end {ends:e})",
        statistics.samples, statistics.steps
    );
    assert!(statistics.steps * 20 < statistics.samples);
    assert!(between < 1e-13, "{between:e}");
}

/// ω₀ = (0.01, 1, 0.01) to t = 1000: DOP853 does not lose accuracy as its tolerance tightens
/// (each tenfold tightening from 1e-8 to 1e-13 ends within a factor 3 of the one before,
/// and rtol 1e-13 within 1e-9).
#[test]
fn dop853_near_the_separatrix_gains_as_rtol_tightens_to_1e13() {
    let omega = [0.01, 1.0, 0.01];
    let samples = Sampling::Every {
        interval: 10.0,
        end: 1000.0,
    };
    let errors: Vec<f64> = [1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13]
        .iter()
        .map(|&rtol| {
            error_against_closed_form(omega, Method::dop853(rtol, rtol * 1e-3), samples.clone()).0
        })
        .collect();
    println!("dop853 near the separatrix, rtol 1e-8 … 1e-13: {errors:?}");
    for pair in errors.windows(2) {
        assert!(pair[1] <= 3.0 * pair[0], "{errors:?}");
    }
    assert!(errors[5] <= 1e-9, "{errors:?}");
}

/// ω₀ = (1e-3, 1, 1e-3) to t = 1000 with a million steps of 1e-3: each step's rounding of
/// `y + Δ` (5e-17) used to add up to 2e-8 for RK4 and 4e-7 for the fourth-order splitting;
/// with the rounding carried they reach 2e-10 and 5e-10.
#[test]
fn a_million_small_steps_do_not_add_up_their_rounding() {
    let omega = [1e-3, 1.0, 1e-3];
    let samples = Sampling::Every {
        interval: 100.0,
        end: 1000.0,
    };
    for (name, method) in [
        ("rk4", Method::Rk4 { step: 1e-3 }),
        (
            "splitting4",
            Method::Splitting {
                step: 1e-3,
                order: SplittingOrder::Fourth,
            },
        ),
    ] {
        let (error, statistics) = error_against_closed_form(omega, method, samples.clone());
        println!("{name}: {} steps, error {error:e}", statistics.steps);
        assert!(error < 2e-9, "{name}: {error:e}");
    }
}
