//! The torque-free body stated as the textbook states it (issue 32): a disk given |ω| and
//! the angle γ of ω from its axis, its θ, φ̇ and ψ̇ derived by kinetics (the constraints on
//! ω's components solved with ΣM_G = Ḣ_G = 0) against the hand derivation below in f64.

use crate::common::examples::{analysed_example, edited_example, result, scalar_value};
use kinetics::scene::Value;

/// The scalar result `name`'s value with the givens' values.
fn number(name: &str) -> f64 {
    let (scene, analysis) = analysed_example("torque_free_disk_from_omega", "");
    scalar_value(&scene, &analysis, name)
}

#[test]
fn a_disk_given_omega_and_gamma_has_the_theta_and_rates_of_the_hand_derivation() {
    // By hand: H_G = I' ω_y j + I ω_z k is along Z = sin θ j + cos θ k, so tan θ =
    // I' ω_y / (I ω_z) with ω_y = ω sin γ, ω_z = ω cos γ; φ̇ sin θ = ω_y; ψ̇ + φ̇ cos θ = ω_z.
    let (m, r, w, gamma) = (2.0_f64, 0.2_f64, 40.0_f64, 30f64.to_radians());
    let (i, i_prime) = (m * r * r / 2.0, m * r * r / 4.0);
    let (omega_y, omega_z) = (w * gamma.sin(), w * gamma.cos());
    let theta = (i_prime * omega_y / (i * omega_z)).atan();
    let phidot = omega_y / theta.sin();
    let psidot = omega_z - phidot * theta.cos();
    for (name, by_hand) in [("theta", theta), ("phidot", phidot), ("psidot", psidot)] {
        let derived = number(name);
        assert!(
            (derived - by_hand).abs() <= 1e-12 * by_hand.abs(),
            "{name}: {derived} against {by_hand}"
        );
    }
    // The figures the scene's comment quotes.
    assert!((theta.to_degrees() - 16.10).abs() < 0.005);
    assert!((phidot - 72.11).abs() < 0.005 && (psidot + 34.64).abs() < 0.005);
    // Retrograde: ψ̇ and φ̇ of opposite signs (I' < I).
    assert!(psidot * phidot < 0.0);
}

/// The page says where θ comes from: tan θ = ½ tan γ, the textbook's tan γ = (I/I') tan θ.
#[test]
fn the_angle_comes_from_its_tangent_on_the_page() {
    let (_, analysis) = analysed_example("torque_free_disk_from_omega", "");
    let step = analysis
        .plan
        .iter()
        .find(|s| kinetics::print::markup::text(&s.title).contains("from its tangent"))
        .expect("a step for the angle");
    assert_eq!(step.relations.len(), 1);
    assert_eq!(step.relations[0].lhs.to_string(), "tan(theta)");
    assert_eq!(step.relations[0].rhs.to_string(), "1/2*tan(gamma)");
}

/// The scene with `gamma` given another value, analysed.
fn with_gamma(
    degrees: &str,
) -> Result<(kinetics::scene::Scene, kinetics::scene::Analysis), String> {
    let scene = edited_example(
        "torque_free_disk_from_omega",
        &[("gamma = 30 deg", format!("gamma = {degrees} deg").as_str())],
    );
    let analysis = kinetics::scene::analyse(&scene).map_err(|d| d.render())?;
    Ok((scene, analysis))
}

/// ω along the axis (γ = 0): the axis is along H_G, θ = 0, where the Eulerian angles do not
/// tell precession from spin; refused saying so, not "divides by zero".
#[test]
fn omega_along_the_axis_is_refused_naming_the_vertical_axis() {
    let message = with_gamma("0").unwrap_err();
    assert!(
        message.contains("every root for theta is ruled out (the axis is vertical there"),
        "{message}"
    );
    assert!(
        message.contains("state it without 'euler angles'"),
        "{message}"
    );
}

/// ω across the axis (γ = 90°): a disk turning about a diameter, θ = 90°, φ̇ = |ω|, ψ̇ = 0
/// (the tangent's pole, decided by the given's value).
#[test]
fn omega_across_the_axis_turns_the_disk_about_a_diameter() {
    let (scene, analysis) = with_gamma("90").unwrap();
    let value = |name: &str| scalar_value(&scene, &analysis, name);
    assert!((value("theta") - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    assert!((value("phidot") - 40.0).abs() < 1e-12);
    assert!(value("psidot").abs() < 1e-12);
}

/// ω at 120° from the axis: θ past 90° (arctan + π), still tan θ = ½ tan γ, and ψ̇ > 0.
#[test]
fn omega_beyond_a_right_angle_tilts_the_axis_past_ninety_degrees() {
    let (scene, analysis) = with_gamma("120").unwrap();
    let theta = scalar_value(&scene, &analysis, "theta");
    let gamma = 120f64.to_radians();
    assert!((theta.tan() - gamma.tan() / 2.0).abs() < 1e-12);
    assert!(theta > std::f64::consts::FRAC_PI_2 && theta < std::f64::consts::PI);
}

/// Without `find precession` the scene is still a body under no force (no load, ā given):
/// its constraints are solved with ΣM_G = Ḣ_G = 0 all the same.
#[test]
fn the_rates_without_asking_for_the_precession() {
    let scene = edited_example(
        "torque_free_disk_from_omega",
        &[("find theta, phidot, psidot, precession", "find phidot")],
    );
    let analysis = kinetics::scene::analyse(&scene).unwrap();
    let phidot = scalar_value(&scene, &analysis, "phidot");
    let gamma = 30f64.to_radians();
    assert!((phidot - 40.0 * (4.0 - 3.0 * gamma.sin().powi(2)).sqrt()).abs() < 1e-12);
}

/// A cylinder with h = √3 r has I' = I exactly: no precession, decided exactly (it said
/// "retrograde" from the round-off of √3 beside ψ̇ = 0).
#[test]
fn equal_moments_by_a_defined_given_are_decided_exactly() {
    let scene = edited_example(
        "torque_free_cylinder",
        &[("given h = 2 m", "given h = sqrt(3)*r")],
    );
    let analysis = kinetics::scene::analyse(&scene).unwrap();
    let Value::Precession(p) = result(&analysis, "precession") else {
        panic!("a precession")
    };
    assert_eq!(
        p.sense,
        kinetics::mechanics::torque_free_axisymmetric::PrecessionSense::EqualMoments
    );
}

/// The other textbook statement, H_G and θ: constraints on H_G's components (H_G = [Ī]{ω},
/// put in with the body) solved with ΣM_G = 0. By hand: I'φ̇ sin θ = H sin θ, so φ̇ = H/I';
/// I ω_z = H cos θ, so ψ̇ = H cos θ/I − φ̇ cos θ.
#[test]
fn a_disk_given_its_angular_momentum_and_theta() {
    let text = "given m = 2 kg\ngiven r = 0.2 m\ngiven H = 0.5 kg*m^2/s\ngiven theta = 20 deg\n\
                unknown phidot, psidot : rad/s\neuler angles steady\nbody disk(r) mass m along z\n\
                vbar = 0\nabar = 0\nconstraint H_y = H*sin(theta)\n\
                constraint H_z = H*cos(theta)\nfind phidot, psidot, precession\n";
    let scene = kinetics::scene::parse_scene("h.scene", text).unwrap();
    let analysis = kinetics::scene::analyse(&scene).unwrap();
    let value = |name: &str| scalar_value(&scene, &analysis, name);
    let (m, r, h, theta) = (2.0, 0.2, 0.5, 20f64.to_radians());
    let (i, i_prime) = (m * r * r / 2.0, m * r * r / 4.0);
    let phidot = h / i_prime;
    let psidot = h * theta.cos() / i - phidot * theta.cos();
    assert!((value("phidot") - phidot).abs() < 1e-12 * phidot);
    assert!((value("psidot") - psidot).abs() < 1e-12 * psidot.abs());
}

/// H_G in a constraint without the loads stated: refused saying what to state.
#[test]
fn a_constraint_on_h_needs_the_loads() {
    let text = "given m = 2 kg\ngiven r = 0.2 m\ngiven H = 0.5 kg*m^2/s\n\
                unknown w_z : rad/s\nbody disk(r) mass m along z\nomega = w_z*k\n\
                constraint H_z = H\nfind w_z\n";
    let scene = kinetics::scene::parse_scene("h.scene", text).unwrap();
    let message = kinetics::scene::analyse(&scene).unwrap_err().render();
    assert!(
        message
            .contains("a constraint on H_G (H_x, H_y, H_z) is solved with the equations of motion"),
        "{message}"
    );
}

/// ω within 1e-30 of the right angle to the axis: θ is 90° to the same closeness (it printed
/// θ = 0: atan of a huge tangent was taken for zero within a rounding bound that grew with
/// its argument).
#[test]
fn omega_all_but_across_the_axis_tilts_it_all_but_ninety_degrees() {
    let scene = edited_example(
        "torque_free_disk_from_omega",
        &[("given gamma = 30 deg", "given gamma = atan(1e30)")],
    );
    let analysis = kinetics::scene::analyse(&scene).unwrap();
    let page = kinetics::solution::render_numbers(
        &scene,
        &analysis,
        kinetics::solution::Format::Json,
        false,
    );
    let page: serde_json::Value = serde_json::from_str(&page).unwrap();
    let theta = page["results"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["name"] == "theta")
        .unwrap()["value"]
        .as_f64()
        .unwrap();
    assert!((theta - 90.0).abs() < 1e-9, "θ = {theta}°");
}

/// θ and γ both unknown (φ̇ given in their place): each enters through sin and cos, and
/// one unknown angle is solved at a time. Refused saying so and naming the angle to make a
/// given, not "over-determined: this constraint contradicts the others" (it said that).
#[test]
fn two_unknown_angles_are_refused_naming_the_one_to_give() {
    let scene = edited_example(
        "torque_free_disk_from_omega",
        &[
            ("given gamma = 30 deg", "given phidot = 72.11 rad/s"),
            ("unknown theta : deg", "unknown theta, gamma : deg"),
            ("unknown phidot, psidot", "unknown psidot"),
            (
                "find theta, phidot, psidot, precession",
                "find theta, gamma",
            ),
        ],
    );
    let message = kinetics::scene::analyse(&scene).unwrap_err().render();
    assert!(
        message.contains(
            "the unknowns theta and gamma both enter through sin and cos: kinetics solves for one unknown angle at a time"
        ),
        "{message}"
    );
    assert!(
        message.contains("'given gamma = …' in place of the unknown"),
        "{message}"
    );
}
