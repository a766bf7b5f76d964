//! Compiled evaluation: a flat instruction tape built once from expressions, evaluated
//! many times, interpreted over any `Float` or compiled to machine code (`f64`).
//!
//! - `interpreter.rs`: the instructions, the tape and its evaluation
//! - `builder.rs`: expressions to a tape (shared subexpressions, exact constant folding,
//!   pruning of fixed inputs)
//! - `batch.rs`: many parameter sets, in blocks of lanes and on all cores
//!
//! With the `jit` feature (on by default), the machine code:
//!
//! - `native.rs`: the tape as machine code, its checked evaluation
//! - `native_compile.rs`: lowering a tape to machine code with Cranelift
//! - `native_batch.rs`: the machine code over many parameter sets on all cores
//! - `native_schedule.rs`: the order the machine code computes registers in

pub mod batch;
pub mod builder;
pub mod interpreter;
#[cfg(feature = "jit")]
pub mod native;
#[cfg(feature = "jit")]
pub mod native_batch;
#[cfg(feature = "jit")]
pub mod native_compile;
#[cfg(feature = "jit")]
mod native_schedule;
