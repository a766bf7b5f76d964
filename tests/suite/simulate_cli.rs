//! `kinetics simulate` as a whole process: CSV and JSON samples, `auto` taking the closed
//! form for a torque-free scene and agreeing with DOP853, a plot that is written once and
//! not overwritten without `--force`, and bad options refused.

use crate::common::binary::{kinetics, scene};

fn rows(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

#[test]
fn auto_is_exact_for_a_free_body_and_agrees_with_dop853() {
    let free = scene("free_body");
    let (code, exact, stderr) = kinetics(&["simulate", &free, "--at", "5,17.5,40"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stderr.contains("exact (closed form)"), "{stderr}");
    let (_, numeric, stderr) = kinetics(&[
        "simulate",
        &free,
        "--at",
        "5,17.5,40",
        "--method",
        "dop853",
        "--rtol",
        "1e-13",
    ]);
    assert!(stderr.contains("steps"), "{stderr}");
    let (e, n) = (rows(&exact), rows(&numeric));
    assert_eq!(e.len(), 3);
    for (a, b) in e.iter().zip(&n) {
        for k in 1..4 {
            assert!(
                (a[k] - b[k]).abs() < 1e-8,
                "t = {}: {} vs {}",
                a[0],
                a[k],
                b[k]
            );
        }
        // Kinetic energy and |H| are the conserved invariants.
        assert!((a[8] - e[0][8]).abs() < 1e-12 && (a[9] - e[0][9]).abs() < 1e-12);
    }
}

#[test]
fn json_and_every_sampling() {
    let (code, out, _) = kinetics(&[
        "simulate",
        &scene("free_body"),
        "--until",
        "2",
        "--every",
        "0.5",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v.as_array().unwrap().len(), 5);
    assert_eq!(v[4][0], 2.0);
}

#[cfg(feature = "plot")]
#[test]
fn the_plot_is_written_and_never_overwritten_silently() {
    let path = std::env::temp_dir().join(format!("kinetics-plot-{}.svg", std::process::id()));
    let _ = std::fs::remove_file(&path);
    let p = path.to_str().unwrap();
    let (code, _, stderr) = kinetics(&[
        "simulate",
        &scene("free_body"),
        "--until",
        "30",
        "--plot",
        p,
    ]);
    assert_eq!(code, 0, "{stderr}");
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("angular velocity"));
    let (code, _, stderr) = kinetics(&[
        "simulate",
        &scene("free_body"),
        "--until",
        "30",
        "--plot",
        p,
    ]);
    assert_eq!(code, 1);
    assert!(stderr.contains("--force"), "{stderr}");
    let _ = std::fs::remove_file(&path);
}

#[test]
fn bad_requests_are_refused() {
    let (code, _, stderr) = kinetics(&["simulate", &scene("free_body"), "--at", "3,1"]);
    assert_eq!(code, 1);
    assert!(stderr.contains("strictly increasing"), "{stderr}");
    let (code, _, stderr) = kinetics(&["simulate", &scene("sp18_2_rolling_disk"), "--until", "1"]);
    assert_eq!(code, 1);
    assert!(stderr.contains("no numerical value"), "{stderr}");
    let (code, _, stderr) = kinetics(&[
        "simulate",
        &scene("sp18_4_shaft_reactions"),
        "--until",
        "1",
        "--method",
        "exact",
    ]);
    assert_eq!(code, 1, "{stderr}");
}

#[test]
fn a_time_dependent_couple_follows_the_closed_form() {
    // Sphere: I = 2/5 m r² = 0.02; couple M0 sin(p t) i with M0 = 0.02, p = 2, w_0 = 1:
    // w_x(t) = w_0 + M0 (1 - cos p t)/(p I); w_y, w_z constant.
    let times: [f64; 4] = [0.5, 1.0, 2.5, 10.0];
    let at = times.map(|t| t.to_string()).join(",");
    let (code, out, stderr) = kinetics(&[
        "simulate",
        &scene("spun_up_sphere"),
        "--at",
        &at,
        "--rtol",
        "1e-12",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains("steps"),
        "a varying couple is integrated: {stderr}"
    );
    for (row, t) in rows(&out).iter().zip(times) {
        let expected = 1.0 + 0.02 * (1.0 - (2.0 * t).cos()) / (2.0 * 0.02);
        assert!(
            (row[1] - expected).abs() < 1e-10,
            "t = {t}: {} vs {expected}",
            row[1]
        );
        assert!((row[2] - 0.5).abs() < 1e-12 && row[3].abs() < 1e-12);
    }
}
