//! Issue 18's parts together, on a rotor none of the helpers wrote: a thin disk skewed 1°
//! about the direction (0, 1, 1) on a shaft along x, a 30 g lump, positions in mm, speed in
//! rpm. The parts were built apart (units inside the mathematics; `find balance`; principal
//! axes; the engineer's page), and these are the seams between them:
//!
//! - the balance planes and radius written in mm are in SI like every other length (they
//!   kept a unit marker, `50*[mm]`, and the masses had no value);
//! - π from `1 deg` is a constant, not a given without a value (`principal_O needs values
//!   for pi`);
//! - the engineer's page gives each intermediate value the unit of its name (`v_Px` in m/s,
//!   not in rad/s from a right-hand side whose lengths are plain SI numbers).
//!
//! Every number is checked against a computation written here: the disk's tensor rotated by
//! Rodrigues' formula, the lump's products as m x y, the two-plane equations by Cramer's rule.

use crate::common::binary::kinetics_with_input;
use kinetics::mechanics::two_plane_balance::CorrectionAngle;
use kinetics::{analyse, parse_scene, Value};

const SCENE: &str = "title Skewed disk rotor
given m = 2.5 kg
given r = 120 mm
given w = 3000 rpm
unknown A_y, A_z, B_y, B_z : N
body disk(r) mass m at (100 mm, 0, 0) rotated 1 deg about (0, 1, 1)
body point() mass 30 g at (100 mm, 80 mm, 0)
fixed point
omega = w*i
omegadot = 0
force A = A_y*j + A_z*k at (0, 0, 0)
force B = B_y*j + B_z*k at (250 mm, 0, 0)
point P at (100 mm, 0, 120 mm)
find principal_O, B_y, v_P, balance in planes x = 50 mm, x = 200 mm at radius 100 mm
";

/// The rotor's products of inertia about O by hand, `(I_xy, I_xz)` (positive integrals): the
/// disk's centroidal tensor diag(½mr², ¼mr², ¼mr²) (axis along x) turned by R (Rodrigues,
/// 1° about n = (0, 1, 1)/√2), its centre on the axis; the lump's m x y.
fn products_by_hand() -> (f64, f64) {
    let (m, r) = (2.5, 0.12);
    let theta = 1f64.to_radians();
    let n = [0.0, 1.0 / 2f64.sqrt(), 1.0 / 2f64.sqrt()];
    let k = [[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]];
    let mut rot = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let k2: f64 = (0..3).map(|l| k[i][l] * k[l][j]).sum();
            let identity = if i == j { 1.0 } else { 0.0 };
            rot[i][j] = identity + theta.sin() * k[i][j] + (1.0 - theta.cos()) * k2;
        }
    }
    let own = [m * r * r / 2.0, m * r * r / 4.0, m * r * r / 4.0];
    // [I] = R diag(own) Rᵀ; the chapter's I_xy is −[I]_xy.
    let entry = |i: usize, j: usize| (0..3).map(|l| rot[i][l] * own[l] * rot[j][l]).sum::<f64>();
    let lump = 0.030 * 0.100 * 0.080;
    (-entry(0, 1) + lump, -entry(0, 2))
}

#[test]
fn balance_planes_in_mm_and_an_angle_in_degrees_give_the_hand_masses() {
    let scene = parse_scene("skewed_rotor.scene", SCENE).expect("the scene parses");
    let analysis = analyse(&scene).expect("the scene solves");
    let (i_xy, i_xz) = products_by_hand();
    // P_1 + P_2 = -S_y, x_1 P_1 + x_2 P_2 = -I_xy (and Q with S_z = 0, I_xz), by Cramer.
    let (x_1, x_2, radius) = (0.050, 0.200, 0.100);
    let s_y = 0.030 * 0.080;
    let p_2 = (x_1 * s_y - i_xy) / (x_2 - x_1);
    let q_2 = -i_xz / (x_2 - x_1);
    let hand = [(-s_y - p_2, -q_2), (p_2, q_2)];
    let Some((_, Value::Balance(corrections))) = analysis
        .results
        .iter()
        .find(|(_, v)| matches!(v, Value::Balance(_)))
    else {
        panic!("the balance is a result")
    };
    let value = |e: &kinetics::Expr| e.eval(&|s| scene.value(s)).expect("a number");
    for (k, (p, q)) in hand.iter().enumerate() {
        let c = &corrections[k];
        let mass = (p * p + q * q).sqrt() / radius;
        let found = value(&c.mass);
        assert!(
            (found - mass).abs() < 1e-9 * mass,
            "m_{}: {found} against {mass}",
            k + 1
        );
        let CorrectionAngle::Atan2 { q: cq, p: cp } = &c.angle else {
            panic!("the angle of plane {} is not a multiple of 15°", k + 1)
        };
        let angle = value(cq).atan2(value(cp));
        assert!((angle - q.atan2(*p)).abs() < 1e-9, "θ_{}", k + 1);
    }
}

#[test]
fn the_engineers_page_has_every_number_with_its_names_unit() {
    let run = kinetics_with_input(&["solve", "-", "--numbers"], SCENE);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let page = run.stdout;
    // π from `1 deg` is a constant: the principal frame about O is found.
    assert!(page.contains("principal_O:\n    I_1 = "), "{page}");
    // v_P = ω × r_P: ω r = 3000 rpm · 120 mm = 37.70 m/s along −y (a length, not rad/s).
    assert!(page.contains("    v_Py = -37.70 m/s\n"), "{page}");
    assert!(page.contains("    v_Px = 0 m/s\n"), "{page}");
    assert!(page.contains("    rbar_x = 0.1 m\n"), "{page}");
    assert!(page.contains("    I_xz = 0.0001110 kg·m²\n"), "{page}");
    // The correction masses have values: their planes are lengths in SI.
    assert!(page.contains("  m_1 = 0.02455 kg\n"), "{page}");
    assert!(!page.contains("has no value"), "{page}");
}

#[test]
fn a_tensor_too_wide_for_the_page_is_shown_by_its_numbers_in_latex_notation() {
    let scene = SCENE.replace("find principal_O", "find I_O, principal_O");
    let run = kinetics_with_input(&["solve", "-", "--format", "latex"], scene);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let results = run.stdout.split("Results").nth(1).expect("a results block");
    let tensor = results
        .lines()
        .find(|l| l.contains("[I_O]"))
        .expect("the tensor's row");
    // Its entries hold sin(π/180) terms a page wide each: the step before has them.
    assert!(!tensor.contains(r"\sin"), "{tensor}");
    // I_yz = 1.371e-6 kg·m² is written as LaTeX writes a power of ten.
    assert!(results.contains(r"-1.371\times 10^{-6}"), "{results}");
    assert!(!results.contains("e-6"), "{results}");
}
