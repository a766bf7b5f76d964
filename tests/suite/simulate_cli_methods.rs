//! `kinetics simulate` with each integrator and its own parameter, as a whole process:
//! `--method rk4 --step h` and `--method splitting --step h` agree with `--method exact` on
//! the shipped torque-free scene and with a tight dop853 run on the forced one, to the
//! accuracy their step gives (and the step is the one asked for: halving it divides the
//! error by 2^order); `--format csv` given explicitly is the default output; a
//! parameter the chosen method does not use is refused with the reason.

use crate::common::binary::{kinetics, scene};

/// The CSV columns, in order.
const HEADER: &str = "t,w_x,w_y,w_z,q_w,q_x,q_y,q_z,T,H";

/// Sampling of every run below: `--until 20 --every 0.5`, 41 rows at `t = k/2`.
const UNTIL: f64 = 20.0;
const EVERY: f64 = 0.5;
const ROWS: usize = 41;

/// A successful run of `scene` sampled every [`EVERY`] up to [`UNTIL`], with `extra`
/// options: its CSV rows (checked: header, row count, times) and its standard error.
fn simulate(scene_name: &str, extra: &[&str]) -> (Vec<[f64; 10]>, String) {
    let path = scene(scene_name);
    let (until, every) = (UNTIL.to_string(), EVERY.to_string());
    let mut args = vec!["simulate", &path, "--until", &until, "--every", &every];
    args.extend_from_slice(extra);
    let (code, out, stderr) = kinetics(&args);
    assert_eq!(code, 0, "{args:?}: {stderr}");
    let mut lines = out.lines();
    assert_eq!(lines.next(), Some(HEADER), "{args:?}");
    let rows: Vec<[f64; 10]> = lines
        .map(|line| {
            let fields: Vec<f64> = line.split(',').map(|v| v.parse().unwrap()).collect();
            fields.try_into().unwrap_or_else(|f| panic!("{f:?}"))
        })
        .collect();
    assert_eq!(rows.len(), ROWS, "{args:?}");
    for (k, row) in rows.iter().enumerate() {
        // t = k·every is computed exactly and printed with 17 digits, so it reads back exact.
        assert_eq!(row[0], k as f64 * EVERY, "{args:?}");
    }
    (rows, stderr)
}

/// Largest difference over all rows of `ω` (absolute, |ω| ≈ 1 in both scenes) and of the
/// attitude quaternion (`|Δq|`, half the angle between the rotations; `acos` of their dot
/// product would resolve no angle below 1.5e-8).
fn difference(a: &[[f64; 10]], b: &[[f64; 10]]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(a, b)| {
            let omega = (1..4).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max);
            let chord = |sign: f64| (4..8).map(|k| (a[k] - sign * b[k]).powi(2)).sum::<f64>();
            let attitude = chord(1.0).min(chord(-1.0)).sqrt();
            omega.max(attitude)
        })
        .fold(0.0, f64::max)
}

/// A fixed-step method at `step` and `step/2` against `truth`: the error at `step` is below
/// `bound`, and halving the step divides it by about `2^order` (so `--step` is honoured).
/// Each run takes `UNTIL/step` steps, which standard error reports.
fn check_fixed_step(
    scene_name: &str,
    method: &str,
    step: f64,
    order: i32,
    truth: &[[f64; 10]],
    bound: f64,
) {
    let mut errors = [0.0; 2];
    for (error, h) in errors.iter_mut().zip([step, step / 2.0]) {
        let h_text = h.to_string();
        let (rows, stderr) = simulate(scene_name, &["--method", method, "--step", &h_text]);
        let steps = (UNTIL / h).round();
        assert!(
            stderr.contains(&format!("method: {steps} steps")),
            "{method} --step {h}: {stderr}"
        );
        *error = difference(&rows, truth);
    }
    println!(
        "{scene_name} {method}: error {:e} at step {step}, {:e} at {}",
        errors[0],
        errors[1],
        step / 2.0
    );
    assert!(
        errors[0] < bound,
        "{scene_name} {method} --step {step}: error {:e}",
        errors[0]
    );
    let ratio = errors[0] / errors[1];
    let expected = 2f64.powi(order);
    assert!(
        (0.7 * expected..1.4 * expected).contains(&ratio),
        "{scene_name} {method}: halving the step divides the error by {ratio}, not ~{expected}"
    );
}

// The bounds below are three times the error measured at `--step 0.02` over 20 s. The
// reference (the closed form, or dop853 at rtol 1e-13) is good to about 1e-12, far below
// the smallest error measured (3e-11 at step 0.01), and halving the step divides every error
// by 16.0: they are the methods' truncation errors `C h⁴`, which depend on the platform's
// rounding only in digits far beyond the factor of three.

#[test]
fn fixed_step_methods_agree_with_the_closed_form_on_the_free_body() {
    let (exact, stderr) = simulate("free_body", &["--method", "exact", "--format", "csv"]);
    assert!(stderr.contains("exact (closed form)"), "{stderr}");
    // Measured 8.3e-10 and 4.8e-10.
    check_fixed_step("free_body", "rk4", 0.02, 4, &exact, 2.5e-9);
    check_fixed_step("free_body", "splitting", 0.02, 4, &exact, 1.5e-9);
}

#[test]
fn fixed_step_methods_agree_with_tight_dop853_on_the_forced_sphere() {
    let (reference, stderr) =
        simulate("spun_up_sphere", &["--method", "dop853", "--rtol", "1e-13"]);
    assert!(stderr.contains("steps"), "{stderr}");
    // Measured 7.5e-9 and 5.7e-8.
    check_fixed_step("spun_up_sphere", "rk4", 0.02, 4, &reference, 2.5e-8);
    check_fixed_step("spun_up_sphere", "splitting", 0.02, 4, &reference, 1.5e-7);
}

#[test]
fn explicit_csv_is_the_default_output() {
    let path = scene("free_body");
    let base = ["simulate", &path, "--until", "5", "--every", "0.25"];
    let (code, default, _) = kinetics(&base);
    assert_eq!(code, 0);
    let (code, explicit, _) = kinetics(&[&base[..], &["--format", "csv"]].concat());
    assert_eq!(code, 0);
    assert_eq!(explicit, default);
    assert_eq!(explicit.lines().next(), Some(HEADER));
    assert_eq!(explicit.lines().count(), 1 + 21);
}

#[test]
fn a_parameter_the_method_does_not_use_is_refused() {
    let path = scene("free_body");
    for (method, flag, value, reason) in [
        ("dop853", "--step", "1e-3", "chooses its own steps"),
        ("auto", "--step", "1e-3", "chooses its own steps"),
        ("exact", "--step", "1e-3", "neither a tolerance nor steps"),
        ("exact", "--rtol", "1e-8", "neither a tolerance nor steps"),
        ("rk4", "--rtol", "1e-8", "give --step"),
        ("splitting", "--rtol", "1e-8", "give --step"),
    ] {
        let (code, out, stderr) = kinetics(&[
            "simulate", &path, "--until", "1", "--method", method, flag, value,
        ]);
        assert_eq!(code, 1, "{method} {flag}: {stderr}");
        assert!(out.is_empty(), "{method} {flag}: wrote {out}");
        assert!(
            stderr.contains(&format!("{flag} does not apply to --method {method}"))
                && stderr.contains(reason),
            "{method} {flag}: {stderr}"
        );
    }
    // Both at once is refused by the argument parser whatever the method.
    let (code, _, stderr) = kinetics(&[
        "simulate", &path, "--until", "1", "--rtol", "1e-8", "--step", "1e-3",
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("cannot be used with"), "{stderr}");
}

/// The closed form asked of a body under a moment: refused at the loads that make the
/// moment, saying auto would integrate it.
#[test]
fn exact_under_a_moment_is_refused_at_the_loads() {
    let path = scene("spun_up_sphere");
    let (code, out, stderr) = kinetics(&["simulate", &path, "--until", "1", "--method", "exact"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(out.is_empty(), "wrote {out}");
    assert!(
        stderr.contains("the closed form exists only for a torque-free body")
            && stderr.contains("couple M_0*sin(p*t)*i")
            && stderr.contains("auto integrates it (vern9 below --rtol 1e-9, dop853 above)"),
        "{stderr}"
    );
}
