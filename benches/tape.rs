//! The compiled tape against the same formula written by hand and against tree-walking
//! `Expr::eval`, for the general Euler equations in a frame rotating at Ω (§18.5–18.6):
//!
//! ```text
//! ΣM_G = [I]{ω̇} + Ω × ([I]{ω})
//! ```
//!
//! with 9 kinematic inputs (ω, ω̇, Ω) and 6 inertia components → 3 moments; then a batch of
//! 10⁵ parameter sets: a loop of single evaluations, the blocked serial batch, the rayon
//! batch, and the hand-written formula in a loop. "tape native" is the same tape compiled
//! to machine code (`Tape::compile_native`), one point and the rayon batch, and the cost of
//! compiling it.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use kinetics::algebra::{Expr, Symbol, Vector};
use kinetics::mechanics::euler::body_angular_velocity;
use kinetics::mechanics::inertia::InertiaTensor;
use kinetics::mechanics::rotating_frame::rate_of_angular_momentum;
use kinetics::numeric::Tape;

const INPUTS: [&str; 15] = [
    "w_x", "w_y", "w_z", "wdot_x", "wdot_y", "wdot_z", "Omega_x", "Omega_y", "Omega_z", "I_x",
    "I_y", "I_z", "I_xy", "I_yz", "I_xz",
];
const BATCH: usize = 100_000;

/// The chapter's equation as one would type it: `H = [I]ω` with the products of inertia
/// entered with a minus sign, then `[I]ω̇ + Ω × H`.
fn hand_written(p: &[f64]) -> [f64; 3] {
    let [wx, wy, wz, ax, ay, az, ox, oy, oz, ix, iy, iz, ixy, iyz, ixz] = p[..15] else {
        unreachable!("15 inputs")
    };
    let hx = ix * wx - ixy * wy - ixz * wz;
    let hy = -ixy * wx + iy * wy - iyz * wz;
    let hz = -ixz * wx - iyz * wy + iz * wz;
    [
        ix * ax - ixy * ay - ixz * az + (oy * hz - oz * hy),
        -ixy * ax + iy * ay - iyz * az + (oz * hx - ox * hz),
        -ixz * ax - iyz * ay + iz * az + (ox * hy - oy * hx),
    ]
}

fn moments() -> Vec<Expr> {
    let omega = body_angular_velocity();
    let alpha = Vector::new(
        Expr::symbol("wdot_x"),
        Expr::symbol("wdot_y"),
        Expr::symbol("wdot_z"),
    );
    let frame = Vector::new(
        Expr::symbol("Omega_x"),
        Expr::symbol("Omega_y"),
        Expr::symbol("Omega_z"),
    );
    let d = rate_of_angular_momentum(&InertiaTensor::general(), &omega, &alpha, &frame, "G")
        .expect("the general tensor expands");
    d.result().iter().map(|r| r.rhs.clone()).collect()
}

/// A deterministic table of parameter sets (a linear congruential sequence in [0.5, 2.5)).
fn table(sets: usize) -> Vec<f64> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    (0..sets * INPUTS.len())
        .map(|_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            0.5 + 2.0 * (state >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let outputs = moments();
    let symbols: Vec<Symbol> = INPUTS.iter().map(|n| Symbol::new(n)).collect();
    let tape = Tape::compile(&outputs, &symbols).expect("every symbol is an input");
    let native = tape.compile_native().expect("the host is supported");
    let point = table(1);
    let mut out = [0.0; 3];
    let mut scratch = Vec::new();
    tape.eval_with(&point, &mut out, &mut scratch)
        .expect("finite");
    let mut native_out = [0.0; 3];
    native.eval(&point, &mut native_out).expect("finite");
    assert_eq!(out, native_out, "native and interpreted tapes agree");
    let hand = hand_written(&point);
    for (t, h) in out.iter().zip(hand) {
        assert!(
            (t - h).abs() <= 1e-13 * h.abs().max(1.0),
            "tape {t} vs hand {h}"
        );
    }
    println!(
        "tape: {} instructions for {} outputs of {} inputs",
        tape.instruction_count(),
        tape.n_outputs(),
        tape.n_inputs()
    );

    let mut single = c.benchmark_group("general Euler, Ω frame (15 → 3), one point");
    single.bench_function("hand-written", |b| {
        b.iter(|| hand_written(black_box(&point)))
    });
    // The tapes write their outputs into a slice that is handed to `black_box`, not copied
    // out: copying `[f64; 3]` right after the call reads two of the compiled code's 8-byte
    // stores with one 16-byte load, which the processor cannot forward from its store
    // buffer, and that stall (about 3 ns here) would be the benchmark's, not the tape's.
    single.bench_function("tape eval_with f64", |b| {
        b.iter(|| {
            tape.eval_with(black_box(&point), black_box(&mut out), &mut scratch)
                .expect("finite")
        })
    });
    single.bench_function("tape native", |b| {
        b.iter(|| {
            native
                .eval(black_box(&point), black_box(&mut native_out))
                .expect("finite")
        })
    });
    single.bench_function("compile_native (once per tape)", |b| {
        b.iter(|| tape.compile_native().expect("the host is supported"))
    });
    let value = |s: Symbol| symbols.iter().position(|&x| x == s).map(|k| point[k]);
    single.bench_function("Expr::eval (tree walking)", |b| {
        b.iter(|| {
            outputs
                .iter()
                .map(|e| e.eval(&|s| value(black_box(s))).expect("finite"))
                .sum::<f64>()
        })
    });
    single.finish();

    let rows = table(BATCH);
    let n = INPUTS.len();
    let mut batch = c.benchmark_group("general Euler, Ω frame, 1e5 parameter sets");
    batch.sample_size(20);
    batch.bench_function(BenchmarkId::new("hand-written loop", BATCH), |b| {
        b.iter(|| {
            rows.chunks_exact(n)
                .map(|p| hand_written(black_box(p)))
                .collect::<Vec<_>>()
        })
    });
    batch.bench_function(BenchmarkId::new("tape eval_with loop", BATCH), |b| {
        b.iter(|| {
            let mut all = vec![0.0; 3 * BATCH];
            for (p, o) in rows.chunks_exact(n).zip(all.chunks_exact_mut(3)) {
                tape.eval_with(black_box(p), o, &mut scratch)
                    .expect("finite");
            }
            all
        })
    });
    batch.bench_function(BenchmarkId::new("tape eval_batch_serial", BATCH), |b| {
        b.iter(|| tape.eval_batch_serial(black_box(&rows), n).expect("finite"))
    });
    batch.bench_function(BenchmarkId::new("tape eval_batch (rayon)", BATCH), |b| {
        b.iter(|| tape.eval_batch(black_box(&rows), n).expect("finite"))
    });
    batch.bench_function(
        BenchmarkId::new("tape native eval_batch (rayon)", BATCH),
        |b| b.iter(|| native.eval_batch(black_box(&rows), n).expect("finite")),
    );
    batch.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
