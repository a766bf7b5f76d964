//! A title's mathematics as Unicode plain text: `\dot{\mathbf{H}}_G` → `Ḣ_G`, `\omega` → `ω`,
//! `_{Gxyz}` → `_Gxyz`, `_2` → `₂`, `^2` → `²`, `^T` → `ᵀ`, `^\circ` → `°`, `\frac12` → `½`,
//! `\int xy\,dm` → `∫xy dm`; bold is dropped, `=`, `+`, `×` … are spaced, a minus that
//! begins a term is not.

use super::commands::{is_spaced, Accent};
use super::parse::{is_sign, Node};
use crate::visible;

/// Words in plain text: as they are, but a character a reader cannot see (ESC, a
/// right-to-left override) as its escape `\u{1b}` ([`visible::escaped`]).
pub fn words(out: &mut String, words: &str) {
    out.push_str(&visible::escaped(words));
}

/// The text of a list of nodes.
pub fn maths(nodes: &[Node]) -> String {
    let mut out = String::new();
    let mut previous: Option<&Node> = None;
    let mut blank = false;
    for node in nodes {
        match node {
            Node::Blank => {
                blank = true;
                continue;
            }
            Node::Operator(c) if is_spaced(*c) && !is_sign(previous) => {
                out.truncate(out.trim_end().len());
                out.push(' ');
                out.push(*c);
                out.push(' ');
            }
            Node::Operator(c @ (',' | ':')) => {
                out.truncate(out.trim_end().len());
                out.push(*c);
                out.push(' ');
            }
            Node::ThinSpace => space(&mut out),
            other => {
                if blank {
                    space(&mut out);
                }
                one(&mut out, other);
            }
        }
        blank = false;
        previous = Some(node);
    }
    out.truncate(out.trim_end().len());
    out
}

/// One space, never two, never leading.
fn space(out: &mut String) {
    if !out.is_empty() && !out.ends_with(' ') {
        out.push(' ');
    }
}

fn one(out: &mut String, node: &Node) {
    match node {
        Node::Letter(c) | Node::Operator(c) => out.push(*c),
        Node::Number(digits) => out.push_str(digits),
        Node::Blank | Node::ThinSpace => space(out),
        Node::Face(_, body) | Node::Group(body) => out.push_str(&maths(body)),
        Node::Text(text) => words(out, text),
        Node::Function(name) => {
            out.push_str(name);
            out.push(' ');
        }
        Node::Accent(accent, body) => accented(out, *accent, &maths(body)),
        Node::Fraction {
            numerator,
            denominator,
            ..
        } => fraction(out, &maths(numerator), &maths(denominator)),
        Node::Scripts { base, sub, sup } => {
            one(out, base);
            if let Some(sub) = sub {
                script(out, &maths(sub), '_', subscript_of);
            }
            if let Some(sup) = sup {
                script(out, &maths(sup), '^', superscript_of);
            }
        }
    }
}

/// A letter with its accent: precomposed where Unicode has it (`Ḣ`, `ā`), else followed by
/// the combining accent (`ω̇`, `r̄`).
fn accented(out: &mut String, accent: Accent, base: &str) {
    const PRECOMPOSED: [(char, Accent, char); 6] = [
        ('H', Accent::Dot, 'Ḣ'),
        ('a', Accent::Bar, 'ā'),
        ('x', Accent::Dot, 'ẋ'),
        ('y', Accent::Dot, 'ẏ'),
        ('z', Accent::Dot, 'ż'),
        ('x', Accent::DoubleDot, 'ẍ'),
    ];
    let mut chars = base.chars();
    if let (Some(c), None) = (chars.next(), chars.next()) {
        if let Some(p) = PRECOMPOSED.iter().find(|p| p.0 == c && p.1 == accent) {
            out.push(p.2);
            return;
        }
    }
    out.push_str(base);
    out.push(accent.combining());
}

/// `½` for the vulgar fractions Unicode has, else `n/d` with a part of several terms
/// parenthesised.
fn fraction(out: &mut String, numerator: &str, denominator: &str) {
    const VULGAR: [(&str, &str, char); 8] = [
        ("1", "2", '½'),
        ("1", "3", '⅓'),
        ("2", "3", '⅔'),
        ("1", "4", '¼'),
        ("3", "4", '¾'),
        ("1", "5", '⅕'),
        ("1", "6", '⅙'),
        ("1", "8", '⅛'),
    ];
    if let Some(v) = VULGAR
        .iter()
        .find(|v| v.0 == numerator && v.1 == denominator)
    {
        out.push(v.2);
        return;
    }
    for (k, part) in [numerator, denominator].into_iter().enumerate() {
        if k == 1 {
            out.push('/');
        }
        let grouped = part.contains([' ', '/']);
        if grouped {
            out.push('(');
        }
        out.push_str(part);
        if grouped {
            out.push(')');
        }
    }
}

/// A script in Unicode sub- or superscript characters when each but a blank has one (`₂`,
/// `²`, `ᵀ`, `ⁿ⁺¹`), else
/// after `mark` (`_Gxyz`), parenthesised when it holds a space.
fn script(out: &mut String, text: &str, mark: char, small: fn(char) -> Option<char>) {
    let tight = text.chars().filter(|c| *c != ' ');
    if let Some(small) = tight.map(small).collect::<Option<String>>() {
        out.push_str(&small);
        return;
    }
    out.push(mark);
    if text.contains(' ') {
        out.push('(');
        out.push_str(text);
        out.push(')');
    } else {
        out.push_str(text);
    }
}

fn subscript_of(c: char) -> Option<char> {
    let digit = c.to_digit(10)?;
    char::from_u32(0x2080 + digit)
}

fn superscript_of(c: char) -> Option<char> {
    Some(match c {
        '1' => '¹',
        '2' => '²',
        '3' => '³',
        '0' | '4'..='9' => char::from_u32(0x2070 + c.to_digit(10)?)?,
        '+' => '⁺',
        '-' => '⁻',
        'T' => 'ᵀ',
        'n' => 'ⁿ',
        '∘' => '°',
        _ => return None,
    })
}
