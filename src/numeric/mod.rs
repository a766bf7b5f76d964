//! Numbers: evaluation, integration of Euler's equations, exact torque-free motion.

pub mod dual;
pub mod error;

pub use dual::Dual;
pub use error::NumericError;
