//! Issue 18, items 4 and 5: the engineer's page (`solve --numbers`), the answers before the
//! symbolic steps when every given has a value, and one spelling of a name everywhere.
//!
//! Sample Problem 18.3 by hand (L = 2.4 m, m = 20 kg, ω = 15 rad/s, β = 60°, g = 9.81):
//! `ā = −½ L cos β ω² i = −135 m/s² i`; `I_xy = ⅙ m L² sin 2β = 16.63 kg·m²` about A;
//! `Ḣ_z = I_xy ω² = 3741 N·m`; `T_BC = m g cot β / 2 + ⅓ m L cos β ω² = 1857 N`.

use super::common::binary::{kinetics, kinetics_with_input, scene};
use serde_json::Value;

fn solve(args: &[&str]) -> String {
    let (code, out, err) = kinetics(args);
    assert_eq!(code, 0, "{err}");
    out
}

fn by_hand() -> (f64, f64, f64, f64) {
    let (l, m, w, beta, g) = (2.4f64, 20.0, 15.0, 60f64.to_radians(), 9.81);
    let abar_x = -0.5 * l * beta.cos() * w * w;
    let i_xy = m * l * l * (2.0 * beta).sin() / 6.0;
    let t_bc = m * g / (2.0 * beta.tan()) + m * l * beta.cos() * w * w / 3.0;
    (abar_x, i_xy, i_xy * w * w, t_bc)
}

#[test]
fn the_engineers_page_in_text_has_numbers_not_steps() {
    let (abar_x, i_xy, hdot_z, t_bc) = by_hand();
    let rod = scene("sp18_3_rotating_rod");
    let out = solve(&["solve", &rod, "--numbers"]);
    assert!(!out.contains("Step "), "{out}");
    assert!(!out.contains("cos(beta)"), "symbolic terms:\n{out}");
    let results = &out[out.find("Results").unwrap()..out.find("Intermediate values").unwrap()];
    assert!(
        results.contains(&format!("abar = -({:.0} m/s²) i", -abar_x)),
        "{results}"
    );
    assert!(
        results.contains(&format!("T_BC = {t_bc:.0} N")),
        "{results}"
    );
    assert!(results.contains("A_z = 0 N"), "{results}");
    assert!(out.contains(&format!("I_xy = {i_xy:.2} kg·m²")), "{out}");
    assert!(out.contains(&format!("Hdot_z = {hdot_z:.0} N·m")), "{out}");
}

#[test]
fn the_engineers_page_in_json() {
    let (abar_x, i_xy, _, t_bc) = by_hand();
    let rod = scene("sp18_3_rotating_rod");
    let json: Value =
        serde_json::from_str(&solve(&["solve", &rod, "--numbers", "--format", "json"])).unwrap();
    assert!(json.get("steps").is_none());
    let results = json["results"].as_array().unwrap();
    let t = results.iter().find(|r| r["name"] == "T_BC").unwrap();
    assert!((t["value"].as_f64().unwrap() / t_bc - 1.0).abs() < 1e-12);
    assert_eq!(t["unit"], "N");
    let abar = results.iter().find(|r| r["name"] == "abar").unwrap();
    assert!((abar["value"][0].as_f64().unwrap() / abar_x - 1.0).abs() < 1e-12);
    assert_eq!(abar["value"][1], 0.0);
    let values: Vec<&Value> = json["intermediate"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|s| s["values"].as_array().unwrap())
        .collect();
    let product = values.iter().find(|v| v["name"] == "I_xy").unwrap();
    assert!((product["value"].as_f64().unwrap() / i_xy - 1.0).abs() < 1e-12);
    assert_eq!(product["unit"], "kg·m²");
}

/// The engineer's page in every notation is the same page: each answer and each
/// intermediate value the text page gives is in the LaTeX, Markdown and HTML pages too.
#[test]
fn the_numbers_page_in_every_notation() {
    let rod = scene("sp18_3_rotating_rod");
    let text = solve(&["solve", &rod, "--numbers"]);
    assert!(text.contains("  T_BC = 1857 N\n"), "{text}");
    let latex = solve(&["solve", &rod, "--numbers", "--format", "latex"]);
    let markdown = solve(&["solve", &rod, "--numbers", "--format", "markdown"]);
    let html = solve(&["solve", &rod, "--numbers", "--format", "html"]);
    assert!(latex.contains(r"T_{BC} &= 1857\,\mathrm{N}"), "{latex}");
    assert!(
        latex.contains(r"\paragraph{Intermediate values}"),
        "{latex}"
    );
    assert!(markdown.contains("## Intermediate values"), "{markdown}");
    assert!(html.contains("<h2>Intermediate values</h2>"), "{html}");
    // Every number of the text page (its right-hand sides' digits) is on the other pages.
    let numbers: Vec<&str> = text
        .lines()
        .filter_map(|l| l.split(" = ").nth(1)?.split(' ').next())
        .filter(|n| n.parse::<f64>().is_ok())
        .collect();
    assert!(numbers.len() > 10, "{text}");
    for n in numbers {
        let magnitude = n.trim_start_matches('-');
        assert!(latex.contains(magnitude), "{n} not in\n{latex}");
        assert!(markdown.contains(magnitude), "{n} not in\n{markdown}");
        assert!(
            html.contains(&format!("<mn>{magnitude}</mn>")),
            "{n} not in\n{html}"
        );
    }
}

#[test]
fn with_every_value_given_the_answers_come_before_the_steps() {
    let out = solve(&["solve", &scene("sp18_3_rotating_rod")]);
    let answers = out.find("Answers\n").expect("an Answers block");
    assert!(answers < out.find("Step 1").unwrap(), "{out}");
    assert!(
        out[answers..].starts_with("Answers\n  abar = -(135 m/s²) i\n"),
        "{out}"
    );
    // A symbolic given: no answers block, the steps first.
    let symbolic = solve(&["solve", &scene("long_relations")]);
    assert!(!symbolic.contains("Answers"), "{symbolic}");
}

const TWO_SPELLINGS: &str = "given m = 2 kg
given r = 0.1 m
given w1 = 3 rad/s
unknown M1 : N*m
body sphere(r) mass m
fixed point
omega = w1*k
couple M1*k
find T, M1
";

/// `w1` and `w_1` are one symbol; the page spells it one way, `w_1` (ω₁ in LaTeX),
/// in the givens, the steps and the results alike (README: names).
#[test]
fn a_name_has_one_spelling_on_the_page() {
    let text = kinetics_with_input(&["solve", "-"], TWO_SPELLINGS).stdout;
    assert!(text.contains("  w_1 = 3 rad/s\n"), "{text}");
    assert!(text.contains("T = 1/5*m*r^2*w_1^2 = 0.036 J"), "{text}");
    assert!(text.contains("  M_1 = 0 N·m\n"), "{text}");
    assert!(!text.contains("w1") && !text.contains("M1"), "{text}");
    let json: Value = serde_json::from_str(
        &kinetics_with_input(&["solve", "-", "--format", "json"], TWO_SPELLINGS).stdout,
    )
    .unwrap();
    assert_eq!(json["givens"][2]["name"], "w_1");
    assert_eq!(json["results"][1]["name"], "M_1");
    assert_eq!(json["results"][0]["text"], "1/5*m*r^2*w_1^2");
    let latex = kinetics_with_input(&["solve", "-", "--format", "latex"], TWO_SPELLINGS).stdout;
    assert!(latex.contains(r"\omega_1 = 3\,\mathrm{rad/s}"), "{latex}");
    assert!(latex.contains(r"M_1 &= 0\,\mathrm{N\cdot m}"), "{latex}");
    assert!(!latex.contains("w1") && !latex.contains("M1"), "{latex}");
}

/// `--digits N` sets the significant figures of every number on the page, in every format:
/// SP 18.3's T_BC = 1857 N (by hand, `by_hand`) is 1860 N in three figures, and A_x, from
/// ΣF_x = A_x − T_BC = m ā_x, is −843.4 N, or −843 N; out of 1..=17 it is refused.
#[test]
fn digits_set_the_significant_figures() {
    let rod = scene("sp18_3_rotating_rod");
    let (abar_x, _, _, t_bc) = by_hand();
    let a_x = 20.0 * abar_x + t_bc;
    assert_eq!(format!("{t_bc:.0}"), "1857");
    assert_eq!(format!("{a_x:.1}"), "-843.4");
    let text = solve(&["solve", &rod, "--digits", "3"]);
    assert!(text.contains("  T_BC = 1860 N\n"), "{text}");
    assert!(text.contains("  A_x = -843 N\n"), "{text}");
    let latex = solve(&["solve", &rod, "--digits", "6", "--format", "latex"]);
    assert!(
        latex.contains(&format!(r"= {t_bc:.2}\,\mathrm{{N}}")),
        "{latex}"
    );
    let (code, _, err) = kinetics(&["solve", &rod, "--digits", "0"]);
    assert_eq!(code, 2);
    assert!(err.contains("0 is not in 1..=17"), "{err}");
}

/// The values of `--numbers` in JSON: (step title, name, value) of every intermediate value.
fn intermediate_values(example: &str) -> Vec<(String, String, f64)> {
    let out = solve(&["solve", &scene(example), "--numbers", "--format", "json"]);
    let page: Value = serde_json::from_str(&out).unwrap();
    let mut all = Vec::new();
    for step in page["intermediate"].as_array().unwrap() {
        let title = step["step"].as_str().unwrap().to_string();
        for v in step["values"].as_array().unwrap() {
            let name = v["name"].as_str().unwrap().to_string();
            all.push((title.clone(), name, v["value"].as_f64().unwrap()));
        }
    }
    all
}

/// A value of a step that holds a solved unknown (θ of a top's steady tilt) is shown with
/// the unknown put in (it was left off the page): K_y = sin θ, ω_z = ψ̇ + φ̇ cos θ and
/// Ḣ_x = m g r sin θ (ΣM_x = Ḣ_x, the weight's moment about O), θ from the hand
/// derivation in the scene: cos θ = 2 (r φ̇ ψ̇ − 2 g)/(3 r φ̇²).
#[test]
fn values_that_hold_a_solved_unknown_are_on_the_numbers_page() {
    let (m, r, g, phidot, psidot) = (0.5f64, 0.04, 9.81, 2.65, 60.0 * std::f64::consts::PI);
    let theta = (2.0 * (r * phidot * psidot - 2.0 * g) / (3.0 * r * phidot * phidot)).acos();
    let all = intermediate_values("top_steady_tilt");
    let value = |name: &str| {
        let found = all.iter().find(|(_, n, _)| n == name);
        found
            .unwrap_or_else(|| panic!("{name} on the page: {all:?}"))
            .2
    };
    let close = |got: f64, want: f64| {
        assert!(
            (got - want).abs() <= 1e-9 * want.abs(),
            "{got} against {want}"
        )
    };
    close(value("K_y"), theta.sin());
    close(value("omega_z"), psidot + phidot * theta.cos());
    close(value("Hdot_x"), m * g * r * theta.sin());
}

/// With two solutions (a top's slow and fast precession), each value that holds the
/// unknown is shown once per solution under `(solution k)`: ω_y = φ̇ₖ sin θ with each φ̇ₖ
/// of I' φ̇² cos θ − I ψ̇ φ̇ + m g r = 0 for the disk (I = m r²/2, I' = 5/4 m r² about O)
/// after the factor sin θ.
#[test]
fn values_of_each_solution_under_its_number() {
    let (m, r, g, theta, psidot) = (
        0.5f64,
        0.04,
        9.81,
        30f64.to_radians(),
        60.0 * std::f64::consts::PI,
    );
    let (i, i_prime) = (m * r * r / 2.0, 1.25 * m * r * r);
    // I ω_z φ̇ − I' φ̇² cos θ = m g r with ω_z = ψ̇ + φ̇ cos θ: (I − I') cos θ φ̇² + I ψ̇ φ̇ − m g r = 0.
    let (a, b, c) = ((i - i_prime) * theta.cos(), i * psidot, -m * g * r);
    let roots = [
        (-b + (b * b - 4.0 * a * c).sqrt()) / (2.0 * a),
        (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a),
    ];
    let all = intermediate_values("top_slow_and_fast_precession");
    for k in [1, 2] {
        let omega_y = all
            .iter()
            .find(|(t, n, _)| t.ends_with(&format!("(solution {k})")) && n == "omega_y")
            .unwrap_or_else(|| panic!("omega_y of solution {k}: {all:?}"))
            .2;
        assert!(
            roots
                .iter()
                .any(|p| (omega_y - p * theta.sin()).abs() <= 1e-9 * omega_y.abs()),
            "omega_y = {omega_y} against the roots {roots:?}"
        );
    }
}
