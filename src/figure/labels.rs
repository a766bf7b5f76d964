//! Where each label stands: near its anchor (an arrow's head, a point, an edge's middle, or
//! any point of a part's side it names), on the side it wants if that is free. Each label's
//! spots round its anchor, ring by ring, are scored — standing too close to another label
//! weighs most, then standing on the body, then crossing a stroke (a load's arrow or a rod
//! more than a hairline), then standing nearer another label's anchor than its own (a reader
//! would give it to the wrong arrow), then its distance and its turn from the wanted side —
//! and the placing of all of them together is made cheap: each placed in turn, then annealed
//! from each of a few fixed seeds and polished by single and paired moves, the cheapest kept,
//! so a point's letter does not take the spot an arrow's label needs and push it far away.

use super::canvas::points_of;
use super::view::P2;
use super::{Ink, Label, Mark, Role, Stroke, FONT_SIZE};
use crate::numeric::splitmix::SplitMix64;
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
const CROSSING: f64 = 25.0;
const NEARER_ANOTHER: f64 = 80.0;
const PER_DEGREE: f64 = 0.08;
const PER_UNIT: f64 = 1.5;
/// How many times more crossing a bar (a rod, the shaft) costs than crossing a line as wide.
const BAR_CUT: f64 = 4.0;
/// How near its anchor a line passes that does not part a label from it (a line through
/// the anchor).
const THROUGH_ANCHOR: f64 = 1.5;
/// Past this distance from its anchor, a label's distance costs its square too.
const FAR: f64 = 20.0;
const PER_FAR_SQUARED: f64 = 0.1;
/// How much more each unit away costs the label of a point or a part's size.
const POINT_TIGHTER: f64 = 2.5;
/// The shares of its slide a size's label may stand off its side's middle, and what each unit
/// along its side costs against a unit away from it.
const SLIDES: [f64; 5] = [0.0, -0.5, 0.5, -1.0, 1.0];
const PER_UNIT_ALONG: f64 = 0.5;

/// A label asked for: its markup, the point it names and the side it would stand on. A
/// part's size names a stretch of its side (`anchor ± slide`), along which its label may move
/// off the middle where that is crowded (a rod's middle where another rod crosses it).
pub struct Wanted {
    pub markup: String,
    pub anchor: P2,
    pub slide: P2,
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
    /// as a textbook sets a dimension's figure; else beside it, as freely as an arrow's
    /// label (just outside its line reads as well as on it).
    Dimension,
}

/// Half the size of a label's box: its text's ink (its width, its height above the baseline
/// and its depth below, a subscript's drop and an accent included), padded; so a plain `G`
/// stands as near its anchor as it looks, and `B_y` is no further from its arrow's head
/// than its letters are.
pub fn half_size(markup_text: &str) -> (f64, f64) {
    let (_, ink) = markup::svg(markup_text);
    (
        ink.width * FONT_SIZE / 2.0 + PADDING,
        (ink.above + ink.below) * FONT_SIZE / 2.0 + PADDING,
    )
}

/// What a label is placed among: the strokes, the body's faces and every label's anchor.
struct Surroundings<'a> {
    /// Each drawn segment, with what crossing it costs (a rod more than a hairline).
    strokes: Vec<(P2, P2, f64)>,
    faces: Vec<&'a [P2]>,
    anchors: Vec<P2>,
}

/// Every wanted label placed among `marks`, so that the sum of their costs is low: each
/// placed in turn (the dimensions first, then the others in order) where it costs least among
/// those placed before it, then the placing annealed and improved until no label gains by
/// moving alone or by moving the one label that stands where it would rather be (a point's
/// letter sitting on an arrow's free end, which pushed the arrow's label far away).
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
    let sizes: Vec<(f64, f64)> = wanted.iter().map(|w| half_size(&w.markup)).collect();
    let spots = wanted
        .iter()
        .enumerate()
        .map(|(k, w)| spots(w, sizes[k], &around, k))
        .collect();
    let mut layout = Layout {
        spots,
        sizes,
        chosen: vec![None; wanted.len()],
    };
    // The dimensions first, each on its line while that is free; then the rest, in order.
    let mut order: Vec<usize> = (0..wanted.len()).collect();
    order.sort_by_key(|k| wanted[*k].names != Names::Dimension);
    for k in order {
        layout.chosen[k] = Some(layout.cheapest(k));
    }
    layout.improve();
    wanted
        .iter()
        .enumerate()
        .map(|(k, w)| Label {
            markup: w.markup.clone(),
            centre: layout.chosen[k].map_or(w.anchor, |s| layout.spots[k][s].centre),
            half_width: layout.sizes[k].0,
            half_height: layout.sizes[k].1,
        })
        .collect()
}

/// Where a label may stand, and what standing there costs before other labels are counted.
struct Spot {
    centre: P2,
    cost: f64,
}

/// The spots of every label round its anchor, with their costs: its distance (more for what
/// hugs its anchor, and past [`FAR`] its square too), its turn from the wanted side, and its
/// faults among the strokes, the faces and the other anchors.
fn spots(w: &Wanted, (hw, hh): (f64, f64), around: &Surroundings, own: usize) -> Vec<Spot> {
    // A point's letter (G, O, A) or a part's size hugs what it names.
    let per_unit = match w.names {
        Names::Beside | Names::Dimension => PER_UNIT,
        Names::OnBody => PER_UNIT * POINT_TIGHTER,
    };
    candidates(w, hw, hh)
        .into_iter()
        .map(
            |Candidate {
                 centre,
                 anchor,
                 gap,
                 turn,
             }| {
                // Far from its anchor a label no longer reads as its own: each unit costs more.
                let far = (gap - FAR).max(0.0);
                let along = anchor.minus(w.anchor).length();
                let cost = per_unit * (gap + PER_UNIT_ALONG * along)
                    + PER_FAR_SQUARED * far * far
                    + PER_DEGREE * turn.abs()
                    + faults(centre, (hw, hh), around, (own, anchor, w));
                Spot { centre, cost }
            },
        )
        .collect()
}

/// The labels' spots and the one each stands on; the cost of a placing is the sum of its
/// spots' costs and [`OVER_LABEL`] for each pair of labels too close.
struct Layout {
    spots: Vec<Vec<Spot>>,
    sizes: Vec<(f64, f64)>,
    chosen: Vec<Option<usize>>,
}

/// Sweeps of [`Layout::improve`] at most (each lowers the cost; a few settle it).
const SWEEPS: usize = 12;
/// A move must gain more than this to be made.
const GAIN: f64 = 1e-9;
/// The annealing's schedule: its first temperature (a rise of this cost is taken one time in
/// e), the share kept each round, the tries a round makes for each label, and the seed of its
/// draws.
const HOT: f64 = 200.0;
const COOLING: f64 = 0.9;
/// Where the annealing stops (a rise of one unit of cost taken one time in e; the polish
/// after it finds the nearest minimum), and a rise so large against the temperature that it
/// is never taken (`exp(−20)`).
const COLD: f64 = 1.0;
const HOPELESS: f64 = 20.0;
const TRIES_PER_LABEL: usize = 30;
const SEED: u64 = 0x6b69_6e65_7469_6373;
/// The annealings run, from seeds [`SEED`] on.
const RUNS: u64 = 8;

impl Layout {
    /// Whether label `a` on spot `sa` and label `b` on spot `sb` stand too close.
    fn clash(&self, (a, sa): (usize, usize), (b, sb): (usize, usize)) -> bool {
        let (ca, cb) = (self.spots[a][sa].centre, self.spots[b][sb].centre);
        let ((wa, ha), (wb, hb)) = (self.sizes[a], self.sizes[b]);
        (ca.x - cb.x).abs() < wa + wb + BETWEEN_LABELS
            && (ca.y - cb.y).abs() < ha + hb + BETWEEN_LABELS
    }

    /// The placed labels other than `k` that label `k` on spot `s` clashes with.
    fn clashes(&self, k: usize, s: usize) -> impl Iterator<Item = usize> + '_ {
        self.chosen
            .iter()
            .enumerate()
            .filter_map(move |(j, chosen)| {
                let sj = (*chosen)?;
                (j != k && self.clash((k, s), (j, sj))).then_some(j)
            })
    }

    /// What label `k` costs on spot `s` among the labels placed.
    fn cost(&self, k: usize, s: usize) -> f64 {
        self.spots[k][s].cost + OVER_LABEL * self.clashes(k, s).count() as f64
    }

    /// The spot where label `k` costs least among the labels placed (the first of equals).
    fn cheapest(&self, k: usize) -> usize {
        (0..self.spots[k].len())
            .map(|s| (s, self.cost(k, s)))
            .fold((0, f64::INFINITY), |best, (s, c)| match c < best.1 {
                true => (s, c),
                false => best,
            })
            .0
    }

    /// From the placing made, anneals and polishes once for each of [`RUNS`] seeds and keeps
    /// the cheapest placing (one annealing's luck decides less).
    fn improve(&mut self) {
        let start = self.chosen.clone();
        let mut best: Option<(f64, Vec<Option<usize>>)> = None;
        for run in 0..RUNS {
            self.chosen = start.clone();
            self.anneal(SEED.wrapping_add(run));
            self.polish();
            let total = self.total();
            if best.as_ref().is_none_or(|(b, _)| total < b - GAIN) {
                best = Some((total, self.chosen.clone()));
            }
        }
        if let Some((_, chosen)) = best {
            self.chosen = chosen;
        }
    }

    /// What the placing costs: each label's cost where it stands.
    fn total(&self) -> f64 {
        (0..self.chosen.len())
            .filter_map(|k| self.chosen[k].map(|s| self.cost(k, s)))
            .sum()
    }

    /// Moves labels while the placing's cost falls: a label alone to its cheapest spot, or a
    /// label to a spot where one other label stands in its way, that one moved to its own
    /// cheapest spot, when the two together gain.
    fn polish(&mut self) {
        for _ in 0..SWEEPS {
            let mut moved = false;
            for k in 0..self.chosen.len() {
                moved |= self.move_alone(k) || self.move_with_blocker(k);
            }
            if !moved {
                return;
            }
        }
    }

    /// Simulated annealing, as Christensen, Marks and Shieber found best for placing labels
    /// (*An empirical study of algorithms for point-feature label placement*, ACM Transactions
    /// on Graphics 14 (1995)): a label drawn at random tries a spot drawn at random, taken when
    /// the placing's cost falls and, when it rises by `Δ`, with probability `exp(−Δ/T)`; the
    /// temperature `T` falls by [`COOLING`] each round of [`TRIES_PER_LABEL`] tries a label,
    /// from [`HOT`] to [`COLD`] or until a round takes nothing. The cheapest placing met is
    /// kept. The draws come from a fixed seed: the same figure every time.
    fn anneal(&mut self, seed: u64) {
        let n = self.chosen.len();
        if n < 2 || self.chosen.contains(&None) {
            return;
        }
        let mut random = SplitMix64(seed);
        let (mut total, mut best_total, mut best) = (0.0, 0.0, self.chosen.clone());
        // What each label costs where it stands, kept as labels move.
        let mut now: Vec<f64> = (0..n)
            .map(|k| self.chosen[k].map_or(0.0, |at| self.cost(k, at)))
            .collect();
        let mut temperature = HOT;
        while temperature >= COLD {
            let mut taken = 0;
            for _ in 0..TRIES_PER_LABEL * n {
                let k = random.below(n);
                let s = random.below(self.spots[k].len());
                let Some(at) = self.chosen[k] else {
                    continue;
                };
                // A spot dearer on its own than the label is now by far is not taken.
                if self.spots[k][s].cost - now[k] > HOPELESS * temperature {
                    continue;
                }
                let rise = self.cost(k, s) - now[k];
                if rise <= 0.0 || random.unit() < (-rise / temperature).exp() {
                    for j in (0..n).filter(|j| *j != k) {
                        let Some(sj) = self.chosen[j] else {
                            continue;
                        };
                        if self.clash((k, at), (j, sj)) {
                            now[j] -= OVER_LABEL;
                        }
                        if self.clash((k, s), (j, sj)) {
                            now[j] += OVER_LABEL;
                        }
                    }
                    now[k] += rise;
                    self.chosen[k] = Some(s);
                    total += rise;
                    taken += 1;
                    if total < best_total - GAIN {
                        (best_total, best) = (total, self.chosen.clone());
                    }
                }
            }
            temperature *= COOLING;
            if taken == 0 {
                break;
            }
        }
        self.chosen = best;
    }

    fn move_alone(&mut self, k: usize) -> bool {
        let Some(now) = self.chosen[k] else {
            return false;
        };
        let best = self.cheapest(k);
        let gains = self.cost(k, best) < self.cost(k, now) - GAIN;
        if gains {
            self.chosen[k] = Some(best);
        }
        gains
    }

    /// Label `k` to the spot that gains most when the one label in its way moves too.
    fn move_with_blocker(&mut self, k: usize) -> bool {
        let Some(now) = self.chosen[k] else {
            return false;
        };
        let before_k = self.cost(k, now);
        let mut best: Option<(f64, usize, usize, usize)> = None;
        for s in 0..self.spots[k].len() {
            if self.spots[k][s].cost >= before_k - GAIN {
                continue;
            }
            let blockers: Vec<usize> = self.clashes(k, s).take(2).collect();
            let [j] = blockers[..] else {
                continue;
            };
            let Some(now_j) = self.chosen[j] else {
                continue;
            };
            let shared = |clash: bool| if clash { OVER_LABEL } else { 0.0 };
            let before = before_k + self.cost(j, now_j) - shared(self.clash((k, now), (j, now_j)));
            self.chosen[k] = Some(s);
            let to = self.cheapest(j);
            let after = self.cost(k, s) + self.cost(j, to) - shared(self.clash((k, s), (j, to)));
            self.chosen[k] = Some(now);
            let gain = before - after;
            if gain > GAIN && best.is_none_or(|(g, ..)| gain > g) {
                best = Some((gain, s, j, to));
            }
        }
        let Some((_, s, j, to)) = best else {
            return false;
        };
        self.chosen[k] = Some(s);
        self.chosen[j] = Some(to);
        true
    }
}

/// A centre tried for a label: the point of its anchor's stretch it stands by, its gap from
/// that point and its turn from the wanted side.
struct Candidate {
    centre: P2,
    anchor: P2,
    gap: f64,
    turn: f64,
}

/// The centres tried round the anchor and the points of its stretch (a dimension's first on
/// it).
fn candidates(w: &Wanted, hw: f64, hh: f64) -> Vec<Candidate> {
    let mut out = Vec::new();
    if w.names == Names::Dimension {
        out.push(Candidate {
            centre: w.anchor,
            anchor: w.anchor,
            gap: 0.0,
            turn: 0.0,
        });
    }
    let slides = match w.slide.length() > 0.0 {
        true => &SLIDES[..],
        false => &SLIDES[..1],
    };
    for anchor in slides.iter().map(|k| w.anchor.plus(w.slide.times(*k))) {
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
                out.push(Candidate {
                    centre: anchor.plus(d.times(gap + reach)),
                    anchor,
                    gap,
                    turn,
                });
            }
        }
    }
    out
}

/// The cost of a box's faults apart from other labels: faces it stands on (unless it names
/// something on the body), strokes it crosses (but a dimension's own line, which it breaks),
/// and standing nearer another label's anchor than label `own`'s (standing by `mine`, its
/// anchor or a point of its stretch).
fn faults(
    c: P2,
    (hw, hh): (f64, f64),
    around: &Surroundings,
    (own, mine, w): (usize, P2, &Wanted),
) -> f64 {
    let distance_to_box = |p: P2| {
        let dx = ((p.x - c.x).abs() - hw).max(0.0);
        let dy = ((p.y - c.y).abs() - hh).max(0.0);
        (dx * dx + dy * dy).sqrt()
    };
    let own_distance = distance_to_box(mine);
    let nearer_another = around.anchors.iter().enumerate().any(|(k, a)| {
        k != own
            && (a.x - mine.x).powi(2) + (a.y - mine.y).powi(2) > 1.0
            && distance_to_box(*a) + 2.0 < own_distance
    });
    // What stands on the body (its anchor on a face) is named on the body.
    let on_body = w.names == Names::OnBody || around.faces.iter().any(|f| inside(mine, f));
    let corners = [
        P2::new(c.x - hw, c.y - hh),
        P2::new(c.x + hw, c.y - hh),
        P2::new(c.x + hw, c.y + hh),
        P2::new(c.x - hw, c.y + hh),
        c,
    ];
    let inside_faces = match on_body {
        true => 0,
        false => around
            .faces
            .iter()
            .filter(|f| corners.iter().any(|p| inside(*p, f)))
            .count(),
    };
    let broken = (w.names == Names::Dimension).then_some(mine);
    let crossed: f64 = around
        .strokes
        .iter()
        // Most strokes are nowhere near: their extents do not meet the box.
        .filter(|(a, b, _)| {
            a.x.max(b.x) >= c.x - hw
                && a.x.min(b.x) <= c.x + hw
                && a.y.max(b.y) >= c.y - hh
                && a.y.min(b.y) <= c.y + hh
        })
        .filter(|(a, b, _)| crosses_box(*a, *b, c, hw, hh))
        .filter(|(a, b, _)| broken.is_none_or(|p| !through(p, *a, *b)))
        .map(|(_, _, weight)| weight)
        .sum();
    // A stroke between the label and what it names (an arrow passing between G's dot and
    // its letter) parts them: the letter reads as the arrow's. Lines through the anchor (G's
    // axes, a rod it lies on, its own arrow) do not.
    let nearest = P2::new(
        mine.x.clamp(c.x - hw, c.x + hw),
        mine.y.clamp(c.y - hh, c.y + hh),
    );
    let parted: f64 = around
        .strokes
        .iter()
        .filter(|(a, b, _)| !near_segment(mine, *a, *b, THROUGH_ANCHOR))
        .filter(|(a, b, _)| segments_cross(mine, nearest, *a, *b))
        .map(|(_, _, weight)| weight)
        .sum();
    ON_BODY * inside_faces as f64
        + CROSSING * (crossed + parted)
        + if nearer_another { NEARER_ANOTHER } else { 0.0 }
}

/// The segments a mark draws (its path, its arrow's line and heads, a dot's box diagonal),
/// each weighted by its stroke's width against an outline's (a bar's [`BAR_CUT`] times
/// more), a vector's arrow (not an axis) as a rod.
fn segments(mark: &Mark) -> Vec<(P2, P2, f64)> {
    let chain = |points: &[P2], closed: bool, weight: f64| {
        let mut s: Vec<(P2, P2, f64)> = points.windows(2).map(|w| (w[0], w[1], weight)).collect();
        if closed && points.len() > 2 {
            s.push((points[points.len() - 1], points[0], weight));
        }
        s
    };
    // A bar (a rod, the shaft) under a label is cut by its white box: the rod reads as two.
    let weight = |stroke: &Stroke| match stroke.width >= Stroke::SHAFT.width {
        true => BAR_CUT * stroke.width / Stroke::OUTLINE.width,
        false => (stroke.width / Stroke::OUTLINE.width).max(1.0),
    };
    // A vector's arrow (a load, ω, v̄; not an axis) under a label reads as labelled by it,
    // and is cut by its box: as costly as a rod.
    let vector = weight(&Stroke::ROD);
    match mark {
        // A band of paper under a rod is nothing a label can stand on.
        Mark::Path { stroke, .. } if stroke.ink == Ink::Paper => Vec::new(),
        Mark::Path {
            points,
            closed,
            stroke,
            ..
        } => chain(points, *closed, weight(stroke)),
        Mark::Arrow { stroke, role, .. } => {
            let line = match role {
                Role::Axis => weight(stroke),
                _ => vector,
            };
            let mut s = chain(&mark.line(), false, line);
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
    near_segment(p, a, b, 0.5)
}

/// Whether the segment from `a` to `b` passes within `within` of the point `p`.
fn near_segment(p: P2, a: P2, b: P2, within: f64) -> bool {
    p.to_segment(a, b) < within
}

/// Whether the segments `p q` and `a b` cross (each one's ends on either side of the other).
fn segments_cross(p: P2, q: P2, a: P2, b: P2) -> bool {
    let side = |o: P2, u: P2, v: P2| (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x);
    side(p, q, a) * side(p, q, b) < 0.0 && side(a, b, p) * side(a, b, q) < 0.0
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
