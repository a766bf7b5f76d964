//! What a scene's text is refused for before the grammar reads it: its size and the nesting
//! of its mathematics, and a line on which more than one '(' is never closed.
//!
//! Nesting is counted in the text the grammar reads as mathematics: a comment line or a
//! title or statement line may hold any number of parentheses (the grammar skips them as
//! text, without nesting).
//!
//! The grammar learns that a '(' of a line's mathematics is never closed only at the end of
//! the line: it reads the rest of the line as a group, fails, and reads the '(' again as an
//! ordinary character (for the expression parser to report). One such '(' on a line costs
//! a second reading of the line at most; `n` of them cost `n` readings of what follows them
//! (200 on a line of a megabyte took seconds). So a line with more than one is refused here,
//! at the first, in one pass: the file cannot be read anyway.
//!
//! The count is the grammar's: a '(' that a ')' later on the line closes is a group, even
//! if a comment's text closes it (a group reads that text too); a '#' outside every group
//! begins a comment, and the text of a title or statement line is not mathematics.

use crate::parse::Diagnostic;

/// Refuses a scene's text before the grammar: too large or nested too deeply (comment lines,
/// titles and statement lines aside, [`crate::parse::limits`]), or a line with unclosed
/// parentheses.
pub(super) fn check_before_grammar(source_name: &str, source: &str) -> Result<(), Diagnostic> {
    let mathematics = without_comment_lines_and_prose(source);
    crate::parse::limits::check_input(source_name, &mathematics).map_err(|d| {
        // The same place in the text as written, quoted as written.
        let start = d.span.offset();
        let mut at = Diagnostic::at(source_name, source, start, start + d.span.len(), d.message);
        at.help = d.help;
        at
    })?;
    check_unclosed_parentheses(source_name, source)
}

/// `source` with each comment line, title and statement line blanked, byte for byte: the
/// same offsets.
fn without_comment_lines_and_prose(source: &str) -> String {
    source
        .split_inclusive('\n')
        .map(|line| {
            let text = line.trim_start_matches([' ', '\t']);
            if text.starts_with('#') || is_prose(line) {
                line.chars()
                    .map(|c| match c {
                        '\n' | '\r' => c.to_string(),
                        _ => " ".repeat(c.len_utf8()),
                    })
                    .collect::<String>()
            } else {
                line.to_string()
            }
        })
        .collect()
}

/// Refuses the first line (but a title or statement line) with more than one '(' that is
/// never closed.
fn check_unclosed_parentheses(source_name: &str, source: &str) -> Result<(), Diagnostic> {
    let mut start = 0;
    for line in source.split('\n') {
        let unclosed = unclosed_before_comment(line);
        if unclosed.len() > 1 && !is_prose(line) {
            let at = start + unclosed[0];
            return Err(Diagnostic::at(
                source_name,
                source,
                at,
                at + 1,
                format!(
                    "{} '(' on this line are never closed; the first is here",
                    unclosed.len()
                ),
            )
            .with_help("every '(' needs a matching ')' on the same line"));
        }
        start += line.len() + 1;
    }
    Ok(())
}

/// A title or a statement line: words, not mathematics.
fn is_prose(line: &str) -> bool {
    let line = line.trim_start_matches([' ', '\t']);
    line.starts_with("title") || line.starts_with("statement")
}

/// Byte offsets of the '(' of `line` that no ')' closes, before a comment. None when a ')'
/// closes nothing: the grammar stops there, before any of them.
fn unclosed_before_comment(line: &str) -> Vec<usize> {
    // The '(' still open at the end of the line, by the usual matching.
    let mut open = Vec::new();
    for (i, b) in line.bytes().enumerate() {
        match b {
            b'(' => open.push(i),
            b')' if open.pop().is_none() => return Vec::new(),
            _ => {}
        }
    }
    // A '#' is outside every group when each '(' still open there is one never closed.
    let mut depth = 0usize;
    for (i, b) in line.bytes().enumerate() {
        match b {
            b'(' => depth += 1,
            b')' => depth = depth.saturating_sub(1),
            b'#' => {
                let unclosed_before = open.partition_point(|&o| o < i);
                if depth == unclosed_before {
                    open.truncate(unclosed_before);
                    break;
                }
            }
            _ => {}
        }
    }
    open
}

#[cfg(test)]
mod tests {
    use super::unclosed_before_comment;

    #[test]
    fn counts_the_parentheses_the_grammar_cannot_close() {
        assert_eq!(unclosed_before_comment("omega = f(f(x"), [9, 11]);
        assert_eq!(unclosed_before_comment("omega = (a (b)"), [8]);
        assert_eq!(unclosed_before_comment("omega = (a) ((b"), [12, 13]);
        assert_eq!(
            unclosed_before_comment("omega = (a)) ((b"),
            [] as [usize; 0]
        );
        // A comment outside every group ends the line; inside a group it is the group's text.
        assert_eq!(
            unclosed_before_comment("omega = w*i # see (1 (2"),
            [] as [usize; 0]
        );
        assert_eq!(unclosed_before_comment("omega = (w # a) (b (c"), [16, 19]);
        assert_eq!(unclosed_before_comment("omega = ( (w # a) (b"), [8, 18]);
    }
}
