//! A derived value made up to the dimension of the quantity it is: where a number written
//! with its unit in the scene (`at (150 mm, 0, 0)`) is a plain number in the scene's units
//! (3/20), a value's dimension read from its symbols is not the quantity's, and unit markers
//! of factor one (`[kg]`, `[m]`, `[s]`; `[slug]`, `[ft]`, `[s]` in U.S. units) make it up,
//! sum by sum where the hidden lengths differ from term to term. The markers are gone when
//! the verdict takes the sides in the scene's units; meanwhile a claim's terms are judged as
//! the quantities they name.

use super::Context;
use crate::algebra::{Expr, View};
use crate::scene::model::Quantity;
use crate::scene::units::{dimension_with, Dimension};
use crate::scene::units_in_math::{marker, marker_dimension};
use crate::scene::Value;

impl Context {
    /// A scalar's or a vector's components as `quantity`'s dimension ([`Context::in_dimension`]);
    /// other values as they are.
    pub(super) fn value_in_dimension(&self, value: Value, quantity: Quantity) -> Value {
        let dimension = quantity.dimension(&self.dimensions);
        match value {
            Value::Scalar(e) => Value::Scalar(self.in_dimension(e, dimension)),
            Value::Vector(v) => Value::Vector(v.map(|e| self.in_dimension(e, dimension))),
            other => other,
        }
    }

    /// `value` as a quantity of `dimension` (the module documentation): as it is when it
    /// is one already, else with the markers that make it up, as a whole when its terms
    /// agree, sum by sum when they do not.
    pub(super) fn in_dimension(&self, value: Expr, dimension: Option<Dimension>) -> Expr {
        let Some(wanted) = dimension else {
            return value;
        };
        if value.is_zero() {
            return value;
        }
        match self.dimension_of(&value) {
            Ok(has) if has == wanted => value,
            Ok(has) => value * self.markers(wanted, has),
            // Hidden lengths of different powers in different terms (`192 M W_1 g + 48 W_1
            // W_2 g` with 1/2 ft and 1/4 ft put in): each term made up apart.
            Err(_) => self.homogeneous(&value, wanted).unwrap_or(value),
        }
    }

    /// `value` in `wanted`: each sum in it, inside out, with every term made up to its
    /// first term's dimension and a function's argument and a root's base to none, by unit
    /// markers of factor one (any choice keeps the value), then the whole to `wanted`; none
    /// where a part has no dimension at all.
    fn homogeneous(&self, value: &Expr, wanted: Dimension) -> Option<Expr> {
        let made_up = self.made_up(value)?;
        let has = self.dimension_of(&made_up).ok()?;
        Some(made_up * self.markers(wanted, has))
    }

    /// `e` with each of its sums' terms in the dimension of the first ([`Context::homogeneous`]).
    fn made_up(&self, e: &Expr) -> Option<Expr> {
        let each = |xs: &[Expr]| {
            xs.iter()
                .map(|x| self.made_up(x))
                .collect::<Option<Vec<_>>>()
        };
        let to = |x: Expr, wanted: Dimension| -> Option<Expr> {
            let has = self.dimension_of(&x).ok()?;
            Some(x * self.markers(wanted, has))
        };
        Some(match e.view() {
            View::Num(_) | View::Sym(_) => e.clone(),
            View::Add(terms) => {
                let terms = each(terms)?;
                let first = self.dimension_of(terms.first()?).ok()?;
                let marked = terms.into_iter().map(|t| to(t, first));
                Expr::add_all(marked.collect::<Option<Vec<_>>>()?)
            }
            View::Mul(factors) => Expr::mul_all(each(factors)?),
            // A root's base is made a pure number: its dimension need be no square.
            View::Pow(base, exponent) if exponent.as_num().is_some_and(|q| !q.is_integer()) => {
                to(self.made_up(base)?, Dimension::NONE)?
                    .checked_pow(exponent)
                    .ok()?
            }
            View::Pow(base, exponent) => self.made_up(base)?.checked_pow(exponent).ok()?,
            View::Func(f, argument) => f.apply(to(self.made_up(argument)?, Dimension::NONE)?),
        })
    }

    /// The unit markers (of the system's base units) that make `has` up to `wanted`.
    fn markers(&self, wanted: Dimension, has: Dimension) -> Expr {
        // The markers of the system's base units (slug, ft, s in U.S. units), of factor one.
        let [mass, length, time] = self.unit_system.base_units();
        let missing = [
            (mass, wanted.mass - has.mass),
            (length, wanted.length - has.length),
            (time, wanted.time - has.time),
        ];
        let markers = missing
            .iter()
            .filter(|(_, power)| *power != 0)
            .filter_map(|(unit, power)| Some(marker(unit)?.powi(i64::from(*power))));
        Expr::mul_all(markers)
    }

    /// The dimension of an expression of this context's symbols and unit markers.
    pub(super) fn dimension_of(
        &self,
        e: &Expr,
    ) -> Result<Dimension, crate::scene::units::DimensionError> {
        dimension_with(e, &|s| {
            self.dimensions
                .get(&s)
                .copied()
                .or_else(|| marker_dimension(s))
        })
    }
}
