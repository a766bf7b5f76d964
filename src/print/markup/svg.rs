//! A title's mathematics as the text of an SVG `<text>` element (a figure's label): letters
//! as they are (the element sets them in italics), a subscript or superscript a smaller
//! `<tspan>` shifted off the baseline, an accent its combining character (`φ̇`); and the
//! width it takes, in ems, for placing it before any browser lays it out.

use super::parse::Node;
use super::text;

/// The widths, in ems, of a serif italic's letter, digit, operator and space (generous: the
/// widest of Latin Modern and DejaVu Serif, the fallback a browser may use), and the size
/// of a script.
const LETTER_EM: f64 = 0.62;
const DIGIT_EM: f64 = 0.6;
const OPERATOR_EM: f64 = 0.7;
const SPACE_EM: f64 = 0.25;
const SCRIPT_SIZE: f64 = 0.7;

/// Appends the nodes' SVG text; returns their width in ems.
pub fn maths(out: &mut String, nodes: &[Node]) -> f64 {
    nodes.iter().map(|n| one(out, n)).sum()
}

fn one(out: &mut String, node: &Node) -> f64 {
    match node {
        Node::Scripts { base, sub, sup } => {
            let mut width = one(out, base);
            for (script, shift) in [(sub, "sub"), (sup, "super")] {
                if let Some(script) = script {
                    out.push_str(&format!(
                        "<tspan baseline-shift=\"{shift}\" font-size=\"{}%\">",
                        (SCRIPT_SIZE * 100.0) as u32
                    ));
                    width += SCRIPT_SIZE * maths(out, script);
                    out.push_str("</tspan>");
                }
            }
            width
        }
        Node::Group(body) | Node::Face(_, body) => maths(out, body),
        Node::Function(name) => {
            // Apart from a factor before it (`M₀ sin pt`, not `M₀sin`).
            if !out.is_empty() && !out.ends_with(' ') {
                out.push(' ');
            }
            out.push_str("<tspan font-style=\"normal\">");
            out.push_str(name);
            out.push_str("</tspan> ");
            (name.len() as f64 + 1.0) * DIGIT_EM
        }
        // The minus sign, not the hyphen typed (`L − z₂`), as the HTML writer draws it.
        Node::Operator('-') => {
            out.push('−');
            OPERATOR_EM
        }
        other => {
            let plain = text::maths(std::slice::from_ref(other));
            escaped(out, &plain);
            plain
                .chars()
                .map(|c| match c {
                    c if c.is_alphabetic() => LETTER_EM,
                    c if c.is_ascii_digit() => DIGIT_EM,
                    ' ' => SPACE_EM,
                    // A combining accent takes no room of its own.
                    '\u{300}'..='\u{36f}' => 0.0,
                    _ => OPERATOR_EM,
                })
                .sum()
        }
    }
}

/// Words as SVG text: `& < >` as references.
pub fn escaped(out: &mut String, words: &str) {
    for c in words.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            c => out.push(c),
        }
    }
}

/// Words' width in ems.
pub fn words_em(words: &str) -> f64 {
    words.chars().count() as f64 * LETTER_EM
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_difference_is_written_with_the_minus_sign() {
        let (text, _) = crate::print::markup::svg("$L - z_2$");
        assert!(text.starts_with("L−z<tspan"), "{text}");
    }
}
