//! A scene as a numerical problem for the simulator: the centroidal inertia tensor, the
//! initial angular velocity, and the moment of the loads about G, all from the givens'
//! values. Loads are taken as fixed in the body (constant body-frame moments).

use super::analysis::centroidal_body;
use super::model::Scene;
use crate::algebra::{Expr, Symbol};
use crate::numeric::body_inertia::BodyInertia;
use crate::numeric::rigid_body_state::RigidBodyState;
use crate::numeric::simulate::Problem;
use crate::numeric::torque::Torque;
use crate::parse::Diagnostic;
use nalgebra::{Matrix3, UnitQuaternion, Vector3};

fn whole(scene: &Scene, message: String, help: &str) -> Diagnostic {
    Diagnostic::at(&scene.source_name, &scene.source, 0, 0, message).with_help(help)
}

fn number(scene: &Scene, e: &Expr, what: &str) -> Result<f64, Diagnostic> {
    e.eval(&|s: Symbol| scene.value(s)).map_err(|err| {
        whole(
            scene,
            format!("{what} has no numerical value: {err}"),
            "give every symbol of the body, omega and the loads a value ('given m = 2 kg')",
        )
    })
}

/// The initial-value problem of the scene's body, starting at rest orientation at t = 0.
pub fn problem(scene: &Scene) -> Result<Problem<f64>, Diagnostic> {
    let (_, centroid, inertia) = centroidal_body(scene)?;
    let matrix = inertia.matrix();
    let mut tensor = Matrix3::zeros();
    for r in 0..3 {
        for c in 0..3 {
            tensor[(r, c)] = number(scene, &matrix[(r, c)], "the inertia tensor")?;
        }
    }
    let omega = scene.omega.as_ref().ok_or_else(|| {
        whole(
            scene,
            "the scene gives no omega".into(),
            "add 'omega = w_1*i + w_2*j + w_3*k'",
        )
    })?;
    let mut omega0 = Vector3::zeros();
    for k in 0..3 {
        omega0[k] = number(scene, &omega[k], "omega")?;
    }
    let mut moment = Vector3::zeros();
    for f in &scene.forces {
        let arm = &f.point - &centroid;
        let m = arm.cross(&f.value);
        for k in 0..3 {
            moment[k] += number(scene, &m[k], &format!("the moment of force {}", f.name))?;
        }
    }
    for c in &scene.couples {
        for k in 0..3 {
            moment[k] += number(scene, &c[k], "a couple")?;
        }
    }
    Ok(Problem {
        inertia: BodyInertia::Tensor(tensor),
        torque: if moment == Vector3::zeros() {
            Torque::None
        } else {
            Torque::Body(moment)
        },
        initial: RigidBodyState::new(omega0, UnitQuaternion::identity()),
        start_time: 0.0,
    })
}
