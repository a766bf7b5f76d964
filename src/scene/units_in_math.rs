//! Units inside a scene's mathematics: `at (300 mm, 0, 0)`, `mass 20 g`,
//! `omega = 1200 rpm*k`, `force P = 2 kN*j`. A unit name written after a number
//! (`parse/units_after_numbers.rs`) that the scene does not declare is that unit: while the
//! expression's dimension is checked it is a marker symbol, `[mm]`, in the unit's dimension
//! (no name a scene can write has brackets); then each marker is replaced by the unit's
//! exact factor into the scene's unit system (`unit_system.rs`: in SI `mm` 1/1000, in U.S.
//! customary units `in` 1/12; `rpm` π/30 and `deg` π/180 in both), so that `300 mm` is 3/10
//! exactly, the same as a given `0.3 m`.

use super::named_unit::NamedUnit;
use super::unit_system::UnitSystem;
use super::units::{unit_named, Dimension};
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

/// `e` with each marker replaced by its unit's exact factor into `system`.
pub fn in_system(e: &Expr, system: UnitSystem) -> Result<Expr, AlgebraError> {
    e.subs(&|s| {
        let (q, pi_power) = system.exact_of_one(&NamedUnit::named(unit_of(s)?))?;
        Some(Expr::num(q) * Expr::pi().powi(pi_power))
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
        let si = in_system(&e, UnitSystem::Si).unwrap();
        assert_eq!(si, Expr::rational(3, 10) + Expr::pi() / Expr::int(6));
        let inches = Expr::int(6) * marker("in").unwrap();
        assert_eq!(
            in_system(&inches, UnitSystem::Us).unwrap(),
            Expr::rational(1, 2)
        );
    }
}
