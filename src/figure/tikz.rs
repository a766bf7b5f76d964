//! A figure as a `tikzpicture` (TikZ, Debian's `texlive-pictures`), in the coordinates of the
//! SVG: a figure unit is ¾ pt, so the figure is as wide on paper as on screen and its labels
//! stand where they were placed; each label a node centred on its box, on white, so a line
//! passing under it breaks there.

use super::{Dashes, Figure, Ink, Mark, Stroke, FACE_OPACITY, P2};
use crate::print::markup;
use std::fmt::Write;

/// The accent colour of the loads, as xcolor spells it (the SVG's `#0b5cad`).
const ACCENT: &str = "{rgb,255:red,11;green,92;blue,173}";

/// The figure as a `tikzpicture` environment.
pub fn tikz(figure: &Figure) -> String {
    let mut out =
        String::from("\\begin{tikzpicture}[x=0.75pt,y=0.75pt,line cap=round,line join=round]\n");
    for mark in &figure.marks {
        self::mark(&mut out, mark);
    }
    for label in &figure.labels {
        let _ = writeln!(
            out,
            "\\node[inner sep=0.8pt,fill=white] at {} {{{}}};",
            point(label.centre),
            markup::latex(&label.markup)
        );
    }
    // The picture's bounding box is the figure's, labels and margin included.
    let _ = writeln!(
        out,
        "\\useasboundingbox {} rectangle {};",
        point(figure.min),
        point(figure.max)
    );
    out.push_str("\\end{tikzpicture}");
    out
}

fn point(p: P2) -> String {
    format!("({:.2},{:.2})", p.x, p.y)
}

fn colour(stroke: &Stroke) -> &'static str {
    match stroke.ink {
        Ink::Black => "black",
        Ink::Accent => ACCENT,
        Ink::Paper => "white",
    }
}

/// A stroke's options: its colour, its width in points, its dashes.
fn options(stroke: &Stroke) -> String {
    let dashes = match stroke.dashes {
        Dashes::Solid => "",
        Dashes::Hidden => ",dash pattern=on 3pt off 1.9pt",
        Dashes::CentreLine => ",dash pattern=on 4.5pt off 2.25pt on 1pt off 2.25pt",
    };
    format!(
        "draw={},line width={:.2}pt{dashes}",
        colour(stroke),
        stroke.width * 0.75
    )
}

fn chain(points: impl Iterator<Item = P2>) -> String {
    points.map(point).collect::<Vec<_>>().join(" -- ")
}

fn mark(out: &mut String, mark: &Mark) {
    match mark {
        Mark::Path {
            points,
            closed,
            filled,
            stroke,
        } => {
            let fill = match filled {
                true => format!(",fill=white,fill opacity={FACE_OPACITY}"),
                false => String::new(),
            };
            let cycle = if *closed { " -- cycle" } else { "" };
            let _ = writeln!(
                out,
                "\\path[{}{fill}] {}{cycle};",
                options(stroke),
                chain(points.iter().copied())
            );
        }
        Mark::Arrow { stroke, role, .. } => {
            let line = mark.line();
            let _ = writeln!(
                out,
                "\\path[{}] {};",
                options(stroke),
                chain(line.into_iter())
            );
            let fill = match role.open_head() {
                true => "white",
                false => colour(stroke),
            };
            for head in mark.heads() {
                let _ = writeln!(
                    out,
                    "\\path[draw={},fill={fill},line width=0.75pt] {} -- cycle;",
                    colour(stroke),
                    chain(head.into_iter())
                );
            }
        }
        Mark::Dot { at, radius } => {
            let _ = writeln!(out, "\\fill {} circle ({radius});", point(*at));
        }
    }
}
