//! A scene with `euler angles` as a heavy top for the simulator
//! ([`HeavyTop`](crate::numeric::rigid_body::heavy_top::HeavyTop)): the axial and transverse
//! moments about the reference point (the fixed point O, else the mass centre G), the
//! moment of the loads about it, and the initial Eulerian angles and rates from the givens.
//!
//! The loads are written with the fixed vertical `K = sin θ j + cos θ k` in Oxyz; their
//! moment about the reference point must be the weight's `ΣM = W c sin θ i` (a weight on the
//! axis, `force weight = -m*g*K at (0, 0, c)`; none on a free body), which is what the
//! equations of the top take: `W c` is read at `θ = 90°` and the whole moment checked at
//! several θ, anything else refused at the loads. φ and ψ start at their givens, or 0 when
//! the scene does not declare them; a rate `steady` makes zero starts at 0.
//!
//! Every error stands at the statement it comes from: the moments at the body, the loads at
//! the first load whose moment is not of the weight's form (else the first load), an angle
//! or rate at the `euler angles` statement.

use super::model::{EulerAnglesStatement, Scene, Span};
use super::simulation::{body_place, loads_place, number};
use crate::algebra::{Expr, Symbol, Vector};
use crate::numeric::rigid_body::eulerian_angles::EulerianAngles;
use crate::numeric::rigid_body::heavy_top::HeavyTop;
use crate::parse::Diagnostic;
use std::f64::consts::FRAC_PI_2;

/// The angles at which the moment of the loads is checked against `W c sin θ i`.
const CHECK_ANGLES: [f64; 3] = [0.3, 1.2, 2.4];
/// Relative agreement asked of that check (the moment is evaluated in f64).
const CHECK_TOLERANCE: f64 = 1e-12;

/// The top the scene describes and where it starts. See the module's documentation.
pub fn heavy_top(scene: &Scene) -> Result<(HeavyTop, EulerianAngles), Diagnostic> {
    let statement = scene.euler_angles.ok_or_else(|| {
        scene.error_at(
            body_place(scene),
            "the scene has no 'euler angles' statement",
            "a top is simulated from its Eulerian angles: add 'euler angles' and give theta and the rates",
        )
    })?;
    let body = body_place(scene);
    let algebra =
        |e: crate::algebra::AlgebraError| scene.error_at(body, e.to_string(), "simplify the body");
    let (inertia, reference) = scene.inertia_of_body(scene.fixed_point).map_err(algebra)?;
    let [_, transverse, axial] = &inertia.moments;
    let transverse = number(
        scene,
        transverse,
        "the transverse moment of inertia I'",
        body,
    )?;
    let axial = number(scene, axial, "the axial moment of inertia I", body)?;
    let places = &scene.places;
    let loads: Vec<(Vector, Span)> = scene
        .forces
        .iter()
        .map(|f| (&f.point - &reference).cross(&f.value))
        .zip(places.forces.iter().copied())
        .chain(
            scene
                .couples
                .iter()
                .cloned()
                .zip(places.couples.iter().copied()),
        )
        .collect();
    let moment = loads
        .iter()
        .map(|(m, _)| m.clone())
        .fold(Vector::from_element(Expr::zero()), |a, b| a + b);
    let theta = EulerAnglesStatement::angles().nutation;
    let weight_arm = match weight_arm(scene, &moment, theta, loads_place(scene)) {
        Ok(weight_arm) => weight_arm,
        Err(refusal) => {
            // Blamed on the first load (in the file) whose own moment is not of that form.
            let culprit = loads
                .iter()
                .filter(|(m, at)| weight_arm(scene, m, theta, *at).is_err())
                .map(|(_, at)| *at)
                .min_by_key(|at| at.start);
            return Err(match culprit {
                Some(at) => weight_arm(scene, &moment, theta, at)
                    .err()
                    .unwrap_or(refusal),
                None => refusal,
            });
        }
    };
    let top = HeavyTop::new(axial, transverse, weight_arm).map_err(|e| {
        scene.error_at(
            body,
            e.to_string(),
            "check the masses and sizes of the body",
        )
    })?;
    let start = initial_angles(scene, statement)?;
    top.problem(&start).map_err(|e| {
        scene.error_at(
            statement.span,
            e.to_string(),
            "give theta between 0 and 180 deg, and finite rates",
        )
    })?;
    Ok((top, start))
}

/// `W c` from `ΣM = W c sin θ i`: read at θ = 90°, checked at [`CHECK_ANGLES`]; a
/// refusal stands at `at`.
fn weight_arm(scene: &Scene, moment: &Vector, theta: Symbol, at: Span) -> Result<f64, Diagnostic> {
    let evaluate = |angle: f64| -> Result<[f64; 3], Diagnostic> {
        let mut m = [0.0; 3];
        for (k, component) in moment.iter().enumerate() {
            let value = |s: Symbol| match s == theta {
                true => Some(angle),
                false => scene.value(s),
            };
            m[k] = component.eval(&value).map_err(|e| {
                scene.error_at(
                    at,
                    format!("the moment of the loads has no numerical value: {e}"),
                    "give every symbol of the loads a value; with 'euler angles' the loads may \
                     depend on theta (through K) but not on the time or the other angles",
                )
            })?;
        }
        Ok(m)
    };
    let weight_arm = evaluate(FRAC_PI_2)?[0];
    for angle in CHECK_ANGLES {
        let m = evaluate(angle)?;
        let expected = [weight_arm * angle.sin(), 0.0, 0.0];
        let scale = weight_arm.abs() + m.iter().map(|v| v.abs()).sum::<f64>();
        if m.iter()
            .zip(expected)
            .any(|(got, want)| (got - want).abs() > CHECK_TOLERANCE * scale)
        {
            return Err(scene.error_at(
                at,
                format!(
                    "at theta = {angle} rad the moment of the loads is ({:e}, {:e}, {:e}), not \
                     W c sin(theta) i = ({:e}, 0, 0): the simulation of a top takes the moment \
                     of its weight only",
                    m[0], m[1], m[2], expected[0]
                ),
                "write the weight on the axis, 'force weight = -m*g*K at (0, 0, c)', and no \
                 other load",
            ));
        }
    }
    Ok(weight_arm)
}

/// θ, φ, ψ and their rates from the givens (φ, ψ and a rate `steady` zeroes: 0 when not
/// declared), each a number, else an error at the statement.
fn initial_angles(
    scene: &Scene,
    statement: EulerAnglesStatement,
) -> Result<EulerianAngles, Diagnostic> {
    let angles = EulerAnglesStatement::angles();
    let value = |s: Symbol, optional: bool| -> Result<f64, Diagnostic> {
        if optional && scene.dimension(s).is_none() {
            return Ok(0.0);
        }
        scene.value(s).ok_or_else(|| {
            scene.error_at(
                statement.span,
                format!("simulating the top needs a value of {}", s.name()),
                format!("give it: 'given {} = ...'", s.name()),
            )
        })
    };
    let zeroed = statement.zero();
    let rate = |s: Symbol| value(s, zeroed.contains(&s));
    Ok(EulerianAngles {
        theta: value(angles.nutation, false)?,
        phi: value(angles.precession, true)?,
        psi: value(angles.spin, true)?,
        theta_dot: rate(angles.nutation.dot())?,
        phi_dot: rate(angles.precession.dot())?,
        psi_dot: rate(angles.spin.dot())?,
    })
}
