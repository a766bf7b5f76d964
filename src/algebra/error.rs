//! Errors of the expression algebra.

use thiserror::Error;

/// Largest number of terms an expansion may produce before it is refused.
pub const MAX_EXPANDED_TERMS: usize = 100_000;

/// Largest expansion, in nodes (symbols, numbers, operations; a long number one more per
/// ten digits or so), before it is refused: 801 terms each holding `cos` of a sum of 3,654
/// terms print as 80 MB, 98,770 terms each holding a 1,200-digit number as 118 MB.
pub const MAX_EXPANDED_NODES: usize = 2_000_000;

/// Why an algebraic operation could not give an exact result.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum AlgebraError {
    #[error("division by zero")]
    DivisionByZero,
    #[error("{what} would have {size} terms, more than the limit of {limit}")]
    TooLarge {
        what: String,
        size: String,
        limit: usize,
    },
    #[error(
        "the expansion would be longer than {0} symbols and ten-digit groups of numbers (a long name counts once per sixteen letters); expand a part of it"
    )]
    ExpansionTooLong(usize),
    #[error("no value for the symbol {0}")]
    MissingValue(String),
    #[error("{expression} evaluates to {value}, which is not a finite number")]
    NotFinite { expression: String, value: String },
    #[error("cannot differentiate {0} with respect to time: its exponent depends on time")]
    TimeDependentExponent(String),
    #[error("{0}")]
    NotAVector(String),
    #[error("the exponent {0} is out of range: its power cannot be multiplied out")]
    ExponentOutOfRange(String),
    /// A function where it has no value: `tan` at an odd multiple of π/2.
    #[error("{0} is undefined (the tangent of an odd multiple of 90° is infinite)")]
    Undefined(String),
    /// An exact number past [`crate::algebra::MAX_DIGITS`] decimal digits.
    #[error("{what} would have about {digits} digits, more than the limit of {limit}")]
    NumberTooLarge {
        what: String,
        digits: u64,
        limit: u64,
    },
    /// Polynomial arithmetic (a gcd, a cancellation) past its bound on work.
    #[error(
        "{what} needs more than {limit} steps of polynomial arithmetic; simplify a part of it"
    )]
    TooMuchWork { what: String, limit: u64 },
    #[error("{0} is not a polynomial: it has a denominator")]
    NotAPolynomial(String),
    /// An input to a simplification larger than its bound, in nodes.
    #[error(
        "the expression is too large to simplify: more than {0} symbols, operations and ten-digit groups of numbers; simplify a part of it"
    )]
    TooLargeToSimplify(usize),
    /// The command's work budget ([`crate::algebra::work`]) spent: not passed over by a
    /// route, it ends the command.
    #[error("this input needs more than {limit} operations, the work allowed for its length")]
    OutOfWork { limit: u64 },
}

impl AlgebraError {
    /// Whether this is a refusal for size or work (a bound of the algebra), not a property
    /// of the expression's value: a shorter form may still be reached another way.
    pub fn is_beyond_bounds(&self) -> bool {
        matches!(
            self,
            AlgebraError::TooLarge { .. }
                | AlgebraError::ExpansionTooLong(_)
                | AlgebraError::ExponentOutOfRange(_)
                | AlgebraError::NumberTooLarge { .. }
                | AlgebraError::TooMuchWork { .. }
                | AlgebraError::TooLargeToSimplify(_)
        )
    }
}
