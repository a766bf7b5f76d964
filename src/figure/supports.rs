//! The supports a textbook draws round a body, each ending on a hatched base (a line with
//! short slanted hatches, facing the reader, as a fixed surface is drawn):
//!
//! - the pivot at a fixed point O that nothing else drawn holds (a top's tip, a gyroscope's
//!   stand, SP 18.2's axle): a pedestal under O standing on a base, over O where the body
//!   hangs from it (its mass centre below O). Where ω turns about a fixed axis the shaft and
//!   its bearings hold the body, and where O lies on a floor a body rolls on (a cone's apex)
//!   the floor does; none where an arrow drawn from O runs the pedestal's way (SP 18.5's
//!   −ω₂ j), which it would hide, nor where it would stand on or against the body as drawn
//!   (a wheel round its pivot), where it would read as part of the body;
//! - the wires the scene hangs the body from (`wire from P to Q`, SP 18.1's plate): a line
//!   from the body's point to its anchor, the base across it there;
//! - the posts the scene stands round it (`post from P to Q`, the post a spinning rod strikes):
//!   a bar from its base, hatched, to its top.
//!
//! ```text
//!        O
//!       / \        height PEDESTAL, half-width PEDESTAL_HALF_WIDTH
//!      /___\
//!    ///////// base, BASE_HALF_WIDTH each side, hatched
//! ```

use super::canvas::{Canvas, Layer};
use super::extent::Extent;
use super::view::{self, add, scaled, P3};
use super::{FigureError, Stroke};
use crate::scene::model::{Scene, SupportKind};

/// The pedestal's height, its half-width and a base's half-width, in shares of the reach.
const PEDESTAL: f64 = 0.12;
const PEDESTAL_HALF_WIDTH: f64 = 0.06;
const BASE_HALF_WIDTH: f64 = 0.1;
/// The hatches under a base: how many, and their depth in shares of the pedestal's height.
const HATCHES: u32 = 5;
const HATCH: f64 = 0.35;
/// How near, in shares of the reach, O must lie to a floor's level to stand on it.
const ON_FLOOR: f64 = 1e-6;
/// An arrow from O within this angle of the pedestal's direction takes that side.
const TAKEN_DEG: f64 = 25.0;

/// The pivot at O where the scene fixes O and no floor at O's level (`floors`, the levels of
/// the floors drawn) holds it, on a side no arrow drawn from O (`from_o`, their unit
/// directions) takes. The caller leaves it out where a fixed axis holds the body.
pub fn pivot(canvas: &mut Canvas, scene: &Scene, body: &Extent, floors: &[f64], from_o: &[P3]) {
    if !scene.fixed_point {
        return;
    }
    let up = canvas.view().up();
    if floors
        .iter()
        .any(|level| level.abs() < ON_FLOOR * body.reach)
    {
        return;
    }
    // Away from the body: under O, over it where the body hangs from O.
    let away = match view::dot(body.centre, up) < 0.0 {
        true => up,
        false => scaled(up, -1.0),
    };
    let taken = TAKEN_DEG.to_radians().cos();
    if from_o.iter().any(|d| view::dot(*d, away) >= taken) {
        return;
    }
    let reach = body.reach;
    let foot = scaled(away, PEDESTAL * reach);
    let across = facing(canvas, away);
    // A pedestal drawn on or against the body (a wheel round its pivot) would read as part
    // of it: none where O, the foot or the base's ends come within a pedestal's height of
    // the body's outline on the page.
    let base_end = |side: f64| add(foot, scaled(across, side * BASE_HALF_WIDTH * reach));
    let marks = [[0.0; 3], foot, base_end(1.0), base_end(-1.0)];
    let page = |p: P3| canvas.project(p);
    let near_body = |p: P3| {
        body.covers(canvas, p)
            || body
                .samples
                .iter()
                .any(|s| page(*s).minus(page(p)).length() < PEDESTAL * reach)
    };
    if marks.into_iter().any(near_body) {
        return;
    }
    let corner = |side: f64| add(foot, scaled(across, side * PEDESTAL_HALF_WIDTH * reach));
    let pedestal = [[0.0; 3], corner(1.0), corner(-1.0)];
    canvas.path(Layer::Behind, &pedestal, true, Stroke::GROUND);
    base(canvas, foot, away, reach);
}

/// Each wire and post the scene states: a wire's line from the body to its anchor, the base
/// across it there; a post's bar, drawn among the parts at its depth, from the base it stands
/// on to its top. Each kept clear of the arrows drawn after it.
pub fn stated(canvas: &mut Canvas, scene: &Scene, body: &Extent) -> Result<(), FigureError> {
    for (k, support) in scene.supports.iter().enumerate() {
        let what = format!("support {}", k + 1);
        let from = canvas.vector(&support.from, &what)?;
        let to = canvas.vector(&support.to, &what)?;
        if view::norm(view::sub(to, from)) == 0.0 {
            continue;
        }
        match support.kind {
            SupportKind::Wire => {
                canvas.path(Layer::Behind, &[from, to], false, Stroke::WIRE);
                canvas.keep_clear(from, to, Stroke::WIRE);
                base(canvas, to, view::unit(view::sub(to, from)), body.reach);
            }
            SupportKind::Post => {
                canvas.bar(from, to, Stroke::SHAFT);
                canvas.keep_clear(from, to, Stroke::SHAFT);
                base(canvas, from, view::unit(view::sub(from, to)), body.reach);
            }
        }
    }
    Ok(())
}

/// Across the unit `away`, square to the eye too: a base across it faces the reader.
fn facing(canvas: &Canvas, away: P3) -> P3 {
    view::unit(view::cross(canvas.view().toward_eye(), away))
}

/// A fixed surface's base at `at`, across the unit `away` (the side it holds from), its
/// hatches slanting away.
fn base(canvas: &mut Canvas, at: P3, away: P3, reach: f64) {
    let across = facing(canvas, away);
    let point = |out: f64, side: f64| add(at, add(scaled(away, out), scaled(across, side)));
    let half = BASE_HALF_WIDTH * reach;
    canvas.path(
        Layer::Behind,
        &[point(0.0, -half), point(0.0, half)],
        false,
        Stroke::GROUND,
    );
    let depth = HATCH * PEDESTAL * reach;
    for k in 0..HATCHES {
        let side = -half + 2.0 * half * f64::from(k + 1) / f64::from(HATCHES + 1);
        let hatch = [point(0.0, side), point(depth, side - depth)];
        canvas.path(Layer::Behind, &hatch, false, Stroke::GROUND);
    }
}
