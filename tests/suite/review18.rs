//! Review of issue 18 with a scene not among the examples: a plate 300 mm × 200 mm of 4 kg,
//! centre at (300, 100, 50) mm, turned 30° about z then 20° about x, ω = 2 i + 120 rpm k
//! about a fixed O. `deg` and `rpm` bring π into the tensor; π is a constant, not a given
//! that needs a value. By hand: the principal moments about G are the plate's own,
//! m b²/12, m a²/12, m (a² + b²)/12 (a rotation does not change them).

use super::common::binary::kinetics_with_input;
use serde_json::Value;

const TURNED_PLATE: &str = "title Turned plate
given m = 4 kg
given a = 300 mm
given b = 200 mm
given w = 120 rpm
body plate(a, b) mass m at (300 mm, 100 mm, 50 mm) rotated 30 deg about z, then 20 deg about x
fixed point
omega = w*k + 2 rad/s*i
find principal_G, principal_O
";

#[test]
fn pi_from_deg_and_rpm_is_not_a_given_without_a_value() {
    let run = kinetics_with_input(
        &["solve", "-", "--numbers", "--format", "json"],
        TURNED_PLATE,
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let json: Value = serde_json::from_str(&run.stdout).unwrap();
    let moments = &json["results"][0]["value"]["moments"];
    let (m, a, b) = (4.0f64, 0.3f64, 0.2f64);
    let by_hand = [
        m * b * b / 12.0,
        m * a * a / 12.0,
        m * (a * a + b * b) / 12.0,
    ];
    for (k, want) in by_hand.iter().enumerate() {
        let got = moments[k].as_f64().unwrap();
        assert!(
            (got - want).abs() <= 1e-12 * want,
            "I_{}: {got} vs {want}",
            k + 1
        );
    }
}

/// Three unbalance masses in grams at positions in mm, the planes and radius written in mm
/// (not through givens). By hand, two-plane balancing: `P_1 + P_2 = −S_x`,
/// `z_1 P_1 + z_2 P_2 = −I_xz` (and Q with S_y, I_yz), `m_k = √(P_k² + Q_k²)/r`.
const ROTOR_IN_MM: &str = "title Rotor in millimetres
given m1 = 15 g
given m2 = 25 g
given m3 = 10 g
given w = 3000 rpm
body point() mass m1 at (40 mm, 30 mm, 120 mm)
body point() mass m2 at (-50 mm, 0, 260 mm)
body point() mass m3 at (0, -70 mm, 400 mm)
fixed point
omega = w*k
find balance in planes z = 20 mm, z = 480 mm at radius 100 mm
";

#[test]
fn balance_planes_and_radius_written_in_mm_are_brought_to_si() {
    let run = kinetics_with_input(
        &["solve", "-", "--numbers", "--format", "json"],
        ROTOR_IN_MM,
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let json: Value = serde_json::from_str(&run.stdout).unwrap();
    // (mass, x, y, z) of each unbalance mass, kg and m.
    type Mass = (f64, f64, f64, f64);
    let masses: [Mass; 3] = [
        (0.015, 0.04, 0.03, 0.12),
        (0.025, -0.05, 0.0, 0.26),
        (0.01, 0.0, -0.07, 0.4),
    ];
    let sum = |f: &dyn Fn(&Mass) -> f64| masses.iter().map(f).sum::<f64>();
    let (s_x, s_y) = (sum(&|p| p.0 * p.1), sum(&|p| p.0 * p.2));
    let (i_xz, i_yz) = (sum(&|p| p.0 * p.1 * p.3), sum(&|p| p.0 * p.2 * p.3));
    let (z1, z2, r) = (0.02, 0.48, 0.1);
    let second = |s: f64, i: f64| (-i + z1 * s) / (z2 - z1);
    let (p2, q2) = (second(s_x, i_xz), second(s_y, i_yz));
    let (p1, q1) = (-s_x - p2, -s_y - q2);
    let by_hand = [p1.hypot(q1) / r, p2.hypot(q2) / r];
    let results = json["results"].as_array().unwrap();
    for (k, want) in by_hand.iter().enumerate() {
        // The scene's masses m2, m3 are m_2, m_3: the corrections are named apart, m_a, m_b.
        let name = ["m_a", "m_b"][k];
        let got = results.iter().find(|r| r["name"] == name).unwrap();
        let got = got["value"].as_f64().unwrap_or(f64::NAN);
        assert!(
            (got - want).abs() <= 1e-12 * want,
            "{name}: {got} vs {want}"
        );
    }
}

/// Direction cosines a rounding away from a rotation: the message shows how far, not
/// "its length squared is 1, not 1".
#[test]
fn nearly_orthonormal_direction_cosines_are_refused_with_a_readable_departure() {
    let scene = "given m = 1 kg
given a = 0.2 m
body rod(a) mass m axes (1, 0, 0), (0, 0.6, 0.8), (0, -0.8, 0.6000001)
fixed point
omega = 2 rad/s*k
find T
";
    let run = kinetics_with_input(&["solve", "-"], scene);
    assert_ne!(run.code, 0);
    assert!(
        run.stderr
            .contains("its length squared is 1 + 1.2e-7, not 1")
            && run.stderr.contains("y'·z' is 8.0e-8, not 0"),
        "{}",
        run.stderr
    );
}
