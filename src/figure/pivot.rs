//! The support at a fixed point O that nothing else drawn holds: a top's pivot, a gyroscope's
//! stand, the pivot of SP 18.2's axle. Where ω turns about a fixed axis the shaft and its
//! bearings hold the body, and where O lies on the floor a body rolls on (a cone's apex) the
//! floor does; elsewhere the scene's `fixed point` is drawn as a textbook draws a pivot, a
//! pedestal under O standing on a hatched base, facing the reader:
//!
//! ```text
//!        O
//!       / \        height PEDESTAL, half-width PEDESTAL_HALF_WIDTH
//!      /___\
//!    ///////// base, BASE_HALF_WIDTH each side, hatched
//! ```
//!
//! under O, over it where the body hangs from O (its mass centre below); none where an arrow
//! drawn from O runs that way (SP 18.2's −ω₂ j), which a pedestal would hide.

use super::body::Extent;
use super::canvas::{Canvas, Layer};
use super::view::{self, add, scaled, P3};
use super::{FigureError, Stroke};
use crate::scene::model::Scene;

/// The pedestal's height, its half-width and its base's half-width, in shares of the reach.
const PEDESTAL: f64 = 0.12;
const PEDESTAL_HALF_WIDTH: f64 = 0.06;
const BASE_HALF_WIDTH: f64 = 0.1;
/// The hatches under the base: how many, and their length in shares of the pedestal's height.
const HATCHES: u32 = 5;
const HATCH: f64 = 0.35;
/// How near, in shares of the reach, O must lie to a floor's level to stand on it.
const ON_FLOOR: f64 = 1e-6;
/// An arrow from O within this angle of the pedestal's direction takes that side.
const TAKEN_DEG: f64 = 25.0;

/// The pivot at O where the scene fixes O and no shaft (ω about a fixed direction) or floor
/// at O's level (`floors`, the levels of the floors drawn) holds it, on a side no arrow drawn
/// from O (`from_o`, their unit directions) takes.
pub fn draw(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    floors: &[f64],
    from_o: &[P3],
) -> Result<(), FigureError> {
    let unknowns = super::loads::magnitudes(scene);
    if !scene.fixed_point || super::loads::fixed_direction(canvas, scene, &unknowns)?.is_some() {
        return Ok(());
    }
    let up = canvas.view().up();
    if floors
        .iter()
        .any(|level| level.abs() < ON_FLOOR * body.reach)
    {
        return Ok(());
    }
    // Away from the body: under O, over it where the body hangs from O.
    let away = match view::dot(body.centre, up) < 0.0 {
        true => up,
        false => scaled(up, -1.0),
    };
    let taken = TAKEN_DEG.to_radians().cos();
    if from_o.iter().any(|d| view::dot(*d, away) >= taken) {
        return Ok(());
    }
    // Across, square to the eye and to up: the pedestal faces the reader.
    let across = view::unit(view::cross(canvas.view().toward_eye(), up));
    let reach = body.reach;
    let at = |down: f64, side: f64| {
        add(
            scaled(away, down * PEDESTAL * reach),
            scaled(across, side * reach),
        )
    };
    let pedestal = [
        at(0.0, 0.0),
        at(1.0, PEDESTAL_HALF_WIDTH),
        at(1.0, -PEDESTAL_HALF_WIDTH),
    ];
    canvas.path(Layer::Behind, &pedestal, true, Stroke::GROUND);
    let base = [at(1.0, -BASE_HALF_WIDTH), at(1.0, BASE_HALF_WIDTH)];
    canvas.path(Layer::Behind, &base, false, Stroke::GROUND);
    for k in 0..HATCHES {
        let side =
            -BASE_HALF_WIDTH + 2.0 * BASE_HALF_WIDTH * f64::from(k + 1) / f64::from(HATCHES + 1);
        let hatch = [at(1.0, side), at(1.0 + HATCH, side - HATCH * PEDESTAL)];
        canvas.path(Layer::Behind, &hatch, false, Stroke::GROUND);
    }
    Ok(())
}
