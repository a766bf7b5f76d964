//! The bound on the size of exact numbers: at most [`MAX_DIGITS`] decimal digits in the
//! numerator or the denominator of a number written in or formed from the input (and a
//! decimal's scale within ±[`MAX_DECIMAL_EXPONENT`]), and the
//! estimates checked against it before a product or sum of numbers is folded:
//!
//! - a product `Π nᵢ/dᵢ` has at most `Σ bits(nᵢ)` bits above and `Σ bits(dᵢ)` below;
//! - a sum over the common denominator `D` (the product of the distinct `dᵢ`) has a
//!   numerator of at most `m · max|nᵢ| · D` for `m` terms.
//!
//! `Q`'s arithmetic stays infallible; the parser and the expansion ask first and refuse
//! with [`AlgebraError::NumberTooLarge`] where the bound would be crossed.

use super::error::AlgebraError;
use super::rational::Q;

/// Largest number of decimal digits the numerator or the denominator of an exact number
/// written or formed from the input may have; a larger one is refused
/// ([`AlgebraError::NumberTooLarge`]) where it would be formed.
pub const MAX_DIGITS: u64 = 10_000;

/// Largest scale `|e|` of a decimal literal `d·10^e` (its exponent less the digits after
/// the point).
pub const MAX_DECIMAL_EXPONENT: u64 = 4096;

/// `log2(10)`, to turn a count of bits into one of decimal digits.
const BITS_PER_DIGIT: f64 = std::f64::consts::LOG2_10;

impl Q {
    /// An upper bound on the bits of the larger part of `Π qᵢ`: the parts' lengths add,
    /// but for a part `1` (one bit), which multiplies nothing (a product of 40,000 symbols,
    /// each with the coefficient 1, was refused as a number of 10,000 digits).
    pub fn product_bits<'a>(factors: impl IntoIterator<Item = &'a Q>) -> u64 {
        let multiplying = |bits: u64| if bits == 1 { 0 } else { bits };
        let (num, den) = factors.into_iter().fold((0u64, 0u64), |(n, d), q| {
            let (qn, qd) = q.bit_lengths();
            (
                n.saturating_add(multiplying(qn)),
                d.saturating_add(multiplying(qd)),
            )
        });
        num.max(den)
    }

    /// An upper bound on the bits of the larger part of `Σ qᵢ` (`m` terms `nᵢ/dᵢ`): over a
    /// common denominator `D`, the product of the distinct `dᵢ`, the numerator is at most
    /// `m · max|nᵢ| · D`; a denominator `1`, or one met before, adds nothing (so a sum
    /// of many decimals with a few denominators stays small).
    pub fn sum_bits<'a>(terms: impl IntoIterator<Item = &'a Q>) -> u64 {
        let (mut count, mut num, mut den) = (0u64, 0u64, 0u64);
        let mut seen = std::collections::HashSet::new();
        for q in terms {
            let (qn, qd) = q.bit_lengths();
            count += 1;
            num = num.max(qn);
            if qd > 1 && seen.insert(q.denom()) {
                den = den.saturating_add(qd);
            }
        }
        num.saturating_add(den)
            .saturating_add(u64::from(64 - count.leading_zeros()))
    }

    /// `Ok` when a number of `bits` bits (an estimate of what `what` would form) is within
    /// [`MAX_DIGITS`] decimal digits, else the error that names it.
    pub fn check_bits(what: &str, bits: u64) -> Result<(), AlgebraError> {
        let digits = (bits as f64 / BITS_PER_DIGIT).ceil() as u64;
        if digits <= MAX_DIGITS {
            return Ok(());
        }
        Err(AlgebraError::NumberTooLarge {
            what: what.to_string(),
            digits,
            limit: MAX_DIGITS,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scale of a decimal is at most ±4096 and its digits at most `MAX_DIGITS`.
    #[test]
    fn decimals_are_bounded() {
        assert!(Q::parse_decimal("1e4096").is_some());
        assert!(Q::parse_decimal("1e-4096").is_some());
        assert_eq!(Q::parse_decimal("1e4097"), None);
        assert_eq!(Q::parse_decimal("1e-4097"), None);
        assert_eq!(Q::parse_decimal("1e9223372036854775808"), None);
        let long = "1".repeat(MAX_DIGITS as usize);
        assert!(Q::parse_decimal(&long).is_some());
        assert_eq!(Q::parse_decimal(&format!("{long}1")), None);
    }

    #[test]
    fn digit_bounds() {
        let ten = |e: i64| Q::parse_decimal(&format!("1e{e}")).unwrap();
        let (n, d) = ten(-10).bit_lengths();
        assert_eq!((n, d), (1, 34));
        assert!(Q::product_bits([&ten(308), &ten(308)]) >= ten(616).bit_lengths().0);
        let sum = [Q::new(1, 3).unwrap(), Q::new(1, 7).unwrap(), Q::int(5)];
        let (sn, sd) = (&(&sum[0] + &sum[1]) + &sum[2]).bit_lengths();
        assert!(Q::sum_bits(&sum) >= sn.max(sd));
        assert!(Q::check_bits("x", 33_000).is_ok());
        let err = Q::check_bits("the product", 40_000)
            .unwrap_err()
            .to_string();
        assert!(err.contains("more than the limit of 10000"), "{err}");
    }
}
