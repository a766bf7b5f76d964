//! Angular momentum (§18.2): `{H_G} = [I]{ω}`, by components
//!
//! ```text
//! H_x =  I_x ω_x - I_xy ω_y - I_xz ω_z
//! H_y = -I_xy ω_x + I_y ω_y - I_yz ω_z
//! H_z = -I_xz ω_x - I_yz ω_y + I_z ω_z
//! ```
//!
//! and about another point, `H_O = H_G + r̄ × m v̄`. For a body turning about a fixed point
//! O the same `[I]{ω}` holds with moments and products about O.

use super::derivation::{Derivation, Relation, Step};
use super::inertia::InertiaTensor;
use super::linear_momentum::linear_momentum;
use super::moment_transfer::{moment_transfer, Labels};
use crate::algebra::vector::expand_each;
use crate::algebra::vector_products::mat_vec;
use crate::algebra::{AlgebraError, Expr, Vector};

/// `{H} = [I]{ω}`; `point` names the reference point (`G` or `O`).
///
/// About a fixed axis z, `ω = w k`: `[I]{ω}` is w times the third column of `[I]`, where the
/// products of inertia enter with a minus sign.
///
/// ```
/// use kinetics::{angular_momentum, parse_expression, Expr, InertiaTensor, Vector};
///
/// let omega = Vector::new(Expr::zero(), Expr::zero(), Expr::symbol("w"));
/// let h = angular_momentum(&InertiaTensor::general(), &omega, "O")?;
/// let hand = |t: &str| parse_expression("by hand", t).unwrap();
/// let components: Vec<&Expr> = h.result().iter().map(|r| &r.rhs).collect();
/// assert_eq!(components, [&hand("-I_xz w"), &hand("-I_yz w"), &hand("I_z w")]);
/// assert_eq!(h.name, "H_O");
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn angular_momentum(
    inertia: &InertiaTensor,
    omega: &Vector,
    point: &str,
) -> Result<Derivation, AlgebraError> {
    let h = expand_each(&mat_vec(&inertia.matrix(), omega))?;
    Ok(Derivation {
        name: format!("H_{point}"),
        title: format!("angular momentum about ${point}$"),
        steps: vec![Step {
            vectors: Vec::new(),
            table: None,
            title: format!(
                r"angular momentum, $\{{\mathbf{{H}}_{{{point}}}\}} = {tensor}\{{\boldsymbol{{\omega}}\}}$",
                tensor = InertiaTensor::written_about(point)
            ),
            relations: Relation::components("H", &h),
        }],
    })
}

/// `{H_G1} = [I]{ω₁}`: the angular momentum about G just before an impact, its components
/// `H_x1`, `H_y1`, `H_z1` (as the chapter's `H₁ + Σ M Δt = H₂`).
pub fn angular_momentum_before(
    inertia: &InertiaTensor,
    omega_before: &Vector,
) -> Result<Derivation, AlgebraError> {
    let h = expand_each(&mat_vec(&inertia.matrix(), omega_before))?;
    Ok(Derivation {
        name: "H_G1".into(),
        title: "angular momentum about $G$ before the blow".into(),
        steps: vec![Step::new(
            r"angular momentum about $G$ just before the blow, $\{\mathbf{H}_1\} = [I]\{\boldsymbol{\omega}_1\}$",
            Relation::components_named(&h, |x| format!("H_{x}1")),
        )],
    })
}

/// `H_O = H_G + r̄ × m v̄`, where `rbar` is the position of G from O.
///
/// A particle (`H_G = 0`) at `r̄ = x̄ i` moving with `v̄ = v j`: `r̄ × m v̄ = m x̄ v (i × j)`,
/// so `H_O = m x̄ v k`.
///
/// ```
/// use kinetics::mechanics::angular_momentum::angular_momentum_about_point;
/// use kinetics::{parse_expression, Expr, Vector};
///
/// let (zero, m) = (Vector::from_element(Expr::zero()), Expr::symbol("m"));
/// let rbar = Vector::new(Expr::symbol("xbar"), Expr::zero(), Expr::zero());
/// let vbar = Vector::new(Expr::zero(), Expr::symbol("v"), Expr::zero());
/// let h_o = angular_momentum_about_point(&zero, &rbar, &m, &vbar)?;
/// let by_hand = parse_expression("by hand", "m xbar v")?;
/// let components: Vec<&Expr> = h_o.result().iter().map(|r| &r.rhs).collect();
/// assert_eq!(components, [&Expr::zero(), &Expr::zero(), &by_hand]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn angular_momentum_about_point(
    h_g: &Vector,
    rbar: &Vector,
    mass: &Expr,
    vbar: &Vector,
) -> Result<Derivation, AlgebraError> {
    moment_transfer(
        h_g,
        rbar,
        &linear_momentum(mass, vbar)?,
        Labels {
            components: "H",
            name: "H_O",
            title: "angular momentum about $O$",
            moment: r"\bar{\mathbf{r}} \times m\bar{\mathbf{v}}",
            moment_title: "moment of the linear momentum",
            total_title: r"angular momentum about $O$, $\mathbf{H}_O = \mathbf{H}_G + \bar{\mathbf{r}} \times m\bar{\mathbf{v}}$",
        },
    )
}
