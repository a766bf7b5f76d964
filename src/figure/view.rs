//! The projection of a figure: an orthographic view from in front, to the right and above,
//! the textbook's near-isometric one, turned a little (of a few azimuths and elevations)
//! where it would see a direction that matters end-on or draw two along one line. With z
//! up, x comes toward the reader (drawn down and to the left), y goes to the right and z
//! straight up; a circle is drawn as the ellipse it projects to and a sphere as a circle.
//!
//! The scene's "up" is z unless the scene says otherwise (`up y`) or its axes do: the fixed
//! vertical K of the Eulerian angles (`K = sin θ j + cos θ k`), or the direction a weight (a
//! force holding `g`) points against. The view turns that direction up: `p ↦ (R·p)
//! projected`, R the cyclic turn of the axes when y (or x) is up — a y-up problem in the
//! textbook's layout, z toward the reader, x to the right — else the rotation that takes
//! `up` to z by the shortest turn.

/// A point or direction in the scene's frame, in its length unit.
pub type P3 = [f64; 3];

/// A point or direction in the plane of the figure, y up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct P2 {
    pub x: f64,
    pub y: f64,
}

impl P2 {
    pub fn new(x: f64, y: f64) -> P2 {
        P2 { x, y }
    }
    /// How far the point is from the segment from `a` to `b`.
    pub fn to_segment(self, a: P2, b: P2) -> f64 {
        let d = b.minus(a);
        let t = ((self.x - a.x) * d.x + (self.y - a.y) * d.y) / (d.x * d.x + d.y * d.y).max(1e-300);
        a.plus(d.times(t.clamp(0.0, 1.0))).minus(self).length()
    }
    pub fn plus(self, o: P2) -> P2 {
        P2::new(self.x + o.x, self.y + o.y)
    }
    pub fn minus(self, o: P2) -> P2 {
        P2::new(self.x - o.x, self.y - o.y)
    }
    pub fn times(self, k: f64) -> P2 {
        P2::new(self.x * k, self.y * k)
    }
    pub fn length(self) -> f64 {
        self.x.hypot(self.y)
    }
    /// The direction of `self`, or none for a (nearly) zero vector.
    pub fn unit(self) -> Option<P2> {
        let l = self.length();
        (l > 1e-12).then(|| self.times(1.0 / l))
    }
    /// Turned a quarter turn counter-clockwise.
    pub fn normal(self) -> P2 {
        P2::new(-self.y, self.x)
    }
}

/// Azimuths of the eye from the x axis toward y and elevations above the horizontal, the
/// textbook's first: x toward the reader and down to the left, y to the right, z up in all.
const AZIMUTHS_DEG: [f64; 4] = [35.0, 50.0, 22.0, 65.0];
const ELEVATIONS_DEG: [f64; 2] = [25.0, 35.0];
/// Seen within this of end-on (its drawn length as a share of its length), a direction is
/// lost; two directions drawn within this angle of each other read as one.
const END_ON: f64 = 0.45;
const COLLINEAR_DEG: f64 = 10.0;
/// Two points this share of the points' spread apart read as one when drawn under
/// [`COINCIDING`] of their distance apart.
const APART: f64 = 0.2;
const COINCIDING: f64 = 0.3;
/// A point drawn within this share of the points' spread of a rod reads as on it.
const ON_ROD: f64 = 0.05;

/// The view: the turn that brings the scene's up to z, then the projection onto the screen.
#[derive(Debug, Clone, Copy)]
pub struct View {
    turn: [[f64; 3]; 3],
    eye: P3,
    right: P3,
    screen_up: P3,
}

impl View {
    /// The textbook's view with `up` (a direction of the scene's frame) drawn straight up.
    pub fn with_up(up: P3) -> View {
        View::from(up, AZIMUTHS_DEG[0], ELEVATIONS_DEG[0])
    }

    /// Of the textbook-like views with `up` drawn up, the first in which none of the
    /// `directions` that matter (the axes, ω, each part's axes) is seen end-on, no two of
    /// them are drawn along one line, no two of the `points` that matter (O, G, a rod's
    /// ends, a load's point) far apart are drawn on one another, and none of them is drawn
    /// on a rod it is far from (a frame's G where one rod crosses another as drawn); else
    /// the one with the fewest such faults.
    pub fn choose(up: P3, directions: &[P3], points: &[P3], rods: &[[P3; 2]]) -> View {
        let mut best: Option<(usize, View)> = None;
        for e in ELEVATIONS_DEG {
            for a in AZIMUTHS_DEG {
                let view = View::from(up, a, e);
                let faults = view.faults(directions)
                    + view.coinciding(points)
                    + view.on_other_rods(points, rods);
                if best.as_ref().is_none_or(|(f, _)| faults < *f) {
                    best = Some((faults, view));
                }
                if faults == 0 {
                    return view;
                }
            }
        }
        best.map_or_else(|| View::with_up(up), |(_, v)| v)
    }

    /// The directions seen end-on, and the pairs of distinct directions drawn along one line.
    fn faults(&self, directions: &[P3]) -> usize {
        let drawn: Vec<(P3, P2)> = directions
            .iter()
            .map(|d| unit(*d))
            .map(|d| (d, self.project(d)))
            .collect();
        let end_on = drawn.iter().filter(|(_, p)| p.length() < END_ON).count();
        let mut along_one_line = 0;
        for (k, (d1, p1)) in drawn.iter().enumerate() {
            for (d2, p2) in &drawn[k + 1..] {
                let same = dot(*d1, *d2).abs() > 0.999;
                let (Some(u1), Some(u2)) = (p1.unit(), p2.unit()) else {
                    continue;
                };
                let sine = (u1.x * u2.y - u1.y * u2.x).abs();
                if !same && sine < COLLINEAR_DEG.to_radians().sin() {
                    along_one_line += 1;
                }
            }
        }
        end_on + along_one_line
    }

    /// The pairs of `points` apart in the scene (by over [`APART`] of their spread) seen
    /// nearly one behind the other: drawn under [`COINCIDING`] of their distance apart.
    fn coinciding(&self, points: &[P3]) -> usize {
        let spread = spread(points);
        let mut count = 0;
        for (k, p) in points.iter().enumerate() {
            for q in &points[k + 1..] {
                let drawn = self.project(*p).minus(self.project(*q)).length();
                let apart = norm(sub(*p, *q));
                if apart > APART * spread && drawn < COINCIDING * apart {
                    count += 1;
                }
            }
        }
        count
    }

    /// The `points` drawn within [`ON_ROD`] of the points' spread of a rod they are over
    /// [`APART`] of it from in the scene.
    fn on_other_rods(&self, points: &[P3], rods: &[[P3; 2]]) -> usize {
        let spread = spread(points);
        points
            .iter()
            .flat_map(|p| rods.iter().map(move |r| (p, r)))
            .filter(|(p, [a, b])| {
                to_segment(**p, *a, *b) > APART * spread
                    && self
                        .project(**p)
                        .to_segment(self.project(*a), self.project(*b))
                        < ON_ROD * spread
            })
            .count()
    }

    fn from(up: P3, azimuth_deg: f64, elevation_deg: f64) -> View {
        let (a, e) = (azimuth_deg.to_radians(), elevation_deg.to_radians());
        let eye = [e.cos() * a.cos(), e.cos() * a.sin(), e.sin()];
        let right = unit(cross([0.0, 0.0, 1.0], eye));
        let screen_up = cross(eye, right);
        View {
            turn: turn_up(unit(up)),
            eye,
            right,
            screen_up,
        }
    }

    /// Where the scene's point `p` is drawn (scene length units, y up).
    pub fn project(&self, p: P3) -> P2 {
        let q = apply(&self.turn, p);
        P2::new(dot(q, self.right), dot(q, self.screen_up))
    }

    /// How far toward the eye `p` stands (larger is nearer), for what hides what.
    pub fn depth(&self, p: P3) -> f64 {
        dot(apply(&self.turn, p), self.eye)
    }

    /// The scene's up, the direction drawn straight up, in the scene's frame.
    pub fn up(&self) -> P3 {
        [0, 1, 2].map(|j| self.turn[2][j])
    }

    /// The direction toward the eye in the scene's frame (the turn undone).
    pub fn toward_eye(&self) -> P3 {
        let t = &self.turn;
        [0, 1, 2].map(|j| (0..3).map(|i| t[i][j] * self.eye[i]).sum())
    }
}

/// The rotation that draws `u` up: for y or x up the cyclic turn of the axes, so the
/// textbook's layout of a y-up problem (z toward the reader, x to the right, y up) follows;
/// else the shortest turn to z.
fn turn_up(u: P3) -> [[f64; 3]; 3] {
    let close = |a: P3| dot(u, a) > 1.0 - 1e-12;
    if close([0.0, 1.0, 0.0]) {
        // (x, y, z) drawn as (z, x, y): z toward the reader, x right, y up.
        return [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    }
    if close([1.0, 0.0, 0.0]) {
        return [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]];
    }
    turn_to_z(u)
}

/// The rotation taking the unit vector `u` to z (Rodrigues about u × z); the half turn about
/// x when u is −z.
fn turn_to_z(u: P3) -> [[f64; 3]; 3] {
    let c = u[2];
    if c < -1.0 + 1e-12 {
        return [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]];
    }
    // v = u × z, R = I + [v]× + [v]×² / (1 + c).
    let v = [u[1], -u[0], 0.0];
    let k = 1.0 / (1.0 + c);
    let vx = [[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]];
    let mut r = [[0.0; 3]; 3];
    for (i, row) in r.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            let square: f64 = (0..3).map(|m| vx[i][m] * vx[m][j]).sum();
            *cell = f64::from(u8::from(i == j)) + vx[i][j] + square * k;
        }
    }
    r
}

/// The frame's unit vectors i, j, k.
pub const UNIT: [P3; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// The part of `v` square to the unit `a` (its distance from the line along `a` through O).
pub fn square_to(v: P3, a: P3) -> P3 {
    sub(v, scaled(a, dot(v, a)))
}

/// Whether `p` is within `within` of the line along the unit `a` through O.
pub fn on_line(p: P3, a: P3, within: f64) -> bool {
    norm(square_to(p, a)) < within
}

/// The largest distance between two of the `points`.
fn spread(points: &[P3]) -> f64 {
    points
        .iter()
        .flat_map(|p| points.iter().map(move |q| norm(sub(*p, *q))))
        .fold(0.0, f64::max)
}

/// How far `p` is from the segment from `a` to `b`.
pub fn to_segment(p: P3, a: P3, b: P3) -> f64 {
    let along = sub(b, a);
    let t = dot(sub(p, a), along) / dot(along, along).max(1e-300);
    norm(sub(p, add(a, scaled(along, t.clamp(0.0, 1.0)))))
}

pub fn dot(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub fn norm(a: P3) -> f64 {
    dot(a, a).sqrt()
}

/// `a / |a|` (zero stays zero).
pub fn unit(a: P3) -> P3 {
    let n = norm(a);
    if n == 0.0 {
        a
    } else {
        scaled(a, 1.0 / n)
    }
}

pub fn scaled(a: P3, k: f64) -> P3 {
    [a[0] * k, a[1] * k, a[2] * k]
}

pub fn add(a: P3, b: P3) -> P3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `m · p` for a 3 × 3 matrix by rows.
pub fn apply(m: &[[f64; 3]; 3], p: P3) -> P3 {
    [dot(m[0], p), dot(m[1], p), dot(m[2], p)]
}

/// Two unit vectors across `axis` (a unit vector), with `axis` a right-handed triple.
pub fn across(axis: P3) -> (P3, P3) {
    let helper = if axis[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let u = unit(cross(axis, helper));
    let v = cross(axis, u);
    (u, v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn z_up_x_toward_the_reader_y_to_the_right() {
        let view = View::with_up([0.0, 0.0, 1.0]);
        let (x, y, z) = (
            view.project([1.0, 0.0, 0.0]),
            view.project([0.0, 1.0, 0.0]),
            view.project([0.0, 0.0, 1.0]),
        );
        assert!(x.x < 0.0 && x.y < 0.0, "x down and to the left: {x:?}");
        assert!(y.x > 0.5, "y to the right: {y:?}");
        assert!(z.x.abs() < 1e-12 && z.y > 0.9, "z straight up: {z:?}");
        assert!(view.depth([1.0, 0.0, 0.0]) > 0.0, "x toward the eye");
    }

    #[test]
    fn a_direction_the_first_view_sees_end_on_is_seen_from_another() {
        let first = View::with_up([0.0, 0.0, 1.0]);
        let toward_eye = first.toward_eye();
        assert!(
            first.project(toward_eye).length() < 1e-9,
            "end-on in the first view"
        );
        let chosen = View::choose([0.0, 0.0, 1.0], &[toward_eye, [0.0, 0.0, 1.0]], &[], &[]);
        assert!(
            chosen.project(toward_eye).length() >= END_ON,
            "seen side-on"
        );
        assert!(
            chosen.project([0.0, 0.0, 1.0]).x.abs() < 1e-12,
            "z still up"
        );
    }

    #[test]
    fn the_stated_up_is_drawn_up() {
        for up in [
            [0.0, 1.0, 0.0],
            [0.0, 0.5, 0.8],
            [0.0, 0.0, -1.0],
            [1.0, 0.0, 0.0],
        ] {
            let p = View::with_up(up).project(unit(up));
            assert!(p.x.abs() < 1e-12 && p.y > 0.9, "{up:?} -> {p:?}");
        }
    }
}
