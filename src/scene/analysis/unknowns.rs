//! The unknowns of a scene: the equations of motion (or of impulse and momentum, for a scene
//! with impulses) taken from mechanics, solved once for every unknown they hold; an unknown
//! solved in general but left undetermined by the givens' values (a zero pivot, L = 0) is
//! refused at its find.

use super::super::kinematic_constraints::{self, H_COMPONENTS};
use super::super::model::{Quantity, Request, Scene, Span};
use super::super::stated_kinematics::at_reducing_angle;
use super::super::units::dimension_with;
use super::motion_obeys_loads::equation_named;
use super::scene_solve::{sine_and_cosine_of, solve_scene};
use super::{zero_vector, Analyser, Value};
use crate::algebra::polynomial_solve::{Solutions, SolveError};
use crate::algebra::{AlgebraError, Axis, Expr, Func, Symbol, Vector, View};
use crate::mechanics::angular_momentum::angular_momentum_before;
use crate::mechanics::derivation::{Derivation, Relation, Step};
use crate::mechanics::equations_of_motion::{equations_of_motion, Loads, MomentCentre};
use crate::mechanics::impulse_momentum::{impulse_momentum, ImpulseMomentum};
use crate::mechanics::resultant::{resultant_force, resultant_moment, AppliedForce};
use crate::parse::Diagnostic;
use std::collections::HashMap;

/// Where an equation the unknowns are solved from comes from: an equation of motion (named
/// only when an error quotes it) or a constraint (its line).
enum Origin {
    Motion(Relation),
    Constraint(Span),
}

impl Analyser<'_> {
    /// The solver's error at `at`, its help naming what `equations` need.
    fn solve_error(
        &self,
        at: Span,
        e: SolveError,
        equations: &[Expr],
        origins: &[Origin],
    ) -> Diagnostic {
        if matches!(e, SolveError::Inconsistent { .. }) && pivot_without_reaction(self.scene) {
            return self.scene.error_at(at, e.to_string(), PIVOT_REACTION);
        }
        if let SolveError::Inconsistent { equation, residual } = &e {
            if let Some(origin) = origins.get(*equation) {
                let (named, at) = match origin {
                    Origin::Motion(relation) => (self.motion_equation_named(relation), at),
                    Origin::Constraint(span) => {
                        let line = self.scene.line_of(*span);
                        (format!("the constraint on line {line}"), *span)
                    }
                };
                return self.scene.error_at(
                    at,
                    format!("over-determined: {named} contradicts the others (with them it reduces to 0 = {residual})"),
                    "the givens, the constraints and the loads state more than one motion allows: make one of the givens in it an unknown, drop a constraint, or add the load that drives the motion",
                );
            }
        }
        if let SolveError::UnderDetermined(open) = &e {
            let scene = self.scene;
            let wanted: Vec<&str> = scene
                .unknowns
                .iter()
                .map(|u| u.0)
                .filter(|u| equations.iter().any(|e| e.contains(*u)))
                .map(|u| u.name())
                .collect();
            let open: Vec<&str> = open.iter().map(|s| s.name()).collect();
            if equations.len() < wanted.len() {
                return scene.error_at(
                    at,
                    format!(
                        "under-determined: {} equations (the constraints and the equations of motion that hold an unknown) for the {} unknowns {}; they do not fix {}",
                        equations.len(),
                        wanted.len(),
                        wanted.join(", "),
                        open.join(", ")
                    ),
                    format!(
                        "give one of them a value ('given {} = …') or add a condition ('constraint …')",
                        open.last().copied().unwrap_or("x")
                    ),
                );
            }
        }
        kinematic_constraints::solve_error(self.scene, at, e, equations)
    }

    /// An equation of motion named as on the page (`ΣM_G = Ḣ_G about x`).
    fn motion_equation_named(&self, relation: &Relation) -> String {
        let scene = self.scene;
        // The side that holds no number put in from a unit (ṁā, Ḣ in the givens), else the
        // other, else the residual.
        let of = |e: &Expr| match e.is_zero() {
            true => None,
            false => dimension_with(e, &|s| scene.dimension(s)).ok(),
        };
        let dimension = of(&relation.rhs)
            .or_else(|| of(&relation.lhs))
            .or_else(|| of(&relation.residual()));
        equation_named(scene, dimension, relation.axis)
    }

    pub(super) fn unknown(&mut self, at: Span, s: Symbol) -> Result<Expr, Diagnostic> {
        if let Some(v) = self.kinematics(at)?.solved.iter().find(|(u, _)| *u == s) {
            return Ok(v.1.clone());
        }
        if self.unknowns.is_none() {
            let derivation = if self.scene.impulses.is_empty() {
                self.equations_of_motion(at)?
            } else {
                self.impulse_momentum(at)?
            };
            let mut constraints = self.kinematics(at)?.with_equations_of_motion.clone();
            // H_G's components named in a constraint: [Ī]{ω}, shown as its step.
            let scene = self.scene;
            if constraints
                .iter()
                .any(|(e, _)| kinematic_constraints::names_angular_momentum(scene, e))
            {
                let h = self.h_g(at)?;
                let component = |s: Symbol| {
                    let k = H_COMPONENTS.iter().position(|n| *n == s.name())?;
                    scene.dimension(s).is_none().then(|| h[k].clone())
                };
                for (e, _) in constraints.iter_mut() {
                    *e = e.subs(&component).map_err(self.algebra(at))?;
                }
            }
            let motion = derivation
                .result()
                .iter()
                .map(|r| (r.residual(), Origin::Motion(r.clone())));
            let constraints = constraints
                .into_iter()
                .map(|(e, span)| (e, Origin::Constraint(span)));
            let mut equations: Vec<Expr> = Vec::new();
            let mut origins: Vec<Origin> = Vec::new();
            for (e, origin) in motion.chain(constraints) {
                let e = self.known(&e).map_err(self.algebra(at))?;
                if !e.is_zero() {
                    equations.push(e);
                    origins.push(origin);
                }
            }
            self.plan.extend(derivation.steps);
            let wanted: Vec<Symbol> = self
                .scene
                .unknowns
                .iter()
                .map(|u| u.0)
                .filter(|u| equations.iter().any(|e| e.contains(*u)))
                .collect();
            let Solutions {
                branches,
                dropped,
                free,
                polynomial,
                eliminated,
            } = solve_scene(self.scene, &equations, &wanted)
                .map_err(|e| self.solve_error(at, e, &equations, &origins))?;
            if !eliminated.is_empty() {
                let relations = eliminated
                    .into_iter()
                    .map(|(w, value)| Relation::new(Expr::sym(w), value, Axis::X))
                    .collect();
                self.plan.push(Step::new(
                    "the unknowns that enter an equation linearly, from it, put into the others",
                    relations,
                ));
            }
            if let Some((u, p)) = polynomial {
                let mut relations = vec![Relation::new(p.clone(), Expr::zero(), Axis::X)];
                // `tan θ − t`: the angle from its tangent (`scene_solve.rs`).
                let tangent = Func::Tan.apply(Expr::sym(u));
                let from_tangent = (&tangent - &p).expand().ok().filter(|t| !t.contains(u));
                let title = match (sine_and_cosine_of(self.scene, u), from_tangent) {
                    (Some([(c, cosine), (s, sine)]), _) => {
                        relations.push(Relation::new(Expr::sym(c), cosine, Axis::X));
                        relations.push(Relation::new(Expr::sym(s), sine, Axis::X));
                        format!(
                            "the equations in the angle's sine and cosine, with ${}^2 = 1 - {}^2$: a polynomial in ${}$",
                            s.latex(),
                            c.latex(),
                            c.latex()
                        )
                    }
                    (None, Some(t)) => {
                        relations = vec![Relation::new(tangent, t, Axis::X)];
                        format!(
                            r"the equation in ${0}$ alone is $A\,\mathrm{{sin}}\,{0} + B\,\mathrm{{cos}}\,{0} = 0$: ${0}$ from its tangent",
                            u.latex()
                        )
                    }
                    (None, None) => {
                        format!("the equations reduce to a polynomial in ${}$", u.latex())
                    }
                };
                self.plan.push(Step::new(title, relations));
            }
            if branches.is_empty() {
                if let Some(d) = dropped.first() {
                    let mut reasons: Vec<&str> =
                        dropped.iter().map(|d| d.reason.as_str()).collect();
                    reasons.dedup();
                    return Err(self.fail(
                        at,
                        format!(
                            "no solution: every root for {} is ruled out ({})",
                            d.unknown.name(),
                            reasons.join("; ")
                        ),
                        match reasons.as_slice() {
                            [only] if only.contains("φ and ψ are not told apart") => {
                                "with the axis along K (θ = 0 or 180°) the motion is a spin about a fixed axis, which the Eulerian angles do not describe: state it without 'euler angles' (omega = w*k), or change the givens"
                            }
                            _ => "the givens admit no such motion (a top spinning too slowly has no real steady precession): change the givens or the unknowns",
                        },
                    ));
                }
            }
            // Each root the problem's conditions rule out, its value and the reason.
            for d in &dropped {
                let title = format!("a root ruled out: {}", d.condition.words);
                let root = Relation::new(Expr::sym(d.unknown), d.value.clone(), Axis::X);
                let why = Relation::new(d.condition.lhs.clone(), d.condition.rhs.clone(), Axis::X);
                let relations = match why == root {
                    true => vec![root],
                    false => vec![root, why],
                };
                self.plan.push(Step::new(title, relations));
            }
            // Elimination can leave fractions inside fractions (a pivot over a pivot): such a
            // value in lowest terms over one denominator, when that is within the algebra's
            // bounds; the others as they are (their shortest form is chosen when shown).
            let branches: Vec<Vec<(Symbol, Expr)>> = branches
                .into_iter()
                .map(|branch| {
                    branch
                        .into_iter()
                        .map(|(u, v)| match has_nested_fraction(&v) {
                            true => (u, v.cancel().unwrap_or(v)),
                            false => (u, v),
                        })
                        .collect()
                })
                .collect();
            let several = branches.len() > 1;
            for (k, branch) in branches.iter().enumerate() {
                let title = match several {
                    true => format!("solution {} of {}", k + 1, branches.len()),
                    false => "solve the equations for the unknowns".to_string(),
                };
                let relations = branch
                    .iter()
                    .map(|(u, v)| Relation::new(Expr::sym(*u), v.clone(), Axis::X))
                    .collect();
                self.plan.push(Step::new(title, relations));
            }
            let maps = branches
                .into_iter()
                .map(|branch| {
                    let mut map: HashMap<Symbol, Expr> = branch.into_iter().collect();
                    for f in &free {
                        map.remove(f);
                    }
                    map
                })
                .collect();
            self.unknowns = Some(maps);
            self.undetermined_with_values = self.undetermined_with_values(&equations, &wanted);
        }
        if let Some(equations) = self.undetermined_with_values.get(&s) {
            // Named as the request is written when it asks for this unknown (`T_BC in N`).
            let scene = self.scene;
            let named = scene
                .requests
                .iter()
                .find(|r| r.span == at && r.quantity == Quantity::Unknown(s))
                .map_or_else(|| s.name().to_string(), Request::as_written);
            return Err(scene.division_by_zero_at(at, &named, equations));
        }
        self.unknowns
            .as_ref()
            .and_then(|solutions| solutions.get(self.solution)?.get(&s).cloned())
            .ok_or_else(|| self.solve_error(at, SolveError::UnderDetermined(vec![s]), &[], &[]))
    }

    /// The request's value in each solution after the first (`raw` as derived, `first` its
    /// value in the first solution); none when the equations have one solution or the value
    /// is the same in all.
    pub(super) fn in_other_solutions(
        &mut self,
        request: &Request,
        raw: &Value,
        first: &Value,
    ) -> Result<Vec<Value>, Diagnostic> {
        let count = self.unknowns.as_ref().map_or(1, Vec::len);
        let mut values = Vec::new();
        for k in 1..count {
            self.solution = k;
            let value = match request.quantity {
                Quantity::Unknown(s) => self.unknown(request.span, s).map(Value::Scalar),
                _ => self.in_givens(request.span, raw.clone()),
            };
            self.solution = 0;
            values.push(value?);
        }
        match values.iter().all(|v| v == first) {
            true => Ok(Vec::new()),
            false => Ok(values),
        }
    }

    /// The unknowns that the equations determine in general, dividing by a symbolic pivot,
    /// but not with the givens' values, where the pivot is zero (a shaft of length L = 0):
    /// found by solving again with every given's exact value. Each comes with the equations
    /// (their sum), whose zero givens the error names. Empty when a given in the equations
    /// has no value.
    fn undetermined_with_values(
        &self,
        equations: &[Expr],
        wanted: &[Symbol],
    ) -> HashMap<Symbol, Expr> {
        let scene = self.scene;
        let value = |s: Symbol| scene.exact_value(s).map(Expr::num);
        let all_valued = equations
            .iter()
            .flat_map(|e| e.symbols())
            .all(|s| wanted.contains(&s) || scene.value(s).is_some());
        let with_values: Option<Vec<Expr>> =
            equations.iter().map(|e| e.subs(&value).ok()).collect();
        let (true, Some(with_values)) = (all_valued, with_values) else {
            return HashMap::new();
        };
        let undetermined = match solve_scene(scene, &with_values, wanted) {
            Ok(solutions) => solutions.free,
            Err(SolveError::UnderDetermined(free)) => free,
            Err(SolveError::Inconsistent { .. }) => wanted.to_vec(),
            Err(_) => Vec::new(),
        };
        let together = Expr::add_all(equations.iter().cloned());
        undetermined
            .into_iter()
            .map(|u| (u, together.clone()))
            .collect()
    }

    /// `ΣF = m ā` and the moments: `ΣM_O = Ḣ_O` about a fixed point O, or with the rate
    /// about G, `ΣM_O = Ḣ_G + r̄ × m ā` (`about G`), or `ΣM_G = Ḣ_G` (no fixed point).
    pub(super) fn equations_of_motion(&mut self, at: Span) -> Result<Derivation, Diagnostic> {
        let scene = self.scene;
        let a = self.abar(at)?;
        let about = match (scene.fixed_point, scene.about_mass_centre) {
            (true, false) => MomentCentre::FixedPoint,
            (true, true) => MomentCentre::FixedPointThroughMassCentre,
            (false, _) => MomentCentre::MassCentre,
        };
        let rate = self.rate_of_angular_momentum(at, about == MomentCentre::FixedPoint)?;
        // With `euler angles` at θ = 90° (say) the loads are taken there, as the kinematics.
        let reduced = |v: &Vector| at_reducing_angle(scene, v).map_err(self.algebra(at));
        let values: Vec<Vector> = scene
            .forces
            .iter()
            .map(|f| reduced(&f.value))
            .collect::<Result<_, _>>()?;
        let couples: Vec<Vector> = scene
            .couples
            .iter()
            .map(reduced)
            .collect::<Result<_, _>>()?;
        let forces: Vec<AppliedForce> = scene
            .forces
            .iter()
            .zip(&values)
            .map(|(f, value)| AppliedForce {
                value,
                point: &f.point,
            })
            .collect();
        let loads = Loads {
            forces: &forces,
            couples: &couples,
        };
        let body = self.mass_centre(at)?;
        equations_of_motion(&body, &a, &rate, loads, about).map_err(self.algebra(at))
    }

    /// `m v̄₁ + Σ F Δt = m v̄₂` and `[I]{ω₁} + Σ r × F Δt = [I]{ω₂}` about G, for an impact
    /// on a body that moves with `v̄₁` and `ω₁` before it (`before vbar`, `before omega`; at
    /// rest when not given).
    pub(super) fn impulse_momentum(&mut self, at: Span) -> Result<Derivation, Diagnostic> {
        let v = self.vbar(at)?;
        let h = self.h_g(at)?;
        let scene = self.scene;
        let h_before = match &scene.omega_before {
            Some(omega) => {
                let inertia = self.body(at)?.inertia.clone();
                let d = angular_momentum_before(&inertia, omega).map_err(self.algebra(at))?;
                self.record_vector(d)
            }
            None => zero_vector(),
        };
        let body = self.body(at)?;
        let impulses: Vec<AppliedForce> = scene
            .impulses
            .iter()
            .map(|i| AppliedForce {
                value: &i.value,
                point: &i.point,
            })
            .collect();
        let rest = zero_vector();
        let before = scene.vbar_before.as_ref().unwrap_or(&rest);
        let derive = || -> Result<Derivation, AlgebraError> {
            impulse_momentum(&ImpulseMomentum {
                mass: &body.mass,
                velocity_before: before,
                velocity_after: &v,
                angular_momentum_before: &h_before,
                angular_momentum_after: &h,
                linear_impulse: &resultant_force(&impulses)?,
                angular_impulse: &resultant_moment(&impulses, &[], &body.centroid)?,
            })
        };
        derive().map_err(self.algebra(at))
    }
}

/// Whether `e` has a fraction inside a denominator: a negative power whose base holds
/// another negative power (`1/(a/(b + c) - d)`).
fn has_nested_fraction(e: &Expr) -> bool {
    fn inside(e: &Expr, under_bar: bool) -> bool {
        match e.view() {
            View::Num(_) | View::Sym(_) => false,
            View::Add(items) | View::Mul(items) => items.iter().any(|x| inside(x, under_bar)),
            View::Func(_, argument) => inside(argument, under_bar),
            View::Pow(base, exponent) => {
                let reciprocal = exponent.as_num().is_some_and(|q| q.is_negative());
                (reciprocal && under_bar) || inside(base, under_bar || reciprocal)
            }
        }
    }
    inside(e, false)
}

/// What to write when a top's pivot has no reaction: the statements of
/// `examples/scenes/top_slow_and_fast_precession.scene`.
const PIVOT_REACTION: &str = "a fixed point needs its reaction as a force at O: declare \
     'unknown R_x, R_y, R_z : N' and write 'force R = R_x*i + R_y*j + R_z*k at (0, 0, 0)'";

/// A scene with `euler angles` about a fixed point O and no force at O: a top or gyroscope
/// whose pivot's reaction was left out. Its ΣF = m ā then has the loads alone (the weight:
/// the mass centre would fall freely, not turn about O), so the equations contradict each
/// other.
fn pivot_without_reaction(scene: &Scene) -> bool {
    scene.euler_angles.is_some()
        && scene.fixed_point
        && !scene
            .forces
            .iter()
            .any(|f| f.point.iter().all(Expr::is_zero))
}

#[cfg(test)]
mod tests {
    use super::has_nested_fraction;
    use crate::parse::parse_expression;

    #[test]
    fn a_fraction_inside_a_denominator_is_nested() {
        let nested = |t: &str| has_nested_fraction(&parse_expression("test", t).unwrap());
        assert!(nested("1/(a/(b + c) - d)"));
        assert!(nested("x + P/(m*(1 - k/(m*r^2)))"));
        assert!(!nested("3*M/(8*c) - 3/8*m*c*w^2"));
        assert!(!nested("a*(m_2*b - m_1*l)/(4*l) + sin(1/t)"));
    }
}
