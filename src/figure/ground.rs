//! The floor a body rolls on: where the scene holds a point of the body still
//! (`constraint velocity at P = 0`) at the body's lowest level, with no blow there (a blow
//! held at a point is an impact on a ledge or a post, which the scene does not shape), a patch
//! of the level plane through the point, square to the scene's up, drawn behind the body, as
//! a textbook draws the floor a disk or a cone rolls on.

use super::body::Extent;
use super::canvas::{Canvas, Layer};
use super::view::{self, add, scaled};
use super::{FigureError, Stroke};
use crate::scene::model::{ConstraintKind, Scene};

/// Half the patch's side, in proportion to the body's reach.
const HALF_SIDE: f64 = 0.45;

/// The floor under each point held still at the body's lowest level; the level of each floor
/// drawn (its height along the scene's up).
pub fn draw(canvas: &mut Canvas, scene: &Scene, body: &Extent) -> Result<Vec<f64>, FigureError> {
    let up = canvas.view().up();
    let (u, v) = view::across(up);
    let struck = scene
        .impulses
        .iter()
        .map(|i| canvas.vector(&i.point, "an impulse's point"))
        .collect::<Result<Vec<_>, _>>()?;
    let bottom = body
        .samples
        .iter()
        .map(|s| view::dot(*s, up))
        .fold(f64::INFINITY, f64::min);
    let mut levels = Vec::new();
    for c in &scene.constraints {
        let ConstraintKind::VelocityZero(at) = &c.kind else {
            continue;
        };
        let p = canvas.vector(at, "the point held still")?;
        let lowest = bottom >= view::dot(p, up) - 1e-6 * body.reach;
        let blow = struck
            .iter()
            .any(|q| view::norm(view::sub(*q, p)) < 1e-9 * body.reach);
        if !lowest || blow {
            continue;
        }
        let h = HALF_SIDE * body.reach;
        let corners = [(1.0, 1.0), (1.0, -1.0), (-1.0, -1.0), (-1.0, 1.0)]
            .map(|(a, b)| add(p, add(scaled(u, a * h), scaled(v, b * h))));
        canvas.path(Layer::Behind, &corners, true, Stroke::GROUND);
        levels.push(view::dot(p, up));
    }
    Ok(levels)
}
