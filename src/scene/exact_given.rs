//! A given's value as an exact expression, for the algebra: the number as written is an
//! exact decimal (`0.1` is 1/10), and each unit's factor into the scene's unit system is
//! exact too (`unit_system.rs`): the degree is π/180, the revolution per minute π/30, `mm`
//! 1/1000 in SI, `in` 1/12 in U.S. customary units. So `given theta = 90 deg` is π/2, and `sin θ` there is 1. A given defined by
//! earlier givens (`given psidot = v/r_w`) is its definition with their exact values.

use super::model::Scene;
use crate::algebra::{Expr, Symbol, Q};

impl Scene {
    /// The value of a given as an exact expression (a rational times a power of π), when
    /// the scene gives it a value (see the module documentation).
    pub fn exact_given(&self, s: Symbol) -> Option<Expr> {
        let given = self.givens.iter().find(|g| g.symbol == s)?;
        if let Some(definition) = &given.definition {
            return definition.exact.clone();
        }
        let written = given.written.as_ref()?;
        let number = match written.number.strip_prefix('-') {
            Some(magnitude) => -&Q::parse_decimal(magnitude)?,
            None => Q::parse_decimal(&written.number)?,
        };
        let (factor, pi_power) = self.unit_system.exact_of_one(&written.unit)?;
        Some(Expr::num(&number * &factor) * Expr::pi().powi(pi_power))
    }

    /// Whether `e` is zero: as an expression, with each defined given put in as its
    /// definition (`v + r_w ψ̇` with `ψ̇ = −v/r_w`), or with every given's exact value in
    /// place, so that a tie the values make (`I_x = I_y` for a box with `a = b`) is decided
    /// exactly, however small the difference between values that are not equal.
    pub fn is_exactly_zero(&self, e: &Expr) -> bool {
        let exact = |s: Symbol| self.exact_given(s);
        let zero = |x: Result<Expr, _>| x.and_then(|x: Expr| x.expand()).is_ok_and(|x| x.is_zero());
        zero(Ok(e.clone())) || zero(e.subs(&|s| self.defined_given(s))) || zero(e.subs(&exact))
    }

    /// A defined given as its definition in the givens that are not defined (definitions
    /// name only earlier givens, so the chain ends).
    fn defined_given(&self, s: Symbol) -> Option<Expr> {
        let definition = self
            .givens
            .iter()
            .find(|g| g.symbol == s)?
            .definition
            .as_ref()?;
        definition.expr.subs(&|t| self.defined_given(t)).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::parse_scene;

    fn exact(given: &str) -> Option<Expr> {
        let text =
            format!("given {given}\ngiven M = 5 kg\ngiven R = 1 m\nbody sphere(R) mass M\nfind T");
        let scene = parse_scene("t.scene", &text).unwrap();
        scene.exact_given(scene.givens[0].symbol)
    }

    #[test]
    fn degrees_are_rational_multiples_of_pi() {
        assert_eq!(exact("theta = 90 deg"), Some(Expr::pi() / Expr::int(2)));
        assert_eq!(exact("theta = -22.5 deg"), Some(-Expr::pi() / Expr::int(8)));
        assert_eq!(exact("n = 60 rpm"), Some(Expr::int(2) * Expr::pi()));
        assert_eq!(exact("w = 90 deg/s"), Some(Expr::pi() / Expr::int(2)));
    }

    #[test]
    fn decimals_and_units_are_exact() {
        assert_eq!(exact("L = 100 mm"), Some(Expr::rational(1, 10)));
        assert_eq!(exact("L = 0.1 m"), Some(Expr::rational(1, 10)));
        assert_eq!(exact("h = 10 ft"), Some(Expr::rational(3048, 1000)));
        assert_eq!(exact("a = 2 m/s^2"), Some(Expr::int(2)));
        assert_eq!(exact("x = 1.5e3"), Some(Expr::int(1500)));
        assert_eq!(exact("p : kg"), None);
    }
}
