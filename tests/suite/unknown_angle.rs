//! An unknown angle inside sin and cos (issue 32): a top's steady tilt θ for a given
//! precession and spin, solved exactly through cos θ, against the moment equation solved
//! by bisection here in f64; the vertical axis (θ = 0, 180°) ruled out with its reason; and
//! a precession too fast for any tilt refused naming why.

use crate::common::examples::{analysed_example, edited_example, scalar_value};
use kinetics::scene::{analyse, parse_scene, Value};

/// `ΣM_x − Ḣ_x` past its factor sin θ for the disk top about its pivot: W r − (I ω_z −
/// I′ φ̇ cos θ) φ̇, I = m r²/2, I′ = 5/4 m r², ω_z = ψ̇ + φ̇ cos θ.
fn moment_balance(theta: f64, phidot: f64, psidot: f64) -> f64 {
    let (m, r, g) = (0.5, 0.04, 9.81);
    let (i, i_prime) = (m * r * r / 2.0, 1.25 * m * r * r);
    let omega_z = psidot + phidot * theta.cos();
    m * g * r - (i * omega_z - i_prime * phidot * theta.cos()) * phidot
}

/// The root of `f` in (a, b) by bisection, its ends of opposite signs.
fn bisection(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    assert!(f(a) * f(b) < 0.0, "a sign change in the bracket");
    for _ in 0..200 {
        let mid = 0.5 * (a + b);
        if f(a) * f(mid) <= 0.0 {
            b = mid;
        } else {
            a = mid;
        }
    }
    0.5 * (a + b)
}

#[test]
fn a_top_s_steady_tilt_for_a_given_precession_and_spin() {
    let (scene, analysis) = analysed_example("top_steady_tilt", "");
    let theta = scalar_value(&scene, &analysis, "theta");
    let psidot = 1800.0 * std::f64::consts::PI / 30.0;
    let by_bisection = bisection(
        |t| moment_balance(t, 2.65, psidot),
        1e-6,
        std::f64::consts::PI - 1e-6,
    );
    assert!(
        (theta - by_bisection).abs() < 1e-12,
        "{theta} against {by_bisection}"
    );
    assert!((theta.to_degrees() - 31.17).abs() < 0.01);
    // The vertical axis solves the equation too (its factor sin θ), and is ruled out.
    let words: Vec<String> = analysis
        .plan
        .iter()
        .map(|s| kinetics::print::markup::text(&s.title))
        .collect();
    assert_eq!(
        words
            .iter()
            .filter(|w| w.contains("φ and ψ not told apart"))
            .count(),
        2,
        "{words:?}"
    );
}

#[test]
fn a_precession_no_tilt_can_hold_is_refused_naming_why() {
    // φ̇ = 2.5 rad/s: cos θ = 2(r φ̇ ψ̇ − 2g)/(3 r φ̇²) = −2.05, beyond −1.
    let scene = edited_example(
        "top_steady_tilt",
        &[("phidot = 2.65 rad/s", "phidot = 2.5 rad/s")],
    );
    let message = analyse(&scene).unwrap_err().render();
    assert!(
        message.contains(
            "every root for theta is ruled out (its cosine would be beyond ±1, which is no angle"
        ),
        "{message}"
    );
}

/// A disk tilted by the unknown β on a shaft, held by a couple M: M = (I − I′) ω² sin β
/// cos β (I = m r²/2 about the disk's axis, I′ = m r²/4), so sin 2β = 2M/((I − I′) ω²) has
/// four roots in (−180°, 180°]: β₀, 90° − β₀, β₀ − 180°, −90° − β₀. Each root's equation
/// holds only to nested radicals the algebra does not cancel; decided with the givens' values
/// within the rounding bound (it was "no solution" before).
#[test]
fn a_tilt_held_by_a_couple_has_each_root_of_its_double_angle() {
    let text = "given m = 4 kg\ngiven r = 120 mm\ngiven w = 1200 rpm\ngiven M = 38.88 N*m\n\
                unknown beta : deg\nbody disk(r) mass m rotated beta about z\nfixed point\n\
                omega = w*i\ncouple M*k\nfind beta\n";
    let scene = parse_scene("tilt.scene", text).unwrap();
    let analysis = analyse(&scene).unwrap();
    let (m, r, w, couple) = (4.0, 0.12, 1200.0 * std::f64::consts::PI / 30.0, 38.88);
    let (i, i_prime) = (m * r * r / 2.0, m * r * r / 4.0);
    let beta0 = 0.5 * (2.0 * couple / ((i - i_prime) * w * w)).asin();
    let half_turn = std::f64::consts::PI;
    let mut by_hand = [
        beta0,
        half_turn / 2.0 - beta0,
        beta0 - half_turn,
        -half_turn / 2.0 - beta0,
    ];
    by_hand.sort_by(f64::total_cmp);
    let mut derived = each_solution(&scene, &analysis);
    derived.sort_by(f64::total_cmp);
    assert_eq!(derived.len(), 4, "{derived:?}");
    for (d, h) in derived.iter().zip(by_hand) {
        assert!((d - h).abs() < 1e-9, "{d} against {h}");
    }
}

/// Fewer equations than unknowns (one constraint and ΣM_G = Ḣ_G about x, for θ, φ̇, ψ̇) is
/// said as that, with the statement to add, not as "no polynomial in theta".
#[test]
fn too_few_equations_for_an_angle_say_so() {
    let scene = edited_example(
        "torque_free_disk_from_omega",
        &[("constraint omega_y = w*sin(gamma)\n", "")],
    );
    let message = analyse(&scene).unwrap_err().render();
    assert!(
        message.contains("under-determined: 2 equations (the constraints and the equations of motion that hold an unknown) for the 3 unknowns theta, phidot, psidot"),
        "{message}"
    );
    assert!(
        message.contains("add a condition ('constraint …')"),
        "{message}"
    );
}

/// The direction of ω alone (ω_y = ω_z tan γ) with φ̇ given: θ from the squared equation,
/// its roots at the vertical axis (cos θ = ±1 behind unsimplified radicals) ruled out with
/// the givens' values; θ = 16.10° as tan θ = ½ tan γ.
#[test]
fn the_direction_of_omega_fixes_the_tilt_of_a_disk() {
    let text = "given m = 2 kg\ngiven r = 0.2 m\ngiven phidot = 30 rad/s\ngiven gam = 30 deg\n\
                unknown theta : deg\nunknown psidot : rad/s\neuler angles steady\n\
                body disk(r) mass m along z\nvbar = 0\nabar = 0\n\
                constraint omega_y = omega_z*tan(gam)\nfind theta, psidot, precession\n";
    let scene = parse_scene("d.scene", text).unwrap();
    let analysis = analyse(&scene).unwrap();
    let theta = scalar_value(&scene, &analysis, "theta");
    let by_hand = (30f64.to_radians().tan() / 2.0).atan();
    assert!((theta - by_hand).abs() < 1e-12, "{theta} against {by_hand}");
    let thetas = analysis
        .results
        .iter()
        .filter(|(r, _)| r.name == "theta")
        .count();
    assert_eq!(thetas, 1, "one solution, the vertical axis ruled out");
}

/// A rod hinged to a vertical shaft, its angle β from the shaft unknown, placed by
/// `rotated beta - 90 deg` (so β enters as sin(β − 90°) = −cos β): solved as the angle it is,
/// cos β = 3g/(2Lω²) by hand (ΣM_O = Ḣ_O about z), not refused as over-determined.
#[test]
fn an_angle_written_a_quarter_turn_off_is_still_the_angle() {
    let text = "given m = 2 kg\ngiven L = 0.6 m\ngiven w = 10 rad/s\ngiven g = 9.81 m/s^2\n\
                unknown beta : deg\nunknown O_x, O_y, O_z : N\nunknown M_x, M_y : N*m\n\
                body rod(L) mass m at (L/2*sin(beta), -L/2*cos(beta), 0) rotated beta - 90 deg about z\n\
                fixed point\nomega = w*j\nforce O = O_x*i + O_y*j + O_z*k at (0, 0, 0)\n\
                force W = -m*g*j at (L/2*sin(beta), -L/2*cos(beta), 0)\ncouple M_x*i + M_y*j\n\
                find beta\n";
    let scene = parse_scene("rod.scene", text).unwrap();
    let analysis = analyse(&scene).unwrap();
    let betas = each_solution(&scene, &analysis);
    let by_hand = (3.0 * 9.81 / (2.0 * 0.6 * 100.0f64)).acos();
    assert!(
        betas.iter().any(|b| (b - by_hand).abs() < 1e-12),
        "{betas:?} against {by_hand}"
    );
}

/// The value of every result, a scalar in each solution (one row per solution).
fn each_solution(scene: &kinetics::Scene, analysis: &kinetics::Analysis) -> Vec<f64> {
    let value = |(_, v): &(kinetics::scene::model::Request, Value)| {
        let Value::Scalar(e) = v else {
            panic!("a scalar result")
        };
        e.eval(&|s| scene.value(s)).unwrap()
    };
    analysis.results.iter().map(value).collect()
}
