//! Rotation about a fixed axis (§18.8). With z along the axis, `ω = ω k`, Ω = ω and
//! `α = ω̇`, `ΣM_O = [I]{α k} + ω k × [I]{ω k}` gives
//!
//! ```text
//! ΣM_x = -I_xz α + I_yz ω²
//! ΣM_y = -I_yz α - I_xz ω²
//! ΣM_z =  I_z α
//! ```
//!
//! For a shaft on bearings A (at O) and B (at distance l along z), the moments about A of
//! the radial reactions at B are `ΣM_x = -l B_y`, `ΣM_y = l B_x`, so the dynamic reactions
//! are `B_y = -(ΣM_x)/l`, `B_x = (ΣM_y)/l`, and `A = m ā - B` with
//! `ā = α k × r̄ - ω² r̄_⊥` (gravity's static part is left out).

use super::derivation::{Derivation, Relation, Step};
use super::inertia::InertiaTensor;
use super::rotating_frame::rate_of_angular_momentum;
use crate::algebra::{AlgebraError, Axis, Expr, Vector};

fn axis_vector(e: Expr) -> Vector {
    Vector::new(Expr::zero(), Expr::zero(), e)
}

/// The three moment equations for rotation about z.
///
/// `[I]{α k} = α(-I_xz, -I_yz, I_z)` and `w k × [I]{w k} = w²(I_yz, -I_xz, 0)`
/// (`k × i = j`, `k × j = -i`); their sum is the chapter's form.
///
/// ```
/// use kinetics::{fixed_axis_rotation, parse_expression, print, InertiaTensor};
///
/// let d = fixed_axis_rotation(&InertiaTensor::general())?;
/// let printed: Vec<String> = d
///     .result()
///     .iter()
///     .map(|r| print::text_about(&r.rhs, r.axis))
///     .collect();
/// assert_eq!(printed, ["-I_xz*alpha + I_yz*w^2", "-I_yz*alpha - I_xz*w^2", "I_z*alpha"]);
/// let by_hand = parse_expression("by hand", "-alpha I_xz + w^2 I_yz")?;
/// assert_eq!(d.result()[0].rhs, by_hand);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fixed_axis_rotation(inertia: &InertiaTensor) -> Result<Derivation, AlgebraError> {
    let omega = axis_vector(Expr::symbol("w"));
    let alpha = axis_vector(Expr::symbol("alpha"));
    let rate = rate_of_angular_momentum(inertia, &omega, &alpha, &omega, "O")?;
    let moments = Vector::from_iterator(rate.result().iter().map(|r| r.rhs.clone()));
    let mut steps = vec![Step {
        table: None,
        title: "z along the fixed axis: ω = ω k, Ω = ω, α = ω̇ (ω_x = ω_y = 0)".into(),
        relations: Relation::components("H", &(inertia.matrix() * &omega)),
    }];
    steps.extend(rate.steps);
    steps.push(Step {
        table: None,
        title: "ΣM_O = Ḣ_O".into(),
        relations: Relation::components("SumM", &moments),
    });
    Ok(Derivation {
        name: "fixed_axis".into(),
        title: "rotation about a fixed axis".into(),
        steps,
    })
}

/// Dynamic reactions of bearings A (at the origin) and B (at `z = l`) on a body of mass
/// `m` whose mass centre is at `(x̄, ȳ)` off the axis.
///
/// With the mass centre on the axis (`x̄ = ȳ = 0`) the reactions come from the products of
/// inertia alone: `B_x = ΣM_y/l = (-I_yz α - I_xz ω²)/l`,
/// `B_y = -ΣM_x/l = (I_xz α - I_yz ω²)/l`, and `A = -B` (`m ā = 0`).
///
/// ```
/// use kinetics::mechanics::fixed_axis::bearing_reactions;
/// use kinetics::{parse_expression, Expr, InertiaTensor};
///
/// let (m, l, zero) = (Expr::symbol("m"), Expr::symbol("l"), Expr::zero());
/// let d = bearing_reactions(&InertiaTensor::general(), &m, (&zero, &zero), &l)?;
/// let [b_x, b_y, a_x, a_y] = d.result() else { panic!("four reactions") };
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// assert_eq!(b_x.rhs, hand("(-I_yz alpha - I_xz w^2)/l"));
/// assert_eq!(b_y.rhs, hand("(I_xz alpha - I_yz w^2)/l"));
/// assert_eq!((&a_x.rhs, &a_y.rhs), (&-&b_x.rhs, &-&b_y.rhs));
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn bearing_reactions(
    inertia: &InertiaTensor,
    mass: &Expr,
    centroid: (&Expr, &Expr),
    l: &Expr,
) -> Result<Derivation, AlgebraError> {
    let fixed = fixed_axis_rotation(inertia)?;
    let moments: Vec<Expr> = fixed.result().iter().map(|r| r.rhs.clone()).collect();
    let (w, alpha) = (Expr::symbol("w"), Expr::symbol("alpha"));
    let (xbar, ybar) = centroid;
    let b_x = (&moments[1] / l).expand()?;
    let b_y = (-&moments[0] / l).expand()?;
    let a_bar_x = -(&alpha * ybar) - w.powi(2) * xbar;
    let a_bar_y = &alpha * xbar - w.powi(2) * ybar;
    let a_x = (mass * &a_bar_x - &b_x).expand()?;
    let a_y = (mass * &a_bar_y - &b_y).expand()?;
    let s = Expr::symbol;
    Ok(Derivation {
        name: "reactions".into(),
        title: "dynamic reactions of the bearings".into(),
        steps: vec![
            Step {
                table: None,
                title: "moments about A of the reaction at B: ΣM_x = -l B_y, ΣM_y = l B_x".into(),
                relations: vec![
                    Relation::new(-(l * s("B_y")), moments[0].clone(), Axis::X),
                    Relation::new(l * s("B_x"), moments[1].clone(), Axis::Y),
                ],
            },
            Step {
                table: None,
                title: "ΣF = m ā with ā = α k × r̄ - ω² r̄".into(),
                relations: vec![
                    Relation::new(s("A_x") + s("B_x"), mass * &a_bar_x, Axis::X),
                    Relation::new(s("A_y") + s("B_y"), mass * &a_bar_y, Axis::Y),
                ],
            },
            Step {
                table: None,
                title: "the reactions".into(),
                relations: vec![
                    Relation::new(s("B_x"), b_x, Axis::X),
                    Relation::new(s("B_y"), b_y, Axis::Y),
                    Relation::new(s("A_x"), a_x, Axis::X),
                    Relation::new(s("A_y"), a_y, Axis::Y),
                ],
            },
        ],
    })
}
