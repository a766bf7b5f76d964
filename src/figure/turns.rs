//! The angles a part is turned through, where the scene names them (`body disk(r) mass m
//! rotated beta about z`): at the part's centre, a dashed line along one of its own axes as it
//! stood before the turn, one along it after, and the arc between them labelled with the
//! angle, as a textbook marks the tilt β of a disk on its shaft.
//!
//! The axis drawn is the part's own x' (a rod's length, a disk's axis, a box's edge a) unless
//! the turn is about it, then y'. Its direction after the turn through θ about the unit `a` is
//! Rodrigues' `v cos θ + (a × v) sin θ + a (a · v)(1 − cos θ)`; both lines are drawn square to
//! `a`, so the arc between them is the angle θ itself.

use super::canvas::{Canvas, Layer};
use super::extent::Extent;
use super::view::{self, add, cross, dot, scaled, square_to, P3};
use super::{FigureError, Stroke};
use crate::mechanics::shapes::Shape;
use crate::scene::model::Scene;

/// The arc's radius, in proportion to the body's reach: [`ARC_RADIUS`], or for a small angle
/// as much as gives an arc [`SHORTEST_ARC`] long, up to [`LONGEST_RADIUS`]; the lines run on
/// past it by a share of it.
const ARC_RADIUS: f64 = 0.55;
const SHORTEST_ARC: f64 = 0.3;
const LONGEST_RADIUS: f64 = 0.9;
const LINE_PAST_ARC: f64 = 1.45;
/// Points on an arc.
const ARC_POINTS: usize = 24;

/// Each named angle a part is turned through, marked at the part's centre.
pub fn draw(canvas: &mut Canvas, scene: &Scene, body: &Extent) -> Result<(), FigureError> {
    for (k, part) in scene.parts.iter().enumerate() {
        let what = format!("body {}", k + 1);
        let centre = canvas.vector(&part.position, &what)?;
        for turn in &part.turns {
            if turn.angle.as_symbol().is_none() {
                continue;
            }
            let a = view::unit(canvas.vector(&turn.axis, &what)?);
            let theta = canvas.value(&turn.angle, &what)?;
            // A rod's own x' (its length) as it stood, unless the turn is about it; another
            // part's own axis across the turn drawn longest (a disk's diameter, not its axis
            // seen end-on along a shaft toward the reader).
            let own = canvas.columns(&turn.from, &what)?;
            let across = |v: &P3| view::norm(square_to(*v, a)) > 0.5;
            let drawn = |v: &P3| {
                let d = square_to(*v, a);
                canvas.project(d).minus(canvas.project([0.0; 3])).length()
            };
            let before = match (&part.shape, across(&own[0])) {
                (Shape::SlenderRod { .. }, true) => own[0],
                _ => own
                    .iter()
                    .filter(|v| across(v))
                    .copied()
                    .max_by(|u, v| drawn(u).total_cmp(&drawn(v)))
                    .unwrap_or(own[1]),
            };
            let from = view::unit(square_to(before, a));
            // A small angle on a larger arc, so it is seen.
            let radius = (SHORTEST_ARC / theta.abs().max(1e-9)).clamp(ARC_RADIUS, LONGEST_RADIUS);
            mark(canvas, centre, from, a, theta, radius * body.reach);
            let middle = turned(from, a, theta / 2.0);
            canvas.label(
                super::arrows::label(&turn.angle),
                add(centre, scaled(middle, radius * body.reach)),
                middle,
            );
        }
    }
    Ok(())
}

/// The lines from `centre` along `from` and along it turned through `theta` about `a`, past
/// the arc of `radius` between them, and the arc.
fn mark(canvas: &mut Canvas, centre: P3, from: P3, a: P3, theta: f64, radius: f64) {
    for d in [from, turned(from, a, theta)] {
        let tip = add(centre, scaled(d, radius * LINE_PAST_ARC));
        canvas.path(Layer::Front, &[centre, tip], false, Stroke::CENTRE_LINE);
    }
    arc(canvas, centre, from, a, theta, radius);
}

/// The arc of `radius` about `centre` from the unit `from` through `theta` about the unit `a`
/// (square to `from`).
pub fn arc(canvas: &mut Canvas, centre: P3, from: P3, a: P3, theta: f64, radius: f64) {
    let arc: Vec<P3> = (0..=ARC_POINTS)
        .map(|s| {
            let t = theta * s as f64 / ARC_POINTS as f64;
            add(centre, scaled(turned(from, a, t), radius))
        })
        .collect();
    canvas.path(Layer::Front, &arc, false, Stroke::MOTION);
}

/// `v` turned through `theta` about the unit `a` (Rodrigues).
pub fn turned(v: P3, a: P3, theta: f64) -> P3 {
    let (c, s) = (theta.cos(), theta.sin());
    add(
        add(scaled(v, c), scaled(cross(a, v), s)),
        scaled(a, dot(a, v) * (1.0 - c)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quarter_turn_about_z_takes_x_to_y_and_back() {
        let (x, z) = ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
        let y = turned(x, z, std::f64::consts::FRAC_PI_2);
        assert!(y[0].abs() < 1e-12 && (y[1] - 1.0).abs() < 1e-12 && y[2].abs() < 1e-12);
        let back = turned(y, z, -std::f64::consts::FRAC_PI_2);
        assert!((back[0] - 1.0).abs() < 1e-12 && back[1].abs() < 1e-12);
    }
}
