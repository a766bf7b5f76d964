//! Euler's equations of motion (§18.6): with Ω = ω and axes fixed in the body,
//! `ΣM_G = [I]{ω̇} + ω × ([I]{ω})`. In principal axes they take the cyclic form
//!
//! ```text
//! ΣM_x = I_x ω̇_x - (I_y - I_z) ω_y ω_z
//! ΣM_y = I_y ω̇_y - (I_z - I_x) ω_z ω_x
//! ΣM_z = I_z ω̇_z - (I_x - I_y) ω_x ω_y
//! ```
//!
//! and with products of inertia the general equations, grouped by kinematic terms.

use super::derivation::{Derivation, Relation, Step};
use super::inertia::InertiaTensor;
use super::rotating_frame::rate_of_angular_momentum;
use crate::algebra::vector::expand_each;
use crate::algebra::{AlgebraError, Expr, Vector};

/// The body-frame angular velocity `(w_x, w_y, w_z)`.
pub fn body_angular_velocity() -> Vector {
    Vector::new(
        Expr::symbol("w_x"),
        Expr::symbol("w_y"),
        Expr::symbol("w_z"),
    )
}

/// Euler's equations for the given tensor (principal or general) in body axes.
///
/// A check against §18.8: with products of inertia, a body spinning steadily about z
/// (`ω_x = ω_y = 0`, `ω̇ = 0`) needs `ΣM_x = I_yz ω_z²` and `ΣM_y = -I_xz ω_z²`, the
/// fixed-axis equations at `α = 0`.
///
/// ```
/// use kinetics::algebra::Symbol;
/// use kinetics::{euler_equations, parse_expression, InertiaTensor};
///
/// let euler = euler_equations(&InertiaTensor::general())?;
/// let steady = ["w_x", "w_y", "wdot_x", "wdot_y", "wdot_z"].map(Symbol::new);
/// let about_z = |s: Symbol| steady.contains(&s).then(kinetics::Expr::zero);
/// let moments: Vec<_> = euler
///     .result()
///     .iter()
///     .map(|r| r.rhs.subs(&about_z))
///     .collect::<Result<_, _>>()?;
/// let hand = |t: &str| parse_expression("by hand", t).unwrap();
/// assert_eq!(moments, [hand("I_yz w_z^2"), hand("-I_xz w_z^2"), hand("0")]);
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn euler_equations(inertia: &InertiaTensor) -> Result<Derivation, AlgebraError> {
    let omega = body_angular_velocity();
    let omega_dot = Vector::new(omega[0].d_dt()?, omega[1].d_dt()?, omega[2].d_dt()?);
    let rate = rate_of_angular_momentum(inertia, &omega, &omega_dot, &omega, "G")?;
    let moments = expand_each(&Vector::from_iterator(
        rate.result().iter().map(|r| r.rhs.clone()),
    ))?;
    let mut steps = rate.steps;
    steps.push(Step {
        vectors: Vec::new(),
        table: None,
        title: r"Euler's equations: $\Sigma\mathbf{M}_G = \dot{\mathbf{H}}_G$ with $\boldsymbol{\Omega} = \boldsymbol{\omega}$ (axes fixed in the body)".into(),
        relations: Relation::components("SumM", &moments),
    });
    Ok(Derivation {
        name: "euler".into(),
        title: if inertia.is_principal() {
            "Euler's equations of motion (principal axes)".into()
        } else {
            "Euler's equations of motion (general axes)".into()
        },
        steps,
    })
}
