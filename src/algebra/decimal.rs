//! Decimal literals as exact rationals: `0.1` is `1/10`, `1.5e-3` is `3/2000`; the algebra
//! never rounds what a person typed. And the way back for a reader: a number in four
//! significant figures (`-129.8`, `0.01235`, `1.500e-7`).

use super::digit_bound::{MAX_DECIMAL_EXPONENT, MAX_DIGITS};
use super::rational::{reduced_big, Q};
use num_bigint::BigInt;
use num_rational::BigRational;

/// Four significant figures, without trailing noise: `-129.8`, `0.01234`, `1.235e-7`; a
/// magnitude outside [1e-4, 1e6) in scientific notation.
pub fn four_significant_figures(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let magnitude = x.abs().log10().floor() as i32;
    if !(-4..6).contains(&magnitude) {
        return format!("{x:.3e}");
    }
    let decimals = (3 - magnitude).max(0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

impl Q {
    /// The exact value of a decimal literal such as `12`, `0.25`, `1.5e-3` or `.5`; `None`
    /// when it is not one, when its scale (the exponent less the digits after the point) is
    /// beyond ±[`MAX_DECIMAL_EXPONENT`], or when it has more than [`MAX_DIGITS`] digits.
    pub fn parse_decimal(text: &str) -> Option<Q> {
        let (mantissa, exponent) = match text.find(['e', 'E']) {
            Some(at) => (&text[..at], text[at + 1..].parse::<i64>().ok()?),
            None => (text, 0),
        };
        let (int_part, frac_part) = match mantissa.find('.') {
            Some(at) => (&mantissa[..at], &mantissa[at + 1..]),
            None => (mantissa, ""),
        };
        if int_part.is_empty() && frac_part.is_empty() {
            return None;
        }
        let digits: String = [int_part, frac_part].concat();
        if !digits.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        let scale = exponent.checked_sub(frac_part.len() as i64)?;
        if scale.unsigned_abs() > MAX_DECIMAL_EXPONENT
            || digits.len() as u64 + scale.max(0).unsigned_abs() > MAX_DIGITS
        {
            return None;
        }
        let value: BigInt = digits.parse().ok()?;
        let ten = BigInt::from(10);
        let power = num_traits::pow(ten, scale.unsigned_abs() as usize);
        Some(if scale >= 0 {
            Q::from_big(BigRational::from_integer(value * power))
        } else {
            reduced_big(value, power)
        })
    }
}
