//! Numbers: evaluation, integration of Euler's equations, exact torque-free motion.

pub mod body_inertia;
pub mod dop853;
pub mod double_double;
pub mod double_double_constants;
pub mod double_double_elementary;
pub mod double_double_float;
pub mod dual;
pub mod elliptic;
pub mod error;
pub mod euler_rhs;
pub mod exact_propagation;
pub mod harmonic_moment;
mod native_schedule;
pub mod native_tape;
pub mod native_tape_batch;
pub mod native_tape_compile;
pub mod ode;
pub mod plot;
pub mod reference;
pub mod rigid_body_state;
pub mod rk4;
pub mod sample_sink;
pub mod simulate;
pub mod splitting;
pub mod tape;
pub mod tape_batch;
pub mod tape_builder;
pub mod torque;
pub mod torque_free;
pub mod work_precision;

pub use dual::Dual;
pub use error::NumericError;
pub use native_tape::NativeTape;
pub use tape::{Instruction, Tape};
