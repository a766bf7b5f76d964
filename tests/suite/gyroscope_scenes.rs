//! The gyroscope's scenes (§18.9–18.11, `euler angles steady`): each example's result against
//! the textbook's closed form evaluated here in f64 from the givens (independently of the
//! analysis), their worked solutions as snapshots, and the plan of a steady precession, which
//! pulls neither Euler's equations for a general body nor an integration.

use crate::common::examples::{analysed_example, result, scalar_value};
use kinetics::mechanics::torque_free_axisymmetric::PrecessionSense;
use kinetics::scene::{Analysis, Scene, Value};
use kinetics::solution::{render, Format};
use std::process::Command;

const EXAMPLES: [&str; 6] = [
    "gyroscope_required_moment",
    "top_slow_and_fast_precession",
    "wheel_gyroscope_horizontal",
    "torque_free_cylinder",
    "torque_free_disk",
    "torque_free_disk_from_omega",
];

/// The components of a vector request with the givens' values.
fn numbers(scene: &Scene, analysis: &Analysis, name: &str) -> [f64; 3] {
    match result(analysis, name) {
        Value::Vector(v) => {
            let c = |k: usize| v[k].eval(&|s| scene.value(s)).expect("a number");
            [c(0), c(1), c(2)]
        }
        other => panic!("{name} is not a vector: {other:?}"),
    }
}

/// `find precession`: tan γ with the givens' values, and the sense.
fn precession(scene: &Scene, analysis: &Analysis) -> (f64, PrecessionSense) {
    match result(analysis, "precession") {
        Value::Precession(p) => (
            p.tan_gamma.eval(&|s| scene.value(s)).expect("a number"),
            p.sense,
        ),
        other => panic!("precession is not a precession: {other:?}"),
    }
}

/// The sense by the sign of `I′ − I` in f64 (the textbook's rule, §18.11).
fn sense_by_hand(i: f64, i_prime: f64) -> PrecessionSense {
    if i_prime > i {
        PrecessionSense::Direct
    } else {
        PrecessionSense::Retrograde
    }
}

/// A given's SI value.
fn given(scene: &Scene, name: &str) -> f64 {
    scene
        .value(kinetics::algebra::Symbol::new(name))
        .unwrap_or_else(|| panic!("{name} has a value"))
}

fn close(derived: f64, expected: f64, what: &str) {
    assert!(
        (derived - expected).abs() <= 1e-9 * expected.abs().max(1.0),
        "{what}: derived {derived}, by the closed form {expected}"
    );
}

/// Eq. 18.44 about O with the weight: `M_x = φ̇ sin θ (I ω_z − I′ φ̇ cos θ) − m g c sin θ`.
#[test]
fn the_required_couple_is_that_of_steady_precession_less_the_weight() {
    let (scene, a) = analysed_example("gyroscope_required_moment", "");
    let g = |n: &str| given(&scene, n);
    let (m, r, c, theta) = (g("m"), g("r"), g("c"), 60f64.to_radians());
    let (phidot, psidot) = (g("phidot"), g("psidot"));
    let (i, i_prime) = (m * r * r / 2.0, m * r * r / 4.0 + m * c * c);
    let omega_z = psidot + phidot * theta.cos();
    let m_x = phidot * theta.sin() * (i * omega_z - i_prime * phidot * theta.cos())
        - m * g("g") * c * theta.sin();
    close(scalar_value(&scene, &a, "M_x"), m_x, "M_x");
    close(scalar_value(&scene, &a, "M_y"), 0.0, "M_y");
    close(scalar_value(&scene, &a, "M_z"), 0.0, "M_z");
    // G on a circle of radius c sin θ about the vertical: the pivot holds up the weight and
    // gives the centripetal force m c sin θ φ̇², horizontal, towards the vertical through O.
    let (r_y, r_z) = (
        scalar_value(&scene, &a, "R_y"),
        scalar_value(&scene, &a, "R_z"),
    );
    let vertical = r_y * theta.sin() + r_z * theta.cos();
    let horizontal = r_y * theta.cos() - r_z * theta.sin();
    close(vertical, m * g("g"), "the vertical component of R");
    close(
        horizontal,
        m * c * theta.sin() * phidot * phidot,
        "its horizontal one",
    );
}

/// At θ = 90°: `m g L = I ψ̇ φ̇`, `I = m r²/2`; `R_y = m g`, `R_z = −m L φ̇²`.
#[test]
fn the_wheel_precesses_at_its_weights_moment_over_its_spin_momentum() {
    let (scene, a) = analysed_example("wheel_gyroscope_horizontal", "");
    let g = |n: &str| given(&scene, n);
    let (m, r, l, psidot) = (g("m"), g("r"), g("L"), g("psidot"));
    let phidot = m * g("g") * l / (m * r * r / 2.0 * psidot);
    close(scalar_value(&scene, &a, "phidot"), phidot, "phidot");
    close(scalar_value(&scene, &a, "R_y"), m * g("g"), "R_y");
    close(
        scalar_value(&scene, &a, "R_z"),
        -m * l * phidot * phidot,
        "R_z",
    );
}

/// The top (OG = r): `(I − I′) cos θ φ̇² + I ψ̇ φ̇ − m g r = 0`, solved here by the quadratic formula;
/// each root is a solution of its own, the slow one first.
#[test]
fn the_top_precesses_slowly_or_fast_at_the_roots_of_its_quadratic() {
    let (scene, a) = analysed_example("top_slow_and_fast_precession", "");
    let g = |n: &str| given(&scene, n);
    let (m, r, psidot, theta) = (g("m"), g("r"), g("psidot"), 30f64.to_radians());
    let (i, i_prime) = (m * r * r / 2.0, m * r * r / 4.0 + m * r * r);
    let (qa, qb, qc) = ((i - i_prime) * theta.cos(), i * psidot, -m * g("g") * r);
    let root = (qb * qb - 4.0 * qa * qc).sqrt();
    let mut roots = [(-qb + root) / (2.0 * qa), (-qb - root) / (2.0 * qa)];
    roots.sort_by(f64::total_cmp);
    let rows: Vec<(Option<usize>, f64)> = a
        .results
        .iter()
        .map(|(request, value)| match value {
            Value::Scalar(e) => (request.solution, e.eval(&|s| scene.value(s)).unwrap()),
            other => panic!("phidot is a scalar: {other:?}"),
        })
        .collect();
    assert_eq!(rows.len(), 2, "{rows:?}");
    assert_eq!((rows[0].0, rows[1].0), (Some(1), Some(2)));
    close(rows[0].1, roots[0], "the slow precession");
    close(rows[1].1, roots[1], "the fast precession");
    assert!(roots[0] > 0.0 && roots[1] > 10.0 * roots[0]);
}

/// Torque-free: `ψ̇ = (I′ − I) φ̇ cos θ / I` (direct: ψ̇ and φ̇ of one sign, I < I′), ω at
/// the angle γ from the axis with `tan γ = (I/I′) tan θ`, and `H_G = I′ φ̇ K`.
#[test]
fn the_torque_free_cylinder_spins_and_precesses_as_eq_18_50_says() {
    let (scene, a) = analysed_example("torque_free_cylinder", "");
    let g = |n: &str| given(&scene, n);
    let (m, r, h, phidot, theta) = (g("m"), g("r"), g("h"), g("phidot"), 30f64.to_radians());
    let (i, i_prime) = (m * r * r / 2.0, m * (3.0 * r * r + h * h) / 12.0);
    let psidot = (i_prime - i) * phidot * theta.cos() / i;
    close(scalar_value(&scene, &a, "psidot"), psidot, "psidot");
    assert!(psidot * phidot > 0.0, "a long body precesses directly");
    let omega = numbers(&scene, &a, "omega");
    close(omega[0], 0.0, "omega_x");
    close(omega[1] / omega[2], i / i_prime * theta.tan(), "tan(gamma)");
    let h_g = numbers(&scene, &a, "H_G");
    close(h_g[1], i_prime * phidot * theta.sin(), "H_y");
    close(h_g[2], i_prime * phidot * theta.cos(), "H_z");
    let (tan_gamma, sense) = precession(&scene, &a);
    close(
        tan_gamma,
        i / i_prime * theta.tan(),
        "tan(gamma) of find precession",
    );
    assert_eq!(sense, sense_by_hand(i, i_prime));
    assert_eq!(sense, PrecessionSense::Direct);
}

/// A thin disk (`I = m r²/2 > I′ = m r²/4`): retrograde, `ψ̇ = −φ̇ cos θ / 2`, and
/// `tan γ = 2 tan θ`, γ beyond θ; the binary's JSON gives γ in degrees and the sense in words.
#[test]
fn the_torque_free_disk_precesses_retrograde() {
    let (scene, a) = analysed_example("torque_free_disk", "");
    let g = |n: &str| given(&scene, n);
    let (m, r, phidot, theta) = (g("m"), g("r"), g("phidot"), g("theta"));
    let (i, i_prime) = (m * r * r / 2.0, m * r * r / 4.0);
    let psidot = (i_prime - i) * phidot * theta.cos() / i;
    close(scalar_value(&scene, &a, "psidot"), psidot, "psidot");
    assert!(psidot * phidot < 0.0, "a flat body precesses retrograde");
    let tan_gamma = i / i_prime * theta.tan();
    let (derived, sense) = precession(&scene, &a);
    close(derived, tan_gamma, "tan(gamma)");
    assert_eq!(sense, sense_by_hand(i, i_prime));
    assert_eq!(sense, PrecessionSense::Retrograde);
    let path = format!(
        "{}/examples/scenes/torque_free_disk.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let out = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(["solve", "--format", "json", &path])
        .output()
        .expect("the binary runs");
    assert!(out.status.success());
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let row = |name: &str| {
        doc["results"]
            .as_array()
            .and_then(|rows| rows.iter().find(|r| r["name"] == name))
            .unwrap_or_else(|| panic!("no row {name}"))
            .clone()
    };
    let gamma = row("gamma");
    assert_eq!(gamma["unit"], "deg");
    let degrees = gamma["value"].as_f64().expect("a number");
    close(degrees, tan_gamma.atan().to_degrees(), "gamma in degrees");
    assert!(
        degrees > theta.to_degrees(),
        "gamma > theta in retrograde precession"
    );
    let words = row("precession");
    assert_eq!(words["text"], "retrograde precession (I' < I)");
    assert!(words["value"].is_null());
}

/// `find precession` is refused at the `find` in a scene with loads, or without `euler
/// angles`, saying why.
#[test]
fn a_precession_is_refused_with_loads_or_without_eulerian_angles() {
    let path = format!(
        "{}/examples/scenes/torque_free_disk.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("the example exists");
    let refusal = |text: &str| {
        let scene = kinetics::parse_scene(&path, text).unwrap_or_else(|d| panic!("{}", d.render()));
        let d = kinetics::analyse(&scene).expect_err("refused");
        let at = &text[d.span.offset()..d.span.offset() + d.span.len()];
        (d.message, at.to_string())
    };
    let loaded = text
        .replace(
            "vbar = 0",
            "given g = 9.81 m/s^2\nforce W = -m*g*K at (0, 0, 0)\nvbar = 0",
        )
        .replace("find psidot, precession", "find precession");
    let (message, at) = refusal(&loaded);
    assert!(message.contains("under no force"), "{message}");
    assert_eq!(at, "precession");
    let unstated = text
        .replace("euler angles steady\n", "omega = w*k\n")
        .replace("unknown psidot", "given w = 3 rad/s")
        .replace("find psidot, precession", "find precession");
    let (message, at) = refusal(&unstated);
    assert!(message.contains("euler angles"), "{message}");
    assert_eq!(at, "precession");
}

/// A cylinder whose length has no value: the sign of `I′ − I = m (h² − 3 r²)/12` is open, and
/// `find precession` says so, naming h.
#[test]
fn a_precession_whose_sense_needs_values_is_refused_naming_them() {
    let path = format!(
        "{}/examples/scenes/torque_free_cylinder.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path)
        .expect("the example exists")
        .replace("given h = 2 m", "given h : m")
        .replace("find psidot, omega, H_G, precession", "find precession");
    let scene = kinetics::parse_scene(&path, &text).unwrap_or_else(|d| panic!("{}", d.render()));
    let d = kinetics::analyse(&scene).expect_err("refused");
    assert!(d.message.contains("not decided"), "{}", d.message);
    assert!(d.message.contains("values for h"), "{}", d.message);
}

/// `kinetics plan` of a steady precession: the Eulerian angles' steps, `Ḣ_O = [I_O]{ω̇} +
/// Ω × H_O`; neither Euler's equations for a general body (Ω = ω) nor an integration.
#[test]
fn the_plan_of_a_steady_precession_pulls_only_what_it_needs() {
    let path = format!(
        "{}/examples/scenes/wheel_gyroscope_horizontal.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let out = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(["plan", &path])
        .output()
        .expect("the binary runs");
    assert!(out.status.success());
    let plan = String::from_utf8_lossy(&out.stdout);
    for wanted in [
        "Ω = φ̇ K + θ̇ i",
        "steady precession",
        "Ω × H_O",
        "equations of motion",
    ] {
        assert!(plan.contains(wanted), "the plan lacks {wanted:?}:\n{plan}");
    }
    for unwanted in ["Euler's equations", "integrat", "Ω = ω", "kinetic energy"] {
        assert!(
            !plan.contains(unwanted),
            "the plan has {unwanted:?}:\n{plan}"
        );
    }
}

#[test]
fn worked_solutions_of_the_gyroscopes_in_text_and_latex() {
    for name in EXAMPLES {
        let (scene, a) = analysed_example(name, "");
        insta::assert_snapshot!(
            format!("{name}_text"),
            render(&scene, &a, Format::Text, false)
        );
        insta::assert_snapshot!(
            format!("{name}_latex"),
            render(&scene, &a, Format::Latex, false)
        );
    }
}

/// One quantity, one symbol: no two symbols of an example's steps share a LaTeX spelling.
/// The gyroscope's and the torque-free body's ω_z must be the symbol the Eulerian angles'
/// step derives (`omega_z`): a second one (`w_z`) would share `\omega_z`, and the page would
/// print it `w_z` to keep the two apart.
#[test]
fn each_quantity_of_a_gyroscope_page_is_one_symbol() {
    for name in EXAMPLES {
        let (_, a) = analysed_example(name, "");
        let mut symbols: Vec<kinetics::algebra::Symbol> = a
            .plan
            .iter()
            .flat_map(|s| &s.relations)
            .flat_map(|r| r.lhs.symbols().into_iter().chain(r.rhs.symbols()))
            .collect();
        symbols.sort();
        symbols.dedup();
        for (k, s) in symbols.iter().enumerate() {
            for t in &symbols[k + 1..] {
                assert_ne!(
                    s.latex(),
                    t.latex(),
                    "{name}: {} and {} are one quantity in two symbols",
                    s.name(),
                    t.name()
                );
            }
        }
    }
}

/// The `Answers` block of a text solution.
fn answers(solution: &str) -> Vec<&str> {
    solution
        .lines()
        .skip_while(|l| *l != "Answers")
        .take_while(|l| !l.is_empty())
        .collect()
}

/// `tests/bad_scenes/top_pivot_without_reaction.scene`, the example's top without the force
/// at its pivot, is refused with a help that names the statements adding the reaction;
/// written into the scene as quoted, they give the example's slow and fast precession
/// (which `the_top_precesses_slowly_or_fast_at_the_roots_of_its_quadratic` checks by hand).
#[test]
fn a_top_without_its_pivots_reaction_is_told_the_statements_that_add_it() {
    let root = env!("CARGO_MANIFEST_DIR");
    let read = |path: &str| std::fs::read_to_string(format!("{root}/{path}")).unwrap();
    let bad = read("tests/bad_scenes/top_pivot_without_reaction.scene");
    let (ok, _, stderr) = solve_stdin(&bad, "text");
    assert!(!ok, "{stderr}");
    let help = stderr
        .lines()
        .find_map(|l| l.trim_start().strip_prefix("= help: "))
        .unwrap_or_else(|| panic!("no help in {stderr}"));
    assert!(
        help.starts_with("a fixed point needs its reaction as a force at O"),
        "{help}"
    );
    let statements: Vec<&str> = help.split('\'').skip(1).step_by(2).collect();
    assert_eq!(statements.len(), 2, "{help}");
    let mended = format!("{bad}\n{}\n", statements.join("\n"));
    let (ok, solution, stderr) = solve_stdin(&mended, "text");
    assert!(ok, "{stderr}");
    let (ok, example, stderr) = solve_stdin(
        &read("examples/scenes/top_slow_and_fast_precession.scene"),
        "text",
    );
    assert!(ok, "{stderr}");
    assert_eq!(answers(&solution), answers(&example));
    assert_eq!(answers(&solution).len(), 3, "{solution}");
}

/// `kinetics solve` of a scene given on standard input: (success, stdout, stderr).
fn solve_stdin(scene: &str, format: &str) -> (bool, String, String) {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(["solve", "--format", format, "-"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the binary runs");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(scene.as_bytes())
        .expect("written");
    let out = child.wait_with_output().expect("the binary ends");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The top of `top_slow_and_fast_precession` spinning at 300 rpm: `I²ψ̇² − 4 (I′ − I) cos θ m g
/// r < 0` by hand in f64, so both roots of the quadratic in φ̇ are complex and the scene says
/// so at its `find`, with the reason, instead of "under-determined".
#[test]
fn a_top_spinning_too_slowly_is_refused_with_the_reason() {
    let path = format!(
        "{}/examples/scenes/top_slow_and_fast_precession.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path)
        .expect("the example exists")
        .replace("given psidot = 1800 rpm", "given psidot = 300 rpm");
    let (m, r, g, theta) = (0.5f64, 0.04f64, 9.81f64, 30f64.to_radians());
    let psidot = 300.0 * std::f64::consts::TAU / 60.0;
    let (i, i_prime) = (m * r * r / 2.0, 1.25 * m * r * r);
    let discriminant = (i * psidot).powi(2) - 4.0 * (i_prime - i) * theta.cos() * m * g * r;
    assert!(discriminant < 0.0, "by hand the top spins too slowly");
    let (ok, _, stderr) = solve_stdin(&text, "text");
    assert!(!ok);
    for wanted in [
        "no solution: every root for phidot is ruled out",
        "discriminant",
        "is negative",
        "find phidot",
        "spinning too slowly",
    ] {
        assert!(stderr.contains(wanted), "{wanted:?} not in:\n{stderr}");
    }
}

/// A top whose distance r from the pivot is unknown: `r (r φ̇ (ψ̇/2 − 3/4 φ̇ cos θ) − g) = 0`
/// (eq. 18.44 with I = m r²/2, I′ = 5/4 m r²); r = 0 is dropped in the plan, with the reason
/// (r, a length, must be positive), in text and in JSON, and r is `4g/(φ̇ (2ψ̇ − 3φ̇ cos θ))`.
#[test]
fn a_dropped_root_is_shown_with_its_reason() {
    let scene = "given m = 0.5 kg
given g = 9.81 m/s^2
given theta = 30 deg
given psidot = 1800 rpm
given phidot = 2 rad/s
unknown r : m
unknown R_x, R_y, R_z : N
euler angles steady
fixed point
body disk(r) mass m at (0, 0, r) along z
force W = -m*g*K at (0, 0, r)
force R = R_x*i + R_y*j + R_z*k at (0, 0, 0)
find r
";
    let (ok, text, stderr) = solve_stdin(scene, "text");
    assert!(ok, "{stderr}");
    let step = text
        .split("\n\n")
        .find(|s| s.contains("a root ruled out"))
        .unwrap_or_else(|| panic!("no dropped root in:\n{text}"));
    assert!(
        step.contains("r would be zero; it must be positive"),
        "{step}"
    );
    assert!(step.contains("\n  r = 0"), "{step}");
    let (ok, json, _) = solve_stdin(scene, "json");
    assert!(ok);
    let doc: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let titles: Vec<&str> = doc["plan"]
        .as_array()
        .expect("a plan")
        .iter()
        .filter_map(|t| t.as_str())
        .collect();
    assert!(
        titles.contains(&"a root ruled out: r would be zero; it must be positive"),
        "{titles:?}"
    );
    let (g, theta, phidot) = (9.81f64, 30f64.to_radians(), 2.0f64);
    let psidot = 1800.0 * std::f64::consts::TAU / 60.0;
    let r = 4.0 * g / (phidot * (2.0 * psidot - 3.0 * phidot * theta.cos()));
    let derived = doc["results"][0]["value"].as_f64().expect("r has a value");
    close(derived, r, "r");
}
