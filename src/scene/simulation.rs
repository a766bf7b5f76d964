//! A scene as a numerical problem for the simulator: the centroidal inertia tensor, the
//! initial angular velocity, and the moment of the loads about G, all from the givens'
//! values. Loads are taken as fixed in the body; a load may vary with the time `t`, and then
//! the moment is a [`Torque::Time`] (a function of time alone, so every method, the
//! splitting included, can integrate it).
//!
//! Every error stands at the statement it comes from: the inertia at the body, ω at `omega`,
//! the moment at the first load without a value. A problem whose initial kinetic energy
//! `T = ½ωᵀ[I]ω` or `|H_G| = |[I]ω|` is beyond f64 is refused before anything is simulated,
//! at `omega` when `|ω|` contributes most of the magnitude, at the body otherwise; an
//! overflow found later in the run stands at the body ([`located`]).

use super::analysis::centroidal_body;
use super::model::{Scene, Span};
use super::parse::TIME;
use super::units::Dimension;
use crate::algebra::{AlgebraError, Expr, Symbol, Vector};
use crate::mechanics::composite_body::MassProperties;
use crate::numeric::rigid_body::inertia::BodyInertia;
use crate::numeric::rigid_body::simulate::{Problem, ANGULAR_MOMENTUM, KINETIC_ENERGY};
use crate::numeric::rigid_body::state::RigidBodyState;
use crate::numeric::rigid_body::torque::Torque;
use crate::numeric::tape::interpreter::Tape;
use crate::numeric::NumericError;
use crate::parse::Diagnostic;
use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use std::cell::RefCell;

/// Advice for a value beyond the numbers a simulation computes with.
const RANGE_HELP: &str =
    "a simulation computes in f64, up to about 1.8e308 (SI units): check the mass, the sizes and omega";

/// The first `body` statement: where the body as a whole is blamed.
pub(super) fn body_place(scene: &Scene) -> Span {
    scene.places.body.first().copied().unwrap_or_default()
}

/// The value of `e`, or an error at `at`: a symbol without a value, or a value beyond f64.
pub(super) fn number(scene: &Scene, e: &Expr, what: &str, at: Span) -> Result<f64, Diagnostic> {
    e.eval(&|s: Symbol| scene.value(s))
        .map_err(|err| match err {
            AlgebraError::NotFinite { .. } => {
                scene.error_at(at, format!("{what} is not finite: {err}"), RANGE_HELP)
            }
            _ => scene.error_at(
                at,
                format!("{what} has no numerical value: {err}"),
                "give every symbol of the body, omega and the loads a value ('given m = 2 kg')",
            ),
        })
}

/// Where the moment of the loads is blamed: the first load (in the file) one of whose
/// components has no finite value, else the first load.
pub(super) fn loads_place(scene: &Scene) -> Span {
    let places = &scene.places;
    let fails = |v: &Vector| {
        v.iter()
            .any(|e| e.eval(&|s: Symbol| scene.value(s)).is_err())
    };
    let forces = scene.forces.iter().zip(&places.forces);
    let failing_forces = forces.filter(|(f, _)| fails(&f.value) || fails(&f.point));
    let failing_couples = scene
        .couples
        .iter()
        .zip(&places.couples)
        .filter(|(c, _)| fails(c));
    failing_forces
        .map(|(_, at)| *at)
        .chain(failing_couples.map(|(_, at)| *at))
        .min_by_key(|at| at.start)
        .or_else(|| {
            places
                .forces
                .iter()
                .chain(&places.couples)
                .copied()
                .min_by_key(|at| at.start)
        })
        .unwrap_or_default()
}

/// `10^exponent` written as `2e399`: a magnitude too large for f64, from its logarithm.
fn power_of_ten(exponent: f64) -> String {
    let mut whole = exponent.floor();
    let mut mantissa = (10f64.powf(exponent - whole) * 100.0).round() / 100.0;
    if mantissa >= 10.0 {
        (mantissa, whole) = (mantissa / 10.0, whole + 1.0);
    }
    format!("{mantissa}e{whole}")
}

/// Refuses an initial state whose `T = ½ωᵀ[I]ω` or `|H_G| = |[I]ω|` overflows, naming the
/// quantity and its true size. Both are computed from `ω/|ω|_max` and `[I]/|I|_max`, whose
/// logarithms add: `log T = 2 log|ω|_max + log|I|_max + log(½ ω̂ᵀ[Î]ω̂)`.
fn initial_magnitudes(
    scene: &Scene,
    tensor: &Matrix3<f64>,
    omega: &Vector3<f64>,
) -> Result<(), Diagnostic> {
    let (largest_omega, largest_inertia) = (omega.amax(), tensor.amax());
    if largest_omega == 0.0 || largest_inertia == 0.0 {
        return Ok(());
    }
    let inertia = BodyInertia::Tensor(tensor / largest_inertia);
    let unit_omega = omega / largest_omega;
    let (w, i) = (largest_omega.log10(), largest_inertia.log10());
    let body = BodyInertia::Tensor(*tensor);
    let checks = [
        (
            KINETIC_ENERGY,
            body.kinetic_energy(omega),
            2.0 * w + i + inertia.kinetic_energy(&unit_omega).log10(),
            2.0 * w >= i,
            scene.unit_system.unit(Dimension::MOMENT, true),
        ),
        (
            ANGULAR_MOMENTUM,
            body.angular_momentum_magnitude(omega),
            w + i + inertia.angular_momentum_magnitude(&unit_omega).log10(),
            w >= i,
            scene.unit_system.unit(Dimension::new(1, 2, -1), false),
        ),
    ];
    for (quantity, value, exponent, omega_dominates, unit) in checks {
        if value.is_finite() {
            continue;
        }
        let at = match scene.places.omega {
            Some(at) if omega_dominates => at,
            _ => body_place(scene),
        };
        return Err(scene.error_at(
            at,
            format!(
                "{quantity} overflows ({} {unit}) at t = 0 s",
                power_of_ten(exponent)
            ),
            RANGE_HELP,
        ));
    }
    Ok(())
}

/// A numerical failure of the simulation of `scene`, at the statement it comes from: the
/// body's motion (a state, T or |H| that overflows, an inadmissible inertia, a spin too fast
/// for the step budget) at the body. A sample sink's or the code generator's failure is not
/// about a statement: `None`.
pub fn located(scene: &Scene, error: &NumericError) -> Option<Diagnostic> {
    if *error == NumericError::NotTorqueFree {
        return Some(scene.error_at(
            loads_place(scene),
            error.to_string(),
            "these loads have a moment about G, so the motion is not torque-free; the method \
             auto integrates it (vern9 below --rtol 1e-9, dop853 above)",
        ));
    }
    let help = match error {
        NumericError::Physics(_) => "check the masses and sizes of the body",
        NumericError::InvalidInput { .. } => {
            "the motion of this body cannot be computed as given: check its mass and sizes, \
             omega and the loads"
        }
        NumericError::StepLimit { .. } | NumericError::StepBudgetHopeless { .. } => {
            "the body turns too fast for the interval to be followed step by step: a shorter \
             --until, or a looser --rtol"
        }
        NumericError::SampleOverflow { .. } => RANGE_HELP,
        NumericError::NonFinite { .. } | NumericError::StepSizeUnderflow { .. } => {
            "the integration diverged or the moment is not finite: a shorter --step (rk4, \
             splitting) or dop853 may follow this motion; else check omega and the loads"
        }
        _ => return None,
    };
    Some(scene.error_at(body_place(scene), error.to_string(), help))
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
            constant[k] = number(
                scene,
                &moment[k],
                "the moment of the loads",
                loads_place(scene),
            )?;
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
            scene.error_at(
                loads_place(scene),
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
        scene.error_at(
            loads_place(scene),
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
            tensor[(r, c)] = number(
                scene,
                &matrix[(r, c)],
                "the inertia tensor",
                body_place(scene),
            )?;
        }
    }
    let omega = scene.omega.as_ref().ok_or_else(|| {
        scene.error_at(
            body_place(scene),
            "the scene gives no omega",
            "add 'omega = w_1*i + w_2*j + w_3*k'",
        )
    })?;
    let mut omega0 = Vector3::zeros();
    for k in 0..3 {
        omega0[k] = number(
            scene,
            &omega[k],
            "omega",
            scene.places.omega.unwrap_or_default(),
        )?;
    }
    let inertia = BodyInertia::Tensor(tensor);
    inertia.validate().map_err(|e| {
        scene.error_at(
            body_place(scene),
            e.to_string(),
            "check the masses and sizes of the body",
        )
    })?;
    initial_magnitudes(scene, &tensor, &omega0)?;
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
        inertia,
        torque,
        initial: RigidBodyState::new(omega0, UnitQuaternion::identity()),
        start_time: 0.0,
    })
}
