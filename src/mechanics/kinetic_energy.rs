//! Kinetic energy (§18.4):
//!
//! ```text
//! T = ½ m v̄² + ½ {ω}ᵀ[I]{ω}
//!   = ½ m v̄² + ½(I_x ω_x² + I_y ω_y² + I_z ω_z² - 2I_xy ω_x ω_y - 2I_yz ω_y ω_z - 2I_xz ω_z ω_x)
//! ```
//!
//! For a body about a fixed point O, `T = ½ {ω}ᵀ[I_O]{ω}` (no translational part).

use super::derivation::{Derivation, Relation, Step};
use super::inertia::InertiaTensor;
use crate::algebra::vector_products::{dot, mat_vec};
use crate::algebra::{AlgebraError, Axis, Expr, Vector};

/// `T = ½ m v̄² + ½ ωᵀ[I]ω`; `translation` is `Some((m, v̄))` for a free body, `None` for a
/// body about a fixed point.
///
/// A disk rolling in a plane, principal axes, `v̄ = v i`, `ω = w k`: `T = ½ m v² + ½ I_z w²`;
/// about a fixed point the translational part is left out.
///
/// ```
/// use kinetics::{kinetic_energy, parse_expression, Expr, InertiaTensor, Vector};
///
/// let vbar = Vector::new(Expr::symbol("v"), Expr::zero(), Expr::zero());
/// let omega = Vector::new(Expr::zero(), Expr::zero(), Expr::symbol("w"));
/// let (inertia, m) = (InertiaTensor::principal(), Expr::symbol("m"));
/// let hand = |t: &str| parse_expression("by hand", t).unwrap();
/// let free = kinetic_energy(&inertia, &omega, Some((&m, &vbar)))?;
/// assert_eq!(free.result()[0].rhs, hand("1/2 m v^2 + 1/2 I_z w^2"));
/// let about_o = kinetic_energy(&inertia, &omega, None)?;
/// assert_eq!(about_o.result()[0].rhs, hand("1/2 I_z w^2"));
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn kinetic_energy(
    inertia: &InertiaTensor,
    omega: &Vector,
    translation: Option<(&Expr, &Vector)>,
) -> Result<Derivation, AlgebraError> {
    let half = Expr::rational(1, 2);
    let rotational = (&half * &dot(omega, &mat_vec(&inertia.matrix(), omega))).expand()?;
    let t = Expr::symbol("T");
    let steps = match translation {
        Some((m, v)) => {
            let translational = (&half * m * dot(v, v)).expand()?;
            vec![
                Step {
                    table: None,
                    title: r"kinetic energy, rotational part $\tfrac12\{\boldsymbol{\omega}\}^T[I]\{\boldsymbol{\omega}\}$".into(),
                    relations: vec![Relation::new(
                        Expr::symbol("T_rot"),
                        rotational.clone(),
                        Axis::X,
                    )],
                },
                Step {
                    table: None,
                    title: r"kinetic energy, $T = \tfrac12 m\bar{v}^2 + \tfrac12\{\boldsymbol{\omega}\}^T[I]\{\boldsymbol{\omega}\}$: add the translational part".into(),
                    relations: vec![Relation::new(t, &translational + &rotational, Axis::X)],
                },
            ]
        }
        None => vec![Step {
            table: None,
            title: r"kinetic energy about the fixed point $O$, $T = \tfrac12\{\boldsymbol{\omega}\}^T[I_O]\{\boldsymbol{\omega}\}$".into(),
            relations: vec![Relation::new(t, rotational, Axis::X)],
        }],
    };
    Ok(Derivation {
        name: "T".into(),
        title: if translation.is_some() {
            "kinetic energy".into()
        } else {
            "kinetic energy about a fixed point $O$".into()
        },
        steps,
    })
}
