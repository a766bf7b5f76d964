//! No answer without its equations of motion (issue 32): a motion the givens and constraints
//! fix alone is checked against ΣF = m ā and ΣM = Ḣ (or impulse and momentum), and refused
//! with the equation and how far its sides are apart when the scene's loads cannot produce
//! it. Each residual here is worked out by hand in f64 from the textbook's formulas, apart
//! from the analysis.

use crate::common::examples::result;
use kinetics::mechanics::torque_free_axisymmetric::PrecessionSense;
use kinetics::scene::{analyse, parse_scene, Analysis, Scene, Value};

fn solved(text: &str) -> Result<(Scene, Analysis), String> {
    let scene = parse_scene("t.scene", text).map_err(|e| e.render())?;
    let analysis = analyse(&scene).map_err(|e| e.render())?;
    Ok((scene, analysis))
}

fn refusal(text: &str) -> String {
    match solved(text) {
        Ok((_, analysis)) => panic!("solved, not refused: {:?}", analysis.results),
        Err(message) => message,
    }
}

/// The number after `differ by ` in a refusal, in SI.
fn difference(message: &str) -> f64 {
    let after = message.split("differ by ").nth(1).expect("a difference");
    let number = after.split(' ').next().expect("a number");
    number.parse().expect("a number")
}

fn number(scene: &Scene, analysis: &Analysis, name: &str) -> f64 {
    match result(analysis, name) {
        Value::Scalar(e) => e.eval(&|s| scene.value(s)).expect("a number"),
        other => panic!("{name} is not a scalar: {other:?}"),
    }
}

/// A thin disk (m = 2 kg, r = 0.2 m) under no force whose rates the constraints fix from
/// |ω| = w and its angle γ to the axis, with θ given as well.
fn disk_with(constraints: &str, givens: &str) -> String {
    format!(
        "given m = 2 kg
given r = 0.2 m
given theta = 30 deg
{givens}
unknown phidot, psidot : rad/s
euler angles steady
body disk(r) mass m along z
vbar = 0
abar = 0
{constraints}
find phidot, psidot, precession"
    )
}

#[test]
fn a_torque_free_disk_given_both_theta_and_gamma_is_refused_naming_the_moment_equation() {
    let text = disk_with(
        "constraint phidot*sin(theta) = w*sin(gamma)
constraint phidot*cos(theta) + psidot = w*cos(gamma)",
        "given gamma = 30 deg\ngiven w = 40 rad/s",
    );
    let message = refusal(&text);
    assert!(message.contains("ΣM_G = Ḣ_G about x"), "{message}");
    assert!(message.contains("they fix phidot, psidot"), "{message}");
    assert!(
        message.contains("t.scene:11:1"),
        "at the first constraint: {message}"
    );
    assert!(message.contains("tan γ = (I/I') tan θ"), "{message}");
    // By hand (§18.11, steady precession, no moment): ΣM_x = 0 must equal
    // Ḣ_x = (I ω_z − I′ φ̇ cos θ) φ̇ sin θ, with I = m r²/2, I′ = m r²/4,
    // φ̇ = w sin γ / sin θ from ω_y = φ̇ sin θ, and ω_z = w cos γ.
    let (m, r, w) = (2.0_f64, 0.2_f64, 40.0_f64);
    let (theta, gamma) = (30f64.to_radians(), 30f64.to_radians());
    let (i, i_prime) = (m * r * r / 2.0, m * r * r / 4.0);
    let phidot = w * gamma.sin() / theta.sin();
    let hdot_x = (i * w * gamma.cos() - i_prime * phidot * theta.cos()) * phidot * theta.sin();
    let off = difference(&message);
    assert!(
        (off - hdot_x).abs() < 5e-4 * hdot_x,
        "{off} against {hdot_x}"
    );
}

#[test]
fn a_torque_free_disk_whose_constraint_obeys_the_moment_equation_is_solved() {
    // ψ̇ = (I′ − I) φ̇ cos θ / I = −φ̇ cos θ / 2 for a thin disk: the equations of motion
    // hold for the motion the constraint fixes, so it is answered.
    let text = disk_with(
        "constraint phidot = w\nconstraint psidot = -phidot*cos(theta)/2",
        "given w = 30 rad/s",
    );
    let (scene, analysis) = solved(&text).expect("solved");
    let psidot = number(&scene, &analysis, "psidot");
    let by_hand = -30.0 * 30f64.to_radians().cos() / 2.0;
    assert!(
        (psidot - by_hand).abs() < 1e-12,
        "{psidot} against {by_hand}"
    );
    let Value::Precession(p) = result(&analysis, "precession") else {
        panic!("a precession")
    };
    assert_eq!(p.sense, PrecessionSense::Retrograde);
}

/// A disk on a shaft about its fixed centre, turned by a couple `M k` at the rate `alpha`.
fn driven_disk(couple: &str) -> String {
    format!(
        "given m = 4 kg
given r = 0.5 m
given w = 10 rad/s
given alpha = 3 rad/s^2
given M = {couple}
body disk(r) mass m along z
fixed point
omega = w*k
omegadot = alpha*k
couple M*k
find H_O"
    )
}

#[test]
fn a_couple_that_cannot_drive_the_stated_angular_acceleration_is_refused() {
    let message = refusal(&driven_disk("2 N*m"));
    assert!(message.contains("ΣM_O = Ḣ_O about z"), "{message}");
    assert!(message.contains("the givens state a motion"), "{message}");
    // By hand: Ḣ_z = I α = (m r²/2) α = 1.5 N·m against the couple's 2 N·m.
    let off = difference(&message);
    assert!((off - 0.5).abs() < 1e-9, "{off}");
}

#[test]
fn the_couple_that_drives_it_is_accepted() {
    // M = (m r²/2) α = 0.5 · 3 = 1.5 N·m exactly.
    let (_, analysis) = solved(&driven_disk("1.5 N*m")).expect("solved");
    assert!(matches!(result(&analysis, "H_O"), Value::Vector(_)));
}

#[test]
fn a_blow_that_cannot_give_the_stated_velocity_is_refused() {
    // m v̄₂ = F Δt: 2 kg × 3 m/s is 6 N·s, not the 5 N·s of the blow (T_trans needs no
    // unknown, so impulse and momentum are formed only to check the motion).
    let text = "given m = 2 kg
given r = 0.1 m
given v = 3 m/s
given J = 5 N*s
unknown w_x, w_y, w_z : rad/s
body sphere(r) mass m
vbar = v*i
omega = w_x*i + w_y*j + w_z*k
impulse J*i at (0, 0, 0)
find T_trans";
    let message = refusal(text);
    assert!(message.contains("m v̄₁ + ΣF Δt = m v̄₂ about x"), "{message}");
    assert!((difference(&message) - 1.0).abs() < 1e-9, "{message}");
}

#[test]
fn a_given_gamma_the_motion_does_not_have_is_refused_at_that_given() {
    // The constraints dropped: ψ̇ comes from ΣM_G = Ḣ_G, and γ then from θ,
    // tan γ = (I/I′) tan θ = 2 tan 30° = 1.155, γ = 49.11°, not the 30° given.
    let text = disk_with(
        "constraint phidot = w",
        "given gamma = 30 deg\ngiven w = 40 rad/s",
    )
    .replace("find phidot, psidot, precession", "find psidot, precession");
    let message = refusal(&text);
    assert!(
        message
            .contains("gamma = 30 deg (given on line 4) is not the angle between ω and the axis"),
        "{message}"
    );
    let by_hand = (2.0 * 30f64.to_radians().tan()).atan().to_degrees();
    assert!(
        message.contains(&format!("γ = {by_hand:.2}°")),
        "{by_hand}: {message}"
    );
    assert!(message.contains("t.scene:4:7"), "{message}");
}
