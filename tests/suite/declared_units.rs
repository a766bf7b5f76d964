//! A result takes its unknown's declared unit (issue 32): `unknown C_x : lb` shows C_x in
//! pounds and `unknown theta : deg` in degrees without `find … in`, converted from the SI
//! value worked out by hand here; `find … in` still wins.

use kinetics::scene::{analyse, parse_scene};
use kinetics::solution::{render, Format};

const ROD: &str = "given m = 10 kg
given L = 2 ft
given w = 60 rpm
unknown C_x : lb
body rod(L) mass m at (L/2, 0, 0)
fixed point
omega = w*k
force C = C_x*i at (0, 0, 0)
find C_x";

fn page(text: &str) -> String {
    let scene = parse_scene("t.scene", text).unwrap();
    let analysis = analyse(&scene).unwrap();
    render(&scene, &analysis, Format::Text, false)
}

/// The number after `name = … = ` on the results line, and its unit.
fn shown(page: &str, name: &str) -> (f64, String) {
    let results = page.split("Results").nth(1).expect("a results block");
    let line = results
        .lines()
        .find(|l| l.trim_start().starts_with(&format!("{name} =")))
        .expect("the result's line");
    let value = line.rsplit(" = ").next().unwrap();
    let (number, unit) = value.split_once(' ').unwrap();
    (number.parse().unwrap(), unit.to_string())
}

#[test]
fn an_unknown_declared_in_pounds_is_shown_in_pounds() {
    // By hand: C_x = −m (L/2) ω², L = 0.6096 m, ω = 2π rad/s; 1 lb = 4.4482216152605 N.
    let newtons = -10.0 * 0.3048 * (2.0 * std::f64::consts::PI).powi(2);
    let pounds = newtons / 4.448_221_615_260_5;
    let (number, unit) = shown(&page(ROD), "C_x");
    assert_eq!(unit, "lb");
    assert!((number - pounds).abs() < 0.005, "{number} against {pounds}");
    // `find … in` is the unit asked for.
    let (number, unit) = shown(&page(&ROD.replace("find C_x", "find C_x in N")), "C_x");
    assert_eq!(unit, "N");
    assert!(
        (number - newtons).abs() < 0.05,
        "{number} against {newtons} (four figures)"
    );
}

#[test]
fn an_unknown_angle_declared_in_degrees_is_shown_in_degrees() {
    let text = std::fs::read_to_string("examples/scenes/top_steady_tilt.scene")
        .unwrap()
        .replace("unknown theta : rad", "unknown theta : deg");
    let (number, unit) = shown(&page(&text), "theta");
    assert_eq!(unit, "deg");
    assert!((number - 31.17).abs() < 0.005, "{number}");
}

#[test]
fn the_customary_and_everyday_units_have_their_exact_factors() {
    use kinetics::{Expr, Symbol};
    let text = "given v = 72 km/h
given u = 45 mi/h
given P = 2 kip
given Q = 12 oz
given F = 3 lbf
given M = 30 in*lb
given t1 = 0.5 h
given M_s = 1 kg
body sphere(0.1 m) mass M_s
find T";
    let scene = parse_scene("t.scene", text).unwrap();
    let exact = |name: &str| scene.exact_given(Symbol::new(name)).unwrap();
    let lbf = Expr::rational(44_482_216_152_605, 10_000_000_000_000);
    // 72 km/h = 20 m/s; 45 mi/h = 45 · 1609.344/3600 = 20.1168 m/s; 0.5 h = 1800 s.
    assert_eq!(exact("v"), Expr::int(20));
    assert_eq!(exact("u"), Expr::rational(201_168, 10_000));
    assert_eq!(exact("t_1"), Expr::int(1800));
    // 2 kip = 2000 lbf; 12 oz = 12/16 lbf; 30 in·lb = 30 · 0.0254 m · 1 lbf.
    assert_eq!(exact("P"), Expr::int(2000) * lbf.clone());
    assert_eq!(exact("Q"), Expr::rational(3, 4) * lbf.clone());
    assert_eq!(exact("F"), Expr::int(3) * lbf.clone());
    assert_eq!(exact("M"), Expr::rational(762, 1000) * lbf);
}
