//! The demand-driven analysis of a scene: each request pulls only the derivations it needs,
//! each derivation is done at most once, and the order in which they were done is the plan.
//!
//! | request | pulls |
//! |---|---|
//! | `omega` | kinematics (constraints solved) |
//! | `vbar`, `mvbar` | kinematics, motion of the mass centre |
//! | `abar`, `mabar` | kinematics, acceleration of the mass centre |
//! | `H_G` | inertia, kinematics, angular momentum |
//! | `H_O` | inertia, kinematics, angular momentum, motion of the mass centre |
//! | `T` | inertia, kinematics, motion of the mass centre, kinetic energy |
//! | `Hdot_G` | inertia, kinematics, rate of change of angular momentum |
//! | an unknown | impulse and momentum (a scene with impulses), else the equations of motion; then the solution |

use super::model::{ConstraintKind, Request, Scene, Span};
use crate::algebra::linear_solve::{solve_linear, Solution, SolveError};
use crate::algebra::{Expr, Symbol, Vector};
use crate::mechanics::derivation::{Relation, Step};
use crate::mechanics::inertia::InertiaTensor;
use crate::parse::Diagnostic;
use crate::print::Axis;
use std::collections::HashMap;

/// A derived quantity: scalar or vector, with the name it was asked by.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Scalar(Expr),
    Vector(Vector),
}

/// The outcome: the plan (steps in the order done) and each request's result.
#[derive(Debug, Clone)]
pub struct Analysis {
    pub plan: Vec<Step>,
    pub results: Vec<(Request, Value)>,
}

/// The body as a whole: mass, mass centre, inertia about G.
struct Body {
    mass: Expr,
    centroid: Vector,
    inertia: InertiaTensor,
}

struct Kinematics {
    omega: Vector,
    omega_dot: Vector,
    frame_rate: Vector,
    /// Values of unknowns fixed by the kinematic constraints.
    solved: Vec<(Symbol, Expr)>,
}

/// Lazily computed pieces; `plan` records each as it is done.
struct Analyser<'a> {
    scene: &'a Scene,
    plan: Vec<Step>,
    body: Option<Body>,
    kinematics: Option<Kinematics>,
    vbar: Option<Vector>,
    abar: Option<Vector>,
    h_g: Option<Vector>,
    hdot_g: Option<Vector>,
    unknowns: Option<HashMap<Symbol, Expr>>,
}

/// Runs the analysis for the scene's requests.
pub fn analyse(scene: &Scene) -> Result<Analysis, Diagnostic> {
    let mut a = Analyser::new(scene);
    let mut results = Vec::new();
    for request in &scene.requests {
        let value = a.request(request)?;
        let value = a.in_givens(request, value)?;
        results.push((request.clone(), value));
    }
    Ok(Analysis {
        plan: a.plan,
        results,
    })
}

/// The body's mass, mass centre (from O) and centroidal inertia, for callers that need the
/// body but no derivation (the simulator).
pub fn centroidal_body(scene: &Scene) -> Result<(Expr, Vector, InertiaTensor), Diagnostic> {
    let mut a = Analyser::new(scene);
    let whole_file = Request::at("body", Span { start: 0, end: 0 });
    let body = a.body(&whole_file)?;
    Ok((
        body.mass.clone(),
        body.centroid.clone(),
        body.inertia.clone(),
    ))
}

fn zero_vector() -> Vector {
    Vector::from_element(Expr::zero())
}

fn expand_vector(v: &Vector) -> Vector {
    v.map(|e| e.expand().unwrap_or(e))
}

fn components(name: &str, v: &Vector) -> Vec<Relation> {
    Relation::components(name, v)
}

impl<'a> Analyser<'a> {
    fn new(scene: &'a Scene) -> Analyser<'a> {
        Analyser {
            scene,
            plan: Vec::new(),
            body: None,
            kinematics: None,
            vbar: None,
            abar: None,
            h_g: None,
            hdot_g: None,
            unknowns: None,
        }
    }

    fn fail(
        &self,
        request: &Request,
        message: impl Into<String>,
        help: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic::at(
            &self.scene.source_name,
            &self.scene.source,
            request.span.start,
            request.span.end,
            message,
        )
        .with_help(help)
    }

    fn request(&mut self, r: &Request) -> Result<Value, Diagnostic> {
        Ok(match r.name.as_str() {
            "omega" => Value::Vector(self.kinematics(r)?.omega.clone()),
            "vbar" => Value::Vector(self.vbar(r)?),
            "mvbar" | "m*vbar" => {
                let m = self.body(r)?.mass.clone();
                Value::Vector(expand_vector(&self.vbar(r)?.map(|v| &m * &v)))
            }
            "abar" => Value::Vector(self.abar(r)?),
            "mabar" | "m*abar" => {
                let m = self.body(r)?.mass.clone();
                Value::Vector(expand_vector(&self.abar(r)?.map(|v| &m * &v)))
            }
            "H_G" => Value::Vector(self.h_g(r)?),
            "H_O" => Value::Vector(self.h_o(r)?),
            "T" => Value::Scalar(self.kinetic_energy(r)?),
            "Hdot_G" => Value::Vector(self.hdot_g(r)?),
            name => {
                let s = Symbol::new(name);
                if !self.scene.is_unknown(s) {
                    return Err(self.fail(
                        r,
                        format!("cannot find '{name}'"),
                        "ask for omega, vbar, mvbar, abar, mabar, H_G, H_O, T, Hdot_G, or a declared unknown",
                    ));
                }
                Value::Scalar(self.unknown(r, s)?)
            }
        })
    }

    /// A result expressed in the givens alone: unknowns in it are solved and substituted.
    fn in_givens(&mut self, r: &Request, value: Value) -> Result<Value, Diagnostic> {
        let mut exprs: Vec<Expr> = match &value {
            Value::Scalar(e) => vec![e.clone()],
            Value::Vector(v) => v.iter().cloned().collect(),
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
            solved.push((u, self.unknown(r, u)?));
        }
        let lookup = |s: Symbol| solved.iter().find(|(u, _)| *u == s).map(|(_, v)| v.clone());
        for e in exprs.iter_mut() {
            *e = e
                .subs(&lookup)
                .and_then(|x| x.expand())
                .map_err(|err| self.fail(r, err.to_string(), "simplify the scene"))?;
        }
        Ok(match value {
            Value::Scalar(_) => Value::Scalar(exprs.remove(0)),
            Value::Vector(_) => Value::Vector(Vector::from_iterator(exprs)),
        })
    }

    fn body(&mut self, r: &Request) -> Result<&Body, Diagnostic> {
        if self.body.is_none() {
            let parts = &self.scene.parts;
            if parts.is_empty() {
                return Err(self.fail(
                    r,
                    "the scene has no body",
                    "add a line such as 'body disk(r) mass m at (L, 0, 0)'",
                ));
            }
            let mass = Expr::add_all(parts.iter().map(|p| p.mass.clone()));
            let moment: Vector = parts.iter().fold(zero_vector(), |acc, p| {
                acc + p.position.map(|x| &p.mass * &x)
            });
            let centroid = expand_vector(&moment.map(|x| &x / &mass));
            let own = |p: &super::model::Part| {
                p.shape
                    .centroidal_inertia(&p.mass)
                    .and_then(|i| i.rotated(&p.rotation))
                    .map_err(|e| self.fail(r, e.to_string(), "simplify the scene"))
            };
            let inertia = if parts.len() == 1 {
                own(&parts[0])?
            } else {
                let about_o = parts
                    .iter()
                    .map(|p| Ok(own(p)?.parallel_axis(&p.mass, &p.position)))
                    .collect::<Result<Vec<_>, Diagnostic>>()?
                    .into_iter()
                    .reduce(|a, b| a.add(&b))
                    .unwrap_or_else(|| {
                        InertiaTensor::diagonal([Expr::zero(), Expr::zero(), Expr::zero()])
                    });
                about_o.parallel_axis(&-&mass, &centroid)
            };
            let inertia = InertiaTensor {
                moments: inertia.moments.map(|e| e.expand().unwrap_or(e)),
                products: inertia.products.map(|e| e.expand().unwrap_or(e)),
            };
            let s = Expr::symbol;
            self.plan.push(Step {
                title: "mass, mass centre and centroidal inertia of the body (products of inertia positive, ∫xy dm)".into(),
                relations: [
                    vec![Relation::new(s("m_body"), mass.clone(), Axis::X)],
                    components("rbar", &centroid),
                    [("I_x", 0), ("I_y", 1), ("I_z", 2)]
                        .map(|(n, k)| Relation::new(s(n), inertia.moments[k].clone(), Axis::X))
                        .to_vec(),
                    [("I_xy", 0), ("I_yz", 1), ("I_xz", 2)]
                        .map(|(n, k)| Relation::new(s(n), inertia.products[k].clone(), Axis::X))
                        .to_vec(),
                ]
                .concat(),
            });
            self.body = Some(Body {
                mass,
                centroid,
                inertia,
            });
        }
        Ok(self
            .body
            .as_ref()
            .unwrap_or_else(|| unreachable!("set above")))
    }

    fn kinematics(&mut self, r: &Request) -> Result<&Kinematics, Diagnostic> {
        if self.kinematics.is_none() {
            let scene = self.scene;
            let omega = scene.omega.clone().unwrap_or_else(zero_vector);
            let mut equations: Vec<Expr> = Vec::new();
            // The constraint each equation came from, to locate errors.
            let mut sources: Vec<Span> = Vec::new();
            let mut shown: Vec<Relation> = Vec::new();
            for c in &scene.constraints {
                let at = Request::at("constraint", c.span);
                match &c.kind {
                    ConstraintKind::VelocityZero(point) => {
                        let base = if scene.fixed_point {
                            zero_vector()
                        } else {
                            let vbar = scene.vbar.clone().ok_or_else(|| {
                                self.fail(
                                    &at,
                                    "a velocity constraint needs the motion of the body",
                                    "add 'fixed point' or 'vbar = ...'",
                                )
                            })?;
                            let centroid = self.body(r)?.centroid.clone();
                            vbar - omega.cross(&centroid)
                        };
                        let v = expand_vector(&(base + omega.cross(point)));
                        for (k, c) in v.iter().enumerate() {
                            if !c.is_zero() {
                                equations.push(c.clone());
                                sources.push(at.span);
                                shown.push(Relation::new(
                                    c.clone(),
                                    Expr::zero(),
                                    [Axis::X, Axis::Y, Axis::Z][k],
                                ));
                            }
                        }
                    }
                    ConstraintKind::Equation(lhs, rhs) => {
                        equations.push(lhs - rhs);
                        sources.push(at.span);
                        shown.push(Relation::new(lhs.clone(), rhs.clone(), Axis::X));
                    }
                }
            }
            let constrained: Vec<Symbol> = scene
                .unknowns
                .iter()
                .map(|u| u.0)
                .filter(|u| equations.iter().any(|e| e.contains(*u)))
                .collect();
            let solved = if equations.is_empty() {
                vec![]
            } else {
                let Solution {
                    values: solved,
                    free,
                } = solve_linear(&equations, &constrained).map_err(|e| {
                    // An equation that cannot be used is reported at its constraint.
                    let span = match &e {
                        SolveError::Inconsistent { equation, .. }
                        | SolveError::Nonlinear { equation, .. } => sources.get(*equation).copied(),
                        _ => None,
                    };
                    match span {
                        Some(span) => self.solve_error(&Request::at("constraint", span), e),
                        None => self.solve_error(r, e),
                    }
                })?;
                if !free.is_empty() {
                    return Err(self.solve_error(r, SolveError::UnderDetermined(free)));
                }
                let mut relations = shown;
                relations.extend(
                    solved
                        .iter()
                        .map(|(u, v)| Relation::new(Expr::sym(*u), v.clone(), Axis::X)),
                );
                self.plan.push(Step {
                    title: "kinematic constraints, solved for the unknown rates".into(),
                    relations,
                });
                solved
            };
            let subst = |v: &Vector| -> Vector {
                expand_vector(&v.map(|e| {
                    e.subs(&|s| solved.iter().find(|(u, _)| *u == s).map(|(_, x)| x.clone()))
                        .unwrap_or(e)
                }))
            };
            let omega = subst(&omega);
            let omega_dot = subst(&scene.omega_dot.clone().unwrap_or_else(zero_vector));
            let frame_rate = subst(&scene.frame_rate.clone().unwrap_or_else(|| omega.clone()));
            let mut relations = components("omega", &omega);
            if scene.frame_rate.is_some() {
                relations.extend(components("Omega", &frame_rate));
            }
            self.plan.push(Step {
                title: if scene.frame_rate.is_some() {
                    "angular velocity ω of the body and Ω of the frame (Ω ≠ ω: [I] is constant in this frame)".into()
                } else {
                    "angular velocity ω (axes fixed in the body, Ω = ω)".into()
                },
                relations,
            });
            self.kinematics = Some(Kinematics {
                omega,
                omega_dot,
                frame_rate,
                solved,
            });
        }
        Ok(self
            .kinematics
            .as_ref()
            .unwrap_or_else(|| unreachable!("set above")))
    }

    fn solve_error(&self, r: &Request, e: SolveError) -> Diagnostic {
        let help = match &e {
            SolveError::UnderDetermined(_) => "give more conditions, or fewer unknowns",
            SolveError::Inconsistent { .. } => "remove a condition or an unknown that conflicts",
            _ => "unknowns must appear linearly",
        };
        self.fail(r, e.to_string(), help)
    }

    /// Substitutes the unknowns already solved from the kinematic constraints.
    fn known(&self, e: &Expr) -> Expr {
        match &self.kinematics {
            Some(k) if !k.solved.is_empty() => e
                .subs(&|s| {
                    k.solved
                        .iter()
                        .find(|(u, _)| *u == s)
                        .map(|(_, x)| x.clone())
                })
                .and_then(|x| x.expand())
                .unwrap_or_else(|_| e.clone()),
            _ => e.clone(),
        }
    }

    fn vbar(&mut self, r: &Request) -> Result<Vector, Diagnostic> {
        if self.vbar.is_none() {
            let omega = self.kinematics(r)?.omega.clone();
            let centroid = self.body(r)?.centroid.clone();
            let v = match (&self.scene.vbar, self.scene.fixed_point) {
                (Some(v), _) => v.map(|c| self.known(&c)),
                (None, true) => expand_vector(&omega.cross(&centroid)),
                (None, false) => {
                    return Err(self.fail(
                        r,
                        "the velocity of the mass centre is not given",
                        "add 'fixed point' (O is fixed) or 'vbar = ...'",
                    ))
                }
            };
            self.plan.push(Step {
                title: if self.scene.vbar.is_some() {
                    "velocity of the mass centre (given)".into()
                } else {
                    "velocity of the mass centre, v̄ = ω × r̄ (O fixed)".into()
                },
                relations: components("vbar", &v),
            });
            self.vbar = Some(v);
        }
        Ok(self.vbar.clone().unwrap_or_else(zero_vector))
    }

    fn abar(&mut self, r: &Request) -> Result<Vector, Diagnostic> {
        if self.abar.is_none() {
            if let Some(given) = &self.scene.abar {
                let a = given.map(|c| self.known(&c));
                self.kinematics(r)?;
                self.plan.push(Step {
                    title: "acceleration of the mass centre (given)".into(),
                    relations: components("abar", &a),
                });
                self.abar = Some(a);
                return Ok(self.abar.clone().unwrap_or_else(zero_vector));
            }
            if !self.scene.fixed_point {
                return Err(self.fail(
                    r,
                    "the acceleration of the mass centre needs a fixed point",
                    "add 'fixed point' when the body turns about the origin O, or give 'abar = ...'",
                ));
            }
            let k = self.kinematics(r)?;
            let (omega, omega_dot, frame) =
                (k.omega.clone(), k.omega_dot.clone(), k.frame_rate.clone());
            let centroid = self.body(r)?.centroid.clone();
            let alpha = expand_vector(&(omega_dot + frame.cross(&omega)));
            let a = expand_vector(&(alpha.cross(&centroid) + omega.cross(&omega.cross(&centroid))));
            self.plan.push(Step {
                title: "acceleration of the mass centre, ā = α × r̄ + ω × (ω × r̄), α = (ω̇)_frame + Ω × ω".into(),
                relations: [components("alpha", &alpha), components("abar", &a)].concat(),
            });
            self.abar = Some(a);
        }
        Ok(self.abar.clone().unwrap_or_else(zero_vector))
    }

    fn h_g(&mut self, r: &Request) -> Result<Vector, Diagnostic> {
        if self.h_g.is_none() {
            let omega = self.kinematics(r)?.omega.clone();
            let h = expand_vector(&(self.body(r)?.inertia.matrix() * omega));
            self.plan.push(Step {
                title: "angular momentum about G, {H_G} = [I]{ω}".into(),
                relations: components("H", &h),
            });
            self.h_g = Some(h);
        }
        Ok(self.h_g.clone().unwrap_or_else(zero_vector))
    }

    fn h_o(&mut self, r: &Request) -> Result<Vector, Diagnostic> {
        let h_g = self.h_g(r)?;
        let v = self.vbar(r)?;
        let body = self.body(r)?;
        let (m, centroid) = (body.mass.clone(), body.centroid.clone());
        let h_o = expand_vector(&(h_g + centroid.cross(&v.map(|x| &m * &x))));
        self.plan.push(Step {
            title: "angular momentum about O, H_O = H_G + r̄ × m v̄".into(),
            relations: components("H", &h_o),
        });
        Ok(h_o)
    }

    fn kinetic_energy(&mut self, r: &Request) -> Result<Expr, Diagnostic> {
        let omega = self.kinematics(r)?.omega.clone();
        let v = self.vbar(r)?;
        let body = self.body(r)?;
        let (m, inertia) = (body.mass.clone(), body.inertia.clone());
        let d = crate::mechanics::kinetic_energy::kinetic_energy(&inertia, &omega, Some((&m, &v)))
            .map_err(|e| self.fail(r, e.to_string(), "simplify the scene"))?;
        let t = d.result()[0].rhs.clone();
        self.plan.push(Step {
            title: "kinetic energy, T = ½ m v̄² + ½ {ω}ᵀ[I]{ω}".into(),
            relations: vec![Relation::new(Expr::symbol("T"), t.clone(), Axis::X)],
        });
        Ok(t)
    }

    fn hdot_g(&mut self, r: &Request) -> Result<Vector, Diagnostic> {
        if self.hdot_g.is_none() {
            let k = self.kinematics(r)?;
            let (omega, omega_dot, frame) =
                (k.omega.clone(), k.omega_dot.clone(), k.frame_rate.clone());
            let inertia = self.body(r)?.inertia.clone();
            let d = crate::mechanics::rotating_frame::rate_of_angular_momentum(
                &inertia, &omega, &omega_dot, &frame,
            )
            .map_err(|e| self.fail(r, e.to_string(), "simplify the scene"))?;
            let hdot = Vector::from_iterator(d.result().iter().map(|x| x.rhs.clone()));
            self.plan.push(Step {
                title: "rate of change of angular momentum, Ḣ_G = [I]{ω̇} + Ω × H_G".into(),
                relations: components("Hdot", &hdot),
            });
            self.hdot_g = Some(hdot);
        }
        Ok(self.hdot_g.clone().unwrap_or_else(zero_vector))
    }

    fn unknown(&mut self, r: &Request, s: Symbol) -> Result<Expr, Diagnostic> {
        if let Some(v) = self.kinematics(r)?.solved.iter().find(|(u, _)| *u == s) {
            return Ok(v.1.clone());
        }
        if self.unknowns.is_none() {
            let equations = if self.scene.impulses.is_empty() {
                self.equations_of_motion(r)?
            } else {
                self.impulse_momentum(r)?
            };
            let wanted: Vec<Symbol> = self
                .scene
                .unknowns
                .iter()
                .map(|u| u.0)
                .filter(|u| equations.iter().any(|e| e.contains(*u)))
                .collect();
            let Solution {
                values: solution,
                free,
            } = solve_linear(&equations, &wanted).map_err(|e| self.solve_error(r, e))?;
            self.plan.push(Step {
                title: "solve the equations for the unknowns".into(),
                relations: solution
                    .iter()
                    .map(|(u, v)| Relation::new(Expr::sym(*u), v.clone(), Axis::X))
                    .collect(),
            });
            let mut map: HashMap<Symbol, Expr> = solution.into_iter().collect();
            for f in free {
                map.remove(&f);
            }
            self.unknowns = Some(map);
        }
        self.unknowns
            .as_ref()
            .and_then(|m| m.get(&s).cloned())
            .ok_or_else(|| self.solve_error(r, SolveError::UnderDetermined(vec![s])))
    }

    /// `ΣF = m ā` and `ΣM_P = Ḣ_G + r̄_{G/P} × m ā` about P = O (fixed point) or G.
    fn equations_of_motion(&mut self, r: &Request) -> Result<Vec<Expr>, Diagnostic> {
        let a = self.abar(r)?;
        let hdot = self.hdot_g(r)?;
        let body = self.body(r)?;
        let (m, centroid) = (body.mass.clone(), body.centroid.clone());
        let about_o = self.scene.fixed_point;
        let reference = if about_o {
            zero_vector()
        } else {
            centroid.clone()
        };
        let forces = self
            .scene
            .forces
            .iter()
            .fold(zero_vector(), |acc, f| acc + f.value.clone());
        let moments = self.scene.forces.iter().fold(zero_vector(), |acc, f| {
            acc + (f.point.clone() - reference.clone()).cross(&f.value)
        }) + self
            .scene
            .couples
            .iter()
            .fold(zero_vector(), |acc, c| acc + c.clone());
        let ma = a.map(|x| &m * &x);
        let rate = expand_vector(&(hdot + (centroid - reference).cross(&ma)));
        let (forces, moments, ma) = (
            expand_vector(&forces),
            expand_vector(&moments),
            expand_vector(&ma),
        );
        let point = if about_o { "O" } else { "G" };
        let mut relations = Vec::new();
        let axes = [Axis::X, Axis::Y, Axis::Z];
        for k in 0..3 {
            relations.push(Relation::new(forces[k].clone(), ma[k].clone(), axes[k]));
        }
        for k in 0..3 {
            relations.push(Relation::new(moments[k].clone(), rate[k].clone(), axes[k]));
        }
        relations.retain(|r| !(r.lhs.is_zero() && r.rhs.is_zero()));
        self.plan.push(Step {
            title: format!("equations of motion: ΣF = m ā (x, y, z), then ΣM_{point} = Ḣ_G + r̄ × m ā (x, y, z)"),
            relations,
        });
        let mut equations: Vec<Expr> = (0..3).map(|k| &forces[k] - &ma[k]).collect();
        equations.extend((0..3).map(|k| &moments[k] - &rate[k]));
        Ok(equations
            .into_iter()
            .map(|e| self.known(&e))
            .filter(|e| !e.is_zero())
            .collect())
    }

    /// `m v̄₂ = Σ F Δt` and `[I]{ω₂} = Σ r × F Δt` about G, for an impact from rest.
    fn impulse_momentum(&mut self, r: &Request) -> Result<Vec<Expr>, Diagnostic> {
        let v = self.vbar(r)?;
        let h = self.h_g(r)?;
        let body = self.body(r)?;
        let (m, centroid) = (body.mass.clone(), body.centroid.clone());
        let linear = expand_vector(
            &self
                .scene
                .impulses
                .iter()
                .fold(zero_vector(), |acc, (imp, _)| acc + imp.clone()),
        );
        let angular = expand_vector(
            &self
                .scene
                .impulses
                .iter()
                .fold(zero_vector(), |acc, (imp, point)| {
                    acc + (point.clone() - centroid.clone()).cross(imp)
                }),
        );
        let mv = expand_vector(&v.map(|x| &m * &x));
        let axes = [Axis::X, Axis::Y, Axis::Z];
        let mut relations = Vec::new();
        for k in 0..3 {
            relations.push(Relation::new(linear[k].clone(), mv[k].clone(), axes[k]));
        }
        for k in 0..3 {
            relations.push(Relation::new(angular[k].clone(), h[k].clone(), axes[k]));
        }
        relations.retain(|r| !(r.lhs.is_zero() && r.rhs.is_zero()));
        self.plan.push(Step {
            title: "impulse and momentum from rest: Σ F Δt = m v̄ (x, y, z), then Σ r × F Δt = H_G (x, y, z)".into(),
            relations,
        });
        let mut equations: Vec<Expr> = (0..3).map(|k| &linear[k] - &mv[k]).collect();
        equations.extend((0..3).map(|k| &angular[k] - &h[k]));
        Ok(equations
            .into_iter()
            .map(|e| self.known(&e))
            .filter(|e| !e.is_zero())
            .collect())
    }
}
