//! The body part by part, each in its own axes turned into the frame's (`frame = R · own`)
//! and placed by its mass centre: a rod a thick segment along x', a plate a parallelogram,
//! a disk or ring the ellipse its circle projects to, a cylinder, tube or cone the outline of
//! its ends (the convex hull of the projected circles, the apex) with the near end on it, a
//! sphere or shell its silhouette circle with an equator, a prism its faces toward the eye, a
//! point mass a dot; a body given only by its inertia a dashed sphere. Each part fills white,
//! nearer parts over farther ones.

use super::canvas::Canvas;
use super::extent::{convex_hull, Extent, Solid};
use super::view::{self, across, add, scaled, sub, P2, P3};
use super::{Dashes, FigureError, Mark, Stroke};
use crate::mechanics::shapes::Shape;
use crate::scene::model::{Part, Scene};

/// Points on a drawn circle.
const CIRCLE_POINTS: usize = 48;
/// A point mass's dot radius, in figure units.
const POINT_MASS_RADIUS: f64 = 3.5;
/// The white left each side of a rod where a farther line crosses behind it, in figure
/// units, and the share of its length at each end left without (its joints).
const ROD_GAP: f64 = 2.5;
const JOINT: f64 = 0.15;
/// Draws every part; the body's extent.
pub fn draw(canvas: &mut Canvas, scene: &Scene) -> Result<Extent, FigureError> {
    let mut samples = Vec::new();
    let mut solids = Vec::new();
    let mut lines = Vec::new();
    let loaded = canvas.loaded_points(scene)?;
    let (mut mass, mut moment) = (0.0, [0.0; 3]);
    for (k, part) in scene.parts.iter().enumerate() {
        let what = format!("body {}", k + 1);
        let placed = Placed::of(canvas, part, &what)?;
        let m = canvas.value(&part.mass, &what)?;
        mass += m;
        moment = add(moment, scaled(placed.centre, m));
        let (outline, mut marks) = placed.outline(canvas, &part.shape, &loaded, &what)?;
        // A point mass is named by its mass (m_1), as a figure names an unbalance.
        if let (Shape::PointMass, Some(_)) = (&part.shape, part.mass.as_symbol()) {
            canvas.label_on_body(
                super::arrows::label(&part.mass),
                placed.centre,
                placed.centre,
            );
        }
        let alone = scene.parts.len() == 1;
        for size in placed.named_sizes(canvas, &part.shape, alone, &what)? {
            if let Some([a, b]) = size.line {
                marks.push(open_path(canvas, &[a, b], Stroke::AXIS));
            }
            canvas.label_along(size.label, size.along, size.outward);
        }
        if let (Shape::SlenderRod { .. }, [a, b]) = (&part.shape, &outline[..]) {
            canvas.keep_clear(*a, *b, Stroke::ROD);
        }
        match (&part.shape, &outline[..]) {
            (Shape::SlenderRod { .. }, [a, b]) => lines.push([*a, *b]),
            (Shape::PointMass, _) => lines.push([placed.centre; 2]),
            _ => solids.push(Solid {
                samples: outline.clone(),
                centre: placed.centre,
                axes: placed.axes,
                opaque: !matches!(part.shape, Shape::ThinRing { .. }),
            }),
        }
        samples.extend(outline);
        canvas.part(placed.centre, marks);
    }
    let centre = match mass > 0.0 {
        true => scaled(moment, 1.0 / mass),
        false => [0.0; 3],
    };
    let reach = samples
        .iter()
        .flat_map(|p| [view::norm(*p), view::norm(sub(*p, centre))])
        .fold(0.0, f64::max);
    Ok(Extent {
        samples,
        centre,
        reach: if reach > 0.0 { reach } else { 1.0 },
        solids,
        lines,
    })
}

/// A length of a shape written as one symbol, labelled with it where it shows: a rod's or a
/// side's by the middle half of it, a radius by a thin line from the centre to the rim, a
/// cone's height by one along its axis; the label stands by a point of `along`, by its
/// middle where that is free.
struct NamedSize {
    label: String,
    along: [P3; 2],
    outward: P3,
    line: Option<[P3; 2]>,
}

/// A part's mass centre and its own axes in the frame.
struct Placed {
    centre: P3,
    axes: [P3; 3],
}

impl Placed {
    fn of(canvas: &Canvas, part: &Part, what: &str) -> Result<Placed, FigureError> {
        let centre = canvas.vector(&part.position, what)?;
        let axes = canvas.columns(&part.rotation, what)?;
        Ok(Placed { centre, axes })
    }

    /// The point at own coordinates `(a, b, c)`.
    fn at(&self, a: f64, b: f64, c: f64) -> P3 {
        let [x, y, z] = self.axes;
        add(
            self.centre,
            add(scaled(x, a), add(scaled(y, b), scaled(z, c))),
        )
    }

    /// The outline points of the part and its marks.
    fn outline(
        &self,
        canvas: &Canvas,
        shape: &Shape,
        loaded: &[P3],
        what: &str,
    ) -> Result<(Vec<P3>, Vec<Mark>), FigureError> {
        let len = |e| canvas.value(e, what);
        let x = self.axes[0];
        let end = |h: f64| add(self.centre, scaled(x, h));
        Ok(match shape {
            Shape::SlenderRod { length } => {
                let l = len(length)? / 2.0;
                let ends = vec![self.at(-l, 0.0, 0.0), self.at(l, 0.0, 0.0)];
                // Paper under its middle: a farther rod crossing behind it shows broken there;
                // one joined to its end (a frame's corner) is left whole.
                let middle = l * (1.0 - 2.0 * JOINT);
                let gap = open_path(
                    canvas,
                    &[self.at(-middle, 0.0, 0.0), self.at(middle, 0.0, 0.0)],
                    Stroke::gap(Stroke::ROD.width + 2.0 * ROD_GAP),
                );
                let mark = open_path(canvas, &ends, Stroke::ROD);
                (ends, vec![gap, mark])
            }
            Shape::ThinPlate { a, b } => {
                let (a, b) = (len(a)? / 2.0, len(b)? / 2.0);
                let corners = vec![
                    self.at(-a, -b, 0.0),
                    self.at(a, -b, 0.0),
                    self.at(a, b, 0.0),
                    self.at(-a, b, 0.0),
                ];
                let mark = face(canvas, &corners);
                (corners, vec![mark])
            }
            Shape::ThinDisk { radius } => {
                let c = circle(self.centre, x, len(radius)?);
                let mark = face(canvas, &c);
                (c, vec![mark])
            }
            Shape::ThinRing { radius } => {
                let c = circle(self.centre, x, len(radius)?);
                let mark = closed_path(canvas, &c, Stroke::ROD);
                (c, vec![mark])
            }
            Shape::SolidCylinder { radius, length } => {
                let (r, h) = (len(radius)?, len(length)? / 2.0);
                let ends = [circle(end(-h), x, r), circle(end(h), x, r)];
                solid_of(canvas, &ends, x)
            }
            Shape::Tube {
                outer,
                inner,
                length,
            } => {
                let (r, ri, h) = (len(outer)?, len(inner)?, len(length)? / 2.0);
                let ends = [circle(end(-h), x, r), circle(end(h), x, r)];
                let (points, mut marks) = solid_of(canvas, &ends, x);
                let near = near_end(canvas, x, h);
                marks.push(closed_path(
                    canvas,
                    &circle(end(near), x, ri),
                    Stroke::OUTLINE,
                ));
                (points, marks)
            }
            Shape::SolidCone { radius, height } => {
                // G is a quarter of the height from the base: the apex ¾h behind it.
                let (r, h) = (len(radius)?, len(height)?);
                let apex = end(-0.75 * h);
                let base = circle(end(0.25 * h), x, r);
                let mut points = base.clone();
                points.push(apex);
                let hull = hull(canvas, &points);
                let base_mark = closed_path(canvas, &base, Stroke::OUTLINE);
                (points, vec![hull, base_mark])
            }
            Shape::SolidSphere { radius } | Shape::SphericalShell { radius } => {
                sphere(canvas, self.centre, len(radius)?, false)
            }
            Shape::RectangularPrism { a, b, c } => {
                let half = [len(a)? / 2.0, len(b)? / 2.0, len(c)? / 2.0];
                let (corners, mut marks) = self.prism(canvas, half);
                marks.extend(self.hidden_edges(canvas, half, loaded));
                (corners, marks)
            }
            Shape::Gyration { radii } => {
                let r = radii
                    .iter()
                    .map(len)
                    .try_fold(0.0, |m, k| k.map(|k| f64::max(m, k)))?;
                sphere(canvas, self.centre, r, true)
            }
            Shape::Explicit(_) => {
                let r = 0.25 * canvas.base_length();
                sphere(canvas, self.centre, r, true)
            }
            Shape::PointMass => (
                vec![self.centre],
                vec![Mark::Dot {
                    at: canvas.project(self.centre),
                    radius: POINT_MASS_RADIUS,
                }],
            ),
        })
    }

    /// The shape's lengths that are one symbol (`rod(c)`, `plate(a, b)`, `disk(r)`), each
    /// labelled with it: a rod's at its middle, or where its middle is the body's mass centre
    /// (`alone`, the body's one part), lettered G, half way from there to its end.
    fn named_sizes(
        &self,
        canvas: &Canvas,
        shape: &Shape,
        alone: bool,
        what: &str,
    ) -> Result<Vec<NamedSize>, FigureError> {
        let [x, y, _] = self.axes;
        // A radius is drawn along a diagonal of the part's plane (off the frame's axes that
        // often lie in it), the one drawn most nearly down and to the right.
        let (a, b) = across(x);
        let screen = |d: P3| canvas.project(d).minus(canvas.project([0.0; 3]));
        let u = [add(a, b), sub(a, b), sub(b, a), scaled(add(a, b), -1.0)]
            .map(view::unit)
            .into_iter()
            .max_by(|p, q| {
                let (p, q) = (screen(*p), screen(*q));
                (p.x - p.y).total_cmp(&(q.x - q.y))
            })
            .unwrap_or(a);
        let mut out = Vec::new();
        // Named by the middle half of the stretch from `at − half` to `at + half`.
        let mut name =
            |e: &crate::algebra::Expr, (at, half): (P3, P3), outward: P3, line: Option<[P3; 2]>| {
                if e.as_symbol().is_some() {
                    let quarter = scaled(half, 0.5);
                    out.push(NamedSize {
                        label: super::arrows::label(e),
                        along: [sub(at, quarter), add(at, quarter)],
                        outward,
                        line,
                    });
                }
            };
        let len = |e| canvas.value(e, what);
        match shape {
            Shape::SlenderRod { length } => {
                // A lone rod's from G to its end, off G's letter.
                let l = len(length)? / 2.0;
                let (at, half) = match alone {
                    true => (add(self.centre, scaled(x, l / 2.0)), scaled(x, l / 2.0)),
                    false => (self.centre, scaled(x, l)),
                };
                name(length, (at, half), u, None);
            }
            Shape::ThinPlate { a, b } => {
                let (ha, hb) = (len(a)? / 2.0, len(b)? / 2.0);
                let a_side = (self.at(0.0, -hb, 0.0), scaled(x, ha));
                name(a, a_side, scaled(y, -1.0), None);
                name(b, (self.at(ha, 0.0, 0.0), scaled(y, hb)), x, None);
            }
            Shape::RectangularPrism { a, b, c } => {
                let half = [len(a)? / 2.0, len(b)? / 2.0, len(c)? / 2.0];
                for (k, side) in [a, b, c].into_iter().enumerate() {
                    let middle = self.outline_edge(canvas, half, k);
                    let edge = (middle, scaled(self.axes[k], half[k]));
                    name(side, edge, sub(middle, self.centre), None);
                }
            }
            Shape::ThinDisk { radius }
            | Shape::ThinRing { radius }
            | Shape::SolidSphere { radius }
            | Shape::SphericalShell { radius } => {
                let rim = add(self.centre, scaled(u, len(radius)?));
                let half = scaled(u, len(radius)? / 2.0);
                name(
                    radius,
                    (add(self.centre, half), half),
                    u,
                    Some([self.centre, rim]),
                );
            }
            Shape::SolidCylinder { radius, length }
            | Shape::Tube {
                outer: radius,
                length,
                ..
            } => {
                let (r, h) = (len(radius)?, len(length)? / 2.0);
                let near = add(self.centre, scaled(x, near_end(canvas, x, h)));
                let rim = add(near, scaled(u, r));
                let half_radius = scaled(u, r / 2.0);
                name(
                    radius,
                    (add(near, half_radius), half_radius),
                    u,
                    Some([near, rim]),
                );
                name(
                    length,
                    (add(self.centre, scaled(u, r)), scaled(x, h)),
                    u,
                    None,
                );
            }
            Shape::SolidCone { radius, height } => {
                let (r, h) = (len(radius)?, len(height)?);
                let base = add(self.centre, scaled(x, 0.25 * h));
                let apex = add(self.centre, scaled(x, -0.75 * h));
                let half_radius = scaled(u, r / 2.0);
                name(
                    radius,
                    (add(base, half_radius), half_radius),
                    u,
                    Some([base, add(base, scaled(u, r))]),
                );
                // The height along the axis, from the apex to the base's centre.
                let middle = (add(self.centre, scaled(x, -0.25 * h)), scaled(x, h / 2.0));
                name(height, middle, scaled(u, -1.0), Some([apex, base]));
            }
            Shape::Gyration { .. } | Shape::Explicit(_) | Shape::PointMass => {}
        }
        Ok(out)
    }

    /// A box's faces that look toward the eye, each filled.
    fn prism(&self, canvas: &Canvas, half: [f64; 3]) -> (Vec<P3>, Vec<Mark>) {
        let eye = canvas.view().toward_eye();
        let corner = |s: [f64; 3]| self.at(s[0] * half[0], s[1] * half[1], s[2] * half[2]);
        let mut corners = Vec::new();
        let mut marks = Vec::new();
        for axis in 0..3 {
            for side in [-1.0, 1.0] {
                let outward = scaled(self.axes[axis], side);
                let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
                let face_corners: Vec<P3> = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                    .iter()
                    .map(|(a, b)| {
                        let mut s = [0.0; 3];
                        s[axis] = side;
                        s[u] = *a;
                        s[v] = *b;
                        corner(s)
                    })
                    .collect();
                corners.extend(face_corners.iter().copied());
                if view::dot(outward, eye) > 1e-9 {
                    marks.push(face(canvas, &face_corners));
                }
            }
        }
        (corners, marks)
    }

    /// The middle of the box's edge along its own axis `k` that a side's length is written
    /// by: of the four, one on a face toward the eye, drawn farthest down and to the right of
    /// the centre (on the outline, clear of the faces).
    fn outline_edge(&self, canvas: &Canvas, half: [f64; 3], k: usize) -> P3 {
        let eye = canvas.view().toward_eye();
        let (u, v) = ((k + 1) % 3, (k + 2) % 3);
        let centre = canvas.project(self.centre);
        let mut best = (f64::NEG_INFINITY, self.centre);
        for (su, sv) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
            let seen = view::dot(scaled(self.axes[u], su), eye) > 0.0
                || view::dot(scaled(self.axes[v], sv), eye) > 0.0;
            let mut s = [0.0; 3];
            (s[u], s[v]) = (su * half[u], sv * half[v]);
            let middle = self.at(s[0], s[1], s[2]);
            let drawn = canvas.project(middle).minus(centre);
            let score = drawn.x * 0.5 - drawn.y;
            if seen && score > best.0 {
                best = (score, middle);
            }
        }
        best.1
    }

    /// A box's corner out of sight (its three faces turned from the eye) where a load acts
    /// or a point is named: its three edges dashed, as a textbook shows a hidden corner.
    fn hidden_edges(&self, canvas: &Canvas, half: [f64; 3], loaded: &[P3]) -> Vec<Mark> {
        let eye = canvas.view().toward_eye();
        // The far corner's sides: each against its axis's side facing the eye.
        let s = [0, 1, 2].map(|k| match view::dot(self.axes[k], eye) > 0.0 {
            true => -1.0,
            false => 1.0,
        });
        let at = |s: [f64; 3]| self.at(s[0] * half[0], s[1] * half[1], s[2] * half[2]);
        let corner = at(s);
        let size = view::norm(half);
        if !loaded
            .iter()
            .any(|p| view::norm(sub(*p, corner)) < 1e-9 * size)
        {
            return Vec::new();
        }
        (0..3)
            .map(|k| {
                let mut next = s;
                next[k] = -s[k];
                open_path(canvas, &[corner, at(next)], Stroke::HIDDEN)
            })
            .collect()
    }
}

/// Which end (−h or +h along the axis `x`) faces the eye.
fn near_end(canvas: &Canvas, x: P3, h: f64) -> f64 {
    match view::dot(x, canvas.view().toward_eye()) >= 0.0 {
        true => h,
        false => -h,
    }
}

/// A solid of revolution's two end circles: their hull filled, the near end drawn on it.
fn solid_of(canvas: &Canvas, ends: &[Vec<P3>; 2], x: P3) -> (Vec<P3>, Vec<Mark>) {
    let points: Vec<P3> = ends.iter().flatten().copied().collect();
    let hull = hull(canvas, &points);
    let near = match view::dot(x, canvas.view().toward_eye()) >= 0.0 {
        true => &ends[1],
        false => &ends[0],
    };
    let near = closed_path(canvas, near, Stroke::OUTLINE);
    (points, vec![hull, near])
}

/// A sphere's silhouette (the circle across the line of sight) filled, and its equator.
fn sphere(canvas: &Canvas, centre: P3, r: f64, dashed: bool) -> (Vec<P3>, Vec<Mark>) {
    let outline = circle(centre, canvas.view().toward_eye(), r);
    let stroke = Stroke {
        dashes: match dashed {
            true => Dashes::Hidden,
            false => Dashes::Solid,
        },
        ..Stroke::OUTLINE
    };
    let mut silhouette = face(canvas, &outline);
    if let Mark::Path { stroke: s, .. } = &mut silhouette {
        *s = stroke;
    }
    let equator = closed_path(canvas, &circle(centre, [0.0, 0.0, 1.0], r), Stroke::AXIS);
    let mut points = outline;
    points.extend(circle(centre, [1.0, 0.0, 0.0], r));
    points.extend(circle(centre, [0.0, 1.0, 0.0], r));
    (points, vec![silhouette, equator])
}

/// The circle of radius `r` about `centre` across the unit `axis`.
pub(super) fn circle(centre: P3, axis: P3, r: f64) -> Vec<P3> {
    let (u, v) = across(view::unit(axis));
    (0..CIRCLE_POINTS)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / CIRCLE_POINTS as f64;
            add(centre, add(scaled(u, r * t.cos()), scaled(v, r * t.sin())))
        })
        .collect()
}

fn open_path(canvas: &Canvas, points: &[P3], stroke: Stroke) -> Mark {
    Mark::Path {
        points: points.iter().map(|p| canvas.project(*p)).collect(),
        closed: false,
        filled: false,
        stroke,
    }
}

fn closed_path(canvas: &Canvas, points: &[P3], stroke: Stroke) -> Mark {
    Mark::Path {
        points: points.iter().map(|p| canvas.project(*p)).collect(),
        closed: true,
        filled: false,
        stroke,
    }
}

/// A polygon filled white with the outline's stroke.
fn face(canvas: &Canvas, points: &[P3]) -> Mark {
    Mark::Path {
        points: points.iter().map(|p| canvas.project(*p)).collect(),
        closed: true,
        filled: true,
        stroke: Stroke::OUTLINE,
    }
}

/// The convex hull of the projected points, filled.
pub(super) fn hull(canvas: &Canvas, points: &[P3]) -> Mark {
    let projected: Vec<P2> = points.iter().map(|p| canvas.project(*p)).collect();
    Mark::Path {
        points: convex_hull(projected),
        closed: true,
        filled: true,
        stroke: Stroke::OUTLINE,
    }
}
