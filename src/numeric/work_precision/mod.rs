//! Work against precision: how much time each method needs for how much accuracy.
//!
//! - `study.rs`: every method at several settings on a set of bodies, timed, with its error
//! - `equal_error.rs`: a method's time at exactly one error, for comparing methods there
//! - `plot.rs`: SVG line charts (also the simulation's ω(t)); feature `plot`

pub mod equal_error;
#[cfg(feature = "plot")]
pub mod plot;
pub mod study;
