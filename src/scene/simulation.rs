//! A scene as a numerical problem for the simulator: the centroidal inertia tensor, the
//! initial angular velocity, and the moment of the loads about G, all from the givens'
//! values. Loads are taken as fixed in the body; a load may vary with the time `t`, and then
//! the moment is a [`Torque::Time`] (a function of time alone, so every method, the
//! splitting included, can integrate it).

use super::analysis::centroidal_body;
use super::model::{Scene, Span};
use super::parse::TIME;
use crate::algebra::{Expr, Symbol, Vector};
use crate::mechanics::composite_body::MassProperties;
use crate::numeric::rigid_body::inertia::BodyInertia;
use crate::numeric::rigid_body::simulate::Problem;
use crate::numeric::rigid_body::state::RigidBodyState;
use crate::numeric::rigid_body::torque::Torque;
use crate::numeric::tape::interpreter::Tape;
use crate::parse::Diagnostic;
use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use std::cell::RefCell;

fn whole(scene: &Scene, message: String, help: &str) -> Diagnostic {
    scene.error_at(Span::default(), message, help)
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

/// The moment of the loads about G as a torque: constant when it does not depend on time,
/// otherwise a function of `t` alone evaluated through a compiled tape (as machine code where
/// the host allows).
fn torque(scene: &Scene, moment: &Vector) -> Result<Torque<f64>, Diagnostic> {
    let time = Symbol::new(TIME);
    // A scene that declares `t` uses it as a quantity of its own, not as the time.
    let varies = scene.dimension(time).is_none() && moment.iter().any(|m| m.contains(time));
    if !varies {
        let mut constant = Vector3::zeros();
        for k in 0..3 {
            constant[k] = number(scene, &moment[k], "the moment of the loads")?;
        }
        return Ok(if constant == Vector3::zeros() {
            Torque::None
        } else {
            Torque::Body(constant)
        });
    }
    let mut inputs = vec![time];
    for s in moment.iter().flat_map(|m| m.symbols()) {
        if !inputs.contains(&s) {
            inputs.push(s);
        }
    }
    let mut values = vec![0.0];
    for s in &inputs[1..] {
        values.push(scene.value(*s).ok_or_else(|| {
            whole(
                scene,
                format!(
                    "the moment of the loads has no numerical value: no value for {}",
                    s.name()
                ),
                "give every symbol of the loads a value ('given M0 = 2 N*m')",
            )
        })?);
    }
    let outputs: Vec<Expr> = moment.iter().cloned().collect();
    let tape = Tape::compile(&outputs, &inputs).map_err(|e| {
        whole(
            scene,
            format!("the moment of the loads cannot be compiled: {e}"),
            "simplify the loads",
        )
    })?;
    // Machine code where Cranelift has a backend (it halves the instructions of an rk4 run
    // with a time-varying couple); the interpreter elsewhere, and in a build without the
    // `jit` feature. Both give the same values.
    #[cfg(feature = "jit")]
    let native = tape.compile_native().ok();
    let scratch = RefCell::new((values, Vec::new()));
    Ok(Torque::Time(Box::new(move |t: f64| {
        let mut guard = scratch.borrow_mut();
        let (inputs, registers) = &mut *guard;
        inputs[0] = t;
        let mut out = [0.0; 3];
        #[cfg(feature = "jit")]
        let evaluated = match &native {
            Some(native) => native.eval(inputs, &mut out),
            None => tape.eval_with(inputs, &mut out, registers),
        };
        #[cfg(not(feature = "jit"))]
        let evaluated = tape.eval_with(inputs, &mut out, registers);
        // A non-finite moment is left as NaN; the driver stops with an error at that time.
        if evaluated.is_err() {
            out = [f64::NAN; 3];
        }
        Vector3::new(out[0], out[1], out[2])
    })))
}

/// The initial-value problem of the scene's body, starting at rest orientation at t = 0.
///
/// A sphere of 5 kg and radius 0.1 m: `I = 2/5 m r² = 0.02 kg·m²` about every axis. A couple
/// `M j` and a force `F i` at `r j` from its centre give `ΣM_G = M j + r j × F i =
/// (0, M, -r F) = (0, 3, -1) N·m`.
///
/// ```
/// use kinetics::scene::simulation::problem;
/// use kinetics::{parse_scene, BodyInertia, Torque};
///
/// let scene = parse_scene(
///     "sphere.scene",
///     "given m = 5 kg
/// given r = 0.1 m
/// given w = 2 rad/s
/// given M = 3 N*m
/// given F = 10 N
/// body sphere(r) mass m
/// vbar = 0
/// omega = w*k
/// couple M*j
/// force P = F*i at (0, r, 0)
/// find T",
/// )?;
/// let p = problem(&scene)?;
/// let BodyInertia::Tensor(tensor) = p.inertia else { panic!("the full tensor") };
/// assert!((tensor - nalgebra::Matrix3::identity() * 0.02).abs().max() < 1e-15);
/// assert_eq!(p.initial.omega, nalgebra::Vector3::new(0.0, 0.0, 2.0));
/// let Torque::Body(moment) = p.torque else { panic!("a constant moment") };
/// assert!((moment - nalgebra::Vector3::new(0.0, 3.0, -1.0)).norm() < 1e-15);
/// # Ok::<(), kinetics::Diagnostic>(())
/// ```
pub fn problem(scene: &Scene) -> Result<Problem<f64>, Diagnostic> {
    let MassProperties {
        centroid, inertia, ..
    } = centroidal_body(scene)?;
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
    let arms = scene
        .forces
        .iter()
        .map(|f| (&f.point - &centroid).cross(&f.value));
    let moment = scene
        .couples
        .iter()
        .cloned()
        .chain(arms)
        .fold(Vector::from_element(Expr::zero()), |a, b| a + b);
    let torque = torque(scene, &moment)?;
    Ok(Problem {
        inertia: BodyInertia::Tensor(tensor),
        torque,
        initial: RigidBodyState::new(omega0, UnitQuaternion::identity()),
        start_time: 0.0,
    })
}
