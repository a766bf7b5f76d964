//! Mutations of an input's text, for expressions and scenes alike: on tokens (replace one by
//! a hostile token, delete, duplicate, negate, wrap in a power, nest), on lines (delete,
//! duplicate, splice one from another input, a hostile title: issue 29's injections and
//! control characters) and on bytes (insert, truncate, a byte that is not UTF-8 or a
//! byte-order mark). A scene is mutated a line at a time, so most mutants still parse and
//! reach the analysis.

use crate::hostile;
use crate::random::Random;

/// `text` with one to a few mutations; `other` is another input of the corpus to splice from.
pub fn mutate(r: &mut Random, text: &str, other: &str) -> String {
    let mut text = text.to_string();
    for _ in 0..r.size(4) {
        text = once(r, &text, other);
    }
    text
}

fn once(r: &mut Random, text: &str, other: &str) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    if lines.is_empty() {
        lines.push(String::new());
    }
    let at = r.below(lines.len());
    match r.below(14) {
        12 => match lines.iter().position(|l| l.starts_with("title")) {
            Some(title) => lines[title] = hostile::title(r),
            None => lines.insert(0, hostile::title(r)),
        },
        13 if r.one_in(4) => lines[0] = format!("\u{feff}{}", lines[0]),
        0 if lines.len() > 1 => {
            lines.remove(at);
        }
        1 => {
            let copy = lines[at].clone();
            lines.insert(at, copy);
        }
        2 => {
            let donor: Vec<&str> = other.lines().collect();
            if !donor.is_empty() {
                lines.insert(at, r.pick(&donor).to_string());
            }
        }
        3 => {
            let cut = r.below(text.len() + 1);
            return text.get(..cut).unwrap_or(text).to_string();
        }
        4 => lines[at] = bytes(r, &lines[at]),
        _ => lines[at] = tokens(r, &lines[at]),
    }
    let mut out = lines.join("\n");
    out.push('\n');
    out
}

/// The line cut into words (names and numbers) and single other characters.
fn tokenize(line: &str) -> Vec<String> {
    let mut tokens: Vec<String> = Vec::new();
    let word = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '.';
    for c in line.chars() {
        match tokens.last_mut() {
            Some(last) if word(c) && last.chars().all(word) => last.push(c),
            _ => tokens.push(c.to_string()),
        }
    }
    tokens
}

fn tokens(r: &mut Random, line: &str) -> String {
    let mut t = tokenize(line);
    if t.is_empty() {
        return hostile::construct(r);
    }
    let at = r.below(t.len());
    match r.below(8) {
        7 => t.insert(at, r.pick(&hostile::INJECTIONS).to_string()),
        0 => t[at] = hostile::token(r),
        1 => t.insert(at, hostile::token(r)),
        2 => {
            t.remove(at);
        }
        3 => t[at] = format!("-{}", t[at]),
        4 => t[at] = format!("0*{}", t[at]),
        5 => t[at] = format!("({}-{})", t[at], t[at]),
        _ => {
            let n = r.size(30);
            let f = r.pick(&["abs", "sin", "sqrt", "f", ""]).to_string();
            t[at] = format!("{}{}{}", format!("{f}(").repeat(n), t[at], ")".repeat(n));
        }
    }
    t.concat()
}

/// A byte inserted or replaced: printable, or now and then a control byte or one that is
/// not UTF-8 (a lone continuation or lead byte, 0xFF). The targets take text, so such a
/// byte reaches them as the replacement character U+FFFD, as `from_utf8_lossy` reads it;
/// the command line's own refusal of it is covered by `tests/reproducers/`.
fn bytes(r: &mut Random, line: &str) -> String {
    let mut b = line.as_bytes().to_vec();
    let at = r.below(b.len() + 1);
    let printable = match r.below(8) {
        0 => *r.pick(&[0x1b, 0x00, 0x07, 0x08, 0x0d, 0x7f]),
        1 => *r.pick(&[0x80, 0xbf, 0xc3, 0xe2, 0xf0, 0xff]),
        _ => b' ' + r.below(95) as u8,
    };
    if r.one_in(2) || b.is_empty() || at == b.len() {
        b.insert(at, printable);
    } else {
        b[at] = printable;
    }
    String::from_utf8_lossy(&b).into_owned()
}
