//! Issue 18, item 4: floating-point noise never prints, and a zero keeps its unit.
//!
//! `box_centre_on_axis`: a block whose centre, placed by an arm at 90° (`L cos θ` with
//! θ = 90 deg), lies on the shaft. By hand, `v̄ = ω × r̄ = 0` and `ā = 0` exactly, and about O
//! `H_O = I_z ω k` with `I_z = m (a² + b²)/12`, checked here also as a sum over a grid of
//! point masses; `T = ½ I_z ω²`. `balanced_shaft`: the bearing reactions are exactly zero,
//! each printed `0 N` in text, LaTeX, HTML and JSON.

use super::common::binary::{kinetics, scene};
use serde_json::Value;

fn solve(name: &str, format: &str) -> String {
    let (code, out, err) = kinetics(&["solve", &scene(name), "--format", format]);
    assert_eq!(code, 0, "{err}");
    out
}

fn result<'a>(json: &'a Value, name: &str) -> &'a Value {
    json["results"]
        .as_array()
        .expect("results")
        .iter()
        .find(|r| r["name"] == name)
        .unwrap_or_else(|| panic!("{name} in the results"))
}

/// `I_z` of a uniform a × b block about its centre line, as n³ point masses at the centres
/// of the cells of a grid (the midpoint rule gives `m (a² + b²)(1 − 1/n²)/12`).
fn point_mass_i_z(m: f64, a: f64, b: f64, n: usize) -> f64 {
    let cell = |k: usize, side: f64| (k as f64 + 0.5) / n as f64 * side - side / 2.0;
    let dm = m / (n * n * n) as f64;
    let mut sum = 0.0;
    for i in 0..n {
        for j in 0..n {
            sum += n as f64 * dm * (cell(i, a).powi(2) + cell(j, b).powi(2));
        }
    }
    sum
}

#[test]
fn a_mass_centre_on_the_axis_moves_exactly_not_at_all() {
    let json: Value = serde_json::from_str(&solve("box_centre_on_axis", "json")).unwrap();
    for name in ["vbar", "abar"] {
        let r = result(&json, name);
        assert_eq!(r["value"], serde_json::json!([0.0, 0.0, 0.0]), "{name}");
    }
    assert_eq!(result(&json, "vbar")["unit"], "m/s");
    assert_eq!(result(&json, "abar")["unit"], "m/s²");
    let (m, a, b, w) = (3.0, 0.4, 0.2, 10.0);
    let i_z = m * (a * a + b * b) / 12.0;
    let grid = point_mass_i_z(m, a, b, 200);
    assert!((grid / i_z - 1.0).abs() < 1e-4, "{grid} against {i_z}");
    let h = result(&json, "H_O");
    assert_eq!(h["value"][0], 0.0);
    assert_eq!(h["value"][1], 0.0);
    assert!((h["value"][2].as_f64().unwrap() - i_z * w).abs() < 1e-14);
    assert_eq!(h["unit"], "kg·m²/s");
    let t = result(&json, "T")["value"].as_f64().unwrap();
    assert!((t - 0.5 * i_z * w * w).abs() < 1e-14);

    let text = solve("box_centre_on_axis", "text");
    assert!(text.contains("vbar = 0 m/s\n"), "{text}");
    assert!(text.contains("abar = 0 m/s²\n"), "{text}");
    assert!(!text.contains("e-1"), "noise printed:\n{text}");
}

#[test]
fn an_exact_zero_keeps_its_unit_in_every_format() {
    let json: Value = serde_json::from_str(&solve("balanced_shaft", "json")).unwrap();
    for name in ["A_y", "B_y", "A_z", "B_z"] {
        let r = result(&json, name);
        assert_eq!(
            (&r["value"], &r["unit"]),
            (&serde_json::json!(0.0), &serde_json::json!("N"))
        );
    }
    let text = solve("balanced_shaft", "text");
    assert!(text.contains("  A_y = 0 N\n"), "{text}");
    let latex = solve("balanced_shaft", "latex");
    assert!(latex.contains(r"A_y &= 0\,\mathrm{N}"), "{latex}");
    let html = solve("balanced_shaft", "html");
    assert!(html.contains("<mi mathvariant=\"normal\">N</mi>"), "{html}");
    let markdown = solve("balanced_shaft", "markdown");
    assert!(markdown.contains(r"A_y &= 0\,\mathrm{N}"), "{markdown}");
}
