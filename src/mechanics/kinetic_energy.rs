//! Kinetic energy (§18.4):
//!
//! ```text
//! T = ½ m v̄² + ½ {ω}ᵀ[I]{ω}
//!   = ½ m v̄² + ½(I_x ω_x² + I_y ω_y² + I_z ω_z² - 2I_xy ω_x ω_y - 2I_yz ω_y ω_z - 2I_xz ω_z ω_x)
//! ```
//!
//! The two parts are `T_trans = ½ m v̄²` (the motion of G) and `T_rot = ½ {ω}ᵀ[Ī]{ω}` (the
//! rotation about G). For a body about a fixed point O, `T = ½ {ω}ᵀ[I_O]{ω}` (no
//! translational part); the split is still about G, with `v̄ = ω × r̄` and `[Ī]`.

use super::derivation::{Derivation, Relation, Step};
use super::inertia::InertiaTensor;
use super::slip::{half_unless, Slip};
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
    let Some((mass, vbar)) = translation else {
        let rotational = rotational_energy(inertia, omega)?;
        return Ok(Derivation {
            name: "T".into(),
            title: "kinetic energy about a fixed point $O$".into(),
            steps: vec![Step::new(
                r"kinetic energy about the fixed point $O$, $T = \tfrac12\{\boldsymbol{\omega}\}^T[I_O]\{\boldsymbol{\omega}\}$",
                vec![Relation::new(Expr::symbol("T"), rotational, Axis::X)],
            )],
        });
    };
    kinetic_energy_split(inertia, omega, mass, vbar, false)
}

/// `T = T_trans + T_rot`, `T_trans = ½ m v̄²`, `T_rot = ½ {ω}ᵀ[Ī]{ω}`, about the mass centre
/// G (`inertia` is `[Ī]`); `o_fixed` says the body turns about a fixed point O, which the
/// first step's title names (the split is about G all the same). The first step gives the
/// two parts, the last `T` (the result).
///
/// A sphere rolling at `v̄ = r w`: `T_trans = ½ m r² w²`, `T_rot = ⅕ m r² w²`.
///
/// ```
/// use kinetics::mechanics::kinetic_energy::kinetic_energy_split;
/// use kinetics::{parse_expression, Expr, InertiaTensor, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// let i = hand("2/5 m r^2");
/// let sphere = InertiaTensor::diagonal([i.clone(), i.clone(), i]);
/// let omega = Vector::new(Expr::zero(), Expr::zero(), hand("w"));
/// let vbar = Vector::new(hand("r w"), Expr::zero(), Expr::zero());
/// let d = kinetic_energy_split(&sphere, &omega, &hand("m"), &vbar, false)?;
/// let parts: Vec<&Expr> = d.steps[0].relations.iter().map(|r| &r.rhs).collect();
/// assert_eq!(parts, [&hand("1/2 m r^2 w^2"), &hand("1/5 m r^2 w^2")]);
/// assert_eq!(d.result()[0].rhs, hand("7/10 m r^2 w^2"));
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn kinetic_energy_split(
    inertia: &InertiaTensor,
    omega: &Vector,
    mass: &Expr,
    vbar: &Vector,
    o_fixed: bool,
) -> Result<Derivation, AlgebraError> {
    let half = half_unless(Slip::HalfMissingTranslation);
    let translational = (half * mass * dot(vbar, vbar)).expand()?;
    let rotational = rotational_energy(inertia, omega)?;
    let parts = r"$T_{\text{trans}} = \tfrac12 m\bar{v}^2$, $T_{\text{rot}} = \tfrac12\{\boldsymbol{\omega}\}^T[I]\{\boldsymbol{\omega}\}$";
    let title = if o_fixed {
        format!("kinetic energy split about the mass centre $G$ ($O$ is fixed, but the split is about $G$, with $[I]$ about $G$): {parts}")
    } else {
        format!("kinetic energy, translation of $G$ and rotation about $G$: {parts}")
    };
    Ok(Derivation {
        name: "T".into(),
        title: "kinetic energy".into(),
        steps: vec![
            Step::new(
                title,
                vec![
                    Relation::new(Expr::symbol("T_trans"), translational.clone(), Axis::X),
                    Relation::new(Expr::symbol("T_rot"), rotational.clone(), Axis::X),
                ],
            ),
            Step::new(
                r"kinetic energy, $T = T_{\text{trans}} + T_{\text{rot}}$",
                vec![Relation::new(
                    Expr::symbol("T"),
                    &translational + &rotational,
                    Axis::X,
                )],
            ),
        ],
    })
}

/// `T₁`, the kinetic energy just before an impact, from the motion then (`ω₁`, and `v̄₁` with
/// `[Ī]` about G, or about a fixed point O with `[I_O]` and no `v̄₁`):
/// `T₁ = ½ m v̄₁² + ½ {ω₁}ᵀ[Ī]{ω₁}`, or `T₁ = ½ {ω₁}ᵀ[I_O]{ω₁}`. One step, its result `T_1`.
///
/// A sphere sliding at `v₀` and spinning at `w₀` before the blow:
///
/// ```
/// use kinetics::mechanics::kinetic_energy::kinetic_energy_before;
/// use kinetics::{parse_expression, Expr, InertiaTensor, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// let i = hand("2/5 m r^2");
/// let sphere = InertiaTensor::diagonal([i.clone(), i.clone(), i]);
/// let omega = Vector::new(Expr::zero(), Expr::zero(), hand("w_0"));
/// let vbar = Vector::new(hand("v_0"), Expr::zero(), Expr::zero());
/// let d = kinetic_energy_before(&sphere, &omega, Some((&hand("m"), &vbar)))?;
/// assert_eq!(d.result()[0].rhs, hand("1/2 m v_0^2 + 1/5 m r^2 w_0^2"));
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn kinetic_energy_before(
    inertia: &InertiaTensor,
    omega: &Vector,
    translation: Option<(&Expr, &Vector)>,
) -> Result<Derivation, AlgebraError> {
    let rotational = rotational_energy(inertia, omega)?;
    let (energy, title) = match translation {
        Some((mass, vbar)) => {
            let half = half_unless(Slip::HalfMissingTranslation);
            let translational = (half * mass * dot(vbar, vbar)).expand()?;
            (
                translational + rotational,
                r"kinetic energy just before the impact, $T_1 = \tfrac12 m\bar{v}_1^2 + \tfrac12\{\boldsymbol{\omega}_1\}^T[I]\{\boldsymbol{\omega}_1\}$",
            )
        }
        None => (
            rotational,
            r"kinetic energy just before the impact, about the fixed point $O$, $T_1 = \tfrac12\{\boldsymbol{\omega}_1\}^T[I_O]\{\boldsymbol{\omega}_1\}$",
        ),
    };
    Ok(Derivation {
        name: "T_1".into(),
        title: "kinetic energy before the impact".into(),
        steps: vec![Step::new(
            title,
            vec![Relation::new(Expr::symbol("T_1"), energy, Axis::X)],
        )],
    })
}

/// The kinetic energy an impact takes away, `T_lost = T₁ − T₂` (negative when the blow
/// gives the body energy, as a hammer does).
pub fn energy_lost(before: &Expr, after: &Expr) -> Result<Derivation, AlgebraError> {
    let lost = (before - after).expand()?;
    Ok(Derivation {
        name: "T_lost".into(),
        title: "energy lost in the impact".into(),
        steps: vec![Step::new(
            r"kinetic energy lost in the impact, $T_{\text{lost}} = T_1 - T_2$",
            vec![Relation::new(Expr::symbol("T_lost"), lost, Axis::X)],
        )],
    })
}

/// `½ {ω}ᵀ[I]{ω}`, multiplied out.
fn rotational_energy(inertia: &InertiaTensor, omega: &Vector) -> Result<Expr, AlgebraError> {
    let half = half_unless(Slip::HalfMissingRotation);
    (half * dot(omega, &mat_vec(&inertia.matrix(), omega))).expand()
}
