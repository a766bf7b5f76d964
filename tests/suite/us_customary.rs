//! The page in the givens' unit system (issue 32): a shaft stated in lb, in, ft and rpm shows
//! every result and intermediate value in U.S. customary units (lb, ft, slug, lb·ft,
//! slug·ft², lb·ft·s) without `find … in`, each against a hand computation in those units;
//! the system chosen on the command line (`--units`) wins over the givens'.

use crate::common::examples::analysed_example;
use kinetics::scene::unit_system::UnitSystem;
use kinetics::scene::{Analysis, Scene};
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

/// `--units si` (the scene's system set before the page is written) shows the same shaft in
/// newtons and kg·m²: the pound is 4.4482216152605 N, the slug·ft² 1.3558179483314 kg·m².
#[test]
fn the_system_chosen_wins_over_the_givens() {
    let (mut scene, analysis) = analysed_example("shaft_in_us_units", "");
    let us = numbers(&scene, &analysis);
    scene.unit_system = UnitSystem::Si;
    let si = numbers(&scene, &analysis);
    let (unit, newtons) = first(&si, "B_y");
    assert_eq!(unit, "N");
    assert!((newtons - first(&us, "B_y").1 * 4.4482216152605).abs() < 1e-9 * newtons);
    let (unit, inertia) = first(&si, "I_x");
    assert_eq!(unit, "kg·m²");
    let slug_ft2 = 4.4482216152605 / 0.3048 * 0.3048 * 0.3048;
    assert!((inertia - first(&us, "I_x").1 * slug_ft2).abs() < 1e-12);
}
