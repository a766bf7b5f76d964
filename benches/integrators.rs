//! Cost and accuracy of the integrators of Euler's equations on the free body
//! I = (1, 2, 3), ω₀ = (1, 1, 1), q₀ = 1, integrated to t = 100 with one sample at the end.
//! Before timing, each configuration's max |Δω| against the closed-form motion (sampled
//! every 1.0) is printed, and after timing, for DOP853 and Verner's 9(8) pair, the fastest
//! setting of each whose error is at most 1e-11 and the ratio of their times, then their
//! times at exactly that error, each read off its line between the settings that bracket it
//! (`work_precision::equal_error`). For scale: the `ode_solvers` crate's DOP853 takes about
//! 0.16 ms on this problem for an error of 4e-11. The second group integrates ω alone with
//! the same DOP853 (the attitude adds four equations and their error control), in case
//! that figure was measured on ω alone.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kinetics::numeric::integrators::adaptive::AdaptiveSettings;
use kinetics::numeric::integrators::dop853::Dop853;
use kinetics::numeric::integrators::ode::OdeSystem;
use kinetics::numeric::integrators::splitting::SplittingOrder;
use kinetics::numeric::rigid_body::inertia::BodyInertia;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{simulate, Method, Problem, Sampling};
use kinetics::numeric::rigid_body::state::RigidBodyState;
use kinetics::numeric::rigid_body::torque::Torque;
use kinetics::numeric::rigid_body::torque_free::TorqueFree;
use kinetics::numeric::work_precision::equal_error::time_at;
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
    let mut methods: Vec<(String, Method<f64>)> = Vec::new();
    for rtol in [1e-13, 1e-12, 1e-11, 1e-10] {
        methods.push((
            format!("dop853 rtol {rtol:e}"),
            Method::dop853(rtol, rtol * 1e-2),
        ));
        methods.push((
            format!("vern9 rtol {rtol:e}"),
            Method::vern9(rtol, rtol * 1e-2),
        ));
    }
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
    let exact = TorqueFree::new(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(1.0, 1.0, 1.0),
        UnitQuaternion::identity(),
    )
    .expect("the benchmark problem is valid");
    let reference: Vec<Vector3<f64>> = (0..=END as usize).map(|k| exact.omega(k as f64)).collect();
    let end_only = Sampling::Times(vec![END]);
    // (method, max |Δω|, mean time of a run) of the adaptive pairs.
    let mut pairs: Vec<(String, f64, f64)> = Vec::new();
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
        if matches!(method, Method::Dop853 { .. } | Method::Vern9 { .. }) {
            pairs.push((name, error, mean_seconds(&problem, &method, &end_only)));
        }
    }
    group.finish();
    let fastest = |family: &str| {
        pairs
            .iter()
            .filter(|(name, error, _)| name.starts_with(family) && *error <= EQUAL_ERROR)
            .min_by(|a, b| a.2.total_cmp(&b.2))
    };
    if let (Some(dop853), Some(vern9)) = (fastest("dop853"), fastest("vern9")) {
        println!(
            "at max |Δω| ≤ {EQUAL_ERROR:e}: {} {:.1e} in {:.3e} s, {} {:.1e} in {:.3e} s: \
             vern9 {:.2}× as fast",
            dop853.0,
            dop853.1,
            dop853.2,
            vern9.0,
            vern9.1,
            vern9.2,
            dop853.2 / vern9.2
        );
    }
    // The same at exactly the error compared (the settings above land at different ones).
    let at_equal_error = |family: &str| {
        let points: Vec<(f64, f64)> = pairs
            .iter()
            .filter(|(name, _, _)| name.starts_with(family))
            .map(|&(_, error, seconds)| (error, seconds))
            .collect();
        time_at(&points, EQUAL_ERROR)
    };
    if let (Some(dop853), Some(vern9)) = (at_equal_error("dop853"), at_equal_error("vern9")) {
        println!(
            "at max |Δω| = {EQUAL_ERROR:e} (each read off its line, log-log): dop853 {dop853:.3e} s, \
             vern9 {vern9:.3e} s: vern9 {:.2}× as fast",
            dop853 / vern9
        );
    }
}

/// The error at which the pairs are compared.
const EQUAL_ERROR: f64 = 1e-11;

/// Mean wall time of one run, over runs filling at least half a second (for the ratio
/// printed after criterion's own measurements).
fn mean_seconds(problem: &Problem<f64>, method: &Method<f64>, sampling: &Sampling<f64>) -> f64 {
    let started = std::time::Instant::now();
    let mut runs = 0u32;
    while started.elapsed().as_secs_f64() < 0.5 {
        black_box(omegas(problem, method, sampling));
        runs += 1;
    }
    started.elapsed().as_secs_f64() / f64::from(runs)
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
    let settings = AdaptiveSettings::new(rtol, rtol * 1e-2);
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
