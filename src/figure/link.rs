//! The link that holds a body pivoted at a point it does not reach: SP 18.2's axle OG of
//! negligible mass, a top's stem, a gyroscope's arm. A scene states no part for it (it has
//! no mass), yet without it the body floats apart from its pivot O; drawn as the shaft is, a
//! bar from O along OG to where it meets the body.

use super::canvas::Canvas;
use super::extent::Extent;
use super::view::{self, add, scaled, P3};
use super::Stroke;
use crate::scene::model::Scene;

/// The steps O to G is followed in to find where the link meets the body.
const STEPS: u32 = 100;
/// How near, in shares of the reach, the body must come to O to hold at O itself.
const AT_O: f64 = 1e-6;

/// The link from O to the body of one part about a fixed point O it does not reach, where
/// no shaft is drawn: drawn, and its ends (O, then where it meets the body). None where
/// there is no such link.
pub fn draw(canvas: &mut Canvas, scene: &Scene, body: &Extent) -> Option<[P3; 2]> {
    if !scene.fixed_point || scene.parts.len() != 1 {
        return None;
    }
    let margin = AT_O * body.reach;
    let along = |k: u32| scaled(body.centre, f64::from(k) / f64::from(STEPS));
    let meets = (0..=STEPS).find(|k| body.reaches(along(*k), margin))?;
    if meets == 0 {
        return None;
    }
    let end = along(meets);
    canvas.bar([0.0; 3], end, Stroke::SHAFT);
    canvas.keep_clear([0.0; 3], end, Stroke::SHAFT);
    Some([[0.0; 3], end])
}

/// Where along the link a label of its length stands, and the side it stands on: by its
/// middle, on the side the frame's axis drawn most nearly up the page points to, among those
/// square to it.
pub fn middle(canvas: &Canvas, [o, end]: [P3; 2]) -> (P3, P3) {
    let d = view::unit(view::sub(end, o));
    let side = view::UNIT
        .into_iter()
        .flat_map(|e| [e, scaled(e, -1.0)])
        .filter(|e| view::dot(*e, d).abs() < 0.5)
        .max_by(|a, b| {
            let up = |e: &P3| canvas.project(*e).y - canvas.project([0.0; 3]).y;
            up(a).total_cmp(&up(b))
        })
        .unwrap_or([0.0, 0.0, 1.0]);
    (add(o, scaled(view::sub(end, o), 0.5)), side)
}
