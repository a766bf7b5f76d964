//! A gyroscope's or top's Eulerian angles (§18.9): the fixed vertical Z (along K, drawn up)
//! as a centre line from O, the angle θ from it to the axis of symmetry z as an arc, the
//! precession φ̇ a curved arrow about Z above the body and whatever is drawn up along Z, the
//! spin ψ̇ one about z past the body and whatever is drawn along z.

use super::body::Extent;
use super::canvas::{Canvas, Layer};
use super::view::{self, add, scaled, P3};
use super::{FigureError, Role, Stroke};
use crate::algebra::Expr;
use crate::mechanics::eulerian_angles::EulerianAngles;

/// Lengths in proportion to the body's reach: φ̇'s curve stands [`PRECESSION_AT`] up the
/// vertical or higher (above ψ̇ where θ is small), the vertical runs [`PAST_RATE`] past it;
/// θ's arc, and the curves' radius.
pub const PRECESSION_AT: f64 = 1.2;
const PAST_RATE: f64 = 0.15;
const ARC_RADIUS: f64 = 0.3;
pub const RATE_RADIUS: f64 = 0.12;

/// The fixed vertical K, the unit vector the precession is about, at the figure's θ.
pub fn vertical(canvas: &Canvas) -> Result<P3, FigureError> {
    let theta = canvas.value(&Expr::sym(EulerianAngles::chapter().nutation), "theta")?;
    Ok([0.0, theta.sin(), theta.cos()])
}

/// The vertical, θ, and the rates: φ̇ about K at `precession` from O, ψ̇ about z at `spin`
/// from O (each past what is drawn along its line).
pub fn angles(
    canvas: &mut Canvas,
    body: &Extent,
    precession: f64,
    spin: f64,
) -> Result<(), FigureError> {
    let k = vertical(canvas)?;
    let z = [0.0, 0.0, 1.0];
    let reach = body.reach;
    let top = scaled(k, precession + PAST_RATE * reach);
    canvas.path(Layer::Behind, &[[0.0; 3], top], false, Stroke::CENTRE_LINE);
    canvas.keep_clear([0.0; 3], top);
    canvas.label("$Z$".into(), top, k);
    // θ: the arc from K to z, its label outside the middle.
    let arc: Vec<P3> = (0..=24)
        .map(|s| {
            let t = f64::from(s) / 24.0;
            scaled(
                view::unit(add(scaled(k, 1.0 - t), scaled(z, t))),
                ARC_RADIUS * reach,
            )
        })
        .collect();
    canvas.path(Layer::Front, &arc, false, Stroke::MOTION);
    let middle = arc[arc.len() / 2];
    canvas.label(r"$\theta$".into(), middle, middle);
    let r = RATE_RADIUS * reach;
    rate(canvas, scaled(k, precession), k, r, r"$\dot\phi$");
    rate(canvas, scaled(z, spin), z, r, r"$\dot\psi$");
    Ok(())
}

/// A curved arrow round `axis` (right-handed) about `centre`, labelled.
fn rate(canvas: &mut Canvas, centre: P3, axis: P3, r: f64, label: &str) {
    let start = canvas.turning_arrow(centre, axis, r, Stroke::MOTION, Role::Rate);
    canvas.label(label.into(), start, view::sub(start, centre));
}
