//! `find balance in planes ... at radius r` (issue 18, item 3), checked against computations
//! written here without the library's mechanics:
//!
//! - `rotor_two_unbalance_masses`: the two-plane equations solved by hand (Cramer's rule on
//!   `P_1 + P_2 = -S_x`, `z_A P_1 + z_B P_2 = -I_xz` and likewise in y), the masses
//!   `√(P² + Q²)/r` and angles `atan2(Q, P)` to 4 significant figures; the bearing reactions
//!   before balancing from the point masses' `m e ω²`; the rotor with the hand's correction
//!   masses added as point masses has zero bearing reactions, exactly and in numbers;
//! - a shaft along x with one mass off the axis and no bearings: two equal masses opposite it,
//!   at exactly 180°, and the residual effective force and moments zero.

use crate::common::examples::{analysed_example, result};
use kinetics::algebra::Symbol;
use kinetics::mechanics::two_plane_balance::{Correction, CorrectionAngle};
use kinetics::{analyse, parse_scene, render, Expr, Format, Scene, Value};

/// The rotor's givens in SI, as the scene writes them (g and mm).
const M1: f64 = 0.020;
const M2: f64 = 0.030;
const E1: f64 = 0.060;
const E2: f64 = 0.050;
const Z1: f64 = 0.100;
const Z2: f64 = 0.250;
const L: f64 = 0.400;
const ZA: f64 = 0.050;
const ZB: f64 = 0.350;
const R: f64 = 0.080;

/// 1500 rpm in rad/s.
fn omega() -> f64 {
    1500.0 * 2.0 * std::f64::consts::PI / 60.0
}

/// A point mass `(m, x, y, z)`.
type PointMass = (f64, f64, f64, f64);

/// The masses as point masses: m1 along x, m2 along (-3/5, 4/5).
fn point_masses() -> [PointMass; 2] {
    [(M1, E1, 0.0, Z1), (M2, -0.6 * E2, 0.8 * E2, Z2)]
}

/// By hand: `(P_1, P_2, Q_1, Q_2)` from `P_1 + P_2 = -S_x`, `z_A P_1 + z_B P_2 = -I_xz`
/// (Cramer: `P_2 = (z_A S_x - I_xz)/(z_B - z_A)`, `P_1 = -S_x - P_2`), likewise in y.
fn hand_moments() -> (f64, f64, f64, f64) {
    let masses = point_masses();
    let s_x: f64 = masses.iter().map(|(m, x, _, _)| m * x).sum();
    let s_y: f64 = masses.iter().map(|(m, _, y, _)| m * y).sum();
    let i_xz: f64 = masses.iter().map(|(m, x, _, z)| m * x * z).sum();
    let i_yz: f64 = masses.iter().map(|(m, _, y, z)| m * y * z).sum();
    let p_2 = (ZA * s_x - i_xz) / (ZB - ZA);
    let q_2 = (ZA * s_y - i_yz) / (ZB - ZA);
    (-s_x - p_2, p_2, -s_y - q_2, q_2)
}

fn close(found: f64, expected: f64, relative: f64, what: &str) {
    assert!(
        (found - expected).abs() <= relative * expected.abs().max(1e-300),
        "{what}: {found} against {expected} by hand"
    );
}

fn value(scene: &Scene, e: &Expr) -> f64 {
    e.eval(&|s: Symbol| scene.value(s))
        .unwrap_or_else(|err| panic!("{e}: {err}"))
}

fn corrections(analysis: &kinetics::Analysis) -> &[Correction; 2] {
    match result(analysis, "balance") {
        Value::Balance(corrections) => corrections,
        _ => panic!("a balance is its corrections"),
    }
}

/// The angle in degrees of a correction whose `P`, `Q` have values.
fn degrees(scene: &Scene, c: &Correction) -> f64 {
    match &c.angle {
        CorrectionAngle::Exact(t) => value(scene, t).to_degrees(),
        CorrectionAngle::Atan2 { q, p } => value(scene, q).atan2(value(scene, p)).to_degrees(),
        CorrectionAngle::Undefined => panic!("a correction is needed in both planes"),
    }
}

#[test]
fn rotor_correction_masses_and_angles_match_the_hand_computation() {
    let (scene, analysis) = analysed_example("rotor_two_unbalance_masses", "");
    let (p_1, p_2, q_1, q_2) = hand_moments();
    // The numbers of the scene's comment: P = (-0.0007, 0.0004), Q = (-0.0004, -0.0008) kg·m.
    close(p_1, -0.0007, 1e-9, "P_1");
    close(q_2, -0.0008, 1e-9, "Q_2");
    let [first, second] = corrections(&analysis);
    for (c, (p, q)) in [first, second].into_iter().zip([(p_1, q_1), (p_2, q_2)]) {
        close(value(&scene, &c.p), p, 1e-12, "P");
        close(value(&scene, &c.q), q, 1e-12, "Q");
        let mass = (p * p + q * q).sqrt() / R;
        close(value(&scene, &c.mass), mass, 5e-5, "the correction mass");
        close(
            degrees(&scene, c),
            q.atan2(p).to_degrees(),
            5e-5,
            "the angle",
        );
    }
    // To 4 significant figures: 10.08 g at -150.3°, 11.18 g at -63.43°.
    close(value(&scene, &first.mass) * 1000.0, 10.08, 5e-4, "m_1 in g");
    close(degrees(&scene, first), -150.3, 5e-4, "theta_1");
    close(
        value(&scene, &second.mass) * 1000.0,
        11.18,
        5e-4,
        "m_2 in g",
    );
    close(degrees(&scene, second), -63.43, 5e-4, "theta_2");
}

#[test]
fn rotor_results_render_with_units_in_every_format() {
    let (scene, analysis) = analysed_example("rotor_two_unbalance_masses", "");
    let json: serde_json::Value =
        serde_json::from_str(&render(&scene, &analysis, Format::Json, false)).unwrap();
    let row = |name: &str| {
        json["results"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["name"] == name)
            .unwrap_or_else(|| panic!("{name} is a result row"))
            .clone()
    };
    // The unbalance masses are given as m1, m2 (the symbols m_1, m_2): the corrections are
    // named apart, m_a and m_b, so no line reads m_1 = …m_1….
    let names: Vec<&serde_json::Value> = json["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| &r["name"])
        .collect();
    assert!(
        !names.iter().any(|n| *n == "m_1" || *n == "m_2"),
        "{names:?}"
    );
    assert_eq!(row("m_a")["unit"], "kg");
    assert_eq!(row("theta_a")["unit"], "deg");
    close(
        row("theta_b")["value"].as_f64().unwrap(),
        -63.43,
        5e-4,
        "theta_b",
    );
    let text = render(&scene, &analysis, Format::Text, false);
    assert!(text.contains("theta_a = -150.3 deg"), "{text}");
    assert!(text.contains("= 0.01118 kg"), "{text}");
    let latex = render(&scene, &analysis, Format::Latex, false);
    assert!(latex.contains(r"\theta_a &= -150.3^\circ"), "{latex}");
    let markdown = render(&scene, &analysis, Format::Markdown, false);
    assert!(markdown.contains(r"\theta_b &= -63.43^\circ"), "{markdown}");
    let html = render(&scene, &analysis, Format::Html, false);
    assert!(html.contains("<mn>63.43</mn>"), "{html}");
}

#[test]
fn rotor_reactions_before_balancing_are_the_masses_m_e_w2() {
    let (scene, analysis) = analysed_example("rotor_two_unbalance_masses", "");
    let w2 = omega().powi(2);
    // Each mass pulls the shaft with m ω² (x, y) at its z; B takes -Σ z F/L, A the rest.
    let force = |k: usize| -> [f64; 2] {
        let sum = |f: &dyn Fn(&PointMass) -> f64| -> f64 { point_masses().iter().map(f).sum() };
        let [f_x, f_y] = [
            sum(&|(m, x, _, _)| m * w2 * x),
            sum(&|(m, _, y, _)| m * w2 * y),
        ];
        let [zf_x, zf_y] = [
            sum(&|(m, x, _, z)| m * w2 * x * z),
            sum(&|(m, _, y, z)| m * w2 * y * z),
        ];
        let b = [-zf_x / L, -zf_y / L];
        [[-f_x - b[0], -f_y - b[1]], b][k]
    };
    for (name, expected) in [
        ("A_x in N", force(0)[0]),
        ("A_y in N", force(0)[1]),
        ("B_x in N", force(1)[0]),
        ("B_y in N", force(1)[1]),
    ] {
        let name = name.trim_end_matches(" in N");
        let Value::Scalar(e) = result(&analysis, name) else {
            panic!("{name} is a scalar")
        };
        close(value(&scene, e), expected, 1e-9, name);
    }
}

/// The rotor's scene with the hand's correction masses as point masses: `m_k` at radius r
/// and angle θ_k in the plane `z_k`, written through `P_k`, `Q_k` of the hand formulas in the
/// givens (`m_k = √(P² + Q²)/r` at `(r P/√(P² + Q²), r Q/√(P² + Q²), z_k)`).
fn corrected_rotor() -> String {
    let path = format!(
        "{}/examples/scenes/rotor_two_unbalance_masses.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(path).expect("the example exists");
    let kept: Vec<&str> = text.lines().filter(|l| !l.starts_with("find")).collect();
    let s_x = "(m1*e1 - 3/5*m2*e2)";
    let s_y = "(4/5*m2*e2)";
    let i_xz = "(m1*e1*z1 - 3/5*m2*e2*z2)";
    let i_yz = "(4/5*m2*e2*z2)";
    let p_2 = format!("((z_A*{s_x} - {i_xz})/(z_B - z_A))");
    let q_2 = format!("((z_A*{s_y} - {i_yz})/(z_B - z_A))");
    let p_1 = format!("(-{s_x} - {p_2})");
    let q_1 = format!("(-{s_y} - {q_2})");
    let body = |p: &str, q: &str, plane: &str| {
        let norm = format!("sqrt({p}^2 + {q}^2)");
        format!("body point() mass {norm}/r at (r*{p}/{norm}, r*{q}/{norm}, {plane})")
    };
    format!(
        "{}\n{}\n{}\nfind A_x, A_y, B_x, B_y\n",
        kept.join("\n"),
        body(&p_1, &q_1, "z_A"),
        body(&p_2, &q_2, "z_B")
    )
}

#[test]
fn the_corrected_rotor_has_zero_bearing_reactions() {
    let text = corrected_rotor();
    let scene = parse_scene("corrected.scene", &text).unwrap_or_else(|d| panic!("{}", d.render()));
    let analysis = analyse(&scene).unwrap_or_else(|d| panic!("{}", d.render()));
    for name in ["A_x", "A_y", "B_x", "B_y"] {
        let Value::Scalar(e) = result(&analysis, name) else {
            panic!("{name} is a scalar")
        };
        assert!(e.is_zero(), "{name} = {e}, not zero exactly");
        assert!(value(&scene, e).abs() < 1e-12, "{name} in N");
    }
    // The balance's own residual: its last step, the reactions after correction, all zero.
    let (_, balanced) = analysed_example("rotor_two_unbalance_masses", "");
    let last = balanced.plan.last().expect("a plan");
    assert_eq!(last.relations.len(), 4);
    assert!(last.relations.iter().all(|r| r.rhs.is_zero()));
}

#[test]
fn a_shaft_along_x_without_bearings_is_balanced_by_two_masses_opposite() {
    // One mass m at (d, e, 0); planes x = 0 and x = 2d: P_1 + P_2 = -m e, 2d P_2 = -m d e,
    // so P_1 = P_2 = -m e/2, Q = 0: m_k = m e/(2r) at θ = 180° (from y toward z).
    let scene = parse_scene(
        "shaft.scene",
        "given m : kg\ngiven d : m\ngiven e : m\ngiven r : m\ngiven w : rad/s\n\
         body point() mass m at (d, e, 0)\nfixed point\nomega = w*i\n\
         find balance in planes x = 0, x = 2*d at radius r\n",
    )
    .unwrap_or_else(|d| panic!("{}", d.render()));
    let analysis = analyse(&scene).unwrap_or_else(|d| panic!("{}", d.render()));
    for c in corrections(&analysis) {
        assert_eq!(c.angle, CorrectionAngle::Exact(Expr::pi()));
        for (m, e, r) in [(2.0, 0.3, 0.1), (0.5, 1.5, 2.0)] {
            let at = |s: Symbol| match s.name() {
                "m" => Some(m),
                "e" => Some(e),
                "r" => Some(r),
                _ => Some(0.7),
            };
            close(c.mass.eval(&at).unwrap(), m * e / (2.0 * r), 1e-12, "m_k");
        }
    }
    let last = analysis.plan.last().expect("a plan");
    assert!(last.relations.iter().all(|r| r.rhs.is_zero()), "{last:?}");
    let text = render(&scene, &analysis, Format::Text, false);
    assert!(text.contains("theta_1 = pi"), "{text}");
}

#[test]
fn no_correction_in_a_plane_is_mass_zero_and_no_angle() {
    // One mass m at (e, e, a) in the plane z = a itself: P_1 = Q_1 = -m e, nothing at z = b,
    // so m_1 = √2 m e/r at -135°, m_2 = 0 and θ_2 undefined. With c = e the mass is on the
    // axis: symbolically a correction m |c - e|/r, with the values none at all.
    let scene = |position: &str| {
        let text = format!(
            "given m = 20 g\ngiven e = 60 mm\ngiven c = 60 mm\ngiven a = 100 mm\n\
             given b = 300 mm\ngiven r = 40 mm\ngiven w = 1500 rpm\n\
             body point() mass m at {position}\nfixed point\nomega = w*k\n\
             find balance in planes z = a, z = b at radius r\n"
        );
        let scene = parse_scene("one.scene", &text).unwrap_or_else(|d| panic!("{}", d.render()));
        let analysis = analyse(&scene).unwrap_or_else(|d| panic!("{}", d.render()));
        render(&scene, &analysis, Format::Text, false)
    };
    let in_plane = scene("(e, e, a)");
    // √2 · 0.02 kg · 0.06 m / 0.04 m = 0.042426 kg.
    close(2f64.sqrt() * M1 * E1 / 0.04, 0.042426, 1e-5, "m_1 by hand");
    assert!(
        in_plane.contains("m_1 = sqrt(2)*m*e/r = 0.04243 kg"),
        "{in_plane}"
    );
    assert!(
        in_plane.contains("theta_1 = -3/4*pi = -135 deg"),
        "{in_plane}"
    );
    assert!(
        in_plane.contains("m_2 = 0 kg\n  theta_2 = undefined"),
        "{in_plane}"
    );
    let on_axis = scene("(e - c, 0, a)");
    assert!(
        on_axis.contains("= 0 kg\n  theta_1 = undefined"),
        "{on_axis}"
    );
}
