//! `Matrix3<Expr> * Vector3<Expr>` and `Vector3::cross` work, and agree with the same
//! products computed in floating point.

use kinetics::algebra::{Expr, Matrix, Symbol, Vector};
use nalgebra::{Matrix3, Vector3};

fn s(name: &str) -> Expr {
    Expr::symbol(name)
}

fn inertia() -> Matrix {
    Matrix::new(
        s("I_x"),
        -s("I_xy"),
        -s("I_xz"),
        -s("I_xy"),
        s("I_y"),
        -s("I_yz"),
        -s("I_xz"),
        -s("I_yz"),
        s("I_z"),
    )
}

#[test]
fn matrix_times_vector_gives_the_chapter_components() {
    let w = Vector::new(s("w_x"), s("w_y"), s("w_z"));
    let h = inertia() * &w;
    assert_eq!(
        h[0],
        s("I_x") * s("w_x") - s("I_xy") * s("w_y") - s("I_xz") * s("w_z")
    );
    assert_eq!(
        h[1],
        -s("I_xy") * s("w_x") + s("I_y") * s("w_y") - s("I_yz") * s("w_z")
    );
    assert_eq!(
        h[2],
        -s("I_xz") * s("w_x") - s("I_yz") * s("w_y") + s("I_z") * s("w_z")
    );
}

#[test]
fn cross_product_agrees_with_floating_point() {
    let w = Vector::new(s("w_x"), s("w_y"), s("w_z"));
    let symbolic = w.cross(&(inertia() * &w));
    let values = [
        ("I_x", 3.0),
        ("I_y", 4.0),
        ("I_z", 5.5),
        ("I_xy", 0.3),
        ("I_yz", -0.2),
        ("I_xz", 0.7),
        ("w_x", 1.1),
        ("w_y", -0.4),
        ("w_z", 2.0),
    ];
    let lookup = |sym: Symbol| {
        values
            .iter()
            .find(|(n, _)| Symbol::new(n) == sym)
            .map(|(_, v)| *v)
    };
    let i = Matrix3::new(3.0, -0.3, -0.7, -0.3, 4.0, 0.2, -0.7, 0.2, 5.5);
    let wf = Vector3::new(1.1, -0.4, 2.0);
    let numeric = wf.cross(&(i * wf));
    for k in 0..3 {
        let v: f64 = symbolic[k].eval(&lookup).unwrap();
        assert!(
            (v - numeric[k]).abs() < 1e-12,
            "component {k}: {v} vs {}",
            numeric[k]
        );
    }
}
