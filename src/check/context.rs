//! What a claim is checked against: the names it may use and what each stands for.
//!
//! - A general body in body-fixed axes (Ω = ω), the symbols of `kinetics derive --general`:
//!   `H_x H_y H_z` (and the vector `H_G`) are `{H_G} = [I]{ω}`, `H_O = H_G + r̄ × m v̄`, `T`
//!   the kinetic energy with `½ m v̄²`, `M_x` (or `SumM_x`) the right sides of Euler's
//!   equations, `Hdot_x` the rate `[I]{ω̇} + ω × H_G`; `--principal` drops the products of
//!   inertia; `v` is the speed |v̄|, and `omega_x`, `alpha_x`, `a_x`, `v_x` spell `w_x`, `wdot_x`,
//!   `wdot_x`, `vbar_x`. Other names are free symbols, for claims of pure algebra, except a name that
//!   misspells one of the chapter's (`I_xx`, `H_w`), which is refused with a suggestion.
//! - Rotation about the fixed axis z (`--fixed-axis`): `SumM_x SumM_y SumM_z` (also `M_x`)
//!   the moments of §18.7 in `w` and `alpha`, and the dynamic bearing reactions.
//! - A scene: its givens, its unknowns (standing for their solved values) and every quantity
//!   its analysis can derive (`omega`, `vbar`, `H_G`, `H_O`, `T`, `Hdot_G`, ...); any other
//!   name is unknown.
//!
//! Every derived value comes from the mechanics functions `derive` and `solve` print (the
//! catalogue, or the scene's analysis), never from a copy.

mod hidden_units;
mod suggestion;

use crate::algebra::work::Budget;
use crate::algebra::{AlgebraError, Domains, Expr, Symbol, Vector};
use crate::mechanics::catalogue::derive_general;
use crate::mechanics::slip::Slip;
use crate::parse::claim::Name;
use crate::parse::Follows;
use crate::scene::analysis::values_of;
use crate::scene::model::{Quantity, Request, Span};
use crate::scene::unit_system::UnitSystem;
use crate::scene::units::{Dimension, Dimensions};
use crate::scene::units_in_math::{marker, marker_dimension};
use crate::scene::{Scene, Value};
use std::collections::HashMap;
use std::sync::{Arc, OnceLock};

/// What a name stands for in a context.
#[derive(Debug, Clone)]
enum Meaning {
    /// A derived quantity's value (a vector as `a i + b j + c k`).
    Derived(Expr),
    /// Another spelling of symbols the context knows (`omega_x` for `w_x`, `v` for
    /// `√(vbar_x² + vbar_y² + vbar_z²)`, `omega` for `w_x i + w_y j + w_z k`): not derived.
    Alias(Expr),
    /// A scene quantity with a value in each solution of the scene's equations (a top's
    /// slow and fast precession), in the order the analysis gives them.
    Solutions(Vec<Expr>),
    /// A scene quantity its analysis could not derive: why.
    Underivable(String),
}

/// The names a claim may use, what each stands for, and the symbols' dimensions and domains.
#[derive(Debug, Clone)]
pub struct Context {
    /// In words, for the report: "a general body in body-fixed axes".
    pub description: String,
    meanings: HashMap<String, Meaning>,
    /// The symbols this context knows, with their dimensions.
    dimensions: Dimensions,
    /// Whether a name the context does not know is a free symbol (no scene) or an error.
    free_symbols: bool,
    domains: Domains,
    /// The exact values (in the scene's unit system) of a scene's givens that have one.
    values: HashMap<Symbol, Expr>,
    /// The unit system of the values, which a number written with a unit in a claim is
    /// brought into: SI without a scene.
    unit_system: UnitSystem,
    /// How close a claim written in numbers must come to the exact value, relative to it.
    relative_tolerance: f64,
    /// Where the meanings come from, to derive them again with a slip (none in a context
    /// derived with one).
    source: Option<Source>,
    /// The context derived with each slip of [`Slip::ALL`], when a claim first needs it.
    slipped: Arc<[OnceLock<Option<Context>>; Slip::ALL.len()]>,
    /// Names that are another spelling of one quantity (`M_x` of `SumM_x`), by the spelling.
    spellings: HashMap<String, String>,
    /// A student's world ([`Context::with_names`]): its values come from their lines, whose
    /// numbers are in the unit system without their units, so a value may mix dimensions
    /// (`-750 m c` for α = 3000 rad/s² put in): no claim is refused for its dimensions here.
    world: bool,
}

/// Where a context's meanings come from.
#[derive(Debug, Clone)]
enum Source {
    General { principal: bool, fixed_point: bool },
    FixedAxis,
    Scene(Arc<Scene>),
}

/// The relative tolerance of a claim in numbers unless told otherwise: 0.5 %, a number
/// rounded to three significant figures.
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 0.005;

/// The chapter's bases whose subscripts a general-body claim must spell right.
const CHAPTER_BASES: [&str; 10] = [
    "I", "w", "wdot", "vbar", "H", "M", "SumM", "Hdot", "omega", "v",
];

fn unit_vector_sum(v: &Vector) -> Expr {
    let [i, j, k] = crate::algebra::vector::unit_vectors();
    &(&(&v[0] * &i) + &(&v[1] * &j)) + &(&v[2] * &k)
}

/// `a² + b² + c²` of the named symbols.
fn expr_sum_of_squares(names: [&str; 3]) -> Expr {
    Expr::add_all(names.map(|n| Expr::symbol(n).powi(2)))
}

fn symbols(names: &[&str], dimension: Dimension, into: &mut Dimensions) {
    for name in names {
        into.insert(Symbol::new(name), dimension);
    }
}

/// The symbols of the general body, with their dimensions.
fn general_dimensions() -> Dimensions {
    let mut d = Dimensions::new();
    symbols(
        &["I_x", "I_y", "I_z", "I_xy", "I_yz", "I_xz"],
        Dimension::INERTIA,
        &mut d,
    );
    symbols(&["m"], Dimension::MASS, &mut d);
    symbols(
        &["w_x", "w_y", "w_z", "w"],
        Dimension::ANGULAR_VELOCITY,
        &mut d,
    );
    symbols(
        &["wdot_x", "wdot_y", "wdot_z", "alpha"],
        Dimension::ANGULAR_ACCELERATION,
        &mut d,
    );
    symbols(&["vbar_x", "vbar_y", "vbar_z"], Dimension::VELOCITY, &mut d);
    symbols(&["xbar", "ybar", "zbar", "l"], Dimension::LENGTH, &mut d);
    d
}

impl Context {
    /// A general body in body-fixed axes (Ω = ω); `principal`: every product of inertia
    /// zero; `fixed_point`: the body turns about a fixed point O (or its mass centre is at
    /// rest), v̄ = 0 and the axes, moments of inertia and angular momentum are about that
    /// point (`T = ½ ωᵀ[I_O]ω`, `H_O = [I_O]ω`).
    pub fn general(principal: bool, fixed_point: bool) -> Result<Context, AlgebraError> {
        let mut c = Context::empty("a general body in body-fixed axes", general_dimensions());
        if principal {
            c.description.push_str(", principal axes");
        }
        let h_g = Context::derive_vector("H_G", principal)?;
        c.components("H", &h_g);
        c.derived("H_G", unit_vector_sum(&h_g));
        c.derived(
            "H_O",
            unit_vector_sum(&Context::derive_vector("H_O", principal)?),
        );
        c.derived("T", Context::derive_scalar("T", principal)?);
        let euler = Context::derive_vector("euler", principal)?;
        c.components("M", &euler);
        c.components("SumM", &euler);
        c.moments_spelt_m();
        c.derived("SumM", unit_vector_sum(&euler));
        // Body-fixed axes: the frame turns with the body, Ω = ω.
        let body_fixed = |s: Symbol| match s.name() {
            "Omega_x" => Some(Expr::symbol("w_x")),
            "Omega_y" => Some(Expr::symbol("w_y")),
            "Omega_z" => Some(Expr::symbol("w_z")),
            _ => None,
        };
        let hdot = Context::derive_vector_with("Hdot", principal, &body_fixed)?;
        c.components("Hdot", &hdot);
        c.derived("Hdot_G", unit_vector_sum(&hdot));
        for (vector, parts) in [
            ("omega", ["w_x", "w_y", "w_z"]),
            ("wdot", ["wdot_x", "wdot_y", "wdot_z"]),
            ("vbar", ["vbar_x", "vbar_y", "vbar_z"]),
            ("rbar", ["xbar", "ybar", "zbar"]),
        ] {
            c.derived(
                vector,
                unit_vector_sum(&Vector::from_iterator(parts.map(Expr::symbol))),
            );
        }
        for axis in ["x", "y", "z"] {
            // Body-fixed axes: the frame's Ω is ω.
            for (alias, target) in [
                ("omega", "w"),
                ("Omega", "w"),
                ("alpha", "wdot"),
                ("a", "wdot"),
                ("omegadot", "wdot"),
                ("v", "vbar"),
            ] {
                c.alias(&format!("{alias}_{axis}"), &format!("{target}_{axis}"));
            }
        }
        // The speed of the mass centre, v = |v̄| (`T = 1/2 m v^2 + ...`).
        let speed = expr_sum_of_squares(["vbar_x", "vbar_y", "vbar_z"])
            .checked_pow(&Expr::rational(1, 2))?;
        c.meanings.insert("v".into(), Meaning::Alias(speed));
        if fixed_point {
            c.about_fixed_point()?;
        }
        c.source = Some(Source::General {
            principal,
            fixed_point,
        });
        Ok(c)
    }

    /// The general body turned about a fixed point O: v̄ = 0 in every derived value, and the
    /// angular momentum and its rate named about O (the moments of inertia are O's).
    fn about_fixed_point(&mut self) -> Result<(), AlgebraError> {
        self.description = format!("{} about a fixed point O", self.description);
        let at_rest =
            |s: Symbol| matches!(s.name(), "vbar_x" | "vbar_y" | "vbar_z").then(Expr::zero);
        for meaning in self.meanings.values_mut() {
            if let Meaning::Derived(e) | Meaning::Alias(e) = meaning {
                *e = e.subs(&at_rest)?;
            }
        }
        for name in ["vbar_x", "vbar_y", "vbar_z"] {
            self.meanings
                .insert(name.into(), Meaning::Alias(Expr::zero()));
        }
        let about_g = "about G: with a fixed point the axes are at O; write H_O, Hdot_O";
        for (g, o) in [("H_G", "H_O"), ("Hdot_G", "Hdot_O")] {
            if let Some(Meaning::Derived(e)) = self.meanings.remove(g) {
                self.derived(o, e);
            }
            self.meanings
                .insert(g.into(), Meaning::Underivable(about_g.into()));
        }
        Ok(())
    }

    /// Rotation about the fixed axis z at `w`, `alpha` (§18.7): the moments and the bearings'
    /// dynamic reactions.
    pub fn fixed_axis() -> Result<Context, AlgebraError> {
        let mut c = Context::empty("rotation about the fixed axis z", general_dimensions());
        let moments = Context::derive_vector("fixed_axis", false)?;
        c.components("M", &moments);
        c.components("SumM", &moments);
        c.moments_spelt_m();
        c.derived("SumM", unit_vector_sum(&moments));
        let reactions = derive_general("reactions", false).expect("a catalogue name")?;
        for r in reactions.result() {
            c.derived(r.lhs.to_string().as_str(), r.rhs.clone());
        }
        c.alias("a", "alpha");
        c.alias("omega", "w");
        // H_O = [I_O]ω and T = ½ ωᵀ[I_O]ω of the general body, turning at ω = w k about O.
        let about_axis = |s: Symbol| match s.name() {
            "w_x" | "w_y" | "vbar_x" | "vbar_y" | "vbar_z" => Some(Expr::zero()),
            "w_z" => Some(Expr::symbol("w")),
            _ => None,
        };
        let h = Context::derive_vector_with("H_G", false, &about_axis)?;
        c.components("H", &h);
        c.derived("H_O", unit_vector_sum(&h));
        c.derived("T", Context::derive_scalar("T", false)?.subs(&about_axis)?);
        c.source = Some(Source::FixedAxis);
        Ok(c)
    }

    /// A scene: its givens, its unknowns (their solved values) and the quantities its
    /// analysis derives. A quantity the scene cannot derive is an error where a claim uses it,
    /// saying why.
    pub fn scene(scene: &Scene) -> Context {
        let mut dimensions = Dimensions::new();
        for g in &scene.givens {
            dimensions.insert(g.symbol, g.dimension);
        }
        for (u, d) in &scene.unknowns {
            dimensions.insert(*u, *d);
        }
        let title = scene.title.as_deref().unwrap_or(&scene.source_name);
        let mut c = Context::empty(&format!("the scene {title}"), dimensions);
        c.free_symbols = false;
        c.domains = scene.domains();
        c.unit_system = scene.unit_system;
        c.values = scene
            .givens
            .iter()
            .filter_map(|g| Some((g.symbol, scene.exact_given(g.symbol)?)))
            .collect();
        let mut quantities: Vec<(String, Quantity)> = Quantity::NAMED
            .iter()
            .filter(|(name, _)| !name.contains('*'))
            .map(|(name, q)| (name.to_string(), *q))
            .collect();
        quantities.extend(
            scene
                .unknowns
                .iter()
                .map(|(u, _)| (u.name().to_string(), Quantity::Unknown(*u))),
        );
        for point in &scene.points {
            let p = Symbol::new(&point.name);
            quantities.push((format!("v_{}", point.name), Quantity::PointVelocity(p)));
            quantities.push((format!("a_{}", point.name), Quantity::PointAcceleration(p)));
        }
        let impulses = scene.impulses.iter().filter_map(|i| i.name);
        quantities.extend(impulses.map(|s| (s.name().to_string(), Quantity::NamedImpulse(s))));
        // A named force (`force R = R_x*i + R_y*j at ...`) whose name no given or unknown has.
        let forces = scene
            .forces
            .iter()
            .map(|f| Symbol::new(&f.name))
            .filter(|s| !s.name().is_empty() && !c.dimensions.contains_key(s));
        quantities.extend(forces.map(|s| (s.name().to_string(), Quantity::NamedForce(s))));
        let requests: Vec<Request> = quantities
            .iter()
            .map(|(name, quantity)| request(scene, name, *quantity))
            .collect();
        // One analyser for every quantity: what several need is derived once.
        for ((name, quantity), values) in quantities.iter().zip(values_of(scene, &requests)) {
            let meaning = match values {
                Ok(values) if values.len() > 1 => c.solutions(name, *quantity, values),
                Ok(mut values) => match values.pop() {
                    Some(value) => c.meaning_of(name, *quantity, value, scene),
                    None => continue,
                },
                Err(d) => Meaning::Underivable(d.message),
            };
            c.meanings.insert(name.clone(), meaning);
        }
        c.source = Some(Source::Scene(Arc::new(scene.clone())));
        c
    }

    /// Whether `slip` changes what `name` stands for (a slip that changes no name of a
    /// claim cannot explain it).
    pub fn slip_changes(&self, slip: Slip, name: &str) -> bool {
        self.slipped(slip)
            .is_some_and(|slipped| slipped.stands_for(name) != self.stands_for(name))
    }

    /// The value `name` stands for (in the first solution, where it has several).
    fn stands_for(&self, name: &str) -> Option<&Expr> {
        match self.meanings.get(name)? {
            Meaning::Derived(e) | Meaning::Alias(e) => Some(e),
            Meaning::Solutions(each) => each.first(),
            Meaning::Underivable(_) => None,
        }
    }

    /// This context derived again with `slip` made wherever its piece is formed: what a
    /// claim holds in when it makes that slip. Derived once, when first asked; none for a
    /// context that is itself slipped, or where the slipped derivation fails.
    pub fn slipped(&self, slip: Slip) -> Option<&Context> {
        let source = self.source.as_ref()?;
        let k = Slip::ALL.iter().position(|s| *s == slip)?;
        self.slipped[k]
            .get_or_init(|| {
                // The context's work, not the claim's that first needs it: bounded by the
                // budget of the context's own input.
                let bytes = match source {
                    Source::Scene(scene) => scene.source.len(),
                    _ => 0,
                };
                let derive = || {
                    slip.applied(|| match source {
                        Source::General {
                            principal,
                            fixed_point,
                        } => Context::general(*principal, *fixed_point).ok(),
                        Source::FixedAxis => Context::fixed_axis().ok(),
                        Source::Scene(scene) => Some(Context::scene(scene)),
                    })
                };
                let (c, _) = Budget::for_input(bytes).run_apart(derive).ok()?;
                let mut c = c?;
                c.source = None;
                c.relative_tolerance = self.relative_tolerance;
                Some(c)
            })
            .as_ref()
    }

    /// A quantity with a value in each solution of the scene's equations: a scalar or a
    /// vector (its components are not named apart).
    fn solutions(&self, name: &str, quantity: Quantity, values: Vec<Value>) -> Meaning {
        let each: Option<Vec<Expr>> = values
            .into_iter()
            .map(|value| match self.value_in_dimension(value, quantity) {
                Value::Scalar(e) => Some(e),
                Value::Vector(v) => Some(unit_vector_sum(&v)),
                _ => None,
            })
            .collect();
        match each {
            Some(each) => Meaning::Solutions(each),
            None => Meaning::Underivable(format!(
                "{name} has a value in each solution of the scene's equations, and is not a scalar or a vector"
            )),
        }
    }

    /// What a scene's derived value means in a claim; a vector's components are named too
    /// (`omega_x`, `abar_y`, `H_z`), and an inertia tensor's moments and products (`I_x`,
    /// `I_xy`, and for an axisymmetric body `I` and `I'`), where no given or unknown has the
    /// name.
    fn meaning_of(
        &mut self,
        name: &str,
        quantity: Quantity,
        value: Value,
        scene: &Scene,
    ) -> Meaning {
        // The moments a claim names are about the fixed point, else about G.
        let reference = if scene.fixed_point {
            Quantity::InertiaAboutO
        } else {
            Quantity::InertiaAboutG
        };
        let axisymmetric = scene.euler_angles.is_some();
        match self.value_in_dimension(value, quantity) {
            Value::Scalar(e) => Meaning::Derived(e),
            Value::Vector(v) => {
                if let Some(base) = component_base(quantity, scene.fixed_point) {
                    self.components(base, &v);
                }
                Meaning::Derived(unit_vector_sum(&v))
            }
            Value::Tensor(m) => {
                if quantity == reference {
                    self.inertia_names(&m, axisymmetric);
                }
                Meaning::Underivable(format!(
                    "{name} is a tensor, not a value a claim can hold; its moments and products are I_x, I_y, I_z, I_xy, I_yz, I_xz"
                ))
            }
            Value::Balance(_) => {
                Meaning::Underivable("a balance is not a quantity of a claim".into())
            }
            Value::Precession(_) => Meaning::Underivable(
                "the sense of a precession is not a quantity of a claim".into(),
            ),
            Value::Principal(_) => Meaning::Underivable(
                "a frame of principal axes is not a value a claim can hold".into(),
            ),
        }
    }

    fn empty(description: &str, dimensions: Dimensions) -> Context {
        Context {
            description: description.to_string(),
            meanings: HashMap::new(),
            dimensions,
            free_symbols: true,
            domains: Domains::chapter_defaults(),
            values: HashMap::new(),
            unit_system: UnitSystem::Si,
            relative_tolerance: DEFAULT_RELATIVE_TOLERANCE,
            source: None,
            slipped: Arc::new(std::array::from_fn(|_| OnceLock::new())),
            spellings: HashMap::new(),
            world: false,
        }
    }

    /// Whether this is a student's world ([`Context::with_names`]).
    pub fn is_world(&self) -> bool {
        self.world
    }

    /// `M_x`, `M_y`, `M_z`: other spellings of `SumM_x`, `SumM_y`, `SumM_z`.
    fn moments_spelt_m(&mut self) {
        for axis in ["x", "y", "z"] {
            self.spellings
                .insert(format!("M_{axis}"), format!("SumM_{axis}"));
        }
    }

    /// The one name of the quantity `written` stands for: `SumM_x` for `M_x`, `w_1` for `w1`.
    pub fn canonical(&self, written: &str) -> String {
        match self.spellings.get(written) {
            Some(name) => name.clone(),
            None => Symbol::new(written).name().to_string(),
        }
    }

    fn derive_vector(name: &str, principal: bool) -> Result<Vector, AlgebraError> {
        let d = derive_general(name, principal).expect("a catalogue name")?;
        Ok(Vector::from_iterator(
            d.result().iter().map(|r| r.rhs.clone()),
        ))
    }

    /// [`Context::derive_vector`] with symbols replaced (`Omega_x` by `w_x` in body axes).
    fn derive_vector_with(
        name: &str,
        principal: bool,
        replace: &dyn Fn(Symbol) -> Option<Expr>,
    ) -> Result<Vector, AlgebraError> {
        let v = Context::derive_vector(name, principal)?;
        Ok(Vector::from_iterator(
            v.iter()
                .map(|e| e.subs(replace))
                .collect::<Result<Vec<_>, _>>()?,
        ))
    }

    fn derive_scalar(name: &str, principal: bool) -> Result<Expr, AlgebraError> {
        let d = derive_general(name, principal).expect("a catalogue name")?;
        Ok(d.result()[0].rhs.clone())
    }

    fn derived(&mut self, name: &str, value: Expr) {
        self.meanings
            .insert(name.to_string(), Meaning::Derived(value));
    }

    fn alias(&mut self, name: &str, of: &str) {
        self.meanings
            .insert(name.to_string(), Meaning::Alias(Expr::symbol(of)));
    }

    /// A name the context gives a derived value, unless a given or unknown has it.
    fn derived_unless_taken(&mut self, name: &str, value: Expr) {
        if !self.dimensions.contains_key(&Symbol::new(name)) {
            self.derived(name, value);
        }
    }

    /// `base_x`, `base_y`, `base_z` for the components of `v`.
    fn components(&mut self, base: &str, v: &Vector) {
        for (axis, value) in ["x", "y", "z"].iter().zip(v.iter()) {
            self.derived_unless_taken(&format!("{base}_{axis}"), value.clone());
        }
    }

    /// The moments and products of inertia of a tensor in the chapter's convention
    /// (`[I]` has `−I_xy` off the diagonal): `I_x`, `I_y`, `I_z`, `I_xy`, `I_yz`, `I_xz`; and for
    /// an axisymmetric body about z, the textbook's `I` (about the axis) and `I'` (across it).
    fn inertia_names(&mut self, tensor: &crate::algebra::Matrix, axisymmetric: bool) {
        let entry = |r: usize, c: usize| tensor[(r, c)].clone();
        for (name, value) in [
            ("I_x", entry(0, 0)),
            ("I_y", entry(1, 1)),
            ("I_z", entry(2, 2)),
            ("I_xy", -entry(0, 1)),
            ("I_yz", -entry(1, 2)),
            ("I_xz", -entry(0, 2)),
        ] {
            let value = self.in_dimension(value, Some(Dimension::INERTIA));
            self.derived_unless_taken(name, value);
        }
        if axisymmetric {
            for (name, value) in [("I", entry(2, 2)), ("I'", entry(0, 0))] {
                let value = self.in_dimension(value, Some(Dimension::INERTIA));
                self.derived_unless_taken(name, value);
            }
        }
    }

    /// What a written name stands for here: the resolver of [`crate::parse::parse_claim`]
    /// (in the first solution of a scene's equations, where they have several).
    pub fn name(&self, written: &str) -> Name {
        self.name_in_solution(written, 0)
    }

    /// What a written name stands for in the solution `k` (from 0) of a scene's equations.
    pub fn name_in_solution(&self, written: &str, k: usize) -> Name {
        // `w1` is the symbol `w_1`: a name is looked up as written and as the symbol's.
        let symbol = Symbol::new(written);
        let meaning = self.meaning(written);
        match meaning {
            Some(Meaning::Derived(e) | Meaning::Alias(e)) => return Name::Derived(e.clone()),
            Some(Meaning::Solutions(each)) => {
                return Name::Derived(each[k.min(each.len() - 1)].clone())
            }
            Some(Meaning::Underivable(why)) => {
                return Name::Unknown(format!(
                    "{} cannot derive {written}: {why}",
                    self.description
                ))
            }
            None => {}
        }
        if self.dimensions.contains_key(&symbol) {
            return Name::Symbol;
        }
        let base = written.split('_').next().unwrap_or(written);
        let misspelt = written.contains('_') && CHAPTER_BASES.contains(&base)
            || self.spelt_like_known(written);
        if self.free_symbols && !misspelt {
            return Name::Symbol;
        }
        Name::Unknown(self.suggestion(written))
    }

    /// The meaning of a written name, looked up as written and as its symbol's name.
    fn meaning(&self, written: &str) -> Option<&Meaning> {
        self.meanings
            .get(written)
            .or_else(|| self.meanings.get(Symbol::new(written).name()))
    }

    /// How many values `name` has: one in each solution of the scene's equations, else 1.
    pub fn solution_count(&self, name: &str) -> usize {
        match self.meaning(name) {
            Some(Meaning::Solutions(each)) => each.len(),
            _ => 1,
        }
    }

    /// Whether `name`, written in a claim, is another spelling of symbols (not a derived
    /// quantity): its side is not thereby the derived one.
    pub fn is_alias(&self, name: &str) -> bool {
        matches!(self.meaning(name), Some(Meaning::Alias(_)))
    }

    /// A symbol's dimension, when the context knows it (a unit's marker, [`Context::unit`],
    /// has its unit's).
    pub fn dimension(&self, s: Symbol) -> Option<Dimension> {
        self.dimensions
            .get(&s)
            .copied()
            .or_else(|| {
                self.meanings.get(s.name()).and_then(|m| match m {
                    Meaning::Derived(e) | Meaning::Alias(e) => self.dimension_of(e).ok(),
                    Meaning::Solutions(each) => self.dimension_of(each.first()?).ok(),
                    Meaning::Underivable(_) => None,
                })
            })
            .or_else(|| marker_dimension(s))
    }

    /// The unit a name after a number stands for (`1857 N`, `150 mm`), as its marker: in a
    /// context whose givens have values, a unit of the table that is not a name here (in SP
    /// 18.5, where `N` is the normal force, `2 N` is twice it); after a unit, any unit of the
    /// table (`0.0913 N*m` is in N·m where m is the mass).
    pub fn unit(&self, name: &str, follows: Follows) -> Option<Expr> {
        let taken =
            self.meanings.contains_key(name) || self.dimensions.contains_key(&Symbol::new(name));
        let free = !taken || follows == Follows::Unit;
        (self.has_values() && free).then(|| marker(name))?
    }

    /// This context with each name of `values` standing for that value instead of what the
    /// mechanics derives: the values a student's earlier lines give the names, where a later
    /// line is checked to see whether it follows from them. No slip is tried in it.
    pub fn with_names(&self, values: &HashMap<String, Expr>) -> Context {
        let mut c = self.clone();
        for (name, value) in values {
            let spellings = self.spellings.iter().filter(|(_, of)| *of == name);
            for written in spellings.map(|(w, _)| w).chain([name]) {
                c.meanings
                    .insert(written.clone(), Meaning::Derived(value.clone()));
            }
        }
        c.source = None;
        c.slipped = Arc::new(std::array::from_fn(|_| OnceLock::new()));
        c.world = true;
        c
    }

    /// Every value of a derived scalar `written` stands for: one, or one in each solution of
    /// the scene's equations (a top's slow and fast precession).
    pub fn derived_scalar_values(&self, written: &str) -> Vec<Expr> {
        match self.meaning(written) {
            Some(Meaning::Solutions(each)) => each.clone(),
            _ => self.derived_scalar(written).into_iter().collect(),
        }
    }

    /// The value of a derived scalar `written` stands for (in the first solution): the names
    /// whose value a line of a derivation may fix. Not a given, an alias or a vector.
    pub fn derived_scalar(&self, written: &str) -> Option<Expr> {
        match self.meaning(written)? {
            Meaning::Derived(e) if !crate::algebra::vector::has_unit_vectors(e) => Some(e.clone()),
            Meaning::Solutions(each) => each
                .first()
                .filter(|e| !crate::algebra::vector::has_unit_vectors(e))
                .cloned(),
            _ => None,
        }
    }

    /// This context deciding claims in numbers within `relative` of the exact value.
    pub fn with_relative_tolerance(mut self, relative: f64) -> Context {
        self.relative_tolerance = relative;
        self.slipped = Arc::new(std::array::from_fn(|_| OnceLock::new()));
        self
    }

    /// How close a claim written in numbers must come to the exact value, relative to it.
    pub fn relative_tolerance(&self) -> f64 {
        self.relative_tolerance
    }

    /// The unit system of the values: a claim's numbers with units are brought into it.
    pub fn unit_system(&self) -> UnitSystem {
        self.unit_system
    }

    /// The exact value, in the scene's unit system, of a given the scene gives one
    /// (`beta = 60 deg` is π/3).
    pub fn value(&self, s: Symbol) -> Option<Expr> {
        self.values.get(&s).cloned()
    }

    /// Whether some given has a value (a claim may then be written in numbers).
    pub fn has_values(&self) -> bool {
        !self.values.is_empty()
    }

    /// The symbols' domains (masses and lengths positive, ...).
    pub fn domains(&self) -> &Domains {
        &self.domains
    }
}

/// `find NAME` for a quantity, at the end of the scene's text.
fn request(scene: &Scene, name: &str, quantity: Quantity) -> Request {
    Request {
        quantity,
        name: name.to_string(),
        span: Span {
            start: scene.source.len(),
            end: scene.source.len(),
        },
        unit: None,
        shown_in: None,
        solution: None,
    }
}

/// The base of the names of a derived vector's components in a claim (`omega_x`). `H_x` and
/// `Hdot_x` are about the point the worked solution takes moments about: O in a scene with a
/// fixed point (its page writes Ḣ_O's components `Hdot_x`), else G.
fn component_base(quantity: Quantity, fixed_point: bool) -> Option<&'static str> {
    match quantity {
        Quantity::AngularVelocity => Some("omega"),
        Quantity::MassCentreVelocity => Some("vbar"),
        Quantity::MassCentreAcceleration => Some("abar"),
        Quantity::AngularMomentumAboutG if !fixed_point => Some("H"),
        Quantity::RateOfAngularMomentum if !fixed_point => Some("Hdot"),
        Quantity::AngularMomentumAboutO if fixed_point => Some("H"),
        Quantity::RateOfAngularMomentumAboutO if fixed_point => Some("Hdot"),
        _ => None,
    }
}
