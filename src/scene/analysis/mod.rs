//! The demand-driven analysis of a scene: each request pulls only the derivations it needs,
//! each derivation is done at most once, and the order in which they were done is the plan.
//! Every quantity comes from a [`crate::mechanics`] function, and the plan shows that
//! function's steps: the analysis chooses, caches and substitutes, and derives nothing itself.
//!
//! With a fixed point O (and no `about G`) the route is the textbook's (§18.7–18.8): the
//! moments and products of inertia about O, `{H_O} = [I_O]{ω}`, `T = ½{ω}ᵀ[I_O]{ω}` and
//! `ΣM_O = Ḣ_O`; the mass centre only where `ΣF = m ā` or v̄ needs it. Otherwise the
//! centroidal route: `[Ī]`, `H_G`, `H_O = H_G + r̄ × m v̄`, `ΣM = Ḣ_G + r̄ × m ā`.
//!
//! | request | pulls (about O) | pulls (about G) |
//! |---|---|---|
//! | `omega` | kinematics (constraints solved) | the same |
//! | `vbar`, `mvbar` | kinematics, mass centre, its motion | kinematics, body about G, motion of G |
//! | `abar`, `mabar` | kinematics, mass centre, its acceleration | kinematics, body about G, acceleration of G |
//! | `H_G` | body about G, kinematics, angular momentum | the same |
//! | `H_O` | inertia about O, kinematics, angular momentum | body about G, kinematics, `H_G`, motion of G, `H_O` |
//! | `T` | inertia about O, kinematics, kinetic energy | body about G, kinematics, motion of G, kinetic energy |
//! | `Hdot_G` | body about G, kinematics, rate of change of angular momentum | the same |
//! | `Hdot_O` | inertia about O, kinematics, `Ḣ_O = [I_O]{ω̇} + Ω × H_O` | `Ḣ_G`, `ā`, `Ḣ_O = Ḣ_G + r̄ × m ā` (refused without a fixed point) |
//! | `T_trans`, `T_rot` | kinematics, motion of G, body about G, the split | the same |
//! | `T_1`, `T_lost` | inertia about O, `ω₁` (`T_1`); `T` too (`T_lost`) | body about G, `v̄₁`, `ω₁`; `T` too |
//! | `v_A`, `a_A` | kinematics, `ω × r_A`, `α × r_A + ω × (ω × r_A)` | kinematics, v̄ or ā, `v̄ + ω × (r_A − r̄)`, ... |
//! | a named impulse | its components, the unknowns among them solved | the same |
//! | a named force | its components, the unknowns among them solved | the same |
//! | `I_G`, `principal_G` | body about G (then the principal frame) | the same |
//! | `I_O`, `principal_O` | inertia about O (then the principal frame) | the same |
//! | `precession` | body about G, the torque-free motion, γ and the sense with its I and I′ | the same |
//! | an unknown | the equations of motion with `Ḣ_O` (or impulse and momentum); then the solution | the same with `Ḣ_G` |

mod abbreviations;
mod balance;
mod impact_energy;
mod motion_obeys_loads;
mod points;
mod presented;
mod principal;
mod scene_solve;
mod torque_free;
mod unknowns;

use super::kinematic_constraints::{solve_constraints, SolvedConstraints};
use super::model::{ConstraintKind, Part, Quantity, Request, Scene, Span};
use crate::algebra::work;
use crate::algebra::{AlgebraError, Expr, Matrix, Symbol, Vector};
use crate::mechanics::angular_momentum::{angular_momentum, angular_momentum_about_point};
use crate::mechanics::composite_body::{composite_body, MassProperties};
use crate::mechanics::derivation::{Derivation, Relation, Step};
use crate::mechanics::inertia::InertiaTensor;
use crate::mechanics::inertia::MassPart;
use crate::mechanics::inertia_about_point::inertia_about_fixed_point;
use crate::mechanics::kinematics::{acceleration_of_mass_centre, velocity_of_mass_centre};
use crate::mechanics::kinetic_energy::{kinetic_energy, kinetic_energy_split};
use crate::mechanics::linear_momentum::{effective_force, linear_momentum};
use crate::mechanics::mass_centre::{mass_centre, MassCentre};
use crate::mechanics::principal_frame::PrincipalFrame;
use crate::mechanics::rotating_frame::{
    rate_of_angular_momentum, rate_of_angular_momentum_about_point,
};
use crate::mechanics::slip::Slip;
use crate::mechanics::torque_free_axisymmetric::Precession;
use crate::mechanics::two_plane_balance::Correction;
use crate::parse::Diagnostic;
pub use abbreviations::Abbreviations;
use std::collections::HashMap;

/// A derived quantity: scalar or vector.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Scalar(Expr),
    Vector(Vector),
    /// `find balance ...`: the two correction masses and their angles.
    Balance(Box<[Correction; 2]>),
    /// An inertia tensor `[I]`, the chapter's signs (off-diagonal `−I_xy`, ...).
    Tensor(Matrix),
    /// Principal moments, ascending, and axes (a right-handed frame).
    Principal(PrincipalFrame),
    /// `find precession`: γ and the sense of the torque-free precession.
    Precession(Box<Precession>),
}

/// The outcome: the plan (steps in the order done) and each request's result.
#[derive(Debug, Clone)]
pub struct Analysis {
    pub plan: Vec<Step>,
    pub results: Vec<(Request, Value)>,
    /// Names of the long radicands the plan is written with; a page shows the results
    /// with them too.
    pub abbreviations: Abbreviations,
    /// Each solution of the scene's equations: its unknowns' values in the givens (empty
    /// when the scene solves for none), for the values of the steps that hold unknowns.
    pub solutions: Vec<HashMap<Symbol, Expr>>,
}

/// Lazily computed pieces; `plan` records the steps of each derivation as it is done.
struct Analyser<'a> {
    scene: &'a Scene,
    plan: Vec<Step>,
    body: Option<MassProperties>,
    /// The mass and mass centre, when the route about O needs them without the body about G.
    centre: Option<MassCentre>,
    /// The moments and products of inertia about the fixed point O.
    inertia_o: Option<InertiaTensor>,
    kinematics: Option<SolvedConstraints>,
    vbar: Option<Vector>,
    abar: Option<Vector>,
    h_g: Option<Vector>,
    hdot_g: Option<Vector>,
    hdot_o: Option<Vector>,
    /// `T_trans`, `T_rot` and `T` about G.
    energy_split: Option<[Expr; 3]>,
    /// `T_1`, just before an impact.
    energy_before: Option<Expr>,
    /// The unknowns' values in each solution of the equations (one, unless an unknown
    /// entered polynomially and several real roots remain).
    unknowns: Option<Vec<HashMap<Symbol, Expr>>>,
    /// Which solution the unknowns are looked up in.
    solution: usize,
    /// Unknowns solved in general that the givens' values leave undetermined.
    undetermined_with_values: HashMap<Symbol, Expr>,
}

/// Runs the analysis for the scene's requests.
///
/// A sphere spinning at w about z, asked only for its kinetic energy:
/// `T = ½ (2/5 m r²) w² = 1/5 m r² w²`, and the plan derives no rate of angular momentum.
///
/// ```
/// use kinetics::{analyse, parse_expression, parse_scene, Value};
///
/// let scene = parse_scene(
///     "sphere.scene",
///     "given m : kg
/// given r : m
/// given w : rad/s
/// body sphere(r) mass m
/// vbar = 0
/// omega = w*k
/// find T",
/// )?;
/// let analysis = analyse(&scene)?;
/// let (_, Value::Scalar(t)) = &analysis.results[0] else { panic!("T is a scalar") };
/// assert_eq!(*t, parse_expression("by hand", "1/5 m r^2 w^2")?);
/// let words = |step: &kinetics::mechanics::Step| kinetics::print::markup::text(&step.title);
/// assert!(analysis.plan.iter().all(|step| !words(step).contains('Ḣ')));
/// # Ok::<(), kinetics::Diagnostic>(())
/// ```
pub fn analyse(scene: &Scene) -> Result<Analysis, Diagnostic> {
    analysed(scene, Steps::Written)
}

/// [`analyse`] for a caller that reads the results alone (a notebook's values): the same
/// derivations and results, the plan's steps not written (`plan` empty, no long radicand
/// named) — writing them is most of the work of a small scene (SP 18.4: 0.67 → 0.2 ms).
/// A page needs [`analyse`].
pub fn analyse_results(scene: &Scene) -> Result<Analysis, Diagnostic> {
    analysed(scene, Steps::Skipped)
}

/// Whether an analysis writes its plan's steps for a page.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Steps {
    Written,
    Skipped,
}

fn analysed(scene: &Scene, steps: Steps) -> Result<Analysis, Diagnostic> {
    let mut a = Analyser::new(scene);
    let mut results = Vec::new();
    for request in &scene.requests {
        let raw = a.request(request)?;
        let value = a.in_givens(request.span, raw.clone())?;
        let others = a.in_other_solutions(request, &raw, &value)?;
        if others.is_empty() {
            results.push((request.clone(), value));
            continue;
        }
        // A row per solution, each labelled with its number.
        for (k, value) in std::iter::once(value).chain(others).enumerate() {
            let mut row = request.clone();
            row.solution = Some(k + 1);
            results.push((row, value));
        }
    }
    a.motion_obeys_loads()?;
    let domains = scene.domains();
    let written = match steps {
        Steps::Written => &a.plan[..],
        Steps::Skipped => &[],
    };
    let mut analysis = Analysis {
        plan: written
            .iter()
            .map(|s| {
                work::doing(
                    || format!("writing the step “{}”", s.title),
                    || s.simplified(&domains),
                )
            })
            .collect(),
        results: results
            .into_iter()
            .map(|(request, value)| {
                let what = || format!("writing the result {}", request.as_written());
                let presented = work::doing(what, || value.presented(&domains));
                (request, presented)
            })
            .collect(),
        abbreviations: Abbreviations::default(),
        solutions: a.unknowns.clone().unwrap_or_default(),
    };
    if steps == Steps::Written {
        Abbreviations::name_in(&mut analysis, &|s| scene.dimension(s).is_some());
    }
    Ok(analysis)
}

/// The value of each request (one a solution of the scene's equations), all asked of one
/// analyser: what several need (the body, the kinematics, the unknowns) is derived once, and
/// a request the scene cannot derive has its error while the others have their values. No
/// plan is kept or simplified: this is for the checker's context, which asks for every
/// quantity a scene names.
pub fn values_of(scene: &Scene, requests: &[Request]) -> Vec<Result<Vec<Value>, Diagnostic>> {
    let mut a = Analyser::new(scene);
    let values: Vec<Result<Vec<Value>, Diagnostic>> = requests
        .iter()
        .map(|request| {
            let raw = a.request(request)?;
            let value = a.in_givens(request.span, raw.clone())?;
            let others = a.in_other_solutions(request, &raw, &value)?;
            Ok(std::iter::once(value).chain(others).collect())
        })
        .collect();
    // A motion its loads cannot produce has no quantities to check a claim against. With a
    // slip made (the checker's reading of a student's error) the values are that error's, not
    // the scene's statement: the scene was checked as derived.
    if Slip::active().is_some() {
        return values;
    }
    match a.motion_obeys_loads() {
        Ok(()) => values,
        Err(refusal) => values.iter().map(|_| Err(refusal.clone())).collect(),
    }
}

/// The body's mass, mass centre (from O) and centroidal inertia, for callers that need the
/// body but no derivation (the simulator); an error stands at the first body statement.
pub fn centroidal_body(scene: &Scene) -> Result<MassProperties, Diagnostic> {
    // Errors stand at the first body statement, or at the end of a file without one.
    let end = Span {
        start: scene.source.len(),
        end: scene.source.len(),
    };
    let at = scene.places.body.first().copied().unwrap_or(end);
    Analyser::new(scene).body(at).cloned()
}

fn zero_vector() -> Vector {
    Vector::from_element(Expr::zero())
}

impl<'a> Analyser<'a> {
    fn new(scene: &'a Scene) -> Analyser<'a> {
        Analyser {
            scene,
            plan: Vec::new(),
            body: None,
            centre: None,
            inertia_o: None,
            kinematics: None,
            vbar: None,
            abar: None,
            h_g: None,
            hdot_g: None,
            hdot_o: None,
            energy_split: None,
            energy_before: None,
            unknowns: None,
            solution: 0,
            undetermined_with_values: HashMap::new(),
        }
    }

    fn fail(&self, at: Span, message: impl Into<String>, help: impl Into<String>) -> Diagnostic {
        self.scene.error_at(at, message, help)
    }

    /// An algebra error met while deriving for the request at `at`.
    fn algebra(&self, at: Span) -> impl Fn(AlgebraError) -> Diagnostic + '_ {
        self.scene.algebra_error_at(at)
    }

    /// Records the derivation's steps in the plan and hands back the right-hand sides of its
    /// result (`H_x, H_y, H_z`; `T`).
    fn record(&mut self, d: Derivation) -> Vec<Expr> {
        let result = d.result().iter().map(|r| r.rhs.clone()).collect();
        self.plan.extend(d.steps);
        result
    }

    /// [`Analyser::record`] for a derivation whose result is a vector's three components.
    fn record_vector(&mut self, d: Derivation) -> Vector {
        Vector::from_iterator(self.record(d))
    }

    fn request(&mut self, r: &Request) -> Result<Value, Diagnostic> {
        let at = r.span;
        Ok(match r.quantity {
            Quantity::AngularVelocity => Value::Vector(self.kinematics(at)?.omega.clone()),
            Quantity::MassCentreVelocity => Value::Vector(self.vbar(at)?),
            Quantity::LinearMomentum => {
                let (m, v) = (self.mass_centre(at)?.mass, self.vbar(at)?);
                Value::Vector(linear_momentum(&m, &v).map_err(self.algebra(at))?)
            }
            Quantity::MassCentreAcceleration => Value::Vector(self.abar(at)?),
            Quantity::EffectiveForce => {
                let (m, a) = (self.mass_centre(at)?.mass, self.abar(at)?);
                Value::Vector(effective_force(&m, &a).map_err(self.algebra(at))?)
            }
            Quantity::AngularMomentumAboutG => Value::Vector(self.h_g(at)?),
            Quantity::AngularMomentumAboutO => Value::Vector(self.h_o(at)?),
            Quantity::KineticEnergy => Value::Scalar(self.kinetic_energy(at)?),
            Quantity::RateOfAngularMomentum => {
                Value::Vector(self.rate_of_angular_momentum(at, false)?)
            }
            Quantity::RateOfAngularMomentumAboutO => Value::Vector(self.hdot_o(at)?),
            Quantity::TranslationalKineticEnergy => {
                Value::Scalar(self.energy_split(at)?[0].clone())
            }
            Quantity::RotationalKineticEnergy => Value::Scalar(self.energy_split(at)?[1].clone()),
            Quantity::KineticEnergyBefore => Value::Scalar(self.energy_before(at)?),
            Quantity::KineticEnergyAfter => {
                self.in_an_impact(at, "T_2")?;
                Value::Scalar(self.kinetic_energy(at)?)
            }
            Quantity::EnergyLost => Value::Scalar(self.energy_lost(at)?),
            Quantity::PointVelocity(p) => Value::Vector(self.point_velocity(at, p)?),
            Quantity::PointAcceleration(p) => Value::Vector(self.point_acceleration(at, p)?),
            Quantity::NamedImpulse(s) => Value::Vector(self.named_impulse(at, s)?),
            Quantity::NamedForce(s) => Value::Vector(self.named_force(at, s)?),
            Quantity::InertiaAboutG => Value::Tensor(self.body(at)?.inertia.matrix()),
            Quantity::InertiaAboutO => Value::Tensor(self.inertia_about_o(at)?.matrix()),
            Quantity::PrincipalAboutG => self.principal(r, false)?,
            Quantity::PrincipalAboutO => self.principal(r, true)?,
            Quantity::Unknown(s) => Value::Scalar(self.unknown(at, s)?),
            Quantity::Balance => self.balance(at)?,
            Quantity::Precession => self.torque_free(at)?,
        })
    }

    /// A result expressed in the givens alone: unknowns in it are solved and substituted.
    fn in_givens(&mut self, at: Span, value: Value) -> Result<Value, Diagnostic> {
        let mut exprs: Vec<Expr> = match &value {
            Value::Scalar(e) => vec![e.clone()],
            Value::Vector(v) => v.iter().cloned().collect(),
            Value::Balance(_) | Value::Tensor(_) | Value::Principal(_) | Value::Precession(_) => {
                return Ok(value)
            }
        };
        let pending: Vec<Symbol> = self
            .scene
            .unknowns
            .iter()
            .map(|u| u.0)
            .filter(|u| exprs.iter().any(|e| e.contains(*u)))
            .collect();
        if pending.is_empty() {
            return Ok(value);
        }
        let mut solved = Vec::with_capacity(pending.len());
        for u in pending {
            solved.push((u, self.unknown(at, u)?));
        }
        let lookup = |s: Symbol| solved.iter().find(|(u, _)| *u == s).map(|(_, v)| v.clone());
        for e in exprs.iter_mut() {
            *e = e
                .subs(&lookup)
                .and_then(|x| x.expand())
                .map_err(self.algebra(at))?;
        }
        Ok(match value {
            Value::Scalar(_) => Value::Scalar(exprs.remove(0)),
            Value::Vector(_) => Value::Vector(Vector::from_iterator(exprs)),
            Value::Balance(_) | Value::Tensor(_) | Value::Principal(_) | Value::Precession(_) => {
                value
            }
        })
    }

    /// The scene's parts, each with its centroidal inertia in the frame's axes.
    fn parts(&self, at: Span) -> Result<Vec<MassPart>, Diagnostic> {
        let parts = &self.scene.parts;
        if parts.is_empty() {
            return Err(self.fail(
                at,
                "the scene has no body",
                "add a line such as 'body disk(r) mass m at (L, 0, 0)'",
            ));
        }
        parts
            .iter()
            .map(Part::mass_part)
            .collect::<Result<_, AlgebraError>>()
            .map_err(self.algebra(at))
    }

    /// An algebra error met while finding the mass centre: a division by zero is a total
    /// mass of zero.
    fn mass_error(&self, at: Span) -> impl Fn(AlgebraError) -> Diagnostic + '_ {
        move |e| match e {
            AlgebraError::DivisionByZero => self.fail(
                at,
                "the total mass of the body is zero",
                "give every body a positive mass",
            ),
            e => self.algebra(at)(e),
        }
    }

    fn body(&mut self, at: Span) -> Result<&MassProperties, Diagnostic> {
        if self.body.is_none() {
            let parts = self.parts(at)?;
            let (body, derivation) = composite_body(&parts).map_err(self.mass_error(at))?;
            self.plan.extend(derivation.steps);
            self.body = Some(body);
        }
        Ok(self
            .body
            .as_ref()
            .unwrap_or_else(|| unreachable!("set above")))
    }

    /// The mass and mass centre: from the body about G when it is derived (or the route is
    /// about G), else from the parts alone (the route about O needs no inertia about G).
    fn mass_centre(&mut self, at: Span) -> Result<MassCentre, Diagnostic> {
        if self.body.is_some() || !self.scene.about_fixed_point() {
            let body = self.body(at)?;
            return Ok(MassCentre {
                mass: body.mass.clone(),
                centroid: body.centroid.clone(),
            });
        }
        if self.centre.is_none() {
            let parts = self.parts(at)?;
            let (centre, derivation) = mass_centre(&parts).map_err(self.mass_error(at))?;
            self.plan.extend(derivation.steps);
            self.centre = Some(centre);
        }
        Ok(self
            .centre
            .clone()
            .unwrap_or_else(|| unreachable!("set above")))
    }

    /// `[I_O]`: the moments and products of inertia about the fixed point O.
    fn inertia_about_o(&mut self, at: Span) -> Result<InertiaTensor, Diagnostic> {
        if self.inertia_o.is_none() {
            let parts = self.parts(at)?;
            let (inertia, derivation) =
                inertia_about_fixed_point(&parts).map_err(self.algebra(at))?;
            self.plan.extend(derivation.steps);
            self.inertia_o = Some(inertia);
        }
        Ok(self
            .inertia_o
            .clone()
            .unwrap_or_else(|| unreachable!("set above")))
    }

    fn kinematics(&mut self, at: Span) -> Result<&SolvedConstraints, Diagnostic> {
        if self.kinematics.is_none() {
            // The mass centre matters only to a velocity constraint on a body without a
            // fixed point; the body is not derived for scenes that do not need it.
            let scene = self.scene;
            let needs_centroid = !scene.fixed_point
                && scene.vbar.is_some()
                && scene
                    .constraints
                    .iter()
                    .any(|c| matches!(c.kind, ConstraintKind::VelocityZero(_)));
            let centroid = if needs_centroid {
                Some(self.body(at)?.centroid.clone())
            } else {
                None
            };
            let (kinematics, steps) = solve_constraints(self.scene, centroid.as_ref(), at)?;
            self.plan.extend(steps);
            self.kinematics = Some(kinematics);
        }
        Ok(self
            .kinematics
            .as_ref()
            .unwrap_or_else(|| unreachable!("set above")))
    }

    /// Substitutes the unknowns already solved from the kinematic constraints.
    fn known(&self, e: &Expr) -> Result<Expr, AlgebraError> {
        match &self.kinematics {
            Some(k) => k.substitute(e),
            None => Ok(e.clone()),
        }
    }

    fn known_vector(&self, v: &Vector, at: Span) -> Result<Vector, Diagnostic> {
        let known: Result<Vec<Expr>, AlgebraError> = v.iter().map(|c| self.known(c)).collect();
        Ok(Vector::from_iterator(known.map_err(self.algebra(at))?))
    }

    fn vbar(&mut self, at: Span) -> Result<Vector, Diagnostic> {
        if let Some(v) = &self.vbar {
            return Ok(v.clone());
        }
        let omega = self.kinematics(at)?.omega.clone();
        // The body comes first in the plan, as in the chapter's solutions.
        let centroid = self.mass_centre(at)?.centroid;
        let v = match (&self.scene.vbar, self.scene.fixed_point) {
            (Some(given), _) => {
                let v = self.known_vector(given, at)?;
                // Stated in unknowns (solved by impulse and momentum, say), it is not given.
                let title = match given
                    .iter()
                    .any(|c| c.has_symbol_where(&|s| self.scene.is_unknown(s)))
                {
                    true => "velocity of the mass centre (as stated, in the unknowns)",
                    false => "velocity of the mass centre (given)",
                };
                self.plan.push(Step {
                    vectors: Vec::new(),
                    table: None,
                    title: title.into(),
                    relations: Relation::components("vbar", &v),
                });
                v
            }
            (None, true) => {
                let d = velocity_of_mass_centre(&omega, &centroid).map_err(self.algebra(at))?;
                self.record_vector(d)
            }
            (None, false) => {
                return Err(self.fail(
                    at,
                    "the velocity of the mass centre is not given",
                    "add 'fixed point' (O is fixed) or 'vbar = ...'",
                ))
            }
        };
        self.vbar = Some(v.clone());
        Ok(v)
    }

    fn abar(&mut self, at: Span) -> Result<Vector, Diagnostic> {
        if let Some(a) = &self.abar {
            return Ok(a.clone());
        }
        let a = if let Some(given) = &self.scene.abar {
            self.kinematics(at)?;
            let a = self.known_vector(given, at)?;
            self.plan.push(Step {
                vectors: Vec::new(),
                table: None,
                title: "acceleration of the mass centre (given)".into(),
                relations: Relation::components("abar", &a),
            });
            a
        } else if self.scene.fixed_point {
            let k = self.kinematics(at)?;
            let (omega, omega_dot, frame) =
                (k.omega.clone(), k.omega_dot.clone(), k.frame_rate.clone());
            let centroid = self.mass_centre(at)?.centroid;
            let d = acceleration_of_mass_centre(&omega, &omega_dot, &frame, &centroid)
                .map_err(self.algebra(at))?;
            // The step shows α, then ā: the acceleration is its last three relations.
            Vector::from_iterator(self.record(d).split_off(3))
        } else {
            return Err(self.fail(
                at,
                "the acceleration of the mass centre needs a fixed point",
                "add 'fixed point' when the body turns about the origin O, or give 'abar = ...'",
            ));
        };
        self.abar = Some(a.clone());
        Ok(a)
    }

    fn h_g(&mut self, at: Span) -> Result<Vector, Diagnostic> {
        if let Some(h) = &self.h_g {
            return Ok(h.clone());
        }
        let omega = self.kinematics(at)?.omega.clone();
        let inertia = self.body(at)?.inertia.clone();
        let d = angular_momentum(&inertia, &omega, "G").map_err(self.algebra(at))?;
        let h = self.record_vector(d);
        self.h_g = Some(h.clone());
        Ok(h)
    }

    /// About O: `{H_O} = [I_O]{ω}`; about G: `H_O = H_G + r̄ × m v̄`.
    fn h_o(&mut self, at: Span) -> Result<Vector, Diagnostic> {
        if self.scene.about_fixed_point() {
            let omega = self.kinematics(at)?.omega.clone();
            let inertia = self.inertia_about_o(at)?;
            let d = angular_momentum(&inertia, &omega, "O").map_err(self.algebra(at))?;
            return Ok(self.record_vector(d));
        }
        let h_g = self.h_g(at)?;
        let v = self.vbar(at)?;
        let body = self.body(at)?;
        let d = angular_momentum_about_point(&h_g, &body.centroid, &body.mass, &v)
            .map_err(self.algebra(at))?;
        Ok(self.record_vector(d))
    }

    /// About O: `T = ½{ω}ᵀ[I_O]{ω}`; about G: `T = T_trans + T_rot`.
    fn kinetic_energy(&mut self, at: Span) -> Result<Expr, Diagnostic> {
        if !self.scene.about_fixed_point() {
            return Ok(self.energy_split(at)?[2].clone());
        }
        let omega = self.kinematics(at)?.omega.clone();
        let inertia = self.inertia_about_o(at)?;
        let d = kinetic_energy(&inertia, &omega, None).map_err(self.algebra(at))?;
        Ok(self.record(d)[0].clone())
    }

    /// `T_trans = ½ m v̄²`, `T_rot = ½{ω}ᵀ[Ī]{ω}` and their sum `T`, about G (with a fixed
    /// point too, `v̄ = ω × r̄`).
    fn energy_split(&mut self, at: Span) -> Result<[Expr; 3], Diagnostic> {
        if let Some(split) = &self.energy_split {
            return Ok(split.clone());
        }
        let omega = self.kinematics(at)?.omega.clone();
        // The body about G first: v̄ then takes its mass centre (not the parts' again).
        self.body(at)?;
        let v = self.vbar(at)?;
        let fixed_point = self.scene.fixed_point;
        let body = self.body(at)?;
        let d = kinetic_energy_split(&body.inertia, &omega, &body.mass, &v, fixed_point)
            .map_err(self.algebra(at))?;
        let parts: Vec<Expr> = d.steps[0].relations.iter().map(|r| r.rhs.clone()).collect();
        let t = self.record(d).remove(0);
        let split = [parts[0].clone(), parts[1].clone(), t];
        self.energy_split = Some(split.clone());
        Ok(split)
    }

    /// `Ḣ_O` about the fixed point O: `[I_O]{ω̇} + Ω × H_O`, or with `about G`,
    /// `Ḣ_G + r̄ × m ā`. Without a fixed point it is refused: O is then no fixed point.
    fn hdot_o(&mut self, at: Span) -> Result<Vector, Diagnostic> {
        if !self.scene.fixed_point {
            return Err(self.fail(
                at,
                "Hdot_O is the rate of change of the angular momentum about a fixed point O, and this scene's origin O is not fixed",
                "add 'fixed point' when the body turns about the origin O, or ask for Hdot_G (sum M_G = Hdot_G holds in any motion)",
            ));
        }
        if let Some(h) = &self.hdot_o {
            return Ok(h.clone());
        }
        if self.scene.about_fixed_point() {
            return self.rate_of_angular_momentum(at, true);
        }
        let hdot_g = self.rate_of_angular_momentum(at, false)?;
        let a = self.abar(at)?;
        let body = self.mass_centre(at)?;
        let d = rate_of_angular_momentum_about_point(&hdot_g, &body.centroid, &body.mass, &a)
            .map_err(self.algebra(at))?;
        let hdot = self.record_vector(d);
        self.hdot_o = Some(hdot.clone());
        Ok(hdot)
    }

    /// `Ḣ = [I]{ω̇} + Ω × H` about G (`[Ī]`) or about O (`[I_O]`).
    fn rate_of_angular_momentum(&mut self, at: Span, about_o: bool) -> Result<Vector, Diagnostic> {
        let cached = if about_o { &self.hdot_o } else { &self.hdot_g };
        if let Some(h) = cached {
            return Ok(h.clone());
        }
        let k = self.kinematics(at)?;
        let (omega, omega_dot, frame) =
            (k.omega.clone(), k.omega_dot.clone(), k.frame_rate.clone());
        let (inertia, point) = if about_o {
            (self.inertia_about_o(at)?, "O")
        } else {
            (self.body(at)?.inertia.clone(), "G")
        };
        let d = rate_of_angular_momentum(&inertia, &omega, &omega_dot, &frame, point)
            .map_err(self.algebra(at))?;
        let hdot = self.record_vector(d);
        let cache = if about_o {
            &mut self.hdot_o
        } else {
            &mut self.hdot_g
        };
        *cache = Some(hdot.clone());
        Ok(hdot)
    }
}
