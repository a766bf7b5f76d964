//! Cost and accuracy of the integrators of Euler's equations on the free body
//! I = (1, 2, 3), ω₀ = (1, 1, 1), q₀ = 1, integrated to t = 100 with one sample at the end.
//! Before timing, each configuration's max |Δω| against a DOP853 run at rtol 1e-14
//! (sampled every 1.0) is printed. For scale: the `ode_solvers` crate's DOP853 takes about
//! 0.16 ms on this problem for an error of 4e-11.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kinetics::numeric::body_inertia::BodyInertia;
use kinetics::numeric::rigid_body_state::RigidBodyState;
use kinetics::numeric::sample_sink::Sample;
use kinetics::numeric::simulate::{simulate, Method, Problem, Sampling};
use kinetics::numeric::splitting::SplittingOrder;
use kinetics::numeric::torque::Torque;
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
    let mut methods = vec![(
        "dop853 rtol 1e-12".to_string(),
        Method::dop853(1e-12, 1e-14),
    )];
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

criterion_group!(benches, integrators);
criterion_main!(benches);
