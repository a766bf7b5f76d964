//! A title's mathematics as the text of an SVG `<text>` element (a figure's label): letters
//! as they are (the element sets them in italics), a subscript or superscript a smaller
//! `<tspan>` shifted off the baseline, an accent its combining character (`φ̇`); and the
//! ink it takes, in ems — its width, and how far it stands above and below its baseline —
//! for placing it before any browser lays it out.

use super::parse::Node;
use super::text;

/// The width, in ems, of a character of words set upright (generous: the widest of Latin
/// Modern and DejaVu Serif, the fallback a browser may use).
const LETTER_EM: f64 = 0.62;
/// The advances, in ems, of Latin Modern Roman Italic's capitals A to Z and small letters a
/// to z (`lmroman10-italic.otf`, rounded up): a `W` is half as wide again as a letter's
/// [`LETTER_EM`], an `i` half as wide.
const CAPITALS_EM: [f64; 26] = [
    0.75, 0.71, 0.73, 0.77, 0.69, 0.66, 0.78, 0.75, 0.4, 0.54, 0.78, 0.64, 0.91, 0.75, 0.78, 0.69,
    0.78, 0.74, 0.57, 0.73, 0.75, 0.75, 1.01, 0.75, 0.75, 0.62,
];
const SMALL_EM: [f64; 26] = [
    0.52, 0.47, 0.47, 0.52, 0.47, 0.32, 0.47, 0.52, 0.32, 0.32, 0.47, 0.27, 0.83, 0.57, 0.52, 0.52,
    0.47, 0.43, 0.42, 0.34, 0.55, 0.47, 0.67, 0.47, 0.5, 0.42,
];
/// The advance of a letter the browser takes from another face (a Greek letter): the widest
/// of them, `ω` and `Δ`.
const OTHER_LETTER_EM: f64 = 0.82;
/// The widths, in ems, of a digit, an operator and a space, and the size of a script.
const DIGIT_EM: f64 = 0.6;
const OPERATOR_EM: f64 = 0.7;
const SPACE_EM: f64 = 0.25;
const THIN_SPACE_EM: f64 = 1.0 / 6.0;
const SCRIPT_SIZE: f64 = 0.7;
/// How far a subscript's baseline is lowered and a superscript's raised, in ems of the
/// script: near TeX's (a subscript's top at the letter's middle, not below its foot, which
/// is where a browser's `baseline-shift="sub"` sets it).
const SUBSCRIPT_DROP: f64 = 0.45;
const SUPERSCRIPT_RISE: f64 = 0.55;
/// How high, in ems, a capital or a tall letter stands, an accent over it, an operator; and
/// how low a letter with a descender (`y`, `φ`) or an operator reaches.
const LETTER_HEIGHT: f64 = 0.7;
const ACCENTED_HEIGHT: f64 = 0.92;
const OPERATOR_HEIGHT: f64 = 0.6;
const DESCENDER: f64 = 0.22;
const OPERATOR_DEPTH: f64 = 0.1;
/// The letters, Latin and Greek, whose descender reaches below the baseline.
const DESCENDING: &str = "fgjpqyβγζημξρςφχψ";

/// The ink of a piece of text, in ems: its width, and how far it stands above and reaches
/// below its baseline.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Ink {
    pub width: f64,
    pub above: f64,
    pub below: f64,
}

impl Ink {
    /// `self` and then `next` on the same baseline.
    pub(super) fn then(self, next: Ink) -> Ink {
        Ink {
            width: self.width + next.width,
            above: self.above.max(next.above),
            below: self.below.max(next.below),
        }
    }

    /// A script's ink: at [`SCRIPT_SIZE`], its baseline `rise` ems of the script above the
    /// line's (below where negative).
    fn script(self, rise: f64) -> Ink {
        let shift = rise * SCRIPT_SIZE;
        Ink {
            width: self.width * SCRIPT_SIZE,
            above: (self.above * SCRIPT_SIZE + shift).max(0.0),
            below: (self.below * SCRIPT_SIZE - shift).max(0.0),
        }
    }

    /// Plain text's ink: each character's width, its letters' height (more under an
    /// accent) and their descenders'.
    fn of_words(words: &str) -> Ink {
        words
            .chars()
            .map(|c| match c {
                c if c.is_alphabetic() => Ink {
                    width: advance(c),
                    above: LETTER_HEIGHT,
                    below: if DESCENDING.contains(c) {
                        DESCENDER
                    } else {
                        0.0
                    },
                },
                c if c.is_ascii_digit() => Ink {
                    width: DIGIT_EM,
                    above: LETTER_HEIGHT,
                    below: 0.0,
                },
                ' ' => Ink {
                    width: SPACE_EM,
                    ..Ink::default()
                },
                // A combining accent takes no room of its own, but stands over its letter.
                '\u{300}'..='\u{36f}' => Ink {
                    above: ACCENTED_HEIGHT,
                    ..Ink::default()
                },
                _ => Ink {
                    width: OPERATOR_EM,
                    above: OPERATOR_HEIGHT,
                    below: OPERATOR_DEPTH,
                },
            })
            .fold(Ink::default(), Ink::then)
    }
}

/// A letter's advance in ems: Latin Modern's for a Latin letter, else [`OTHER_LETTER_EM`].
fn advance(letter: char) -> f64 {
    match letter {
        'A'..='Z' => CAPITALS_EM[letter as usize - 'A' as usize],
        'a'..='z' => SMALL_EM[letter as usize - 'a' as usize],
        _ => OTHER_LETTER_EM,
    }
}

/// Words' ink: each character as wide as a letter (generous: words are set upright in a
/// proportional face, their spaces too), as high and as deep as their letters.
pub fn words(words: &str) -> Ink {
    Ink {
        width: words.chars().count() as f64 * LETTER_EM,
        ..Ink::of_words(words)
    }
}

/// Appends the nodes' SVG text; returns their ink. A function's argument stands a space
/// after its name, its parenthesis right after it (`sin pt`, `sin(pt)`).
pub fn maths(out: &mut String, nodes: &[Node]) -> Ink {
    let mut ink = Ink::default();
    for (k, node) in nodes.iter().enumerate() {
        ink = ink.then(one(out, node));
        let parenthesis = matches!(nodes.get(k + 1), Some(Node::Operator('(')));
        if matches!(node, Node::Function(_)) && !parenthesis {
            out.push(' ');
        }
    }
    ink
}

fn one(out: &mut String, node: &Node) -> Ink {
    match node {
        Node::Scripts { base, sub, sup } => {
            let mut ink = one(out, base);
            for (script, rise) in [(sub, -SUBSCRIPT_DROP), (sup, SUPERSCRIPT_RISE)] {
                if let Some(script) = script {
                    out.push_str(&format!(
                        "<tspan baseline-shift=\"{rise}em\" font-size=\"{}%\">",
                        (SCRIPT_SIZE * 100.0) as u32
                    ));
                    ink = ink.then(maths(out, script).script(rise));
                    out.push_str("</tspan>");
                }
            }
            ink
        }
        Node::Group(body) | Node::Face(_, body) => maths(out, body),
        Node::Function(name) => {
            // Apart from a factor before it (`M₀ sin pt`, not `M₀sin`).
            if !out.is_empty() && !out.ends_with(' ') {
                out.push(' ');
            }
            out.push_str("<tspan font-style=\"normal\">");
            out.push_str(name);
            out.push_str("</tspan>");
            Ink {
                width: (name.len() as f64 + 1.0) * DIGIT_EM,
                above: LETTER_HEIGHT,
                below: DESCENDER,
            }
        }
        // `\,` the thin space itself (U+2009), which SVG text does not collapse.
        Node::ThinSpace => {
            out.push('\u{2009}');
            Ink {
                width: THIN_SPACE_EM,
                ..Ink::default()
            }
        }
        // A relation stands apart by thin spaces, as TeX sets it (`ω₂ = Ω`).
        Node::Operator('=') => {
            out.push_str("\u{2009}=\u{2009}");
            Ink::of_words("=").then(Ink {
                width: 2.0 * THIN_SPACE_EM,
                ..Ink::default()
            })
        }
        // The minus sign, not the hyphen typed (`L − z₂`), as the HTML writer draws it.
        Node::Operator('-') => {
            out.push('−');
            Ink::of_words("−")
        }
        other => {
            let plain = text::maths(std::slice::from_ref(other));
            escaped(out, &plain);
            Ink::of_words(&plain)
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

#[cfg(test)]
mod tests {
    #[test]
    fn a_function_takes_its_parenthesis_without_a_space_and_a_bare_argument_with_one() {
        let (text, _) = crate::print::markup::svg(r"$M_0 \sin(p t)$");
        assert!(text.ends_with("sin</tspan>(pt)"), "{text}");
        let (text, _) = crate::print::markup::svg(r"$\sin \theta$");
        assert!(text.ends_with("sin</tspan> θ"), "{text}");
    }

    #[test]
    fn a_thin_space_is_kept_and_a_relation_stands_apart_by_thin_spaces() {
        let (text, spaced) = crate::print::markup::svg(r"$F\,\Delta t$");
        assert_eq!(text, "F\u{2009}Δt");
        let (_, tight) = crate::print::markup::svg(r"$F\Delta t$");
        assert!((spaced.width - tight.width - 1.0 / 6.0).abs() < 1e-12);
        let (text, _) = crate::print::markup::svg(r"$a=b$");
        assert_eq!(text, "a\u{2009}=\u{2009}b");
    }

    #[test]
    fn a_difference_is_written_with_the_minus_sign() {
        let (text, _) = crate::print::markup::svg("$L - z_2$");
        assert!(text.starts_with("L−z<tspan"), "{text}");
    }
}
