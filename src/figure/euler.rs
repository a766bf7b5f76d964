//! A gyroscope's or top's Eulerian angles (§18.9): the fixed vertical Z (along K, drawn up)
//! as a centre line from O, the angle θ from it to the axis of symmetry z as an arc, the
//! precession φ̇ a curved arrow about Z above the body and whatever is drawn up along Z, the
//! spin ψ̇ one about z past the body and whatever is drawn along z; and ω where the scene
//! states it by its components, with the angle it makes with z (§18.11's γ).

use super::canvas::{Canvas, Layer};
use super::extent::Extent;
use super::view::{self, add, scaled, P3};
use super::{FigureError, Role, Stroke};
use crate::algebra::{Expr, Symbol, Vector};
use crate::mechanics::eulerian_angles::EulerianAngles;
use crate::scene::kinematic_constraints::OMEGA_COMPONENTS;
use crate::scene::model::{ConstraintKind, Scene};
use crate::scene::units::Dimension;

/// Lengths in proportion to the body's reach: φ̇'s curve stands [`PRECESSION_AT`] up the
/// vertical or higher (above ψ̇ where θ is small), the vertical runs [`PAST_RATE`] past it;
/// θ's arc, and the curves' radius.
pub const PRECESSION_AT: f64 = 1.2;
const PAST_RATE: f64 = 0.15;
const ARC_RADIUS: f64 = 0.3;
pub const RATE_RADIUS: f64 = 0.12;
/// How far below φ̇'s curve, in its radii, H_G's head stands (under no force), and the
/// least length, in the body's reach, it shows past the body.
const MOMENTUM_BELOW_RATE: f64 = 1.5;
pub const MOMENTUM_LENGTH: f64 = 0.3;
/// The radius of the arc of ω's angle from z, outside θ's (Z may stand between z and ω).
const OMEGA_ARC_RADIUS: f64 = 0.45;

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
    (precession, spin): (f64, f64),
    momentum: Option<f64>,
) -> Result<(), FigureError> {
    let k = vertical(canvas)?;
    let z = [0.0, 0.0, 1.0];
    let reach = body.reach;
    let top = scaled(k, precession + PAST_RATE * reach);
    canvas.path(Layer::Behind, &[[0.0; 3], top], false, Stroke::CENTRE_LINE);
    canvas.keep_clear([0.0; 3], top, Stroke::CENTRE_LINE);
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
    if let Some(head) = momentum {
        let below_rate = precession - MOMENTUM_BELOW_RATE * r;
        angular_momentum(canvas, body, k, head.max(below_rate));
    }
    let angles = EulerianAngles::chapter();
    let (phi, psi) = (angles.precession.dot(), angles.spin.dot());
    rate(canvas, scaled(k, precession), (k, phi), r, r"$\dot\phi$");
    rate(canvas, scaled(z, spin), (z, psi), r, r"$\dot\psi$");
    Ok(())
}

/// Under no force H_G is constant, and the vertical Z is taken along it (§18.11): H_G an
/// arrow up Z from G (at O), under the body's faces until it comes out of them, its head
/// `head` up Z (under φ̇'s curve). Not drawn where the body reaches that high.
fn angular_momentum(canvas: &mut Canvas, body: &Extent, k: P3, head: f64) {
    let out = body.drawn_along(canvas, k);
    if view::norm(body.centre) > 1e-9 * body.reach || head <= out {
        return;
    }
    let (from, to) = (scaled(k, out), scaled(k, head));
    canvas.path(Layer::Behind, &[[0.0; 3], from], false, Stroke::MOTION);
    canvas.arrow(
        Layer::Front,
        from,
        to,
        false,
        Stroke::MOTION,
        Role::AngularMomentum,
    );
    let across = view::unit(view::square_to([1.0, 0.0, 0.0], k));
    canvas.label(super::arrows::named("H_G"), to, across);
}

/// A curved arrow round `axis` about `centre` the way the rate `dot` turns it (right-handed
/// where it is positive or has no value, else the other way: a wheel rolling forward spins
/// at ψ̇ = −v/r about its axle), labelled.
fn rate(canvas: &mut Canvas, centre: P3, (axis, dot): (P3, Symbol), r: f64, label: &str) {
    // A rate the figure has no number for (a scene that names no φ̇) turns the positive way.
    let sense = canvas.value(&Expr::sym(dot), dot.name()).unwrap_or(1.0);
    let about = match sense < 0.0 {
        true => scaled(axis, -1.0),
        false => axis,
    };
    let start = canvas.turning_arrow(centre, about, r, Stroke::MOTION, Role::Rate);
    canvas.label(label.into(), start, view::sub(start, centre));
}

/// ω where the scene states it by its components (`constraint omega_y = w*sin(gamma)`,
/// `constraint omega_z = w*cos(gamma)`): its components along y and z, and along x too
/// unless the precession is steady (then ω_x = θ̇ = 0). None where they are not all stated.
pub fn stated_omega(scene: &Scene) -> Option<Vector> {
    let steady = scene.euler_angles.as_ref()?.steady;
    let mut omega = Vector::from_element(Expr::zero());
    let mut stated = [false; 3];
    for c in &scene.constraints {
        let ConstraintKind::Equation(lhs, rhs) = &c.kind else {
            continue;
        };
        let component = lhs
            .as_symbol()
            .and_then(|s| OMEGA_COMPONENTS.iter().position(|n| *n == s.name()));
        if let Some(k) = component {
            omega[k] = rhs.clone();
            stated[k] = true;
        }
    }
    (stated[1] && stated[2] && (stated[0] || steady)).then_some(omega)
}

/// The arc from z to `omega` (at the figure's sizes) drawn about O, labelled with the given
/// angle its components are written in whose value is the angle between them (γ in
/// `w sin γ j + w cos γ k`); nothing where no such angle is given. The arc's radius, if
/// drawn.
pub fn omega_angle(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    omega: &Vector,
) -> Result<Option<f64>, FigureError> {
    let z = [0.0, 0.0, 1.0];
    let w = view::unit(canvas.vector(omega, "omega")?);
    let square = view::cross(z, w);
    if view::norm(square) < 1e-9 {
        return Ok(None);
    }
    let between = view::dot(z, w).clamp(-1.0, 1.0).acos();
    let mut angle = None;
    for s in omega.iter().flat_map(|c| c.symbols()) {
        let is_angle = scene.dimension(s) == Some(Dimension::NONE);
        if is_angle && (canvas.value(&Expr::sym(s), "omega")? - between).abs() < 1e-9 {
            angle = Some(s);
            break;
        }
    }
    let Some(angle) = angle else {
        return Ok(None);
    };
    let a = view::unit(square);
    let radius = OMEGA_ARC_RADIUS * body.reach;
    super::turns::arc(canvas, [0.0; 3], z, a, between, radius);
    let middle = super::turns::turned(z, a, between / 2.0);
    canvas.label(
        super::arrows::label(&Expr::sym(angle)),
        scaled(middle, radius),
        middle,
    );
    Ok(Some(radius))
}
