//! Rotation about a fixed axis (§18.8). With z along the axis, `ω = ω k`, Ω = ω and
//! `α = ω̇`, `ΣM_O = [I]{α k} + ω k × [I]{ω k}` gives
//!
//! ```text
//! ΣM_x = -I_xz α + I_yz ω²
//! ΣM_y = -I_yz α - I_xz ω²
//! ΣM_z =  I_z α
//! ```
//!
//! The chapter's shafts often lie along x: the same derivation with the axis `a` and the two
//! across it `b`, `c` in cyclic order (`e_b × e_c = e_a`: for z, x then y; for x, y then z),
//! so every equation is the one above with the subscripts turned cyclically.
//!
//! For a shaft on bearings A (at O) and B (at distance l along the axis), the moments about
//! A of the radial reactions at B are `ΣM_b = -l B_c`, `ΣM_c = l B_b` (z: `ΣM_x = -l B_y`,
//! `ΣM_y = l B_x`), so `B_c = -(ΣM_b)/l`, `B_b = (ΣM_c)/l`, and `A = m ā - B` with
//! `ā = α e_a × r̄ - ω² r̄_⊥` (gravity's static part is left out).

use super::derivation::{Derivation, Relation, Step};
use super::inertia::InertiaTensor;
use super::rotating_frame::rate_of_angular_momentum;
use crate::algebra::{AlgebraError, Axis, Expr, Vector};

const AXES: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];
const LETTERS: [&str; 3] = ["x", "y", "z"];
const UNIT_VECTORS: [&str; 3] = [r"\mathbf{i}", r"\mathbf{j}", r"\mathbf{k}"];

/// The axis of rotation `a` and the two across it `b`, `c` in cyclic order, as indices.
fn across(axis: Axis) -> (usize, usize, usize) {
    let a = axis.index();
    (a, (a + 1) % 3, (a + 2) % 3)
}

/// `e` along the axis of index `a`.
fn along(a: usize, e: Expr) -> Vector {
    let mut v = Vector::from_element(Expr::zero());
    v[a] = e;
    v
}

/// The three moment equations for rotation about `axis` (the chapter's z, or x, y).
///
/// `[I]{α k} = α(-I_xz, -I_yz, I_z)` and `w k × [I]{w k} = w²(I_yz, -I_xz, 0)`
/// (`k × i = j`, `k × j = -i`); their sum is the chapter's form.
///
/// ```
/// use kinetics::{fixed_axis_rotation, parse_expression, print, Axis, InertiaTensor};
///
/// let d = fixed_axis_rotation(&InertiaTensor::general(), Axis::Z)?;
/// let printed: Vec<String> = d
///     .result()
///     .iter()
///     .map(|r| print::text_about(&r.rhs, r.axis))
///     .collect();
/// assert_eq!(printed, ["-I_xz*alpha + I_yz*w^2", "-I_yz*alpha - I_xz*w^2", "I_z*alpha"]);
/// let by_hand = parse_expression("by hand", "-alpha I_xz + w^2 I_yz")?;
/// assert_eq!(d.result()[0].rhs, by_hand);
/// // A shaft along x: the same equations with x → y → z → x.
/// let along_x = fixed_axis_rotation(&InertiaTensor::general(), Axis::X)?;
/// let turned = parse_expression("by hand", "-alpha I_xy + w^2 I_xz")?;
/// assert_eq!(along_x.result()[1].rhs, turned);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn fixed_axis_rotation(
    inertia: &InertiaTensor,
    axis: Axis,
) -> Result<Derivation, AlgebraError> {
    let (a, b, c) = across(axis);
    let omega = along(a, Expr::symbol("w"));
    let alpha = along(a, Expr::symbol("alpha"));
    let rate = rate_of_angular_momentum(inertia, &omega, &alpha, &omega, "O")?;
    let moments = Vector::from_iterator(rate.result().iter().map(|r| r.rhs.clone()));
    let (la, lb, lc) = (LETTERS[a], LETTERS[b], LETTERS[c]);
    let mut steps = vec![Step {
        vectors: Vec::new(),
        table: None,
        title: format!(
            r"${la}$ along the fixed axis: $\boldsymbol{{\omega}} = \omega{}$, $\boldsymbol{{\Omega}} = \boldsymbol{{\omega}}$, $\alpha = \dot{{\omega}}$ ($\omega_{lb} = \omega_{lc} = 0$)",
            UNIT_VECTORS[a]
        ),
        relations: Relation::components("H", &(inertia.matrix() * &omega)),
    }];
    steps.extend(rate.steps);
    steps.push(Step {
        vectors: Vec::new(),
        table: None,
        title: r"$\Sigma\mathbf{M}_O = \dot{\mathbf{H}}_O$".into(),
        relations: Relation::components("SumM", &moments),
    });
    Ok(Derivation {
        name: "fixed_axis".into(),
        title: "rotation about a fixed axis".into(),
        steps,
    })
}

/// Dynamic reactions of bearings A (at the origin) and B (at distance `l` along `axis`) on a
/// body of mass `m` whose mass centre is at `centroid` = `(r̄_b, r̄_c)` off the axis (for z:
/// `(x̄, ȳ)`; for x: `(ȳ, z̄)`; for y: `(z̄, x̄)`).
///
/// With the mass centre on the axis (`x̄ = ȳ = 0`) the reactions come from the products of
/// inertia alone: `B_x = ΣM_y/l = (-I_yz α - I_xz ω²)/l`,
/// `B_y = -ΣM_x/l = (I_xz α - I_yz ω²)/l`, and `A = -B` (`m ā = 0`).
///
/// ```
/// use kinetics::mechanics::fixed_axis::bearing_reactions;
/// use kinetics::{parse_expression, Axis, Expr, InertiaTensor};
///
/// let (m, l, zero) = (Expr::symbol("m"), Expr::symbol("l"), Expr::zero());
/// let d = bearing_reactions(&InertiaTensor::general(), &m, (&zero, &zero), &l, Axis::Z)?;
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
    axis: Axis,
) -> Result<Derivation, AlgebraError> {
    let (a, b, c) = across(axis);
    let fixed = fixed_axis_rotation(inertia, axis)?;
    let moments: Vec<Expr> = fixed.result().iter().map(|r| r.rhs.clone()).collect();
    let (w, alpha) = (Expr::symbol("w"), Expr::symbol("alpha"));
    let (r_b, r_c) = centroid;
    let b_b = (&moments[c] / l).expand()?;
    let b_c = (-&moments[b] / l).expand()?;
    let a_bar_b = -(&alpha * r_c) - w.powi(2) * r_b;
    let a_bar_c = &alpha * r_b - w.powi(2) * r_c;
    let a_b = (mass * &a_bar_b - &b_b).expand()?;
    let a_c = (mass * &a_bar_c - &b_c).expand()?;
    let (lb, lc) = (LETTERS[b], LETTERS[c]);
    let s = |name: &str, k: &str| Expr::symbol(&format!("{name}_{k}"));
    Ok(Derivation {
        name: "reactions".into(),
        title: "dynamic reactions of the bearings".into(),
        steps: vec![
            Step {
                vectors: Vec::new(),
                table: None,
                title: format!(
                    r"moments about $A$ of the reaction at $B$: $\Sigma M_{lb} = -l B_{lc}$, $\Sigma M_{lc} = l B_{lb}$"
                ),
                relations: vec![
                    Relation::new(-(l * s("B", lc)), moments[b].clone(), AXES[b]),
                    Relation::new(l * s("B", lb), moments[c].clone(), AXES[c]),
                ],
            },
            Step {
                vectors: Vec::new(),
                table: None,
                title: format!(
                    r"$\Sigma\mathbf{{F}} = m\bar{{\mathbf{{a}}}}$ with $\bar{{\mathbf{{a}}}} = \alpha{} \times \bar{{\mathbf{{r}}}} - \omega^2 \bar{{\mathbf{{r}}}}$",
                    UNIT_VECTORS[a]
                ),
                relations: vec![
                    Relation::new(s("A", lb) + s("B", lb), mass * &a_bar_b, AXES[b]),
                    Relation::new(s("A", lc) + s("B", lc), mass * &a_bar_c, AXES[c]),
                ],
            },
            Step {
                vectors: Vec::new(),
                table: None,
                title: "the reactions".into(),
                relations: vec![
                    Relation::new(s("B", lb), b_b, AXES[b]),
                    Relation::new(s("B", lc), b_c, AXES[c]),
                    Relation::new(s("A", lb), a_b, AXES[b]),
                    Relation::new(s("A", lc), a_c, AXES[c]),
                ],
            },
        ],
    })
}
