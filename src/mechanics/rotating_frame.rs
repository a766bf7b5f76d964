//! Rate of change of angular momentum in a rotating frame (§18.5, §18.7):
//!
//! ```text
//! Ḣ_G = (Ḣ_G)_Gxyz + Ω × H_G,     (Ḣ_G)_Gxyz = [I]{ω̇}
//! ```
//!
//! `(Ḣ_G)_Gxyz = [I]{ω̇}` because the moments and products of inertia are constant in a
//! frame in which the body's mass distribution looks the same: the body-fixed frame
//! (Ω = ω), or, for an axisymmetric body, a frame that does not spin with the body (Ω ≠ ω).
//! The same holds about a fixed point O with `[I_O]` (§18.7):
//! `Ḣ_O = (Ḣ_O)_Oxyz + Ω × H_O`, `(Ḣ_O)_Oxyz = [I_O]{(ω̇)_Oxyz}` (the rates of ω's components
//! in the frame, not α when Ω ≠ ω); or, from the rate about G,
//! `Ḣ_O = Ḣ_G + r̄ × m ā` (O fixed, `r̄` the position of G from O).

use super::derivation::{Derivation, Relation, Step};
use super::inertia::InertiaTensor;
use super::linear_momentum::effective_force;
use super::moment_transfer::{moment_transfer, Labels};
use super::slip::Slip;
use crate::algebra::vector::expand_each;
use crate::algebra::vector_products::{cross, mat_vec};
use crate::algebra::{AlgebraError, Expr, Vector};

/// `Ḣ = [I]{ω̇} + Ω × ([I]{ω})`. `omega_dot` holds the rates of the components of ω as
/// seen in the rotating frame; `frame_rate` is Ω; `point` names the point the moments and
/// products of `inertia` are about (`G`, or a fixed point `O`).
///
/// The gyroscopic moment: a rotor spinning steadily at `w_z` about its axis z while the frame
/// turns at `Omega_x` about x. `(Ḣ)_Gxyz = 0` and `Ω × H = Omega_x i × I_z w_z k`, so
/// `Ḣ = -I_z Omega_x w_z j` (`i × k = -j`).
///
/// ```
/// use kinetics::mechanics::rotating_frame::rate_of_angular_momentum;
/// use kinetics::{parse_expression, Expr, InertiaTensor, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap();
/// let vector = |x: &str, y: &str, z: &str| Vector::new(hand(x), hand(y), hand(z));
/// let hdot = rate_of_angular_momentum(
///     &InertiaTensor::principal(),
///     &vector("0", "0", "w_z"),
///     &vector("0", "0", "0"),
///     &vector("Omega_x", "0", "0"),
///     "G",
/// )?;
/// let components: Vec<&Expr> = hdot.result().iter().map(|r| &r.rhs).collect();
/// assert_eq!(components, [&hand("0"), &hand("-I_z Omega_x w_z"), &hand("0")]);
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn rate_of_angular_momentum(
    inertia: &InertiaTensor,
    omega: &Vector,
    omega_dot: &Vector,
    frame_rate: &Vector,
    point: &str,
) -> Result<Derivation, AlgebraError> {
    let matrix = inertia.matrix();
    let relative = match Slip::SquareForRate.is_active() {
        true => mat_vec(&matrix, &omega.map(|w| w.powi(2))),
        false => mat_vec(&matrix, omega_dot),
    };
    let h = mat_vec(&matrix, omega);
    let transport = transport_term(frame_rate, omega, &h);
    let total = expand_each(&(&relative + &transport))?;
    let tensor = InertiaTensor::written_about(point);
    Ok(Derivation {
        name: "Hdot".into(),
        title: "rate of change of angular momentum".into(),
        steps: vec![
            Step::vector(
                format!(
                    r"rate relative to the rotating frame, $(\dot{{\mathbf{{H}}}}_{point})_{{{point}xyz}} = {tensor}\{{(\dot{{\boldsymbol{{\omega}}}})_{{{point}xyz}}\}}$"
                ),
                format!(r"(\dot{{\mathbf{{H}}}}_{point})_{{{point}xyz}}"),
                expand_each(&relative)?,
            ),
            Step::vector(
                "transport term",
                format!(r"\boldsymbol{{\Omega}} \times \mathbf{{H}}_{point}"),
                expand_each(&transport)?,
            ),
            Step::new(
                format!(
                    r"$\dot{{\mathbf{{H}}}}_{point} = (\dot{{\mathbf{{H}}}}_{point})_{{{point}xyz}} + \boldsymbol{{\Omega}} \times \mathbf{{H}}_{point}$"
                ),
                Relation::components("Hdot", &total),
            ),
        ],
    })
}

/// The transport term `Ω × H` (or what a slip makes of it: none, `ω × H`, `H × Ω`).
fn transport_term(frame_rate: &Vector, omega: &Vector, h: &Vector) -> Vector {
    if Slip::TransportTermMissing.is_active() {
        Vector::from_element(Expr::zero())
    } else if Slip::OmegaForFrameRate.is_active() {
        cross(omega, h)
    } else if Slip::CrossProductReversed.is_active() {
        cross(h, frame_rate)
    } else {
        cross(frame_rate, h)
    }
}

/// `Ḣ_O = Ḣ_G + r̄ × m ā` for a body turning about the fixed point O, from the rate
/// `hdot_g` about its mass centre G at `rbar` from O.
///
/// A particle (`Ḣ_G = 0`) at `r̄ = x̄ i` with `ā = a j`: `r̄ × m ā = m x̄ a k`.
///
/// ```
/// use kinetics::mechanics::rotating_frame::rate_of_angular_momentum_about_point;
/// use kinetics::{parse_expression, Expr, Vector};
///
/// let (zero, m) = (Vector::from_element(Expr::zero()), Expr::symbol("m"));
/// let rbar = Vector::new(Expr::symbol("xbar"), Expr::zero(), Expr::zero());
/// let abar = Vector::new(Expr::zero(), Expr::symbol("a"), Expr::zero());
/// let hdot_o = rate_of_angular_momentum_about_point(&zero, &rbar, &m, &abar)?;
/// let components: Vec<&Expr> = hdot_o.result().iter().map(|r| &r.rhs).collect();
/// assert_eq!(components[2], &parse_expression("by hand", "m xbar a")?);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn rate_of_angular_momentum_about_point(
    hdot_g: &Vector,
    rbar: &Vector,
    mass: &Expr,
    abar: &Vector,
) -> Result<Derivation, AlgebraError> {
    moment_transfer(
        hdot_g,
        rbar,
        &effective_force(mass, abar)?,
        Labels {
            components: "Hdot",
            name: "Hdot_O",
            title: "rate of change of angular momentum about $O$",
            moment: r"\bar{\mathbf{r}} \times m\bar{\mathbf{a}}",
            moment_title: "moment of the effective force",
            total_title: r"rate of change of angular momentum about the fixed point $O$, $\dot{\mathbf{H}}_O = \dot{\mathbf{H}}_G + \bar{\mathbf{r}} \times m\bar{\mathbf{a}}$",
        },
    )
}
