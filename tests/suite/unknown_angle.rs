//! An unknown angle inside sin and cos (issue 32): a top's steady tilt θ for a given
//! precession and spin, solved exactly through cos θ, against the moment equation solved
//! by bisection here in f64; the vertical axis (θ = 0, 180°) ruled out with its reason; and
//! a precession too fast for any tilt refused naming why.

use crate::common::examples::{analysed_example, result};
use kinetics::scene::{analyse, parse_scene, Value};

/// `ΣM_x − Ḣ_x` past its factor sin θ for the disk top about its pivot: W r − (I ω_z −
/// I′ φ̇ cos θ) φ̇, I = m r²/2, I′ = 5/4 m r², ω_z = ψ̇ + φ̇ cos θ.
fn moment_balance(theta: f64, phidot: f64, psidot: f64) -> f64 {
    let (m, r, g) = (0.5, 0.04, 9.81);
    let (i, i_prime) = (m * r * r / 2.0, 1.25 * m * r * r);
    let omega_z = psidot + phidot * theta.cos();
    m * g * r - (i * omega_z - i_prime * phidot * theta.cos()) * phidot
}

/// The root of `f` in (a, b) by bisection, its ends of opposite signs.
fn bisection(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    assert!(f(a) * f(b) < 0.0, "a sign change in the bracket");
    for _ in 0..200 {
        let mid = 0.5 * (a + b);
        if f(a) * f(mid) <= 0.0 {
            b = mid;
        } else {
            a = mid;
        }
    }
    0.5 * (a + b)
}

#[test]
fn a_top_s_steady_tilt_for_a_given_precession_and_spin() {
    let (scene, analysis) = analysed_example("top_steady_tilt", "");
    let Value::Scalar(theta) = result(&analysis, "theta") else {
        panic!("θ is a scalar")
    };
    let theta = theta.eval(&|s| scene.value(s)).unwrap();
    let psidot = 1800.0 * std::f64::consts::PI / 30.0;
    let by_bisection = bisection(
        |t| moment_balance(t, 2.65, psidot),
        1e-6,
        std::f64::consts::PI - 1e-6,
    );
    assert!(
        (theta - by_bisection).abs() < 1e-12,
        "{theta} against {by_bisection}"
    );
    assert!((theta.to_degrees() - 31.17).abs() < 0.01);
    // The vertical axis solves the equation too (its factor sin θ), and is ruled out.
    let words: Vec<String> = analysis
        .plan
        .iter()
        .map(|s| kinetics::print::markup::text(&s.title))
        .collect();
    assert_eq!(
        words
            .iter()
            .filter(|w| w.contains("φ and ψ not told apart"))
            .count(),
        2,
        "{words:?}"
    );
}

#[test]
fn a_precession_no_tilt_can_hold_is_refused_naming_why() {
    // φ̇ = 2.5 rad/s: cos θ = 2(r φ̇ ψ̇ − 2g)/(3 r φ̇²) = −2.05, beyond −1.
    let text = std::fs::read_to_string("examples/scenes/top_steady_tilt.scene")
        .unwrap()
        .replace("phidot = 2.65 rad/s", "phidot = 2.5 rad/s");
    let scene = parse_scene("t.scene", &text).unwrap();
    let message = analyse(&scene).unwrap_err().render();
    assert!(
        message.contains(
            "every root for theta is ruled out (its cosine would be beyond ±1, which is no angle"
        ),
        "{message}"
    );
}
