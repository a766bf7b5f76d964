//! Unknowns solved by elimination come out in lowest terms over one denominator, not as the
//! fractions inside fractions that pivots over pivots leave.
//!
//! A free solid cylinder (radius r, length h, axis along x before it is turned by θ about z),
//! at rest, struck by the impulse P k at its end face's rim, R (h/2, r, 0) from G: by hand,
//! m v̄ = P k and
//! [I]{ω} = r × P k with [I] = R diag(m r²/2, m(3r² + h²)/12, m(3r² + h²)/12) Rᵀ, R the turn
//! by θ about z (examples/scenes/free_cylinder_struck_off_centre.scene). Solved here
//! numerically (Cramer's rule) and compared with kinetics' forms.

use crate::common::examples::{analysed_example, result};
use kinetics::algebra::{Expr, Symbol};
use kinetics::scene::Value;

fn determinant(a: [[f64; 3]; 3]) -> f64 {
    a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
}

/// ω from [I]{ω} = b by Cramer's rule.
fn solve(a: [[f64; 3]; 3], b: [f64; 3]) -> [f64; 3] {
    let d = determinant(a);
    [0, 1, 2].map(|k| {
        let mut ak = a;
        for (row, bi) in ak.iter_mut().zip(b) {
            row[k] = bi;
        }
        determinant(ak) / d
    })
}

#[test]
fn a_free_cylinder_struck_off_centre_is_solved_in_lowest_terms() {
    let (_, analysis) = analysed_example("free_cylinder_struck_off_centre", "");
    let (m, r, h, p, theta) = (2.0, 0.3, 1.1, 5.0, 0.7_f64);
    let values = |s: Symbol| match s.name() {
        "m" => Some(m),
        "r" => Some(r),
        "h" => Some(h),
        "P" => Some(p),
        "theta" => Some(theta),
        _ => None,
    };
    let eval = |e: &Expr| e.eval(&values).expect("evaluates");
    // [I] = R diag(a, t, t) Rᵀ, R about z: products enter with a minus sign.
    let (axial, across) = (m * r * r / 2.0, m * (3.0 * r * r + h * h) / 12.0);
    let (c, s) = (theta.cos(), theta.sin());
    let inertia = [
        [
            axial * c * c + across * s * s,
            (axial - across) * c * s,
            0.0,
        ],
        [
            (axial - across) * c * s,
            axial * s * s + across * c * c,
            0.0,
        ],
        [0.0, 0.0, across],
    ];
    // r × P k with r = R (h/2, r, 0), the end face's rim point turned with the body.
    let (p_x, p_y) = (h / 2.0 * c - r * s, h / 2.0 * s + r * c);
    let omega = solve(inertia, [p_y * p, -p_x * p, 0.0]);
    for (name, expected) in ["w_x", "w_y", "w_z"].into_iter().zip(omega) {
        let Value::Scalar(form) = result(&analysis, name) else {
            panic!("{name} is a scalar")
        };
        let got = eval(form);
        assert!(
            (got - expected).abs() <= 1e-12 * expected.abs().max(1.0),
            "{name}: {got} vs {expected}"
        );
        // Lowest terms: a few hundred characters, not the thousands elimination left.
        let printed = kinetics::print::text(form);
        assert!(printed.len() < 300, "{name} = {printed}");
    }
    let t = p * p / (2.0 * m)
        + 0.5
            * (0..3)
                .map(|i| {
                    (0..3)
                        .map(|j| omega[i] * inertia[i][j] * omega[j])
                        .sum::<f64>()
                })
                .sum::<f64>();
    let Value::Scalar(form) = result(&analysis, "T") else {
        panic!("T is a scalar")
    };
    assert!(
        (eval(form) - t).abs() <= 1e-12 * t,
        "T: {} vs {t}",
        eval(form)
    );
    assert!(
        kinetics::print::text(form).len() < 400,
        "T = {}",
        kinetics::print::text(form)
    );
}
