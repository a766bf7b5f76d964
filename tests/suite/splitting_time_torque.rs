//! The Lie–Poisson splitting under moments that vary with time (and attitude): observed
//! orders 2 and 4 against DOP853 at rtol 1e-13, the bookkeeping of the angular momentum
//! (the torque-free pieces keep `q H` to round-off, so it changes exactly by the kicks),
//! the spun-up sphere scene against its closed form, and the refusal of a moment of `ω`.

use kinetics::numeric::integrators::splitting::SplittingOrder;
use kinetics::numeric::rigid_body::inertia::BodyInertia;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{simulate, Method, Problem, Sampling};
use kinetics::numeric::rigid_body::state::RigidBodyState;
use kinetics::numeric::rigid_body::torque::Torque;
use kinetics::numeric::NumericError;
use kinetics::scene::parse::parse_scene;
use kinetics::scene::simulation::problem as scene_problem;
use nalgebra::{UnitQuaternion, Vector3};
use std::process::Command;

const MOMENTS: [f64; 3] = [1.0, 2.0, 3.0];

/// A thruster programme in body axes.
fn body_moment(t: f64) -> Vector3<f64> {
    Vector3::new(0.3 * (2.0 * t).sin(), 0.2 * t.cos(), 0.1 + 0.05 * t)
}

/// A moment fixed in space that varies in time.
fn fixed_moment(t: f64) -> Vector3<f64> {
    Vector3::new(0.2 * t.cos(), 0.2 * (2.0 * t).sin(), 0.1)
}

fn time_torque() -> Torque<f64> {
    Torque::Time(Box::new(body_moment))
}

fn attitude_torque() -> Torque<f64> {
    Torque::Attitude(Box::new(|t, q: &UnitQuaternion<f64>| {
        q.inverse_transform_vector(&fixed_moment(t))
    }))
}

fn problem(torque: Torque<f64>) -> Problem<f64> {
    Problem {
        inertia: BodyInertia::Principal(Vector3::from(MOMENTS)),
        torque,
        initial: RigidBodyState::new(
            Vector3::new(0.4, 1.0, -0.3),
            UnitQuaternion::from_euler_angles(0.1, -0.2, 0.3),
        ),
        start_time: 0.5,
    }
}

fn run(problem: &Problem<f64>, method: Method<f64>, times: &[f64]) -> Vec<Sample<f64>> {
    let mut samples = Vec::new();
    simulate(
        problem,
        &method,
        &Sampling::Times(times.to_vec()),
        &mut |s: Sample<f64>| samples.push(s),
        &mut |_| {},
    )
    .unwrap();
    samples
}

/// Largest `|Δω|` or attitude angle between two runs.
fn distance(a: &[Sample<f64>], b: &[Sample<f64>]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| {
            (x.omega - y.omega)
                .norm()
                .max(x.orientation.angle_to(&y.orientation))
        })
        .fold(0.0, f64::max)
}

#[test]
fn observed_orders_are_two_and_four_for_moments_of_time_and_attitude() {
    let times = [1.5, 3.0, 4.5];
    for (name, make) in [
        ("time", time_torque as fn() -> Torque<f64>),
        ("attitude", attitude_torque),
    ] {
        let p = problem(make());
        let truth = run(&p, Method::dop853(1e-13, 1e-15), &times);
        for (order, steps, expected) in [
            (SplittingOrder::Second, [0.02, 0.01, 0.005], 4.0),
            (SplittingOrder::Fourth, [0.1, 0.05, 0.025], 16.0),
        ] {
            let errors: Vec<f64> = steps
                .iter()
                .map(|&step| distance(&run(&p, Method::Splitting { step, order }, &times), &truth))
                .collect();
            let ratios = [errors[0] / errors[1], errors[1] / errors[2]];
            println!("{name} {order:?}: errors {errors:?}, ratios {ratios:?}");
            assert!(
                errors[2] > 1e-10,
                "{name}: errors must stay above the reference's"
            );
            for r in ratios {
                assert!(
                    (r / expected - 1.0).abs() < 0.12,
                    "{name} {order:?}: ratio {r} not {expected}"
                );
            }
        }
    }
}

/// `∫ M_fixed dt` as the splitting applies it: a Strang step of size `c·h` from `s` kicks
/// by `c·h/2·M(s)` and `c·h/2·M(s + c·h)`.
fn kicked_impulse(start: f64, end: f64, step: f64, weights: &[f64]) -> Vector3<f64> {
    let count = ((end - start) / step).round() as usize;
    let h = (end - start) / count as f64;
    let mut impulse = Vector3::zeros();
    for k in 0..count {
        let mut s = start + h * k as f64;
        for &w in weights {
            impulse += (fixed_moment(s) + fixed_moment(s + w * h)) * (w * h / 2.0);
            s += w * h;
        }
    }
    impulse
}

#[test]
fn the_fixed_frame_momentum_changes_exactly_by_the_kicks() {
    // Under a moment fixed in space, qH changes only in the kicks (by h·M_fixed); the
    // torque-free pieces turn H and q together and keep qH (so |H| too) to round-off.
    let p = problem(attitude_torque());
    let moments = Vector3::from(MOMENTS);
    let fixed_momentum =
        |omega: &Vector3<f64>, q: &UnitQuaternion<f64>| q * omega.component_mul(&moments);
    let h0 = fixed_momentum(&p.initial.omega, &p.initial.orientation);
    let end = 20.5;
    let cube_root_of_two = 2f64.cbrt();
    let outer = 1.0 / (2.0 - cube_root_of_two);
    for (order, weights) in [
        (SplittingOrder::Second, vec![1.0]),
        (
            SplittingOrder::Fourth,
            vec![outer, 1.0 - 2.0 * outer, outer],
        ),
    ] {
        let step = 0.05;
        let last = run(&p, Method::Splitting { step, order }, &[end])[0];
        let expected = h0 + kicked_impulse(0.5, end, step, &weights);
        let defect = (fixed_momentum(&last.omega, &last.orientation) - expected).norm();
        // The true impulse differs by the quadrature error, far above round-off.
        let exact_impulse = Vector3::new(
            0.2 * (end.sin() - 0.5f64.sin()),
            -0.1 * ((2.0 * end).cos() - 1f64.cos()),
            0.1 * (end - 0.5),
        );
        let quadrature = (h0 + exact_impulse - expected).norm();
        println!("{order:?}: |qH − (qH₀ + Σ kicks)| = {defect:e}, quadrature error {quadrature:e}");
        assert!(defect < 1e-12, "{order:?}: {defect:e}");
        assert!(quadrature > 1e3 * defect);
    }
}

#[test]
fn a_moment_of_the_angular_velocity_is_refused_with_the_reason() {
    let p = Problem {
        torque: Torque::Function(Box::new(|_, s: &RigidBodyState<f64>| -0.1 * s.omega)),
        ..problem(Torque::None)
    };
    let error = simulate(
        &p,
        &Method::Splitting {
            step: 0.01,
            order: SplittingOrder::Fourth,
        },
        &Sampling::Times(vec![1.0]),
        &mut |_: Sample<f64>| {},
        &mut |_| {},
    )
    .unwrap_err();
    assert!(matches!(error, NumericError::InvalidInput { .. }));
    let message = error.to_string();
    assert!(
        message.contains("ω frozen") && message.contains("Torque::Time"),
        "{message}"
    );
}

/// `ω_x(t) = w_0 + M_0 (1 − cos pt)/(p I)`, `I = 2/5 m r²`, from the scene's own comment.
fn sphere_closed_form(t: f64) -> Vector3<f64> {
    let (m, r, m0, p, w0, w1) = (5.0, 0.1, 0.02, 2.0, 1.0, 0.5);
    let inertia = 0.4 * m * r * r;
    Vector3::new(w0 + m0 * (1.0 - (p * t).cos()) / (p * inertia), w1, 0.0)
}

fn sphere_scene_path() -> String {
    format!(
        "{}/examples/scenes/spun_up_sphere.scene",
        env!("CARGO_MANIFEST_DIR")
    )
}

#[test]
fn the_spun_up_sphere_scene_is_a_time_torque_and_the_splitting_solves_it() {
    let path = sphere_scene_path();
    let source = std::fs::read_to_string(&path).unwrap();
    let scene = parse_scene(&path, &source).unwrap();
    let p = scene_problem(&scene).unwrap();
    assert!(matches!(p.torque, Torque::Time(_)), "{:?}", p.torque);
    // A sphere's torque-free pieces commute, so the drift is exact and the only error is
    // that of the kicks as a quadrature of ∫ M dt / I: for the Strang step the trapezoid rule,
    // within h²/12 · t · max|f''| = h²/12 · 10 s · M_0 p²/I = h² · 10/3.
    let times = [0.7, 2.5, 10.0];
    for (order, step, bound) in [
        (SplittingOrder::Second, 1e-3, 1e-6 * 10.0 / 3.0),
        (SplittingOrder::Fourth, 1e-2, 1e-9),
    ] {
        let samples = run(&p, Method::Splitting { step, order }, &times);
        let error = samples
            .iter()
            .map(|s| (s.omega - sphere_closed_form(s.t)).amax())
            .fold(0.0, f64::max);
        println!("{order:?} h = {step}: max |ω − closed form| {error:e}");
        assert!(error < bound, "{order:?}: {error:e}");
    }
}

#[test]
fn kinetics_simulate_with_the_splitting_matches_the_closed_form() {
    let out = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args([
            "simulate",
            &sphere_scene_path(),
            "--at",
            "1,2.5,10",
            "--method",
            "splitting",
            "--step",
            "0.01",
        ])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rows: Vec<Vec<f64>> = stdout
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 3);
    for row in rows {
        let exact = sphere_closed_form(row[0]);
        for k in 0..3 {
            assert!(
                (row[1 + k] - exact[k]).abs() < 1e-9,
                "t = {}: ω_{k} = {} vs {}",
                row[0],
                row[1 + k],
                exact[k]
            );
        }
    }
}
