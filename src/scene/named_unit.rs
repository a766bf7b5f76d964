//! A unit by its names: units of the table (`units.rs`), each with a whole power, in the
//! order written — `N·m`, `m/s²`, `kg·m²/s`, `lb·ft`, or none for a pure number. It is read
//! once, where the scene is read (`unit_text.rs`), or named for a dimension in SI
//! ([`NamedUnit::si`]); every page prints it from its names, never from text.

use super::unit_text::{unit_powers, UnitTextError};
use super::units::{exact_factor, table_name, unit_named, Dimension, Unit};
use crate::algebra::Q;
use std::fmt;

/// A unit as a product of named units with whole powers.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct NamedUnit {
    powers: Vec<(&'static str, i8)>,
}

/// Names with the magnitudes of their powers.
type Names = Vec<(&'static str, u8)>;

/// No unit: a pure number.
pub static NO_UNIT: NamedUnit = NamedUnit { powers: Vec::new() };

/// Each dimension a result is commonly in, with the SI unit it is given in.
const SI_NAMES: [(Dimension, &[(&str, i8)]); 13] = [
    (Dimension::NONE, &[]),
    (Dimension::MASS, &[("kg", 1)]),
    (Dimension::LENGTH, &[("m", 1)]),
    (Dimension::TIME, &[("s", 1)]),
    (Dimension::FORCE, &[("N", 1)]),
    (Dimension::MOMENT, &[("N", 1), ("m", 1)]),
    (Dimension::ANGULAR_VELOCITY, &[("rad", 1), ("s", -1)]),
    (Dimension::ANGULAR_ACCELERATION, &[("rad", 1), ("s", -2)]),
    (Dimension::VELOCITY, &[("m", 1), ("s", -1)]),
    (Dimension::ACCELERATION, &[("m", 1), ("s", -2)]),
    (Dimension::INERTIA, &[("kg", 1), ("m", 2)]),
    (Dimension::new(1, 1, -1), &[("N", 1), ("s", 1)]),
    (Dimension::new(1, 2, -1), &[("kg", 1), ("m", 2), ("s", -1)]),
];

impl NamedUnit {
    /// The unit `text` names (`N*m`, `m/s^2`, `kg·m²`, `°`), or why it does not read: a
    /// name not in the table, or exponents of its dimension past ±127.
    pub fn read(text: &str) -> Result<NamedUnit, UnitTextError> {
        let mut powers = Vec::new();
        let mut dimension = Dimension::NONE;
        for p in unit_powers(text)? {
            let too_large = || UnitTextError {
                span: p.span,
                message: "the unit's exponents pass ±127".into(),
                help: "write a unit of a physical quantity (m/s^2, kg·m²)".into(),
            };
            let exponent = i8::try_from(p.exponent).map_err(|_| too_large())?;
            let name = table_name(p.name).expect("unit_powers reads only the table's names");
            let named = unit_named(name).expect("a name of the table");
            dimension = named
                .dimension
                .rational_power(&Q::from(i64::from(exponent)))
                .and_then(|d| dimension.checked_times(d))
                .ok_or_else(too_large)?;
            powers.push((name, exponent));
        }
        Ok(NamedUnit { powers })
    }

    /// One unit of the table by its name (`J`, `deg`).
    pub fn named(name: &str) -> NamedUnit {
        let name = table_name(name).expect("a unit of the table, named by the program");
        NamedUnit {
            powers: vec![(name, 1)],
        }
    }

    /// The SI unit a result of dimension `d` is given in: a named one (`N·m`, `rad/s²`,
    /// `kg·m²`), else kilograms, metres and seconds with their powers.
    pub fn si(d: Dimension) -> NamedUnit {
        if let Some((_, names)) = SI_NAMES.iter().find(|(named, _)| *named == d) {
            let powers = names.to_vec();
            return NamedUnit { powers };
        }
        let powers = [("kg", d.mass), ("m", d.length), ("s", d.time)]
            .into_iter()
            .filter(|(_, e)| *e != 0)
            .collect();
        NamedUnit { powers }
    }

    /// Names of the table with their powers, as a unit system names a dimension's unit.
    pub(super) fn of_names(powers: &[(&'static str, i8)]) -> NamedUnit {
        debug_assert!(powers.iter().all(|(n, _)| table_name(n).is_some()));
        NamedUnit {
            powers: powers.to_vec(),
        }
    }

    /// The names of the units it is made of (`lb`, `ft` of `lb·ft`).
    pub fn names(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.powers.iter().map(|(n, _)| *n)
    }

    /// No unit: a pure number.
    pub fn is_none(&self) -> bool {
        self.powers.is_empty()
    }

    /// The degree of angle, which every notation sets as a sign after the number (`60°`).
    pub fn is_degrees(&self) -> bool {
        self.powers == [("deg", 1)]
    }

    /// Its dimension and its factor to SI.
    pub fn unit(&self) -> Unit {
        self.powers.iter().fold(
            Unit {
                dimension: Dimension::NONE,
                to_si: 1.0,
            },
            |unit, (name, exponent)| {
                let named = unit_named(name).expect("a NamedUnit holds only the table's names");
                Unit {
                    dimension: unit.dimension.times(named.dimension.power(*exponent)),
                    to_si: unit.to_si * named.to_si.powi(i32::from(*exponent)),
                }
            },
        )
    }

    /// Its exact factor to SI, as a rational and a power of π (`deg`: 1/180 and π); none
    /// when the rational passes the bounds of exact numbers.
    pub fn exact_factor(&self) -> Option<(Q, i64)> {
        let (mut factor, mut pi_power) = (Q::ONE, 0i64);
        for (name, exponent) in &self.powers {
            let unit = exact_factor(name)?;
            let q = Q::new(unit.numerator, unit.denominator)?;
            factor = &factor * &q.checked_pow(i64::from(*exponent))?;
            pi_power += i64::from(unit.pi_power) * i64::from(*exponent);
        }
        Some((factor, pi_power))
    }

    /// The names over `/` and under it, each with its power's magnitude: `kg·m²/s` is
    /// `([kg, m²], [s])`.
    fn fraction(&self) -> (Names, Names) {
        let part = |sign: fn(i8) -> bool| {
            self.powers
                .iter()
                .filter(|(_, e)| sign(*e))
                .map(|(n, e)| (*n, e.unsigned_abs()))
                .collect()
        };
        (part(|e| e > 0), part(|e| e < 0))
    }
}

/// How a notation writes a unit: a name, a name raised to a power, and the marks of a
/// product and of a quotient.
pub struct UnitMarks {
    pub name: fn(&str) -> String,
    pub power: fn(String, i64) -> String,
    pub times: &'static str,
    pub over: &'static str,
}

impl NamedUnit {
    /// The unit in a notation's `marks`: `N·m`, `m/s²`, `kg·m²/s`; with nothing over the
    /// bar or more than one name under it, its powers negative, `s⁻¹`, `kg·m⁻¹·s⁻²`.
    pub fn written_with(&self, marks: &UnitMarks) -> String {
        let named = |name: &str, e: i64| match e {
            1 => (marks.name)(name),
            e => (marks.power)((marks.name)(name), e),
        };
        let joined = |part: &[(&str, u8)]| {
            let names: Vec<String> = part.iter().map(|(n, e)| named(n, i64::from(*e))).collect();
            names.join(marks.times)
        };
        let (over, under) = self.fraction();
        match (over.is_empty(), under.len()) {
            (_, 0) => joined(&over),
            (false, 1) => format!("{}{}{}", joined(&over), marks.over, joined(&under)),
            (_, _) => {
                let powers: Vec<String> = self
                    .powers
                    .iter()
                    .map(|(n, e)| named(n, i64::from(*e)))
                    .collect();
                powers.join(marks.times)
            }
        }
    }
}

/// A power in Unicode superscripts: `²`, `⁻¹`.
fn superscript(exponent: i64) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let digits = exponent.unsigned_abs().to_string();
    let mut out = String::new();
    if exponent < 0 {
        out.push('⁻');
    }
    out.extend(digits.bytes().map(|d| DIGITS[usize::from(d - b'0')]));
    out
}

/// In text: `N·m`, `m/s²`, `kg·m²/s`, `kg·m⁻¹·s⁻²`, `s⁻¹`, `deg`.
impl fmt::Display for NamedUnit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.written_with(&UnitMarks {
            name: str::to_string,
            power: |name, e| name + &superscript(e),
            times: "·",
            over: "/",
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::NamedUnit;
    use crate::scene::units::Dimension;

    #[test]
    fn read_once_and_printed_from_the_names() {
        let printed = |text: &str| NamedUnit::read(text).unwrap().to_string();
        assert_eq!(printed("N*m"), "N·m");
        assert_eq!(printed("N m"), "N·m");
        assert_eq!(printed("m/s^2"), "m/s²");
        assert_eq!(printed("kg·m²/s"), "kg·m²/s");
        assert_eq!(printed("kg/m/s^2"), "kg·m⁻¹·s⁻²");
        assert_eq!(printed("°"), "deg");
        assert!(NamedUnit::read("deg").unwrap().is_degrees());
        assert!(NamedUnit::read("furlong").is_err());
    }

    #[test]
    fn si_units_by_dimension() {
        assert_eq!(NamedUnit::si(Dimension::MOMENT).to_string(), "N·m");
        assert_eq!(
            NamedUnit::si(Dimension::ANGULAR_ACCELERATION).to_string(),
            "rad/s²"
        );
        assert_eq!(NamedUnit::si(Dimension::INERTIA).to_string(), "kg·m²");
        assert_eq!(NamedUnit::si(Dimension::new(1, 3, 0)).to_string(), "kg·m³");
        assert_eq!(NamedUnit::si(Dimension::new(0, 0, -3)).to_string(), "s⁻³");
        assert!(NamedUnit::si(Dimension::NONE).is_none());
    }

    #[test]
    fn read_as_people_write_them() {
        let unit = |text: &str| NamedUnit::read(text).unwrap().unit();
        let moment = unit("N·m");
        assert_eq!(moment.dimension, Dimension::MOMENT);
        for text in ["N*m", "N m", "N.m", "N ⋅ m", "J"] {
            assert_eq!(unit(text), moment, "{text}");
        }
        assert_eq!(unit("kg m²"), unit("kg·m^2"));
        assert_eq!(unit("kg·m^2").dimension, Dimension::INERTIA);
        assert_eq!(unit("m s⁻²"), unit("m/s^2"));
        assert_eq!(unit("m/s^2").dimension, Dimension::ACCELERATION);
        assert_eq!(unit("°"), unit("deg"));
        let e = NamedUnit::read("m^100*m^100").unwrap_err();
        assert_eq!(e.message, "the unit's exponents pass ±127");
    }

    #[test]
    fn dimension_and_factor() {
        let lb_ft = NamedUnit::read("lb*ft").unwrap().unit();
        assert_eq!(lb_ft.dimension, Dimension::MOMENT);
        assert!((lb_ft.to_si - 1.355_817_948_331_400_4).abs() < 1e-12);
        let (q, pi) = NamedUnit::read("deg/s").unwrap().exact_factor().unwrap();
        assert_eq!((q.to_string(), pi), ("1/180".to_string(), 1));
    }
}
