//! Jacobi elliptic functions and Legendre's elliptic integrals through Carlson's symmetric
//! forms, as the exact torque-free motion uses them.
//!
//! - `carlson.rs`: Carlson's `R_F, R_D, R_C, R_J` by the duplication theorem, generic over
//!   [`EllipticScalar`] (f64 and double-double)
//! - `parameter.rs`: the parameter `m` with its complement `m' = 1 − m`, each to full precision
//! - `legendre_integrals.rs`: `K`, `F` and `Π`, complete and incomplete, from `R_F` and `R_J`
//! - `jacobi.rs`: `sn, cn, dn, am` by the descending Landen transformation

mod carlson;
mod jacobi;
mod legendre_integrals;
mod parameter;
#[cfg(test)]
mod test_points;

pub use carlson::{carlson_rc, carlson_rd, carlson_rf, carlson_rj, EllipticScalar};
pub use jacobi::{jacobi, Jacobi};
pub use legendre_integrals::{
    complete_first_kind, complete_third_kind, first_kind_from_sines, incomplete_first_kind,
    incomplete_third_kind, third_kind_from_sines,
};
pub use parameter::EllipticParameter;
