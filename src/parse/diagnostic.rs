//! A located error in user input: file, line, column, a caret under the place, what was
//! expected, and a hint.
//!
//! ```text
//! error: expected an expression (a number, a symbol or a parenthesis), found end of input
//!  --> input:1:7
//!   |
//! 1 | ((((((
//!   |       ^ here
//!   = help: every '(' needs an expression and a matching ')'
//! ```

use super::long_numbers::shorten_long_numbers;
use crate::visible;

/// An error in user input with its location.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error, miette::Diagnostic)]
#[error("{source_name}:{line}:{column}: {message}")]
pub struct Diagnostic {
    /// The file name, or `input` / `<stdin>` for text given directly.
    pub source_name: String,
    /// 1-based line and column (in characters) of the start of the offending span.
    pub line: usize,
    pub column: usize,
    /// Byte span in the source.
    #[label("here")]
    pub span: miette::SourceSpan,
    pub message: String,
    #[help]
    pub help: Option<String>,
    /// The source line that holds the error, for the caret display: of a long line, the
    /// part around the error, `... ` before it when its beginning is left out.
    pub source_line: String,
    /// The characters of the line left out before [`Diagnostic::source_line`].
    pub left_out: usize,
}

/// The most characters of a line quoted.
const QUOTED: usize = 200;
/// Of a line whose error stands past [`QUOTED`] characters less this, the quote begins this
/// many characters before the error, so that the caret stays in view.
const BEFORE_THE_ERROR: usize = 60;
/// What stands for the part of a line left out.
const LEFT_OUT: &str = "... ";

impl Diagnostic {
    /// A diagnostic at byte offsets `start..end` of `source`. Long numbers in the message
    /// that the source does not hold are shortened ([`shorten_long_numbers`]).
    pub fn at(
        source_name: &str,
        source: &str,
        start: usize,
        end: usize,
        message: impl Into<String>,
    ) -> Diagnostic {
        let start = source.floor_char_boundary(start);
        let end = source.floor_char_boundary(end.max(start));
        let line_start = source[..start].rfind('\n').map_or(0, |i| i + 1);
        let line_end = source[start..]
            .find('\n')
            .map_or(source.len(), |i| start + i);
        let line = source[..start].matches('\n').count() + 1;
        let column = source[line_start..start].chars().count() + 1;
        // A file's lines may end in CR LF: the CR is the line's end, not a character of it.
        let line_text = source[line_start..line_end].trim_end_matches('\r');
        let left_out = match column - 1 {
            before if before > QUOTED - BEFORE_THE_ERROR => before - BEFORE_THE_ERROR,
            _ => 0,
        };
        let mut source_line = String::new();
        if left_out > 0 {
            source_line.push_str(LEFT_OUT);
        }
        let mut quoted = line_text.chars().skip(left_out);
        source_line.extend(quoted.by_ref().take(QUOTED));
        if quoted.next().is_some() {
            source_line.push_str(" ...");
        }
        Diagnostic {
            source_name: source_name.to_string(),
            line,
            column,
            span: (start, end - start).into(),
            message: shorten_long_numbers(&message.into(), source),
            help: None,
            source_line,
            left_out,
        }
    }

    /// The same diagnostic with a hint on what to do (long numbers that the quoted line does
    /// not hold shortened, as in the message).
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(shorten_long_numbers(&help.into(), &self.source_line));
        self
    }

    /// The multi-line display: the one-line error, the location, the line and a caret.
    /// Characters a reader cannot see ([`visible::is_hidden`]: ESC, a right-to-left
    /// override) are shown as their escapes, `\u{1b}`, in the message, the name, the line
    /// and the hint, so no input drives the terminal; the caret stands under the character
    /// the column counts (a tab in the line is a tab in the caret's margin, an escape as
    /// many spaces as it is wide).
    pub fn render(&self) -> String {
        let number = self.line.to_string();
        let pad = " ".repeat(number.len());
        // The characters of the quote before the error's.
        let before = match self.left_out {
            0 => self.column.saturating_sub(1),
            left_out => self.column.saturating_sub(1) - left_out + LEFT_OUT.len(),
        };
        let caret_pad = caret_margin(&self.source_line, before);
        let width = caret_width(&self.source_line, before, self.span.len());
        let mut out = format!(
            "error: {}\n{pad}--> {}:{}:{}\n{pad} |\n{number} | {}\n{pad} | {caret_pad}{} here\n",
            visible::escaped(&self.message),
            visible::escaped(&self.source_name),
            self.line,
            self.column,
            visible::escaped(&self.source_line),
            "^".repeat(width)
        );
        if let Some(help) = &self.help {
            out.push_str(&format!("{pad} = help: {}\n", visible::escaped(help)));
        }
        out
    }
}

/// The blanks before a caret under the character after the first `before` of `line` as
/// [`Diagnostic::render`] shows it: a tab for a tab, a space for a character, as many as
/// its escape is wide for a hidden one; spaces past the line's end (at most 200 in all).
fn caret_margin(line: &str, before: usize) -> String {
    let before = before.min(200);
    let mut margin = String::with_capacity(before);
    let mut chars = line.chars();
    for _ in 0..before {
        match chars.next() {
            Some('\t') => margin.push('\t'),
            Some(c) if visible::is_hidden(c) => {
                margin.extend(std::iter::repeat_n(' ', visible::escape_len(c)));
            }
            _ => margin.push(' '),
        }
    }
    margin
}

/// How many carets stand under the `bytes` of `line` after its first `before` characters:
/// one per character as shown (an escape as wide as it is), one per byte past the line's
/// end; at least 1, at most 80.
fn caret_width(line: &str, before: usize, bytes: usize) -> usize {
    let mut width = 0;
    let mut covered = 0;
    for c in line.chars().skip(before) {
        if covered >= bytes {
            break;
        }
        covered += c.len_utf8();
        width += if visible::is_hidden(c) {
            visible::escape_len(c)
        } else {
            1
        };
    }
    (width + bytes.saturating_sub(covered)).clamp(1, 80)
}

#[cfg(test)]
mod tests {
    use super::Diagnostic;

    /// The character the caret of a rendered diagnostic stands under.
    fn under_the_caret(rendered: &str) -> Option<char> {
        let lines: Vec<&str> = rendered.lines().collect();
        let caret = lines.iter().position(|l| l.contains("^ here"))?;
        let column = lines[caret].find('^')?;
        lines[caret - 1][column..].chars().next()
    }

    /// An error far along a long line is quoted with the text around it, so its caret is
    /// in view; near the start the line is quoted from its beginning.
    #[test]
    fn the_caret_of_an_error_far_along_a_line_stays_in_view() {
        let source = format!("{}$ and more", "a+".repeat(5_000));
        let at = source.find('$').unwrap_or(0);
        let rendered = Diagnostic::at("input", &source, at, at + 1, "here").render();
        assert_eq!(under_the_caret(&rendered), Some('$'), "{rendered}");
        assert!(rendered.contains("\n1 | ... a+a+"), "{rendered}");
        let near = Diagnostic::at("input", "x + $", 4, 5, "here").render();
        assert_eq!(under_the_caret(&near), Some('$'), "{near}");
        assert!(near.contains("1 | x + $"), "{near}");
    }

    /// An ESC sequence in the input reaches the terminal escaped, in the quoted line and in
    /// the message, and the caret still stands under the character the column counts.
    #[test]
    fn hidden_characters_are_escaped_and_the_caret_stays_under_its_character() {
        let source = "a\u{1b}[2J\tb $";
        let at = source.find('$').unwrap_or(0);
        let d = Diagnostic::at(
            "in\u{202e}put",
            source,
            at,
            at + 1,
            "unexpected \u{1b}[2J $",
        );
        let shown = d.render();
        assert!(
            !shown.contains('\u{1b}') && !shown.contains('\u{202e}'),
            "{shown}"
        );
        assert!(shown.contains(r"error: unexpected \u{1b}[2J $"), "{shown}");
        assert!(shown.contains(r"--> in\u{202e}put:1:"), "{shown}");
        let lines: Vec<&str> = shown.lines().collect();
        let quoted = lines[3].split_once(" | ").map(|p| p.1).unwrap_or_default();
        let caret = lines[4].split_once(" | ").map(|p| p.1).unwrap_or_default();
        assert_eq!(quoted, "a\\u{1b}[2J\tb $");
        assert_eq!(caret.find('^'), quoted.find('$'), "{shown}");
    }

    /// A caret stands under each character of the span, however many bytes it takes.
    #[test]
    fn one_caret_per_character() {
        let d = Diagnostic::at("f", "a ωω\u{fffd} b", 2, 9, "here");
        assert!(d.render().contains(" |   ^^^ here\n"), "{}", d.render());
    }

    /// A line of a CR LF file is quoted without its CR.
    #[test]
    fn a_carriage_return_ending_a_line_is_not_quoted() {
        let d = Diagnostic::at("f", "given x\r\nfind ?\r\n", 14, 15, "what?");
        assert_eq!(d.source_line, "find ?");
        assert!(!d.render().contains(r"\u{d}"));
    }
}
