//! The two scenes of issue 15, each solved by kinetics and checked against a computation
//! written here without the library's mechanics, at several points of the givens:
//!
//! - `free_box_struck_at_corner`: the impulse-momentum equations solved by hand,
//!   `m v̄ = J` and `[I_G] ω = r_A × J` with the box's moments `m (b² + c²)/12`, ...; and,
//!   without those formulas, the box as a grid of point masses whose angular momentum
//!   `Σ Δm ρ × (ω × ρ)` is the angular impulse;
//! - `compound_body_bent_rod`: each arm a row of point masses; the mass centre
//!   `Σ Δm r / Σ Δm`, the kinetic energy `Σ ½ Δm |v̄ + ω × ρ|²` and the angular momentum
//!   `Σ Δm ρ × (ω × ρ)` with `ρ = r − r̄`.

use kinetics::algebra::{Expr, Symbol};
use kinetics::scene::{analyse, parse_scene, Analysis, Value};

type V3 = [f64; 3];

fn load(name: &str) -> Analysis {
    let path = format!(
        "{}/examples/scenes/{name}.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("the example exists");
    let scene = parse_scene(&path, &text).unwrap_or_else(|d| panic!("{}", d.render()));
    analyse(&scene).unwrap_or_else(|d| panic!("{}", d.render()))
}

fn result(analysis: &Analysis, name: &str) -> Value {
    analysis
        .results
        .iter()
        .find(|(r, _)| r.name == name)
        .unwrap_or_else(|| panic!("{name} is requested"))
        .1
        .clone()
}

/// A symbolic scene evaluated where each given takes the value `point` names for it.
fn eval(e: &Expr, point: &[(&str, f64)]) -> f64 {
    let at = |s: Symbol| point.iter().find(|(n, _)| *n == s.name()).map(|p| p.1);
    e.eval(&at).unwrap_or_else(|err| panic!("{e}: {err}"))
}

fn scalar(analysis: &Analysis, name: &str, point: &[(&str, f64)]) -> f64 {
    match result(analysis, name) {
        Value::Scalar(e) => eval(&e, point),
        _ => panic!("{name} is a vector"),
    }
}

fn vector(analysis: &Analysis, name: &str, point: &[(&str, f64)]) -> V3 {
    match result(analysis, name) {
        Value::Vector(v) => [0, 1, 2].map(|k| eval(&v[k], point)),
        _ => panic!("{name} is a scalar"),
    }
}

/// The right side of the relation `name = ...` shown in a step of the plan.
fn shown(analysis: &Analysis, name: &str, point: &[(&str, f64)]) -> f64 {
    let lhs = Expr::symbol(name);
    let relation = analysis
        .plan
        .iter()
        .flat_map(|step| &step.relations)
        .find(|r| r.lhs == lhs)
        .unwrap_or_else(|| panic!("the plan shows {name}"));
    eval(&relation.rhs, point)
}

fn cross(u: V3, v: V3) -> V3 {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

fn add(u: V3, v: V3) -> V3 {
    [u[0] + v[0], u[1] + v[1], u[2] + v[2]]
}

fn scaled(k: f64, u: V3) -> V3 {
    u.map(|x| k * x)
}

fn dot(u: V3, v: V3) -> f64 {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}

/// `Σ Δm ρ × (ω × ρ)` over point masses `(Δm, ρ)` about their mass centre.
fn angular_momentum(points: &[(f64, V3)], omega: V3) -> V3 {
    points.iter().fold([0.0; 3], |h, &(dm, rho)| {
        add(h, scaled(dm, cross(rho, cross(omega, rho))))
    })
}

/// `|x − y|` within `tolerance` of `|y|` (exactly equal when `y` is zero).
fn close(what: &str, x: f64, y: f64, tolerance: f64) {
    assert!(
        (x - y).abs() <= tolerance * y.abs(),
        "{what}: kinetics {x}, independent {y}"
    );
}

/// Each component within `tolerance` of the length of `y`.
fn close_vectors(what: &str, x: V3, y: V3, tolerance: f64) {
    let scale = dot(y, y).sqrt();
    for k in 0..3 {
        assert!(
            (x[k] - y[k]).abs() <= tolerance * scale,
            "{what}[{k}]: kinetics {x:?}, independent {y:?}"
        );
    }
}

/// Deterministic values in [1/2, 5/2) for the givens (a 64-bit LCG, Knuth's MMIX).
fn values(seed: u64, count: usize) -> Vec<f64> {
    let mut state = seed;
    (0..count)
        .map(|_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            0.5 + 2.0 * ((state >> 11) as f64 / (1u64 << 53) as f64)
        })
        .collect()
}

#[test]
fn free_box_struck_at_a_corner_matches_the_hand_solution() {
    let analysis = load("free_box_struck_at_corner");
    for seed in 1..=5 {
        let x = values(seed, 6);
        let point = [
            ("m", x[0]),
            ("a", x[1]),
            ("b", x[2]),
            ("c", x[3]),
            ("F_2", 10.0 * x[4]),
            ("Dt", 0.01 * x[5]),
        ];
        let [m, a, b, c, f, dt] = point.map(|p| p.1);
        // By hand: the impulse J = F Δt j at r_A = (−a/2, −b/2, −c/2) from G.
        let impulse = [0.0, f * dt, 0.0];
        let corner = [-a / 2.0, -b / 2.0, -c / 2.0];
        let angular_impulse = cross(corner, impulse);
        let moments = [
            m * (b * b + c * c) / 12.0,
            m * (c * c + a * a) / 12.0,
            m * (a * a + b * b) / 12.0,
        ];
        let vbar = scaled(1.0 / m, impulse);
        let omega = [0, 1, 2].map(|k| angular_impulse[k] / moments[k]);
        for (k, axis) in ["x", "y", "z"].iter().enumerate() {
            let v = scalar(&analysis, &format!("vbar_{axis}"), &point);
            close(&format!("vbar_{axis}"), v, vbar[k], 1e-12);
            let w = scalar(&analysis, &format!("w_{axis}"), &point);
            close(&format!("w_{axis}"), w, omega[k], 1e-12);
        }
        // Without the moments' formulas: kinetics' ω gives the box, as a grid of point
        // masses, the angular momentum the blow imparted.
        let solved = ["x", "y", "z"].map(|axis| scalar(&analysis, &format!("w_{axis}"), &point));
        let n = 40;
        let cell = |side: f64, i: usize| side * ((i as f64 + 0.5) / n as f64 - 0.5);
        let dm = m / (n * n * n) as f64;
        let grid: Vec<(f64, V3)> = (0..n * n * n)
            .map(|i| {
                (
                    dm,
                    [cell(a, i % n), cell(b, i / n % n), cell(c, i / (n * n))],
                )
            })
            .collect();
        // The midpoint rule's ∫x² over a side is short by 1/n² of it: 6e-4 at n = 40.
        close_vectors(
            "H_G of the grid",
            angular_momentum(&grid, solved),
            angular_impulse,
            1e-3,
        );
    }
}

#[test]
fn compound_bent_rod_matches_point_mass_sums() {
    let analysis = load("compound_body_bent_rod");
    // Point masses at the midpoints of n equal pieces of each arm: the midpoint rule's
    // ∫s² ds is short by 1/(4n²) of it (over a piece's length L/n), 6e-8 at n = 2000.
    let n = 2000;
    for seed in 11..=15 {
        let x = values(seed, 10);
        let names = [
            "m_1", "m_2", "L_1", "L_2", "v_x", "v_y", "v_z", "w_x", "w_y", "w_z",
        ];
        let point: Vec<(&str, f64)> = names.iter().copied().zip(x.iter().copied()).collect();
        let [m1, m2, l1, l2] = [x[0], x[1], x[2], x[3]];
        let vbar = [x[4], x[5], x[6]];
        let omega = [x[7], x[8], x[9]];
        let piece = |i: usize| (i as f64 + 0.5) / n as f64;
        let arm_1 = (0..n).map(|i| (m1 / n as f64, [l1 * piece(i), 0.0, 0.0]));
        let arm_2 = (0..n).map(|i| (m2 / n as f64, [l1, l2 * piece(i), 0.0]));
        let points: Vec<(f64, V3)> = arm_1.chain(arm_2).collect();
        let mass: f64 = points.iter().map(|p| p.0).sum();
        let first_moment = points
            .iter()
            .fold([0.0; 3], |s, &(dm, r)| add(s, scaled(dm, r)));
        let rbar = scaled(1.0 / mass, first_moment);
        for (k, axis) in ["x", "y", "z"].iter().enumerate() {
            let name = format!("rbar_{axis}");
            close(&name, shown(&analysis, &name, &point), rbar[k], 1e-12);
        }
        let from_g: Vec<(f64, V3)> = points
            .iter()
            .map(|&(dm, r)| (dm, add(r, scaled(-1.0, rbar))))
            .collect();
        let energy: f64 = from_g
            .iter()
            .map(|&(dm, rho)| {
                let v = add(vbar, cross(omega, rho));
                0.5 * dm * dot(v, v)
            })
            .sum();
        close("T", scalar(&analysis, "T", &point), energy, 1e-6);
        close_vectors(
            "H_G",
            vector(&analysis, "H_G", &point),
            angular_momentum(&from_g, omega),
            1e-6,
        );
    }
}
