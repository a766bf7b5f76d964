//! Extreme angular momentum through the simulation driver (`simulate_choice`, as
//! `kinetics simulate` runs it): every method on a torque-free body whose `|H|` is near
//! 1e-150 and 1e150 gives the unit-scale motion, scaled.
//!
//! The motion from `λ ω₀` is the motion from `ω₀` with time scaled by `λ`:
//! `ω(t) = λ ω₁(λ t)`, `q(t) = q₁(λ t)`, `T` scales by `λ²` and `|H|` by `λ`. With `λ` a
//! power of two, dividing the times and the step by `λ` is exact, so the scaled run poses the
//! integrator exactly the unit problem; any difference is the method's own dependence on
//! scale (an absolute constant, an overflow in squaring, an underflow).

use kinetics::numeric::integrators::splitting::SplittingOrder;
use kinetics::numeric::rigid_body::exact_propagation::{simulate_choice, Choice, MethodUsed};
use kinetics::numeric::rigid_body::inertia::BodyInertia;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{Method, Problem, Sampling};
use kinetics::numeric::rigid_body::state::RigidBodyState;
use kinetics::numeric::rigid_body::torque::Torque;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

/// Sample times of the unit-scale run (s); the scaled run samples at `t / λ`.
const TIMES: [f64; 4] = [0.5, 3.0, 10.0, 40.0];

/// Powers of two `λ` giving `|H|` of 1.1e-150 and 1.2e-150, 1.5e150 and 1.6e150 for the
/// bodies below (whose unit-scale `|H|` is about 3.7 and 3.9).
const SCALES: [i32; 2] = [-500, 497];

/// The inertia of a body both as principal moments and as a full tensor (the exact method
/// and the splitting then work in a principal frame of their own).
fn bodies() -> [(&'static str, BodyInertia<f64>, Vector3<f64>); 2] {
    let r = Rotation3::from_euler_angles(0.3, -0.7, 1.1);
    let tensor =
        r.matrix() * Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)) * r.matrix().transpose();
    [
        (
            "principal",
            BodyInertia::Principal(Vector3::new(1.0, 2.0, 3.0)),
            Vector3::new(1.0, 1.0, 1.0),
        ),
        (
            "tensor",
            BodyInertia::Tensor(tensor),
            Vector3::new(0.4, -1.0, 0.8),
        ),
    ]
}

fn problem(inertia: BodyInertia<f64>, omega: Vector3<f64>) -> Problem<f64> {
    Problem {
        inertia,
        torque: Torque::None,
        initial: RigidBodyState::new(omega, UnitQuaternion::from_euler_angles(0.2, 0.1, -0.3)),
        start_time: 0.0,
    }
}

/// Largest [`scaled_difference`] allowed for dop853 with an absolute tolerance. Its
/// `atol = 1e-15` rad/s does not scale with `ω`: at `|ω| ≈ 3e-151` it outweighs `rtol |ω|`
/// and leaves `ω` to the attitude's error control, at `|ω| ≈ 4e149` it vanishes beside it,
/// while at unit scale it is a tenth of a percent of the weight. The two runs are then two
/// different integrations, each good to a few `rtol` (1e-12); their differences measured
/// 1.6e-12 and 3.6e-13 (small `λ`), 4.8e-14 and 1.4e-14 (large), and the bound is ten `rtol`.
const ABSOLUTE_TOLERANCE_DIFFERENCE: f64 = 1e-11;

/// The methods with their time parameters for time scale `1/λ`, and the largest
/// [`scaled_difference`] each may show. Multiplying by a power of two commutes with
/// rounding (away from overflow and subnormals), so a method whose every rule is free of
/// absolute constants gives the unit run's digits exactly, scaled; the bound 0 for those
/// is what was measured, and any absolute constant (an `ε` added to a norm, a smallest step)
/// breaks it.
fn choices(lambda: f64) -> Vec<(&'static str, Choice, f64)> {
    let step = 1e-2 / lambda;
    vec![
        ("auto", Choice::Auto { rtol: 1e-12 }, 0.0),
        ("rk4", Choice::Integrate(Method::Rk4 { step }), 0.0),
        (
            "splitting",
            Choice::Integrate(Method::Splitting {
                step,
                order: SplittingOrder::Fourth,
            }),
            0.0,
        ),
        (
            "splitting (second order)",
            Choice::Integrate(Method::Splitting {
                step,
                order: SplittingOrder::Second,
            }),
            0.0,
        ),
        // A purely relative tolerance: every weight scales with its component.
        (
            "dop853 (atol 0)",
            Choice::Integrate(Method::dop853(1e-12, 0.0)),
            0.0,
        ),
        (
            "vern9 (atol 0)",
            Choice::Integrate(Method::vern9(1e-12, 0.0)),
            0.0,
        ),
        // The tolerances of `kinetics simulate --method dop853 --rtol 1e-12`.
        (
            "dop853",
            Choice::Integrate(Method::dop853(1e-12, 1e-15)),
            ABSOLUTE_TOLERANCE_DIFFERENCE,
        ),
    ]
}

fn run(problem: &Problem<f64>, choice: &Choice, lambda: f64) -> Vec<Sample<f64>> {
    let mut samples = Vec::new();
    let mut sink = |s: Sample<f64>| samples.push(s);
    let sampling = Sampling::Times(TIMES.iter().map(|t| t / lambda).collect());
    let (_, used) = simulate_choice(problem, choice, &sampling, &mut sink, &mut |_| {})
        .unwrap_or_else(|e| panic!("{choice:?} at λ = {lambda:e}: {e}"));
    if matches!(choice, Choice::Auto { .. }) {
        assert_eq!(used, MethodUsed::Exact);
    }
    samples
}

/// The largest relative difference between a scaled run and the unit one scaled: of `ω`
/// (against `|ω|`), of `T` and of `|H|`, and of the attitude quaternion (`|Δq|`, half the
/// angle between the rotations).
fn scaled_difference(scaled: &Sample<f64>, unit: &Sample<f64>, lambda: f64) -> f64 {
    let omega = (scaled.omega / lambda - unit.omega).norm() / unit.omega.norm();
    let energy = (scaled.kinetic_energy / (lambda * lambda) - unit.kinetic_energy).abs()
        / unit.kinetic_energy;
    let momentum = (scaled.angular_momentum_magnitude / lambda - unit.angular_momentum_magnitude)
        .abs()
        / unit.angular_momentum_magnitude;
    let (p, q) = (scaled.orientation.coords, unit.orientation.coords);
    let attitude = (p - q).norm().min((p + q).norm());
    omega.max(energy).max(momentum).max(attitude)
}

#[test]
fn every_method_scales_exactly_to_extreme_angular_momentum() {
    for (body, inertia, omega) in bodies() {
        let unit_problem = problem(inertia, omega);
        for exponent in SCALES {
            let lambda = 2f64.powi(exponent);
            let scaled_problem = problem(inertia, omega * lambda);
            let momentum = inertia.angular_momentum(&(omega * lambda)).norm();
            assert!(
                (1e-150..1e-149).contains(&momentum) || (1e150..1e151).contains(&momentum),
                "|H| = {momentum:e}"
            );
            for ((name, unit_choice, bound), (_, scaled_choice, _)) in
                choices(1.0).into_iter().zip(choices(lambda))
            {
                let unit = run(&unit_problem, &unit_choice, 1.0);
                let scaled = run(&scaled_problem, &scaled_choice, lambda);
                assert_eq!(scaled.len(), TIMES.len());
                let mut worst: f64 = 0.0;
                for ((s, u), t) in scaled.iter().zip(&unit).zip(TIMES) {
                    assert_eq!(s.t, t / lambda);
                    assert!(
                        s.omega
                            .iter()
                            .chain(s.orientation.coords.iter())
                            .all(|v| v.is_finite())
                            && s.kinetic_energy.is_finite()
                            && s.angular_momentum_magnitude.is_finite(),
                        "{body} {name} λ = 2^{exponent}: {s:?}"
                    );
                    worst = worst.max(scaled_difference(s, u, lambda));
                }
                println!("{body} {name} λ = 2^{exponent} (|H| = {momentum:.2e}): {worst:e}");
                assert!(
                    worst <= bound,
                    "{body} {name} at λ = 2^{exponent}: the scaled run differs by {worst:e} \
                     from the unit one scaled (allowed {bound:e})"
                );
            }
        }
    }
}
