//! Parsers of user input, with located diagnostics.

pub mod as_written;
pub mod claim;
mod claim_vectors;
mod cross_letter;
mod cross_product;
pub mod diagnostic;
pub mod expression;
pub mod limits;
pub mod long_numbers;
mod lower;
mod names;
mod units_after_numbers;

pub use claim::{parse_claim, parse_claim_with_units, ClaimSyntax};
pub use diagnostic::Diagnostic;
pub use expression::{
    parse_equation, parse_expression, parse_expression_with_units, parse_statement, Equation,
    Statement,
};
pub use lower::{Follows, Units, DEGREE};
