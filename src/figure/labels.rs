//! Where each label stands: near its anchor (an arrow's head, a point, an edge's middle), on
//! the side it wants if that is free. Every candidate round the anchor, ring by ring, is
//! scored — overlapping a label placed before it weighs most, then standing on the body,
//! then crossing a stroke, then standing nearer another label's anchor than its own (a reader
//! would give it to the wrong arrow), then its distance and its turn from the wanted side —
//! and the cheapest wins: a label crosses a thin line before it drifts away from its arrow.

use super::canvas::points_of;
use super::view::P2;
use super::{Label, Mark, Stroke, FONT_SIZE};
use crate::print::markup;

/// Room between a label's box and its text, and the least room between two labels' boxes.
const PADDING: f64 = 2.0;
const BETWEEN_LABELS: f64 = 3.0;
/// The gaps tried between the anchor and the box, and the turns from the wanted side.
const GAPS: [f64; 10] = [1.5, 4.0, 7.0, 10.0, 14.0, 19.0, 26.0, 34.0, 44.0, 56.0];
const TURNS_DEG: [f64; 10] = [
    0.0, 30.0, -30.0, 60.0, -60.0, 90.0, -90.0, 135.0, -135.0, 180.0,
];
/// What each fault costs, in figure units of distance.
const OVER_LABEL: f64 = 1000.0;
const ON_BODY: f64 = 40.0;
const CROSSING: f64 = 12.0;
const NEARER_ANOTHER: f64 = 80.0;
const PER_DEGREE: f64 = 0.08;
const PER_UNIT: f64 = 1.5;
/// Past this distance from its anchor, a label's distance costs its square too.
const FAR: f64 = 20.0;
const PER_FAR_SQUARED: f64 = 0.1;
/// How much more each unit away costs the label of a point or a part's size.
const POINT_TIGHTER: f64 = 2.5;

/// A label asked for: its markup, the point it names and the side it would stand on.
pub struct Wanted {
    pub markup: String,
    pub anchor: P2,
    pub direction: P2,
    pub names: Names,
}

/// What a label names, which decides where it may stand.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Names {
    /// An arrow or an axis: beside its anchor, off the body.
    Beside,
    /// Something on the body (G, a named point, a part's size): it hugs its anchor and may
    /// stand on a face.
    OnBody,
    /// A dimension: first of all on its own line at its middle, which the label's halo breaks,
    /// as a textbook sets a dimension's figure; it hugs its anchor.
    Dimension,
}

/// The size of a label's box: its text's width and a line's height (1.5 em: a serif's
/// ascent and descent with a subscript's drop), padded.
pub fn half_size(markup_text: &str) -> (f64, f64) {
    let (_, em) = markup::svg(markup_text);
    (em * FONT_SIZE / 2.0 + PADDING, 0.75 * FONT_SIZE + PADDING)
}

/// What a label is placed among: the strokes, the body's faces and every label's anchor.
struct Surroundings<'a> {
    /// Each drawn segment, with what crossing it costs (a rod more than a hairline).
    strokes: Vec<(P2, P2, f64)>,
    faces: Vec<&'a [P2]>,
    anchors: Vec<P2>,
}

/// Every wanted label placed among `marks`: the dimensions first, then the others in order.
pub fn place(wanted: &[Wanted], marks: &[Mark]) -> Vec<Label> {
    let around = Surroundings {
        strokes: marks.iter().flat_map(segments).collect(),
        faces: marks
            .iter()
            .filter_map(|m| match m {
                Mark::Path {
                    points,
                    filled: true,
                    ..
                } => Some(&points[..]),
                _ => None,
            })
            .collect(),
        anchors: wanted.iter().map(|w| w.anchor).collect(),
    };
    // The dimensions first, each on its line while that is free; then the rest, in order.
    let mut order: Vec<usize> = (0..wanted.len()).collect();
    order.sort_by_key(|k| wanted[*k].names != Names::Dimension);
    let mut placed: Vec<Label> = Vec::new();
    for (k, w) in order.iter().map(|k| (*k, &wanted[*k])) {
        let (hw, hh) = half_size(&w.markup);
        let mut best = (f64::INFINITY, w.anchor);
        for (centre, distance, turn) in candidates(w, hw, hh) {
            // A point's letter (G, O, A), a part's size or a dimension hugs what it names.
            let per_unit = match w.names {
                Names::Beside => PER_UNIT,
                Names::OnBody | Names::Dimension => PER_UNIT * POINT_TIGHTER,
            };
            // Far from its anchor a label no longer reads as its own: each unit costs more.
            let far = (distance - FAR).max(0.0);
            let cost = per_unit * distance
                + PER_FAR_SQUARED * far * far
                + PER_DEGREE * turn.abs()
                + faults(centre, (hw, hh), &placed, &around, (k, w));
            if cost < best.0 {
                best = (cost, centre);
            }
        }
        placed.push(Label {
            markup: w.markup.clone(),
            centre: best.1,
            half_width: hw,
            half_height: hh,
        });
    }
    // Back in the order asked for.
    let mut labels: Vec<Option<Label>> = (0..wanted.len()).map(|_| None).collect();
    for (k, label) in order.into_iter().zip(placed) {
        labels[k] = Some(label);
    }
    labels.into_iter().flatten().collect()
}

/// The centres tried round the anchor (a dimension's first on it), with their gap and turn
/// from the wanted side.
fn candidates(w: &Wanted, hw: f64, hh: f64) -> Vec<(P2, f64, f64)> {
    let mut out = Vec::new();
    if w.names == Names::Dimension {
        out.push((w.anchor, 0.0, 0.0));
    }
    for gap in GAPS {
        for turn in TURNS_DEG {
            let t = turn.to_radians();
            let (c, s) = (t.cos(), t.sin());
            let d = P2::new(
                w.direction.x * c - w.direction.y * s,
                w.direction.x * s + w.direction.y * c,
            );
            // How far the box reaches along d from its centre.
            let reach = d.x.abs() * hw + d.y.abs() * hh;
            out.push((w.anchor.plus(d.times(gap + reach)), gap, turn));
        }
    }
    out
}

/// The cost of a box's faults: labels it overlaps, faces it stands on, strokes it crosses,
/// (unless it names something on the body) and standing nearer another label's anchor than
/// label `own`'s.
fn faults(
    c: P2,
    (hw, hh): (f64, f64),
    placed: &[Label],
    around: &Surroundings,
    (own, w): (usize, &Wanted),
) -> f64 {
    let mine = around.anchors[own];
    let distance_to_box = |p: P2| {
        let dx = ((p.x - c.x).abs() - hw).max(0.0);
        let dy = ((p.y - c.y).abs() - hh).max(0.0);
        dx.hypot(dy)
    };
    let own_distance = distance_to_box(mine);
    let nearer_another = around.anchors.iter().enumerate().any(|(k, a)| {
        k != own
            && (a.x - mine.x).hypot(a.y - mine.y) > 1.0
            && distance_to_box(*a) + 2.0 < own_distance
    });
    // What stands on the body (its anchor on a face) is named on the body.
    let on_body = w.names == Names::OnBody || around.faces.iter().any(|f| inside(mine, f));
    let faces: &[&[P2]] = match on_body {
        true => &[],
        false => &around.faces,
    };
    // A dimension's own line, through its anchor, is broken by it, not crossed.
    let broken = (w.names == Names::Dimension).then_some(mine);
    overlap(c, (hw, hh), placed, faces, (&around.strokes, broken))
        + if nearer_another { NEARER_ANOTHER } else { 0.0 }
}

/// How badly a box overlaps what is there: a label, a body's face, a stroke (but those
/// through the point `broken`, a dimension's own line).
fn overlap(
    c: P2,
    (hw, hh): (f64, f64),
    placed: &[Label],
    faces: &[&[P2]],
    (strokes, broken): (&[(P2, P2, f64)], Option<P2>),
) -> f64 {
    let labels = placed
        .iter()
        .filter(|l| {
            (l.centre.x - c.x).abs() < l.half_width + hw + BETWEEN_LABELS
                && (l.centre.y - c.y).abs() < l.half_height + hh + BETWEEN_LABELS
        })
        .count();
    let corners = [
        P2::new(c.x - hw, c.y - hh),
        P2::new(c.x + hw, c.y - hh),
        P2::new(c.x + hw, c.y + hh),
        P2::new(c.x - hw, c.y + hh),
        c,
    ];
    let inside_faces = faces
        .iter()
        .filter(|f| corners.iter().any(|p| inside(*p, f)))
        .count();
    let crossed: f64 = strokes
        .iter()
        .filter(|(a, b, _)| crosses_box(*a, *b, c, hw, hh))
        .filter(|(a, b, _)| broken.is_none_or(|p| !through(p, *a, *b)))
        .map(|(_, _, weight)| weight)
        .sum();
    OVER_LABEL * labels as f64 + ON_BODY * inside_faces as f64 + CROSSING * crossed
}

/// The segments a mark draws (its path, its arrow's line and heads, a dot's box diagonal),
/// each weighted by its stroke's width against an outline's.
fn segments(mark: &Mark) -> Vec<(P2, P2, f64)> {
    let chain = |points: &[P2], closed: bool, weight: f64| {
        let mut s: Vec<(P2, P2, f64)> = points.windows(2).map(|w| (w[0], w[1], weight)).collect();
        if closed && points.len() > 2 {
            s.push((points[points.len() - 1], points[0], weight));
        }
        s
    };
    let weight = |stroke: &Stroke| (stroke.width / Stroke::OUTLINE.width).max(1.0);
    match mark {
        Mark::Path {
            points,
            closed,
            stroke,
            ..
        } => chain(points, *closed, weight(stroke)),
        Mark::Arrow { stroke, .. } => {
            let mut s = chain(&mark.line(), false, weight(stroke));
            for head in mark.heads() {
                s.extend(chain(&head, true, 1.0));
            }
            s
        }
        Mark::Dot { .. } => {
            let p = points_of(mark);
            vec![(p[0], p[1], 2.0)]
        }
    }
}

/// Whether the segment from `a` to `b` passes through the point `p` (within a hairline).
fn through(p: P2, a: P2, b: P2) -> bool {
    let d = b.minus(a);
    let t = ((p.x - a.x) * d.x + (p.y - a.y) * d.y) / (d.x * d.x + d.y * d.y).max(1e-300);
    let foot = a.plus(d.times(t.clamp(0.0, 1.0)));
    foot.minus(p).length() < 0.5
}

/// Whether `p` is inside the polygon (even-odd).
fn inside(p: P2, polygon: &[P2]) -> bool {
    let mut inside = false;
    let n = polygon.len();
    for i in 0..n {
        let (a, b) = (polygon[i], polygon[(i + n - 1) % n]);
        if (a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x {
            inside = !inside;
        }
    }
    inside
}

/// Whether the segment from `a` to `b` meets the box about `c` (Liang–Barsky).
fn crosses_box(a: P2, b: P2, c: P2, hw: f64, hh: f64) -> bool {
    let d = b.minus(a);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, a.x - (c.x - hw)),
        (d.x, (c.x + hw) - a.x),
        (-d.y, a.y - (c.y - hh)),
        (d.y, (c.y + hh) - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_through_a_box_crosses_it_one_beside_it_does_not() {
        let c = P2::new(0.0, 0.0);
        assert!(crosses_box(
            P2::new(-5.0, 0.0),
            P2::new(5.0, 0.5),
            c,
            1.0,
            1.0
        ));
        assert!(!crosses_box(
            P2::new(-5.0, 2.0),
            P2::new(5.0, 2.0),
            c,
            1.0,
            1.0
        ));
        assert!(inside(
            c,
            &[P2::new(-1.0, -1.0), P2::new(1.0, -1.0), P2::new(0.0, 1.0)]
        ));
    }
}
