//! Steady precession of a gyroscope (§18.10): θ, φ̇ and ψ̇ constant, so that
//! `θ̇ = θ̈ = φ̈ = ψ̈ = 0` in the gyroscope's equations of motion
//! ([`gyroscope_equations`]), which then read
//!
//! ```text
//! ΣM_x = (I ω_z − I' φ̇ cos θ) φ̇ sin θ,     ΣM_y = ΣM_z = 0,     ω_z = ψ̇ + φ̇ cos θ
//! ```
//!
//! and, with the axis of spin perpendicular to the axis of precession (θ = 90°, ω_z = ψ̇),
//! `ΣM_x = I ψ̇ φ̇`. Both are obtained by substitution, never written down.

use super::derivation::{Derivation, Relation, Step};
use super::eulerian_angles::{eulerian_kinematics, EulerianAngles};
use super::gyroscope::{axial_spin, gyroscope_equations};
use crate::algebra::{AlgebraError, Axis, Expr, Func, Symbol, Vector};

/// The rates that vanish in steady precession: `θ̇`, `θ̈`, `φ̈`, `ψ̈`.
pub fn steady_rates(angles: &EulerianAngles) -> [Symbol; 4] {
    [
        angles.nutation.dot(),
        angles.nutation.dot().dot(),
        angles.precession.dot().dot(),
        angles.spin.dot().dot(),
    ]
}

/// The steady-precession moments about `point` (`O` or `G`) in Oxyz, from the gyroscope's
/// equations by substitution: `((I ω_z − I'φ̇ cos θ) φ̇ sin θ, 0, 0)` with ω_z the symbol
/// [`axial_spin`]; the steps: the equations, the steady rates set to zero.
///
/// ```
/// use kinetics::mechanics::eulerian_angles::EulerianAngles;
/// use kinetics::mechanics::steady_precession::steady_precession;
/// use kinetics::parse_expression;
///
/// let (moments, _) = steady_precession(&EulerianAngles::chapter(), "O")?;
/// let hand = parse_expression("by hand", "(I omega_z - I' phidot cos(theta)) phidot sin(theta)")?;
/// assert_eq!(moments[0].expand()?, hand.expand()?);
/// assert!(moments[1].is_zero() && moments[2].is_zero());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn steady_precession(
    angles: &EulerianAngles,
    point: &str,
) -> Result<(Vector, Derivation), AlgebraError> {
    let (gyro, general) = gyroscope_equations(angles, point)?;
    let steady = steady_rates(angles);
    let still = |s: Symbol| steady.contains(&s).then(Expr::zero);
    let moments = Vector::from_iterator(
        gyro.moments_in_axial_spin
            .iter()
            .map(|m| m.subs(&still)?.factor_terms())
            .collect::<Result<Vec<_>, _>>()?,
    );
    let mut equations = Relation::components("SumM", &moments);
    equations.push(Relation::new(
        Expr::sym(axial_spin()),
        gyro.axial_spin,
        Axis::Z,
    ));
    let steps = vec![
        Step::new(
            general
                .steps
                .last()
                .map_or_else(String::new, |s| s.title.clone()),
            general.result().to_vec(),
        ),
        Step::new(
            r"steady precession: $\theta$, $\dot\phi$, $\dot\psi$ constant, $\dot\theta = \ddot\theta = \ddot\phi = \ddot\psi = 0$",
            equations,
        ),
    ];
    Ok((
        moments,
        Derivation {
            name: "steady_precession".into(),
            title: "steady precession of a gyroscope".into(),
            steps,
        },
    ))
}

/// Steady precession with the axis of spin perpendicular to the axis of precession
/// (θ = 90°, so ω_z = ψ̇): `ΣM_x = I ψ̇ φ̇`, substituted into [`steady_precession`]'s
/// moment; the steps: the steady moments, then θ = 90°.
///
/// ```
/// use kinetics::mechanics::eulerian_angles::EulerianAngles;
/// use kinetics::mechanics::steady_precession::steady_precession_at_right_angle;
/// use kinetics::parse_expression;
///
/// let (moment, _) = steady_precession_at_right_angle(&EulerianAngles::chapter(), "O")?;
/// assert_eq!(moment, parse_expression("by hand", "I psidot phidot")?);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn steady_precession_at_right_angle(
    angles: &EulerianAngles,
    point: &str,
) -> Result<(Expr, Derivation), AlgebraError> {
    let (moments, steady) = steady_precession(angles, point)?;
    let (kinematics, _) = eulerian_kinematics(angles)?;
    let right_angle = &Expr::pi() * &Expr::rational(1, 2);
    let at_right_angle =
        |e: &Expr| e.subs(&|s| (s == angles.nutation).then(|| right_angle.clone()));
    let omega_z = axial_spin();
    let axial = at_right_angle(&kinematics.omega[2])?;
    let moment =
        at_right_angle(&moments[0].subs(&|s| (s == omega_z).then(|| axial.clone()))?)?.expand()?;
    let theta = Expr::sym(angles.nutation);
    let steps = vec![
        steady
            .steps
            .last()
            .cloned()
            .unwrap_or_else(|| Step::new("", vec![])),
        Step::new(
            r"axis of spin perpendicular to the axis of precession, $\theta = 90^\circ$",
            vec![
                Relation::new(
                    Expr::func(Func::Cos, theta),
                    Expr::func(Func::Cos, right_angle.clone()),
                    Axis::Z,
                ),
                Relation::new(Expr::sym(omega_z), axial, Axis::Z),
                Relation::new(Expr::symbol("SumM_x"), moment.clone(), Axis::X),
            ],
        ),
    ];
    Ok((
        moment,
        Derivation {
            name: "steady_precession_90".into(),
            title: "steady precession, axis of spin perpendicular to the axis of precession".into(),
            steps,
        },
    ))
}
