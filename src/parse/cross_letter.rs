//! In a claim, the letter `x` written as a factor between two vectors is the cross
//! product, as people write it by hand: `(w1 i + w2 j) x (L i - r j)`.
//!
//! A product's factors are split at each letter `x` that stands between two factors (not
//! after a `/`, and neither neighbour itself an `x`). The runs between them are formed
//! left to right, binding tighter than the `x`, as with `×`: at each letter, when the
//! product so far and the next run are both vectors, the letter is `×`; otherwise it is
//! the name `x`, a factor like any other (where reading it as `×` gives a meaning, reading
//! it as a factor would multiply two vectors, which a claim refuses). An expression
//! (`parse_expression`) never reads `x` this way.

use super::claim_vectors::{is_vector, VectorFactors};
use super::diagnostic::Diagnostic;
use super::lower::{Ast, Lowering, Node, Span};
use crate::algebra::{Expr, Q};

/// The letter read as the cross product.
const LETTER: &str = "x";

/// Whether a factor is the letter `x`, not divided.
fn is_letter((divide, node): &(bool, Node)) -> bool {
    !divide && matches!(&node.ast, Ast::Symbol(name) if name == LETTER)
}

/// Whether factor `at` is a letter `x` that may be the cross product: it has a factor on
/// each side, the right one not divided, and neither is a letter `x`.
fn is_cross_letter(factors: &[(bool, Node)], at: usize) -> bool {
    match (at.checked_sub(1).map(|b| &factors[b]), factors.get(at + 1)) {
        (Some(before), Some(after)) => {
            is_letter(&factors[at]) && !is_letter(before) && !is_letter(after) && !after.0
        }
        _ => false,
    }
}

/// Whether any factor of the product may be the cross product.
pub(super) fn has_cross_letter(factors: &[(bool, Node)]) -> bool {
    (1..factors.len().saturating_sub(1)).any(|at| is_cross_letter(factors, at))
}

/// The span from the first factor's text to the last's.
fn span_of(run: &[(bool, Node)]) -> Span {
    match (run.first(), run.last()) {
        (Some(first), Some(last)) => (first.1.span.0, last.1.span.1),
        _ => (0, 0),
    }
}

impl Lowering<'_> {
    /// A claim's product in which some letter `x` may be the cross product.
    pub(super) fn product_with_cross_letters(
        &mut self,
        factors: Vec<(bool, Node)>,
    ) -> Result<Expr, Diagnostic> {
        let cross_letters: Vec<usize> = (0..factors.len())
            .filter(|&at| is_cross_letter(&factors, at))
            .collect();
        let mut runs: Vec<Vec<(bool, Node)>> = vec![Vec::new()];
        let mut letters: Vec<Node> = Vec::new();
        for (at, factor) in factors.into_iter().enumerate() {
            if cross_letters.binary_search(&at).is_ok() {
                letters.push(factor.1);
                runs.push(Vec::new());
            } else if let Some(run) = runs.last_mut() {
                run.push(factor);
            }
        }
        let mut runs = runs.into_iter();
        let mut left = self.run(runs.next().unwrap_or_default())?;
        for (letter, run) in letters.into_iter().zip(runs) {
            let right = self.run(run)?;
            let whole = (left.1 .0, right.1 .1);
            let value = if is_vector(&left.0) && is_vector(&right.0) {
                self.cross(&left, &right)?
            } else {
                let span = letter.span;
                let x = (self.lower(letter)?, span);
                self.three_factors([left, x, right], whole)?
            };
            left = (value, whole);
        }
        Ok(left.0)
    }

    /// One run of factors between letters, as a product, with its span.
    fn run(&mut self, run: Vec<(bool, Node)>) -> Result<(Expr, Span), Diagnostic> {
        let span = span_of(&run);
        let value = self.lower(Node {
            ast: Ast::Product(run),
            span,
        })?;
        Ok((value, span))
    }

    /// The product of the product so far, the name `x` and the next run: numbers bounded,
    /// at most one vector.
    fn three_factors(&self, factors: [(Expr, Span); 3], whole: Span) -> Result<Expr, Diagnostic> {
        let bits = Q::product_bits(factors.iter().map(|(e, _)| e.coefficient()));
        self.check_product_bits(bits, whole)?;
        let mut vectors = VectorFactors::default();
        for factor in &factors {
            vectors.note(self, factor.1, std::slice::from_ref(factor))?;
        }
        Ok(Expr::mul_all(factors.into_iter().map(|(e, _)| e)))
    }
}
