//! The bodies of issue 32: the solid cone (placed by its mass centre, apex ¾h behind it),
//! the tube, the spherical shell, the thin ring and a body given by its radii of gyration,
//! read from scenes and compared with the textbook's formulas written here by hand; and the
//! refusals of a tube whose inner radius is not the smaller and of radii of gyration no body
//! has, on their wording.

use crate::common::examples::{analysed_example, result};
use kinetics::scene::{analyse, parse_scene, Value};
use kinetics::{parse_expression, Expr};

fn hand(text: &str) -> Expr {
    parse_expression("by hand", text).unwrap().expand().unwrap()
}

/// The diagonal and the products of `find NAME`'s tensor, each expanded.
fn tensor(text: &str, name: &str) -> [Expr; 6] {
    let scene = parse_scene("t.scene", text).unwrap();
    let analysis = analyse(&scene).unwrap();
    let Value::Tensor(m) = result(&analysis, name) else {
        panic!("{name} is a tensor")
    };
    let at = |r: usize, c: usize| m[(r, c)].expand().unwrap();
    [at(0, 0), at(1, 1), at(2, 2), at(0, 1), at(1, 2), at(0, 2)]
}

fn refusal(text: &str) -> String {
    match parse_scene("t.scene", text) {
        Ok(_) => panic!("read, not refused"),
        Err(e) => e.render(),
    }
}

#[test]
fn a_solid_cone_about_its_mass_centre_and_about_its_apex() {
    // The apex at O, the axis along x: G is 3h/4 from the apex.
    let scene = "given m : kg
given r : m
given h : m
body cone(r, h) mass m at (3/4*h, 0, 0)
fixed point
find I_G, I_O";
    let axis = hand("3/10 m r^2");
    let across_g = hand("3/80 m (4 r^2 + h^2)");
    let across_apex = hand("3/5 m (r^2/4 + h^2)");
    let zero = Expr::zero();
    assert_eq!(
        tensor(scene, "I_G"),
        [
            axis.clone(),
            across_g.clone(),
            across_g,
            zero.clone(),
            zero.clone(),
            zero.clone()
        ]
    );
    assert_eq!(
        tensor(scene, "I_O"),
        [
            axis,
            across_apex.clone(),
            across_apex,
            zero.clone(),
            zero.clone(),
            zero
        ]
    );
}

#[test]
fn tube_shell_ring_and_radii_of_gyration_by_their_formulas() {
    let with = |body: &str| {
        format!("given m : kg\ngiven a : m\ngiven b : m\ngiven c : m\nbody {body} mass m\nfind I_G")
    };
    let diagonal = |body: &str| {
        let t = tensor(&with(body), "I_G");
        assert!(t[3..].iter().all(Expr::is_zero), "{body}: principal");
        [t[0].clone(), t[1].clone(), t[2].clone()]
    };
    let tube_across = hand("m (3 (a^2 + b^2) + c^2)/12");
    assert_eq!(
        diagonal("tube(a, b, c)"),
        [hand("m (a^2 + b^2)/2"), tube_across.clone(), tube_across]
    );
    let shell = hand("2/3 m a^2");
    assert_eq!(diagonal("shell(a)"), [shell.clone(), shell.clone(), shell]);
    assert_eq!(
        diagonal("ring(a)"),
        [hand("m a^2"), hand("m a^2/2"), hand("m a^2/2")]
    );
    assert_eq!(
        diagonal("gyration(a, b, c)"),
        [hand("m a^2"), hand("m b^2"), hand("m c^2")]
    );
}

#[test]
fn a_tube_whose_inner_radius_is_not_the_smaller_is_refused_at_the_body() {
    let message = refusal("given M = 3 kg\nbody tube(0.1 m, 0.2 m, 0.4 m) mass M\nfind I_G");
    assert!(
        message.contains("the wall thickness of body 1 (tube), 0.1 m - 0.2 m, is negative"),
        "{message}"
    );
    assert!(message.contains("t.scene:2:6"), "{message}");
    assert!(
        message.contains("the inner radius must be less than the outer: tube(r_o, r_i, h)"),
        "{message}"
    );
}

#[test]
fn radii_of_gyration_no_body_has_are_refused() {
    // k_z² = 0.16 m² exceeds k_x² + k_y² = 0.05 m²: I_z > I_x + I_y.
    let message = refusal("given M = 3 kg\nbody gyration(0.1 m, 0.2 m, 0.4 m) mass M\nfind I_G");
    assert!(message.contains("triangle inequality"), "{message}");
    assert!(
        message.contains("no real body has these radii of gyration"),
        "{message}"
    );
}

#[test]
fn the_rolling_cone_example_against_a_hand_computation() {
    // The example's comment works it by hand: ω = -8/3 i rad/s and T = 1.008 J.
    let (scene, analysis) = analysed_example("cone_rolling_about_apex", "");
    let value = |e: &Expr| e.eval(&|s| scene.value(s)).unwrap();
    let Value::Vector(omega) = result(&analysis, "omega") else {
        panic!("ω is a vector")
    };
    let omega: Vec<f64> = omega.iter().map(value).collect();
    assert!((omega[0] + 8.0 / 3.0).abs() < 1e-12 && omega[1] == 0.0 && omega[2] == 0.0);
    let Value::Scalar(t) = result(&analysis, "T") else {
        panic!("T is a scalar")
    };
    // About the apex in the cone's axes: I = 3/10 m r², I' = 3/5 m (r²/4 + h²); ω along the
    // axis a = (0.8, 0.6, 0) is -8/3 · 0.8, across it (along (-0.6, 0.8, 0)) -8/3 · -0.6.
    let (m, r, h) = (5.0, 0.3, 0.4);
    let (i, i_prime) = (0.3 * m * r * r, 0.6 * m * (r * r / 4.0 + h * h));
    let (along, across) = (-8.0 / 3.0 * 0.8, -8.0 / 3.0 * -0.6);
    let by_hand = 0.5 * (i * along * along + i_prime * across * across);
    assert!(
        (value(t) - by_hand).abs() < 1e-12,
        "{} against {by_hand}",
        value(t)
    );
}
