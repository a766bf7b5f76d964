//! Where a simulation's output goes: one [`Sample`] at a time, so that memory does not grow
//! with the number of samples.

use crate::numeric::error::NumericError;
use nalgebra::{RealField, UnitQuaternion, Vector3};

/// The body at one sample time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample<T: RealField + Copy> {
    /// Time.
    pub t: T,
    /// Angular velocity, body-frame components.
    pub omega: Vector3<T>,
    /// Attitude, `r_fixed = q * r_body`.
    pub orientation: UnitQuaternion<T>,
    /// Kinetic energy of rotation `T = ½ ω · [I] ω`.
    pub kinetic_energy: T,
    /// `|H_G| = |[I] ω|`.
    pub angular_momentum_magnitude: T,
}

/// Receives samples in time order. Any `FnMut(Sample<T>)` is an infallible sink; implement
/// the trait to stop the simulation with an error (for instance when a write fails).
pub trait SampleSink<T: RealField + Copy> {
    /// Takes the next sample.
    fn accept(&mut self, sample: Sample<T>) -> Result<(), NumericError>;
}

impl<T: RealField + Copy, F: FnMut(Sample<T>)> SampleSink<T> for F {
    fn accept(&mut self, sample: Sample<T>) -> Result<(), NumericError> {
        self(sample);
        Ok(())
    }
}
