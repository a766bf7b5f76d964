//! `kinetics simulate` against hostile input (issue 14): a value that overflows is a located
//! error naming the quantity, never an `inf` row; every error stands at the statement that
//! causes it; each flag's number is checked by the flag's name; nothing reaches standard
//! output before the arguments and the scene are checked; the plot's path and the number
//! of samples are checked before any work.

use crate::common::binary::kinetics;
use std::path::{Path, PathBuf};

/// A scene file in the temporary directory, unique to this process and `name`.
fn scene_file(name: &str, text: &str) -> PathBuf {
    let path = std::env::temp_dir().join(format!(
        "kinetics-robust-simulate-{}-{name}.scene",
        std::process::id()
    ));
    std::fs::write(&path, text).unwrap();
    path
}

/// The sphere of the reproducers with these values of m (kg), r (m) and w (rad/s); the
/// `omega` statement is on line 7, the body on line 6.
fn sphere(name: &str, m: &str, r: &str, w: &str) -> PathBuf {
    scene_file(
        name,
        &format!(
            "# a sphere spinning about k\n# (the errors must not stand here)\ngiven m = {m} kg\n\
             given r = {r} m\ngiven w = {w} rad/s\nbody sphere(r) mass m\nomega = w*k\nfind T\n"
        ),
    )
}

fn simulate(path: &Path, flags: &[&str]) -> (i32, String, String) {
    let path = path.to_str().unwrap();
    kinetics(&[&["simulate", path][..], flags].concat())
}

/// Every field of every row (after the CSV header) is a finite number.
fn all_finite(csv: &str) -> bool {
    csv.lines()
        .skip(1)
        .flat_map(|l| l.split(','))
        .all(|v| v.parse::<f64>().is_ok_and(f64::is_finite))
}

const METHODS: [&str; 5] = ["auto", "exact", "rk4", "dop853", "splitting"];

#[test]
fn an_initial_kinetic_energy_beyond_f64_is_refused_at_omega_by_every_method() {
    let path = sphere("fast", "1", "1", "1e200");
    for method in METHODS {
        let (code, out, stderr) = simulate(&path, &["--until", "1", "--method", method]);
        assert_eq!(code, 1, "{method}: {stderr}");
        assert!(out.is_empty(), "{method}: wrote {out}");
        assert!(
            stderr.contains("the kinetic energy T = ½ωᵀ[I]ω overflows (2e399 J) at t = 0 s")
                && stderr.contains(":7:1")
                && stderr.contains("omega = w*k"),
            "{method}: {stderr}"
        );
    }
}

#[test]
fn a_huge_mass_gives_finite_numbers_or_an_error_at_the_body() {
    // |H| = 2/5·1e300 = 4e299 is within f64; only its squares were not.
    let path = sphere("heavy", "1e300", "1", "1");
    let (code, out, stderr) = simulate(&path, &["--at", "0,1"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(all_finite(&out), "{out}");
    let h: f64 = out
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(9)
        .unwrap()
        .parse()
        .unwrap();
    assert!((h / 4e299 - 1.0).abs() < 1e-15, "|H| = {h:e}");
    // Heavier and faster, T = ½·4e307·10² overflows: at the body, whose inertia holds
    // most of the magnitude.
    let path = sphere("heavier", "1e300", "1e4", "10");
    let (code, out, stderr) = simulate(&path, &["--at", "0,1"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(out.is_empty(), "wrote {out}");
    assert!(
        stderr.contains("the kinetic energy T = ½ωᵀ[I]ω overflows (2e309 J)")
            && stderr.contains(":6:1"),
        "{stderr}"
    );
    // So large that the inertia tensor itself is not a number.
    let path = sphere("heaviest", "1e300", "1e10", "1");
    let (code, _, stderr) = simulate(&path, &["--until", "1"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("the inertia tensor is not finite") && stderr.contains(":6:1"),
        "{stderr}"
    );
}

#[test]
fn a_motion_that_overflows_during_the_run_stops_at_the_body_without_printing_inf() {
    let path = scene_file(
        "driven",
        "# a sphere under a huge couple\ngiven m = 1 kg\ngiven r = 1 m\ngiven w = 1 rad/s\n\
         given M = 1e300 N*m\nbody sphere(r) mass m\nomega = w*k\ncouple M*i\nfind T\n",
    );
    for method in ["auto", "rk4", "dop853", "splitting"] {
        let (code, out, stderr) = simulate(&path, &["--until", "1000", "--method", method]);
        assert_eq!(code, 1, "{method}: {stderr}");
        assert!(all_finite(&out), "{method}: {out}");
        assert!(
            stderr.contains(":6:1") && stderr.contains("body sphere(r) mass m"),
            "{method}: {stderr}"
        );
    }
}

#[test]
fn scene_errors_stand_at_the_statement_not_the_first_line() {
    let cases = [
        (
            "no_omega",
            "# no omega\ngiven m = 1 kg\ngiven r = 1 m\nbody sphere(r) mass m\nfind T\n",
            "the scene gives no omega",
            ":4:1",
        ),
        (
            "no_force_value",
            "# a force without a value\ngiven m = 1 kg\ngiven r = 1 m\ngiven w = 1 rad/s\n\
             given F : N\nbody sphere(r) mass m\nomega = w*k\nforce P = F*i at (0, r, 0)\n\
             find T\n",
            "the moment of the loads has no numerical value",
            ":8:1",
        ),
        (
            "no_omega_value",
            "# omega without a value\ngiven m = 1 kg\ngiven r = 1 m\ngiven w : rad/s\n\
             body sphere(r) mass m\nomega = w*k\nfind T\n",
            "omega has no numerical value",
            ":6:1",
        ),
    ];
    for (name, text, message, at) in cases {
        let (code, out, stderr) = simulate(&scene_file(name, text), &["--until", "1"]);
        assert_eq!(code, 1, "{name}: {stderr}");
        assert!(out.is_empty(), "{name}: wrote {out}");
        assert!(
            stderr.contains(message) && stderr.contains(at) && !stderr.contains(":1:1"),
            "{name}: {stderr}"
        );
    }
}

#[test]
fn a_body_refused_as_a_whole_stands_at_a_body_statement() {
    // Zero total mass: whichever check refuses it (the total or the negative part), it
    // stands at a body line, not the first comment line.
    let zero = scene_file(
        "zero_mass",
        "# two parts whose masses cancel\ngiven m = 1 kg\ngiven r = 1 m\ngiven w = 1 rad/s\n\
         body sphere(r) mass m\nbody sphere(r) mass -m at (r, 0, 0)\nomega = w*k\nfind T\n",
    );
    let (code, out, stderr) = simulate(&zero, &["--until", "1"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(out.is_empty(), "wrote {out}");
    assert!(
        stderr.contains("body sphere(r) mass") && !stderr.contains(":1:1"),
        "{stderr}"
    );
    // No body at all: at the end of the file, where one would be added.
    let nobody = scene_file(
        "no_body",
        "# no body\ngiven w = 1 rad/s\nomega = w*k\nfind omega\n",
    );
    let (code, _, stderr) = simulate(&nobody, &["--until", "1"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("the scene has no body") && stderr.contains(":5:1"),
        "{stderr}"
    );
}

#[test]
fn each_flag_is_checked_by_its_name_before_anything_is_written() {
    let path = sphere("flags", "1", "1", "1");
    let positive = "it must be a finite positive number";
    let cases: [(&[&str], &str); 14] = [
        (
            &["--until=-5"],
            "--until -5: it must be a finite positive number",
        ),
        (
            &["--until", "-5"],
            "--until -5: it must be a finite positive number",
        ),
        (&["--until", "0"], positive),
        (&["--until", "inf"], "--until inf"),
        (&["--until", "NaN"], "--until NaN"),
        (&["--until", "1", "--every=-1"], "--every -1: it must be"),
        (&["--until", "1", "--every", "0"], "--every 0: it must be"),
        (
            &["--at", "1,0.5"],
            "--at: time number 2 (0.5) is not after 1",
        ),
        (&["--at=-1"], "--at: time number 1 is -1"),
        (&["--at", "0,inf"], "--at: time number 2 is inf"),
        (&["--until", "1", "--rtol=-1"], "--rtol -1: it must be"),
        (&["--until", "1", "--rtol", "NaN"], "--rtol NaN: it must be"),
        (
            &["--until", "1", "--method", "rk4", "--step=-1"],
            "--step -1: it must be",
        ),
        (
            &["--until", "1", "--method", "splitting", "--step", "0"],
            "--step 0: it must be",
        ),
    ];
    for (flags, message) in cases {
        let (code, out, stderr) = simulate(&path, flags);
        assert_eq!(code, 1, "{flags:?}: {stderr}");
        assert!(out.is_empty(), "{flags:?}: wrote {out}");
        assert!(stderr.contains(message), "{flags:?}: {stderr}");
        assert!(!stderr.contains("interval"), "{flags:?}: {stderr}");
    }
}

#[test]
fn a_problem_refused_before_the_first_sample_leaves_standard_output_empty() {
    // The exact method refuses a body under a couple; no header is printed before.
    let path = scene_file(
        "exact_torque",
        "# a couple\ngiven m = 1 kg\ngiven r = 1 m\ngiven w = 1 rad/s\ngiven M = 1 N*m\n\
         body sphere(r) mass m\nomega = w*k\ncouple M*i\nfind T\n",
    );
    for format in ["csv", "json"] {
        let (code, out, stderr) = simulate(
            &path,
            &["--until", "1", "--method", "exact", "--format", format],
        );
        assert_eq!(code, 1, "{stderr}");
        assert!(out.is_empty(), "{format}: wrote {out}");
    }
}

#[test]
fn more_samples_than_the_cap_ask_for_force_before_any_work() {
    let path = sphere("cap", "1", "1", "1");
    let started = std::time::Instant::now();
    let (code, out, stderr) = simulate(&path, &["--until", "1e9", "--every", "1"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(out.is_empty(), "wrote {} bytes", out.len());
    assert!(
        stderr.contains(
            "--until 1e9 --every 1 would write 1000000001 samples, more than 10000000; \
             pass --force"
        ),
        "{stderr}"
    );
    // A hang guard, not a benchmark: the refusal comes before any sample.
    assert!(started.elapsed().as_secs() < 10);
    // With --force the cap is passed: here the scene's own error comes next.
    let no_omega = scene_file(
        "cap_no_omega",
        "# no omega\ngiven m = 1 kg\ngiven r = 1 m\nbody sphere(r) mass m\nfind T\n",
    );
    let (code, out, stderr) = simulate(&no_omega, &["--until", "1e9", "--every", "1", "--force"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(out.is_empty());
    assert!(stderr.contains("the scene gives no omega"), "{stderr}");
    let (code, help, _) = kinetics(&["simulate", "--help"]);
    assert_eq!(code, 0);
    assert!(
        help.contains("10000000") && help.contains("--force"),
        "{help}"
    );
}

#[cfg(all(feature = "plot", unix))]
#[test]
fn the_plot_path_is_checked_before_any_sample() {
    let dir = std::env::temp_dir().join(format!("kinetics-robust-plot-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir(&dir).unwrap();
    let path = sphere("plot", "1", "1", "1");
    let dangling = dir.join("dangling.svg");
    let missing_target = dir.join("nowhere").join("x.svg");
    std::os::unix::fs::symlink(&missing_target, &dangling).unwrap();
    let into_missing = dir.join("missing").join("w.svg");
    let cases: [(PathBuf, bool, &str); 4] = [
        (dangling.clone(), false, "is a symbolic link"),
        (dangling.clone(), true, "does not exist"),
        (into_missing, false, "does not exist"),
        (dir.clone(), false, "is a directory"),
    ];
    for (plot, force, message) in cases {
        let p = plot.to_str().unwrap();
        let mut flags = vec!["--until", "1", "--plot", p];
        if force {
            flags.push("--force");
        }
        let (code, out, stderr) = simulate(&path, &flags);
        assert_eq!(code, 1, "{flags:?}: {stderr}");
        assert!(out.is_empty(), "{flags:?}: wrote {} bytes", out.len());
        assert!(
            stderr.contains("--plot") && stderr.contains(message),
            "{flags:?}: {stderr}"
        );
    }
    assert!(std::fs::symlink_metadata(&dangling)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(!missing_target.exists());
    // A link to a file in a directory that exists is written through with --force only.
    let target = dir.join("target.svg");
    let link = dir.join("link.svg");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let l = link.to_str().unwrap();
    let (code, _, stderr) = simulate(&path, &["--until", "1", "--plot", l]);
    assert_eq!(code, 1, "{stderr}");
    assert!(!target.exists());
    let (code, _, stderr) = simulate(&path, &["--until", "1", "--plot", l, "--force"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(std::fs::read_to_string(&target)
        .unwrap()
        .starts_with("<svg"));
    std::fs::remove_dir_all(&dir).unwrap();
}
