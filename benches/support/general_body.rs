//! The algebra pipeline for a general body (six inertia components, ω, α), shared by the
//! benchmark and by the snapshot test that pins its printed output:
//!
//! ```text
//! H = [I]ω,    T = ½ ωᵀ[I]ω,    [I]α + ω × ([I]ω)
//! ```
//!
//! [`build`] forms the products, [`canonical`] expands `T` and the Euler components,
//! [`latex`] prints each, the Euler components about their own axes.

use kinetics::algebra::vector_products::{cross, dot, mat_vec};
use kinetics::algebra::{Axis, Expr, Matrix, Vector};
use kinetics::print;

/// The expressions as built: `H`, `ωᵀ[I]ω · ½` and `[I]α + ω × H`, not yet expanded.
pub struct Built {
    pub h: Vector,
    pub half_omega_h: Expr,
    pub euler: Vector,
}

/// `H`, `T` and the Euler components in expanded canonical form.
pub struct Canonical {
    pub h: Vector,
    pub t: Expr,
    pub euler: Vector,
}

/// Forms the inertia tensor (each product of inertia negated once, as
/// `InertiaTensor::matrix` does), ω, α and the three products.
pub fn build() -> Built {
    let s = Expr::symbol;
    let [ixy, iyz, ixz] = [s("I_xy"), s("I_yz"), s("I_xz")].map(|p| -p);
    let inertia = Matrix::new(
        s("I_x"),
        ixy.clone(),
        ixz.clone(),
        ixy,
        s("I_y"),
        iyz.clone(),
        ixz,
        iyz,
        s("I_z"),
    );
    let omega = Vector::new(s("w_x"), s("w_y"), s("w_z"));
    let alpha = Vector::new(s("wdot_x"), s("wdot_y"), s("wdot_z"));
    let h = mat_vec(&inertia, &omega);
    let half_omega_h = dot(&omega, &h) * Expr::rational(1, 2);
    let euler = mat_vec(&inertia, &alpha) + cross(&omega, &h);
    Built {
        h,
        half_omega_h,
        euler,
    }
}

/// Expands `T` and the Euler components (`H` is already a sum of monomials).
pub fn canonical(built: &Built) -> Canonical {
    Canonical {
        h: built.h.clone(),
        t: built.half_omega_h.expand().expect("small"),
        euler: built.euler.map(|m| m.expand().expect("small")),
    }
}

/// The axis each Euler component is written about.
pub const AXES: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

/// `H_x, H_y, H_z, T, M_x, M_y, M_z` in LaTeX.
pub fn latex(c: &Canonical) -> Vec<String> {
    let mut out: Vec<String> = c.h.iter().map(print::latex).collect();
    out.push(print::latex(&c.t));
    out.extend(
        c.euler
            .iter()
            .zip(AXES)
            .map(|(m, axis)| print::latex_about(m, axis)),
    );
    out
}

/// The whole pipeline: build, canonicalise, print.
pub fn pipeline() -> Vec<String> {
    latex(&canonical(&build()))
}
