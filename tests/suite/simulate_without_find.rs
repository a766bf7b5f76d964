//! Issue 18, item 5: `kinetics simulate` takes a scene without a `find` line (a simulation
//! asks for the motion, nothing else), while `solve` still says the scene asks for nothing.
//! A free sphere (m = 2 kg, r = 0.1 m) spinning at ω = (1, 2, 3) rad/s keeps, by hand,
//! `T = ½ (2/5 m r²) |ω|² = 0.056 J` and `|H| = (2/5 m r²) |ω| = 0.008 √14 kg·m²/s`.

use crate::common::binary::kinetics_with_input;

const SPHERE: &str = "given m = 2 kg
given r = 0.1 m
body sphere(r) mass m
given w = 1 rad/s
omega = w*i + 2*w*j + 3*w*k
";

#[test]
fn a_scene_without_find_simulates() {
    let run = kinetics_with_input(&["simulate", "-", "--at", "0,2.5"], SPHERE);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let mut lines = run.stdout.lines();
    assert_eq!(lines.next(), Some("t,w_x,w_y,w_z,q_w,q_x,q_y,q_z,T,H"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 2);
    for row in &rows {
        assert!(
            (row[1] - 1.0).abs() < 1e-12 && (row[3] - 3.0).abs() < 1e-12,
            "{row:?}"
        );
        assert!((row[8] - 0.056).abs() < 1e-14, "T = {}", row[8]);
        assert!(
            (row[9] - 0.008 * 14f64.sqrt()).abs() < 1e-14,
            "|H| = {}",
            row[9]
        );
    }
}

#[test]
fn solve_still_needs_a_request() {
    let run = kinetics_with_input(&["solve", "-"], SPHERE);
    assert_eq!(run.code, 1);
    assert!(
        run.stderr.contains("the scene asks for nothing"),
        "{}",
        run.stderr
    );
}
