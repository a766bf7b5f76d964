//! Units inside a scene's mathematics: `at (300 mm, 0, 0)`, `mass 20 g`,
//! `omega = 1200 rpm*k`, `force P = 2 kN*j`. A unit name written after a number
//! (`parse/units_after_numbers.rs`) that the scene does not declare is that unit: while the
//! expression's dimension is checked it is a marker symbol, `[mm]`, in the unit's dimension
//! (no name a scene can write has brackets); then each marker is replaced by the unit's
//! exact factor to SI (`units.rs`: `mm` 1/1000, `rpm` π/30, `deg` π/180), so that
//! `300 mm` is 3/10 exactly, the same as a given `0.3 m`.

use super::units::{exact_factor, unit_named, Dimension};
use crate::algebra::{AlgebraError, Expr, Symbol};

/// The marker of the unit `name` (none when it is not a unit).
pub fn marker(name: &str) -> Option<Expr> {
    unit_named(name).map(|_| Expr::symbol(&format!("[{name}]")))
}

/// The unit a marker symbol stands for.
pub fn unit_of(s: Symbol) -> Option<&'static str> {
    s.name().strip_prefix('[')?.strip_suffix(']')
}

/// The dimension of a marker symbol's unit (none for any other symbol).
pub fn marker_dimension(s: Symbol) -> Option<Dimension> {
    Some(unit_named(unit_of(s)?)?.dimension)
}

/// `e` with each marker replaced by its unit's exact factor to SI.
pub fn in_si(e: &Expr) -> Result<Expr, AlgebraError> {
    e.subs(&|s| {
        let factor = exact_factor(unit_of(s)?)?;
        let rational = Expr::rational(factor.numerator, factor.denominator);
        Some(rational * Expr::pi().powi(i64::from(factor.pi_power)))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markers_read_back_and_become_exact_factors() {
        let mm = marker("mm").unwrap();
        let deg = marker("deg").unwrap();
        assert_eq!(marker("furlong"), None);
        let s = mm.as_symbol().unwrap();
        assert_eq!(marker_dimension(s), Some(Dimension::LENGTH));
        assert_eq!(marker_dimension(Symbol::new("mm")), None);
        let e = Expr::int(300) * mm + Expr::int(30) * deg;
        let si = in_si(&e).unwrap();
        assert_eq!(si, Expr::rational(3, 10) + Expr::pi() / Expr::int(6));
    }
}
