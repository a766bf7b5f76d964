//! Mathematics in its units: read as written (a unit after a number is its marker,
//! `units_in_math.rs`; finite with the givens' values), its dimension checked, then
//! brought into the scene's unit system exactly (`unit_system.rs`); and the help for a dimension error that a declared name which
//! is also a unit explains (`given m = 2 kg` makes `2 m` twice that mass, not two metres).

use super::super::units::{unit_named, Dimension};
use super::super::units_in_math;
use super::{span, Reader, Rule};
use crate::algebra::Expr;
use crate::parse::Diagnostic;
use pest::iterators::Pair;

impl Reader<'_> {
    /// The mathematics `p`, in the dimension `want`, in the scene's unit system.
    pub(super) fn quantity(&self, p: &Pair<Rule>, want: Dimension) -> Result<Expr, Diagnostic> {
        let e = self.math(p)?;
        self.expect_dimension(&e, want, span(p))?;
        self.in_units(&e, span(p))
    }

    /// `e` with its units' exact factors into the scene's unit system.
    pub(super) fn in_units(&self, e: &Expr, at: (usize, usize)) -> Result<Expr, Diagnostic> {
        units_in_math::in_system(e, self.scene.unit_system).map_err(|err| {
            self.error(at, err.to_string())
                .with_help("write the number in another unit")
        })
    }

    /// `help`, and when `e` holds a declared name that is also a unit, that it is read as
    /// the declared quantity there; else when it holds a unit after a number, that it is
    /// read as the unit (`2 g` is two grams unless the scene declares `g`).
    pub(super) fn given_named_as_unit(&self, e: &Expr, help: &str) -> String {
        let symbols = e.symbols();
        let declared_unit = symbols
            .iter()
            .find(|s| unit_named(s.name()).is_some() && self.dims.contains_key(s));
        let unit = symbols.iter().find_map(|s| units_in_math::unit_of(*s));
        match (declared_unit, unit) {
            (None, None) => help.to_string(),
            (None, Some(name)) => format!(
                "{help}; '{name}' after a number is the unit {name} here: to mean a quantity, \
                 declare it ('given {name} = ...')"
            ),
            (Some(s), _) => {
                let name = s.name();
                format!(
                    "{help}; '{name}' here is the declared {name}, not the unit {name}: a name \
                     the scene declares is never read as a unit (rename it, {name}_1 say, to \
                     write the unit)"
                )
            }
        }
    }
}
