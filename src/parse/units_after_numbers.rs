//! A unit written after a number: in a product, a name that directly follows a number
//! (`300 mm`, `-2 kN*j`, `1200 rpm*k`) or such a unit (`2 m/s^2`: `s` follows `m`), as a
//! factor or a divisor, alone or to a whole power, is what the caller's
//! [`Units`](super::lower::Units) gives for it, when it gives something. Anywhere else, and
//! for a name the caller does not read as a unit (one the scene declares), the name is a
//! symbol. The parser knows no unit itself: the scene decides which names are units and what
//! each stands for.

use super::diagnostic::Diagnostic;
use super::lower::{Ast, Follows, Lowering, Node, Operation};
use crate::algebra::Expr;

/// Whether a factor as written is a number (`300`, or `-300` with its minus).
pub(super) fn is_number(node: &Node) -> bool {
    match &node.ast {
        Ast::Number(_) => true,
        Ast::Negate(inner) => matches!(inner.ast, Ast::Number(_)),
        _ => false,
    }
}

impl Lowering<'_> {
    /// The value of the factor `node`, which follows a number or a unit in a product, when
    /// it is a unit (`mm`, `s^2`: a number as its exponent), inverted when it is written
    /// after `/`; otherwise the node back, to be lowered as any factor.
    pub(super) fn unit_after_number(
        &mut self,
        node: Node,
        divide: bool,
        follows: Follows,
    ) -> Result<Result<Expr, Node>, Diagnostic> {
        let Some(units) = self.units else {
            return Ok(Err(node));
        };
        let span = node.span;
        let unit = match &node.ast {
            Ast::Symbol(name) => units(name, follows),
            Ast::Power(base, exponent) if is_number(exponent) => match &base.ast {
                Ast::Symbol(name) => units(name, follows),
                _ => None,
            },
            _ => None,
        };
        let Some(unit) = unit else {
            return Ok(Err(node));
        };
        let power = match node.ast {
            Ast::Power(_, exponent) => {
                let exponent = self.lower(*exponent)?;
                unit.checked_pow(&exponent)
                    .map_err(|err| self.algebra_error(err, Operation::Power, span))?
            }
            _ => unit,
        };
        if !divide {
            return Ok(Ok(power));
        }
        power
            .checked_pow(&Expr::int(-1))
            .map(Ok)
            .map_err(|err| self.algebra_error(err, Operation::Division, span))
    }
}
