//! Units and dimensions: SI and US customary units in scene files, converted to SI, and the
//! dimension (mass, length, time) of every expression, so that `N + m` is an error.
//!
//! Exponents of dimensions are whole numbers. A rational power `b^(p/q)` multiplies its
//! base's exponents by `p/q` when each product is whole: `sqrt(a^2 + b^2)` of lengths is a
//! length, `1/sqrt(a^2 + b^2)` per metre, `(a^3)^(1/3)` a length; a power that would give a
//! fractional exponent (`sqrt(a)` of a length) is an error that says so.

use crate::algebra::{Expr, Func, Symbol, View, Q};
use std::collections::HashMap;
use std::fmt;

/// Exponents of mass, length and time.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Dimension {
    pub mass: i8,
    pub length: i8,
    pub time: i8,
}

impl Dimension {
    pub const NONE: Dimension = Dimension::new(0, 0, 0);
    pub const MASS: Dimension = Dimension::new(1, 0, 0);
    pub const LENGTH: Dimension = Dimension::new(0, 1, 0);
    pub const TIME: Dimension = Dimension::new(0, 0, 1);
    pub const FORCE: Dimension = Dimension::new(1, 1, -2);
    pub const MOMENT: Dimension = Dimension::new(1, 2, -2);
    pub const ANGULAR_VELOCITY: Dimension = Dimension::new(0, 0, -1);
    pub const ANGULAR_ACCELERATION: Dimension = Dimension::new(0, 0, -2);
    pub const VELOCITY: Dimension = Dimension::new(0, 1, -1);
    pub const ACCELERATION: Dimension = Dimension::new(0, 1, -2);
    pub const INERTIA: Dimension = Dimension::new(1, 2, 0);

    pub const fn new(mass: i8, length: i8, time: i8) -> Dimension {
        Dimension { mass, length, time }
    }

    pub fn times(self, o: Dimension) -> Dimension {
        Dimension::new(
            self.mass + o.mass,
            self.length + o.length,
            self.time + o.time,
        )
    }

    /// [`Dimension::times`], none when an exponent would pass ±127.
    pub fn checked_times(self, o: Dimension) -> Option<Dimension> {
        Some(Dimension::new(
            self.mass.checked_add(o.mass)?,
            self.length.checked_add(o.length)?,
            self.time.checked_add(o.time)?,
        ))
    }

    pub fn power(self, n: i8) -> Dimension {
        Dimension::new(self.mass * n, self.length * n, self.time * n)
    }

    /// The dimension to the power `p/q`: each exponent times `p/q`, when every one is a
    /// whole number (`(m²)^(1/2)` is m, `(m³)^(-1/3)` is 1/m); none when one is not
    /// (`m^(1/2)`), or is beyond the range of exponents.
    pub fn rational_power(self, exponent: &Q) -> Option<Dimension> {
        let (p, q) = (exponent.numer().to_i64()?, exponent.denom().to_i64()?);
        let scaled = |e: i8| -> Option<i8> {
            let product = i64::from(e).checked_mul(p)?;
            (product % q == 0).then(|| i8::try_from(product / q).ok())?
        };
        Some(Dimension::new(
            scaled(self.mass)?,
            scaled(self.length)?,
            scaled(self.time)?,
        ))
    }

    /// The SI unit a result of this dimension is given in, in text
    /// ([`super::named_unit::NamedUnit::si`]).
    pub fn si_unit(self) -> String {
        super::named_unit::NamedUnit::si(self).to_string()
    }
}

impl fmt::Display for Dimension {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let unit = self.si_unit();
        f.write_str(if unit.is_empty() { "no unit" } else { &unit })
    }
}

/// A unit: its dimension and the factor that converts a value in it to SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    pub dimension: Dimension,
    pub to_si: f64,
}

/// A unit's factor to SI, exactly: `numerator/denominator · π^pi_power`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ExactFactor {
    pub numerator: i64,
    pub denominator: i64,
    pub pi_power: i8,
}

/// Each unit a scene may name: its dimension and its exact factor to SI (the international
/// foot 0.3048 m, the mile 1609.344 m and pound-force 4.4482216152605 N by definition (`lb`
/// and `lbf` alike, the ounce-force `oz` a sixteenth, the `kip` a thousand), the slug
/// lbf·s²/ft; the hour 3600 s; the degree π/180, the revolution per minute 2π/60 = π/30).
const UNIT_TABLE: [(&str, Dimension, i64, i64, i8); 23] = [
    ("kg", Dimension::MASS, 1, 1, 0),
    ("g", Dimension::MASS, 1, 1_000, 0),
    (
        "slug",
        Dimension::MASS,
        44_482_216_152_605,
        3_048_000_000_000,
        0,
    ),
    ("m", Dimension::LENGTH, 1, 1, 0),
    ("mm", Dimension::LENGTH, 1, 1_000, 0),
    ("cm", Dimension::LENGTH, 1, 100, 0),
    ("km", Dimension::LENGTH, 1_000, 1, 0),
    ("mi", Dimension::LENGTH, 1_609_344, 1_000, 0),
    ("ft", Dimension::LENGTH, 3_048, 10_000, 0),
    ("in", Dimension::LENGTH, 254, 10_000, 0),
    ("s", Dimension::TIME, 1, 1, 0),
    ("min", Dimension::TIME, 60, 1, 0),
    ("h", Dimension::TIME, 3_600, 1, 0),
    ("N", Dimension::FORCE, 1, 1, 0),
    ("kN", Dimension::FORCE, 1_000, 1, 0),
    (
        "lb",
        Dimension::FORCE,
        44_482_216_152_605,
        10_000_000_000_000,
        0,
    ),
    (
        "lbf",
        Dimension::FORCE,
        44_482_216_152_605,
        10_000_000_000_000,
        0,
    ),
    (
        "oz",
        Dimension::FORCE,
        44_482_216_152_605,
        160_000_000_000_000,
        0,
    ),
    (
        "kip",
        Dimension::FORCE,
        44_482_216_152_605,
        10_000_000_000,
        0,
    ),
    ("J", Dimension::MOMENT, 1, 1, 0),
    ("rad", Dimension::NONE, 1, 1, 0),
    ("deg", Dimension::NONE, 1, 180, 1),
    ("rpm", Dimension::ANGULAR_VELOCITY, 1, 30, 1),
];

/// The exact factor to SI of the unit `name` (see [`UNIT_TABLE`]).
pub fn exact_factor(name: &str) -> Option<ExactFactor> {
    let (_, _, numerator, denominator, pi_power) = UNIT_TABLE.iter().find(|(n, ..)| *n == name)?;
    Some(ExactFactor {
        numerator: *numerator,
        denominator: *denominator,
        pi_power: *pi_power,
    })
}

/// The units a scene may name, their factor the nearest double to the exact one.
pub fn unit_named(name: &str) -> Option<Unit> {
    let (_, dimension, numerator, denominator, pi_power) =
        UNIT_TABLE.iter().find(|(n, ..)| *n == name)?;
    let pi = std::f64::consts::PI.powi(i32::from(*pi_power));
    Some(Unit {
        dimension: *dimension,
        to_si: *numerator as f64 * pi / *denominator as f64,
    })
}

/// The table's own spelling of the unit `name`, where the table has it.
pub fn table_name(name: &str) -> Option<&'static str> {
    UNIT_TABLE
        .iter()
        .find(|(n, ..)| *n == name)
        .map(|(n, ..)| *n)
}

/// The names accepted by [`unit_named`], for hints.
pub const UNIT_NAMES: &str =
    "kg, g, slug, m, mm, cm, km, ft, in, mi, s, min, h, N, kN, lb, lbf, oz, kip, J, rad, deg, rpm";

/// Dimensions of the symbols of a scene.
pub type Dimensions = HashMap<Symbol, Dimension>;

/// Why an expression has no consistent dimension.
#[derive(Debug, Clone, PartialEq)]
pub enum DimensionError {
    /// Two terms of a sum differ: `(term, its dimension, other term, its dimension)`.
    Mismatch(String, Dimension, String, Dimension),
    /// A symbol that the scene never declared.
    Undeclared(Symbol),
    /// A function of a quantity that has a dimension.
    FunctionOfDimensioned(String, Dimension),
    /// A power whose unit would have a fractional exponent (`sqrt(a)` of a length).
    FractionalPower(String, Dimension),
    /// A product or power whose unit's exponents pass ±127 (`m^200`): not judged.
    ExponentRange(String),
}

impl DimensionError {
    /// The error in words, each dimension named by `unit` (its SI unit in `Display`; a
    /// scene's unit system's in a report on it).
    pub fn in_words(&self, unit: &dyn Fn(Dimension) -> String) -> String {
        match self {
            DimensionError::Mismatch(a, da, b, db) => {
                format!(
                    "unit mismatch: cannot add {a} ({}) to {b} ({})",
                    unit(*da),
                    unit(*db)
                )
            }
            DimensionError::Undeclared(s) => format!("unknown symbol {}", s.name()),
            DimensionError::FunctionOfDimensioned(e, d) => format!(
                "the argument {e} of a function must have no unit, but it is in {}",
                unit(*d)
            ),
            DimensionError::ExponentRange(e) => {
                format!("the unit of {e} has an exponent beyond ±127")
            }
            DimensionError::FractionalPower(e, d) => format!(
                "{e} has no unit: its base is in {}, and this power of it would not be a \
                 whole power of a unit",
                unit(*d)
            ),
        }
    }
}

impl fmt::Display for DimensionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.in_words(&|d| d.to_string()))
    }
}

/// The dimension of `e`, from the dimensions of its symbols.
pub fn dimension_of(e: &Expr, dims: &Dimensions) -> Result<Dimension, DimensionError> {
    dimension_with(e, &|s| dims.get(&s).copied())
}

/// The dimension of `e`, each symbol's from `dimension_of_symbol` (none: the symbol is
/// [`DimensionError::Undeclared`]). A sum's terms share one dimension, a product's is the
/// product of its factors', a power's `b^(p/q)` is its base's times `p/q`, and a function's
/// argument has none.
pub fn dimension_with(
    e: &Expr,
    dimension_of_symbol: &dyn Fn(Symbol) -> Option<Dimension>,
) -> Result<Dimension, DimensionError> {
    let dimension = |e: &Expr| dimension_with(e, dimension_of_symbol);
    match e.view() {
        View::Num(_) => Ok(Dimension::NONE),
        View::Sym(s) => dimension_of_symbol(s).ok_or(DimensionError::Undeclared(s)),
        View::Add(terms) => {
            let first = dimension(&terms[0])?;
            for t in &terms[1..] {
                let d = dimension(t)?;
                if d != first {
                    return Err(DimensionError::Mismatch(
                        terms[0].to_string(),
                        first,
                        t.to_string(),
                        d,
                    ));
                }
            }
            Ok(first)
        }
        View::Mul(factors) => factors.iter().try_fold(Dimension::NONE, |acc, f| {
            acc.checked_times(dimension(f)?)
                .ok_or_else(|| DimensionError::ExponentRange(e.to_string()))
        }),
        View::Pow(b, x) => {
            let base = dimension(b)?;
            match x.as_num() {
                _ if base == Dimension::NONE => Ok(Dimension::NONE),
                Some(exponent) => base.rational_power(exponent).ok_or_else(|| {
                    // Whole exponents fail only by range; a fraction may also not divide.
                    if exponent.is_integer() {
                        DimensionError::ExponentRange(e.to_string())
                    } else {
                        DimensionError::FractionalPower(e.to_string(), base)
                    }
                }),
                None => Err(DimensionError::FunctionOfDimensioned(e.to_string(), base)),
            }
        }
        // |u| has the unit of u.
        View::Func(Func::Abs, arg) => dimension(arg),
        View::Func(_, arg) => {
            let d = dimension(arg)?;
            if d == Dimension::NONE {
                Ok(Dimension::NONE)
            } else {
                Err(DimensionError::FunctionOfDimensioned(arg.to_string(), d))
            }
        }
    }
}
