//! A unit as people write it, and as kinetics prints it: names from the table of
//! `units.rs` multiplied by `*`, `·`, `.` or a space (`N·m`, `N*m`, `N m`), divided by `/`
//! (the name right after it: `m/s^2`, `kg·m²/s`), each with a whole power written `^2`,
//! `^-1` or as a superscript (`m²`, `s⁻¹`); `°` is the degree. One reading serves the
//! unit's names ([`super::named_unit::NamedUnit`]), its dimension and factor (the `given`,
//! `unknown` and `find … in` statements) and the exact value of a given.

use super::units::{unit_named, UNIT_NAMES};

/// One name of a unit with its power (negative after `/`) and its byte span in the text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct UnitPower<'a> {
    pub name: &'a str,
    pub exponent: i32,
    pub span: (usize, usize),
}

/// Why a unit's text does not read: where (a byte span of the text), what, and the help.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnitTextError {
    pub span: (usize, usize),
    pub message: String,
    pub help: String,
}

/// The degree's sign, the unit `deg`.
const DEGREE_SIGN: char = '°';
/// The multiplication signs between two names (a space multiplies too).
const TIMES: [char; 4] = ['*', '.', '·', '⋅'];
const SUPERSCRIPT_DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
const SUPERSCRIPT_MINUS: char = '⁻';

/// The names of `text` with their powers, each name one of the table's (see the module
/// documentation).
pub fn unit_powers(text: &str) -> Result<Vec<UnitPower<'_>>, UnitTextError> {
    let error = |start: usize, end: usize, message: String| UnitTextError {
        span: (start, end),
        message,
        help: format!("the units are {UNIT_NAMES} and °, combined with * · / and ^ (m/s^2, kg·m²)"),
    };
    let mut powers = Vec::new();
    let mut divide = false;
    let mut chars = text.char_indices().peekable();
    while let Some(&(at, c)) = chars.peek() {
        if c.is_whitespace() || TIMES.contains(&c) || c == '/' {
            divide = (divide && c.is_whitespace()) || c == '/';
            chars.next();
            continue;
        }
        let name = if c == DEGREE_SIGN {
            chars.next();
            "deg"
        } else if c.is_ascii_alphabetic() {
            let mut end = at;
            while let Some(&(k, c)) = chars.peek().filter(|(_, c)| c.is_ascii_alphabetic()) {
                end = k + c.len_utf8();
                chars.next();
            }
            &text[at..end]
        } else {
            return Err(error(
                at,
                at + c.len_utf8(),
                format!("unexpected '{c}' in a unit"),
            ));
        };
        let name_end = chars.peek().map_or(text.len(), |(k, _)| *k);
        if unit_named(name).is_none() {
            return Err(error(at, name_end, format!("unknown unit '{name}'")));
        }
        let mut exponent_text = String::new();
        if chars.peek().is_some_and(|(_, c)| *c == '^') {
            chars.next();
            while let Some(&(_, c)) = chars
                .peek()
                .filter(|(_, c)| c.is_ascii_digit() || (*c == '-' && exponent_text.is_empty()))
            {
                exponent_text.push(c);
                chars.next();
            }
        } else {
            while let Some(&(_, c)) = chars
                .peek()
                .filter(|(_, c)| SUPERSCRIPT_DIGITS.contains(c) || *c == SUPERSCRIPT_MINUS)
            {
                exponent_text.push(match SUPERSCRIPT_DIGITS.iter().position(|d| *d == c) {
                    Some(digit) => char::from(b'0' + digit as u8),
                    None => '-',
                });
                chars.next();
            }
        }
        let end = chars.peek().map_or(text.len(), |(k, _)| *k);
        let exponent: i32 = match exponent_text.as_str() {
            "" => 1,
            written => written
                .parse()
                .ok()
                .filter(|e: &i32| e.abs() <= i32::from(i8::MAX))
                .ok_or_else(|| error(name_end, end, "exponent out of range".into()))?,
        };
        powers.push(UnitPower {
            name,
            exponent: if divide { -exponent } else { exponent },
            span: (at, end),
        });
        divide = false;
    }
    if powers.is_empty() {
        return Err(error(0, text.len(), "expected a unit".into()));
    }
    Ok(powers)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slash_divides_the_name_after_it() {
        // kg·m²/s is kg·m²·s⁻¹.
        let powers = unit_powers("kg·m²/s").unwrap();
        let exponents: Vec<(&str, i32)> = powers.iter().map(|p| (p.name, p.exponent)).collect();
        assert_eq!(exponents, [("kg", 1), ("m", 2), ("s", -1)]);
    }

    #[test]
    fn what_is_not_a_unit_is_refused_where_it_stands() {
        let e = unit_powers("N·furlong").unwrap_err();
        assert_eq!(
            (e.span, e.message.as_str()),
            ((3, 10), "unknown unit 'furlong'")
        );
        let e = unit_powers("m/s^999").unwrap_err();
        assert_eq!(e.message, "exponent out of range");
        let e = unit_powers("m+s").unwrap_err();
        assert_eq!(
            (e.span, e.message.as_str()),
            ((1, 2), "unexpected '+' in a unit")
        );
    }
}
