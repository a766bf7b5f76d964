//! Numbers: evaluation, integration of Euler's equations, exact torque-free motion.

pub mod double_double;
pub mod dual;
pub mod elliptic;
pub mod error;
pub mod reference;
pub mod tape;
pub mod tape_batch;
pub mod tape_builder;
pub mod torque_free;

pub use dual::Dual;
pub use error::NumericError;
pub use tape::{Instruction, Tape};
