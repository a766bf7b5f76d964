//! The energy of an impact (issue 32): `T_1` just before the blow from `before vbar` and
//! `before omega`, `T_2` just after (the scene's `T`) and `T_lost = T_1 − T_2`, against the
//! rod that strikes a post worked by hand here (impulse and momentum about G, the end at
//! rest after), and the refusal of an impact's energy in a scene with no impulse.

use crate::common::examples::{analysed_example, result};
use kinetics::scene::{analyse, parse_scene, Value};
use kinetics::Expr;

#[test]
fn a_spinning_rod_striking_a_post_against_a_hand_computation() {
    let (scene, analysis) = analysed_example("spinning_rod_strikes_a_post", "");
    let scalar = |name: &str| match result(&analysis, name) {
        Value::Scalar(e) => e.clone(),
        other => panic!("{name}: {other:?}"),
    };
    let value = |e: &Expr| e.eval(&|s| scene.value(s)).unwrap();
    // By hand. Before: v̄₁ = v0 i, ω₁ = w0 k. The post's impulse R at A = (0, L/2, 0):
    // m v0 + R_x = m v̄_x, R_y = m v̄_y, I w0 − (L/2) R_x = I w (I = m L²/12); A at rest
    // after: v̄_y = 0, v̄_x = w L/2. So w = w0/4 + 3 v0/(2L).
    let (m, l, v0, w0) = (2.0, 1.2, 3.0, 2.0);
    let i = m * l * l / 12.0;
    let w = w0 / 4.0 + 3.0 * v0 / (2.0 * l);
    let vbar = w * l / 2.0;
    let t1 = 0.5 * m * v0 * v0 + 0.5 * i * w0 * w0;
    let t2 = 0.5 * m * vbar * vbar + 0.5 * i * w * w;
    let close = |name: &str, by_hand: f64| {
        let got = value(&scalar(name));
        assert!(
            (got - by_hand).abs() < 1e-12 * t1,
            "{name}: {got} against {by_hand}"
        );
    };
    close("T_1", t1);
    close("T_2", t2);
    close("T_lost", t1 - t2);
    assert!(t1 - t2 > 0.0, "a plastic impact loses energy");
    // Exactly: the energy lost is the difference of the two results.
    let difference = (scalar("T_1") - scalar("T_2")).expand().unwrap();
    assert_eq!(scalar("T_lost").expand().unwrap(), difference);
}

#[test]
fn an_impact_energy_without_an_impulse_is_refused_at_its_find() {
    let text = "given m = 2 kg\ngiven r = 0.1 m\ngiven w = 3 rad/s\nbody sphere(r) mass m\nvbar = 0\nomega = w*k\nfind T, T_lost";
    let scene = parse_scene("t.scene", text).unwrap();
    let message = analyse(&scene).unwrap_err().render();
    assert!(
        message.contains("T_lost is an energy of an impact")
            && message.contains("this scene has no impulse"),
        "{message}"
    );
    assert!(message.contains("t.scene:7:9"), "at T_lost: {message}");
}

#[test]
fn a_body_at_rest_before_the_blow_says_so() {
    // Without `before` lines the body was at rest: T_1 = 0, and the page says why.
    let text = std::fs::read_to_string("examples/scenes/spinning_rod_strikes_a_post.scene")
        .unwrap()
        .replace("before vbar = v0*i\n", "")
        .replace("before omega = w0*k\n", "");
    let scene = parse_scene("t.scene", &text).unwrap();
    let analysis = analyse(&scene).unwrap();
    let Value::Scalar(t1) = result(&analysis, "T_1") else {
        panic!("T_1 is a scalar")
    };
    assert!(t1.is_zero());
    let titles: Vec<String> = analysis
        .plan
        .iter()
        .map(|s| kinetics::print::markup::text(&s.title))
        .collect();
    assert!(
        titles
            .iter()
            .any(|t| t.contains("no `before` line: at rest")),
        "{titles:?}"
    );
}
