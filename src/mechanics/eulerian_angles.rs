//! Eulerian angles (§18.9): the precession φ about the fixed vertical Z, the nutation θ about
//! the line of nodes, the spin ψ about the body's axis of symmetry. The frame Oxyz follows
//! the axis but not the spin: x along the line of nodes, z along the axis, so the vertical is
//! `K = sin θ j + cos θ k`, and
//!
//! ```text
//! Ω = φ̇ K + θ̇ i = θ̇ i + φ̇ sin θ j + φ̇ cos θ k
//! ω = Ω + ψ̇ k   = θ̇ i + φ̇ sin θ j + (ψ̇ + φ̇ cos θ) k
//! ```
//!
//! The rates of ω's components as seen in Oxyz are their time derivatives,
//! `(ω̇)_Oxyz = θ̈ i + (φ̈ sin θ + φ̇ θ̇ cos θ) j + (ψ̈ + φ̈ cos θ − φ̇ θ̇ sin θ) k`: what
//! `Ḣ = [I]{ω̇} + Ω × H` needs (an axisymmetric body's `[I]` is constant in Oxyz).

use super::derivation::{Derivation, Relation, Step};
use crate::algebra::{AlgebraError, Expr, Func, Symbol, Vector};

/// The name of ω's components in Oxyz: `omega_x`, `omega_y`, `omega_z` (ω_x, … on a page).
/// The gyroscope's ω_z ([`super::gyroscope::axial_spin`]) and the ω_y of the body under no
/// force are these symbols, so that a page showing them beside this step shows one quantity.
pub const OMEGA: &str = "omega";

/// The three angles; their rates are the dotted symbols (`phidot`, `thetaddot`, ...).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EulerianAngles {
    /// φ, about the fixed vertical Z.
    pub precession: Symbol,
    /// θ, between Z and the axis of symmetry z, about the line of nodes x.
    pub nutation: Symbol,
    /// ψ, about the axis of symmetry z.
    pub spin: Symbol,
}

impl EulerianAngles {
    /// The chapter's names: `phi`, `theta`, `psi`.
    pub fn chapter() -> EulerianAngles {
        EulerianAngles {
            precession: Symbol::new("phi"),
            nutation: Symbol::new("theta"),
            spin: Symbol::new("psi"),
        }
    }
}

/// The vectors of the motion in the components of Oxyz.
#[derive(Debug, Clone, PartialEq)]
pub struct EulerianKinematics {
    /// `K`, the fixed vertical.
    pub vertical: Vector,
    /// `Ω`, the angular velocity of Oxyz.
    pub frame_rate: Vector,
    /// `ω`, the body's angular velocity.
    pub omega: Vector,
    /// The rates of ω's components as seen in Oxyz.
    pub omega_dot: Vector,
}

/// `K`, `Ω`, `ω` and `(ω̇)_Oxyz` from the angles, with the steps a textbook shows.
///
/// ```
/// use kinetics::mechanics::eulerian_angles::{eulerian_kinematics, EulerianAngles};
/// use kinetics::parse_expression;
///
/// let (motion, _) = eulerian_kinematics(&EulerianAngles::chapter())?;
/// let hand = |t: &str| parse_expression("by hand", t).unwrap();
/// assert_eq!(motion.omega[2], hand("psidot + phidot cos(theta)"));
/// assert_eq!(
///     motion.omega_dot[2],
///     hand("psiddot + phiddot cos(theta) - phidot thetadot sin(theta)")
/// );
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn eulerian_kinematics(
    angles: &EulerianAngles,
) -> Result<(EulerianKinematics, Derivation), AlgebraError> {
    let theta = Expr::sym(angles.nutation);
    let rate = |s: Symbol| Expr::sym(s.dot());
    let (phi_dot, theta_dot, psi_dot) = (
        rate(angles.precession),
        rate(angles.nutation),
        rate(angles.spin),
    );
    let (sin, cos) = (
        Expr::func(Func::Sin, theta.clone()),
        Expr::func(Func::Cos, theta),
    );
    let vertical = Vector::new(Expr::zero(), sin.clone(), cos.clone());
    let frame_rate = Vector::new(theta_dot.clone(), &phi_dot * &sin, &phi_dot * &cos);
    let omega = Vector::new(theta_dot, &phi_dot * &sin, &psi_dot + &(&phi_dot * &cos));
    let omega_dot = Vector::new(omega[0].d_dt()?, omega[1].d_dt()?, omega[2].d_dt()?);
    let derivation = Derivation {
        name: "eulerian_angles".into(),
        title: "Eulerian angles".into(),
        steps: vec![
            Step::new(
                r"the vertical in Oxyz (x along the line of nodes, z along the axis), $\mathbf{K} = \mathrm{sin}\,\theta\,\mathbf{j} + \mathrm{cos}\,\theta\,\mathbf{k}$",
                Relation::components("K", &vertical),
            ),
            Step::new(
                r"the frame turns with the axis, not the spin: $\boldsymbol{\Omega} = \dot\phi\,\mathbf{K} + \dot\theta\,\mathbf{i}$",
                Relation::components("Omega", &frame_rate),
            ),
            Step::new(
                r"$\boldsymbol{\omega} = \boldsymbol{\Omega} + \dot\psi\,\mathbf{k}$",
                Relation::components(OMEGA, &omega),
            ),
            Step::new(
                r"rates of the components of $\boldsymbol{\omega}$ in Oxyz",
                Relation::components("omegadot", &omega_dot),
            ),
        ],
    };
    Ok((
        EulerianKinematics {
            vertical,
            frame_rate,
            omega,
            omega_dot,
        },
        derivation,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::vector_products::cross;

    /// ω − Ω is the spin ψ̇ k; and K, fixed in space, is seen in Oxyz to change at −Ω × K,
    /// where only the nutation moves it: Ω × K = θ̇ i × K (φ̇ K × K = 0).
    #[test]
    fn the_spin_is_omega_less_the_frame_rate_and_the_vertical_moves_by_nutation() {
        let (m, _) = eulerian_kinematics(&EulerianAngles::chapter()).unwrap();
        let spin = &m.omega - &m.frame_rate;
        assert!(spin[0].is_zero() && spin[1].is_zero());
        assert_eq!(spin[2], Expr::symbol("psidot"));
        let along_vertical = cross(&m.frame_rate, &m.vertical);
        let by_hand = cross(
            &Vector::new(Expr::symbol("thetadot"), Expr::zero(), Expr::zero()),
            &m.vertical,
        );
        for k in 0..3 {
            assert_eq!(
                along_vertical[k].expand().unwrap(),
                by_hand[k].expand().unwrap()
            );
        }
    }
}
