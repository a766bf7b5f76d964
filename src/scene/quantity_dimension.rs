//! The dimension of each quantity a scene can ask for, known before its value: a number
//! written with a unit inside the scene (`at (150 mm, 0, 0)`) is a plain number in SI in
//! the results (3/20), so a result's unit is not always readable from its expression
//! (`5/12 m r² w²` is a force when the 5/12 came from 1/(8 · 150 mm)).

use super::model::Quantity;
use super::units::{Dimension, Dimensions};

/// The chapter's quantities and their dimensions.
const DIMENSIONS: [(Quantity, Dimension); 9] = [
    (Quantity::AngularVelocity, Dimension::ANGULAR_VELOCITY),
    (Quantity::MassCentreVelocity, Dimension::VELOCITY),
    (Quantity::LinearMomentum, Dimension::new(1, 1, -1)),
    (Quantity::MassCentreAcceleration, Dimension::ACCELERATION),
    (Quantity::EffectiveForce, Dimension::FORCE),
    (Quantity::AngularMomentumAboutG, Dimension::new(1, 2, -1)),
    (Quantity::AngularMomentumAboutO, Dimension::new(1, 2, -1)),
    (Quantity::KineticEnergy, Dimension::MOMENT),
    (Quantity::RateOfAngularMomentum, Dimension::MOMENT),
];

impl Quantity {
    /// Its dimension: a declared unknown's from `declared`, a chapter quantity's from the
    /// table above (none for a quantity not in it: its expression's dimension is used).
    pub fn dimension(self, declared: &Dimensions) -> Option<Dimension> {
        match self {
            Quantity::Unknown(s) => declared.get(&s).copied(),
            q => DIMENSIONS.iter().find(|(k, _)| *k == q).map(|(_, d)| *d),
        }
    }
}
