//! The vector and scalar products of written operands, `a × b` (also `cross(a, b)`) and
//! `dot(a, b)`:
//!
//! ```text
//! a × b = (a_y b_z − a_z b_y) i + (a_z b_x − a_x b_z) j + (a_x b_y − a_y b_x) k,
//! a · b = a_x b_x + a_y b_y + a_z b_z
//! ```
//!
//! Each operand must be a vector `a i + b j + c k` ([`components`]) or zero; a scalar is
//! refused at its text. `a × b × c` is `(a × b) × c`. The numbers of the components'
//! products are bounded in digits before they are formed.

use super::claim_vectors::is_vector;
use super::diagnostic::Diagnostic;
use super::lower::{Lowering, Node, Operation, Span};
use crate::algebra::vector::{components, unit_vectors};
use crate::algebra::{vector_products, Expr, Vector, Q};

/// A product of two vectors.
#[derive(Clone, Copy)]
enum VectorProduct {
    Cross,
    Dot,
}

impl VectorProduct {
    fn name(self) -> &'static str {
        match self {
            VectorProduct::Cross => "cross product",
            VectorProduct::Dot => "scalar product",
        }
    }
}

/// The most bits of the numerator or denominator of any term's number in `v`.
fn largest_number_bits(v: &Vector) -> u64 {
    v.iter()
        .flat_map(|c| c.terms())
        .map(|t| Q::product_bits([t.coefficient()]))
        .max()
        .unwrap_or(0)
}

/// `c_x i + c_y j + c_z k`.
fn from_components(c: &Vector) -> Expr {
    let [i, j, k] = unit_vectors();
    Expr::sum_of_products(&[(&c[0], &i), (&c[1], &j), (&c[2], &k)])
}

impl Lowering<'_> {
    /// `a × b × c ...`, left to right.
    pub(super) fn cross_chain(&mut self, operands: Vec<Node>) -> Result<Expr, Diagnostic> {
        let mut product: Option<(Expr, Span)> = None;
        for operand in operands {
            let span = operand.span;
            let value = self.lower(operand)?;
            product = Some(match product {
                None => (value, span),
                Some(left) => (self.cross(&left, &(value, span))?, (left.1 .0, span.1)),
            });
        }
        Ok(product.map(|(e, _)| e).unwrap_or_else(Expr::zero))
    }

    /// `a × b` of two lowered operands with the spans of their text.
    pub(super) fn cross(&self, a: &(Expr, Span), b: &(Expr, Span)) -> Result<Expr, Diagnostic> {
        let (u, v) = self.vector_operands(VectorProduct::Cross, a, b)?;
        Ok(from_components(&vector_products::cross(&u, &v)))
    }

    /// `a · b`, written `dot(a, b)`.
    pub(super) fn dot(&self, a: &(Expr, Span), b: &(Expr, Span)) -> Result<Expr, Diagnostic> {
        let (u, v) = self.vector_operands(VectorProduct::Dot, a, b)?;
        Ok(vector_products::dot(&u, &v))
    }

    /// The components of both operands, and the bound on the digits of their products.
    fn vector_operands(
        &self,
        product: VectorProduct,
        a: &(Expr, Span),
        b: &(Expr, Span),
    ) -> Result<(Vector, Vector), Diagnostic> {
        let u = self.vector_operand(product, a)?;
        let v = self.vector_operand(product, b)?;
        let bits = largest_number_bits(&u).saturating_add(largest_number_bits(&v));
        self.check_product_bits(bits, (a.1 .0, b.1 .1))?;
        Ok((u, v))
    }

    /// The components of one operand: zero is the zero vector, a scalar is refused.
    fn vector_operand(
        &self,
        product: VectorProduct,
        (value, span): &(Expr, Span),
    ) -> Result<Vector, Diagnostic> {
        if value.is_zero() {
            return Ok(Vector::from_element(Expr::zero()));
        }
        if !is_vector(value) {
            let message = format!(
                "the {} needs two vectors; {} is a scalar",
                product.name(),
                self.written(*span)
            );
            return Err(self.error_at(*span, message).with_help(
                "write a vector with i, j and k, like (a*i + b*j); a scalar multiplies outside: m (a × b)",
            ));
        }
        components(value).map_err(|err| self.algebra_error(err, Operation::Product, *span))
    }
}
