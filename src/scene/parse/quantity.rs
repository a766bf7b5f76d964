//! Mathematics in its units: read as written (a unit after a number is its marker,
//! `units_in_math.rs`), its dimension checked, then brought to SI exactly and checked finite
//! with the givens' values; and the help for a dimension error that a declared name which
//! is also a unit explains (`given m = 2 kg` makes `2 m` twice that mass, not two metres).

use super::super::units::{unit_named, Dimension};
use super::super::units_in_math;
use super::{span, Reader, Rule};
use crate::algebra::Expr;
use crate::parse::Diagnostic;
use pest::iterators::Pair;

impl Reader<'_> {
    /// The mathematics `p`, in the dimension `want`, in SI.
    pub(super) fn quantity(&self, p: &Pair<Rule>, want: Dimension) -> Result<Expr, Diagnostic> {
        let e = self.math(p)?;
        self.expect_dimension(&e, want, span(p))?;
        self.in_si(&e, span(p))
    }

    /// `e` (its dimension checked) with its units' exact factors to SI, finite with the
    /// givens' values.
    pub(super) fn in_si(&self, e: &Expr, at: (usize, usize)) -> Result<Expr, Diagnostic> {
        let si = units_in_math::in_si(e).map_err(|err| {
            self.error(at, err.to_string())
                .with_help("write the number in another unit")
        })?;
        self.finite_with_values(&si, at)?;
        Ok(si)
    }

    /// `help`, and when `e` holds a declared name that is also a unit, that it is read as
    /// the declared quantity there.
    pub(super) fn given_named_as_unit(&self, e: &Expr, help: &str) -> String {
        let declared_unit = e
            .symbols()
            .into_iter()
            .find(|s| unit_named(s.name()).is_some() && self.dims.contains_key(s));
        match declared_unit {
            None => help.to_string(),
            Some(s) => {
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
