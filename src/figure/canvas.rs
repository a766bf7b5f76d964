//! The canvas a figure is drawn on: the scene's points projected by the view (in the scene's
//! length unit until [`Canvas::finish`] scales them), marks in three layers — behind (the
//! axes), the body's parts far to near, in front (loads and motion) — and the labels asked
//! for, placed when the scale is known.

use super::labels::{self, Wanted};
use super::sizes::Sizes;
use super::view::{self, View, P2, P3};
use super::{Figure, FigureError, Label, Mark, Role, Stroke, MARKS_HEIGHT, MARKS_WIDTH};
use crate::algebra::{Expr, Vector};
use crate::mechanics::eulerian_angles::EulerianAngles;
use crate::scene::model::Scene;

/// The room left around the drawing, in figure units.
const MARGIN: f64 = 6.0;

pub struct Canvas<'s> {
    sizes: &'s Sizes,
    view: View,
    behind: Vec<Mark>,
    /// Each part's marks with the depth of its centre.
    parts: Vec<(f64, Vec<Mark>)>,
    front: Vec<Mark>,
    wanted: Vec<Wanted>,
}

/// Where a mark goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layer {
    Behind,
    Front,
}

impl<'s> Canvas<'s> {
    /// The canvas of `scene` with its up drawn up: the fixed vertical K of the Eulerian
    /// angles, else against the weight (a force holding `g`, or named `W`, `W_1`, `weight`),
    /// else the axis the frame turns about (a precession about the vertical), else z.
    pub fn new(scene: &Scene, sizes: &'s Sizes) -> Result<Canvas<'s>, FigureError> {
        let mut canvas = Canvas {
            sizes,
            view: View::with_up([0.0, 0.0, 1.0]),
            behind: Vec::new(),
            parts: Vec::new(),
            front: Vec::new(),
            wanted: Vec::new(),
        };
        let up = if scene.euler_angles.is_some() {
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
        let mut directions = vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        if let (Some(omega), None) = (&scene.omega, &scene.euler_angles) {
            let w = canvas.vector(omega, "omega")?;
            if view::norm(w) > 0.0 {
                directions.push(w);
            }
        }
        for (k, part) in scene.parts.iter().enumerate() {
            for j in 0..3 {
                let axis = (0..3)
                    .map(|i| canvas.value(&part.rotation[(i, j)], &format!("body {}", k + 1)))
                    .collect::<Result<Vec<f64>, _>>()?;
                directions.push([axis[0], axis[1], axis[2]]);
            }
        }
        canvas.view = View::choose(up, &directions);
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

    fn layer(&mut self, layer: Layer) -> &mut Vec<Mark> {
        match layer {
            Layer::Behind => &mut self.behind,
            Layer::Front => &mut self.front,
        }
    }

    /// A polyline (or polygon) through the scene's points.
    pub fn path(&mut self, layer: Layer, points: &[P3], closed: bool, stroke: Stroke) {
        let points = points.iter().map(|p| self.project(*p)).collect();
        self.layer(layer).push(Mark::Path {
            points,
            closed,
            filled: false,
            stroke,
        });
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
        let (from, to) = (self.project(from), self.project(to));
        self.layer(layer).push(Mark::Arrow {
            from,
            via: Vec::new(),
            to,
            double,
            stroke,
            role,
        });
    }

    /// An arrow along a curve through the scene's points, its head at the last.
    pub fn curved_arrow(&mut self, points: &[P3], stroke: Stroke, role: Role) {
        let mut drawn: Vec<P2> = points.iter().map(|p| self.project(*p)).collect();
        let (Some(to), true) = (drawn.pop(), !drawn.is_empty()) else {
            return;
        };
        let from = drawn.remove(0);
        self.front.push(Mark::Arrow {
            from,
            via: drawn,
            to,
            double: false,
            stroke,
            role,
        });
    }

    /// A dot of `radius` figure units at a scene's point.
    pub fn dot(&mut self, p: P3, radius: f64) {
        let at = self.project(p);
        self.front.push(Mark::Dot { at, radius });
    }

    /// A part's marks, drawn after the parts farther from the eye than `centre`.
    pub fn part(&mut self, centre: P3, marks: Vec<Mark>) {
        let depth = self.view.depth(centre);
        self.parts.push((depth, marks));
    }

    /// A label for the scene's point `anchor`, wanted on the side `direction` (the scene's
    /// frame) points to.
    pub fn label(&mut self, markup: String, anchor: P3, direction: P3) {
        self.want(markup, anchor, direction, false);
    }

    /// A label of something on the body (G, a named point, a part's size), which may stand
    /// on the body's faces.
    pub fn label_on_body(&mut self, markup: String, anchor: P3, direction: P3) {
        self.want(markup, anchor, direction, true);
    }

    fn want(&mut self, markup: String, anchor: P3, direction: P3, on_body: bool) {
        let at = self.project(anchor);
        let toward = self.project(view::add(anchor, direction)).minus(at);
        self.wanted.push(Wanted {
            markup,
            anchor: at,
            direction: toward.unit().unwrap_or(P2::new(1.0, 0.0)),
            on_body,
        });
    }

    /// The figure: every mark scaled so the drawing is [`MARKS_WIDTH`] wide (or
    /// [`MARKS_HEIGHT`] high), then the labels placed.
    pub fn finish(self) -> Figure {
        let mut marks = self.behind;
        let mut parts = self.parts;
        parts.sort_by(|a, b| a.0.total_cmp(&b.0));
        marks.extend(parts.into_iter().flat_map(|(_, m)| m));
        marks.extend(self.front);
        // Without the heads, which are in figure units already.
        let (min, max) = bounds(marks.iter().flat_map(Mark::line));
        let (w, h) = (max.x - min.x, max.y - min.y);
        let scale = match (w > 0.0, h > 0.0) {
            (true, true) => (MARKS_WIDTH / w).min(MARKS_HEIGHT / h),
            (true, false) => MARKS_WIDTH / w,
            (false, true) => MARKS_HEIGHT / h,
            (false, false) => 1.0,
        };
        let marks: Vec<Mark> = marks.into_iter().map(|m| scaled(m, scale)).collect();
        let wanted: Vec<Wanted> = self
            .wanted
            .into_iter()
            .map(|w| Wanted {
                anchor: w.anchor.times(scale),
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

/// A mark with its points times `k` (widths and dot radii are in figure units already).
fn scaled(mark: Mark, k: f64) -> Mark {
    let s = |p: P2| p.times(k);
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
