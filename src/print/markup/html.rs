//! A title in HTML: its words escaped (`& < > " '`, hidden characters as `\u{1b}`), its
//! mathematics as MathML Core in a `<math>` element: letters `<mi>` (upper-case Greek upright), numbers `<mn>`, operators
//! `<mo>`, `\,` an `<mspace>`, `\text` `<mtext>`, scripts `<msub>`/`<msup>`/`<msubsup>`,
//! `\frac` `<mfrac>`, accents `<mover accent="true">` with `¯` `˙` `¨`. A bold face is
//! `mathvariant="bold"` on letters already in Unicode's mathematical bold (𝐇, bold italic
//! 𝝎 for `\boldsymbol`), so a browser that reads only MathML Core shows it bold too.

use super::commands::{is_upper_greek, Face};
use super::parse::Node;
use crate::print::mathml::escaped;

/// Words in HTML, through the one HTML escaper ([`escaped`]).
pub fn words(out: &mut String, words: &str) {
    out.push_str(&escaped(words));
}

/// The mathematics of a list of nodes as one `<math>` element.
pub fn maths(out: &mut String, nodes: &[Node]) {
    out.push_str("<math>");
    list(out, nodes, None);
    out.push_str("</math>");
}

/// Words inside a `<math>` element, as `<mtext>`.
pub fn words_in_maths(out: &mut String, words: &str) {
    out.push_str("<mtext>");
    out.push_str(&escaped(words));
    out.push_str("</mtext>");
}

/// The mathematics of a list of nodes inside a `<math>` element, as one `<mrow>`.
pub fn maths_in_maths(out: &mut String, nodes: &[Node]) {
    row(out, nodes, None);
}

fn list(out: &mut String, nodes: &[Node], face: Option<Face>) {
    for node in nodes {
        one(out, node, face);
    }
}

/// A list as one element, as a script's or a fraction's part must be.
fn row(out: &mut String, nodes: &[Node], face: Option<Face>) {
    out.push_str("<mrow>");
    list(out, nodes, face);
    out.push_str("</mrow>");
}

fn one(out: &mut String, node: &Node, face: Option<Face>) {
    match node {
        Node::Letter(c) => letter(out, *c, face),
        Node::Number(digits) => element(out, "mn", digits),
        Node::Operator(c) => {
            // The minus sign and the prime, not the hyphen and the apostrophe typed.
            let c = match c {
                '-' => '−',
                '\'' => '′',
                c => *c,
            };
            if matches!(c, '(' | ')' | '[' | ']' | '{' | '}' | '|') {
                // A title's fences are inline, the height of the text: never stretched
                // around `{ω}ᵀ` as a display's would be.
                out.push_str(r#"<mo stretchy="false">"#);
                words(out, c.encode_utf8(&mut [0; 4]));
                out.push_str("</mo>");
            } else {
                element(out, "mo", c.encode_utf8(&mut [0; 4]));
            }
        }
        Node::Blank => {}
        Node::ThinSpace => out.push_str(r#"<mspace width="0.1667em"/>"#),
        Node::Face(face, body) => row(out, body, Some(*face)),
        Node::Text(text) => element(out, "mtext", text),
        // An identifier of several letters is upright.
        Node::Function(name) => element(out, "mi", name),
        Node::Group(body) => row(out, body, face),
        Node::Accent(accent, body) => {
            out.push_str(r#"<mover accent="true">"#);
            row(out, body, face);
            element(out, "mo", accent.spacing().encode_utf8(&mut [0; 4]));
            out.push_str("</mover>");
        }
        Node::Fraction {
            numerator,
            denominator,
            ..
        } => {
            out.push_str("<mfrac>");
            row(out, numerator, face);
            row(out, denominator, face);
            out.push_str("</mfrac>");
        }
        Node::Scripts { base, sub, sup } => {
            let tag = match (sub, sup) {
                (Some(_), Some(_)) => "msubsup",
                (Some(_), None) => "msub",
                _ => "msup",
            };
            out.push('<');
            out.push_str(tag);
            out.push('>');
            row(out, std::slice::from_ref(base), face);
            for script in [sub, sup].into_iter().flatten() {
                row(out, script, face);
            }
            out.push_str("</");
            out.push_str(tag);
            out.push('>');
        }
    }
}

/// `<tag>text</tag>`, the text escaped.
fn element(out: &mut String, tag: &str, text: &str) {
    out.push('<');
    out.push_str(tag);
    out.push('>');
    words(out, text);
    out.push_str("</");
    out.push_str(tag);
    out.push('>');
}

/// An identifier's letter in its face.
fn letter(out: &mut String, c: char, face: Option<Face>) {
    let (variant, shown) = match face {
        Some(Face::Bold) => ("bold", bold(c, false)),
        Some(Face::BoldSymbol) => ("bold", bold(c, !is_upper_greek(c))),
        Some(Face::Roman) => ("normal", c),
        None if is_upper_greek(c) => ("normal", c),
        None => ("", c),
    };
    if variant.is_empty() {
        out.push_str("<mi>");
    } else {
        out.push_str(&format!(r#"<mi mathvariant="{variant}">"#));
    }
    out.push(shown);
    out.push_str("</mi>");
}

/// The letter in Unicode's mathematical bold (`italic`: bold italic), the letter itself when
/// Unicode has no such form.
fn bold(c: char, italic: bool) -> char {
    let offset = |first: char, from: u32| char::from_u32(from + (c as u32 - first as u32));
    let shown = match (c, italic) {
        ('A'..='Z', false) => offset('A', 0x1D400),
        ('a'..='z', false) => offset('a', 0x1D41A),
        ('A'..='Z', true) => offset('A', 0x1D468),
        ('a'..='z', true) => offset('a', 0x1D482),
        ('Α'..='Ω', false) => offset('Α', 0x1D6A8),
        ('α'..='ω', false) => offset('α', 0x1D6C2),
        ('Α'..='Ω', true) => offset('Α', 0x1D71C),
        ('α'..='ω', true) => offset('α', 0x1D736),
        _ => None,
    };
    shown.unwrap_or(c)
}
