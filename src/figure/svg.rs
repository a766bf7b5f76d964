//! A figure as an SVG element (inline in an HTML page, or a file beside a Markdown page):
//! y turned down, strokes black or the accent colour, faces white, an impulse's head open,
//! each label a `<text>` whose ink is centred on its box, in a serif italic, on a white box
//! and with a white halo (a white stroke painted under its glyphs) so a line passing under it
//! breaks there, as a textbook knocks the lines out behind its lettering.

use super::{Dashes, Figure, Ink, Mark, Stroke, FACE_OPACITY, FONT_SIZE};
use crate::print::markup;
use std::fmt::Write;

/// The width of the white stroke under a label's glyphs, in figure units.
const HALO: f64 = 3.0;
/// How far inside a label's box the white box knocked out behind it stands: about a unit
/// round its ink, as TikZ's `inner sep` leaves round a node's text.
const KNOCKED_OUT_INSET: f64 = 1.0;

/// The accent colour of the loads.
pub const ACCENT: &str = "#0b5cad";

/// The figure as an SVG file's one `<svg>` element, as wide as its drawing.
pub fn svg(figure: &Figure) -> String {
    element(figure, " xmlns=\"http://www.w3.org/2000/svg\"")
}

/// The figure as an `<svg>` element inside an HTML page (which needs no namespace, and so
/// names no address).
pub fn inline(figure: &Figure) -> String {
    element(figure, "")
}

fn element(figure: &Figure, namespace: &str) -> String {
    let (w, h) = (figure.max.x - figure.min.x, figure.max.y - figure.min.y);
    let mut out = format!(
        "<svg{namespace} class=\"figure\" width=\"{w:.0}\" height=\"{h:.0}\" viewBox=\"{:.2} {:.2} {w:.2} {h:.2}\" role=\"img\" aria-label=\"figure of the problem\">\n",
        figure.min.x, -figure.max.y
    );
    out.push_str("<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n");
    for mark in &figure.marks {
        self::mark(&mut out, mark);
    }
    out.push_str("</g>\n");
    // A white box behind each label, so that no line drawn under it runs on between its
    // glyphs (a dimension's line through `L − z₂` read as a plus), as the TikZ node's fill.
    out.push_str("<g fill=\"white\">\n");
    for label in &figure.labels {
        let (w, h) = (
            label.half_width - KNOCKED_OUT_INSET,
            label.half_height - KNOCKED_OUT_INSET,
        );
        let _ = writeln!(
            out,
            "<rect x=\"{:.2}\" y=\"{:.2}\" width=\"{:.2}\" height=\"{:.2}\"/>",
            label.centre.x - w,
            -label.centre.y - h,
            2.0 * w,
            2.0 * h
        );
    }
    out.push_str("</g>\n");
    let _ = writeln!(
        out,
        "<g font-family=\"'Latin Modern Roman', 'Times New Roman', serif\" font-style=\"italic\" font-size=\"{FONT_SIZE}\" text-anchor=\"middle\" stroke=\"white\" stroke-width=\"{HALO}\" stroke-linejoin=\"round\" paint-order=\"stroke\">"
    );
    for label in &figure.labels {
        // The baseline where the ink (a subscript's drop under it, an accent over it) is
        // centred on the box.
        let (text, ink) = markup::svg(&label.markup);
        let baseline = label.centre.y - (ink.above - ink.below) * FONT_SIZE / 2.0;
        let _ = writeln!(
            out,
            "<text x=\"{:.2}\" y=\"{:.2}\">{text}</text>",
            label.centre.x, -baseline
        );
    }
    out.push_str("</g>\n</svg>");
    out
}

fn colour(stroke: &Stroke) -> &'static str {
    match stroke.ink {
        Ink::Black => "black",
        Ink::Accent => ACCENT,
        Ink::Paper => "white",
    }
}

/// `stroke`, its width and its dashes as attributes.
fn stroke_attributes(stroke: &Stroke) -> String {
    let dashes = match stroke.dashes {
        Dashes::Solid => "",
        Dashes::Hidden => " stroke-dasharray=\"4 2.5\"",
        Dashes::CentreLine => " stroke-dasharray=\"6 3 1.5 3\"",
    };
    format!(
        "stroke=\"{}\" stroke-width=\"{}\"{dashes}",
        colour(stroke),
        stroke.width
    )
}

fn points(points: impl Iterator<Item = super::P2>) -> String {
    points
        .map(|p| format!("{:.2},{:.2}", p.x, -p.y))
        .collect::<Vec<_>>()
        .join(" ")
}

fn mark(out: &mut String, mark: &Mark) {
    match mark {
        Mark::Path {
            points: p,
            closed,
            filled,
            stroke,
        } => {
            let element = if *closed { "polygon" } else { "polyline" };
            let fill = match filled {
                true => format!(" fill=\"white\" fill-opacity=\"{FACE_OPACITY}\""),
                false => String::new(),
            };
            let _ = writeln!(
                out,
                "<{element} points=\"{}\"{fill} {}/>",
                points(p.iter().copied()),
                stroke_attributes(stroke)
            );
        }
        Mark::Arrow { stroke, role, .. } => {
            let _ = writeln!(
                out,
                "<polyline points=\"{}\" {}/>",
                points(mark.line().into_iter()),
                stroke_attributes(stroke)
            );
            let fill = match role.open_head() {
                true => "white",
                false => colour(stroke),
            };
            for head in mark.heads() {
                let _ = writeln!(
                    out,
                    "<polygon points=\"{}\" fill=\"{fill}\" stroke=\"{}\" stroke-width=\"1\"/>",
                    points(head.into_iter()),
                    colour(stroke)
                );
            }
        }
        Mark::Dot { at, radius } => {
            let _ = writeln!(
                out,
                "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"{radius}\" fill=\"black\"/>",
                at.x, -at.y
            );
        }
    }
}
