//! Scalar types other than `f64`, each a `num_traits::Float`, so the tape and `Expr::eval`
//! run over them unchanged.
//!
//! - `dual.rs`: dual numbers `a + b ε`, exact first derivatives
//! - `double_double.rs`: ~32-digit arithmetic `hi + lo` (error-free sums and products)
//! - `double_double_float.rs`: `DoubleDouble` as a `num_traits::Float`
//! - `double_double_elementary.rs`: exp, ln, sin/cos, atan2 in double-double
//! - `double_double_constants.rs`: the standard constants as nearest `hi + lo` pairs

pub mod double_double;
pub mod double_double_constants;
pub mod double_double_elementary;
pub mod double_double_float;
pub mod dual;
