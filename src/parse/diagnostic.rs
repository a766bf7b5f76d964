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
    /// The source line that holds the error, for the caret display.
    pub source_line: String,
}

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
        let mut source_line: String = source[line_start..line_end].chars().take(200).collect();
        if source_line.len() < line_end - line_start {
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
        }
    }

    /// The same diagnostic with a hint on what to do (long numbers that the quoted line does
    /// not hold shortened, as in the message).
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(shorten_long_numbers(&help.into(), &self.source_line));
        self
    }

    /// The multi-line display: the one-line error, the location, the line and a caret.
    pub fn render(&self) -> String {
        let number = self.line.to_string();
        let pad = " ".repeat(number.len());
        let caret_pad = " ".repeat(self.column.saturating_sub(1).min(200));
        let width = self.span.len().clamp(1, 80);
        let mut out = format!(
            "error: {}\n{pad}--> {}:{}:{}\n{pad} |\n{number} | {}\n{pad} | {caret_pad}{} here\n",
            self.message,
            self.source_name,
            self.line,
            self.column,
            self.source_line,
            "^".repeat(width)
        );
        if let Some(help) = &self.help {
            out.push_str(&format!("{pad} = help: {help}\n"));
        }
        out
    }
}
