//! Numbers: evaluation, integration of Euler's equations, exact torque-free motion.

pub mod double_double;
pub mod elliptic;
pub mod error;

pub use error::NumericError;
