//! In a claim, every value is a scalar or a vector `a i + b j + c k` whose components are
//! scalars, so that its components are well defined and the two sides can be compared:
//!
//! - a product has at most one vector factor (`i j` and `(a i)(b j)` are refused: the
//!   user means `×`, `cross(a, b)` or `dot(a, b)`);
//! - a sum adds vectors to vectors and scalars to scalars (`a i + b` is refused at `b`);
//! - nothing divides by a vector, and no function takes a vector (a power of one is
//!   refused for every expression, in [`lower`](super::lower)).
//!
//! Each refusal points at the text written and quotes it.

use super::diagnostic::Diagnostic;
use super::lower::{Lowering, Span};
use crate::algebra::{Expr, Role};

/// Whether `e` is written with a unit vector `i`, `j` or `k` (after names are resolved).
pub(super) fn is_vector(e: &Expr) -> bool {
    e.has_symbol_where(&|s| s.role() == Role::UnitVector)
}

/// The help of every refusal of a product of vectors.
const WRITE_A_VECTOR_PRODUCT: &str =
    "write × or cross(a, b) for the cross product, dot(a, b) for the scalar product";

/// The written factors of one product seen so far that hold a vector: the first one's span.
#[derive(Default)]
pub(super) struct VectorFactors {
    first: Option<Span>,
}

impl VectorFactors {
    /// Notes the written factor at `span`, whose gathered factors are `run`: a second
    /// vector factor (or two inside this one) is refused, quoting both.
    pub(super) fn note(
        &mut self,
        lowering: &Lowering,
        span: Span,
        run: &[(Expr, Span)],
    ) -> Result<(), Diagnostic> {
        let vectors = run.iter().filter(|(e, _)| is_vector(e)).count();
        let refused = match (vectors, self.first) {
            (0, _) => None,
            (1, None) => {
                self.first = Some(span);
                None
            }
            (1, Some(first)) => Some((first.0, span.1)),
            _ => Some(span),
        };
        match refused {
            None => Ok(()),
            Some(product) => Err(lowering
                .error_at(
                    product,
                    format!(
                        "a product of two vectors, {}, has no meaning",
                        lowering.written(product)
                    ),
                )
                .with_help(WRITE_A_VECTOR_PRODUCT)),
        }
    }
}

/// Refuses a sum that adds a nonzero scalar to a vector, at the first such scalar term.
pub(super) fn check_sum(lowering: &Lowering, terms: &[(Expr, Span)]) -> Result<(), Diagnostic> {
    let Some((_, vector)) = terms.iter().find(|(e, _)| is_vector(e)) else {
        return Ok(());
    };
    match terms.iter().find(|(e, _)| !e.is_zero() && !is_vector(e)) {
        None => Ok(()),
        Some((_, scalar)) => Err(lowering
            .error_at(
                *scalar,
                format!(
                    "the scalar {} is added to the vector {}",
                    lowering.written(*scalar),
                    lowering.written(*vector)
                ),
            )
            .with_help(
                "every term of a vector has i, j or k; write a scalar's direction, like a*i",
            )),
    }
}

/// A divisor that is a vector, refused where it is written.
pub(super) fn division_by_a_vector(lowering: &Lowering, span: Span) -> Diagnostic {
    lowering
        .error_at(
            span,
            format!(
                "dividing by a vector, {}, has no meaning",
                lowering.written(span)
            ),
        )
        .with_help("divide by a scalar; a vector has no inverse")
}

/// `name(v)` of a vector `v`, refused at the call.
pub(super) fn function_of_a_vector(
    lowering: &Lowering,
    name: &str,
    call: Span,
    argument: Span,
) -> Diagnostic {
    lowering
        .error_at(
            call,
            format!(
                "{name} of a vector, {}, has no meaning",
                lowering.written(argument)
            ),
        )
        .with_help(format!(
            "{name} takes a scalar; for a vector's magnitude write sqrt(dot(v, v))"
        ))
}
