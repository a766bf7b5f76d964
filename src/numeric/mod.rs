//! Numbers: evaluation, integration of Euler's equations, exact torque-free motion.

pub mod error;

pub use error::NumericError;
