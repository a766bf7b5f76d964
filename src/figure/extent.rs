//! Where the body is, as the figure's other pieces ask: its outline's points, its mass
//! centre G and its reach; whether a point is inside a part, behind one or covered by the
//! body as drawn, and how far a line from a point runs out of sight (inside a solid part,
//! behind it, or behind a disk's or a plate's face), in steps of the reach.

use super::canvas::Canvas;
use super::view::{self, add, scaled, sub, P2, P3};

/// The steps, in shares of the reach, a line out of the body is followed in until it leaves
/// the body's outline on the page, and the most of them.
const OUT_STEP: f64 = 0.05;
const OUT_STEPS: u32 = 40;
/// How far behind a disk's or a plate's plane, in shares of the reach, a point is behind its
/// face (nearer, it lies on the face).
const FACE_DEPTH: f64 = 1e-6;
/// A part's span across its plane, in shares of its size, below which it is flat (the
/// rounding of a disk's outline points).
const FLAT: f64 = 1e-9;

/// Where the body is: points on its outline, its mass centre G and its reach (the farthest
/// outline point from O or G, the length every arrow is drawn in proportion to).
pub struct Extent {
    pub samples: Vec<P3>,
    pub centre: P3,
    pub reach: f64,
    pub(super) solids: Vec<Solid>,
    /// The rods, end to end, and the point masses, a point twice.
    pub(super) lines: Vec<[P3; 2]>,
}

/// A part with room inside (not a rod or a point mass): its outline's points, its centre,
/// its own axes, and whether it is a face that hides what is behind it (a plate, a disk; not
/// a ring, which is drawn as its rim).
pub(super) struct Solid {
    pub(super) samples: Vec<P3>,
    pub(super) centre: P3,
    pub(super) axes: [P3; 3],
    pub(super) opaque: bool,
}

impl Solid {
    /// Whether `p` is within the part's box in its own axes (a flat part's plane within
    /// `depth`), and the part goes on past it both ways along `d` by `depth` or more.
    fn holds(&self, p: P3, d: P3, depth: f64) -> bool {
        let (behind, ahead) = self.span(d, p);
        self.within(p, depth) && ahead > depth && -behind > depth
    }

    /// Whether `p` is within the part's box in its own axes, widened by `margin` (narrowed
    /// where it is negative, except across a flat part, which has no inside there).
    fn within(&self, p: P3, margin: f64) -> bool {
        self.axes.iter().all(|a| {
            let (lo, hi) = self.span(*a, self.centre);
            let margin = match hi - lo > -2.0 * margin {
                true => margin,
                false => 0.0,
            };
            let x = view::dot(sub(p, self.centre), *a);
            x >= lo - margin && x <= hi + margin
        })
    }

    /// Whether the part has room across each of its axes (a box, a cylinder; not a plate or
    /// a disk, on whose face a line in its plane is drawn).
    fn thick(&self) -> bool {
        self.flat_normal().is_none()
    }

    /// The axis a flat part (a plate, a disk, a ring) has no room along, the normal to its
    /// plane: its outline's span along it is rounding next to its size.
    fn flat_normal(&self) -> Option<P3> {
        let size = self
            .samples
            .iter()
            .map(|s| view::norm(sub(*s, self.centre)))
            .fold(0.0, f64::max);
        self.axes.iter().copied().find(|a| {
            let (lo, hi) = self.span(*a, self.centre);
            hi - lo <= FLAT * size
        })
    }

    /// Whether the point `q` is behind the part's face as drawn: the part is flat and
    /// opaque, `q` is on the page inside its outline, and a line from `q` toward the eye
    /// crosses its plane by more than `depth` (a line in its plane lies on its face).
    fn faces_over(&self, canvas: &Canvas, q: P3, depth: f64) -> bool {
        let eye = canvas.view().toward_eye();
        let Some(normal) = self.flat_normal().filter(|_| self.opaque) else {
            return false;
        };
        let before = view::dot(sub(self.centre, q), normal) * view::dot(eye, normal).signum();
        before > depth && on_page_inside(canvas, &self.samples, q)
    }

    /// How far the part's outline goes back and on along `axis` from `at`.
    fn span(&self, axis: P3, at: P3) -> (f64, f64) {
        self.samples
            .iter()
            .map(|s| view::dot(sub(*s, at), axis))
            .fold((0.0f64, 0.0f64), |(lo, hi), x| (lo.min(x), hi.max(x)))
    }
}

impl Extent {
    /// How far the body goes along the unit vector `d` from the origin (0 if it lies behind).
    pub fn along(&self, d: P3) -> f64 {
        self.samples
            .iter()
            .map(|p| view::dot(*p, d))
            .fold(0.0, f64::max)
    }

    /// How far the body goes along the unit vector `d` from the origin as drawn: past
    /// [`Extent::along`], on to where the line comes out of the body's outline on the page (a
    /// thin disk's axis seen through its face), in steps of [`OUT_STEP`] of the reach.
    pub fn drawn_along(&self, canvas: &Canvas, d: P3) -> f64 {
        let start = self.along(d);
        let step = OUT_STEP * self.reach;
        (0..=OUT_STEPS)
            .map(|k| start + step * f64::from(k))
            .find(|t| !self.covers(canvas, scaled(d, *t)))
            .unwrap_or(start + step * f64::from(OUT_STEPS))
    }

    /// Whether the point `p` is inside one of the solid parts (a plate, disk, box, …; not a
    /// rod or a point mass) with the part on both sides of it along the unit vector `d` by
    /// `depth` or more: a load there (a weight at G) is inside the body, not on its surface.
    pub fn surrounds(&self, p: P3, d: P3, depth: f64) -> bool {
        self.solids.iter().any(|solid| solid.holds(p, d, depth))
    }

    /// Whether the point `p`, on a solid part's surface, is out of sight behind it: a step
    /// toward the eye from it goes into the part (a box's far corner, a point on a face
    /// turned from the eye).
    pub fn hides(&self, canvas: &Canvas, p: P3, depth: f64) -> bool {
        self.goes_into(p, canvas.view().toward_eye(), depth)
    }

    /// Whether a step of `depth` from the point `p` on a solid part's surface along the unit
    /// vector `d` goes into the part (a push on a face, a line of sight into it).
    pub fn goes_into(&self, p: P3, d: P3, depth: f64) -> bool {
        let stepped = add(p, scaled(d, depth));
        self.solids
            .iter()
            .any(|s| !s.within(p, -depth) && s.within(stepped, 0.0))
    }

    /// How far along the unit vector `d` a line from the point `p` (G inside a box) runs out
    /// of sight ([`Extent::out_of_sight`]), in steps of [`OUT_STEP`] of the reach up to
    /// `length`.
    pub fn hidden_along(&self, canvas: &Canvas, p: P3, d: P3, length: f64) -> f64 {
        self.along_while(p, d, length, |q| self.out_of_sight(canvas, q))
    }

    /// Whether the point `q` is out of sight as drawn: inside a part with room across each
    /// axis, or behind one (a step toward the eye from it goes into the part), or behind a
    /// disk's or a plate's face. A line in a plate's plane is drawn on its face.
    pub fn out_of_sight(&self, canvas: &Canvas, q: P3) -> bool {
        let step = OUT_STEP * self.reach;
        let eye = canvas.view().toward_eye();
        let in_a_solid = |q: P3| self.solids.iter().any(|s| s.thick() && s.within(q, 0.0));
        let depth = FACE_DEPTH * self.reach;
        self.covers(canvas, q)
            && ((0..=2 * OUT_STEPS).any(|k| in_a_solid(add(q, scaled(eye, step * f64::from(k)))))
                || self.solids.iter().any(|s| s.faces_over(canvas, q, depth)))
    }

    /// The line from `p` along the unit vector `d`, `length` long, in runs where `test`
    /// holds and where it does not, from its start to its end: `(from, to, holds)`, decided
    /// in steps of [`OUT_STEP`] of the reach (a run changes at the first step that differs).
    pub fn runs_along(
        &self,
        p: P3,
        d: P3,
        length: f64,
        test: impl Fn(P3) -> bool,
    ) -> Vec<(f64, f64, bool)> {
        let step = OUT_STEP * self.reach;
        let steps = (length / step).ceil() as u32;
        let mut runs: Vec<(f64, f64, bool)> = Vec::new();
        for k in 0..steps.max(1) {
            let t = (step * f64::from(k)).min(length);
            let holds = test(add(p, scaled(d, t)));
            match runs.last_mut() {
                Some(run) if run.2 == holds => {}
                Some(run) => {
                    run.1 = t;
                    runs.push((t, length, holds));
                }
                None => runs.push((0.0, length, holds)),
            }
        }
        runs
    }

    /// The farthest step of [`OUT_STEP`] of the reach, up to `length`, along the unit vector
    /// `d` from `p` to which every point passes `test`.
    fn along_while(&self, p: P3, d: P3, length: f64, test: impl Fn(P3) -> bool) -> f64 {
        let step = OUT_STEP * self.reach;
        let steps = (length / step).floor() as u32;
        (0..=steps)
            .map(|k| step * f64::from(k))
            .take_while(|t| test(add(p, scaled(d, *t))))
            .last()
            .unwrap_or(0.0)
    }

    /// Whether the body reaches the point `p`, within `margin`: it is in a part's box (in
    /// the part's own axes), or on a rod, or at a point mass.
    pub fn reaches(&self, p: P3, margin: f64) -> bool {
        self.solids.iter().any(|s| s.within(p, margin))
            || self
                .lines
                .iter()
                .any(|[a, b]| view::to_segment(p, *a, *b) <= margin)
    }

    /// Whether the body, as drawn, covers the point `p` (it projects inside the hull of the
    /// body's outline).
    pub fn covers(&self, canvas: &Canvas, p: P3) -> bool {
        on_page_inside(canvas, &self.samples, p)
    }

    /// How far, as drawn, the body goes past the point `p` along the unit vector `d` (0 if
    /// not at all), in lengths along `d`: a load at a point inside it is drawn out past it.
    pub fn beyond(&self, canvas: &Canvas, p: P3, d: P3) -> f64 {
        let at = canvas.project(p);
        let along = canvas.project(add(p, d)).minus(at);
        let Some(v) = along.unit() else {
            return 0.0;
        };
        self.samples
            .iter()
            .map(|s| {
                let q = canvas.project(*s).minus(at);
                (q.x * v.x + q.y * v.y) / along.length()
            })
            .fold(0.0, f64::max)
    }
}

/// Whether the point `p` projects inside the hull of the projected `outline`.
fn on_page_inside(canvas: &Canvas, outline: &[P3], p: P3) -> bool {
    let at = canvas.project(p);
    let hull = convex_hull(outline.iter().map(|s| canvas.project(*s)).collect());
    hull.len() >= 3
        && hull
            .iter()
            .zip(hull.iter().cycle().skip(1))
            .all(|(a, b)| (b.x - a.x) * (at.y - a.y) - (b.y - a.y) * (at.x - a.x) >= 0.0)
}

/// Andrew's monotone chain: the hull counter-clockwise.
pub(super) fn convex_hull(mut p: Vec<P2>) -> Vec<P2> {
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    p.dedup_by(|a, b| (a.x - b.x).abs() < 1e-12 && (a.y - b.y).abs() < 1e-12);
    if p.len() < 3 {
        return p;
    }
    let turn = |o: P2, a: P2, b: P2| (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    let mut hull: Vec<P2> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = hull.len();
        let points: Box<dyn Iterator<Item = &P2>> = match pass {
            0 => Box::new(p.iter()),
            _ => Box::new(p.iter().rev()),
        };
        for &q in points {
            while hull.len() >= start + 2
                && turn(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    hull
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hull_of_a_square_and_its_centre_is_the_square() {
        let p = |x, y| P2::new(x, y);
        let hull = convex_hull(vec![
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(0.5, 0.5),
            p(1.0, 1.0),
            p(0.0, 1.0),
        ]);
        assert_eq!(hull.len(), 4);
        assert!(!hull.contains(&p(0.5, 0.5)));
    }
}
