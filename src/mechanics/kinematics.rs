//! Velocity and acceleration of points of a rigid body (the kinematics the chapter uses):
//!
//! ```text
//! v_P = v_A + ω × r_{P/A}
//! α   = (ω̇)_Oxyz + Ω × ω                      (ω's rates seen in a frame turning at Ω)
//! v_P = ω × r_P,  a_P = α × r_P + ω × (ω × r_P)                 (O fixed, r_P from O)
//! v_P = v̄ + ω × r_{P/G},  a_P = ā + α × r_{P/G} + ω × (ω × r_{P/G})   (through G)
//! ```
//!
//! The mass centre is the body point P = G of the fixed-point forms: `v̄ = ω × r̄`,
//! `ā = α × r̄ + ω × (ω × r̄)`.

use super::derivation::{Derivation, Relation, Step};
use crate::algebra::vector::expand_each;
use crate::algebra::vector_products::cross;
use crate::algebra::{AlgebraError, Symbol, Vector};

/// `v_P = v_A + ω × r_{P/A}`: the velocity of the body point at `relative` from A.
pub fn velocity_of_point(
    velocity_of_a: &Vector,
    omega: &Vector,
    relative: &Vector,
) -> Result<Vector, AlgebraError> {
    expand_each(&(velocity_of_a + cross(omega, relative)))
}

/// A point of the body as a derivation names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyPoint<'a> {
    /// The mass centre G: `v̄`, `ā`, at `r̄`.
    MassCentre,
    /// A point the scene names (`A`): `v_A`, `a_A`, at `r_A`.
    Named(&'a str),
}

/// The point whose motion a body point's is found from.
#[derive(Debug, Clone, Copy)]
pub enum Through<'a> {
    /// The fixed point O, the origin: at rest.
    FixedPoint,
    /// The mass centre G at `position` from O, moving with `motion` (its velocity v̄ for a
    /// velocity, its acceleration ā for an acceleration).
    MassCentre {
        position: &'a Vector,
        motion: &'a Vector,
    },
}

impl BodyPoint<'_> {
    /// In words: `the mass centre`, `point $A$`.
    fn words(self) -> String {
        match self {
            BodyPoint::MassCentre => "the mass centre".into(),
            BodyPoint::Named(name) => format!("point ${}$", Symbol::new(name).latex()),
        }
    }

    /// The vector of its motion in LaTeX: `letter` is `v` or `a` (`\bar{\mathbf{v}}`,
    /// `\mathbf{v}_A`); `r` gives its position (`\bar{\mathbf{r}}`, `\mathbf{r}_A`).
    fn latex(self, letter: &str) -> String {
        match self {
            BodyPoint::MassCentre => format!(r"\bar{{\mathbf{{{letter}}}}}"),
            BodyPoint::Named(name) => {
                format!(r"\mathbf{{{letter}}}_{{{}}}", Symbol::new(name).latex())
            }
        }
    }

    /// A derivation's name for its velocity (`letter` `v`) or acceleration (`a`): `vbar`, `v_A`.
    fn derivation_name(self, letter: &str) -> String {
        match self {
            BodyPoint::MassCentre => format!("{letter}bar"),
            BodyPoint::Named(name) => format!("{letter}_{name}"),
        }
    }

    /// The component relations of its velocity (`letter` `v`) or acceleration (`a`):
    /// `vbar_x`, ... for G, `v_Ax`, ... for A.
    fn components(self, letter: &str, v: &Vector) -> Vec<Relation> {
        match self {
            BodyPoint::MassCentre => Relation::components(&format!("{letter}bar"), v),
            BodyPoint::Named(name) => {
                Relation::components_named(v, |x| format!("{letter}_{name}{x}"))
            }
        }
    }
}

impl Through<'_> {
    /// The position of `point` relative to the reference (`r_P`, or `r_P − r̄`), in LaTeX and
    /// as a vector, and the reference's motion (zero at O).
    fn relative(self, point: BodyPoint, position: &Vector) -> (String, Vector, Option<Vector>) {
        match self {
            Through::FixedPoint => (point.latex("r"), position.clone(), None),
            Through::MassCentre {
                position: centroid,
                motion,
            } => (
                format!(r"({} - \bar{{\mathbf{{r}}}})", point.latex("r")),
                position - centroid,
                Some(motion.clone()),
            ),
        }
    }
}

/// `v_P = ω × r_P` (O fixed) or `v_P = v̄ + ω × (r_P − r̄)` (through G), for the body point
/// `point` at `position` from O.
///
/// A rod along x turning at w about z through the fixed end O: its tip at `L i` moves at
/// `w k × L i = L w j`.
///
/// ```
/// use kinetics::mechanics::kinematics::{velocity_of_body_point, BodyPoint, Through};
/// use kinetics::{parse_expression, Expr, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap();
/// let omega = Vector::new(Expr::zero(), Expr::zero(), hand("w"));
/// let tip = Vector::new(hand("L"), Expr::zero(), Expr::zero());
/// let d = velocity_of_body_point(BodyPoint::Named("B"), &omega, &tip, Through::FixedPoint)?;
/// let v: Vec<&Expr> = d.result().iter().map(|r| &r.rhs).collect();
/// assert_eq!(v, [&Expr::zero(), &hand("L w"), &Expr::zero()]);
/// assert_eq!(d.result()[1].lhs, hand("v_By"));
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn velocity_of_body_point(
    point: BodyPoint,
    omega: &Vector,
    position: &Vector,
    through: Through,
) -> Result<Derivation, AlgebraError> {
    let (r, relative, reference) = through.relative(point, position);
    let zero = Vector::from_element(crate::algebra::Expr::zero());
    let v = velocity_of_point(reference.as_ref().unwrap_or(&zero), omega, &relative)?;
    let (v_latex, words) = (point.latex("v"), point.words());
    let title = match reference {
        None => format!(
            r"velocity of {words}, ${v_latex} = \boldsymbol{{\omega}} \times {r}$ ($O$ fixed)"
        ),
        Some(_) => format!(
            r"velocity of {words}, ${v_latex} = \bar{{\mathbf{{v}}}} + \boldsymbol{{\omega}} \times {r}$"
        ),
    };
    Ok(Derivation {
        name: point.derivation_name("v"),
        title: format!("velocity of {words}"),
        steps: vec![Step::new(title, point.components("v", &v))],
    })
}

/// `v̄ = ω × r̄` for a body turning about the fixed point O.
pub fn velocity_of_mass_centre(
    omega: &Vector,
    centroid: &Vector,
) -> Result<Derivation, AlgebraError> {
    velocity_of_body_point(BodyPoint::MassCentre, omega, centroid, Through::FixedPoint)
}

/// `α = (ω̇)_frame + Ω × ω` and `a_P = α × r_P + ω × (ω × r_P)` (O fixed) or
/// `a_P = ā + α × (r_P − r̄) + ω × (ω × (r_P − r̄))` (through G), for the body point `point`
/// at `position` from O; `omega_dot` holds the rates of ω's components seen in the frame,
/// which turns at `frame_rate` (Ω), so α is the absolute angular acceleration. The step
/// shows α, then the acceleration: the result is its last three relations.
pub fn acceleration_of_body_point(
    point: BodyPoint,
    omega: &Vector,
    omega_dot: &Vector,
    frame_rate: &Vector,
    position: &Vector,
    through: Through,
) -> Result<Derivation, AlgebraError> {
    let (r, relative, reference) = through.relative(point, position);
    let alpha = expand_each(&(omega_dot + cross(frame_rate, omega)))?;
    let turning = cross(&alpha, &relative) + cross(omega, &cross(omega, &relative));
    let a = expand_each(&match &reference {
        None => turning,
        Some(abar) => abar + turning,
    })?;
    let (a_latex, words) = (point.latex("a"), point.words());
    let start = match reference {
        None => String::new(),
        Some(_) => r"\bar{\mathbf{a}} + ".into(),
    };
    let title = format!(
        r"acceleration of {words}, ${a_latex} = {start}\boldsymbol{{\alpha}} \times {r} + \boldsymbol{{\omega}} \times (\boldsymbol{{\omega}} \times {r})$, $\boldsymbol{{\alpha}} = (\dot{{\boldsymbol{{\omega}}}})_{{\text{{frame}}}} + \boldsymbol{{\Omega}} \times \boldsymbol{{\omega}}$"
    );
    Ok(Derivation {
        name: point.derivation_name("a"),
        title: format!("acceleration of {words}"),
        steps: vec![Step::new(
            title,
            [
                Relation::components("alpha", &alpha),
                point.components("a", &a),
            ]
            .concat(),
        )],
    })
}

/// `ā = α × r̄ + ω × (ω × r̄)` for a body turning about the fixed point O (the body point G).
pub fn acceleration_of_mass_centre(
    omega: &Vector,
    omega_dot: &Vector,
    frame_rate: &Vector,
    centroid: &Vector,
) -> Result<Derivation, AlgebraError> {
    acceleration_of_body_point(
        BodyPoint::MassCentre,
        omega,
        omega_dot,
        frame_rate,
        centroid,
        Through::FixedPoint,
    )
}
