//! The floor a body rests or rolls on, at its lowest level, as a textbook draws it: a patch of
//! the level plane square to the scene's up, drawn behind the body. The floor stands under
//!
//! - a point the scene holds still (`constraint velocity at P = 0`) at or below the body's
//!   lowest level, with no blow there (a blow held at a point is an impact on a ledge or a
//!   post, which the scene does not shape): the disk or the cone rolling on it;
//! - a force of one component straight up at the body's lowest level: the floor's push on a
//!   box (N_A, N_B), which no other support gives;
//!
//! and it reaches the fixed point O where O lies on it (a cone's apex), so the line of contact
//! from O lies on the floor. One patch covers every such point at a level: its centre their
//! middle, its half side [`HALF_SIDE`] of the reach, or [`MARGIN`] past the farthest of them.

use super::canvas::{Canvas, Layer};
use super::extent::Extent;
use super::view::{self, add, scaled, P3};
use super::{FigureError, Stroke};
use crate::scene::model::{ConstraintKind, Scene};

/// The patch's half side, and its least margin past its farthest point, in proportion to
/// the body's reach.
const HALF_SIDE: f64 = 0.45;
const MARGIN: f64 = 0.2;
/// How near, in shares of the reach, two points stand to one level, and a force to up.
const LEVEL: f64 = 1e-6;
const STRAIGHT_UP: f64 = 1e-9;

/// The floor under the points held still or pushed up at the body's lowest level; the level
/// of each floor drawn (its height along the scene's up).
pub fn draw(canvas: &mut Canvas, scene: &Scene, body: &Extent) -> Result<Vec<f64>, FigureError> {
    let up = canvas.view().up();
    let height = |p: P3| view::dot(p, up);
    let near = LEVEL * body.reach;
    let bottom = body
        .samples
        .iter()
        .map(|s| height(*s))
        .fold(f64::INFINITY, f64::min);
    let mut held: Vec<P3> = Vec::new();
    let struck = scene
        .impulses
        .iter()
        .map(|i| canvas.vector(&i.point, "an impulse's point"))
        .collect::<Result<Vec<_>, _>>()?;
    for c in &scene.constraints {
        let ConstraintKind::VelocityZero(at) = &c.kind else {
            continue;
        };
        let p = canvas.vector(at, "the point held still")?;
        let blow = struck.iter().any(|q| view::norm(view::sub(*q, p)) < near);
        if bottom >= height(p) - near && !blow {
            held.push(p);
        }
    }
    for f in &scene.forces {
        let value = canvas.vector(&f.value, &f.name)?;
        let p = canvas.vector(&f.point, &f.name)?;
        let straight_up = view::norm(value) > 0.0
            && view::dot(view::unit(value), up) > 1.0 - STRAIGHT_UP
            && super::arrows::nonzero(&f.value).len() == 1;
        if straight_up && (height(p) - bottom).abs() < near {
            held.push(p);
        }
    }
    let mut levels: Vec<f64> = Vec::new();
    for p in &held {
        if !levels.iter().any(|l| (l - height(*p)).abs() < near) {
            levels.push(height(*p));
        }
    }
    let (u, v) = view::across(up);
    for level in &levels {
        let mut on: Vec<P3> = held
            .iter()
            .copied()
            .filter(|p| (height(*p) - level).abs() < near)
            .collect();
        if scene.fixed_point && level.abs() < near {
            on.push([0.0; 3]);
        }
        let middle = scaled(
            on.iter().fold([0.0; 3], |a, p| add(a, *p)),
            1.0 / on.len() as f64,
        );
        let farthest = on
            .iter()
            .map(|p| view::norm(view::sub(*p, middle)))
            .fold(0.0, f64::max);
        let h = (HALF_SIDE * body.reach).max(farthest + MARGIN * body.reach);
        let corners = [(1.0, 1.0), (1.0, -1.0), (-1.0, -1.0), (-1.0, 1.0)]
            .map(|(a, b)| add(middle, add(scaled(u, a * h), scaled(v, b * h))));
        canvas.path(Layer::Behind, &corners, true, Stroke::GROUND);
    }
    Ok(levels)
}
