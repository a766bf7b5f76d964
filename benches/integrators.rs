//! Cost and accuracy of the integrators of Euler's equations on the free body
//! I = (1, 2, 3), ω₀ = (1, 1, 1), q₀ = 1, integrated to t = 100 with one sample at the end.
//! Before timing, each configuration's max |Δω| against a DOP853 run at rtol 1e-14
//! (sampled every 1.0) is printed. For scale: the `ode_solvers` crate's DOP853 takes about
//! 0.16 ms on this problem for an error of 4e-11. The second group integrates ω alone with
//! the same DOP853 (the attitude adds four equations and their error control), in case
//! that figure was measured on ω alone.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kinetics::numeric::integrators::dop853::{Dop853, Dop853Settings};
use kinetics::numeric::integrators::ode::OdeSystem;
use kinetics::numeric::integrators::splitting::SplittingOrder;
use kinetics::numeric::rigid_body::inertia::BodyInertia;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{simulate, Method, Problem, Sampling};
use kinetics::numeric::rigid_body::state::RigidBodyState;
use kinetics::numeric::rigid_body::torque::Torque;
use nalgebra::{UnitQuaternion, Vector3};

const END: f64 = 100.0;

fn body() -> Problem<f64> {
    Problem {
        inertia: BodyInertia::Principal(Vector3::new(1.0, 2.0, 3.0)),
        torque: Torque::None,
        initial: RigidBodyState::new(Vector3::new(1.0, 1.0, 1.0), UnitQuaternion::identity()),
        start_time: 0.0,
    }
}

fn omegas(
    problem: &Problem<f64>,
    method: &Method<f64>,
    sampling: &Sampling<f64>,
) -> Vec<Vector3<f64>> {
    let mut omegas = Vec::new();
    simulate(
        problem,
        method,
        sampling,
        &mut |s: Sample<f64>| omegas.push(s.omega),
        &mut |_| {},
    )
    .expect("the benchmark problem is valid");
    omegas
}

fn methods() -> Vec<(String, Method<f64>)> {
    let mut methods: Vec<(String, Method<f64>)> = [1e-12, 1e-11, 1e-10]
        .iter()
        .map(|&rtol| {
            (
                format!("dop853 rtol {rtol:e}"),
                Method::dop853(rtol, rtol * 1e-2),
            )
        })
        .collect();
    for step in [0.01, 0.001] {
        methods.push((format!("rk4 h {step}"), Method::Rk4 { step }));
        for order in [SplittingOrder::Second, SplittingOrder::Fourth] {
            methods.push((
                format!("splitting {order:?} h {step}"),
                Method::Splitting { step, order },
            ));
        }
    }
    methods
}

fn integrators(c: &mut Criterion) {
    let problem = body();
    let trajectory = Sampling::Every {
        interval: 1.0,
        end: END,
    };
    let reference = omegas(&problem, &Method::dop853(1e-14, 1e-16), &trajectory);
    let end_only = Sampling::Times(vec![END]);
    let mut group = c.benchmark_group("free body I=(1,2,3) to t=100");
    for (name, method) in methods() {
        let error = omegas(&problem, &method, &trajectory)
            .iter()
            .zip(&reference)
            .map(|(a, b)| (a - b).amax())
            .fold(0.0, f64::max);
        let statistics = simulate(
            &problem,
            &method,
            &end_only,
            &mut |_: Sample<f64>| {},
            &mut |_| {},
        )
        .expect("the benchmark problem is valid");
        println!(
            "{name}: max |Δω| = {error:.1e} ({} steps, {} evaluations)",
            statistics.steps, statistics.evaluations
        );
        group.bench_function(&name, |b| {
            b.iter(|| {
                let mut last = Vector3::zeros();
                simulate(
                    black_box(&problem),
                    &method,
                    &end_only,
                    &mut |s: Sample<f64>| last = s.omega,
                    &mut |_| {},
                )
                .expect("the benchmark problem is valid");
                last
            })
        });
    }
    group.finish();
}

/// Euler's equations for ω alone, `I ω̇ = (I ω) × ω` (no attitude), to time the DOP853
/// core without the attitude.
struct ReducedEuler {
    moments: Vector3<f64>,
}

impl OdeSystem<f64, 3> for ReducedEuler {
    fn derivative(&self, _t: f64, omega: &Vector3<f64>) -> Vector3<f64> {
        self.moments
            .component_mul(omega)
            .cross(omega)
            .component_div(&self.moments)
    }
}

fn reduced_final_omega(rtol: f64) -> (Vector3<f64>, usize) {
    let system = ReducedEuler {
        moments: Vector3::new(1.0, 2.0, 3.0),
    };
    let settings = Dop853Settings::new(rtol, rtol * 1e-2);
    let mut integrator = Dop853::new(&system, 0.0, Vector3::repeat(1.0), END, settings)
        .expect("the benchmark problem is valid");
    while integrator.t() < END {
        integrator
            .step(&system)
            .expect("the benchmark problem is valid");
    }
    (*integrator.y(), integrator.statistics().accepted_steps)
}

fn reduced_dop853(c: &mut Criterion) {
    let (reference, _) = reduced_final_omega(1e-14);
    let mut group = c.benchmark_group("ω only, I=(1,2,3) to t=100");
    for rtol in [1e-12, 1e-11, 1e-10] {
        let (omega, steps) = reduced_final_omega(rtol);
        let error = (omega - reference).amax();
        println!("dop853 ω only rtol {rtol:e}: |Δω(100)| = {error:.1e} ({steps} steps)");
        group.bench_function(format!("dop853 rtol {rtol:e}"), |b| {
            b.iter(|| reduced_final_omega(black_box(rtol)))
        });
    }
    group.finish();
}

criterion_group!(benches, integrators, reduced_dop853);
criterion_main!(benches);
