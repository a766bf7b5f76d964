//! The algebra pipeline for a general body (six inertia components, ω, α): build,
//! canonicalise and print as LaTeX `H = [I]ω`, `T = ½ ωᵀ[I]ω` and `[I]α + ω × ([I]ω)`.
//! For scale: SymEngine does this pipeline in about 0.1 ms and SymPy in 7–25 ms.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kinetics::algebra::{Expr, Matrix, Vector};
use kinetics::print::{self, Axis};

fn pipeline() -> Vec<String> {
    let s = Expr::symbol;
    let inertia = Matrix::new(
        s("I_x"),
        -s("I_xy"),
        -s("I_xz"),
        -s("I_xy"),
        s("I_y"),
        -s("I_yz"),
        -s("I_xz"),
        -s("I_yz"),
        s("I_z"),
    );
    let omega = Vector::new(s("w_x"), s("w_y"), s("w_z"));
    let alpha = Vector::new(s("wdot_x"), s("wdot_y"), s("wdot_z"));
    let h = &inertia * &omega;
    let t = (omega.dot(&h) * Expr::rational(1, 2))
        .expand()
        .expect("small");
    let euler = &inertia * &alpha + omega.cross(&h);
    let axes = [Axis::X, Axis::Y, Axis::Z];
    let mut out: Vec<String> = h.iter().map(print::latex).collect();
    out.push(print::latex(&t));
    for (m, axis) in euler.iter().zip(axes) {
        out.push(print::latex_about(&m.expand().expect("small"), axis));
    }
    out
}

fn bench(c: &mut Criterion) {
    c.bench_function("general body: H, T, Euler built, canonical, LaTeX", |b| {
        b.iter(|| black_box(pipeline()))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
