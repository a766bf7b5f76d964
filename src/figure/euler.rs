//! A gyroscope's or top's Eulerian angles (§18.9): the fixed vertical Z (along K, drawn up)
//! as a centre line from O, the angle θ from it to the axis of symmetry z as an arc, the
//! precession φ̇ a curved arrow about Z above the body, the spin ψ̇ one about z past it.

use super::body::Extent;
use super::canvas::{Canvas, Layer};
use super::view::{self, add, scaled, P3};
use super::{FigureError, Role, Stroke};
use crate::algebra::Expr;
use crate::mechanics::eulerian_angles::EulerianAngles;

/// Lengths in proportion to the body's reach.
const VERTICAL: f64 = 1.35;
const ARC_RADIUS: f64 = 0.3;
const RATE_RADIUS: f64 = 0.12;

pub fn angles(canvas: &mut Canvas, body: &Extent) -> Result<(), FigureError> {
    let angles = EulerianAngles::chapter();
    let theta = canvas.value(&Expr::sym(angles.nutation), "theta")?;
    let k = [0.0, theta.sin(), theta.cos()];
    let z = [0.0, 0.0, 1.0];
    let reach = body.reach;
    let top = scaled(k, VERTICAL * reach);
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
    let phi = add(top, scaled(k, -0.15 * reach));
    rate(canvas, phi, k, RATE_RADIUS * reach, r"$\dot\phi$");
    let past = body.along(z) + 0.2 * reach;
    rate(
        canvas,
        scaled(z, past),
        z,
        RATE_RADIUS * reach,
        r"$\dot\psi$",
    );
    Ok(())
}

/// A curved arrow round `axis` (right-handed) about `centre`, labelled.
fn rate(canvas: &mut Canvas, centre: P3, axis: P3, r: f64, label: &str) {
    let start = canvas.turning_arrow(centre, axis, r, Stroke::MOTION, Role::Rate);
    canvas.label(label.into(), start, view::sub(start, centre));
}
