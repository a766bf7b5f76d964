//! The torque-free body stated as the textbook states it (issue 32): a disk given |ω| and
//! the angle γ of ω from its axis, its θ, φ̇ and ψ̇ derived by kinetics (the constraints on
//! ω's components solved with ΣM_G = Ḣ_G = 0) against the hand derivation below in f64.

use crate::common::examples::{analysed_example, result};
use kinetics::scene::Value;

/// The scalar result `name`'s value with the givens' values.
fn number(name: &str) -> f64 {
    let (scene, analysis) = analysed_example("torque_free_disk_from_omega", "");
    let Value::Scalar(e) = result(&analysis, name) else {
        panic!("{name} is a scalar")
    };
    e.eval(&|s| scene.value(s)).unwrap()
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
