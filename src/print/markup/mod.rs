//! Titles with mathematics: words, and mathematics between `$…$` in a small LaTeX subset,
//! rendered in four notations from one tree ([`parse`]), and as a figure's SVG label ([`svg`]):
//!
//! ```
//! use kinetics::print::markup;
//! let title = r"rate relative to the rotating frame, $(\dot{\mathbf{H}}_G)_{Gxyz} = [I]\{\dot{\boldsymbol{\omega}}\}$";
//! assert_eq!(markup::text(title), "rate relative to the rotating frame, (Ḣ_G)_Gxyz = [I]{ω̇}");
//! assert_eq!(
//!     markup::latex(r"products of inertia positive, $\int xy\,dm$ (I_xy)"),
//!     r"products of inertia positive, $\int xy\,dm$ (I\_xy)"
//! );
//! assert_eq!(markup::markdown("about $O$, [I_O]"), r"about $O$, \[I\_O\]");
//! assert_eq!(markup::text(r"$M_0 \sin\theta$"), "M₀ sin θ");
//! assert_eq!(markup::html("$T$ & more"), "<math><mi>T</mi></math> &amp; more");
//! assert!(markup::validate(r"$\foo$").is_err());
//! ```
//!
//! The subset: letters, digits, `+ - = × · ( ) [ ] , . / | : ' < >`, `\{ \}`, scripts
//! `_x`, `_{Gxyz}`, `^2`, `^{T}`, and the commands of [`commands`]. A malformed title never
//! panics: every renderer shows it as words, escaped, and [`validate`] says why.

mod commands;
mod html;
mod latex;
mod markdown;
mod parse;
mod svg;
mod text;

pub use parse::{MarkupError, MarkupErrorKind};
use parse::{Node, Segment};
pub use svg::Ink;

/// Unicode plain text: `(Ḣ_G)_Gxyz = [I]{ω̇}`.
pub fn text(title: &str) -> String {
    render(title, text::words, |out, nodes| {
        out.push_str(&text::maths(nodes))
    })
}

/// LaTeX text mode: words escaped, each mathematics as `$…$` in the subset's one spelling;
/// a character pdflatex cannot set as its escape (`\u{202e}`), so the page compiles.
pub fn latex(title: &str) -> String {
    render(title, latex::words, |out, nodes| {
        out.push('$');
        latex::maths(out, nodes, latex::Notation::Latex);
        out.push('$');
    })
}

/// Plain words (no mathematics read in them) in LaTeX text mode, by the one escaper of
/// LaTeX's text: what [`latex`] does to a title's words.
pub fn latex_words(words: &str) -> String {
    let mut out = String::with_capacity(words.len() + words.len() / 4);
    latex::words(&mut out, words);
    out
}

/// Plain words in Markdown, by the one escaper of Markdown's words: what [`markdown`] does
/// to a title's words.
pub fn markdown_words(words: &str) -> String {
    let mut out = String::with_capacity(words.len() + words.len() / 4);
    markdown::words(&mut out, words);
    out
}

/// Markdown: words escaped for Markdown, each mathematics as `$…$` (LaTeX); no `<`, `>` or
/// `&` as itself anywhere, so no tag reaches a renderer.
pub fn markdown(title: &str) -> String {
    render(title, markdown::words, |out, nodes| {
        out.push('$');
        latex::maths(out, nodes, latex::Notation::Markdown);
        out.push('$');
    })
}

/// HTML: words escaped, each mathematics a `<math>` element (MathML Core).
pub fn html(title: &str) -> String {
    render(title, html::words, html::maths)
}

/// MathML inside a `<math>` element (a result said in words): words `<mtext>`, each
/// mathematics an `<mrow>`.
pub fn mathml(title: &str) -> String {
    render(title, html::words_in_maths, html::maths_in_maths)
}

/// The text of an SVG `<text>` element (a figure's label), and its ink in ems: words and
/// mathematics as text, a script a smaller `<tspan>` off the baseline.
pub fn svg(title: &str) -> (String, Ink) {
    let mut out = String::new();
    let mut ink = Ink::default();
    match parse::parse(title) {
        Ok(segments) => {
            for segment in &segments {
                match segment {
                    Segment::Words(w) => {
                        // Words upright in a label set in italics.
                        let mut plain = String::new();
                        text::words(&mut plain, w);
                        out.push_str("<tspan font-style=\"normal\">");
                        svg::escaped(&mut out, &plain);
                        out.push_str("</tspan>");
                        ink = ink.then(svg::words(&plain));
                    }
                    Segment::Maths(nodes) => ink = ink.then(svg::maths(&mut out, nodes)),
                }
            }
        }
        Err(_) => {
            let plain = visible_words(title);
            svg::escaped(&mut out, &plain);
            ink = svg::words(&plain);
        }
    }
    (out, ink)
}

fn visible_words(words: &str) -> String {
    let mut plain = String::new();
    text::words(&mut plain, words);
    plain
}

/// Whether the title is well formed: the first unknown command, unbalanced brace or `$`,
/// missing argument or character outside the subset, at its byte offset.
pub fn validate(title: &str) -> Result<(), MarkupError> {
    parse::parse(title).map(|_| ())
}

/// A title's words and mathematics, each through its renderer; a malformed title all words.
/// Mathematics with nothing in it is left out (`$$` would open display mathematics).
fn render(title: &str, words: fn(&mut String, &str), maths: fn(&mut String, &[Node])) -> String {
    let mut out = String::with_capacity(title.len() + title.len() / 2);
    match parse::parse(title) {
        Ok(segments) => {
            for segment in &segments {
                match segment {
                    Segment::Words(w) => words(&mut out, w),
                    Segment::Maths(nodes) if nodes.iter().all(|n| *n == Node::Blank) => {}
                    Segment::Maths(nodes) => maths(&mut out, nodes),
                }
            }
        }
        Err(_) => words(&mut out, title),
    }
    out
}
