//! The unit system a page is in: SI, or U.S. customary when the scene's givens are written in
//! it. Every value a page shows (results, intermediate values) is in its system's unit for the
//! value's dimension:
//!
//! ```text
//!             SI          U.S. customary
//! mass        kg          slug  (lb·s²/ft)
//! length      m           ft
//! force       N           lb
//! moment      N·m         lb·ft   (work and energy: ft·lb)
//! inertia     kg·m²       slug·ft²
//! velocity    m/s         ft/s
//! H           kg·m²/s     lb·ft·s
//! impulse     N·s         lb·s
//! ```
//!
//! (angles and rates are rad, rad/s, rad/s² in both). The values are computed in the
//! system itself: every number a scene writes with a unit is brought to the system's unit of
//! its dimension by the exact ratio of the two ([`UnitSystem::exact_of_one`]: `6 in` is 1/2
//! in U.S. customary units, 381/2500 in SI), so that a step shows `1/2` (feet) where the
//! user wrote inches, never metres. The table's units are coherent in either system (1 lb
//! accelerates 1 slug at 1 ft/s²), so the equations of motion hold as written in both.

use super::named_unit::NamedUnit;
use super::units::Dimension;
use crate::algebra::Q;

/// SI or U.S. customary.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum UnitSystem {
    #[default]
    Si,
    Us,
}

/// Units that say a scene is written in SI, and in U.S. customary units; the others (s, min,
/// h, rad, deg, rpm) belong to both.
const SI_UNITS: [&str; 9] = ["kg", "g", "m", "mm", "cm", "km", "N", "kN", "J"];
const US_UNITS: [&str; 8] = ["slug", "ft", "in", "mi", "lb", "lbf", "oz", "kip"];

/// The U.S. customary unit of each dimension a result is commonly in.
const US_NAMES: [(Dimension, &[(&str, i8)]); 13] = [
    (Dimension::NONE, &[]),
    (Dimension::MASS, &[("slug", 1)]),
    (Dimension::LENGTH, &[("ft", 1)]),
    (Dimension::TIME, &[("s", 1)]),
    (Dimension::FORCE, &[("lb", 1)]),
    (Dimension::MOMENT, &[("lb", 1), ("ft", 1)]),
    (Dimension::ANGULAR_VELOCITY, &[("rad", 1), ("s", -1)]),
    (Dimension::ANGULAR_ACCELERATION, &[("rad", 1), ("s", -2)]),
    (Dimension::VELOCITY, &[("ft", 1), ("s", -1)]),
    (Dimension::ACCELERATION, &[("ft", 1), ("s", -2)]),
    (Dimension::INERTIA, &[("slug", 1), ("ft", 2)]),
    (Dimension::new(1, 1, -1), &[("lb", 1), ("s", 1)]),
    (Dimension::new(1, 2, -1), &[("lb", 1), ("ft", 1), ("s", 1)]),
];

/// The system units of these names belong to alone; none when they are of both (s, deg,
/// rpm) or mixed.
fn of_names<'a>(names: impl IntoIterator<Item = &'a str>) -> Option<UnitSystem> {
    let (mut si, mut us) = (false, false);
    for name in names {
        si |= SI_UNITS.contains(&name);
        us |= US_UNITS.contains(&name);
    }
    match (si, us) {
        (true, false) => Some(UnitSystem::Si),
        (false, true) => Some(UnitSystem::Us),
        _ => None,
    }
}

impl UnitSystem {
    /// The system the units a scene is written in belong to: U.S. customary when one of them
    /// is (ft, in, lb, slug, …) and none is SI's (kg, m, N, …); else SI.
    pub fn of_units<'a>(units: impl IntoIterator<Item = &'a NamedUnit>) -> UnitSystem {
        let names = units.into_iter().flat_map(NamedUnit::names);
        match of_names(names) {
            Some(UnitSystem::Us) => UnitSystem::Us,
            _ => UnitSystem::Si,
        }
    }

    /// The units of mass, length and time the system's values are in: kg, m, s; slug, ft, s.
    pub fn base_units(self) -> [&'static str; 3] {
        match self {
            UnitSystem::Si => ["kg", "m", "s"],
            UnitSystem::Us => ["slug", "ft", "s"],
        }
    }

    /// The system a unit belongs to alone: `lb·ft` U.S. customary, `N·m` SI; none for a unit
    /// of both (`deg`, `rad/s`, `s`) or of both mixed.
    pub fn of_unit(unit: &NamedUnit) -> Option<UnitSystem> {
        of_names(unit.names())
    }

    /// The system named on the command line: `si` or `us`.
    pub fn named(name: &str) -> Option<UnitSystem> {
        match name {
            "si" | "SI" => Some(UnitSystem::Si),
            "us" | "US" => Some(UnitSystem::Us),
            _ => None,
        }
    }

    /// One `unit` in this system's unit of its dimension, exactly: a rational and a power of
    /// π (`in`: 1/12 in U.S. customary units, 127/5000 in SI; `rpm`: π/30 in both). None past
    /// the bounds of exact numbers.
    pub fn exact_of_one(self, unit: &NamedUnit) -> Option<(Q, i64)> {
        let (q, pi) = unit.exact_factor()?;
        let (base_q, base_pi) = self.unit(unit.unit().dimension, false).exact_factor()?;
        Some((q.checked_div(&base_q)?, pi - base_pi))
    }

    /// [`exact_of_one`](Self::exact_of_one) as the nearest double: the factor that brings a
    /// number written in `unit` into this system, and divides a value of the system to show it
    /// in `unit`.
    pub fn of_one(self, unit: &NamedUnit) -> f64 {
        match self.exact_of_one(unit) {
            Some((q, pi)) => q.to_f64() * std::f64::consts::PI.powi(pi as i32),
            None => unit.unit().to_si / self.unit(unit.unit().dimension, false).unit().to_si,
        }
    }

    /// The unit a value of dimension `d` is shown in; `energy` when a moment's dimension is
    /// work (joules; foot-pounds).
    pub fn unit(self, d: Dimension, energy: bool) -> NamedUnit {
        let work = energy && d == Dimension::MOMENT;
        match self {
            UnitSystem::Si if work => NamedUnit::named("J"),
            UnitSystem::Si => NamedUnit::si(d),
            UnitSystem::Us if work => NamedUnit::of_names(&[("ft", 1), ("lb", 1)]),
            UnitSystem::Us => match US_NAMES.iter().find(|(named, _)| *named == d) {
                Some((_, names)) => NamedUnit::of_names(names),
                None => {
                    let powers: Vec<(&str, i8)> =
                        [("slug", d.mass), ("ft", d.length), ("s", d.time)]
                            .into_iter()
                            .filter(|(_, e)| *e != 0)
                            .collect();
                    NamedUnit::of_names(&powers)
                }
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> NamedUnit {
        NamedUnit::read(text).unwrap()
    }

    /// A number written in a unit comes into each system by the exact ratio of the units.
    #[test]
    fn one_unit_in_each_system() {
        let exact = |system: UnitSystem, unit: &str| system.exact_of_one(&read(unit)).unwrap();
        assert_eq!(exact(UnitSystem::Us, "in"), (Q::new(1, 12).unwrap(), 0));
        assert_eq!(exact(UnitSystem::Us, "mi/h"), (Q::new(22, 15).unwrap(), 0));
        assert_eq!(exact(UnitSystem::Us, "oz"), (Q::new(1, 16).unwrap(), 0));
        assert_eq!(exact(UnitSystem::Us, "lb*s^2/ft"), (Q::ONE, 0));
        assert_eq!(exact(UnitSystem::Us, "rpm"), (Q::new(1, 30).unwrap(), 1));
        assert_eq!(exact(UnitSystem::Si, "in"), (Q::new(127, 5000).unwrap(), 0));
        assert_eq!(exact(UnitSystem::Si, "km/h"), (Q::new(5, 18).unwrap(), 0));
        // 1 kg in slugs: 0.3048 / 4.4482216152605.
        let kg = UnitSystem::Us.of_one(&read("kg"));
        assert!((kg - 0.3048 / 4.448_221_615_260_5).abs() < 1e-16);
        assert_eq!(UnitSystem::Us.of_one(&read("ft")), 1.0);
    }

    #[test]
    fn the_system_of_the_givens() {
        let us = [read("lb"), read("ft"), read("rpm"), read("in")];
        assert_eq!(UnitSystem::of_units(&us), UnitSystem::Us);
        let mixed = [read("lb"), read("m")];
        assert_eq!(UnitSystem::of_units(&mixed), UnitSystem::Si);
        let neutral = [read("rpm"), read("deg")];
        assert_eq!(UnitSystem::of_units(&neutral), UnitSystem::Si);
    }

    /// Each U.S. unit is of the dimension it is named for, and its factor to SI is the
    /// product of the definitions (1 slug·ft² = 14.5939 kg × 0.3048² m²).
    #[test]
    fn us_units_have_their_dimensions_and_factors() {
        for (d, _) in US_NAMES {
            assert_eq!(UnitSystem::Us.unit(d, false).unit().dimension, d, "{d:?}");
        }
        let odd = Dimension::new(2, 1, -3);
        assert_eq!(UnitSystem::Us.unit(odd, false).unit().dimension, odd);
        let inertia = UnitSystem::Us.unit(Dimension::INERTIA, false);
        assert_eq!(inertia.to_string(), "slug·ft²");
        let slug = 4.4482216152605 / 0.3048;
        assert!((inertia.unit().to_si - slug * 0.3048 * 0.3048).abs() < 1e-12);
        assert_eq!(
            UnitSystem::Us.unit(Dimension::MOMENT, true).to_string(),
            "ft·lb"
        );
        assert_eq!(
            UnitSystem::Si.unit(Dimension::MOMENT, true).to_string(),
            "J"
        );
    }
}
