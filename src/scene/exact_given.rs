//! A given's value as an exact expression, for the algebra: the number as written is an
//! exact decimal (`0.1` is 1/10), and each unit's factor to SI is exact too (the table in
//! `units.rs`): the degree is π/180, the revolution per minute π/30, `ft` 3048/10000, `mm`
//! 1/1000. So `given theta = 90 deg` is π/2, and `sin θ` there is 1.

use super::model::Scene;
use super::unit_text::unit_powers;
use super::units::exact_factor;
use crate::algebra::{Expr, Symbol, Q};

impl Scene {
    /// The value of a given as an exact expression (a rational times a power of π), when
    /// the scene gives it a value (see the module documentation).
    pub fn exact_given(&self, s: Symbol) -> Option<Expr> {
        let written = self
            .givens
            .iter()
            .find(|g| g.symbol == s)?
            .written
            .as_deref()?;
        let (number, unit) = split_number(written)?;
        let (factor, pi_power) = unit_factor(unit)?;
        Some(Expr::num(&number * &factor) * Expr::pi().powi(pi_power))
    }
}

/// The number a quantity begins with (the longest prefix that reads as one) and its unit.
fn split_number(written: &str) -> Option<(Q, &str)> {
    let (negative, rest) = match written.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, written),
    };
    let (q, unit) = (1..=rest.len())
        .rev()
        .filter(|&end| rest.is_char_boundary(end))
        .find_map(|end| Some((Q::parse_decimal(&rest[..end])?, rest[end..].trim())))?;
    Some((if negative { -&q } else { q }, unit))
}

/// The exact factor to SI of a unit such as `deg`, `m/s^2` or `kg·m²` (empty: 1), as a
/// rational and a power of π.
fn unit_factor(unit: &str) -> Option<(Q, i64)> {
    let (mut factor, mut pi_power) = (Q::ONE, 0i64);
    if unit.is_empty() {
        return Some((factor, pi_power));
    }
    for power in unit_powers(unit).ok()? {
        let unit = exact_factor(power.name)?;
        let exponent = i64::from(power.exponent);
        let q = Q::new(unit.numerator, unit.denominator)?;
        factor = &factor * &q.checked_pow(exponent)?;
        pi_power += i64::from(unit.pi_power) * exponent;
    }
    Some((factor, pi_power))
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
