//! Bounds on user input, checked before parsing so that no input can overflow the stack
//! or take unbounded time.
//!
//! Nesting is counted as the parser will nest: every open parenthesis (a call's too), every
//! power in a chain (`a^b^c` is `a^(b^c)`: `^` and `**` alike), and every prefix sign (`-x^-x`
//! is `-(x^(-x))`) is one level, and the levels of the enclosing parentheses add up. A binary
//! operator that binds more loosely than a power (`+ - * / × · = ,` and a juxtaposed operand,
//! `x^2 y`) ends the chain of its level. Numbers are read whole, so the sign of an exponent
//! (`1e-1`) is neither an operator nor a prefix sign. Every recursive walk of an expression is
//! bounded by this count: a parsed expression is at most [`MAX_NESTING`] levels deep.

use super::diagnostic::Diagnostic;

/// Largest input accepted, in bytes.
pub const MAX_INPUT_BYTES: usize = 1 << 20;
/// Deepest nesting of parentheses, chained powers and prefix signs, added up.
pub const MAX_NESTING: usize = 200;
/// Longest run of prefix signs (`- - x`).
pub const MAX_PREFIX_RUN: usize = 16;

/// Rejects input that is too large or nested too deeply, with the place where the limit
/// was crossed.
pub fn check_input(source_name: &str, source: &str) -> Result<(), Diagnostic> {
    if source.len() > MAX_INPUT_BYTES {
        return Err(Diagnostic::at(
            source_name,
            &source[..source.floor_char_boundary(256)],
            0,
            0,
            format!(
                "input is {} bytes, more than the limit of {} bytes",
                source.len(),
                MAX_INPUT_BYTES
            ),
        )
        .with_help("split the input into smaller expressions"));
    }
    let mut nesting = Nesting::default();
    let mut previous = Token::Operator;
    let mut prefix_run = 0usize;
    let bytes = source.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let (token, length) = token_at(bytes, i);
        let refused = |message: String| {
            let help =
                "simplify the expression; no formula of this chapter needs that much nesting";
            Err(Diagnostic::at(source_name, source, i, i + length, message).with_help(help))
        };
        let deeper = match token {
            Token::Blank => {
                i += length;
                continue;
            }
            Token::Open => {
                // A '(' after an operand that is not a callee is a product: `2(a + b)`.
                if previous == Token::Operand {
                    nesting.end_chain();
                }
                nesting.open()
            }
            Token::Close => {
                nesting.close();
                None
            }
            Token::Power => nesting.chain("powers"),
            Token::Sign if previous != Token::Operator => {
                nesting.end_chain();
                None
            }
            Token::Sign => {
                prefix_run += 1;
                if prefix_run > MAX_PREFIX_RUN {
                    return refused(format!("more than {MAX_PREFIX_RUN} signs in a row"));
                }
                nesting.chain("signs and powers")
            }
            Token::Operator => {
                nesting.end_chain();
                None
            }
            Token::Operand | Token::Callee => {
                if previous == Token::Operand {
                    nesting.end_chain();
                }
                prefix_run = 0;
                None
            }
        };
        if let Some(what) = deeper {
            return refused(format!("{what} nested more than {MAX_NESTING} levels deep"));
        }
        // A callee's '(' opens its arguments; it is not a product with what comes before.
        previous = match token {
            Token::Close => Token::Operand,
            Token::Sign | Token::Power | Token::Open => Token::Operator,
            other => other,
        };
        i += length;
    }
    Ok(())
}

/// What the nesting count sees of the input, one token at a time.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Token {
    Blank,
    Open,
    Close,
    /// `^` or `**`.
    Power,
    /// `+`, `-` or `−`: binary after an operand, else a prefix sign.
    Sign,
    /// A binary operator looser than a power: `* / × · = ,`.
    Operator,
    /// A number (read whole, its exponent's sign included), a symbol, the degree sign, or
    /// any other character (which the grammar refuses).
    Operand,
    /// A name directly followed by `(`: its parenthesis holds arguments.
    Callee,
}

/// The token that starts at byte `i` and its length in bytes.
fn token_at(bytes: &[u8], i: usize) -> (Token, usize) {
    let rest = &bytes[i..];
    match rest {
        [b' ' | b'\t' | b'\r' | b'\n', ..] => (Token::Blank, 1),
        [b'(', ..] => (Token::Open, 1),
        [b')', ..] => (Token::Close, 1),
        [b'^', ..] => (Token::Power, 1),
        [b'*', b'*', ..] => (Token::Power, 2),
        [b'+' | b'-', ..] => (Token::Sign, 1),
        // The minus sign − (U+2212), as typed from a word processor.
        [0xE2, 0x88, 0x92, ..] => (Token::Sign, 3),
        [b'*' | b'/' | b'=' | b',', ..] => (Token::Operator, 1),
        // The cross product × and the product sign ·.
        [0xC3, 0x97, ..] | [0xC2, 0xB7, ..] => (Token::Operator, 2),
        [c, ..] if c.is_ascii_digit() || *c == b'.' => (Token::Operand, number_length(rest)),
        [c, ..] if c.is_ascii_alphabetic() => {
            let length = rest
                .iter()
                .position(|c| !(c.is_ascii_alphanumeric() || *c == b'_' || *c == b'\''))
                .unwrap_or(rest.len());
            match rest.get(length) {
                Some(b'(') => (Token::Callee, length),
                _ => (Token::Operand, length),
            }
        }
        // Any other character, whole (a UTF-8 sequence is one character).
        [c, ..] => (Token::Operand, utf8_length(*c)),
        [] => (Token::Blank, 1),
    }
}

/// The length of the number at the start of `text`, as the grammar reads one:
/// `digits [. digits] [e [+-] digits]`.
fn number_length(text: &[u8]) -> usize {
    let digits = |from: usize| {
        text[from..]
            .iter()
            .take_while(|c| c.is_ascii_digit())
            .count()
    };
    let mut length = digits(0);
    if text.get(length) == Some(&b'.') {
        length += 1 + digits(length + 1);
    }
    if matches!(text.get(length), Some(b'e' | b'E')) {
        let sign = usize::from(matches!(text.get(length + 1), Some(b'+' | b'-')));
        let exponent = digits(length + 1 + sign);
        if exponent > 0 {
            length += 1 + sign + exponent;
        }
    }
    length.max(1)
}

/// The bytes of the UTF-8 character that begins with `first` (1 for a stray byte).
fn utf8_length(first: u8) -> usize {
    match first {
        0xF0.. => 4,
        0xE0.. => 3,
        0xC0.. => 2,
        _ => 1,
    }
}

/// The levels open at a point of the input: one per open parenthesis, and the chain of
/// powers and prefix signs of each parenthesis level, added up.
#[derive(Default)]
struct Nesting {
    /// The chain of each open level, the outermost (no parenthesis) first.
    chains: Vec<usize>,
    /// Open parentheses plus every chain: the depth the parser will reach.
    total: usize,
}

impl Nesting {
    fn current(&mut self) -> &mut usize {
        if self.chains.is_empty() {
            self.chains.push(0);
        }
        self.chains.last_mut().expect("a level is open")
    }

    /// One more power or sign in the current chain; `what` when that is too deep.
    fn chain(&mut self, what: &'static str) -> Option<&'static str> {
        *self.current() += 1;
        self.total += 1;
        (self.total > MAX_NESTING).then_some(what)
    }

    /// A binary operator looser than a power: the current chain ends.
    fn end_chain(&mut self) {
        let chain = std::mem::take(self.current());
        self.total -= chain;
    }

    /// A '(': one level deeper, with a chain of its own.
    fn open(&mut self) -> Option<&'static str> {
        self.current();
        self.chains.push(0);
        self.total += 1;
        (self.total > MAX_NESTING).then_some("parentheses")
    }

    /// A ')': the level and its chain end (an unmatched one is the grammar's to report).
    fn close(&mut self) {
        if self.chains.len() > 1 {
            let chain = self.chains.pop().expect("a level is open");
            self.total -= chain + 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(source: &str) -> Option<String> {
        check_input("t", source).err().map(|d| d.message)
    }

    /// `count` links of `link` after `first`: `x` then `^x` 200 times is 200 levels.
    fn chain(first: &str, link: &str, count: usize) -> String {
        format!("{first}{}", link.repeat(count))
    }

    #[test]
    fn every_way_of_writing_a_power_is_one_level() {
        for link in ["^x", "**x", "^1e-1", "**1E+5", "^ x", "^(x)", "^sin(x)"] {
            let message = refused(&chain("x", link, MAX_NESTING + 1));
            assert!(
                message.is_some_and(|m| m.contains("nested more than 200")),
                "{link}"
            );
        }
        // Without a parenthesis of their own, 200 links are 200 levels, the most accepted.
        for link in ["^x", "**x", "^1e-1", "**1E+5", "^ x"] {
            assert_eq!(refused(&chain("x", link, MAX_NESTING)), None, "{link}");
        }
    }

    #[test]
    fn a_signed_exponent_is_part_of_its_number() {
        // 1e-1 is one number: the '-' neither ends the chain nor counts as a sign.
        assert!(refused(&chain("1e-1", "^1e-1", MAX_NESTING + 1)).is_some());
        assert_eq!(refused(&chain("1e-1", "^1e-1", MAX_NESTING)), None);
    }

    #[test]
    fn prefix_signs_and_parentheses_add_to_the_powers() {
        // -x^-x^-x…: a sign and a power per link.
        assert_eq!(refused(&chain("-x", "^-x", MAX_NESTING / 2 - 1)), None);
        assert!(refused(&chain("-x", "^-x", MAX_NESTING / 2 + 1)).is_some());
        // x^(x^(x^…)): a parenthesis and a power per level.
        let nested = |n: usize| format!("x{}{}", "^(x".repeat(n), ")".repeat(n));
        assert_eq!(refused(&nested(MAX_NESTING / 2)), None);
        assert!(refused(&nested(MAX_NESTING / 2 + 1)).is_some());
    }

    #[test]
    fn looser_operators_end_a_chain() {
        // Products, sums and juxtaposed factors of powers are long, not deep.
        for link in [
            " + x^2", "*x^2", " x^2", "/x^2", " - x^2", " (x)^2", ", x^2",
        ] {
            assert_eq!(
                refused(&chain("x^2", link, 5 * MAX_NESTING)),
                None,
                "{link}"
            );
        }
        // A callee's parenthesis is not a product: the chain goes on through it.
        assert!(refused(&chain("x", "^f(x)", MAX_NESTING + 1)).is_some());
    }
}
