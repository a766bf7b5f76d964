//! Where each label stands: tried beyond its anchor on the side it wants (an arrow's label
//! past its head), farther out and to either side step by step, then all round; the first
//! box that overlaps no label placed before it, no part of the body and no stroke wins, else
//! the one that overlaps least (another label weighs most, the body next, a stroke least).

use super::canvas::points_of;
use super::view::P2;
use super::{heads, Label, Mark, FONT_SIZE};
use crate::print::markup;

/// Room between a label's box and its text, and between its box and its anchor.
const PADDING: f64 = 2.5;
const GAPS: [f64; 6] = [2.0, 6.0, 11.0, 17.0, 25.0, 36.0];
const SHIFTS: [f64; 5] = [0.0, 1.0, -1.0, 2.0, -2.0];

/// A label asked for: its markup, the point it names and the side it would stand on.
pub struct Wanted {
    pub markup: String,
    pub anchor: P2,
    pub direction: P2,
}

/// The size of a label's box: its text's width and a line's height, padded.
pub fn half_size(markup_text: &str) -> (f64, f64) {
    let (_, em) = markup::svg(markup_text);
    (em * FONT_SIZE / 2.0 + PADDING, 0.62 * FONT_SIZE + PADDING)
}

/// Every wanted label placed among `marks`, in order.
pub fn place(wanted: &[Wanted], marks: &[Mark]) -> Vec<Label> {
    let strokes: Vec<(P2, P2)> = marks.iter().flat_map(segments).collect();
    let faces: Vec<&[P2]> = marks
        .iter()
        .filter_map(|m| match m {
            Mark::Path {
                points,
                filled: true,
                ..
            } => Some(&points[..]),
            _ => None,
        })
        .collect();
    let mut placed: Vec<Label> = Vec::new();
    for w in wanted {
        let (hw, hh) = half_size(&w.markup);
        let mut best: Option<(f64, P2)> = None;
        for centre in candidates(w, hw, hh) {
            let cost = overlap(centre, hw, hh, &placed, &faces, &strokes);
            if best.is_none_or(|(c, _)| cost < c) {
                best = Some((cost, centre));
            }
            if cost == 0.0 {
                break;
            }
        }
        let centre = best.map_or(w.anchor, |(_, c)| c);
        placed.push(Label {
            markup: w.markup.clone(),
            centre,
            half_width: hw,
            half_height: hh,
        });
    }
    placed
}

/// The centres tried, in order: along the wanted side, then the eight directions round.
fn candidates(w: &Wanted, hw: f64, hh: f64) -> Vec<P2> {
    let mut directions = vec![w.direction];
    directions.extend((0..8).map(|k| {
        let t = std::f64::consts::FRAC_PI_4 * f64::from(k);
        P2::new(t.cos(), t.sin())
    }));
    let mut out = Vec::new();
    for d in directions {
        let across = d.normal();
        // How far the box reaches along d from its centre.
        let reach = d.x.abs() * hw + d.y.abs() * hh;
        let step = across.x.abs() * hw + across.y.abs() * hh;
        for gap in GAPS {
            for shift in SHIFTS {
                out.push(
                    w.anchor
                        .plus(d.times(gap + reach))
                        .plus(across.times(shift * step)),
                );
            }
        }
    }
    out
}

/// How badly a box overlaps what is there: 100 a label, 10 a body's face, 1 a stroke.
fn overlap(
    c: P2,
    hw: f64,
    hh: f64,
    placed: &[Label],
    faces: &[&[P2]],
    strokes: &[(P2, P2)],
) -> f64 {
    let labels = placed
        .iter()
        .filter(|l| {
            (l.centre.x - c.x).abs() < l.half_width + hw
                && (l.centre.y - c.y).abs() < l.half_height + hh
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
    let crossed = strokes
        .iter()
        .filter(|(a, b)| crosses_box(*a, *b, c, hw, hh))
        .count();
    100.0 * labels as f64 + 10.0 * inside_faces as f64 + crossed as f64
}

/// The segments a mark draws: its path, its arrow's line and heads, a dot's box diagonal.
fn segments(mark: &Mark) -> Vec<(P2, P2)> {
    let chain = |points: &[P2], closed: bool| {
        let mut s: Vec<(P2, P2)> = points.windows(2).map(|w| (w[0], w[1])).collect();
        if closed && points.len() > 2 {
            s.push((points[points.len() - 1], points[0]));
        }
        s
    };
    match mark {
        Mark::Path { points, closed, .. } => chain(points, *closed),
        Mark::Arrow {
            from,
            via,
            to,
            double,
            ..
        } => {
            let mut line = vec![*from];
            line.extend(via);
            line.push(*to);
            let mut s = chain(&line, false);
            for head in heads(*from, via, *to, *double) {
                s.extend(chain(&head, true));
            }
            s
        }
        Mark::Dot { .. } => {
            let p = points_of(mark);
            vec![(p[0], p[1])]
        }
    }
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
