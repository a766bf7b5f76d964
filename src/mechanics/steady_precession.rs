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
use super::eulerian_angles::EulerianAngles;
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

/// The moments steady precession needs.
#[derive(Debug, Clone, PartialEq)]
pub struct SteadyPrecession {
    /// `ΣM` in Oxyz, with ω_z the symbol [`axial_spin`]: `((I ω_z − I'φ̇ cos θ) φ̇ sin θ, 0, 0)`.
    pub moments: Vector,
    /// `ΣM_x` at θ = 90°, in the rates alone: `I ψ̇ φ̇`.
    pub moment_at_right_angle: Expr,
}

/// The steady-precession moments about `point` (`O` or `G`), from the gyroscope's
/// equations by substitution, with the steps: the equations, the steady rates set to zero,
/// and θ = 90°.
///
/// ```
/// use kinetics::mechanics::eulerian_angles::EulerianAngles;
/// use kinetics::mechanics::steady_precession::steady_precession;
/// use kinetics::parse_expression;
///
/// let (steady, _) = steady_precession(&EulerianAngles::chapter(), "O")?;
/// let hand = |t: &str| parse_expression("by hand", t).unwrap();
/// assert_eq!(steady.moment_at_right_angle, hand("I psidot phidot"));
/// assert!(steady.moments[1].is_zero() && steady.moments[2].is_zero());
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn steady_precession(
    angles: &EulerianAngles,
    point: &str,
) -> Result<(SteadyPrecession, Derivation), AlgebraError> {
    let (gyro, general) = gyroscope_equations(angles, point)?;
    let steady = steady_rates(angles);
    let still = |s: Symbol| steady.contains(&s).then(Expr::zero);
    let moments = Vector::from_iterator(
        gyro.moments_in_axial_spin
            .iter()
            .map(|m| m.subs(&still)?.factor_terms())
            .collect::<Result<Vec<_>, _>>()?,
    );
    let w_z = axial_spin();
    let right_angle = &Expr::pi() * &Expr::rational(1, 2);
    let axial_at_right_angle = gyro
        .axial_spin
        .subs(&|s| (s == angles.nutation).then(|| right_angle.clone()))?;
    let moment_at_right_angle = moments[0]
        .subs(&|s| (s == w_z).then(|| axial_at_right_angle.clone()))?
        .subs(&|s| (s == angles.nutation).then(|| right_angle.clone()))?
        .expand()?;
    let theta = Expr::sym(angles.nutation);
    let mut equations = Relation::components("SumM", &moments);
    equations.push(Relation::new(
        Expr::sym(w_z),
        gyro.axial_spin.clone(),
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
        Step::new(
            r"axis of spin perpendicular to the axis of precession, $\theta = 90^\circ$",
            vec![
                Relation::new(
                    Expr::func(Func::Cos, theta),
                    Expr::func(Func::Cos, right_angle.clone()),
                    Axis::Z,
                ),
                Relation::new(Expr::sym(w_z), axial_at_right_angle, Axis::Z),
                Relation::new(
                    Expr::symbol("SumM_x"),
                    moment_at_right_angle.clone(),
                    Axis::X,
                ),
            ],
        ),
    ];
    Ok((
        SteadyPrecession {
            moments,
            moment_at_right_angle,
        },
        Derivation {
            name: "steady_precession".into(),
            title: "steady precession of a gyroscope".into(),
            steps,
        },
    ))
}
