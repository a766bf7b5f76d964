//! Decimal literals as exact rationals: `0.1` is `1/10`, `1.5e-3` is `3/2000`; the algebra
//! never rounds what a person typed. And the way back for a reader: a number in a fixed
//! number of significant figures (`-129.8`, `0.01235`, `150e-9`).

use super::digit_bound::{MAX_DECIMAL_EXPONENT, MAX_DIGITS};
use super::rational::{reduced_big, Q};
use num_bigint::BigInt;
use num_rational::BigRational;

/// Four significant figures ([`significant_figures`]): `-129.8`, `0.01235`, `150e-9`.
pub fn four_significant_figures(x: f64) -> String {
    significant_figures(x, 4)
}

/// `x` in `n` significant figures (at least one), as an engineer reads it: a rounded value
/// keeps its trailing zeros (`3.930`, `0.0006667`, `2.000`), a value that is exactly what
/// fewer figures say shows only those (`3.93`, `0.04`, `2700`); a magnitude from 10⁵ up or
/// below 10⁻⁴ in engineering notation, its exponent a multiple of three (`123.5e3`,
/// `150e-9`).
pub fn significant_figures(x: f64, n: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return if x.is_nan() {
            "NaN".into()
        } else if x == 0.0 {
            "0".into()
        } else {
            format!("{x}")
        };
    }
    let n = n.max(1);
    // Rounded once: the digits and the exponent of the rounded value (9.99996 is 1.000e1).
    let rounded = format!("{:.*e}", n - 1, x.abs());
    let (mantissa, exponent) = rounded.split_once('e').expect("`{:e}` writes an exponent");
    let exponent: i32 = exponent.parse().expect("`{:e}` writes a whole exponent");
    let mut digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    // Exact in fewer figures: the shortest text that reads back as x has no more digits.
    let shortest = format!("{:e}", x.abs());
    let shortest_digits = shortest
        .split('e')
        .next()
        .map_or(0, |m| m.chars().filter(char::is_ascii_digit).count());
    if shortest_digits <= n {
        let kept = digits.trim_end_matches('0').len().max(1);
        digits.truncate(kept);
    }
    let engineering = if (-4..5).contains(&exponent) {
        0
    } else {
        3 * exponent.div_euclid(3)
    };
    // Digits before the decimal point.
    let before = exponent - engineering + 1;
    let mut text = String::new();
    if x < 0.0 {
        text.push('-');
    }
    if before <= 0 {
        text.push_str("0.");
        text.extend(std::iter::repeat_n('0', before.unsigned_abs() as usize));
        text.push_str(&digits);
    } else {
        let before = before as usize;
        if digits.len() <= before {
            text.push_str(&digits);
            text.extend(std::iter::repeat_n('0', before - digits.len()));
        } else {
            text.push_str(&digits[..before]);
            text.push('.');
            text.push_str(&digits[before..]);
        }
    }
    if engineering != 0 {
        text.push_str(&format!("e{engineering}"));
    }
    text
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
