//! The sample problems end to end: each scene is parsed, analysed on demand and solved, and
//! the results are compared with the notes (symbolic forms by expansion, figures by value).

use crate::common::examples::{analysed_example, result};
use kinetics::algebra::Expr;
use kinetics::parse::parse_expression;
use kinetics::scene::{analyse, parse_scene, Analysis, Scene, Value};
use kinetics::solution::{render, Format};

fn load(name: &str) -> (Scene, Analysis) {
    analysed_example(name, "")
}

fn scalar(analysis: &Analysis, name: &str) -> Expr {
    match result(analysis, name) {
        Value::Scalar(e) => e.clone(),
        _ => panic!("{name} is not a scalar"),
    }
}

fn vector(analysis: &Analysis, name: &str) -> [Expr; 3] {
    match result(analysis, name) {
        Value::Vector(v) => [v[0].clone(), v[1].clone(), v[2].clone()],
        _ => panic!("{name} is not a vector"),
    }
}

fn same(derived: &Expr, expected: &str) {
    let expected = parse_expression("expected", expected).unwrap();
    assert_eq!(
        derived.expand().unwrap(),
        expected.expand().unwrap(),
        "derived {derived}, expected {expected}"
    );
}

fn value(scene: &Scene, e: &Expr) -> f64 {
    e.eval(&|s| scene.value(s))
        .expect("every given has a value")
}

#[test]
fn sample_18_1_plate_after_the_blow() {
    let (_, a) = load("sp18_1_plate_impact");
    let v = vector(&a, "vbar");
    same(&v[0], "0");
    same(&v[2], "-F Dt/m");
    let w = vector(&a, "omega");
    same(&w[0], "6 F Dt/(m b)");
    same(&w[1], "-6 F Dt/(m a)");
    let h = vector(&a, "H_G");
    same(&h[0], "1/2 F Dt b");
    same(&h[1], "-1/2 F Dt a");
}

#[test]
fn sample_18_2_disk_energy_and_momentum() {
    let (_, a) = load("sp18_2_rolling_disk");
    same(&scalar(&a, "T"), "1/8 m r^2 (6 + r^2/L^2) w1^2");
    let h_g = vector(&a, "H_G");
    same(&h_g[0], "1/2 m r^2 w1");
    same(&h_g[1], "-1/2 m r^2 w1 r/(2 L)");
    let h_o = vector(&a, "H_O");
    same(&h_o[0], "1/2 m r^2 w1");
    same(&h_o[1], "-m (L^2 + 1/4 r^2) (r w1/L)");
    same(&vector(&a, "mvbar")[2], "m r w1");
}

#[test]
fn sample_18_3_rod_acceleration_and_tension() {
    let (scene, a) = load("sp18_3_rotating_rod");
    let abar = vector(&a, "abar");
    assert!((value(&scene, &abar[0]) + 135.0).abs() < 1e-9);
    assert!((value(&scene, &vector(&a, "mabar")[0]) + 2700.0).abs() < 1e-9);
    same(
        &scalar(&a, "T_BC"),
        "m g cos(beta)/(2 sin(beta)) + 1/3 m L w^2 cos(beta)",
    );
    same(&scalar(&a, "A_y"), "m g");
}

#[test]
fn sample_18_4_dynamic_reactions_match_the_notes() {
    let (scene, a) = load("sp18_4_shaft_reactions");
    same(&scalar(&a, "D_y"), "-3/16 M/c - 1/4 m c w^2");
    same(&scalar(&a, "D_z"), "3/8 M/c - 1/8 m c w^2");
    same(&scalar(&a, "alpha"), "3 M/(2 m c^2)");
    // The notes round their figures to 0.1 N, not all with the same rounding of omega
    // (1200 rpm = 125.66 rad/s, written 125.7): each figure agrees to 0.1 N.
    for (name, notes) in [
        ("D_y", -129.8),
        ("D_z", -36.8),
        ("C_y", -152.2),
        ("C_z", -155.2),
    ] {
        let v = value(&scene, &scalar(&a, name));
        assert!((v - notes).abs() < 0.1, "{name} = {v}, notes {notes}");
    }
}

#[test]
fn sample_18_5_floor_force_and_pivot_reaction() {
    let (_, a) = load("sp18_5_disk_reactions");
    same(&scalar(&a, "N"), "W + m r^3 w1^2/(2 L^2)");
    // The pivot's reaction as one vector, the notes' R = -(m r² ω₁²/L)(i + (r/2L) j).
    let [r_x, r_y, r_z] = vector(&a, "R");
    same(&r_x, "-m r^2 w1^2/L");
    same(&r_y, "-m r^2 w1^2/L r/(2 L)");
    same(&r_z, "0");
}

#[test]
fn a_scene_asking_only_for_t_derives_no_rate_of_angular_momentum() {
    let text = "given m : kg\ngiven r : m\ngiven L : m\ngiven w1 : rad/s\nunknown w2 : rad/s\n\
                body disk(r) mass m at (L, 0, 0)\nfixed point\nomega = w1*i - w2*j\n\
                constraint velocity at (L, -r, 0) = 0\nfind T\n";
    let scene = parse_scene("only_t.scene", text).unwrap();
    let plan = analyse(&scene).unwrap().plan;
    let titles: Vec<&str> = plan.iter().map(|s| s.title.as_str()).collect();
    assert!(
        titles.iter().any(|t| t.starts_with("kinetic energy")),
        "{titles:?}"
    );
    assert!(
        !titles.iter().any(|t| t.contains("rate of change")
            || t.contains("Euler")
            || t.contains("equations of motion")),
        "{titles:?}"
    );
}

#[test]
fn json_has_the_documented_fields() {
    let (scene, a) = load("sp18_4_shaft_reactions");
    let json: serde_json::Value =
        serde_json::from_str(&render(&scene, &a, Format::Json, false)).unwrap();
    assert!(json["plan"].as_array().is_some_and(|p| !p.is_empty()));
    let d_y = json["results"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["name"] == "D_y")
        .unwrap();
    assert_eq!(d_y["unit"], "N");
    assert!((d_y["value"].as_f64().unwrap() + 129.75).abs() < 0.01);
    assert!(d_y["latex"].as_str().unwrap().contains(r"\frac{3 M}{16 c}"));
}

const EXAMPLES: [&str; 15] = [
    "sp18_1_plate_impact",
    "sp18_2_rolling_disk",
    "sp18_3_rotating_rod",
    "sp18_4_shaft_reactions",
    "sp18_5_disk_reactions",
    "unbalanced_shaft",
    "balanced_shaft",
    "general_body",
    "sliding_box",
    "free_body",
    "spun_up_sphere",
    "free_box_struck_at_corner",
    "compound_body_bent_rod",
    "bent_rod_vertical_shaft",
    "three_part_composite",
];

#[test]
fn worked_solutions_in_text() {
    for name in EXAMPLES {
        let (scene, a) = load(name);
        insta::assert_snapshot!(
            format!("{name}_text"),
            render(&scene, &a, Format::Text, false)
        );
    }
}

#[test]
fn worked_solutions_in_latex() {
    for name in EXAMPLES {
        let (scene, a) = load(name);
        insta::assert_snapshot!(
            format!("{name}_latex"),
            render(&scene, &a, Format::Latex, false)
        );
    }
}

#[test]
fn answers_asked_in_a_unit_are_converted() {
    let path = format!(
        "{}/examples/scenes/sp18_4_shaft_reactions.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(path).unwrap().replace(
        "find alpha, D_y, D_z, C_y, C_z",
        "find D_y in lb, C_y in kN",
    );
    let scene = parse_scene("in_units.scene", &text).unwrap();
    let analysis = analyse(&scene).unwrap();
    kinetics::solution::numbers::check_numeric_requests(&scene, &analysis).unwrap();
    let json: serde_json::Value =
        serde_json::from_str(&render(&scene, &analysis, Format::Json, false)).unwrap();
    let d_y = &json["results"][0];
    assert_eq!(d_y["unit"], "lb");
    // D_y = -3M/(16c) - m c w²/4 with the notes' numbers, converted with 1 lb = 4.4482216152605 N.
    let d_y_newton = -3.0 * 6.0 / (16.0 * 0.1) - 0.25 * 0.3 * 0.1 * 125.7f64.powi(2);
    assert!((d_y["value"].as_f64().unwrap() - d_y_newton / 4.4482216152605).abs() < 1e-9);
    let c_y = &json["results"][1];
    assert_eq!(c_y["unit"], "kN");
    let c_y_newton = -9.0 * 6.0 / (16.0 * 0.1) - 0.25 * 0.3 * 0.1 * 125.7f64.powi(2);
    assert!((c_y["value"].as_f64().unwrap() - c_y_newton / 1000.0).abs() < 1e-12);
}

/// The worked solution's H_O and `kinetics derive`'s come from one function: the scene's plan
/// holds derive's steps with the same titles, and derive's general relations, with the scene's
/// body and motion substituted (from the plan's own earlier steps), are the scene's relations.
/// Derive's H_O is `H_G + r̄ × m v̄`, the centroidal route, which a scene with a fixed point
/// takes when it says `about G`.
#[test]
fn the_h_o_steps_of_a_scene_are_those_of_derive() {
    use kinetics::algebra::Symbol;
    use kinetics::mechanics::catalogue::derive_general;
    let (_, a) = analysed_example("sp18_2_rolling_disk", "about G\n");
    let general = derive_general("H_O", false)
        .expect("derive knows H_O")
        .expect("derives");
    let titles: Vec<&str> = general.steps.iter().map(|s| s.title.as_str()).collect();
    let start = a
        .plan
        .windows(titles.len())
        .position(|w| {
            w.iter()
                .map(|s| s.title.as_str())
                .eq(titles.iter().copied())
        })
        .unwrap_or_else(|| panic!("the plan has derive's H_O steps {titles:?}"));
    // The scene's values of derive's symbols, read from the plan's earlier steps.
    let named = |name: &str| -> Expr {
        a.plan[..start]
            .iter()
            .flat_map(|s| &s.relations)
            .find(|r| r.lhs == Expr::symbol(name))
            .unwrap_or_else(|| panic!("the plan derives {name} before H_O"))
            .rhs
            .clone()
    };
    let mut values: Vec<(Symbol, Expr)> = ["I_x", "I_y", "I_z", "I_xy", "I_yz", "I_xz"]
        .into_iter()
        .map(|n| (Symbol::new(n), named(n)))
        .collect();
    for axis in ["x", "y", "z"] {
        values.push((
            Symbol::new(&format!("w_{axis}")),
            named(&format!("omega_{axis}")),
        ));
        values.push((
            Symbol::new(&format!("{axis}bar")),
            named(&format!("rbar_{axis}")),
        ));
        values.push((
            Symbol::new(&format!("vbar_{axis}")),
            named(&format!("vbar_{axis}")),
        ));
    }
    values.push((Symbol::new("m"), named("m_body")));
    let lookup = |s: Symbol| values.iter().find(|(v, _)| *v == s).map(|(_, e)| e.clone());
    for (derived, shown) in general.steps.iter().zip(&a.plan[start..]) {
        assert_eq!(
            derived.relations.len(),
            shown.relations.len(),
            "{}",
            shown.title
        );
        for (d, s) in derived.relations.iter().zip(&shown.relations) {
            assert_eq!(d.lhs, s.lhs, "{}", shown.title);
            let substituted = d.rhs.subs(&lookup).and_then(|e| e.expand()).unwrap();
            assert_eq!(
                substituted,
                s.rhs.expand().unwrap(),
                "{}: {}",
                shown.title,
                s.lhs
            );
        }
    }
}
