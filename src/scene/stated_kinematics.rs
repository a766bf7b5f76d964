//! ω, the rates of its components in the frame, and the frame's Ω as the scene states them,
//! before its constraints are solved: written (`omega`, `omegadot`, `frame rate`), or from
//! the Eulerian angles (`euler angles`, §18.9) by [`eulerian_kinematics`]:
//!
//! ```text
//! Ω = φ̇ K + θ̇ i,   ω = Ω + ψ̇ k,   K = sin θ j + cos θ k
//! ```
//!
//! With `steady`, `θ̇ = φ̈ = θ̈ = ψ̈ = 0` is put in; an angle θ given at a multiple of 90°
//! (where sin θ or cos θ is zero, so that terms of the equations drop out) is put in
//! exactly, as a textbook reduces a gyroscope at θ = 90°. At other angles θ stays a symbol.

use super::model::Scene;
use crate::algebra::{AlgebraError, Expr, Func, Symbol, Vector};
use crate::mechanics::derivation::{Relation, Step};
use crate::mechanics::eulerian_angles::eulerian_kinematics;

/// ω, `(ω̇)_frame` and the frame's Ω (`None`: the frame is fixed in the body, Ω = ω).
#[derive(Debug, Clone)]
pub struct StatedKinematics {
    pub omega: Vector,
    pub omega_dot: Vector,
    pub frame_rate: Option<Vector>,
}

/// The scene's kinematics as stated, with the steps that show them (none when written).
pub fn stated_kinematics(scene: &Scene) -> Result<(StatedKinematics, Vec<Step>), AlgebraError> {
    let Some(statement) = scene.euler_angles else {
        let zero = || Vector::from_element(Expr::zero());
        let stated = StatedKinematics {
            omega: scene.omega.clone().unwrap_or_else(zero),
            omega_dot: scene.omega_dot.clone().unwrap_or_else(zero),
            frame_rate: scene.frame_rate.clone(),
        };
        return Ok((stated, Vec::new()));
    };
    let angles = super::model::EulerAnglesStatement::angles();
    let (motion, derivation) = eulerian_kinematics(&angles)?;
    let mut steps = derivation.steps;
    let zero = statement.zero();
    let reducing = reducing_angle(scene);
    let put_in = |s: Symbol| match (zero.contains(&s), &reducing) {
        (true, _) => Some(Expr::zero()),
        (false, Some((theta, angle))) if s == *theta => Some(angle.clone()),
        _ => None,
    };
    let each = |v: &Vector| substituted(v, &put_in);
    let stated = StatedKinematics {
        omega: each(&motion.omega)?,
        omega_dot: each(&motion.omega_dot)?,
        frame_rate: Some(each(&motion.frame_rate)?),
    };
    let mut conditions = Vec::new();
    if statement.steady {
        conditions.push(
            r"steady precession, $\dot\theta = \ddot\phi = \ddot\theta = \ddot\psi = 0$"
                .to_string(),
        );
    }
    if let Some((_, angle)) = &reducing {
        conditions.push(format!(
            r"$\theta = {}^\circ$",
            degrees(angle).unwrap_or_default()
        ));
    }
    if !conditions.is_empty() {
        let frame_rate = stated
            .frame_rate
            .clone()
            .unwrap_or_else(|| stated.omega.clone());
        let mut relations = Relation::components("omega", &stated.omega);
        relations.extend(Relation::components("Omega", &frame_rate));
        relations.extend(Relation::components("omegadot", &stated.omega_dot));
        steps.push(Step::new(conditions.join(", "), relations));
    }
    Ok((stated, steps))
}

/// With `euler angles`, θ and its exact given value when sin θ or cos θ is zero there.
fn reducing_angle(scene: &Scene) -> Option<(Symbol, Expr)> {
    scene.euler_angles?;
    let theta = super::model::EulerAnglesStatement::angles().nutation;
    let angle = scene.exact_given(theta).filter(reduces)?;
    Some((theta, angle))
}

/// A load at the angle the kinematics were reduced at (see the module documentation): θ's
/// exact value put in when it makes sin θ or cos θ zero; the vector as it is otherwise.
pub fn at_reducing_angle(scene: &Scene, v: &Vector) -> Result<Vector, AlgebraError> {
    match reducing_angle(scene) {
        Some((theta, angle)) => substituted(v, &|s| (s == theta).then(|| angle.clone())),
        None => Ok(v.clone()),
    }
}

/// Each component with `put_in` substituted, expanded.
fn substituted(
    v: &Vector,
    put_in: &dyn Fn(Symbol) -> Option<Expr>,
) -> Result<Vector, AlgebraError> {
    let c = |e: &Expr| e.subs(put_in)?.expand();
    Ok(Vector::new(c(&v[0])?, c(&v[1])?, c(&v[2])?))
}

/// Whether sin θ or cos θ is zero at this exact angle.
fn reduces(angle: &Expr) -> bool {
    [Func::Sin, Func::Cos]
        .into_iter()
        .any(|f| Expr::func(f, angle.clone()).is_zero())
}

/// An exact angle `q π` in degrees, when that is a whole number.
fn degrees(angle: &Expr) -> Option<i64> {
    let in_degrees = (angle * &Expr::int(180) / Expr::pi()).expand().ok()?;
    in_degrees.as_num()?.to_string().parse().ok()
}
