//! Snapshots pin every derived form of `kinetics derive --general`, in text and LaTeX, for
//! general and principal axes. Each was reviewed against the chapter: the order
//! `I_x ω_x - I_xy ω_y - I_xz ω_z`, the cyclic Euler groups `(I_y - I_z)`, `(I_z - I_x)`,
//! `(I_x - I_y)`, and α terms before ω² terms in the fixed-axis equations.

use std::process::Command;

fn derive(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .arg("derive")
        .args(args)
        .output()
        .expect("the binary runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

#[test]
fn general_body_text() {
    insta::assert_snapshot!(derive(&["--general"]));
}

#[test]
fn general_body_latex() {
    insta::assert_snapshot!(derive(&["--general", "--format", "latex"]));
}

#[test]
fn principal_axes_latex() {
    insta::assert_snapshot!(derive(&["--general", "--principal", "--format", "latex"]));
}

#[test]
fn fixed_axis_steps_text() {
    insta::assert_snapshot!(derive(&["--general", "--only", "fixed_axis", "--steps"]));
}

/// The gyroscope (§18.9–18.11), every step: the equations grouped by `I'` and `I` with
/// ω_z = ψ̇ + φ̇ cos θ, steady precession by substitution (ΣM_x = (I ω_z − I'φ̇ cos θ) φ̇ sin θ,
/// I ψ̇ φ̇ at θ = 90°), and the body under no force (φ̇ = I ω_z/(I' cos θ),
/// ψ̇ = (I' − I) ω_z/I', tan γ = (I/I') tan θ).
#[test]
fn gyroscope_steps_text() {
    insta::assert_snapshot!(derive(&[
        "--general",
        "--only",
        "gyroscope,steady_precession,steady_precession_90,torque_free",
        "--steps",
    ]));
}

#[test]
fn gyroscope_steps_latex() {
    insta::assert_snapshot!(derive(&[
        "--general",
        "--only",
        "gyroscope,steady_precession,steady_precession_90,torque_free",
        "--steps",
        "--format",
        "latex",
    ]));
}

#[test]
fn principal_euler_is_in_cyclic_form() {
    let text = derive(&["--general", "--principal", "--only", "euler"]);
    assert!(text.contains("SumM_x = I_x*wdot_x - (I_y - I_z)*w_y*w_z"));
    assert!(text.contains("SumM_y = I_y*wdot_y - (I_z - I_x)*w_z*w_x"));
    assert!(text.contains("SumM_z = I_z*wdot_z - (I_x - I_y)*w_x*w_y"));
}

#[test]
fn json_lists_results_and_steps() {
    let json: serde_json::Value = serde_json::from_str(&derive(&[
        "--general",
        "--only",
        "H_G,T",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json[0]["name"], "H_G");
    assert_eq!(
        json[0]["result"][0]["latex"],
        r"H_x = I_x \omega_x - I_{xy} \omega_y - I_{xz} \omega_z"
    );
    assert_eq!(json[1]["name"], "T");
}

#[test]
fn unknown_derivation_is_an_error() {
    let out = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(["derive", "--general", "--only", "gyroscopes"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown derivation 'gyroscopes'"));
}
