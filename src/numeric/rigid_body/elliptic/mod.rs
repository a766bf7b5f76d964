//! Jacobi elliptic functions and Legendre's elliptic integrals through Carlson's symmetric
//! forms, as the exact torque-free motion uses them.
//!
//! - `carlson.rs`: Carlson's `R_F, R_D, R_C, R_J` by the duplication theorem, generic over
//!   [`EllipticScalar`] (f64 and double-double)
//! - `parameter.rs`: the parameter `m` with its complement `m' = 1 − m`, each to full precision
//! - `legendre_integrals.rs`: `K`, `F` and `Π`, complete and incomplete, from `R_F` and `R_J`
//! - `jacobi.rs`: `sn, cn, dn, am`, set up once per parameter
//! - `theta.rs`: their theta series in the nome, for m up to about 0.96

mod carlson;
mod jacobi;
mod legendre_integrals;
mod parameter;
#[cfg(test)]
mod test_points;
mod theta;

pub use carlson::{carlson_rc, carlson_rd, carlson_rf, carlson_rj, EllipticScalar};
pub use jacobi::{half_period_sign, jacobi, Jacobi, JacobiFunctions};
pub use legendre_integrals::{
    complete_first_kind, complete_third_kind, first_kind_from_sines, incomplete_first_kind,
    incomplete_third_kind, third_kind_from_sines,
};
pub use parameter::EllipticParameter;
