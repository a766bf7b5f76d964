//! Motion of a rigid body: its state, inertia and applied moment, Euler's equations as an
//! ODE, the exact torque-free motion, and the driver that simulates either.
//!
//! - `state.rs`: angular velocity `ω` and attitude quaternion `q`
//! - `inertia.rs`: principal moments or the full tensor, validated
//! - `torque.rs`: the applied moment and what it depends on
//! - `euler_rhs.rs`: Euler's equations and `q̇ = ½ q ⊗ (0, ω)` as a right-hand side
//! - `torque_free.rs`: exact torque-free motion (Euler–Poinsot), all regimes
//! - `eulerian_angles.rs`: φ, θ, ψ and their rates ↔ attitude and ω (§18.9)
//! - `heavy_top.rs`: a symmetric top about its fixed point under its weight, as a problem
//! - `nutation_limits.rs`: the top's conserved quantities and its turning angles
//! - `elliptic/`: Jacobi elliptic functions and Carlson's integrals it uses
//! - `simulate.rs`: one driver for every method: validation, sampling, streaming
//! - `exact_propagation.rs`: the exact method and `auto`
//! - `sample_sink.rs`: where samples go (memory stays flat)

pub mod elliptic;
pub mod euler_rhs;
pub mod eulerian_angles;
pub mod exact_propagation;
pub mod heavy_top;
pub mod inertia;
pub mod nutation_limits;
pub mod sample_sink;
pub mod simulate;
pub mod state;
pub mod torque;
pub mod torque_free;
