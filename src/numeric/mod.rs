//! Numbers: evaluation, integration of Euler's equations, exact torque-free motion.
//!
//! - [`scalar`]: number types other than `f64` (dual numbers, double-double)
//! - [`tape`]: compiled evaluation of expressions (interpreter and machine code)
//! - [`integrators`]: the ODE integrators and the high-precision reference
//! - [`rigid_body`]: the body's state, inertia and moment, its exact and simulated motion
//! - [`rounding_error`]: an expression in double-double with a bound on its rounding error
//! - [`splitmix`]: a small deterministic pseudorandom generator
//! - [`work_precision`]: time against error for every method, and its plots

pub mod error;
pub mod integrators;
pub mod rigid_body;
pub mod rounding_error;
pub mod scalar;
pub mod splitmix;
pub mod tape;
pub mod work_precision;

pub use error::NumericError;
pub use scalar::dual::Dual;
pub use tape::interpreter::{Instruction, Tape};
#[cfg(feature = "jit")]
pub use tape::native::NativeTape;
