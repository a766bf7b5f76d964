//! Long numbers in messages, shortened to four significant figures.
//!
//! An error may quote a form the engine computed: an expanded term, an exact product of the
//! givens, a value in f64. Its numbers can run to hundreds of digits the user never wrote
//! (`cannot add -1000…000 (no unit)`). In a message, a number of more than
//! [`LONGEST_QUOTED`] digits that the user's own text does not hold is written as
//! `d.ddde±N` (or exactly, `1e200`, when it has at most four significant digits):
//!
//! `-4.9999999999999995e200` → `-5.000e200`, `1` followed by 200 zeros → `1e200`.

/// The most digits a number in a message keeps as they are.
pub const LONGEST_QUOTED: usize = 12;

/// `message` with every number longer than [`LONGEST_QUOTED`] digits that `source` does not
/// hold shortened to four significant figures.
pub fn shorten_long_numbers(message: &str, source: &str) -> String {
    let bytes = message.as_bytes();
    let mut out = String::with_capacity(message.len());
    let mut copied = 0;
    let mut i = 0;
    while i < bytes.len() {
        let starts_number = bytes[i].is_ascii_digit()
            && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_'));
        if !starts_number {
            i += 1;
            continue;
        }
        let end = number_end(bytes, i);
        let token = &message[i..end];
        let digits = token.bytes().take_while(|b| *b != b'e' && *b != b'E');
        if digits.filter(u8::is_ascii_digit).count() > LONGEST_QUOTED && !source.contains(token) {
            out.push_str(&message[copied..i]);
            out.push_str(&scientific(token));
            copied = end;
        }
        i = end;
    }
    out.push_str(&message[copied..]);
    out
}

/// The end of the decimal number that starts at `start`: digits, an optional fraction and
/// an optional exponent.
fn number_end(bytes: &[u8], start: usize) -> usize {
    let digits_from = |mut i: usize| {
        while i < bytes.len() && bytes[i].is_ascii_digit() {
            i += 1;
        }
        i
    };
    let mut end = digits_from(start);
    if end + 1 < bytes.len() && bytes[end] == b'.' && bytes[end + 1].is_ascii_digit() {
        end = digits_from(end + 1);
    }
    if end < bytes.len() && (bytes[end] == b'e' || bytes[end] == b'E') {
        let sign = usize::from(matches!(bytes.get(end + 1), Some(b'+' | b'-')));
        if bytes.get(end + 1 + sign).is_some_and(u8::is_ascii_digit) {
            end = digits_from(end + 1 + sign);
        }
    }
    end
}

/// A decimal number (`ddd`, `ddd.ddd`, either with `e±N`) in four significant figures, its
/// rounding carried through the digits as text: the number may be far beyond f64.
fn scientific(token: &str) -> String {
    let (mantissa, exponent) = match token.find(['e', 'E']) {
        Some(e) => (&token[..e], token[e + 1..].parse::<i64>().unwrap_or(0)),
        None => (token, 0),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let all: Vec<u8> = whole.bytes().chain(fraction.bytes()).collect();
    let Some(first) = all.iter().position(|d| *d != b'0') else {
        return "0".to_string();
    };
    let significant = &all[first..];
    let mut power = exponent + whole.len() as i64 - first as i64 - 1;
    let leading: u64 = significant
        .iter()
        .chain(std::iter::repeat(&b'0'))
        .take(5)
        .fold(0, |n, d| n * 10 + u64::from(d - b'0'));
    let mut four = (leading + 5) / 10;
    if four == 10_000 {
        four = 1_000;
        power += 1;
    }
    let exact = significant[4.min(significant.len())..]
        .iter()
        .all(|d| *d == b'0');
    let shown = if exact {
        let mut s = four.to_string();
        while s.len() > 1 && s.ends_with('0') {
            s.pop();
        }
        s
    } else {
        four.to_string()
    };
    match shown.split_at(1) {
        (head, "") => format!("{head}e{power}"),
        (head, tail) => format!("{head}.{tail}e{power}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_computed_numbers_are_shortened_and_the_users_own_are_kept() {
        let huge = format!("1{}", "0".repeat(200));
        let message = format!("cannot add -{huge} (no unit) to c (m)");
        assert_eq!(
            shorten_long_numbers(&message, "rod(c-1e200)"),
            "cannot add -1e200 (no unit) to c (m)"
        );
        assert_eq!(shorten_long_numbers(&message, &huge), message);
        assert_eq!(
            shorten_long_numbers("m = -4.9999999999999995e200 kg", ""),
            "m = -5.000e200 kg"
        );
        assert_eq!(
            shorten_long_numbers("x = 123456789012345678, w_12 = 7", ""),
            "x = 1.235e17, w_12 = 7"
        );
        assert_eq!(
            shorten_long_numbers("a 0.000000000000000012345678 b", ""),
            "a 1.235e-17 b"
        );
        assert_eq!(
            shorten_long_numbers("99999999999999999/3", ""),
            "1.000e17/3"
        );
        assert_eq!(
            shorten_long_numbers("short 1234567 and 2.5", ""),
            "short 1234567 and 2.5"
        );
    }
}
