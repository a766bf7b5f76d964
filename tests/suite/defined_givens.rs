//! `given name = expression` of earlier givens (issue 32): its unit checked against the one
//! written, its value and exact value from theirs, refused when it names an unknown or a
//! given not yet declared; and the car wheel on a curve (ψ̇ = v/r_w, φ̇ = v/R) against its
//! gyroscopic couple worked by hand.

use crate::common::examples::{analysed_example, result};
use kinetics::scene::{parse_scene, Value};
use kinetics::{Expr, Symbol};

const BODY: &str = "body disk(r_w) mass m along z\nvbar = 0\nomega = w*k\nfind T";

fn scene_with(definition: &str) -> Result<kinetics::Scene, String> {
    let text = format!(
        "given m = 20 kg\ngiven r_w = 0.3 m\ngiven v = 20 m/s\nunknown M_x : N*m\ngiven w = {definition}\n{BODY}"
    );
    parse_scene("t.scene", &text).map_err(|e| e.render())
}

#[test]
fn a_given_defined_by_earlier_givens_has_their_value_and_its_unit() {
    let scene = scene_with("v/r_w : rad/s").unwrap();
    let w = Symbol::new("w");
    assert!((scene.value(w).unwrap() - 20.0 / 0.3).abs() < 1e-12);
    // Exact: 20/(3/10) = 200/3.
    assert_eq!(scene.exact_given(w), Some(Expr::rational(200, 3)));
}

#[test]
fn a_definition_in_another_unit_than_the_one_written_is_refused() {
    let message = scene_with("v : rad/s").unwrap_err();
    assert!(
        message.contains("unit mismatch: the value is in m/s but the unit is rad/s"),
        "{message}"
    );
}

#[test]
fn a_definition_by_an_unknown_or_a_later_name_is_refused_at_it() {
    let message = scene_with("M_x/r_w").unwrap_err();
    assert!(
        message.contains("a given is defined by givens, and M_x is an unknown"),
        "{message}"
    );
    assert!(message.contains("t.scene:5:11"), "{message}");
    let message = scene_with("q/r_w\ngiven q = 1 m/s").unwrap_err();
    assert!(message.contains("unknown symbol q"), "{message}");
}

#[test]
fn a_chain_of_definitions_stays_exact_and_one_without_values_is_symbolic() {
    let text = "given a = 15 deg\ngiven b = 2*a\ngiven c = b + a\ngiven r : m\ngiven s = 2*r\ngiven m = 1 kg\nbody sphere(s) mass m\nvbar = 0\nomega = 0\nfind T";
    let scene = parse_scene("t.scene", text).unwrap();
    let exact = |name: &str| scene.exact_given(Symbol::new(name));
    assert_eq!(exact("b"), Some(Expr::pi() / Expr::int(6)));
    assert_eq!(exact("c"), Some(Expr::pi() / Expr::int(4)));
    assert_eq!(exact("s"), None);
    assert_eq!(scene.value(Symbol::new("s")), None);
}

#[test]
fn the_car_wheel_couple_against_a_hand_computation() {
    let (scene, analysis) = analysed_example("car_wheel_on_a_curve", "");
    let value = |e: &Expr| e.eval(&|s| scene.value(s)).unwrap();
    let scalar = |name: &str| match result(&analysis, name) {
        Value::Scalar(e) => value(e),
        other => panic!("{name}: {other:?}"),
    };
    // ΣM_x = I ψ̇ φ̇ at θ = 90°, I = m r_w²/2, ψ̇ = −v/r_w (rolling), φ̇ = v/R.
    let (m, r_w, v, big_r, g) = (20.0, 0.3, 20.0, 50.0, 9.81);
    let by_hand = m * r_w * r_w / 2.0 * (-v / r_w) * (v / big_r);
    assert!((scalar("M_x") - by_hand).abs() < 1e-12 * by_hand.abs());
    assert_eq!((scalar("M_y"), scalar("M_z")), (0.0, 0.0));
    let Value::Vector(f) = result(&analysis, "F") else {
        panic!("F is a vector")
    };
    // F + W = m ā, ā = −v²/R k: F holds the weight up and turns the wheel.
    assert!((value(&f[1]) - m * g).abs() < 1e-9);
    assert!((value(&f[2]) + m * v * v / big_r).abs() < 1e-9);
    // Rolling: the contact point (0, −r_w, 0) is at rest, v + ψ̇ r_w = 0.
    let psidot = scene.value(kinetics::Symbol::new("psidot")).unwrap();
    assert!((v + psidot * r_w).abs() < 1e-12);
}

/// The car wheel's rolling, `v + r_w ψ̇ = 0` at C, holds once ψ̇ is put in as its
/// definition −v/r_w (with the values, and symbolically without them): a constraint the
/// givens satisfy is shown, not refused as a contradiction; one they do not satisfy (a
/// contact point twice as low: v + 2 r_w ψ̇ = −v) still is.
#[test]
fn a_constraint_the_defined_givens_satisfy_is_shown_not_refused() {
    let (_, analysis) = analysed_example("car_wheel_on_a_curve", "");
    let titles: Vec<&str> = analysis.plan.iter().map(|s| s.title.as_str()).collect();
    assert!(
        titles.contains(&"kinematic constraints, which the givens satisfy"),
        "{titles:?}"
    );
    let symbolic = |contact: &str| {
        let text = format!(
            "given m : kg\ngiven r_w : m\ngiven v : m/s\ngiven R : m\ngiven g : m/s^2\ngiven theta = 90 deg\ngiven psidot = -v/r_w\ngiven phidot = v/R\nunknown M_x, M_y, M_z : N*m\nunknown F_x, F_y, F_z : N\neuler angles steady\nbody disk(r_w) mass m along z\nvbar = v*i\nabar = -v^2/R*k\nconstraint velocity at {contact} = 0\nforce F = F_x*i + F_y*j + F_z*k at (0, 0, 0)\ncouple M_x*i + M_y*j + M_z*k\nfind M_x"
        );
        let scene = parse_scene("t.scene", &text).map_err(|e| e.render())?;
        kinetics::analyse(&scene).map_err(|e| e.render())
    };
    let rolling = symbolic("(0, -r_w, 0)").unwrap();
    let Value::Scalar(m_x) = result(&rolling, "M_x") else {
        panic!("M_x is a scalar")
    };
    // M_x = I ψ̇ φ̇ = (m r_w²/2)(−v/r_w)(v/R), worked by hand, at m = 2, r_w = 3, v = 5, R = 7.
    let at = |s: Symbol| match s.name() {
        "m" => Some(2.0),
        "r_w" => Some(3.0),
        "v" => Some(5.0),
        "R" => Some(7.0),
        "psidot" => Some(-5.0 / 3.0),
        "phidot" => Some(5.0 / 7.0),
        _ => None,
    };
    let by_hand: f64 = 2.0 * 9.0 / 2.0 * (-5.0 / 3.0) * (5.0 / 7.0);
    assert!((m_x.eval(&at).unwrap() - by_hand).abs() < 1e-12);
    let message = symbolic("(0, -2*r_w, 0)").unwrap_err();
    assert!(message.contains("contradicts"), "{message}");
}

#[test]
fn a_definition_by_a_given_declared_later_says_which_line_to_move_below() {
    let text = "given m = 2 kg\ngiven w = v/r\ngiven r = 0.5 m\ngiven v = 3 m/s\nbody sphere(r) mass m\nvbar = 0\nomega = w*k\nfind T";
    let message = parse_scene("t.scene", text).unwrap_err().render();
    assert!(
        message.contains("is given on line") && message.contains("move this line below that one"),
        "{message}"
    );
}
