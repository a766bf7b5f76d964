//! The work-precision study ([`study`], `kinetics bench work-precision`): it covers the bodies
//! the issue names and every method on each (the closed form only where torque-free); every
//! error is finite and non-negative; errors fall as the tolerance tightens or the step
//! shrinks, at each fixed-step method's order, down to round-off; the tightest settings reach
//! stated errors; and the command prints the study's table and writes one SVG chart per body.
//!
//! Every body's errors are measured against the double-double Taylor reference; for the
//! forced bodies that truth is checked independently in `work_precision_forced_truth.rs`. No test here looks at run times.

use crate::common::binary::kinetics;
use kinetics::numeric::work_precision::study::{cases, study, Load, Row};
use nalgebra::Vector3;
use std::collections::BTreeSet;
#[cfg(feature = "plot")]
use std::path::Path;
use std::time::Duration;

/// End time of the study here. The study samples at `UNTIL · k / 100`, and a fixed-step
/// method takes equal steps no longer than its setting that land on each sample time; at
/// `UNTIL = 10` the spacing, 0.1 s, equals the coarsest step, so every setting takes steps of
/// its own (a shorter horizon would shrink the steps of `h = 0.1` and `h = 0.03` alike to the
/// spacing and give them the same error).
const UNTIL: f64 = 10.0;

/// The sample spacing of the study at [`UNTIL`].
const SPACING: f64 = UNTIL / 100.0;

/// Errors below this are round-off: a splitting step of the near-symmetric body is exact up to
/// `κ = 1e-9`, and its errors sit at 2e-15 to 6e-14 whatever the step.
const ROUND_OFF: f64 = 1e-12;

/// The integrator families, each run on every body at three or more settings.
const INTEGRATORS: [&str; 5] = ["dop853", "vern9", "rk4", "splitting2", "splitting4"];

/// The order of convergence of a fixed-step family (none for the adaptive pairs).
fn order(family: &str) -> Option<f64> {
    match family {
        "rk4" | "splitting4" => Some(4.0),
        "splitting2" => Some(2.0),
        _ => None,
    }
}

/// Largest error (`|Δω|` and attitude) allowed at a family's tightest setting on any body,
/// with the largest measured at `UNTIL = 10` over the five bodies.
fn tightest_bound(family: &str) -> f64 {
    match family {
        "exact" => 1e-12,     // 6.4e-15 (intermediate-axis attitude)
        "dop853" => 1e-10,    // rtol 1e-13: 1.2e-12 (forced attitude); generic 3.1e-13
        "vern9" => 1e-12,     // rtol 1e-13: 1.9e-14 (time-forced attitude); generic 1.4e-14
        "rk4" => 1e-9,        // h = 0.003: 1.6e-11 (time-forced attitude)
        "splitting4" => 1e-7, // h = 0.01: 4.9e-9 (time-forced |Δω|)
        "splitting2" => 1e-5, // h = 0.001: 4.1e-7 (time-forced |Δω|)
        other => panic!("no bound for method family {other}"),
    }
}

/// The method family of a row's method, its first word (`"rk4 h=0.01"` → `"rk4"`).
fn family(method: &str) -> &str {
    method.split(' ').next().unwrap()
}

/// The setting of a row's method, the number after `=` (a tolerance or a step).
fn setting(method: &str) -> f64 {
    let (_, value) = method
        .split_once('=')
        .unwrap_or_else(|| panic!("{method} has no setting"));
    value.parse().unwrap()
}

/// The step a fixed-step method takes for setting `h`: the spacing cut into equal steps no
/// longer than `h` (as the driver cuts it, ignoring a relative excess of 1e-12).
fn effective_step(h: f64) -> f64 {
    SPACING / (SPACING / h * (1.0 - 1e-12)).ceil()
}

fn run_study() -> (Vec<Row>, Vec<String>) {
    study(UNTIL, Duration::ZERO, &mut |_| {}).unwrap()
}

/// Rows of one body and one method family, loosest setting first.
fn settings<'a>(rows: &'a [Row], case: &str, family_name: &str) -> Vec<&'a Row> {
    let mut out: Vec<&Row> = rows
        .iter()
        .filter(|r| r.case == case && family(&r.method) == family_name)
        .collect();
    out.sort_by(|a, b| setting(&b.method).total_cmp(&setting(&a.method)));
    out
}

#[test]
fn the_study_covers_the_issues_bodies_with_every_method() {
    let bodies = cases();
    // The issue's bodies: moments, and ω₀ where it gives one.
    let wanted: [([f64; 3], Option<[f64; 3]>); 3] = [
        ([1.0, 2.0, 3.0], Some([1.0, 1.0, 1.0])),
        ([1.0, 1.0 + 1e-9, 2.0], None),
        ([1.0, 2.0, 3.0], Some([1e-3, 1.0, 1e-3])),
    ];
    for (moments, omega0) in wanted {
        assert!(
            bodies.iter().any(|c| matches!(c.load, Load::None)
                && c.moments == Vector3::from(moments)
                && omega0.is_none_or(|w| c.omega0 == Vector3::from(w))),
            "no torque-free body with I = {moments:?}, ω₀ = {omega0:?}"
        );
    }
    assert!(
        bodies.iter().any(|c| !matches!(c.load, Load::None)),
        "no forced body"
    );

    let (rows, notes) = run_study();
    for case in &bodies {
        let torque_free = matches!(case.load, Load::None);
        let families: BTreeSet<&str> = rows
            .iter()
            .filter(|r| r.case == case.name)
            .map(|r| family(&r.method))
            .collect();
        let mut expected = BTreeSet::from(INTEGRATORS);
        if torque_free {
            expected.insert("exact");
        }
        assert_eq!(families, expected, "{}", case.name);
        for f in INTEGRATORS {
            assert!(
                settings(&rows, case.name, f).len() >= 3,
                "{}: fewer than three settings of {f}",
                case.name
            );
        }
        assert!(
            notes.iter().any(|n| n
                .split_once(": ")
                .is_some_and(|(bodies, _)| bodies.split(", ").any(|b| b == case.name))),
            "{}: the table does not say what its truth is",
            case.name
        );
    }
}

#[test]
fn errors_are_finite_and_fall_as_settings_tighten_down_to_round_off() {
    let (rows, _) = run_study();
    for r in &rows {
        for value in [r.omega_error, r.attitude_error, r.seconds_per_run] {
            assert!(value.is_finite() && value >= 0.0, "{r:?}");
        }
    }
    let mut order_checks = BTreeSet::new();
    for case in cases() {
        for f in INTEGRATORS {
            let runs = settings(&rows, case.name, f);
            for pair in runs.windows(2) {
                let (loose, tight) = (pair[0], pair[1]);
                for (what, e_loose, e_tight) in [
                    ("|Δω|", loose.omega_error, tight.omega_error),
                    ("attitude", loose.attitude_error, tight.attitude_error),
                ] {
                    assert!(
                        e_tight < e_loose || e_tight < ROUND_OFF,
                        "{}: {what} grows from {e_loose:e} ({}) to {e_tight:e} ({})",
                        case.name,
                        loose.method,
                        tight.method
                    );
                    // Above round-off by three orders, a fixed-step method of order p gains
                    // at least (h/h')^(p − ½) when its step shrinks from h to h'.
                    if let Some(p) = order(f).filter(|_| e_loose > 1e3 * ROUND_OFF) {
                        let shrink = effective_step(setting(&loose.method))
                            / effective_step(setting(&tight.method));
                        let gain = e_loose / e_tight;
                        assert!(
                            gain >= shrink.powf(p - 0.5),
                            "{}: {what} falls {gain}-fold from {} to {} (steps {shrink}× shorter)",
                            case.name,
                            loose.method,
                            tight.method
                        );
                        order_checks.insert(f);
                    }
                }
            }
        }
    }
    assert_eq!(
        order_checks,
        BTreeSet::from(["rk4", "splitting2", "splitting4"]),
        "every fixed-step family has its order checked somewhere"
    );
}

#[test]
fn the_tightest_settings_reach_small_errors() {
    let (rows, _) = run_study();
    for case in cases() {
        let mut families = INTEGRATORS.to_vec();
        if matches!(case.load, Load::None) {
            families.push("exact");
        }
        for f in families {
            let tightest = if f == "exact" {
                rows.iter()
                    .find(|r| r.case == case.name && r.method == "exact")
                    .unwrap()
            } else {
                *settings(&rows, case.name, f).last().unwrap()
            };
            let bound = tightest_bound(f);
            assert!(
                tightest.omega_error < bound && tightest.attitude_error < bound,
                "{}: {} reaches only {:e} in |Δω|, {:e} in attitude (bound {bound:e})",
                case.name,
                tightest.method,
                tightest.omega_error,
                tightest.attitude_error
            );
        }
    }
}

/// A printed table row: body, method (may hold spaces), time, `|Δω|`, attitude.
#[cfg(feature = "plot")]
fn parse_row(line: &str) -> (String, String, [f64; 3]) {
    let words: Vec<&str> = line.split_whitespace().collect();
    assert!(words.len() >= 5, "not a table row: {line}");
    let n = words.len();
    let numbers = [n - 3, n - 2, n - 1].map(|k| {
        words[k]
            .parse::<f64>()
            .unwrap_or_else(|_| panic!("not a number in {line}"))
    });
    (words[0].to_string(), words[1..n - 3].join(" "), numbers)
}

/// The point lists of an SVG's polylines, each as its number of points.
#[cfg(feature = "plot")]
fn polyline_lengths(svg: &str) -> Vec<usize> {
    svg.split("<polyline")
        .skip(1)
        .map(|element| {
            let points = element
                .split_once("points=\"")
                .and_then(|(_, rest)| rest.split_once('"'))
                .map_or("", |(points, _)| points);
            points
                .split_whitespace()
                .filter(|p| {
                    p.split_once(',')
                        .is_some_and(|(x, y)| x.parse::<f64>().is_ok() && y.parse::<f64>().is_ok())
                })
                .count()
        })
        .collect()
}

#[cfg(feature = "plot")]
fn check_chart(path: &Path, case: &str, rows: &[Row]) {
    let svg = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(
        svg.trim_start().starts_with("<svg") && svg.trim_end().ends_with("</svg>"),
        "{} is not an SVG document",
        path.display()
    );
    assert!(
        svg.contains(case),
        "{}: no title naming {case}",
        path.display()
    );
    let families: BTreeSet<&str> = rows
        .iter()
        .filter(|r| r.case == case)
        .map(|r| family(&r.method))
        .collect();
    for f in &families {
        assert!(svg.contains(f), "{}: no legend entry {f}", path.display());
    }
    // One line through its settings for each family with three or more; axes, ticks and
    // legend swatches have two points.
    let curves = polyline_lengths(&svg)
        .into_iter()
        .filter(|&n| n >= 3)
        .count();
    let families_with_curves = families
        .iter()
        .filter(|f| settings(rows, case, f).len() >= 3)
        .count();
    assert!(
        curves >= families_with_curves,
        "{}: {curves} curves for {families_with_curves} families",
        path.display()
    );
}

#[cfg(feature = "plot")]
#[test]
fn the_command_prints_the_study_and_plots_every_body() {
    let dir = std::env::temp_dir().join(format!("kinetics-work-precision-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prefix = dir.join("wp");
    let until = UNTIL.to_string();
    let (code, out, stderr) = kinetics(&[
        "bench",
        "work-precision",
        "--until",
        &until,
        "--budget-ms",
        "0",
        "--plot",
        prefix.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");

    let (rows, notes) = run_study();
    let printed: Vec<_> = out
        .lines()
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .map(parse_row)
        .collect();
    assert_eq!(printed.len(), rows.len(), "{out}");
    for ((case, method, [seconds, omega, attitude]), r) in printed.iter().zip(&rows) {
        assert_eq!(
            (case.as_str(), method.as_str()),
            (r.case, r.method.as_str())
        );
        assert!(seconds.is_finite() && *seconds >= 0.0, "{case} {method}");
        // Three significant figures are printed.
        for (shown, value) in [(omega, r.omega_error), (attitude, r.attitude_error)] {
            assert!(
                (shown - value).abs() <= 1e-2 * value,
                "{case} {method}: printed {shown:e}, the study gives {value:e}"
            );
        }
    }
    for note in &notes {
        assert!(out.contains(note.as_str()), "the table omits: {note}");
    }

    for case in cases() {
        let path = dir.join(format!("wp-{}.svg", case.name));
        check_chart(&path, case.name, &rows);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_horizon_that_is_not_a_positive_number_is_refused() {
    for until in ["0", "-1", "inf", "NaN"] {
        let flag = format!("--until={until}");
        let (code, out, stderr) = kinetics(&["bench", "work-precision", &flag, "--budget-ms", "0"]);
        assert_eq!(code, 1, "--until {until}: {out}");
        assert!(stderr.contains("--until"), "--until {until}: {stderr}");
    }
}
