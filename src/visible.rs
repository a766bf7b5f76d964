//! Characters a reader cannot see, shown as their escapes: what a user wrote reaches a page
//! or an error message, and an ESC byte in it must not drive the terminal (`\x1b[2J` clears
//! the screen), nor a right-to-left override reorder the words around it.
//!
//! ```
//! use kinetics::visible;
//! assert_eq!(visible::escaped("a\u{1b}[2J b"), r"a\u{1b}[2J b");
//! assert_eq!(visible::escaped("x\u{202e}y\tz"), "x\\u{202e}y\tz");
//! assert!(matches!(visible::escaped("θ é 中"), std::borrow::Cow::Borrowed(_)));
//! ```
//!
//! Below every layer of `src/` (it uses nothing of the crate): the parser's diagnostics, the
//! printers' notations and the binary's messages all show such characters one way.

use std::borrow::Cow;

/// Whether `c` is shown as its escape `\u{…}` wherever text reaches a reader: a control
/// character other than the tab and the line feed (which lay text out; ESC, NUL, the bell,
/// a carriage return or DEL would act on a terminal or vanish), or a character that
/// reorders, hides or breaks the displayed text: the bidirectional controls (U+061C, U+200E,
/// U+200F, U+202A to U+202E, U+2066 to U+2069), the zero-width characters (U+200B to
/// U+200D, and U+FEFF, a byte-order mark inside the text) and the line and paragraph
/// separators (U+2028, U+2029).
pub fn is_hidden(c: char) -> bool {
    (c.is_control() && c != '\t' && c != '\n')
        || matches!(
            c,
            '\u{061C}'
                | '\u{200B}'..='\u{200F}'
                | '\u{202A}'..='\u{202E}'
                | '\u{2066}'..='\u{2069}'
                | '\u{2028}'
                | '\u{2029}'
                | '\u{FEFF}'
        )
}

/// Appends `c` as Rust writes it in a string: `\u{1b}`, `\u{202e}` (hexadecimal, lower case).
pub fn push_escape(out: &mut String, c: char) {
    out.push_str(&c.escape_unicode().to_string());
}

/// The length in characters of `c`'s escape (`\u{1b}` is 6), for aligning a caret under it.
pub fn escape_len(c: char) -> usize {
    c.escape_unicode().count()
}

/// `text` with each character [`is_hidden`] as its escape, every other character as it is;
/// borrowed when there is none. Idempotent: an escape holds no hidden character.
pub fn escaped(text: &str) -> Cow<'_, str> {
    if !text.chars().any(is_hidden) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if is_hidden(c) {
            push_escape(&mut out, c);
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn controls_and_reordering_characters_are_escaped() {
        for c in [
            '\u{0}', '\u{7}', '\u{1b}', '\r', '\u{7f}', '\u{85}', '\u{202e}', '\u{2066}',
        ] {
            assert!(is_hidden(c), "{c:?}");
            assert_eq!(escape_len(c), escaped(&c.to_string()).chars().count());
        }
        for c in ['\t', '\n', ' ', 'a', 'θ', '中', '😀', '\u{301}'] {
            assert!(!is_hidden(c), "{c:?}");
        }
        assert_eq!(escaped("\u{7f}"), r"\u{7f}");
        assert_eq!(escaped(&escaped("\u{1b}x")), escaped("\u{1b}x"));
    }
}
