//! The dimension of each quantity a scene can ask for, known before its value: a number
//! written with a unit inside the scene (`at (150 mm, 0, 0)`) is a plain number in the scene's units in
//! the results (3/20), so a result's unit is not always readable from its expression
//! (`5/12 m r² w²` is a force when the 5/12 came from 1/(8 · 150 mm)); and a zero result
//! keeps its unit.

use super::model::Quantity;
use super::units::{Dimension, Dimensions};

impl Quantity {
    /// Its dimension: a declared unknown's from `declared`, a chapter quantity's from the
    /// mechanics; none for a balance, whose rows (masses, angles) each have their own.
    pub fn dimension(self, declared: &Dimensions) -> Option<Dimension> {
        let momentum = Dimension::new(1, 1, -1);
        let angular_momentum = Dimension::new(1, 2, -1);
        Some(match self {
            Quantity::AngularVelocity => Dimension::ANGULAR_VELOCITY,
            Quantity::MassCentreVelocity | Quantity::PointVelocity(_) => Dimension::VELOCITY,
            Quantity::LinearMomentum | Quantity::NamedImpulse(_) => momentum,
            Quantity::NamedForce(_) => Dimension::FORCE,
            Quantity::MassCentreAcceleration | Quantity::PointAcceleration(_) => {
                Dimension::ACCELERATION
            }
            Quantity::EffectiveForce => Dimension::FORCE,
            Quantity::AngularMomentumAboutG | Quantity::AngularMomentumAboutO => angular_momentum,
            Quantity::KineticEnergy
            | Quantity::TranslationalKineticEnergy
            | Quantity::RotationalKineticEnergy
            | Quantity::KineticEnergyBefore
            | Quantity::KineticEnergyAfter
            | Quantity::EnergyLost
            | Quantity::RateOfAngularMomentum
            | Quantity::RateOfAngularMomentumAboutO => Dimension::MOMENT,
            Quantity::InertiaAboutG | Quantity::InertiaAboutO => Dimension::INERTIA,
            // Its moments' (its axes are unit vectors).
            Quantity::PrincipalAboutG | Quantity::PrincipalAboutO => Dimension::INERTIA,
            Quantity::Unknown(s) => return declared.get(&s).copied(),
            Quantity::Balance | Quantity::Precession => return None,
        })
    }
}

/// The dimension of a name the analysis derives, by the chapter's naming: `I_xy`, `I_1`
/// (inertia), `H_x` (angular momentum), `Hdot_z` (moment), `omega_y`, `Omega_x` (angular
/// velocity), `alpha_x` (angular acceleration), `vbar_x`, `v_Ax` (velocity), `abar_x`, `a_Ax`
/// (acceleration), `rbar_x`, `l` (length), `m_body`, `m_1` (mass), `T`, `T_rot` (energy),
/// `S_y`, `P_1`, `Q_1` (first moments, kg·m), `e_1` (a unit axis). It is what the relation's
/// right-hand side is, whatever plain numbers in the scene's units (`150 mm` is 3/20) it holds. A declared
/// symbol's dimension is declared, and is looked up first by the caller.
pub fn derived_dimension(name: &str) -> Option<Dimension> {
    let stem = name.split('_').next().unwrap_or(name);
    Some(match stem {
        "I" => Dimension::INERTIA,
        "H" => Dimension::new(1, 2, -1),
        "Hdot" => Dimension::MOMENT,
        "omega" | "Omega" => Dimension::ANGULAR_VELOCITY,
        "alpha" | "omegadot" => Dimension::ANGULAR_ACCELERATION,
        "vbar" | "v" => Dimension::VELOCITY,
        "abar" | "a" => Dimension::ACCELERATION,
        "rbar" | "l" => Dimension::LENGTH,
        "m" => Dimension::MASS,
        "T" => Dimension::MOMENT,
        "S" | "P" | "Q" => Dimension::new(1, 1, 0),
        "e" => Dimension::NONE,
        _ => return None,
    })
}
