//! A scene's kinematics with its constraints solved: each constraint gives equations among
//! the unknown rates, which are solved (linearly) and substituted into ω, ω̇ and Ω.
//!
//! ```text
//! velocity at (x, y, z) = 0:   v_P = v̄ + ω × (r_P − r̄) = 0       (v_P = ω × r_P, O fixed)
//! lhs = rhs:                   lhs − rhs = 0
//! ```
//!
//! `omega_x`, `omega_y`, `omega_z` in a constraint are the components of the body's ω in the
//! scene's frame (ω = φ̇ sin θ j + (ψ̇ + φ̇ cos θ) k with Eulerian angles), so a torque-free body
//! is stated as the textbook states it: `constraint omega_y = w*sin(gamma)`. `H_x`, `H_y`,
//! `H_z` are those of H_G = [Ī]{ω}, which needs the body: such a constraint is always solved
//! with the equations of motion (`analysis/unknowns.rs` puts H_G in).
//!
//! In an impact the constraints hold just after the blow, where the impulsive reactions that
//! enforce them are unknown too: their equations are solved with those of impulse and
//! momentum, not alone. So are constraints that do not fix their unknowns alone (an angle
//! inside sin and cos, or fewer equations than unknowns) in a scene whose motion follows from
//! its loads (or a body under no force, stated by its Eulerian angles and ā): they are solved
//! with ΣF = m ā and ΣM = Ḣ.

use super::model::{ConstraintKind, Scene, Span};
use super::stated_kinematics::stated_kinematics;
use crate::algebra::linear_solve::{solve_linear, Solution, SolveError};
use crate::algebra::{AlgebraError, Axis, Expr, Symbol, Vector};
use crate::mechanics::derivation::{Relation, Step};
use crate::mechanics::kinematics::velocity_of_point;
use crate::parse::Diagnostic;

/// The names of ω's components in a constraint.
pub const OMEGA_COMPONENTS: [&str; 3] = ["omega_x", "omega_y", "omega_z"];

/// The names of H_G's components in a constraint.
pub const H_COMPONENTS: [&str; 3] = ["H_x", "H_y", "H_z"];

/// Whether `e` names a component of H_G that the scene does not declare as its own.
pub fn names_angular_momentum(scene: &Scene, e: &Expr) -> bool {
    e.symbols()
        .into_iter()
        .any(|s| H_COMPONENTS.contains(&s.name()) && scene.dimension(s).is_none())
}

/// ω, the rates of its components in the frame, and the frame's Ω, with the unknowns the
/// constraints fixed substituted.
#[derive(Debug, Clone)]
pub struct SolvedConstraints {
    pub omega: Vector,
    pub omega_dot: Vector,
    pub frame_rate: Vector,
    /// Values of unknowns fixed by the kinematic constraints.
    pub solved: Vec<(Symbol, Expr)>,
    /// The constraints' equations (each `= 0`, with the constraint it comes from) to be
    /// solved with the equations of motion, or of impulse and momentum in an impact (see the
    /// module documentation).
    pub with_equations_of_motion: Vec<(Expr, Span)>,
}

impl SolvedConstraints {
    /// `e` with the unknowns the constraints fixed substituted, expanded.
    pub fn substitute(&self, e: &Expr) -> Result<Expr, AlgebraError> {
        if self.solved.is_empty() {
            return Ok(e.clone());
        }
        e.subs(&|s| {
            self.solved
                .iter()
                .find(|(u, _)| *u == s)
                .map(|(_, x)| x.clone())
        })?
        .expand()
    }

    /// Each component with the solved unknowns substituted, expanded.
    fn substitute_vector(&self, v: &Vector) -> Result<Vector, AlgebraError> {
        let each = |e: &Expr| self.substitute(e)?.expand();
        Ok(Vector::new(each(&v[0])?, each(&v[1])?, each(&v[2])?))
    }
}

/// The located diagnostic of a failed solve, with what to do about it.
pub fn solve_error(scene: &Scene, at: Span, e: SolveError, equations: &[Expr]) -> Diagnostic {
    // The givens without a value that the equations hold.
    let without_value: Vec<&str> = scene
        .givens
        .iter()
        .filter(|g| g.value.is_none() && equations.iter().any(|e| e.contains(g.symbol)))
        .map(|g| g.symbol.name())
        .collect();
    let help = match &e {
        SolveError::UnderDetermined(_) => "give more conditions, or fewer unknowns".to_string(),
        SolveError::Inconsistent { .. } => {
            "remove a condition or an unknown that conflicts".to_string()
        }
        SolveError::SeveralAngles(angles) => {
            let rest: Vec<String> = angles[1..]
                .iter()
                .map(|s| format!("'given {} = …'", s.name()))
                .collect();
            format!(
                "make all but one of them givens ({} in place of the unknown), and {} is solved for",
                rest.join(", "),
                angles[0].name()
            )
        }
        SolveError::RootsNotExact { .. } if !without_value.is_empty() => format!(
            "give {} a value, so that the sign deciding how many roots are real is known",
            without_value.join(", ")
        ),
        SolveError::RootsNotExact { .. } => {
            "the givens' values leave that sign too close to zero to tell: change a value slightly"
                .to_string()
        }
        SolveError::DegreeTooHigh { .. } => {
            "a polynomial above degree four has no formula in radicals: give one of the unknowns a value"
                .to_string()
        }
        SolveError::NotPolynomial { .. } | SolveError::NoSinglePolynomial { .. } => {
            "only one unknown may enter nonlinearly, in whole powers: give the others values".to_string()
        }
        SolveError::Nonlinear { .. } | SolveError::Algebra(_) => {
            "unknowns must appear linearly".to_string()
        }
    };
    scene.error_at(at, e.to_string(), help)
}

/// Solves the scene's constraints; `centroid` (the mass centre from O) is needed by a
/// velocity constraint on a body without a fixed point. Returns the kinematics and the steps
/// that show them. Errors are located at the constraint they come from, else at `at`.
pub fn solve_constraints(
    scene: &Scene,
    centroid: Option<&Vector>,
    at: Span,
) -> Result<(SolvedConstraints, Vec<Step>), Diagnostic> {
    let located = |span: Span| scene.algebra_error_at(span);
    let (stated, mut steps) = stated_kinematics(scene).map_err(located(at))?;
    let omega = stated.omega.clone();
    let mut equations: Vec<Expr> = Vec::new();
    // The constraint each equation came from, to locate errors.
    let mut sources: Vec<Span> = Vec::new();
    let mut shown: Vec<Relation> = Vec::new();
    // An equation in no unknown that the givens satisfy (rolling, stated where the spin is
    // a given defined by it) is shown, and has nothing to solve.
    let satisfied =
        |e: &Expr| !scene.unknowns.iter().any(|u| e.contains(u.0)) && scene.is_exactly_zero(e);
    for c in &scene.constraints {
        match &c.kind {
            ConstraintKind::VelocityZero(point) => {
                let v = match (scene.fixed_point, &scene.vbar, centroid) {
                    (true, _, _) => velocity_of_point(&zero_vector(), &omega, point),
                    (false, Some(vbar), Some(centroid)) => {
                        velocity_of_point(vbar, &omega, &(point - centroid))
                    }
                    (false, _, _) => {
                        return Err(scene.error_at(
                            c.span,
                            "a velocity constraint needs the motion of the body",
                            "add 'fixed point' or 'vbar = ...'",
                        ))
                    }
                }
                .map_err(located(c.span))?;
                for (k, axis) in [Axis::X, Axis::Y, Axis::Z].into_iter().enumerate() {
                    if !v[k].is_zero() {
                        if !satisfied(&v[k]) {
                            equations.push(v[k].clone());
                            sources.push(c.span);
                        }
                        shown.push(Relation::new(v[k].clone(), Expr::zero(), axis));
                    }
                }
            }
            ConstraintKind::Equation(lhs, rhs) => {
                let in_rates = |e: &Expr| omega_components_put_in(e, &omega);
                let (rates_lhs, rates_rhs) = (
                    in_rates(lhs).map_err(located(c.span))?,
                    in_rates(rhs).map_err(located(c.span))?,
                );
                let equation = &rates_lhs - &rates_rhs;
                if !satisfied(&equation) {
                    equations.push(equation);
                    sources.push(c.span);
                }
                shown.push(Relation::new(lhs.clone(), rhs.clone(), Axis::X));
                if (&rates_lhs, &rates_rhs) != (lhs, rhs) {
                    shown.push(Relation::new(rates_lhs, rates_rhs, Axis::X));
                }
            }
        }
    }
    let impact = !scene.impulses.is_empty() && !equations.is_empty();
    let constrained: Vec<Symbol> = scene
        .unknowns
        .iter()
        .map(|u| u.0)
        .filter(|u| equations.iter().any(|e| e.contains(*u)))
        .collect();
    let alone = match impact || equations.is_empty() {
        true => None,
        false => Some(solve_linear(&equations, &constrained)),
    };
    // Constraints that do not fix their unknowns alone, where the loads fix the rest.
    let loads_fix_the_rest = scene.motion_follows_from_loads() || scene.under_no_force();
    let names_h = equations.iter().any(|e| names_angular_momentum(scene, e));
    if names_h && !loads_fix_the_rest {
        return Err(scene.error_at(
            at,
            "a constraint on H_G (H_x, H_y, H_z) is solved with the equations of motion, and this scene does not state the loads its motion follows from",
            "state the loads (force, couple), or for a body under no force 'euler angles' with 'vbar = 0' and 'abar = 0'",
        ));
    }
    let with_the_loads = loads_fix_the_rest
        && (names_h
            || match &alone {
                Some(Err(SolveError::Nonlinear { .. })) => true,
                Some(Ok(Solution { free, .. })) => !free.is_empty(),
                _ => false,
            });
    let solved = if equations.is_empty() {
        if !shown.is_empty() {
            steps.push(Step::new(
                "kinematic constraints, which the givens satisfy",
                shown,
            ));
        }
        vec![]
    } else if impact || with_the_loads {
        let title = match impact {
            true => "kinematic constraints just after the blow (solved with impulse and momentum)",
            false => "kinematic constraints (solved with the equations of motion)",
        };
        steps.push(Step::new(title, shown));
        vec![]
    } else {
        let solution = alone.unwrap_or_else(|| unreachable!("solved above"));
        let Solution { values, free } = solution.map_err(|e| {
            // An equation that cannot be used is reported at its constraint.
            let span = match &e {
                SolveError::Inconsistent { equation, .. }
                | SolveError::Nonlinear { equation, .. } => sources.get(*equation).copied(),
                _ => None,
            };
            match (&e, span) {
                (SolveError::Inconsistent { residual, .. }, Some(span)) => scene.error_at(
                    span,
                    format!("over-determined: this constraint contradicts the other constraints and the givens (with them it reduces to 0 = {residual})"),
                    "drop this constraint or one it contradicts, or make a given in it an unknown",
                ),
                _ => solve_error(scene, span.unwrap_or(at), e, &equations),
            }
        })?;
        if !free.is_empty() {
            return Err(solve_error(
                scene,
                at,
                SolveError::UnderDetermined(free),
                &equations,
            ));
        }
        let mut relations = shown;
        relations.extend(
            values
                .iter()
                .map(|(u, v)| Relation::new(Expr::sym(*u), v.clone(), Axis::X)),
        );
        steps.push(Step {
            vectors: Vec::new(),
            table: None,
            title: "kinematic constraints, solved for the unknown rates".into(),
            relations,
        });
        values
    };
    let mut kinematics = SolvedConstraints {
        omega: zero_vector(),
        omega_dot: zero_vector(),
        frame_rate: zero_vector(),
        solved,
        with_equations_of_motion: match impact || with_the_loads {
            true => equations.into_iter().zip(sources).collect(),
            false => vec![],
        },
    };
    let substituted = |v: &Vector| kinematics.substitute_vector(v).map_err(located(at));
    let omega = substituted(&omega)?;
    let omega_dot = substituted(&stated.omega_dot)?;
    let frame_rate = substituted(stated.frame_rate.as_ref().unwrap_or(&omega))?;
    // The Eulerian angles' steps show ω and Ω already, unless constraints changed them.
    let shown_already = scene.euler_angles.is_some() && kinematics.solved.is_empty();
    let mut relations = Relation::components("omega", &omega);
    if stated.frame_rate.is_some() {
        relations.extend(Relation::components("Omega", &frame_rate));
    }
    steps.extend((!shown_already).then(|| Step {
        vectors: Vec::new(),
        table: None,
        // An impulse problem has no rate of change and so no frame rate to speak of.
        title: if stated.frame_rate.is_some() {
            r"angular velocity $\boldsymbol{\omega}$ of the body and $\boldsymbol{\Omega}$ of the frame ($\boldsymbol{\Omega} \neq \boldsymbol{\omega}$: $[I]$ is constant in this frame)".into()
        } else if !scene.impulses.is_empty() {
            r"angular velocity $\boldsymbol{\omega}$".into()
        } else {
            r"angular velocity $\boldsymbol{\omega}$ (axes fixed in the body, $\boldsymbol{\Omega} = \boldsymbol{\omega}$)".into()
        },
        relations,
    }));
    kinematics.omega = omega;
    kinematics.omega_dot = omega_dot;
    kinematics.frame_rate = frame_rate;
    Ok((kinematics, steps))
}

/// `e` with `omega_x`, `omega_y`, `omega_z` the components of ω (a symbol the scene declares
/// by that name is ω's component already, and stays as it is).
fn omega_components_put_in(e: &Expr, omega: &Vector) -> Result<Expr, AlgebraError> {
    let component = |s: Symbol| {
        let k = OMEGA_COMPONENTS.iter().position(|n| *n == s.name())?;
        Some(omega[k].clone())
    };
    e.subs(&component)
}

fn zero_vector() -> Vector {
    Vector::from_element(Expr::zero())
}
