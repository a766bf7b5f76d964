//! The mechanics of chapter 18: inertia, momentum, energy, rotating frames, Euler's
//! equations, fixed-axis rotation and balancing, impulse and momentum.

pub mod principal_axes;
pub mod validation;
