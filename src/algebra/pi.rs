//! π, the one constant of the algebra.
//!
//! π is the symbol `pi` (printed `\pi`), given a meaning everywhere a symbol's value or
//! rate is asked: its value is π = 3.14159… in every scalar type (exact to the type's
//! precision: `hi + lo` with `lo` the part of π below `f64`'s last bit, so a double-double
//! gets 32 digits), its rate is 0 (its role is not kinematic, so `d/dt π = 0`), and the
//! functions of a rational multiple of it are exact (see `exact_angle.rs`). A scene may not
//! declare a symbol named `pi` (refused where it is declared).

use super::expr::{Expr, View};
use super::symbol::Symbol;
use num_traits::Float;

/// The ASCII name of π.
pub const PI_NAME: &str = "pi";

/// π to 53 bits, and what π exceeds it by (π − PI_HI, about 1.2 · 10⁻¹⁶).
const PI_HI: f64 = std::f64::consts::PI;
const PI_LO: f64 = 1.224_646_799_147_353_2e-16;

impl Symbol {
    /// The symbol π.
    pub fn pi() -> Symbol {
        Symbol::new(PI_NAME)
    }

    /// Whether this symbol is π (a comparison of two bytes).
    pub fn is_pi(self) -> bool {
        self.name() == PI_NAME
    }
}

impl Expr {
    /// The constant π.
    pub fn pi() -> Expr {
        Expr::sym(Symbol::pi())
    }

    /// The rational `q` when the expression is `q·π` (π itself included).
    pub fn as_multiple_of_pi(&self) -> Option<&super::rational::Q> {
        match self.monomial() {
            [factor] => match factor.view() {
                View::Sym(s) if s.is_pi() => Some(self.coefficient()),
                _ => None,
            },
            _ => None,
        }
    }
}

/// π in the scalar type `T`, as exactly as `T` holds it.
pub(super) fn pi_value<T: Float>() -> T {
    let part = |x: f64| T::from(x).unwrap_or_else(T::nan);
    part(PI_HI) + part(PI_LO)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::scalar::double_double::DoubleDouble;

    /// π in double-double agrees with the library's 32-digit constant.
    #[test]
    fn pi_in_double_double_is_the_constant() {
        let pi: DoubleDouble = pi_value();
        assert_eq!(pi, DoubleDouble::PI);
        assert_eq!(pi_value::<f64>(), std::f64::consts::PI);
    }

    #[test]
    fn multiples_of_pi_are_recognised() {
        let half_pi = Expr::pi() / Expr::int(2);
        assert_eq!(
            half_pi.as_multiple_of_pi(),
            Some(&super::super::Q::new(1, 2).unwrap())
        );
        assert_eq!(Expr::pi().as_multiple_of_pi(), Some(&super::super::Q::ONE));
        assert!((Expr::pi() * Expr::symbol("x"))
            .as_multiple_of_pi()
            .is_none());
    }
}
