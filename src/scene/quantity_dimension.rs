//! The dimension of each quantity a scene can ask for, known before its value: a number
//! written with a unit inside the scene (`at (150 mm, 0, 0)`) is a plain number in SI in
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
            Quantity::MassCentreAcceleration | Quantity::PointAcceleration(_) => {
                Dimension::ACCELERATION
            }
            Quantity::EffectiveForce => Dimension::FORCE,
            Quantity::AngularMomentumAboutG | Quantity::AngularMomentumAboutO => angular_momentum,
            Quantity::KineticEnergy
            | Quantity::TranslationalKineticEnergy
            | Quantity::RotationalKineticEnergy
            | Quantity::RateOfAngularMomentum
            | Quantity::RateOfAngularMomentumAboutO => Dimension::MOMENT,
            Quantity::InertiaAboutG | Quantity::InertiaAboutO => Dimension::INERTIA,
            // Its moments' (its axes are unit vectors).
            Quantity::PrincipalAboutG | Quantity::PrincipalAboutO => Dimension::INERTIA,
            Quantity::Unknown(s) => return declared.get(&s).copied(),
            Quantity::Balance => return None,
        })
    }
}
