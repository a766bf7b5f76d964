//! An axisymmetric body under no force (§18.11). With ΣM_G = 0, `H_G` is fixed in space:
//! take Z along it, `H_G = H K`. Equating `H_G = I'θ̇ i + I'φ̇ sin θ j + I ω_z k` to
//! `H K = H sin θ j + H cos θ k` component by component (θ not 0, 90° or 180°):
//!
//! ```text
//! θ̇ = 0 (θ constant),   H = I ω_z / cos θ,   φ̇ = I ω_z / (I' cos θ),   ψ̇ = (I' − I) ω_z / I'
//! ```
//!
//! ω = φ̇ sin θ j + ω_z k makes with the axis z the angle γ, `tan γ = ω_y/ω_z = (I/I') tan θ`.
//! The body cone (about z, half-angle γ) rolls on the space cone (about Z, half-angle
//! θ − γ): outside it in direct precession (I' > I: γ < θ, ψ̇ and φ̇ of one sign), with
//! the space cone inside it in retrograde precession (I' < I: γ > θ, the space cone's
//! half-angle γ − θ, ψ̇ and φ̇ of opposite signs).

use super::derivation::{Derivation, Relation, Step};
use super::eulerian_angles::{EulerianAngles, OMEGA};
use super::gyroscope::{axial_spin, gyroscope_equations};
use crate::algebra::linear_solve::{solve_linear, SolveError};
use crate::algebra::{AlgebraError, Axis, Domains, Expr, Func, Symbol};

/// The sense of the precession of a body under no force.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PrecessionSense {
    /// `I' > I` (an elongated body): the spin and the precession of one sense.
    Direct,
    /// `I' < I` (a flattened body): of opposite senses.
    Retrograde,
    /// `I' = I`: ω is along H_G, the body turns about a fixed axis (ψ̇ = 0).
    EqualMoments,
}

/// The sense from the sign of `I' − I` under `domains` (the moments as symbols, or numbers
/// once the givens are substituted); `None` when the sign is not proved.
///
/// ```
/// use kinetics::mechanics::torque_free_axisymmetric::{precession_sense, PrecessionSense};
/// use kinetics::algebra::Domains;
/// use kinetics::Expr;
///
/// let disk = precession_sense(&Expr::rational(1, 2), &Expr::rational(1, 4), &Domains::chapter_defaults());
/// assert_eq!(disk, Some(PrecessionSense::Retrograde));
/// let symbols = precession_sense(&Expr::symbol("I"), &Expr::symbol("I'"), &Domains::chapter_defaults());
/// assert_eq!(symbols, None);
/// ```
pub fn precession_sense(
    axial: &Expr,
    transverse: &Expr,
    domains: &Domains,
) -> Option<PrecessionSense> {
    let excess = (transverse - axial).expand().ok()?;
    if excess.is_zero() {
        Some(PrecessionSense::EqualMoments)
    } else if domains.is_positive(&excess) {
        Some(PrecessionSense::Direct)
    } else if domains.is_positive(&-excess) {
        Some(PrecessionSense::Retrograde)
    } else {
        None
    }
}

/// What a scene asks of a body under no force (`find precession`): the angle γ between ω and
/// the axis, `tan γ = (I/I') tan θ` with the body's moments, and the sense of the precession.
#[derive(Debug, Clone, PartialEq)]
pub struct Precession {
    pub tan_gamma: Expr,
    pub sense: PrecessionSense,
}

/// The motion of the body under no force, in ω_z (the symbol `omega_z`) and θ.
#[derive(Debug, Clone, PartialEq)]
pub struct TorqueFreeMotion {
    /// `H = I ω_z / cos θ`, the magnitude of H_G along Z.
    pub angular_momentum: Expr,
    /// `φ̇ = I ω_z / (I' cos θ)`.
    pub precession_rate: Expr,
    /// `ψ̇ = (I' − I) ω_z / I'`.
    pub spin_rate: Expr,
    /// `tan γ = (I/I') tan θ`, γ the angle between ω and the axis of symmetry.
    pub tan_gamma: Expr,
}

/// The torque-free motion of the axisymmetric body about its mass centre G, with its steps:
/// `H_G = H K` by components, the rates solved, γ, and the two cones.
///
/// ```
/// use kinetics::mechanics::eulerian_angles::EulerianAngles;
/// use kinetics::mechanics::torque_free_axisymmetric::torque_free_axisymmetric;
/// use kinetics::parse_expression;
///
/// let (free, _) = torque_free_axisymmetric(&EulerianAngles::chapter())?;
/// let hand = |t: &str| parse_expression("by hand", t).unwrap();
/// let difference = (&free.spin_rate - &hand("(I' - I) omega_z / I'")).expand()?;
/// assert!(difference.is_zero());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn torque_free_axisymmetric(
    angles: &EulerianAngles,
) -> Result<(TorqueFreeMotion, Derivation), AlgebraError> {
    let (gyro, _) = gyroscope_equations(angles, "G")?;
    let (theta_dot, phi_dot, psi_dot) = (
        angles.nutation.dot(),
        angles.precession.dot(),
        angles.spin.dot(),
    );
    let magnitude = Symbol::new("H");
    let along_z = gyro.kinematics.vertical.map(|k| &Expr::sym(magnitude) * &k);
    let components: Vec<Relation> = [Axis::X, Axis::Y, Axis::Z]
        .into_iter()
        .enumerate()
        .map(|(k, axis)| Relation::new(gyro.angular_momentum[k].clone(), along_z[k].clone(), axis))
        .collect();
    let residuals: Vec<Expr> = components.iter().map(Relation::residual).collect();
    let solved = solve(&residuals, &[theta_dot, magnitude, phi_dot])?;
    let value = |s: Symbol| solved.iter().find(|(u, _)| *u == s).map(|(_, v)| v.clone());
    let (h, precession_rate) = (
        value(magnitude).unwrap_or_else(Expr::zero),
        value(phi_dot).unwrap_or_else(Expr::zero),
    );
    let omega_z = Expr::sym(axial_spin());
    let spin_equation =
        (&omega_z - &gyro.axial_spin).subs(&|s| (s == phi_dot).then(|| precession_rate.clone()))?;
    let spin_rate = solve(&[spin_equation], &[psi_dot])?
        .pop()
        .map_or_else(Expr::zero, |(_, v)| v)
        .cancel()?
        .factor_terms()?;
    let omega_y =
        gyro.kinematics.omega[1].subs(&|s| (s == phi_dot).then(|| precession_rate.clone()))?;
    // tan γ = ω_y/ω_z, written as a multiple of tan θ: the ratio times cos θ / sin θ.
    let theta = Expr::sym(angles.nutation);
    let tan = |e: &Expr| Expr::func(Func::Tan, e.clone());
    let cotangent = &Expr::func(Func::Cos, theta.clone()) / &Expr::func(Func::Sin, theta.clone());
    let multiple = (&(&omega_y / &omega_z) * &cotangent).cancel()?;
    let tan_gamma = &multiple * &tan(&theta);
    let gamma = Expr::symbol("gamma");
    let ratio = (&spin_rate / &precession_rate).cancel()?.factor_terms()?;
    let steps = vec![
        Step::new(
            r"no force: $\Sigma\mathbf{M}_G = \mathbf{0}$, $\mathbf{H}_G$ is fixed in space; $Z$ along it, $\mathbf{H}_G = H\,\mathbf{K}$",
            components,
        ),
        Step::new(
            r"the components along $x$ and $z$ ($\theta \neq 0, 90^\circ, 180^\circ$): $\theta$ is constant",
            vec![
                Relation::new(Expr::sym(theta_dot), Expr::zero(), Axis::X),
                Relation::new(Expr::sym(magnitude), h.clone(), Axis::Z),
            ],
        ),
        Step::new(
            r"the component along $y$, $I'\dot\phi = H$, in $\boldsymbol{\omega} = \omega_y\,\mathbf{j} + \omega_z\,\mathbf{k}$",
            vec![Relation::new(
                Expr::symbol(&format!("{OMEGA}_y")),
                omega_y,
                Axis::Y,
            )],
        ),
        Step::new(
            r"the spin; $\gamma$, the angle of $\boldsymbol{\omega}$ from the axis; body cone: axis $z$, half-angle $\gamma$; space cone: axis $Z$, half-angle $\theta - \gamma$ in direct precession ($I' > I$: $\gamma < \theta$, $\dot\psi$ and $\dot\phi$ of one sign), $\gamma - \theta$ in retrograde precession ($I' < I$)",
            vec![
                Relation::new(Expr::sym(phi_dot), precession_rate.clone(), Axis::Y),
                Relation::new(omega_z.clone(), gyro.axial_spin.clone(), Axis::Z),
                Relation::new(Expr::sym(psi_dot), spin_rate.clone(), Axis::Z),
                Relation::new(tan(&gamma), tan_gamma.clone(), Axis::Z),
                Relation::new(&Expr::sym(psi_dot) / &Expr::sym(phi_dot), ratio, Axis::Z),
            ],
        ),
    ];
    Ok((
        TorqueFreeMotion {
            angular_momentum: h,
            precession_rate,
            spin_rate,
            tan_gamma,
        },
        Derivation {
            name: "torque_free".into(),
            title: "axisymmetric body under no force".into(),
            steps,
        },
    ))
}

/// The unknowns' values from `residuals = 0`, linear in them. A system that does not fix
/// them has a zero pivot, a division by zero (not for these equations, whose pivots are
/// `I'`, `cos θ` and `1`).
fn solve(residuals: &[Expr], unknowns: &[Symbol]) -> Result<Vec<(Symbol, Expr)>, AlgebraError> {
    match solve_linear(residuals, unknowns) {
        Ok(solution) => Ok(solution.values),
        Err(SolveError::Algebra(e)) => Err(e),
        Err(_) => Err(AlgebraError::DivisionByZero),
    }
}
