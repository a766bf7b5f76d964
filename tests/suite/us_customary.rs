//! The page in the givens' unit system (issue 32): a shaft stated in lb, in, ft and rpm shows
//! every result and intermediate value in U.S. customary units (lb, ft, slug, lb·ft,
//! slug·ft², lb·ft·s) without `find … in`, each against a hand computation in those units;
//! the system chosen on the command line (`--units`) wins over the givens'.

use crate::common::examples::{analysed_example, scalar_value};
use kinetics::check::verdict::Verdict;
use kinetics::scene::unit_system::UnitSystem;
use kinetics::scene::{parse_scene_in, Analysis, Scene};
use kinetics::solution::{render_numbers, Format};
use serde_json::Value as Json;

/// The engineer's page as JSON: (name, unit, value or values) of every result and
/// intermediate value.
fn numbers(scene: &Scene, analysis: &Analysis) -> Vec<(String, String, Json)> {
    let page: Json =
        serde_json::from_str(&render_numbers(scene, analysis, Format::Json, false)).unwrap();
    let steps = page["intermediate"].as_array().unwrap();
    let intermediate = steps.iter().flat_map(|s| s["values"].as_array().unwrap());
    page["results"]
        .as_array()
        .unwrap()
        .iter()
        .chain(intermediate)
        .map(|v| {
            let text = |k: &str| v[k].as_str().unwrap().to_string();
            (text("name"), text("unit"), v["value"].clone())
        })
        .collect()
}

fn first<'a>(all: &'a [(String, String, Json)], name: &str) -> (&'a str, f64) {
    let (_, unit, value) = all.iter().find(|(n, ..)| n == name).unwrap();
    (unit, value.as_f64().unwrap())
}

#[test]
fn a_shaft_in_pounds_and_feet_is_worked_in_pounds_and_feet() {
    let (scene, analysis) = analysed_example("shaft_in_us_units", "");
    assert_eq!(scene.unit_system, UnitSystem::Us);
    let all = numbers(&scene, &analysis);
    let us = [
        "lb",
        "ft",
        "slug",
        "lb·ft",
        "slug·ft²",
        "lb·ft·s",
        "ft/s²",
        "rad/s",
        "rad/s²",
    ];
    for (name, unit, _) in &all {
        assert!(us.contains(&unit.as_str()), "{name} in {unit}");
    }
    // By hand, in U.S. units: each rod W/g slugs, c = 5/12 ft, ω = 1200 rpm = 40π rad/s.
    let (w_lb, c, l, g) = (3.0, 5.0 / 12.0, 2.5, 32.2);
    let omega = 1200.0 * std::f64::consts::PI / 30.0;
    let rod = w_lb / g;
    let i_x = 2.0 * rod * c * c / 3.0;
    let i_xy = rod * (l / 4.0) * (c / 2.0) - rod * (3.0 * l / 4.0) * (c / 2.0);
    let b_y = -i_xy * omega * omega / l;
    let close = |got: (&str, f64), unit: &str, want: f64| {
        assert_eq!(got.0, unit);
        assert!(
            (got.1 - want).abs() <= 1e-12 * want.abs(),
            "{got:?} against {want}"
        );
    };
    close(first(&all, "B_y"), "lb", b_y);
    close(first(&all, "A_y"), "lb", -b_y);
    close(first(&all, "m_body"), "slug", 2.0 * rod);
    close(first(&all, "I_x"), "slug·ft²", i_x);
    close(first(&all, "I_xy"), "slug·ft²", i_xy);
    close(first(&all, "Hdot_z"), "lb·ft", -i_xy * omega * omega);
    close(first(&all, "H_x"), "lb·ft·s", i_x * omega);
    assert!((b_y - 153.25).abs() < 0.01);
}

/// `--units si` (the scene read in SI, `parse_scene_in`) shows the same shaft in newtons and
/// kg·m²: the pound is 4.4482216152605 N, the slug·ft² 1.3558179483314 kg·m².
#[test]
fn the_system_chosen_wins_over_the_givens() {
    let (scene, analysis) = analysed_example("shaft_in_us_units", "");
    let us = numbers(&scene, &analysis);
    let (scene, analysis) = in_system(&scene.source, UnitSystem::Si);
    assert_eq!(scene.unit_system, UnitSystem::Si);
    let si = numbers(&scene, &analysis);
    let (unit, newtons) = first(&si, "B_y");
    assert_eq!(unit, "N");
    assert!((newtons - first(&us, "B_y").1 * 4.4482216152605).abs() < 1e-9 * newtons);
    let (unit, inertia) = first(&si, "I_x");
    assert_eq!(unit, "kg·m²");
    let slug_ft2 = 4.4482216152605 / 0.3048 * 0.3048 * 0.3048;
    assert!((inertia - first(&us, "I_x").1 * slug_ft2).abs() < 1e-12);
}

/// `text` read in `system` and analysed.
fn in_system(text: &str, system: UnitSystem) -> (Scene, Analysis) {
    let scene = parse_scene_in("shaft.scene", text, Some(system)).unwrap();
    let analysis = kinetics::analyse(&scene).unwrap();
    (scene, analysis)
}

/// The shaft with its lengths written inside the mathematics (`at (0.625 ft, 2.5 in, 0)`).
const INLINE: &str = "given W = 3 lb\ngiven w = 1200 rpm\ngiven g = 32.2 ft/s^2\n\
    unknown A_y, A_z, B_y, B_z\n\
    body rod(5 in) mass W/g at (0.625 ft, 2.5 in, 0) along y\n\
    body rod(5 in) mass W/g at (1.875 ft, -2.5 in, 0) along y\n\
    fixed point\nomega = w*i\n\
    force A = A_y*j + A_z*k at (0, 0, 0)\nforce B = B_y*j + B_z*k at (2.5 ft, 0, 0)\n\
    find A_y, B_y\n";

/// The relation `lhs = rhs` of the step whose title holds `title`, as text.
fn relation(analysis: &Analysis, title: &str, lhs: &str) -> String {
    let step = analysis
        .plan
        .iter()
        .find(|s| kinetics::print::markup::text(&s.title).contains(title))
        .unwrap_or_else(|| panic!("a step {title}"));
    let r = step
        .relations
        .iter()
        .find(|r| r.lhs.to_string() == lhs)
        .unwrap_or_else(|| panic!("{lhs} in {title}: {:?}", step.relations));
    r.rhs.to_string()
}

/// Numbers written with units inside the mathematics are worked in the page's system: on a
/// page in feet, 2.5 in is 5/24 and the rods' mass centre 5/4 ft along the shaft (it showed
/// 381/1000, metres); the equation of moments has the arm 5/2 (ft). In SI the same scene
/// shows metres (381/1000 = 1.25 × 0.3048), and B_y is the same force either way.
#[test]
fn numbers_with_units_in_the_mathematics_are_in_the_pages_units() {
    let (scene, analysis) = in_system(INLINE, UnitSystem::Us);
    assert_eq!(scene.unit_system, UnitSystem::Us);
    assert_eq!(relation(&analysis, "mass centre", "rbar_x"), "5/4");
    let moments = relation(&analysis, "equations of motion", "5/2*B_y");
    assert!(moments.contains("W*w^2/"), "{moments}");
    let us = scalar_value(&scene, &analysis, "B_y");
    let (si_scene, si_analysis) = in_system(INLINE, UnitSystem::Si);
    assert_eq!(relation(&si_analysis, "mass centre", "rbar_x"), "381/1000");
    let si = scalar_value(&si_scene, &si_analysis, "B_y");
    // By hand, in feet and slugs: B_y = W c w²/(4 g) with c = 5/12 ft.
    let omega = 40.0 * std::f64::consts::PI;
    let by_hand = 3.0 * (5.0 / 12.0) * omega * omega / (4.0 * 32.2);
    assert!(
        (us - by_hand).abs() < 1e-12 * by_hand,
        "{us} against {by_hand}"
    );
    assert!((si - by_hand * 4.4482216152605).abs() < 1e-9 * si, "{si}");
}

/// A claim checked against a scene in U.S. customary units reads a plain number in the
/// scene's units (pounds), a number with a unit in its unit, and reports in pounds.
#[test]
fn a_claim_on_a_us_scene_is_read_and_reported_in_pounds() {
    let (scene, _) = analysed_example("shaft_in_us_units", "");
    let context = kinetics::check::context::Context::scene(&scene);
    let check = |claim: &str| kinetics::check::verdict::check(&context, "claim", claim).unwrap();
    for claim in ["B_y = 153.3 lb", "B_y = 681.7 N", "B_y = 153.3"] {
        let report = check(claim);
        assert_eq!(report.verdict, Verdict::Holds, "{claim}: {report:?}");
        let numbers = report.components[0].numbers.as_ref().unwrap();
        assert_eq!(numbers.unit.as_ref().unwrap().to_string(), "lb");
        assert!(
            (numbers.correct - 153.25).abs() < 0.01,
            "{}",
            numbers.correct
        );
    }
    let wrong = check("B_y = 681.7");
    assert_eq!(
        wrong.verdict,
        Verdict::Differs,
        "681.7 is newtons, not the page's pounds"
    );
}

/// A shaft whose point weights stand at lengths written inside the mathematics (a U.S.
/// instructor's problem): the solved reactions hold hidden lengths of different powers in
/// different terms (`192 M W_1 g + 48 W_1 W_2 g`), which `check` took for a unit mismatch and
/// refused every claim written with a unit; and it reported I_xy in `slug` (the metre's
/// markers put into a scene in feet gave 0.01393 for 0.001294).
const WEIGHTS_AT_INCHES: &str = "given W1 = 4 oz\ngiven W2 = 8 oz\ngiven g = 32.2 ft/s^2\n\
    given L = 2 ft\ngiven w = 600 rpm\ngiven M = 12 in*lb\n\
    unknown alpha : rad/s^2\nunknown A_y, A_z, B_y, B_z : lb\n\
    body point() mass W1/g at (6 in, 4 in, 0)\nbody point() mass W2/g at (18 in, 0, 3 in)\n\
    fixed point\nomega = w*i\nomegadot = alpha*i\n\
    force G1 = -W1*j at (6 in, 4 in, 0)\nforce G2 = -W2*j at (18 in, 0, 3 in)\n\
    force A = A_y*j + A_z*k at (0, 0, 0)\nforce B = B_y*j + B_z*k at (L, 0, 0)\n\
    couple M*i\nfind alpha, A_y, A_z, B_y, B_z, I_O, T\n";

#[test]
fn claims_on_a_scene_with_lengths_in_its_mathematics_are_read_in_its_units() {
    let scene = kinetics::parse_scene("weights.scene", WEIGHTS_AT_INCHES).unwrap();
    assert_eq!(scene.unit_system, UnitSystem::Us);
    let (_, analysis) = in_system(WEIGHTS_AT_INCHES, UnitSystem::Us);
    let b_z = scalar_value(&scene, &analysis, "B_z");
    let context = kinetics::check::context::Context::scene(&scene);
    let check = |claim: &str| kinetics::check::verdict::check(&context, "claim", claim).unwrap();
    let numbers = |claim: &str| {
        let report = check(claim);
        assert_eq!(report.verdict, Verdict::Holds, "{claim}: {report:?}");
        let n = report.components[0].numbers.clone().unwrap();
        (n.correct, n.unit.map(|u| u.to_string()))
    };
    // By hand, in slugs and feet: the weights W/g at (1/2, 1/3, 0) and (3/2, 0, 1/4) ft.
    let (m1, m2) = (0.25 / 32.2, 0.5 / 32.2);
    let i_xy = m1 * 0.5 / 3.0;
    let i_x = m1 / 9.0 + m2 / 16.0;
    let omega = 20.0 * std::f64::consts::PI;
    let (correct, unit) = numbers("I_xy = 0.001294");
    assert!(
        (correct - i_xy).abs() < 1e-12 * i_xy,
        "{correct} against {i_xy}"
    );
    assert_eq!(unit.as_deref(), Some("slug·ft²"));
    let (correct, unit) = numbers("T = 3.619 ft*lb");
    let t = 0.5 * i_x * omega * omega;
    assert!((correct - t).abs() < 1e-12 * t, "{correct} against {t}");
    assert_eq!(unit.as_deref(), Some("ft·lb"));
    // A reaction written in pounds, in newtons, and in ounces: each the solved B_z.
    let newtons = format!("B_z = {:.2} N", b_z * 4.4482216152605);
    let ounces = format!("B_z = {:.1} oz", b_z * 16.0);
    for claim in [format!("B_z = {b_z:.2} lb"), newtons, ounces] {
        let (correct, unit) = numbers(&claim);
        assert!((correct - b_z).abs() < 1e-12 * b_z.abs());
        assert_eq!(unit.as_deref(), Some("lb"), "{claim}");
    }
    // A wrong plain number is decided by its value, not refused as inhomogeneous.
    let wrong = check(&format!("B_z = {:.2}", b_z * 0.7));
    assert_eq!(wrong.verdict, Verdict::Differs);
    assert!(wrong.odd_term.is_none(), "{wrong:?}");
    assert!(wrong.components[0].numbers.is_some());
}

/// A cone top stated in ounces and inches, two steady precessions: φ̇ holds a root of a sum
/// whose terms hide different powers of the foot (`sqrt(81 ψ̇² − 26400 g cos θ)`), which
/// `check` refused as inhomogeneous. By hand about the apex O (the cone 1.5 in by 2 in, G at
/// ¾h = 1.5 in): I = 3/10 m r², I' = 3/5 m (r²/4 + h²), and W c sin θ = φ̇ sin θ (I ψ̇ +
/// (I − I') φ̇ cos θ), a quadratic in φ̇ whose two roots each hold in their solution.
#[test]
fn both_precessions_of_a_cone_in_inches_are_checked_by_value() {
    let text = "given W = 4 oz\ngiven g = 32.2 ft/s^2\ngiven theta = 30 deg\n\
        given psidot = 1800 rpm\nunknown phidot : rad/s\nunknown R_x, R_y, R_z : lb\n\
        euler angles steady\nfixed point\n\
        body cone(1.5 in, 2 in) mass W/g at (0, 0, 1.5 in) along z\n\
        force Wt = -W*K at (0, 0, 1.5 in)\nforce R = R_x*i + R_y*j + R_z*k at (0, 0, 0)\n\
        find phidot\n";
    let scene = kinetics::parse_scene("cone.scene", text).unwrap();
    let context = kinetics::check::context::Context::scene(&scene);
    let (w, g, r, h) = (0.25_f64, 32.2, 1.5 / 12.0, 2.0 / 12.0);
    let (m, c, theta, psidot) = (
        w / g,
        0.75 * h,
        30f64.to_radians(),
        60.0 * std::f64::consts::PI,
    );
    let (i, i_prime) = (0.3 * m * r * r, 0.6 * m * (r * r / 4.0 + h * h));
    let (a, b, k) = ((i - i_prime) * theta.cos(), i * psidot, -w * c);
    let root = |sign: f64| (-b + sign * (b * b - 4.0 * a * k).sqrt()) / (2.0 * a);
    for phidot in [root(1.0), root(-1.0)] {
        let claim = format!("phidot = {phidot:.4} rad/s");
        let report = kinetics::check::verdict::check(&context, "claim", &claim).unwrap();
        assert_eq!(report.verdict, Verdict::Holds, "{claim}: {report:?}");
        let n = report.components[0].numbers.as_ref().unwrap();
        assert!(
            (n.correct - phidot).abs() < 1e-9 * phidot,
            "{} against {phidot}",
            n.correct
        );
    }
}

/// A term of the wrong dimension in a claim on a scene in U.S. units is named in its units
/// (it said "N·m where the other term is in N").
#[test]
fn an_odd_term_on_a_us_scene_is_named_in_pounds_and_feet() {
    let (scene, _) = analysed_example("shaft_in_us_units", "");
    let context = kinetics::check::context::Context::scene(&scene);
    let report = kinetics::check::verdict::check(&context, "claim", "B_y = W*c").unwrap();
    let odd = report.odd_term.expect("W*c is a moment, B_y a force");
    assert_eq!(odd.reason, "is in lb·ft where the other term is in lb");
}

/// `--units si` wins over an unknown's unit of the other system (`: lb` shows newtons, as
/// the rest of the page), and not over a unit of both (`: deg`).
#[test]
fn the_system_chosen_wins_over_an_unknowns_unit_of_the_other_system() {
    let text = "given W = 3 lb\ngiven c = 5 in\ngiven L = 2.5 ft\ngiven w = 1200 rpm\n\
        given g = 32.2 ft/s^2\nunknown A_y, A_z, B_y, B_z : lb\nunknown beta : deg\n\
        body rod(c) mass W/g at (L/4, c/2, 0) along y\n\
        body rod(c) mass W/g at (3*L/4, -c/2, 0) along y\n\
        fixed point\nomega = w*i\nforce A = A_y*j + A_z*k at (0, 0, 0)\n\
        force B = B_y*j + B_z*k at (L, 0, 0)\nconstraint beta = 30 deg\nfind B_y, beta\n";
    let (us, _) = in_system(text, UnitSystem::Us);
    let (si, _) = in_system(text, UnitSystem::Si);
    let unit_of = |scene: &Scene, name: &str| {
        let request = scene.requests.iter().find(|r| r.name == name).unwrap();
        request.shown_in.as_ref().map(ToString::to_string)
    };
    assert_eq!(unit_of(&us, "B_y").as_deref(), Some("lb"));
    assert_eq!(unit_of(&si, "B_y"), None, "N, the system's unit");
    assert_eq!(unit_of(&si, "beta").as_deref(), Some("deg"));
}
