//! The exact expression algebra the derivations are written in.
//!
//! [`Expr`] is an immutable expression in canonical form with exact rational constants and
//! interned [`Symbol`]s. It supports `+ - * /` (so nalgebra matrices and vectors of
//! expressions work), [`Expr::expand`], [`Expr::subs`], [`Expr::collect`], [`Expr::d_dt`],
//! [`Expr::diff`] and [`Expr::eval`] over any float type. [`Expr::sum_of_products`] and
//! [`vector_products`] form `Σ aᵢbᵢ`, `[M]{v}`, `a·b` and `a×b` as one sum per component.
//! Rational functions: [`Expr::cancel`] (lowest terms, by [`polynomial_gcd`]),
//! [`Expr::together`] and [`Expr::factor_terms`].

#[cfg(test)]
mod arbitrary;
mod axis;
mod cancel;
mod collect;
mod common_factor;
mod decimal;
mod derivative;
mod digit_bound;
mod domain;
mod double_angle;
mod error;
mod eval;
mod exact_angle;
mod expand;
mod expansion_size;
mod expr;
mod function;
pub mod linear_solve;
mod merge;
mod operation_count;
mod ops;
mod pi;
mod polynomial;
pub mod polynomial_solve;
mod radicals;
mod rational;
mod sign;
mod simplify;
mod single_angle;
mod square_rewrite;
mod subs;
mod sum_of_products;
mod symbol;
mod tangent;
mod together;
mod traversal;
mod trig_simplify;
pub mod vector;
pub mod vector_products;
pub mod work;

pub use axis::Axis;
pub use cancel::polynomial_gcd;
pub use collect::Collected;
pub use decimal::{four_significant_figures, significant_figures};
pub use digit_bound::MAX_DIGITS;
pub use domain::{Domain, Domains};
pub use error::{AlgebraError, MAX_EXPANDED_TERMS};
pub use eval::rational_to;
pub use expr::{Expr, View};
pub use function::Func;
pub use pi::PI_NAME;
pub use rational::Q;
pub use symbol::{axis_of_subscript, reads_as_several_letters, Role, Symbol};

/// A three-vector of expressions (`i`, `j`, `k` components).
pub type Vector = nalgebra::Vector3<Expr>;
/// A 3 × 3 matrix of expressions, such as the inertia tensor.
pub type Matrix = nalgebra::Matrix3<Expr>;
