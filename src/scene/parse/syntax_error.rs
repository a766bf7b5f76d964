//! The message of a syntax error in a scene file: what the grammar expected at the furthest
//! place it reached, in words, the form of the statement begun there, and a likely misspelt
//! keyword (by edit distance).

use crate::parse::Diagnostic;

/// Each statement with the form it is written in, for the hint of a syntax error.
const STATEMENT_FORMS: [(&str, &str); 22] = [
    ("title", "title Sample Problem 18.4"),
    (
        "statement",
        "statement A thin plate of mass $m$ hangs from two wires (one line or several)",
    ),
    (
        "given",
        "given m = 0.3 kg  or  given L : m  or  given x = 0.2 m real",
    ),
    (
        "body",
        "body rod(c) mass m at (L/2, c/2, 0) along y rotated 30 deg about z, then 20 deg about x  \
         or  ... rotated 2 deg about (0, 1, 1)  or  ... axes (0, 1, 0), (0, 0, 1), (1, 0, 0)",
    ),
    ("fixed", "fixed point"),
    ("about", "about G"),
    ("up", "up y"),
    ("omega", "omega = w1*i - w2*j"),
    ("omegadot", "omegadot = alpha*i"),
    ("frame", "frame rate = -w2*j  or  frame body-fixed"),
    ("vbar", "vbar = vbar_x*i + vbar_z*k"),
    ("abar", "abar = -g*j"),
    ("force", "force D = D_y*j + D_z*k at (L, 0, 0)"),
    ("couple", "couple M*i"),
    (
        "impulse",
        "impulse -F*Dt*k at (-a/2, -b/2, 0)  or  impulse R = R_y*j at (a/2, 0, 0)",
    ),
    ("before", "before vbar = -v_0*j"),
    ("point", "point A at (a/2, b/2, 0)"),
    ("wire", "wire from (a/2, b/2, 0) to (a/2, b, 0)"),
    ("post", "post from (0, L/2, 0) to (0, L/2, L/3)"),
    (
        "constraint",
        "constraint velocity at (L, -r, 0) = 0  or  constraint vbar_y = 0",
    ),
    ("unknown", "unknown C_y, D_y : N"),
    ("find", "find D_y, C_y, H_G, T"),
];

/// A line the grammar cannot read: an unknown first word is named with the nearest
/// statement; a known statement gets its form as the hint.
pub(super) fn syntax_error(
    source_name: &str,
    source: &str,
    at: usize,
    expected: &[String],
) -> Diagnostic {
    let at = source.floor_char_boundary(at.min(source.len()));
    let line_start = source[..at].rfind('\n').map_or(0, |i| i + 1);
    let line = &source[line_start..];
    let line = &line[..line.find('\n').unwrap_or(line.len())];
    let indent = line.len() - line.trim_start().len();
    let word_len = line[indent..]
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '_'))
        .unwrap_or(line.len() - indent);
    let word = &line[indent..indent + word_len];
    let word_start = line_start + indent;
    match STATEMENT_FORMS.iter().find(|(keyword, _)| *keyword == word) {
        Some((keyword, form)) => {
            // The grammar may give up at the start of the statement: point past the keyword.
            let at = if at <= word_start {
                let after = word_start + word_len;
                after + source[after..].len()
                    - source[after..].trim_start_matches([' ', '\t']).len()
            } else {
                at
            };
            let found = match source[at..].chars().next() {
                None => "end of file".to_string(),
                Some('\n') => "end of line".to_string(),
                Some('\r') if source[at + 1..].starts_with('\n') => "end of line".to_string(),
                Some(c) => format!("'{c}'"),
            };
            let expected = match expected {
                [] => String::new(),
                tokens => format!(", expected {}", tokens.join(" or ")),
            };
            Diagnostic::at(
                source_name,
                source,
                at,
                at + 1,
                format!("cannot read this '{keyword}' statement (found {found}{expected})"),
            )
            .with_help(format!("write it as '{form}'"))
        }
        None => {
            let nearest = STATEMENT_FORMS
                .iter()
                .map(|(keyword, _)| (edit_distance(word, keyword), *keyword))
                .min()
                .filter(|(d, _)| *d <= 2 && !word.is_empty());
            let help = match nearest {
                Some((_, keyword)) => format!("did you mean '{keyword}'?"),
                None => format!(
                    "statements begin with one of: {}",
                    STATEMENT_FORMS.map(|(keyword, _)| keyword).join(", ")
                ),
            };
            let shown = if word.is_empty() { line.trim() } else { word };
            Diagnostic::at(
                source_name,
                source,
                word_start,
                word_start + word_len.max(1),
                format!("unknown statement '{shown}'"),
            )
            .with_help(help)
        }
    }
}

/// What the grammar expected, in words, without the spaces, line ends and comments that
/// are allowed almost everywhere.
pub(super) fn expected_words<T: std::fmt::Display>(tokens: &[T]) -> Vec<String> {
    let mut words: Vec<String> = Vec::new();
    for token in tokens.iter().map(T::to_string) {
        let word = match token.as_str() {
            "#" | "BUILTIN_RULE" => continue,
            "0..9" => "a digit".to_string(),
            "A..Z" | "a..z" => "a letter".to_string(),
            t if t.trim().is_empty() => continue,
            t => format!("'{t}'"),
        };
        if !words.contains(&word) {
            words.push(word);
        }
    }
    words
}

/// The Levenshtein distance between two words, for "did you mean".
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let next = (row[j + 1] + 1)
                .min(row[j] + 1)
                .min(diagonal + usize::from(ca != *cb));
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}
