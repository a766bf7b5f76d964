//! The sign of an expression where it can be proved from the domains of its symbols; the
//! rules, each conservative (unknown when a part is unknown):
//!
//! - a number has its sign; a positive symbol is positive, any other symbol unknown;
//! - a sum whose terms are all ≥ 0 is ≥ 0, and > 0 when one of them is; likewise ≤ 0;
//! - a product's sign is the product of its factors' signs (> 0 only if every factor is
//!   strict);
//! - `bⁿ` for an even integer `n` is ≥ 0 (> 0 for a strict `b`, `b ≠ 0`); for an odd `n`
//!   it has the sign of `b`; for any other exponent it is > 0 (≥ 0) for `b > 0` (`b ≥ 0`);
//! - `|u|` is ≥ 0, and > 0 when `u` has a strict sign; `sin`, `cos`, `tan` are unknown.

use super::domain::{Domain, Domains};
use super::expr::{Expr, View};
use super::function::Func;

/// What is proved about the sign of an expression.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Sign {
    Positive,
    NonNegative,
    Negative,
    NonPositive,
    Unknown,
}

impl Sign {
    fn of_number(negative: bool, zero: bool) -> Sign {
        match (negative, zero) {
            (true, _) => Sign::Negative,
            (false, true) => Sign::NonNegative,
            (false, false) => Sign::Positive,
        }
    }

    /// Whether the sign is proved `≥ 0`.
    pub(crate) fn is_nonnegative(self) -> bool {
        matches!(self, Sign::Positive | Sign::NonNegative)
    }

    /// Whether the sign is proved `≤ 0`.
    pub(crate) fn is_nonpositive(self) -> bool {
        matches!(self, Sign::Negative | Sign::NonPositive)
    }

    fn is_strict(self) -> bool {
        matches!(self, Sign::Positive | Sign::Negative)
    }

    /// The sign of `x y` for `x` of this sign and `y` of `other`.
    fn times(self, other: Sign) -> Sign {
        if self == Sign::Unknown || other == Sign::Unknown {
            return Sign::Unknown;
        }
        let flipped = self.is_nonpositive() != other.is_nonpositive();
        let strict = self.is_strict() && other.is_strict();
        match (flipped, strict) {
            (false, true) => Sign::Positive,
            (false, false) => Sign::NonNegative,
            (true, true) => Sign::Negative,
            (true, false) => Sign::NonPositive,
        }
    }

    /// The sign of a sum of terms of this sign and `other`.
    fn plus(self, other: Sign) -> Sign {
        let strict = self.is_strict() || other.is_strict();
        if self.is_nonnegative() && other.is_nonnegative() {
            if strict {
                Sign::Positive
            } else {
                Sign::NonNegative
            }
        } else if self.is_nonpositive() && other.is_nonpositive() {
            if strict {
                Sign::Negative
            } else {
                Sign::NonPositive
            }
        } else {
            Sign::Unknown
        }
    }

    /// The sign of `bⁿ` for `b` of this sign and a numeric `n` (`n` an integer or not).
    fn power(self, integer: Option<i64>) -> Sign {
        match integer {
            Some(n) if n % 2 == 0 => {
                if self.is_strict() {
                    Sign::Positive
                } else {
                    Sign::NonNegative
                }
            }
            Some(_) => self,
            None if self.is_nonnegative() => self,
            None => Sign::Unknown,
        }
    }
}

impl Domains {
    /// `e > 0` or `e < 0` when proved by the rules of the module documentation (None for a
    /// sign not proved strict).
    pub fn strict_sign(&self, e: &Expr) -> Option<std::cmp::Ordering> {
        match self.sign(e) {
            Sign::Positive => Some(std::cmp::Ordering::Greater),
            Sign::Negative => Some(std::cmp::Ordering::Less),
            _ => None,
        }
    }

    /// The sign of `e` proved by the rules of the module documentation.
    pub(crate) fn sign(&self, e: &Expr) -> Sign {
        match e.view() {
            View::Num(q) => Sign::of_number(q.is_negative(), q.is_zero()),
            View::Sym(s) => match self.domain(s) {
                Domain::Positive => Sign::Positive,
                Domain::Real => Sign::Unknown,
            },
            View::Add(terms) => terms.iter().skip(1).fold(self.sign(&terms[0]), |acc, t| {
                if acc == Sign::Unknown {
                    acc
                } else {
                    acc.plus(self.sign(t))
                }
            }),
            View::Mul(factors) => factors.iter().fold(Sign::Positive, |acc, f| {
                if acc == Sign::Unknown {
                    acc
                } else {
                    acc.times(self.sign(f))
                }
            }),
            View::Pow(base, exponent) => match exponent.as_num() {
                Some(n) => self.sign(base).power(n.to_i64()),
                None if self.sign(base) == Sign::Positive => Sign::Positive,
                None => Sign::Unknown,
            },
            View::Func(Func::Abs, argument) => {
                if self.sign(argument).is_strict() {
                    Sign::Positive
                } else {
                    Sign::NonNegative
                }
            }
            // acos is valued in [0, π].
            View::Func(Func::Acos, _) => Sign::NonNegative,
            // atan keeps its argument's sign.
            View::Func(Func::Atan, argument) => self.sign(argument),
            View::Func(..) => Sign::Unknown,
        }
    }
}
