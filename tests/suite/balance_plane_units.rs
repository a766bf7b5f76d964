//! `find balance in planes z = 50 mm, z = 350 mm at radius 80 mm`: lengths written with their
//! unit in the balance request are brought to SI like every other length (they stayed as the
//! marker `[mm]`, so the masses had no number). The rotor of
//! `examples/scenes/rotor_two_unbalance_masses.scene` with its planes and radius written as
//! numbers must give the hand's correction masses: with S_x = m1 e1 - 3/5 m2 e2,
//! S_y = 4/5 m2 e2, I_xz = m1 e1 z1 - 3/5 m2 e2 z2, I_yz = 4/5 m2 e2 z2 (kg, m), Cramer's rule on
//! P1 + P2 = -S_x, z_A P1 + z_B P2 = -I_xz (and Q likewise in y), m_k = sqrt(P_k² + Q_k²)/r
//! and theta_k = atan2(Q_k, P_k).

use crate::common::binary::{kinetics, scene};

/// The value printed for `name` in the Results block of `solve --numbers`, and its unit.
fn printed(out: &str, name: &str) -> (f64, String) {
    let results = out.split("\nResults\n").nth(1).expect("a Results block");
    let line = results
        .lines()
        .find(|l| l.trim_start().starts_with(&format!("{name} = ")))
        .unwrap_or_else(|| panic!("no line for {name} in:\n{out}"));
    let rest = line.split(" = ").nth(1).expect("a value");
    let (number, unit) = rest.split_once(' ').expect("a value and a unit");
    (number.parse().expect("a number"), unit.to_string())
}

#[test]
fn balance_planes_and_radius_in_millimetres_are_lengths_in_si() {
    let text = std::fs::read_to_string(scene("rotor_two_unbalance_masses")).expect("reads");
    let written = "z = z_A, z = z_B at radius r";
    assert!(text.contains(written));
    let text = text.replace(written, "z = 50 mm, z = 350 mm at radius 80 mm");
    let path = std::env::temp_dir().join(format!("balance_mm_{}.scene", std::process::id()));
    std::fs::write(&path, text).expect("writes");
    let (code, out, err) = kinetics(&["solve", "--numbers", path.to_str().expect("utf-8")]);
    let _ = std::fs::remove_file(&path);
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("[mm]"), "a unit marker left in:\n{out}");

    let (m1, m2, e1, e2, z1, z2) = (0.020, 0.030, 0.060, 0.050, 0.100, 0.250);
    let (za, zb, r) = (0.050, 0.350, 0.080);
    let (sx, sy) = (m1 * e1 - 0.6 * m2 * e2, 0.8 * m2 * e2);
    let (ixz, iyz) = (m1 * e1 * z1 - 0.6 * m2 * e2 * z2, 0.8 * m2 * e2 * z2);
    // P1 + P2 = -S, za P1 + zb P2 = -I: P2 = (za S - I)/(zb - za), P1 = -S - P2.
    let plane = |s: f64, i: f64| {
        let second = (za * s - i) / (zb - za);
        (-s - second, second)
    };
    let (p, q) = (plane(sx, ixz), plane(sy, iyz));
    for (k, (pk, qk)) in [(1, (p.0, q.0)), (2, (p.1, q.1))] {
        let (mass, unit) = printed(&out, &format!("m_{k}"));
        assert_eq!(unit, "kg");
        let expected = pk.hypot(qk) / r;
        assert!(
            (mass - expected).abs() < 1e-3 * expected,
            "m_{k} {mass} vs {expected}"
        );
        let (angle, unit) = printed(&out, &format!("theta_{k}"));
        assert_eq!(unit, "deg");
        let expected = qk.atan2(pk).to_degrees();
        assert!(
            (angle - expected).abs() < 0.05,
            "theta_{k} {angle} vs {expected}"
        );
    }
}
