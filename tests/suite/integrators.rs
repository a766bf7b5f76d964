//! Integrators of Euler's equations: orders of convergence, dense output, conservation,
//! torques solved by hand, f32 against f64, validation before the first step, streaming.
//!
//! The reference problem is the free body I = (1, 2, 3), ω₀ = (1, 1, 1), q₀ = 1.

use kinetics::mechanics::principal_axes::principal_axes;
use kinetics::numeric::integrators::splitting::SplittingOrder;
use kinetics::numeric::rigid_body::inertia::BodyInertia;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{
    simulate, Method, Problem, Sampling, SimulationStatistics,
};
use kinetics::numeric::rigid_body::state::RigidBodyState;
use kinetics::numeric::rigid_body::torque::Torque;
use kinetics::numeric::NumericError;
use nalgebra::{Matrix3, RealField, Rotation3, UnitQuaternion, Vector3};
use std::cell::Cell;
use std::rc::Rc;

fn free_body<T: RealField + Copy>(moments: [T; 3], omega: [T; 3]) -> Problem<T> {
    Problem {
        inertia: BodyInertia::Principal(Vector3::from(moments)),
        torque: Torque::None,
        initial: RigidBodyState::new(Vector3::from(omega), UnitQuaternion::identity()),
        start_time: T::zero(),
    }
}

fn reference_body() -> Problem<f64> {
    free_body([1.0, 2.0, 3.0], [1.0, 1.0, 1.0])
}

/// All samples of a run, collected (only for runs with few samples).
fn run<T: RealField + Copy>(
    problem: &Problem<T>,
    method: Method<T>,
    sampling: Sampling<T>,
) -> (Vec<Sample<T>>, SimulationStatistics) {
    let mut samples = Vec::new();
    let statistics = simulate(
        problem,
        &method,
        &sampling,
        &mut |s: Sample<T>| samples.push(s),
        &mut |_| {},
    )
    .expect("simulation runs");
    (samples, statistics)
}

fn final_sample(problem: &Problem<f64>, method: Method<f64>, end: f64) -> Sample<f64> {
    *run(problem, method, Sampling::Times(vec![end]))
        .0
        .last()
        .unwrap()
}

const TIGHT: Method<f64> = Method::Dop853 {
    rtol: 1e-14,
    atol: 1e-16,
    max_steps: 1_000_000,
};

fn omega_error(a: &Sample<f64>, b: &Sample<f64>) -> f64 {
    (a.omega - b.omega).amax()
}

#[test]
fn rk4_error_falls_sixteenfold_when_the_step_halves() {
    let body = reference_body();
    let reference = final_sample(&body, TIGHT, 10.0);
    let errors: Vec<f64> = [0.04, 0.02, 0.01]
        .iter()
        .map(|&step| omega_error(&final_sample(&body, Method::Rk4 { step }, 10.0), &reference))
        .collect();
    println!("rk4 errors at t = 10 for h = 0.04, 0.02, 0.01: {errors:?}");
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!((14.0..18.0).contains(&ratio), "ratio {ratio}");
    }
}

#[test]
fn dense_output_between_steps_matches_a_tight_run() {
    let body = reference_body();
    let sampling = Sampling::Every {
        interval: 1e-3,
        end: 10.0,
    };
    let (coarse, statistics) = run(&body, Method::dop853(1e-10, 1e-12), sampling.clone());
    let (tight, _) = run(&body, TIGHT, sampling);
    let error = coarse
        .iter()
        .zip(&tight)
        .map(|(a, b)| omega_error(a, b).max((a.orientation.coords - b.orientation.coords).amax()))
        .fold(0.0, f64::max);
    println!(
        "dense output: {} samples over {} steps, max error {error:e}",
        statistics.samples, statistics.steps
    );
    // Almost every sample lies strictly inside a step...
    assert!(statistics.steps * 20 < statistics.samples);
    // ...and is still as accurate as the step ends.
    assert!(error < 10.0 * 1e-10, "dense output error {error:e}");
}

#[test]
fn principal_frame_and_rotated_tensor_agree_for_nearly_equal_moments() {
    let rotation = Rotation3::from_scaled_axis(Vector3::new(0.7, -0.2, 1.9));
    for gap in [1e-6, 1e-9, 1e-12] {
        let moments = Vector3::new(1.0, 1.0 + gap, 1.6);
        let tensor =
            rotation.matrix() * Matrix3::from_diagonal(&moments) * rotation.matrix().transpose();
        // The user's body frame carries the full tensor; principal_axes finds the frame.
        let axes = principal_axes(&tensor).unwrap();
        let r = axes.rotation;
        let omega = Vector3::new(0.3, -1.2, 0.8);
        let attitude = UnitQuaternion::from_scaled_axis(Vector3::new(0.1, 0.2, 0.3));
        let full = Problem {
            inertia: BodyInertia::Tensor(tensor),
            torque: Torque::None,
            initial: RigidBodyState::new(omega, attitude),
            start_time: 0.0,
        };
        // ω_principal = Rᵀ ω_body, q_principal = q_body ⊗ R.
        let principal = Problem {
            inertia: BodyInertia::Principal(axes.moments),
            torque: Torque::None,
            initial: RigidBodyState::new(
                r.inverse() * omega,
                attitude * UnitQuaternion::from_rotation_matrix(&r),
            ),
            start_time: 0.0,
        };
        let a = final_sample(&full, TIGHT, 100.0);
        let b = final_sample(&principal, TIGHT, 100.0);
        let omega_difference = (a.omega - r * b.omega).norm() / a.omega.norm();
        let attitude_difference = a
            .orientation
            .angle_to(&(b.orientation * UnitQuaternion::from_rotation_matrix(&r.inverse())));
        println!("gap {gap:e}: relative ω difference {omega_difference:e}, attitude {attitude_difference:e} rad");
        assert!(
            omega_difference < 1e-12,
            "gap {gap:e}: {omega_difference:e}"
        );
        assert!(
            attitude_difference < 1e-12,
            "gap {gap:e}: {attitude_difference:e}"
        );
    }
}

/// Largest relative deviation of a sampled quantity from its first value.
fn relative_drift(samples: &[Sample<f64>], quantity: impl Fn(&Sample<f64>) -> f64) -> f64 {
    let first = quantity(&samples[0]);
    samples
        .iter()
        .map(|s| ((quantity(s) - first) / first).abs())
        .fold(0.0, f64::max)
}

#[test]
fn splitting_conserves_angular_momentum_magnitude_to_round_off() {
    let body = reference_body();
    let sampling = Sampling::Every {
        interval: 1.0,
        end: 1000.0,
    };
    for order in [SplittingOrder::Second, SplittingOrder::Fourth] {
        let method = Method::Splitting { step: 0.01, order };
        let (samples, statistics) = run(&body, method, sampling.clone());
        assert_eq!(statistics.steps, 100_000);
        let momentum_drift = relative_drift(&samples, |s| s.angular_momentum_magnitude);
        let energy_drift = relative_drift(&samples, |s| s.kinetic_energy);
        println!(
            "{order:?} splitting, 1e5 steps of 0.01: |H| drift {momentum_drift:e}, energy drift {energy_drift:e}"
        );
        assert!(
            momentum_drift < 1e-13,
            "{order:?}: |H| drift {momentum_drift:e}"
        );
        // Energy is not conserved exactly, but its error stays bounded at O(h^order).
        assert!(
            energy_drift < 1e-4,
            "{order:?}: energy drift {energy_drift:e}"
        );
    }
}

#[test]
fn splitting_converges_at_its_order_and_is_exact_for_an_axisymmetric_body() {
    let body = reference_body();
    let reference = final_sample(&body, TIGHT, 10.0);
    for (order, steps, expected_ratio) in [
        (SplittingOrder::Second, [0.02, 0.01, 0.005], 4.0),
        (SplittingOrder::Fourth, [0.04, 0.02, 0.01], 16.0),
    ] {
        let errors: Vec<f64> = steps
            .iter()
            .map(|&step| {
                let method = Method::Splitting { step, order };
                omega_error(&final_sample(&body, method, 10.0), &reference)
            })
            .collect();
        println!("{order:?} splitting errors at t = 10 for h = {steps:?}: {errors:?}");
        for pair in errors.windows(2) {
            let ratio = pair[0] / pair[1];
            let bounds = 0.85 * expected_ratio..1.15 * expected_ratio;
            assert!(bounds.contains(&ratio), "{order:?}: ratio {ratio}");
        }
    }
    // Axisymmetric (prolate and oblate): the pieces commute and a coarse step is exact.
    for moments in [[1.0, 1.0, 1.5], [1.0, 2.0, 2.0]] {
        let body = free_body(moments, [0.4, -1.3, 2.1]);
        let exact = final_sample(&body, TIGHT, 10.0);
        let coarse = Method::Splitting {
            step: 0.5,
            order: SplittingOrder::Second,
        };
        let split = final_sample(&body, coarse, 10.0);
        let error = omega_error(&split, &exact).max(split.orientation.angle_to(&exact.orientation));
        println!("axisymmetric {moments:?}: splitting with h = 0.5 off by {error:e}");
        assert!(error < 1e-11, "{error:e}");
    }
}

#[test]
fn energy_drift_of_rk4_and_dop853_is_small_and_measured() {
    let body = reference_body();
    let sampling = Sampling::Every {
        interval: 1.0,
        end: 1000.0,
    };
    let (rk4, _) = run(&body, Method::Rk4 { step: 0.01 }, sampling.clone());
    let (dop, statistics) = run(&body, Method::dop853(1e-10, 1e-12), sampling);
    let rk4_energy = relative_drift(&rk4, |s| s.kinetic_energy);
    let rk4_momentum = relative_drift(&rk4, |s| s.angular_momentum_magnitude);
    let dop_energy = relative_drift(&dop, |s| s.kinetic_energy);
    let dop_momentum = relative_drift(&dop, |s| s.angular_momentum_magnitude);
    println!("t = 1000: rk4 h = 0.01 energy drift {rk4_energy:e}, |H| drift {rk4_momentum:e}");
    println!(
        "t = 1000: dop853 rtol 1e-10 ({} steps) energy drift {dop_energy:e}, |H| drift {dop_momentum:e}",
        statistics.steps
    );
    assert!(rk4_energy < 1e-8 && rk4_momentum < 1e-8);
    assert!(dop_energy < 1e-8 && dop_momentum < 1e-8);
}

#[test]
fn f32_and_f64_agree_to_f32_accuracy() {
    let single = free_body([1.0f32, 2.0, 3.0], [1.0, 1.0, 1.0]);
    let double = reference_body();
    let sampling32 = Sampling::Every {
        interval: 0.5f32,
        end: 10.0,
    };
    let sampling64 = Sampling::Every {
        interval: 0.5f64,
        end: 10.0,
    };
    // Same fixed steps on both sides: the difference is f32 round-off alone. DOP853 picks
    // its own steps, so its f32 run, at rtol 2e-6 near the f32 floor of 10 ε = 1.2e-6, is
    // compared with an accurate f64 run (measured 1.7e-5; f64 itself at rtol 2e-6: 1.6e-5).
    for (method32, method64, bound) in [
        (
            Method::Rk4 { step: 0.01f32 },
            Method::Rk4 { step: 0.01 },
            1e-5,
        ),
        (
            Method::Splitting {
                step: 0.01f32,
                order: SplittingOrder::Second,
            },
            Method::Splitting {
                step: 0.01,
                order: SplittingOrder::Second,
            },
            1e-5,
        ),
        (Method::dop853(2e-6f32, 1e-8), TIGHT, 5e-5),
    ] {
        let (a, _) = run(&single, method32, sampling32.clone());
        let (b, _) = run(&double, method64, sampling64.clone());
        assert_eq!(a.len(), b.len());
        let difference = a
            .iter()
            .zip(&b)
            .map(|(s, d)| (s.omega.cast::<f64>() - d.omega).amax())
            .fold(0.0, f64::max);
        println!("{method32:?}: max |ω_f32 − ω_f64| = {difference:e}");
        assert!(difference < bound, "{method32:?}: {difference:e}");
    }
}

#[test]
fn time_dependent_body_torque_on_a_sphere_matches_the_hand_solution() {
    // I = 2 about every axis: ω × Iω = 0, so I ω̇ = M and with M = (sin t, 0, 0)
    // ω_x(t) = ω_x0 + (1 − cos t)/I while ω_y, ω_z stay put.
    let inertia = 2.0;
    let omega0 = Vector3::new(0.3, 0.5, -0.2);
    let problem = Problem {
        inertia: BodyInertia::Principal(Vector3::repeat(inertia)),
        torque: Torque::Function(Box::new(|t: f64, _: &RigidBodyState<f64>| {
            Vector3::new(t.sin(), 0.0, 0.0)
        })),
        initial: RigidBodyState::new(omega0, UnitQuaternion::identity()),
        start_time: 0.0,
    };
    let sampling = Sampling::Every {
        interval: 0.37,
        end: 20.0,
    };
    for (method, bound) in [
        (Method::dop853(1e-10, 1e-12), 1e-9),
        (Method::Rk4 { step: 0.01 }, 1e-9),
    ] {
        let (samples, _) = run(&problem, method, sampling.clone());
        let error = samples
            .iter()
            .map(|s| {
                let exact = omega0 + Vector3::new((1.0 - s.t.cos()) / inertia, 0.0, 0.0);
                (s.omega - exact).amax()
            })
            .fold(0.0, f64::max);
        println!("{method:?}: max error against the hand solution {error:e}");
        assert!(error < bound, "{method:?}: {error:e}");
    }
}

#[test]
fn constant_fixed_frame_torque_changes_fixed_momentum_linearly() {
    // ΣM = Ḣ in the fixed frame: with a constant fixed-frame moment, H_fixed(t) = H₀ + M t
    // whatever the body does.
    let moment = Vector3::new(0.2, -0.1, 0.05);
    let initial = RigidBodyState::new(
        Vector3::new(1.0, 1.0, 1.0),
        UnitQuaternion::from_scaled_axis(Vector3::new(0.3, 0.1, -0.4)),
    );
    let inertia = BodyInertia::Tensor(Matrix3::new(
        1.2, -0.1, 0.05, -0.1, 2.0, 0.0, 0.05, 0.0, 2.9,
    ));
    let problem = Problem {
        inertia,
        torque: Torque::Fixed(moment),
        initial,
        start_time: 0.0,
    };
    let fixed_momentum = |s: &Sample<f64>| s.orientation * inertia.angular_momentum(&s.omega);
    let start = fixed_momentum(&Sample {
        t: 0.0,
        omega: initial.omega,
        orientation: initial.orientation,
        kinetic_energy: 0.0,
        angular_momentum_magnitude: 0.0,
    });
    let sampling = Sampling::Every {
        interval: 0.5,
        end: 10.0,
    };
    for (method, bound) in [
        (Method::dop853(1e-11, 1e-13), 1e-9),
        (Method::Rk4 { step: 0.005 }, 1e-7),
        // The kick is exact and every rotation keeps q H q⁻¹: round-off only.
        (
            Method::Splitting {
                step: 0.05,
                order: SplittingOrder::Second,
            },
            1e-13,
        ),
    ] {
        let (samples, _) = run(&problem, method, sampling.clone());
        let error = samples
            .iter()
            .map(|s| (fixed_momentum(s) - (start + moment * s.t)).amax())
            .fold(0.0, f64::max);
        println!("{method:?}: max |H_fixed − (H₀ + M t)| = {error:e}");
        assert!(error < bound, "{method:?}: {error:e}");
    }
}

#[test]
fn constant_body_torque_on_a_sphere_gives_linear_spin_up() {
    // I ω̇ = M for a sphere: ω(t) = ω₀ + M t / I.
    let moment = Vector3::new(0.3, -0.6, 0.9);
    let omega0 = Vector3::new(1.0, 0.0, -0.5);
    let problem = Problem {
        inertia: BodyInertia::Principal(Vector3::repeat(1.5)),
        torque: Torque::Body(moment),
        initial: RigidBodyState::new(omega0, UnitQuaternion::identity()),
        start_time: 1.0,
    };
    let sampling = Sampling::Times(vec![1.0, 2.5, 4.0, 11.0]);
    for method in [
        Method::dop853(1e-10, 1e-12),
        Method::Rk4 { step: 0.1 },
        Method::Splitting {
            step: 0.1,
            order: SplittingOrder::Second,
        },
    ] {
        let (samples, _) = run(&problem, method, sampling.clone());
        let error = samples
            .iter()
            .map(|s| (s.omega - (omega0 + moment * (s.t - 1.0) / 1.5)).amax())
            .fold(0.0, f64::max);
        println!("{method:?}: max error {error:e}");
        assert!(error < 1e-12, "{method:?}: {error:e}");
    }
}

/// A problem whose torque function counts its evaluations.
fn counted_problem(
    inertia: BodyInertia<f64>,
    omega: Vector3<f64>,
) -> (Problem<f64>, Rc<Cell<usize>>) {
    let calls = Rc::new(Cell::new(0));
    let counter = Rc::clone(&calls);
    let problem = Problem {
        inertia,
        torque: Torque::Function(Box::new(move |_, _| {
            counter.set(counter.get() + 1);
            Vector3::zeros()
        })),
        initial: RigidBodyState::new(omega, UnitQuaternion::identity()),
        start_time: 0.0,
    };
    (problem, calls)
}

/// Name, body, initial ω, sampling and method of a simulation that must be refused.
type RejectedCase = (
    &'static str,
    BodyInertia<f64>,
    Vector3<f64>,
    Sampling<f64>,
    Method<f64>,
);

#[test]
fn bad_input_is_rejected_before_any_step() {
    let good_inertia = BodyInertia::Principal(Vector3::new(1.0, 2.0, 3.0));
    let good_omega = Vector3::new(1.0, 1.0, 1.0);
    let good_sampling = Sampling::Every {
        interval: 0.1,
        end: 1.0,
    };
    let cases: Vec<RejectedCase> = vec![
        (
            "triangle inequality",
            BodyInertia::Principal(Vector3::new(1.0, 1.0, 3.0)),
            good_omega,
            good_sampling.clone(),
            Method::dop853(1e-8, 1e-10),
        ),
        (
            "indefinite tensor",
            BodyInertia::Tensor(Matrix3::new(2.0, -3.0, 0.0, -3.0, 2.0, 0.0, 0.0, 0.0, 2.0)),
            good_omega,
            good_sampling.clone(),
            Method::Rk4 { step: 0.01 },
        ),
        (
            "slender rod",
            BodyInertia::Principal(Vector3::new(0.0, 1.0, 1.0)),
            good_omega,
            good_sampling.clone(),
            Method::Rk4 { step: 0.01 },
        ),
        (
            "NaN ω",
            good_inertia,
            Vector3::new(f64::NAN, 1.0, 1.0),
            good_sampling.clone(),
            Method::dop853(1e-8, 1e-10),
        ),
        (
            "decreasing times",
            good_inertia,
            good_omega,
            Sampling::Times(vec![0.0, 2.0, 1.0]),
            Method::dop853(1e-8, 1e-10),
        ),
        (
            "infinite time",
            good_inertia,
            good_omega,
            Sampling::Times(vec![0.0, f64::INFINITY]),
            Method::Rk4 { step: 0.01 },
        ),
        (
            "negative interval",
            good_inertia,
            good_omega,
            Sampling::Every {
                interval: -0.1,
                end: 1.0,
            },
            Method::Rk4 { step: 0.01 },
        ),
        (
            "zero step",
            good_inertia,
            good_omega,
            good_sampling.clone(),
            Method::Rk4 { step: 0.0 },
        ),
        (
            "rtol below round-off",
            good_inertia,
            good_omega,
            good_sampling.clone(),
            Method::dop853(1e-17, 0.0),
        ),
        (
            "torque function with the splitting",
            good_inertia,
            good_omega,
            good_sampling.clone(),
            Method::Splitting {
                step: 0.01,
                order: SplittingOrder::Second,
            },
        ),
    ];
    for (name, inertia, omega, sampling, method) in cases {
        let physical = name == "triangle inequality" || name == "indefinite tensor";
        let (problem, calls) = counted_problem(inertia, omega);
        let mut samples = 0;
        let result = simulate(
            &problem,
            &method,
            &sampling,
            &mut |_: Sample<f64>| samples += 1,
            &mut |_| {},
        );
        let error = result.expect_err(name);
        println!("{name}: {error}");
        assert_eq!(calls.get(), 0, "{name}: the torque was evaluated");
        assert_eq!(samples, 0, "{name}: a sample was produced");
        if physical {
            assert!(
                matches!(error, NumericError::Physics(_)),
                "{name}: {error:?}"
            );
        } else {
            assert!(
                matches!(error, NumericError::InvalidInput { .. }),
                "{name}: {error:?}"
            );
        }
    }
}

#[test]
fn a_torque_that_turns_nan_stops_with_an_error() {
    let problem = Problem {
        inertia: BodyInertia::Principal(Vector3::new(1.0, 2.0, 3.0)),
        torque: Torque::Function(Box::new(|t: f64, _: &RigidBodyState<f64>| {
            Vector3::repeat(if t > 1.0 { f64::NAN } else { 0.0 })
        })),
        initial: RigidBodyState::new(Vector3::new(1.0, 1.0, 1.0), UnitQuaternion::identity()),
        start_time: 0.0,
    };
    let sampling = Sampling::Times(vec![0.5, 2.0]);
    let mut last_time = None;
    let dop = simulate(
        &problem,
        &Method::dop853(1e-8, 1e-10),
        &sampling,
        &mut |s: Sample<f64>| last_time = Some(s.t),
        &mut |_| {},
    );
    assert!(
        matches!(dop, Err(NumericError::StepSizeUnderflow { .. })),
        "{dop:?}"
    );
    assert_eq!(
        last_time,
        Some(0.5),
        "the sample before the failure was delivered"
    );
    let rk4 = simulate(
        &problem,
        &Method::Rk4 { step: 0.1 },
        &sampling,
        &mut |_: Sample<f64>| {},
        &mut |_| {},
    );
    assert!(
        matches!(rk4, Err(NumericError::NonFinite { .. })),
        "{rk4:?}"
    );
}

#[test]
fn dop853_stops_at_its_step_budget() {
    let result = simulate(
        &reference_body(),
        &Method::Dop853 {
            rtol: 1e-12,
            atol: 1e-14,
            max_steps: 50,
        },
        &Sampling::Times(vec![100.0]),
        &mut |_: Sample<f64>| {},
        &mut |_| {},
    );
    assert!(
        matches!(result, Err(NumericError::StepLimit { max_steps: 50, .. })),
        "{result:?}"
    );
}

/// An interval a thousand times beyond what the whole budget could cover at the step the
/// integrator takes is given up after a hundred steps (a hundredth of a larger budget), not
/// after all of it.
#[test]
fn dop853_gives_up_a_hopeless_interval_early() {
    let result = simulate(
        &reference_body(),
        &Method::Dop853 {
            rtol: 1e-12,
            atol: 1e-14,
            max_steps: 1000,
        },
        &Sampling::Times(vec![1e12]),
        &mut |_: Sample<f64>| {},
        &mut |_| {},
    );
    assert!(
        matches!(result, Err(NumericError::StepBudgetHopeless { steps: 100, needed, .. }) if needed > 1e6),
        "{result:?}"
    );
}

#[test]
fn a_million_samples_stream_through_a_counting_sink() {
    let mut count = 0usize;
    let mut last_t = f64::NEG_INFINITY;
    let mut fractions = Vec::new();
    let statistics = simulate(
        &reference_body(),
        &Method::dop853(1e-10, 1e-12),
        &Sampling::Every {
            interval: 1e-5,
            end: 10.0,
        },
        &mut |s: Sample<f64>| {
            assert!(s.t > last_t);
            last_t = s.t;
            count += 1;
        },
        &mut |fraction| fractions.push(fraction),
    )
    .unwrap();
    assert_eq!(count, 1_000_001);
    assert_eq!(statistics.samples, 1_000_001);
    assert_eq!(last_t, 10.0);
    // Progress: non-decreasing, throttled to about a thousand calls, ending at 1.
    assert!(fractions.windows(2).all(|w| w[0] <= w[1]));
    assert!(
        fractions.len() <= 1002,
        "{} progress calls",
        fractions.len()
    );
    assert_eq!(fractions.last(), Some(&1.0));
}

#[test]
fn a_zero_attitude_quaternion_is_rejected_and_a_rounded_one_normalised() {
    let mut problem = reference_body();
    problem.initial.orientation =
        UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(0.0, 0.0, 0.0, 0.0));
    let result = simulate(
        &problem,
        &TIGHT,
        &Sampling::Times(vec![1.0]),
        &mut |_: Sample<f64>| {},
        &mut |_| {},
    );
    assert!(
        matches!(result, Err(NumericError::InvalidInput { .. })),
        "{result:?}"
    );

    problem.initial.orientation =
        UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(1.0 + 1e-9, 0.0, 0.0, 0.0));
    let (samples, _) = run(
        &problem,
        Method::Rk4 { step: 0.1 },
        Sampling::Times(vec![0.0, 1.0]),
    );
    for sample in samples {
        assert!(
            (sample.orientation.norm() - 1.0).abs() < 1e-15,
            "{}",
            sample.orientation.norm()
        );
    }
}

#[test]
fn right_hand_side_is_the_chapters_cyclic_form() {
    use kinetics::numeric::rigid_body::euler_rhs::EulerRhs;
    let (ix, iy, iz) = (1.0, 2.0, 2.5);
    let omega = Vector3::new(0.3, -0.7, 1.1);
    let moment = Vector3::new(0.2, 0.1, -0.4);
    let torque = Torque::Body(moment);
    let state = RigidBodyState::new(omega, UnitQuaternion::identity());
    let rhs = EulerRhs::new(BodyInertia::Principal(Vector3::new(ix, iy, iz)), &torque).unwrap();
    let alpha = rhs.angular_acceleration(0.0, &state);
    // ΣM_x = I_x ω̇_x − (I_y − I_z) ω_y ω_z and cyclically.
    let (wx, wy, wz) = (omega.x, omega.y, omega.z);
    let textbook = Vector3::new(
        (moment.x + (iy - iz) * wy * wz) / ix,
        (moment.y + (iz - ix) * wz * wx) / iy,
        (moment.z + (ix - iy) * wx * wy) / iz,
    );
    assert!((alpha - textbook).amax() < 1e-15, "{alpha} vs {textbook}");

    // Full tensor with products of inertia: ΣM = [I] ω̇ + ω × [I] ω must hold.
    let tensor = Matrix3::new(1.2, -0.1, 0.05, -0.1, 2.0, 0.0, 0.05, 0.0, 2.9);
    let rhs = EulerRhs::new(BodyInertia::Tensor(tensor), &torque).unwrap();
    let alpha = rhs.angular_acceleration(0.0, &state);
    let residual = tensor * alpha + omega.cross(&(tensor * omega)) - moment;
    assert!(residual.amax() < 1e-15, "residual {residual}");
}
