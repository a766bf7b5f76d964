//! Parsers of user input, with located diagnostics.

pub mod claim;
pub mod diagnostic;
pub mod expression;
pub mod limits;
pub mod long_numbers;
mod lower;

pub use diagnostic::Diagnostic;
pub use expression::{parse_equation, parse_expression, parse_statement, Equation, Statement};
pub use lower::DEGREE;
