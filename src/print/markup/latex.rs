//! A title in LaTeX text mode: its words escaped (`_ % & # { } ^ ~ \ < > |`, and a Greek
//! letter or a mathematical sign typed in the words set as `$\omega$`), its mathematics
//! written back from the tree, so only the subset reaches the page, in one spelling: braces
//! where an argument has more than one character, a space where a command would run into a
//! letter. A character pdflatex cannot set with the standalone page's packages (article,
//! amsmath, amssymb; OT1 fonts, UTF-8 input) is written as its escape `\u{4e2d}` in
//! typewriter letters: a control character, a right-to-left override, a letter of a script
//! the fonts lack (`中`, an emoji); the page always compiles.
//!
//! The same mathematics is written for a Markdown page ([`Notation::Markdown`]), where `<`,
//! `>` and `&` are the commands `\lt`, `\gt` and `\And`, so no tag reaches a renderer that
//! does not read `$…$` as mathematics.

use super::commands::{is_spaced, latex_of, Accent};
use super::parse::{is_sign, Node};

/// Words in LaTeX text mode (also `\text{…}`'s words). A run of Greek letters and signs is
/// one `$…$`; a combining accent after a letter or one of them puts the accent on it
/// (`ω̇` → `$\dot{\omega}$`).
pub fn words(out: &mut String, words: &str) {
    // Where the last letter or sign set in mathematics begins, while the mathematics is open.
    let mut maths_token: Option<usize> = None;
    let mut previous = None;
    for c in words.chars() {
        let accent = Accent::ALL.into_iter().find(|a| a.combining() == c);
        if let (Some(accent), Some(base)) = (accent, previous.filter(char::is_ascii_alphabetic)) {
            out.pop();
            open(out, &mut maths_token);
            maths_token = Some(out.len());
            word(out, &format!("\\{}{{{base}}}", accent.name()));
            out.push('$');
            previous = None;
            continue;
        }
        if let (Some(accent), Some(start)) = (accent, maths_token) {
            let token = out[start..out.len() - 1].to_string();
            out.truncate(start);
            out.push_str(&format!("\\{}{{{token}}}$", accent.name()));
            continue;
        }
        previous = Some(c);
        if let Some(command) = latex_of(c).filter(|_| !c.is_ascii()) {
            open(out, &mut maths_token);
            maths_token = Some(out.len());
            word(out, &command);
            out.push('$');
            continue;
        }
        maths_token = None;
        match c {
            '_' | '%' | '&' | '#' | '{' | '}' | '$' => {
                out.push('\\');
                out.push(c);
            }
            '^' => out.push_str(r"\^{}"),
            '~' => out.push_str(r"\~{}"),
            '\\' => out.push_str(r"\textbackslash{}"),
            // The OT1 fonts set `<` as `¡`, `>` as `¿` and `|` as an em dash.
            '<' => out.push_str(r"\textless{}"),
            '>' => out.push_str(r"\textgreater{}"),
            '|' => out.push_str(r"\textbar{}"),
            c if Accent::ALL.iter().any(|a| a.combining() == c) => {}
            c if sets(c) => out.push(c),
            // The escape `\u{1b}` of visible.rs, its backslash and braces in LaTeX.
            c => out.push_str(&format!(
                r"\texttt{{\textbackslash u\{{{:x}\}}}}",
                u32::from(c)
            )),
        }
    }
}

/// Whether pdflatex sets `c` in text with the standalone page's packages: printable ASCII
/// and the tab, and the Latin letters and signs of U+00A0 to U+017F and the punctuation its
/// UTF-8 input defines for the OT1 fonts (each compiled, `tests/suite/hostile_output.rs`),
/// but those OT1 lacks (`« » Ð Þ ð þ Ą ą Đ đ Ę ę Ħ ħ Į į ĸ Ŀ ŀ ŉ Ŋ ŋ Ŧ ŧ Ų ų ſ`).
pub fn sets(c: char) -> bool {
    const LACKING: &str = "«»ÐÞðþĄąĐđĘęĦħĮįĸĿŀŉŊŋŦŧŲųſ";
    const PUNCTUATION: &str = "–—‘’“”†‡•…‰€™";
    matches!(c, ' '..='~' | '\t')
        || (('\u{A0}'..='\u{17F}').contains(&c) && !LACKING.contains(c))
        || PUNCTUATION.contains(c)
}

/// Opens mathematics in words, or reopens the run just closed (its `$` taken back).
fn open(out: &mut String, maths_token: &mut Option<usize>) {
    if maths_token.is_some() {
        out.pop();
    } else {
        out.push('$');
    }
}

/// Where the mathematics is written: a LaTeX page, or a Markdown page (whose renderer may
/// not read `$…$` as mathematics, so `<`, `>` and `&` never appear as themselves).
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Notation {
    Latex,
    Markdown,
}

/// The mathematics of a list of nodes (without the `$`): a relation or binary operator with
/// one space each side (not a sign), other blanks as one space, none at either end.
pub fn maths(out: &mut String, nodes: &[Node], notation: Notation) {
    let start = out.len();
    let mut previous = None;
    for node in nodes {
        match node {
            Node::Blank => {
                if out.len() > start && !out.ends_with(' ') {
                    out.push(' ');
                }
                continue;
            }
            Node::Operator(c) if is_spaced(*c) && !is_sign(previous) => {
                if !out.ends_with(' ') {
                    out.push(' ');
                }
                one(out, node, notation);
                out.push(' ');
            }
            node => one(out, node, notation),
        }
        previous = Some(node);
    }
    out.truncate(start + out[start..].trim_end().len());
}

/// Appends `token`, after a space if it would otherwise lengthen a control word: `\omega x`.
fn word(out: &mut String, token: &str) {
    let letters = out.len()
        - out
            .trim_end_matches(|c: char| c.is_ascii_alphabetic())
            .len();
    let control_word = letters > 0 && out[..out.len() - letters].ends_with('\\');
    if control_word && token.starts_with(|c: char| c.is_ascii_alphabetic()) {
        out.push(' ');
    }
    out.push_str(token);
}

fn one(out: &mut String, node: &Node, notation: Notation) {
    match node {
        // In Markdown no character of the maths may make a tag or a link where `$` is not
        // read as maths: `<`, `>`, `[` and `]` are commands.
        Node::Operator(c @ ('<' | '>' | '[' | ']')) if notation == Notation::Markdown => word(
            out,
            match c {
                '<' => r"\lt",
                '>' => r"\gt",
                '[' => r"\lbrack",
                _ => r"\rbrack",
            },
        ),
        Node::Letter(c) | Node::Operator(c) => match latex_of(*c) {
            Some(command) => word(out, &command),
            None => word(out, c.encode_utf8(&mut [0; 4])),
        },
        Node::Number(digits) => out.push_str(digits),
        Node::Function(name) => word(out, &format!("\\{name}")),
        Node::Blank => out.push(' '),
        Node::ThinSpace => out.push_str(r"\,"),
        Node::Face(face, body) => command(out, face.name(), &[body], notation),
        Node::Accent(accent, body) => command(out, accent.name(), &[body], notation),
        Node::Fraction {
            small,
            numerator,
            denominator,
        } => command(
            out,
            if *small { "tfrac" } else { "frac" },
            &[numerator, denominator],
            notation,
        ),
        Node::Text(text) if notation == Notation::Markdown => {
            // `<`, `>` and `&` set in mathematics between the runs of words around them.
            let mut run = String::new();
            for c in text.chars().chain(std::iter::once('\0')) {
                let sign = match c {
                    '<' => r"\lt ",
                    '>' => r"\gt ",
                    '&' => r"\And ",
                    '\0' => "",
                    c => {
                        run.push(c);
                        continue;
                    }
                };
                if !run.is_empty() {
                    out.push_str(r"\text{");
                    words(out, &run);
                    out.push('}');
                    run.clear();
                }
                out.push_str(sign);
            }
        }
        Node::Text(text) => {
            out.push_str(r"\text{");
            words(out, text);
            out.push('}');
        }
        Node::Group(body) => braced(out, body, notation),
        Node::Scripts { base, sub, sup } => {
            one(out, base, notation);
            for (mark, script) in [('_', sub), ('^', sup)] {
                if let Some(script) = script {
                    out.push(mark);
                    let mut inner = String::new();
                    maths(&mut inner, script, notation);
                    if inner.chars().count() == 1 {
                        out.push_str(&inner);
                    } else {
                        out.push('{');
                        out.push_str(&inner);
                        out.push('}');
                    }
                }
            }
        }
    }
}

/// `\name{a}{b}`.
fn command(out: &mut String, name: &str, arguments: &[&Vec<Node>], notation: Notation) {
    out.push('\\');
    out.push_str(name);
    for argument in arguments {
        braced(out, argument, notation);
    }
}

fn braced(out: &mut String, nodes: &[Node], notation: Notation) {
    out.push('{');
    maths(out, nodes, notation);
    out.push('}');
}
