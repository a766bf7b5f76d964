//! Integrators of an initial-value problem, and the ground truth they are measured against.
//!
//! - `ode.rs`: the system `ẏ = f(t, y)` as the explicit integrators see it
//! - `compensated.rs`: sums of many increments with their rounding carried (Kahan–Babuška)
//! - `rk4.rs`: classical Runge–Kutta, fixed step
//! - `adaptive/`: the adaptive-step driver of an embedded pair with dense output
//! - `dop853/`: Dormand–Prince 8(5,3)
//! - `vern9/`: Verner's 9(8) pair
//! - `splitting.rs`: Lie–Poisson splitting of the rigid body, exact rotations
//! - `reference.rs`: order-30 Taylor integrator in double-double (the reference)
//! - `harmonic_moment.rs`: a moment whose Taylor series is exact, for the reference

pub mod adaptive;
pub mod compensated;
pub mod dop853;
pub mod harmonic_moment;
pub mod ode;
pub mod reference;
pub mod rk4;
pub mod splitting;
pub mod vern9;
