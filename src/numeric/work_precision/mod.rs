//! Work against precision: how much time each method needs for how much accuracy.
//!
//! - `study.rs`: every method at several settings on a set of bodies, timed, with its error
//! - `plot.rs`: SVG line charts (also the simulation's ω(t)); feature `plot`

#[cfg(feature = "plot")]
pub mod equal_error;
pub mod plot;
pub mod study;
