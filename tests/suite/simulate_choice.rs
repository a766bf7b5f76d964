//! `auto` and `exact` in the simulation driver: the closed form for a torque-free body given
//! by a full (non-diagonal) tensor agrees with a tight DOP853 run, and a torque sends `auto`
//! to the integrator and `exact` to an error.

use kinetics::numeric::rigid_body::exact_propagation::{simulate_choice, Choice, MethodUsed};
use kinetics::numeric::rigid_body::inertia::BodyInertia;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{Method, Problem, Sampling};
use kinetics::numeric::rigid_body::state::RigidBodyState;
use kinetics::numeric::rigid_body::torque::Torque;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

fn rotated_body(torque: Torque<f64>) -> Problem<f64> {
    let r = Rotation3::from_euler_angles(0.3, -0.7, 1.1);
    let tensor =
        r.matrix() * Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)) * r.matrix().transpose();
    Problem {
        inertia: BodyInertia::Tensor(tensor),
        torque,
        initial: RigidBodyState::new(
            Vector3::new(0.4, -1.0, 0.8),
            UnitQuaternion::from_euler_angles(0.2, 0.1, -0.3),
        ),
        start_time: 0.0,
    }
}

fn run(problem: &Problem<f64>, choice: Choice) -> (Vec<Sample<f64>>, MethodUsed) {
    let mut samples = Vec::new();
    let mut sink = |s: Sample<f64>| samples.push(s);
    let sampling = Sampling::Times(vec![0.5, 10.0, 50.0]);
    let (_, used) = simulate_choice(problem, &choice, &sampling, &mut sink, &mut |_| {}).unwrap();
    (samples, used)
}

#[test]
fn exact_agrees_with_tight_dop853_for_a_full_tensor() {
    let problem = rotated_body(Torque::None);
    let (exact, used) = run(&problem, Choice::Auto { rtol: 1e-10 });
    assert_eq!(used, MethodUsed::Exact);
    let (numeric, _) = run(&problem, Choice::Integrate(Method::dop853(1e-13, 1e-15)));
    for (e, n) in exact.iter().zip(&numeric) {
        let dw = (e.omega - n.omega).norm();
        let dq = e.orientation.angle_to(&n.orientation);
        assert!(
            dw < 1e-9 && dq < 1e-9,
            "t = {}: |Δω| = {dw:e}, attitude {dq:e}",
            e.t
        );
    }
}

#[test]
fn a_torque_sends_auto_to_the_integrator_and_exact_to_an_error() {
    let problem = rotated_body(Torque::Body(Vector3::new(0.1, 0.0, 0.0)));
    let (_, used) = run(&problem, Choice::Auto { rtol: 1e-10 });
    assert_eq!(used, MethodUsed::Integrator);
    let mut sink = |_: Sample<f64>| {};
    let err = simulate_choice(
        &problem,
        &Choice::Exact,
        &Sampling::Times(vec![1.0]),
        &mut sink,
        &mut |_| {},
    );
    assert!(err.unwrap_err().to_string().contains("torque-free"));
}
