//! Issue 18, item 2: a body's orientation (rotation sequences about the fixed frame's axes, an
//! arbitrary axis, direction cosines) and units inside a scene's mathematics, each checked
//! against a computation written here:
//!
//! - each new form's rotation against matrices written by hand: products of elementary
//!   rotations, Rodrigues' formula by hand (exact where it should be: √2 stays √2), columns of
//!   direction cosines;
//! - `disk_tilted_on_shaft`: H_G, T and the bearing reactions against the disk as point
//!   masses (Gauss–Legendre in the radius, equal steps in the angle, exact for these
//!   polynomial and trigonometric integrands) and against the hand derivation in its comment,
//!   at the scene's values and at other values of the givens;
//! - units inside positions and expressions give exactly the scene of the SI numbers;
//! - every new error through the binary, at its place in the file, with its reason.

use crate::common::binary::kinetics;
use kinetics::algebra::{Expr, Symbol};
use kinetics::scene::{analyse, parse_scene, Analysis, Scene, Value};
use std::f64::consts::PI;

type M3 = [[f64; 3]; 3];
type V3 = [f64; 3];

fn scene(text: &str) -> Scene {
    parse_scene("t.scene", text).unwrap_or_else(|d| panic!("{}", d.render()))
}

/// The first body's rotation of a scene whose body line is `body`, evaluated.
fn rotation_of(body: &str) -> M3 {
    let text = format!(
        "given M = 2 kg\ngiven beta = 10 deg\n{body}\nfixed point\nomega = 3 rad/s*i\nfind T"
    );
    let s = scene(&text);
    let r = &s.parts[0].rotation;
    let value = |sym: Symbol| s.value(sym);
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| r[(i, j)].eval(&value).unwrap()))
}

fn product(a: M3, b: M3) -> M3 {
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

fn r_x(t: f64) -> M3 {
    [
        [1.0, 0.0, 0.0],
        [0.0, t.cos(), -t.sin()],
        [0.0, t.sin(), t.cos()],
    ]
}

fn r_y(t: f64) -> M3 {
    [
        [t.cos(), 0.0, t.sin()],
        [0.0, 1.0, 0.0],
        [-t.sin(), 0.0, t.cos()],
    ]
}

fn r_z(t: f64) -> M3 {
    [
        [t.cos(), -t.sin(), 0.0],
        [t.sin(), t.cos(), 0.0],
        [0.0, 0.0, 1.0],
    ]
}

fn same_matrix(what: &str, kinetics: M3, hand: M3) {
    for i in 0..3 {
        for j in 0..3 {
            assert!(
                (kinetics[i][j] - hand[i][j]).abs() <= 1e-15,
                "{what}: kinetics {kinetics:?}, by hand {hand:?}"
            );
        }
    }
}

const DEG: f64 = PI / 180.0;

#[test]
fn a_sequence_turns_about_the_fixed_axes_in_the_order_written() {
    let r = rotation_of("body disk(1 m) mass M rotated 30 deg about z, then 20 deg about x");
    same_matrix("z then x", r, product(r_x(20.0 * DEG), r_z(30.0 * DEG)));
    let r = rotation_of("body disk(1 m) mass M rotated 20 deg about x, then 30 deg about z");
    same_matrix("x then z", r, product(r_z(30.0 * DEG), r_x(20.0 * DEG)));
    let r = rotation_of(
        "body rod(1 m) mass M rotated 10 deg about y, then beta about z, then -40 deg about x",
    );
    let hand = product(r_x(-40.0 * DEG), product(r_z(10.0 * DEG), r_y(10.0 * DEG)));
    same_matrix("three", r, hand);
}

#[test]
fn along_comes_before_the_rotations() {
    // along y: x' -> y, y' -> z, z' -> x; the columns are the own axes in the frame.
    let along_y = [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let along_z = [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]];
    same_matrix(
        "along y",
        rotation_of("body rod(1 m) mass M along y"),
        along_y,
    );
    same_matrix(
        "along z",
        rotation_of("body rod(1 m) mass M along z"),
        along_z,
    );
    let r = rotation_of("body plate(1 m, 2 m) mass M along y rotated beta about z");
    same_matrix("along y, then z", r, product(r_z(10.0 * DEG), along_y));
}

/// Rodrigues' formula written out: `R = cos θ 1 + sin θ [n]ₓ + (1 − cos θ) n nᵀ`.
fn rodrigues(a: V3, t: f64) -> M3 {
    let length = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    let n = a.map(|x| x / length);
    let cross = [[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]];
    [0, 1, 2].map(|i| {
        [0, 1, 2].map(|j| {
            let identity = if i == j { 1.0 } else { 0.0 };
            t.cos() * identity + t.sin() * cross[i][j] + (1.0 - t.cos()) * n[i] * n[j]
        })
    })
}

#[test]
fn a_rotation_about_a_direction_is_rodrigues_and_exact() {
    let r = rotation_of("body rod(1 m) mass M rotated 2 deg about (0, 1, 1)");
    same_matrix("(0, 1, 1)", r, rodrigues([0.0, 1.0, 1.0], 2.0 * DEG));
    let r = rotation_of("body rod(1 m) mass M rotated -75 deg about (3, -4, 12)");
    same_matrix("(3, -4, 12)", r, rodrigues([3.0, -4.0, 12.0], -75.0 * DEG));
    let r = rotation_of("body rod(1 m) mass M rotated 120 deg about (2 mm, 2 mm, 2 mm)");
    // A third of a turn about the diagonal relabels the axes: x -> y -> z -> x.
    same_matrix(
        "diagonal",
        r,
        [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
    );

    // Exact: about (0, 1, 1) by θ, R_xy = -sin θ n_z = -sin θ/√2 and R_yz = (1 - cos θ)/2.
    let s = scene("given M = 2 kg\ngiven theta : rad\nbody rod(1 m) mass M rotated theta about (0, 1, 1)\nfixed point\nomega = 3 rad/s*i\nfind T");
    let r = &s.parts[0].rotation;
    let theta = Expr::symbol("theta");
    let (sin, cos) = (
        Expr::func(kinetics::algebra::Func::Sin, theta.clone()),
        Expr::func(kinetics::algebra::Func::Cos, theta),
    );
    let root_two = Expr::int(2).checked_pow(&Expr::rational(1, 2)).unwrap();
    assert_eq!(r[(0, 1)], -(sin * root_two) / Expr::int(2));
    assert_eq!(r[(1, 2)], (Expr::one() - cos) / Expr::int(2));
}

#[test]
fn direction_cosines_are_the_columns() {
    let r = rotation_of("body rod(1 m) mass M axes (0.6, 0.8, 0), (-0.8, 0.6, 0), (0, 0, 1)");
    same_matrix(
        "decimals",
        r,
        [[0.6, -0.8, 0.0], [0.8, 0.6, 0.0], [0.0, 0.0, 1.0]],
    );
    let r = rotation_of("body rod(1 m) mass M axes(0, 1, 0), (0, 0, 1), (1, 0, 0)");
    same_matrix(
        "no blank before the triples",
        r,
        rotation_of("body rod(1 m) mass M along y"),
    );
    // Exactly symbolic: the columns of R_z(β) are accepted (sin² + cos² = 1) and are R_z(β).
    let by_cosines = scene("given M = 2 kg\ngiven beta : rad\nbody rod(1 m) mass M axes (cos(beta), sin(beta), 0), (-sin(beta), cos(beta), 0), (0, 0, 1)\nfixed point\nomega = 3 rad/s*i\nfind T");
    let by_rotation = scene("given M = 2 kg\ngiven beta : rad\nbody rod(1 m) mass M rotated beta about z\nfixed point\nomega = 3 rad/s*i\nfind T");
    assert_eq!(by_cosines.parts[0].rotation, by_rotation.parts[0].rotation);
    // Written to ten digits, 1/√2 passes (to 1e-9).
    let r = rotation_of(
        "body rod(1 m) mass M axes (0.7071067812, 0.7071067812, 0), (-0.7071067812, 0.7071067812, 0), (0, 0, 1)",
    );
    let hand = r_z(45.0 * DEG);
    for i in 0..3 {
        for j in 0..3 {
            assert!((r[i][j] - hand[i][j]).abs() < 1e-10, "ten digits: {r:?}");
        }
    }
}

fn example() -> (Scene, Analysis) {
    let path = crate::common::binary::scene("disk_tilted_on_shaft");
    let text = std::fs::read_to_string(&path).expect("the example exists");
    let s = parse_scene(&path, &text).unwrap_or_else(|d| panic!("{}", d.render()));
    let a = analyse(&s).unwrap_or_else(|d| panic!("{}", d.render()));
    (s, a)
}

fn result(a: &Analysis, name: &str) -> Value {
    let found = a.results.iter().find(|(r, _)| r.name == name);
    found
        .unwrap_or_else(|| panic!("{name} is requested"))
        .1
        .clone()
}

fn cross(u: V3, v: V3) -> V3 {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

/// The disk of mass `m`, radius `r` and axis x' turned by `beta` about z, as point masses:
/// 3 Gauss–Legendre radii (exact for ∫ρ³ dρ) times 16 equal angles (exact for cos² and sin²).
fn disk_points(m: f64, r: f64, beta: f64) -> Vec<(f64, V3)> {
    let nodes = [
        (-(0.6f64).sqrt(), 5.0 / 9.0),
        (0.0, 8.0 / 9.0),
        ((0.6f64).sqrt(), 5.0 / 9.0),
    ];
    let turn = r_z(beta);
    let mut points = Vec::new();
    for (x, w) in nodes {
        let rho = r * (x + 1.0) / 2.0;
        // ∫∫ σ ρ dρ dφ with σ = m/(π r²): weight w r/2 for dρ, 2π/16 for dφ.
        let ring = m / (PI * r * r) * rho * w * r / 2.0 * (2.0 * PI / 16.0);
        for k in 0..16 {
            let phi = 2.0 * PI * f64::from(k) / 16.0;
            let own = [0.0, rho * phi.cos(), rho * phi.sin()];
            let frame = [0, 1, 2].map(|i| (0..3).map(|j| turn[i][j] * own[j]).sum());
            points.push((ring, frame));
        }
    }
    points
}

fn close(what: &str, kinetics: f64, independent: f64, scale: f64) {
    assert!(
        (kinetics - independent).abs() <= 1e-12 * scale,
        "{what}: kinetics {kinetics}, independent {independent}"
    );
}

#[test]
fn the_tilted_disk_against_point_masses_and_the_hand_derivation() {
    let (s, a) = example();
    let d = 0.15;
    let given = |name: &str| s.value(Symbol::new(name)).expect("a value");
    let scene_values = [
        ("m", given("m")),
        ("r", given("r")),
        ("beta", given("beta")),
        ("w", given("w")),
    ];
    assert_eq!(
        scene_values.map(|(_, v)| v),
        [4.0, 0.12, PI / 18.0, 40.0 * PI]
    );
    let other = [("m", 1.7), ("r", 0.31), ("beta", 0.4), ("w", 12.5)];
    for values in [scene_values, other] {
        let at = |sym: Symbol| values.iter().find(|(n, _)| *n == sym.name()).map(|p| p.1);
        let eval = |e: &Expr| e.eval(&at).unwrap_or_else(|err| panic!("{e}: {err}"));
        let [m, r, beta, w] = values.map(|(_, v)| v);
        let omega = [w, 0.0, 0.0];
        // Point masses: H_G = Σ Δm ρ × (ω × ρ), T = ½ Σ Δm |ω × ρ|².
        let points = disk_points(m, r, beta);
        let mut h = [0.0; 3];
        let mut t = 0.0;
        for (dm, rho) in &points {
            let v = cross(omega, *rho);
            let moment = cross(*rho, v);
            for k in 0..3 {
                h[k] += dm * moment[k];
            }
            t += 0.5 * dm * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        }
        // By hand (the example's comment).
        let quarter = m * r * r * w / 4.0;
        let hand_h = [
            quarter * (1.0 + beta.cos().powi(2)),
            quarter * beta.sin() * beta.cos(),
            0.0,
        ];
        let hand_t = m * r * r * w * w / 8.0 * (1.0 + beta.cos().powi(2));
        let Value::Vector(kinetics_h) = result(&a, "H_G") else {
            panic!("H_G is a vector")
        };
        let Value::Scalar(kinetics_t) = result(&a, "T") else {
            panic!("T is a scalar")
        };
        let scale = hand_h[0].abs();
        for k in 0..3 {
            close("H_G by point masses", eval(&kinetics_h[k]), h[k], scale);
            close("H_G by hand", eval(&kinetics_h[k]), hand_h[k], scale);
        }
        close("T by point masses", eval(&kinetics_t), t, t);
        close("T by hand", eval(&kinetics_t), hand_t, t);
        // Ḣ_G = ω × H_G (ω constant, the disk turning with it); ΣF = 0 and ΣM_O = Ḣ_G with A at
        // x = -d and B at x = d: 2 d B_y = Ḣ_z, A_y = -B_y, and A_z = B_z = 0.
        let h_dot = cross(omega, h);
        let b_y = h_dot[2] / (2.0 * d);
        let hand_b_y = m * r * r * w * w * beta.sin() * beta.cos() / (8.0 * d);
        close("B_y, hand", b_y, hand_b_y, hand_b_y);
        for (name, expected) in [("A_y", -b_y), ("B_y", b_y), ("A_z", 0.0), ("B_z", 0.0)] {
            let Value::Scalar(e) = result(&a, name) else {
                panic!("{name} is a scalar")
            };
            close(name, eval(&e), expected, b_y.abs());
        }
    }
}

#[test]
fn the_reactions_are_forces_in_newtons() {
    let (code, out, err) = kinetics(&[
        "solve",
        &crate::common::binary::scene("disk_tilted_on_shaft"),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("B_y = 5/12*m*r^2*sin(2*beta)*w^2 = 129.6 N\n"),
        "{out}"
    );
    assert!(
        out.contains("T = 1/8*m*r^2*(cos(beta)^2 + 1)*w^2 = 224.0 J"),
        "{out}"
    );
}

/// The example's text with `replace` pairs applied.
fn example_with(replace: &[(&str, &str)]) -> Scene {
    let path = crate::common::binary::scene("disk_tilted_on_shaft");
    let mut text = std::fs::read_to_string(&path).expect("the example exists");
    for (from, to) in replace {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    scene(&text)
}

#[test]
fn units_inside_positions_give_the_scene_of_the_si_numbers() {
    let (written, _) = example();
    let in_metres = example_with(&[("-150 mm", "-15 cm"), ("(150 mm", "(0.5 ft - 2.4 mm")]);
    assert_eq!(written.forces, in_metres.forces);
    let three_twentieths = Expr::rational(3, 20);
    assert_eq!(written.forces[1].point[0], three_twentieths);
    assert_eq!(written.forces[0].point[0], -&three_twentieths);
    // The same scene with d a given of 0.15 m: every result, with d = 3/20, is exactly the same.
    let with_d = example_with(&[
        ("given w = 1200 rpm", "given w = 1200 rpm\ngiven d = 0.15 m"),
        ("(-150 mm, 0, 0)", "(-d, 0, 0)"),
        ("(150 mm, 0, 0)", "(d, 0, 0)"),
    ]);
    let by_d = analyse(&with_d).unwrap();
    let (_, literal) = example();
    let d = |s: Symbol| (s.name() == "d").then(|| three_twentieths.clone());
    for ((request, value), (_, literal_value)) in by_d.results.iter().zip(&literal.results) {
        let pairs: Vec<(Expr, Expr)> = match (value, literal_value) {
            (Value::Scalar(a), Value::Scalar(b)) => vec![(a.clone(), b.clone())],
            (Value::Vector(a), Value::Vector(b)) => {
                (0..3).map(|k| (a[k].clone(), b[k].clone())).collect()
            }
            _ => panic!("{} changed kind", request.name),
        };
        for (by_given, by_unit) in pairs {
            let difference = (by_given.subs(&d).unwrap() - by_unit).expand().unwrap();
            assert!(difference.is_zero(), "{}: {difference}", request.name);
        }
    }
    // Units in other expressions: mass, ω and a force, exact in SI.
    let s = scene("body point() mass 20 g at (300 mm, 0, 0)\nfixed point\nomega = 1200 rpm*k\nforce P = 2 kN*j at (0, 1 ft, 0)\nfind T");
    assert_eq!(s.parts[0].mass, Expr::rational(1, 50));
    assert_eq!(s.parts[0].position[0], Expr::rational(3, 10));
    assert_eq!(s.omega.as_ref().unwrap()[2], Expr::int(40) * Expr::pi());
    assert_eq!(s.forces[0].value[1], Expr::int(2000));
    assert_eq!(s.forces[0].point[1], Expr::rational(3048, 10000));
    // A compound unit after a number, and a given named like a unit read as the given.
    let s = scene("given g = 2 m\ngiven m = 3 kg\nbody rod(2 g) mass 4 m at (0, 0, 0)\nfixed point\nomega = 30 deg/s*i\nfind T");
    assert_eq!(s.parts[0].mass, Expr::int(4) * Expr::symbol("m"));
    assert_eq!(s.omega.as_ref().unwrap()[0], Expr::pi() / Expr::int(6));
}

/// Runs `kinetics solve` on `text`: the error's first line and the whole standard error.
fn refused(text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("kinetics-orient-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!(
        "{:x}.scene",
        text.len() * 7919 + text.bytes().map(usize::from).sum::<usize>()
    ));
    std::fs::write(&path, text).unwrap();
    let (code, _, err) = kinetics(&["solve", path.to_str().unwrap()]);
    assert_eq!(code, 1, "{text} was accepted");
    err
}

const BODY_BEFORE: &str = "given M = 2 kg\n";
const BODY_AFTER: &str = "\nfixed point\nomega = 3 rad/s*i\nfind T\n";

/// `body` refused: its message holds `message`, at line 2 and `column`.
fn body_refused(body: &str, column: usize, message: &str) -> String {
    let err = refused(&format!("{BODY_BEFORE}{body}{BODY_AFTER}"));
    assert!(err.contains(message), "{err}");
    assert!(err.contains(&format!(".scene:2:{column}\n")), "{err}");
    err
}

#[test]
fn every_new_error_is_located_with_its_reason() {
    body_refused(
        "body rod(1 m) mass M rotated 2 deg about (0, 0, 0)",
        42,
        "a rotation about a zero direction has no axis",
    );
    body_refused(
        "body rod(1 m) mass M rotated 2 deg about (0, 1 mm - 1 mm, 0)",
        42,
        "a rotation about a zero direction has no axis",
    );
    let err = body_refused(
        "body rod(1 m) mass M axes (1, 1, 0), (0, 1, 0), (0, 0, 1)",
        27,
        "these direction cosines are not a rotation: x' is not a unit vector (its length squared is 2, not 1); x' and y' are not perpendicular (x'·y' is 1, not 0)",
    );
    assert!(
        err.contains("unit vectors, each perpendicular to the others"),
        "{err}"
    );
    body_refused(
        "body rod(1 m) mass M axes (1, 0, 0), (0, 1, 0), (0, 0, -1)",
        22,
        "x', y', z' are left-handed",
    );
    body_refused(
        "body rod(1 m) mass M axes (1, 0, 0), (0, 0.8, 0.6), (0, 0.6, 0.8)",
        38,
        "y' and z' are not perpendicular (y'·z' is 0.96, not 0)",
    );
    body_refused(
        "body rod(1 m) mass M axes (0.707, 0.707, 0), (-0.707, 0.707, 0), (0, 0, 1)",
        27,
        "x' is not a unit vector (its length squared is 0.999698, not 1)",
    );
    let err = refused("given M = 2 kg\ngiven a : rad\nbody rod(1 m) mass M axes (a, 0, 0), (0, 1, 0), (0, 0, 1)\nfixed point\nomega = 3 rad/s*i\nfind T\n");
    assert!(
        err.contains("x' is not a unit vector (its length squared is not shown to be 1)"),
        "{err}"
    );
    // The sequence's comma is required; the hint shows each form.
    let err = body_refused(
        "body rod(1 m) mass M rotated 30 deg about z then 20 deg about x",
        45,
        "cannot read this 'body' statement (found 't', expected ',')",
    );
    assert!(
        err.contains("then 20 deg about x  or  ... rotated 2 deg about (0, 1, 1)"),
        "{err}"
    );
    // A unit of the wrong kind, and a declared name that is also a unit.
    let err = body_refused(
        "body rod(1 m) mass M at (300 g, 0, 0)",
        26,
        "unit mismatch: expected a quantity in m, found kg",
    );
    assert!(
        err.contains("'g' after a number is the unit g here"),
        "{err}"
    );
    let err =
        refused("given m = 2 kg\nbody rod(2 m) mass m\nfixed point\nomega = 3 rad/s*i\nfind T\n");
    assert!(
        err.contains("unit mismatch: expected a quantity in m, found kg"),
        "{err}"
    );
    assert!(err.contains(".scene:2:10\n"), "{err}");
    assert!(
        err.contains("'m' here is the declared m, not the unit m"),
        "{err}"
    );
    body_refused(
        "body rod(1 m) mass M rotated 30 mm about z",
        30,
        "unit mismatch: expected a quantity in no unit, found m",
    );
    body_refused(
        "body rod(1 m) mass M rotated 2 deg about (1 m, 1, 0)",
        48,
        "unit mismatch: expected a quantity in m, found no unit",
    );
}
