//! The canvas a figure is drawn on: the scene's points projected by the view (in the scene's
//! length unit until [`Canvas::finish`] scales them), marks in three layers — behind (the
//! axes), the body's parts far to near, in front (loads and motion) — and the labels asked
//! for, placed when the scale is known.

use super::labels::{self, Names, Wanted};
use super::sizes::Sizes;
use super::view::{self, View, P2, P3};
use super::{
    Figure, FigureError, Label, Mark, Role, Stroke, ARROWS_APART, BESIDE, MARKS_HEIGHT,
    MARKS_TALLEST, MARKS_WIDTH,
};
use crate::algebra::{Expr, Vector};
use crate::mechanics::eulerian_angles::EulerianAngles;
use crate::mechanics::shapes::Shape;
use crate::scene::model::Scene;

/// The room left around the drawing, in figure units.
const MARGIN: f64 = 6.0;
/// The room each label is given among the marks, in square figure units, and how much larger
/// than [`MARKS_WIDTH`] a crowded drawing may grow for it (to 340 units, 255 pt: still
/// narrower than a page's text).
const ROOM_PER_LABEL: f64 = 4000.0;
const MOST_GROWTH: f64 = 1.3;
/// An arrow lies along a line when it is within this of parallel to it, its tail within
/// this share of its length of the line, and it runs over this share of its length beside it.
const ALONG_DEG: f64 = 6.0;
const ON_LINE: f64 = 0.05;
const OVERLAPPING: f64 = 0.2;
/// An arrow runs on from another's end when the gap between them is less than this share of
/// its length.
const MEETING: f64 = 0.1;
/// The share of a turn a curved arrow about a line goes round.
const TURN: f64 = 0.8;
/// The pieces a bar (a shaft, an axle) is drawn in, each at its own depth among the parts.
const BAR_PIECES: usize = 12;

pub struct Canvas<'s> {
    sizes: &'s Sizes,
    view: View,
    /// The marks under the parts (the axes, the lines inside the body), each with its shift,
    /// as `front`'s.
    behind: Vec<(Mark, P2)>,
    /// Each part's marks with the depth of its centre.
    parts: Vec<(f64, Vec<Mark>)>,
    /// The loads and the motion, each with the shift (in figure units, made after scaling)
    /// that sets it beside a line it would lie along.
    front: Vec<(Mark, P2)>,
    wanted: Vec<(Wanted, P2)>,
    /// The lines, as drawn, a vector's arrow is kept off: the axes, the rods, the shaft, and
    /// the vectors' arrows drawn before it.
    clear: Vec<Kept>,
}

/// A line an arrow is not drawn along: as drawn (before scaling), the shift it was drawn at
/// (in figure units), whether it is an arrow's (else an axis's, a rod's, the shaft's),
/// whether it is one of the axes Oxyz, and its stroke's width.
struct Kept {
    line: (P2, P2),
    shift: P2,
    arrow: bool,
    axis: bool,
    width: f64,
}

impl Kept {
    /// How far an arrow beside it stands: [`ARROWS_APART`] from an arrow, [`BESIDE`] a
    /// line's edge.
    fn apart(&self) -> f64 {
        match self.arrow {
            true => ARROWS_APART,
            false => BESIDE + self.width / 2.0,
        }
    }

    /// Whether the drawn segment lies along it, or (an arrow's) runs on from its end.
    fn under(&self, segment: (P2, P2)) -> bool {
        match self.arrow {
            true => along_or_meeting(segment, self.line),
            false => along(segment, self.line),
        }
    }
}

/// Where a mark goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layer {
    Behind,
    Front,
}

impl<'s> Canvas<'s> {
    /// The canvas of `scene` with its up drawn up: the axis the scene says is up (`up y`),
    /// else the fixed vertical K of the Eulerian angles, else against the weight (a force
    /// holding `g`, or named `W`, `W_1`, `weight`), else the axis the frame turns about (a
    /// precession about the vertical), else z.
    pub fn new(scene: &Scene, sizes: &'s Sizes) -> Result<Canvas<'s>, FigureError> {
        let mut canvas = Canvas {
            sizes,
            view: View::with_up([0.0, 0.0, 1.0]),
            behind: Vec::new(),
            parts: Vec::new(),
            front: Vec::new(),
            wanted: Vec::new(),
            clear: Vec::new(),
        };
        let up = if let Some(axis) = scene.up {
            let mut up = [0.0; 3];
            up[axis.index()] = 1.0;
            up
        } else if scene.euler_angles.is_some() {
            let theta = canvas.value(&Expr::sym(EulerianAngles::chapter().nutation), "theta")?;
            [0.0, theta.sin(), theta.cos()]
        } else {
            let g = crate::algebra::Symbol::new("g");
            let weight = scene.forces.iter().find(|f| {
                f.value.iter().any(|c| c.symbols().contains(&g)) || is_weight_name(&f.name)
            });
            match (weight, &scene.frame_rate) {
                (Some(w), _) => {
                    let down = canvas.vector(&w.value, &w.name)?;
                    match view::norm(down) > 0.0 {
                        true => view::scaled(down, -1.0),
                        false => [0.0, 0.0, 1.0],
                    }
                }
                // A frame turning about one axis precesses about the vertical: that axis up.
                (None, Some(rate)) => {
                    along_one_axis(&canvas.vector(rate, "frame rate")?).unwrap_or([0.0, 0.0, 1.0])
                }
                (None, None) => [0.0, 0.0, 1.0],
            }
        };
        let mut directions = view::UNIT.to_vec();
        // ω and v̄, each drawn as one arrow where it is given: seen end-on, one is a dot.
        let unknowns = super::loads::magnitudes(scene);
        let omega = scene
            .omega
            .as_ref()
            .filter(|_| scene.euler_angles.is_none());
        for (v, name) in [(omega, "omega"), (scene.vbar.as_ref(), "vbar")] {
            let Some(v) = v.filter(|v| super::arrows::drawn_whole(v, &unknowns)) else {
                continue;
            };
            let d = canvas.vector(v, name)?;
            if view::norm(d) > 0.0 {
                directions.push(d);
            }
        }
        // O, G and the points the scene names: drawn apart where they are apart.
        let mut points = vec![[0.0; 3]];
        let mut rods = Vec::new();
        let (mut mass, mut moment) = (0.0, [0.0; 3]);
        for (k, part) in scene.parts.iter().enumerate() {
            let what = format!("body {}", k + 1);
            let axes = canvas.columns(&part.rotation, &what)?;
            directions.extend(axes);
            let centre = canvas.vector(&part.position, &what)?;
            let m = canvas.value(&part.mass, &what)?;
            (mass, moment) = (mass + m, view::add(moment, view::scaled(centre, m)));
            points.push(centre);
            if let Shape::SlenderRod { length } = &part.shape {
                let half = view::scaled(axes[0], canvas.value(length, &what)? / 2.0);
                let ends = [view::add(centre, half), view::sub(centre, half)];
                points.extend(ends);
                rods.push(ends);
            }
        }
        if mass > 0.0 {
            points.push(view::scaled(moment, 1.0 / mass));
        }
        points.extend(canvas.loaded_points(scene)?);
        canvas.view = View::choose(up, &directions, &points, &rods);
        Ok(canvas)
    }

    /// The value of `e` at the figure's sizes; `what` names it in an error.
    pub fn value(&self, e: &Expr, what: &str) -> Result<f64, FigureError> {
        self.sizes.of_expr(e).map_err(|error| FigureError::Value {
            what: what.to_string(),
            error,
        })
    }

    pub fn vector(&self, v: &Vector, what: &str) -> Result<P3, FigureError> {
        Ok([
            self.value(&v[0], what)?,
            self.value(&v[1], what)?,
            self.value(&v[2], what)?,
        ])
    }

    /// The columns of a rotation (a part's own axes in the frame), at the figure's sizes.
    pub fn columns(&self, m: &crate::algebra::Matrix, what: &str) -> Result<[P3; 3], FigureError> {
        let mut axes = [[0.0; 3]; 3];
        for (j, axis) in axes.iter_mut().enumerate() {
            for (i, c) in axis.iter_mut().enumerate() {
                *c = self.value(&m[(i, j)], what)?;
            }
        }
        Ok(axes)
    }

    /// The points a force, an impulse or a name is at.
    pub fn loaded_points(&self, scene: &Scene) -> Result<Vec<P3>, FigureError> {
        let mut out = Vec::new();
        for f in &scene.forces {
            out.push(self.vector(&f.point, &f.name)?);
        }
        for (k, i) in scene.impulses.iter().enumerate() {
            out.push(self.vector(&i.point, &format!("impulse {}", k + 1))?);
        }
        for p in &scene.points {
            out.push(self.vector(&p.position, &p.name)?);
        }
        Ok(out)
    }

    /// The length a symbolic length is first drawn at ([`Sizes::base`]).
    pub fn base_length(&self) -> f64 {
        self.sizes.base
    }

    pub fn project(&self, p: P3) -> P2 {
        self.view.project(p)
    }

    pub fn view(&self) -> &View {
        &self.view
    }

    fn push(&mut self, layer: Layer, mark: Mark, shift: P2) {
        match layer {
            Layer::Behind => self.behind.push((mark, shift)),
            Layer::Front => self.front.push((mark, shift)),
        }
    }

    /// A polyline (or polygon) through the scene's points.
    pub fn path(&mut self, layer: Layer, points: &[P3], closed: bool, stroke: Stroke) {
        self.path_beside(layer, points, closed, stroke, P2::new(0.0, 0.0));
    }

    /// A polyline through the scene's points, drawn `shift` figure units over (the part
    /// inside the body of an arrow drawn beside a line).
    pub fn path_beside(
        &mut self,
        layer: Layer,
        points: &[P3],
        closed: bool,
        stroke: Stroke,
        shift: P2,
    ) {
        let points = points.iter().map(|p| self.project(*p)).collect();
        let mark = Mark::Path {
            points,
            closed,
            filled: false,
            stroke,
        };
        self.push(layer, mark, shift);
    }

    /// The line from `a` to `b` (an axis, a rod, the shaft), drawn with `stroke`, is one a
    /// vector's arrow is not drawn along, but [`BESIDE`] its edge.
    pub fn keep_clear(&mut self, a: P3, b: P3, stroke: Stroke) {
        self.clear.push(Kept {
            line: (self.project(a), self.project(b)),
            shift: P2::new(0.0, 0.0),
            arrow: false,
            axis: false,
            width: stroke.width,
        });
    }

    /// The axis from O to `tip` is one a motion's arrow is drawn [`BESIDE`], not along (a
    /// black arrow on the black axis would read as a piece of it); a load's arrow, in the
    /// accent colour, is drawn on it from its point.
    pub fn keep_axis_clear(&mut self, tip: P3) {
        self.clear.push(Kept {
            line: (self.project([0.0; 3]), self.project(tip)),
            shift: P2::new(0.0, 0.0),
            arrow: false,
            axis: true,
            width: Stroke::AXIS.width,
        });
    }

    /// The arrow from `from` to `to`, drawn `shift` over, is one a later vector's arrow is
    /// drawn [`ARROWS_APART`] beside, not over or on from its end (ω and v̄ the same way from
    /// G, a normal force under a weight, a reaction's head at the tail of ω).
    pub fn keep_arrow_clear(&mut self, from: P3, to: P3, shift: P2) {
        self.clear.push(Kept {
            line: (self.project(from), self.project(to)),
            shift,
            arrow: true,
            axis: false,
            width: Stroke::MOTION.width,
        });
    }

    /// The shift, in figure units, that sets an arrow from `from` to `to` beside the lines
    /// kept clear it would lie along (parallel to each, on it, and over a fifth of its
    /// length; or, an arrow's, running on from its end): across them, as little as leaves
    /// each line its room ([`BESIDE`] a line, [`ARROWS_APART`] from an arrow), on the side
    /// away from `away` where both are as near; zero where it lies along none. A load's
    /// arrow (`over_axes`) lies on the axes Oxyz, drawn over them.
    pub fn beside(&self, from: P3, to: P3, away: P3, over_axes: bool) -> P2 {
        let (p0, p1) = (self.project(from), self.project(to));
        let dot = |a: P2, b: P2| a.x * b.x + a.y * b.y;
        let under: Vec<&Kept> = self
            .clear
            .iter()
            .filter(|k| !(over_axes && k.axis) && k.under((p0, p1)))
            .collect();
        let Some(n) = under
            .iter()
            .find_map(|k| k.line.1.minus(k.line.0).unit())
            .map(|v| v.normal())
        else {
            return P2::new(0.0, 0.0);
        };
        let side = dot(n, p0.minus(self.project(away)));
        let n = match side < 0.0 || (side == 0.0 && n.x < 0.0) {
            true => n.times(-1.0),
            false => n,
        };
        // Each line's place across, and the room it keeps; the nearest free place is at 0 or
        // at the edge of one line's room.
        let kept: Vec<(f64, f64)> = under.iter().map(|k| (dot(k.shift, n), k.apart())).collect();
        let free = |x: f64| {
            kept.iter()
                .all(|(at, apart)| (x - at).abs() >= apart - 1e-9)
        };
        let across = std::iter::once(0.0)
            .chain(kept.iter().flat_map(|(at, apart)| [at + apart, at - apart]))
            .filter(|x| free(*x))
            .min_by(|a, b| a.abs().total_cmp(&b.abs()).then(b.total_cmp(a)))
            .unwrap_or(0.0);
        n.times(across)
    }

    /// Whether the head of an arrow drawn in front (a load, a rate) is within `distance` (in
    /// the scene's length, as drawn, before any shift beside a line) of the scene's point `p`.
    pub fn head_near(&self, p: P3, distance: f64) -> bool {
        let at = self.project(p);
        self.front.iter().any(|(mark, _)| match mark {
            Mark::Arrow { to, .. } => to.minus(at).length() < distance,
            _ => false,
        })
    }

    /// How far along the unit `d` from the scene's point `p`, within `length`, the head of a
    /// load drawn in front lies on the line, pointing back along it (the floor's push at C
    /// below a weight at G): the nearest such head, if any.
    pub fn head_coming(&self, p: P3, d: P3, length: f64) -> Option<f64> {
        let at = self.project(p);
        let per_length = self.project(view::add(p, d)).minus(at);
        let along = per_length.unit()?;
        self.front
            .iter()
            .filter_map(|(mark, _)| match mark {
                Mark::Arrow {
                    from,
                    via,
                    to,
                    role: Role::Force(_) | Role::Impulse,
                    ..
                } => {
                    let last = via.last().unwrap_or(from);
                    let (head, pointing) = (to.minus(at), to.minus(*last));
                    let off = (head.x * along.y - head.y * along.x).abs();
                    let t = (head.x * along.x + head.y * along.y) / per_length.length();
                    let back = pointing.x * along.x + pointing.y * along.y < 0.0;
                    let on_line = off < 1e-9 * per_length.length() * length;
                    (on_line && back && t > 0.0 && t <= length).then_some(t)
                }
                _ => None,
            })
            .min_by(f64::total_cmp)
    }

    /// Whether an arrow drawn in front (a load, a rate) lies along the line from `from` to
    /// `to` as drawn: a dimension's extension line there would run over it.
    pub fn arrow_along(&self, from: P3, to: P3) -> bool {
        let line = (self.project(from), self.project(to));
        self.front.iter().any(|(mark, _)| match mark {
            Mark::Arrow { from, via, to, .. } if via.is_empty() => along((*from, *to), line),
            _ => false,
        })
    }

    /// A straight arrow between two of the scene's points.
    pub fn arrow(
        &mut self,
        layer: Layer,
        from: P3,
        to: P3,
        double: bool,
        stroke: Stroke,
        role: Role,
    ) {
        self.arrow_beside(layer, from, to, double, stroke, role, P2::new(0.0, 0.0));
    }

    /// A straight arrow between two of the scene's points, drawn `shift` figure units over
    /// (see [`Canvas::beside`]).
    #[allow(clippy::too_many_arguments)]
    pub fn arrow_beside(
        &mut self,
        layer: Layer,
        from: P3,
        to: P3,
        double: bool,
        stroke: Stroke,
        role: Role,
        shift: P2,
    ) {
        let (from, to) = (self.project(from), self.project(to));
        let mark = Mark::Arrow {
            from,
            via: Vec::new(),
            to,
            double,
            stroke,
            role,
        };
        self.push(layer, mark, shift);
    }

    /// A curved arrow [`TURN`] of the way round the circle of `radius` about `centre` in the
    /// plane across `axis`, turning right-handedly about it (a rate or a couple about a
    /// line); where it starts, for its label.
    pub fn turning_arrow(
        &mut self,
        centre: P3,
        axis: P3,
        radius: f64,
        stroke: Stroke,
        role: Role,
    ) -> P3 {
        // circle() goes round the axis right-handedly, so the arrow turns the way it should.
        let whole = super::body::circle(centre, axis, radius);
        let n = (whole.len() as f64 * TURN) as usize;
        let mut drawn: Vec<P2> = whole[..n].iter().map(|p| self.project(*p)).collect();
        let to = drawn.pop().unwrap_or(P2::new(0.0, 0.0));
        let from = drawn.remove(0);
        let mark = Mark::Arrow {
            from,
            via: drawn,
            to,
            double: false,
            stroke,
            role,
        };
        self.push(Layer::Front, mark, P2::new(0.0, 0.0));
        whole[0]
    }

    /// A dot of `radius` figure units at a scene's point.
    pub fn dot(&mut self, p: P3, radius: f64) {
        let at = self.project(p);
        self.push(Layer::Front, Mark::Dot { at, radius }, P2::new(0.0, 0.0));
    }

    /// A straight bar from `a` to `b` (a shaft, an axle) in pieces, each drawn among the
    /// parts at its own depth: it passes behind a disk on it and in front of it where it
    /// comes out.
    pub fn bar(&mut self, a: P3, b: P3, stroke: Stroke) {
        let at = |j: usize| {
            view::add(
                a,
                view::scaled(view::sub(b, a), j as f64 / BAR_PIECES as f64),
            )
        };
        for k in 0..BAR_PIECES {
            let (q0, q1) = (at(k), at(k + 1));
            let piece = Mark::Path {
                points: vec![self.project(q0), self.project(q1)],
                closed: false,
                filled: false,
                stroke,
            };
            self.part(view::scaled(view::add(q0, q1), 0.5), vec![piece]);
        }
    }

    /// A part's marks, drawn after the parts farther from the eye than `centre`.
    pub fn part(&mut self, centre: P3, marks: Vec<Mark>) {
        let depth = self.view.depth(centre);
        self.parts.push((depth, marks));
    }

    /// A label for the scene's point `anchor`, wanted on the side `direction` (the scene's
    /// frame) points to.
    pub fn label(&mut self, markup: String, anchor: P3, direction: P3) {
        self.want(markup, anchor, direction, Names::Beside, P2::new(0.0, 0.0));
    }

    /// A label for an arrow drawn beside a line ([`Canvas::arrow_beside`]), shifted with it.
    pub fn label_beside(&mut self, markup: String, anchor: P3, direction: P3, shift: P2) {
        self.want(markup, anchor, direction, Names::Beside, shift);
    }

    /// A label of something on the body (G, a named point, a part's size), which may stand
    /// on the body's faces.
    pub fn label_on_body(&mut self, markup: String, anchor: P3, direction: P3) {
        self.want(markup, anchor, direction, Names::OnBody, P2::new(0.0, 0.0));
    }

    /// A part's size's label, wanted by the middle of the stretch `[a, b]` of its side on the
    /// side `direction` points to, and free to stand by any point of it.
    pub fn label_along(&mut self, markup: String, [a, b]: [P3; 2], direction: P3) {
        let middle = view::scaled(view::add(a, b), 0.5);
        let wanted = Wanted {
            slide: self.project(b).minus(self.project(a)).times(0.5),
            ..self.wanted(markup, middle, direction, Names::OnBody)
        };
        self.wanted.push((wanted, P2::new(0.0, 0.0)));
    }

    /// A dimension's label, at the middle of its line `anchor` if that is free, else beside
    /// it on the side `direction` points to.
    pub fn label_dimension(&mut self, markup: String, anchor: P3, direction: P3) {
        self.want(
            markup,
            anchor,
            direction,
            Names::Dimension,
            P2::new(0.0, 0.0),
        );
    }

    fn want(&mut self, markup: String, anchor: P3, direction: P3, names: Names, shift: P2) {
        let wanted = self.wanted(markup, anchor, direction, names);
        self.wanted.push((wanted, shift));
    }

    /// A label for the point `anchor` alone, wanted on the side `direction` points to.
    fn wanted(&self, markup: String, anchor: P3, direction: P3, names: Names) -> Wanted {
        let at = self.project(anchor);
        let toward = self.project(view::add(anchor, direction)).minus(at);
        Wanted {
            markup,
            anchor: at,
            slide: P2::new(0.0, 0.0),
            direction: toward.unit().unwrap_or(P2::new(1.0, 0.0)),
            names,
        }
    }

    /// The figure: every mark scaled so the drawing is [`MARKS_WIDTH`] wide or [`MARKS_HEIGHT`]
    /// high (a tall one the area of that square, up to [`MARKS_TALLEST`]), larger when each
    /// label would have less than [`ROOM_PER_LABEL`] (up to [`MOST_GROWTH`] times), and those
    /// drawn beside a line shifted, then the labels placed.
    pub fn finish(self) -> Figure {
        let mut marks = self.behind;
        let mut parts = self.parts;
        parts.sort_by(|a, b| a.0.total_cmp(&b.0));
        marks.extend(
            parts
                .into_iter()
                .flat_map(|(_, m)| m)
                .map(|m| (m, P2::new(0.0, 0.0))),
        );
        marks.extend(self.front);
        // Without the heads, which are in figure units already.
        let (min, max) = bounds(marks.iter().flat_map(|(m, _)| m.line()));
        let (w, h) = (max.x - min.x, max.y - min.y);
        let scale = match (w > 0.0, h > 0.0) {
            (true, true) => (MARKS_WIDTH / w)
                .min(MARKS_TALLEST / h)
                .min(MARKS_HEIGHT / h.min((w * h).sqrt())),
            (true, false) => MARKS_WIDTH / w,
            (false, true) => MARKS_HEIGHT / h,
            (false, false) => 1.0,
        };
        // A crowded drawing is drawn larger, so each label keeps its room.
        let area = (w * scale).max(1.0) * (h * scale).max(1.0);
        let crowding = (self.wanted.len() as f64 * ROOM_PER_LABEL / area).sqrt();
        let scale = scale * crowding.clamp(1.0, MOST_GROWTH);
        let marks: Vec<Mark> = marks
            .into_iter()
            .map(|(m, shift)| moved(m, |p| p.times(scale).plus(shift)))
            .collect();
        let wanted: Vec<Wanted> = self
            .wanted
            .into_iter()
            .map(|(w, shift)| Wanted {
                anchor: w.anchor.times(scale).plus(shift),
                slide: w.slide.times(scale),
                ..w
            })
            .collect();
        let labels = labels::place(&wanted, &marks);
        let (mut min, mut max) = bounds(
            marks
                .iter()
                .flat_map(points_of)
                .chain(labels.iter().flat_map(corners)),
        );
        min = min.minus(P2::new(MARGIN, MARGIN));
        max = max.plus(P2::new(MARGIN, MARGIN));
        Figure {
            marks,
            labels,
            min,
            max,
            view: self.view,
            scale,
        }
    }
}

/// Whether the drawn segment from `p0` to `p1` lies along the one from `a` to `b`: within
/// [`ALONG_DEG`] of parallel, its start within [`ON_LINE`] of its length from that line, and
/// running beside it over more than [`OVERLAPPING`] of its length.
fn along(segment: (P2, P2), line: (P2, P2)) -> bool {
    shared(segment, line).is_some_and(|share| share > OVERLAPPING)
}

/// Whether the drawn segment from `p0` to `p1` lies along the one from `a` to `b` or runs on
/// from its end (a gap of less than [`MEETING`] of its length): one arrow after another on a
/// line reads as one long arrow. Two arrows from one tail the opposite ways (a reaction up
/// from O, ω₂ down from it) read as two.
fn along_or_meeting(segment: (P2, P2), line: (P2, P2)) -> bool {
    let (p0, p1) = segment;
    let (a, b) = line;
    let dot = |u: P2, v: P2| u.x * v.x + u.y * v.y;
    let from_its_tail = p0.minus(a).length() < MEETING * p1.minus(p0).length();
    let apart = from_its_tail && dot(p1.minus(p0), b.minus(a)) < 0.0;
    !apart && shared(segment, line).is_some_and(|share| share > -MEETING)
}

/// How much of its length the segment from `p0` to `p1` runs beside the one from `a` to `b`
/// (less than zero: the gap between them along the line), where it is within [`ALONG_DEG`]
/// of parallel to it and its start within [`ON_LINE`] of its length from that line.
fn shared((p0, p1): (P2, P2), (a, b): (P2, P2)) -> Option<f64> {
    let cross = |a: P2, b: P2| a.x * b.y - a.y * b.x;
    let dot = |a: P2, b: P2| a.x * b.x + a.y * b.y;
    let length = p1.minus(p0).length();
    let (u, v) = (p1.minus(p0).unit()?, b.minus(a).unit()?);
    let parallel = cross(u, v).abs() < ALONG_DEG.to_radians().sin();
    let on = cross(p0.minus(a), v).abs() < ON_LINE * length;
    let (t0, t1) = (dot(p0.minus(a), v), dot(p1.minus(a), v));
    let run = t0.max(t1).min(b.minus(a).length()) - t0.min(t1).max(0.0);
    (parallel && on).then_some(run / length)
}

/// The positive axis a vector lies along (either way), if it lies along one.
fn along_one_axis(v: &P3) -> Option<P3> {
    let nonzero: Vec<usize> = (0..3).filter(|k| v[*k] != 0.0).collect();
    match nonzero.as_slice() {
        [k] => {
            let mut axis = [0.0; 3];
            axis[*k] = 1.0;
            Some(axis)
        }
        _ => None,
    }
}

/// Whether a force's name says it is a weight: `W`, `W_1`, `W2`, `weight`.
fn is_weight_name(name: &str) -> bool {
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit() || c == '_');
    stem == "W" || stem.eq_ignore_ascii_case("weight")
}

/// The points a mark passes through, its arrow heads and a dot's extent included.
pub fn points_of(mark: &Mark) -> Vec<P2> {
    match mark {
        Mark::Dot { at, radius } => vec![
            at.minus(P2::new(*radius, *radius)),
            at.plus(P2::new(*radius, *radius)),
        ],
        _ => {
            let mut out = mark.line();
            out.extend(mark.heads().into_iter().flatten());
            out
        }
    }
}

fn corners(l: &Label) -> [P2; 2] {
    let half = P2::new(l.half_width, l.half_height);
    [l.centre.minus(half), l.centre.plus(half)]
}

fn bounds(points: impl Iterator<Item = P2>) -> (P2, P2) {
    let mut min = P2::new(f64::INFINITY, f64::INFINITY);
    let mut max = P2::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
    for p in points {
        min = P2::new(min.x.min(p.x), min.y.min(p.y));
        max = P2::new(max.x.max(p.x), max.y.max(p.y));
    }
    if min.x > max.x {
        return (P2::new(0.0, 0.0), P2::new(0.0, 0.0));
    }
    (min, max)
}

/// A mark with its points moved by `s` (widths and dot radii are in figure units already).
fn moved(mark: Mark, s: impl Fn(P2) -> P2 + Copy) -> Mark {
    match mark {
        Mark::Path {
            points,
            closed,
            filled,
            stroke,
        } => Mark::Path {
            points: points.into_iter().map(s).collect(),
            closed,
            filled,
            stroke,
        },
        Mark::Arrow {
            from,
            via,
            to,
            double,
            stroke,
            role,
        } => Mark::Arrow {
            from: s(from),
            via: via.into_iter().map(s).collect(),
            to: s(to),
            double,
            stroke,
            role,
        },
        Mark::Dot { at, radius } => Mark::Dot { at: s(at), radius },
    }
}
