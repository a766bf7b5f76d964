//! The motion of a gyroscope (§18.9): an axisymmetric body turning about a fixed point O on
//! its axis (or about its mass centre G), its moments of inertia `I` about the axis and `I'`
//! about any transverse axis through that point. In the frame Oxyz of the Eulerian angles
//! (x the line of nodes, z the axis, Ω = θ̇ i + φ̇ sin θ j + φ̇ cos θ k) the body's mass
//! looks the same at every instant, so `[I_O] = diag(I', I', I)` is constant and
//! `Ḣ_O = [I_O]{(ω̇)_Oxyz} + Ω × H_O` (Ω ≠ ω; the rates of ω's components in Oxyz):
//!
//! ```text
//! H_O = I'θ̇ i + I'φ̇ sin θ j + I ω_z k,          ω_z = ψ̇ + φ̇ cos θ
//! ΣM_x = I'(θ̈ − φ̇² sin θ cos θ) + I φ̇ sin θ (ψ̇ + φ̇ cos θ)
//! ΣM_y = I'(φ̈ sin θ + 2θ̇φ̇ cos θ) − I θ̇ (ψ̇ + φ̇ cos θ)
//! ΣM_z = I(ψ̈ + φ̈ cos θ − θ̇φ̇ sin θ)
//! ```
//!
//! Each is derived here from [`rate_of_angular_momentum`]; the grouping by `I'` and `I` is
//! the textbook's, `ω_z` kept as one quantity until it is written out.

use super::derivation::{Derivation, Relation, Step};
use super::eulerian_angles::{eulerian_kinematics, EulerianAngles, EulerianKinematics, OMEGA};
use super::inertia::InertiaTensor;
use super::rotating_frame::rate_of_angular_momentum;
use crate::algebra::vector_products::mat_vec;
use crate::algebra::{AlgebraError, Axis, Expr, Symbol, Vector};

/// `I`, the moment of inertia about the axis of symmetry.
pub fn axial_moment() -> Symbol {
    Symbol::new("I")
}

/// `I'` (printed I′), the moment of inertia about any axis through the point perpendicular
/// to the axis of symmetry.
pub fn transverse_moment() -> Symbol {
    Symbol::new("I'")
}

/// `omega_z` (ω_z), the component of ω along the axis of symmetry, `ψ̇ + φ̇ cos θ`: in the
/// name [`eulerian_kinematics`] gives ω's components ([`OMEGA`]), so that a page showing
/// both (a scene's worked solution) shows one quantity ω_z, not two symbols.
pub fn axial_spin() -> Symbol {
    Symbol::new(&format!("{OMEGA}_z"))
}

/// `[I] = diag(I', I', I)`: the axisymmetric body about a point of its axis, in Oxyz.
pub fn axisymmetric_inertia() -> InertiaTensor {
    let transverse = Expr::sym(transverse_moment());
    InertiaTensor::diagonal([transverse.clone(), transverse, Expr::sym(axial_moment())])
}

/// The gyroscope's vectors in the components of Oxyz.
#[derive(Debug, Clone, PartialEq)]
pub struct GyroscopeEquations {
    /// K, Ω, ω and (ω̇)_Oxyz in the angles.
    pub kinematics: EulerianKinematics,
    /// `ψ̇ + φ̇ cos θ`, what [`axial_spin`] stands for.
    pub axial_spin: Expr,
    /// `H = I'θ̇ i + I'φ̇ sin θ j + I ω_z k`, with ω_z the symbol [`axial_spin`].
    pub angular_momentum: Vector,
    /// `ΣM = Ḣ`, ω_z the symbol [`axial_spin`] (where it appears: ΣM_x, ΣM_y), each
    /// component grouped by `I'` and `I`.
    pub moments_in_axial_spin: Vector,
    /// `ΣM = Ḣ` in the angles alone (ω_z written out), the textbook's equations.
    pub moments: Vector,
}

/// `ΣM = Ḣ` for the axisymmetric body about `point` (`O`, a fixed point on the axis, or
/// `G`), with the steps: the kinematics, ω_z, H, (Ḣ)_Oxyz, Ω × H, Ḣ, and the equations
/// grouped by `I'` and `I` with `ω_z = ψ̇ + φ̇ cos θ` beside them (the result).
///
/// ```
/// use kinetics::mechanics::eulerian_angles::EulerianAngles;
/// use kinetics::mechanics::gyroscope::gyroscope_equations;
/// use kinetics::parse_expression;
///
/// let (gyro, _) = gyroscope_equations(&EulerianAngles::chapter(), "O")?;
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// assert_eq!(
///     gyro.moments[2].expand()?,
///     hand("I (psiddot + phiddot cos(theta) - thetadot phidot sin(theta))")
/// );
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn gyroscope_equations(
    angles: &EulerianAngles,
    point: &str,
) -> Result<(GyroscopeEquations, Derivation), AlgebraError> {
    let (kinematics, motion) = eulerian_kinematics(angles)?;
    let inertia = axisymmetric_inertia();
    let omega_z = axial_spin();
    let written_out = kinematics.omega[2].clone();
    // ω with its axial component held as ω_z; its rates as seen in Oxyz are the angles'.
    let omega = Vector::new(
        kinematics.omega[0].clone(),
        kinematics.omega[1].clone(),
        Expr::sym(omega_z),
    );
    let angular_momentum = mat_vec(&inertia.matrix(), &omega);
    let rate = rate_of_angular_momentum(
        &inertia,
        &omega,
        &kinematics.omega_dot,
        &kinematics.frame_rate,
        point,
    )?;
    let total: Vec<Expr> = rate.result().iter().map(|r| r.rhs.clone()).collect();
    let moments_in_axial_spin = Vector::from_iterator(
        total
            .iter()
            .map(by_moments_of_inertia)
            .collect::<Result<Vec<_>, _>>()?,
    );
    let moments = Vector::from_iterator(
        moments_in_axial_spin
            .iter()
            .map(|m| m.subs(&|s| (s == omega_z).then(|| written_out.clone())))
            .collect::<Result<Vec<_>, _>>()?,
    );
    let tensor = InertiaTensor::written_about(point);
    // Ω and ω as the angles give them: ω's components `omega_x`, …, `omega_z`, the last
    // the symbol [`axial_spin`] from its definition to the equations.
    let mut steps = motion.steps[1..3].to_vec();
    steps.push(Step::new(
        format!(
            r"axisymmetric body, $I_x = I_y = I'$, $I_z = I$: $\mathbf{{H}}_{point} = {tensor}\{{\boldsymbol{{\omega}}\}}$"
        ),
        Relation::components("H", &angular_momentum),
    ));
    steps.extend(rate.steps);
    let mut equations = Relation::components("SumM", &moments_in_axial_spin);
    equations.push(Relation::new(
        Expr::sym(omega_z),
        written_out.clone(),
        Axis::Z,
    ));
    steps.push(Step::new(
        format!(
            r"$\Sigma\mathbf{{M}}_{point} = \dot{{\mathbf{{H}}}}_{point}$, $\omega_z$ the component of $\boldsymbol{{\omega}}$ along the axis"
        ),
        equations,
    ));
    Ok((
        GyroscopeEquations {
            kinematics,
            axial_spin: written_out,
            angular_momentum,
            moments_in_axial_spin,
            moments,
        },
        Derivation {
            name: "gyroscope".into(),
            title: "motion of a gyroscope (axisymmetric body, Eulerian angles)".into(),
            steps,
        },
    ))
}

/// `e` as `I'·(…) + I·(…)`: its terms gathered by the moments of inertia, each coefficient
/// a sum kept as it is (the textbook's grouping).
fn by_moments_of_inertia(e: &Expr) -> Result<Expr, AlgebraError> {
    let moments = [axial_moment(), transverse_moment()];
    let groups = e.collect(&moments)?;
    Ok(Expr::add_all(
        groups.into_iter().map(|g| &g.monomial * &g.coefficient),
    ))
}
