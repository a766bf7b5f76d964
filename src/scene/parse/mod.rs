//! Scene files: `grammar/scene.pest` → [`Scene`], with every error located in the file
//! (file:line:column, a caret, a hint). The mathematics inside a statement goes through the
//! expression parser; its diagnostics are moved to their place in the file.

use super::kinematic_constraints::{H_COMPONENTS, OMEGA_COMPONENTS};
use super::model::{
    Constraint, ConstraintKind, Force, Places, Quantity, Request, Scene, Span, Support, SupportKind,
};
use super::named_unit::NamedUnit;
use super::unit_system::UnitSystem;
use super::units::{dimension_with, Dimension, DimensionError, Dimensions};
use super::units_in_math::{marker, marker_dimension};
use crate::algebra::{vector, Expr, Symbol, Vector};
use crate::parse::{parse_expression_with_units, Diagnostic, Follows};
use pest::iterators::Pair;
use pest::Parser;
use syntax_error::{expected_words, syntax_error};

mod balance;
mod before_grammar;
mod body;
mod euler_angles;
mod given;
mod named;
mod orientation;
mod quantity;
mod reserved_names;
mod similar_name;
mod syntax_error;

/// The name of time in scene mathematics.
pub const TIME: &str = "t";

#[derive(pest_derive::Parser)]
#[grammar = "../grammar/scene.pest"]
struct SceneGrammar;

/// Parses and checks a scene file.
///
/// Values are kept in the scene's unit system (`unit_system.rs`): SI (`100 mm` is 0.1 m),
/// or U.S. customary units (`6 in` is 0.5 ft) when the givens are written in them; an error
/// says where it is and what to do.
///
/// ```
/// use kinetics::algebra::Symbol;
/// use kinetics::parse_scene;
///
/// let scene = parse_scene(
///     "sphere.scene",
///     "given m = 5 kg
/// given r = 100 mm
/// body sphere(r) mass m
/// find T",
/// )?;
/// assert_eq!(scene.value(Symbol::new("r")), Some(0.1));
/// assert_eq!(scene.parts.len(), 1);
///
/// let error = parse_scene("sphere.scene", "given m = 5 kg\nbody sphere(r) mass m\nfind T");
/// let error = error.unwrap_err();
/// assert_eq!((error.line, error.column), (2, 13));
/// assert_eq!(error.message, "unknown symbol r");
/// assert!(error.help.is_some_and(|help| help.contains("given r")));
/// # Ok::<(), kinetics::Diagnostic>(())
/// ```
pub fn parse_scene(source_name: &str, source: &str) -> Result<Scene, Diagnostic> {
    parse_scene_in(source_name, source, None)
}

/// [`parse_scene`] in the unit system `units` (`kinetics solve --units us`), else the
/// givens' ([`UnitSystem::of_units`]).
pub fn parse_scene_in(
    source_name: &str,
    source: &str,
    units: Option<UnitSystem>,
) -> Result<Scene, Diagnostic> {
    let scene = read_scene(source_name, source, units)?;
    if scene.requests.is_empty() {
        return Err(Diagnostic::at(
            source_name,
            source,
            source.len(),
            source.len(),
            "the scene asks for nothing",
        )
        .with_help("add a line such as 'find T, H_G' naming what to compute"));
    }
    Ok(scene)
}

/// [`parse_scene`] for `kinetics simulate`, which asks for nothing but the motion: a scene
/// without a `find` line is accepted (its body, ω and loads are what a simulation needs).
pub fn parse_scene_to_simulate(source_name: &str, source: &str) -> Result<Scene, Diagnostic> {
    read_scene(source_name, source, None)
}

fn read_scene(
    source_name: &str,
    source: &str,
    units: Option<UnitSystem>,
) -> Result<Scene, Diagnostic> {
    before_grammar::check_before_grammar(source_name, source)?;
    // Error detail records the furthest place the grammar reached and what it expected
    // there, at a cost on every parse: a scene that does not parse is parsed again with it
    // (once set it stays set, so no thread's error ever lacks it).
    let parsed = SceneGrammar::parse(Rule::scene, source).or_else(|_| {
        pest::set_error_detail(true);
        SceneGrammar::parse(Rule::scene, source)
    });
    let mut pairs = parsed.map_err(|e| {
        let start = match e.location {
            pest::error::InputLocation::Pos(p) => p,
            pest::error::InputLocation::Span((s, _)) => s,
        };
        let attempts = e.parse_attempts();
        let furthest = attempts
            .as_ref()
            .map_or(start, |a| a.max_position.max(start));
        let expected = attempts
            .map(|a| expected_words(&a.expected_tokens()))
            .unwrap_or_default();
        syntax_error(source_name, source, furthest, &expected)
    })?;
    let statements: Vec<Pair<Rule>> = pairs
        .next()
        .map(Pair::into_inner)
        .into_iter()
        .flatten()
        .collect();
    let mut reader = Reader {
        source_name,
        source,
        dims: Dimensions::new(),
        scene: Scene {
            source_name: source_name.to_string(),
            source: source.to_string(),
            title: None,
            statement: vec![],
            givens: vec![],
            parts: vec![],
            fixed_point: false,
            up: None,
            about_mass_centre: false,
            euler_angles: None,
            omega: None,
            omega_dot: None,
            frame_rate: None,
            vbar: None,
            vbar_before: None,
            omega_before: None,
            abar: None,
            forces: vec![],
            couples: vec![],
            impulses: vec![],
            points: vec![],
            supports: vec![],
            constraints: vec![],
            unknowns: vec![],
            unknown_units: vec![],
            unit_system: units.unwrap_or_else(|| units_of_givens(&statements)),
            requests: vec![],
            balance: None,
            places: Places::default(),
        },
    };
    for dimensionless in vector::unit_vectors().into_iter().chain([Expr::pi()]) {
        if let Some(s) = dimensionless.as_symbol() {
            reader.dims.insert(s, Dimension::NONE);
        }
    }
    // `t` is the time, for loads that vary (`couple M0*sin(p*t)*i`), unless declared.
    reader.dims.insert(Symbol::new(TIME), Dimension::TIME);
    for statement in statements {
        reader.statement(statement)?;
    }
    reader.euler_angles_complete()?;
    // A system chosen (`--units`) wins over an unknown's unit of the other system (`: lb`
    // under `--units si`); a unit of both (`: deg`) stays.
    if let Some(system) = units {
        let other = |unit: &NamedUnit| UnitSystem::of_unit(unit).is_some_and(|s| s != system);
        reader.scene.unknown_units.retain(|(_, unit)| !other(unit));
    }
    reader.resolve_requests()?;
    reader.impact_is_determined()?;
    Ok(reader.scene)
}

/// The unit system of the units the `given` and `unknown` statements write, read before any
/// value is (a unit that does not read is left to the statement's own error).
fn units_of_givens(statements: &[Pair<Rule>]) -> UnitSystem {
    let declarations = statements
        .iter()
        .filter(|p| matches!(p.as_rule(), Rule::given | Rule::unknown));
    let units: Vec<NamedUnit> = declarations
        .flat_map(|p| p.clone().into_inner().flatten())
        .filter(|p| p.as_rule() == Rule::unit)
        .filter_map(|p| NamedUnit::read(p.as_str()).ok())
        .collect();
    UnitSystem::of_units(&units)
}

struct Reader<'a> {
    source_name: &'a str,
    source: &'a str,
    dims: Dimensions,
    scene: Scene,
}

fn span(p: &Pair<Rule>) -> (usize, usize) {
    (p.as_span().start(), p.as_span().end())
}

impl Reader<'_> {
    fn error(&self, (start, end): (usize, usize), message: impl Into<String>) -> Diagnostic {
        Diagnostic::at(self.source_name, self.source, start, end, message)
    }

    fn statement(&mut self, p: Pair<Rule>) -> Result<(), Diagnostic> {
        let at = span(&p);
        let rule = p.as_rule();
        let mut inner: Vec<Pair<Rule>> = p.into_inner().collect();
        if matches!(rule, Rule::omega | Rule::omegadot | Rule::frame) {
            self.not_derived_from_euler_angles(at)?;
        }
        match rule {
            Rule::euler_angles => self.euler_angles(&inner, at)?,
            Rule::title => self.scene.title = inner.first().map(|t| t.as_str().trim().to_string()),
            Rule::problem_statement => {
                let words = inner.first().map_or("", |t| t.as_str().trim());
                self.scene.statement.push(words.to_string());
            }
            Rule::given => self.given(inner)?,
            Rule::body => self.body(inner, at)?,
            Rule::fixed_point => self.scene.fixed_point = true,
            Rule::up => {
                self.only_once(self.scene.up.is_some(), at)?;
                self.scene.up = Some(orientation::frame_axis(&inner[0]));
            }
            Rule::about_g => {
                self.only_once(self.scene.about_mass_centre, at)?;
                self.scene.about_mass_centre = true
            }
            Rule::omega => {
                self.only_once(self.scene.omega.is_some(), at)?;
                self.scene.omega = Some(self.vector(&inner[0], Dimension::ANGULAR_VELOCITY)?)
            }
            Rule::omegadot => {
                self.only_once(self.scene.omega_dot.is_some(), at)?;
                self.scene.omega_dot =
                    Some(self.vector(&inner[0], Dimension::ANGULAR_ACCELERATION)?)
            }
            Rule::frame => {
                if inner[0].as_rule() == Rule::math {
                    self.only_once(self.scene.frame_rate.is_some(), at)?;
                    self.scene.frame_rate =
                        Some(self.vector(&inner[0], Dimension::ANGULAR_VELOCITY)?);
                }
            }
            Rule::vbar => {
                self.only_once(self.scene.vbar.is_some(), at)?;
                self.scene.vbar = Some(self.vector(&inner[0], Dimension::VELOCITY)?)
            }
            Rule::abar => {
                self.only_once(self.scene.abar.is_some(), at)?;
                self.scene.abar = Some(self.vector(&inner[0], Dimension::ACCELERATION)?)
            }
            Rule::force => {
                let name = inner[0].as_str().to_string();
                self.unused_name(&name, span(&inner[0]))?;
                let value = self.vector(&inner[1], Dimension::FORCE)?;
                let point = self.point(&inner[2])?;
                self.scene.forces.push(Force { name, value, point });
            }
            Rule::couple => {
                let c = self.vector(&inner[0], Dimension::MOMENT)?;
                self.scene.couples.push(c);
            }
            Rule::impulse => self.impulse(&inner)?,
            Rule::before => self.before(&inner[0], at)?,
            Rule::named_point => self.named_point(&inner)?,
            Rule::wire | Rule::post => {
                let (kind, what, ends) = match rule {
                    Rule::wire => (
                        SupportKind::Wire,
                        "wire",
                        "its anchor must stand apart from the body's point",
                    ),
                    _ => (
                        SupportKind::Post,
                        "post",
                        "its top must stand apart from its base",
                    ),
                };
                let support = Support {
                    kind,
                    from: self.point(&inner[0])?,
                    to: self.point(&inner[1])?,
                };
                if support.from == support.to {
                    return Err(self.error(at, format!("a {what} from a point to itself: {ends}")));
                }
                self.scene.supports.push(support);
            }
            Rule::constraint => {
                let c = inner.remove(0);
                let constraint = match c.as_rule() {
                    Rule::velocity_zero => {
                        let point = c
                            .into_inner()
                            .next()
                            .ok_or_else(|| self.error(at, "expected a point"))?;
                        ConstraintKind::VelocityZero(self.point(&point)?)
                    }
                    _ => {
                        let sides: Vec<Pair<Rule>> = c.into_inner().collect();
                        // ω's and H_G's components may be named (`kinematic_constraints.rs`).
                        let named: Vec<(Symbol, Dimension)> = OMEGA_COMPONENTS
                            .into_iter()
                            .map(|n| (n, Dimension::ANGULAR_VELOCITY))
                            .chain(
                                H_COMPONENTS
                                    .into_iter()
                                    .map(|n| (n, Dimension::new(1, 2, -1))),
                            )
                            .map(|(n, d)| (Symbol::new(n), d))
                            .filter(|(s, _)| !self.dims.contains_key(s))
                            .collect();
                        for (s, d) in &named {
                            self.dims.insert(*s, *d);
                        }
                        let equation = self.constraint_equation(&sides);
                        for (s, _) in &named {
                            self.dims.remove(s);
                        }
                        equation?
                    }
                };
                self.scene.constraints.push(Constraint {
                    kind: constraint,
                    span: Span {
                        start: at.0,
                        end: at.1,
                    },
                });
            }
            Rule::unknown => self.unknown(inner)?,
            Rule::EOI => {}
            Rule::find => {
                for r in inner {
                    let (start, end) = span(&r);
                    let mut parts = r.into_inner().peekable();
                    if let Some(balance) = parts.next_if(|p| p.as_rule() == Rule::balance) {
                        self.balance(balance)?;
                    }
                    let name = parts
                        .next()
                        .map_or("balance".to_string(), |n| n.as_str().to_string());
                    let unit = match parts.next() {
                        Some(u) => Some(self.unit(&u)?),
                        None => None,
                    };
                    if self.scene.requests.iter().any(|q| q.name == name) {
                        return Err(self
                            .error((start, end), format!("{name} is asked for twice"))
                            .with_help("name each quantity once in 'find'"));
                    }
                    let balance =
                        self.scene.balance.is_some() && name == "balance" && unit.is_none();
                    self.scene.requests.push(Request {
                        // Resolved against the declarations once the whole file is read.
                        quantity: match balance {
                            true => Quantity::Balance,
                            false => Quantity::Unknown(Symbol::new(&name)),
                        },
                        name,
                        span: Span { start, end },
                        unit,
                        shown_in: None,
                        solution: None,
                    });
                }
            }
            _ => return Err(self.error(at, "unexpected statement")),
        }
        let place = Span {
            start: at.0,
            end: at.1,
        };
        match rule {
            Rule::body => self.scene.places.body.push(place),
            Rule::omega => self.scene.places.omega = Some(place),
            Rule::omegadot => self.scene.places.omega_dot = Some(place),
            Rule::frame => self.scene.places.frame = Some(place),
            Rule::force => self.scene.places.forces.push(place),
            Rule::couple => self.scene.places.couples.push(place),
            Rule::before if self.scene.places.before.is_none() => {
                self.scene.places.before = Some(place)
            }
            Rule::impulse if self.scene.places.impulse.is_none() => {
                self.scene.places.impulse = Some(place)
            }
            _ => {}
        }
        Ok(())
    }

    /// Decides what each `find` names, now that every declaration is known: one of the
    /// chapter's quantities, or a declared unknown. A name that is both (an unknown force
    /// called `T`) would be answered with the wrong one: it is refused, at the request.
    fn resolve_requests(&mut self) -> Result<(), Diagnostic> {
        for k in 0..self.scene.requests.len() {
            let request = &self.scene.requests[k];
            if request.quantity == Quantity::Balance {
                continue;
            }
            let at = (request.span.start, request.span.end);
            let symbol = Symbol::new(&request.name);
            let is_unknown = self.scene.is_unknown(symbol);
            let declared = if is_unknown {
                Some("unknown")
            } else if self.scene.givens.iter().any(|g| g.symbol == symbol) {
                Some("given")
            } else {
                None
            };
            let named =
                Quantity::named(&request.name).or_else(|| self.named_request(&request.name));
            let quantity = match (named, declared) {
                (Some(q), None) => q,
                (None, _) if is_unknown => Quantity::Unknown(symbol),
                (Some(q), Some(kind)) => {
                    return Err(self
                        .error(
                            at,
                            format!(
                                "'{}' is both {} and a declared {kind}",
                                request.name,
                                q.description()
                            ),
                        )
                        .with_help(format!(
                            "rename the {kind} ({}_1, say): in 'find', {} means {}",
                            request.name,
                            request.name,
                            q.description()
                        )))
                }
                (None, _) => {
                    if let Some(unnamed) = self.unnamed_point(&request.name, at) {
                        return Err(unnamed);
                    }
                    let unknowns = self.scene.unknowns.iter().map(|(s, _)| s.name());
                    let named = Quantity::NAMED.map(|(n, _)| n);
                    if let Some(similar) =
                        similar_name::similar_name(&request.name, unknowns.chain(named))
                    {
                        return Err(self
                            .error(at, format!("cannot find '{}'", request.name))
                            .with_help(format!(
                            "did you mean '{similar}'? Names differ in letter case and underscores"
                        )));
                    }
                    return Err(self
                        .error(at, format!("cannot find '{}'", request.name))
                        .with_help(format!(
                            "ask for {}, v_A or a_A of a named point A, a declared unknown, or balance in planes z = a, z = b at radius r",
                            Quantity::NAMED.map(|(n, _)| n).join(", ")
                        )));
                }
            };
            self.scene.requests[k].quantity = quantity;
            if let Quantity::Unknown(u) = quantity {
                let declared = self.scene.unknown_units.iter().find(|(s, _)| *s == u);
                self.scene.requests[k].shown_in = declared.map(|(_, unit)| unit.clone());
            }
        }
        Ok(())
    }

    /// A statement that sets one vector of the scene (omega, omegadot, frame rate, vbar)
    /// may appear once: a second would silently replace the first.
    fn only_once(&self, already_set: bool, at: (usize, usize)) -> Result<(), Diagnostic> {
        if !already_set {
            return Ok(());
        }
        let keyword = self.source[at.0..at.1]
            .split_whitespace()
            .next()
            .unwrap_or_default();
        Err(self
            .error(at, format!("'{keyword}' is given twice"))
            .with_help("keep one of the two lines: the second would replace the first"))
    }

    fn declare(&mut self, name: &Pair<Rule>, dimension: Dimension) -> Result<Symbol, Diagnostic> {
        let symbol = Symbol::new(name.as_str());
        if let Some(meaning) = reserved_names::meaning(name.as_str()) {
            return Err(self
                .error(span(name), meaning)
                .with_help("choose another name"));
        }
        self.declarable_with_euler_angles(name)?;
        // `t` is the time unless the scene declares it (a thickness, say).
        let undeclared_time = name.as_str() == TIME && self.scene.dimension(symbol).is_none();
        if self.dims.contains_key(&symbol) && !undeclared_time {
            return Err(self
                .error(span(name), format!("{} is declared twice", name.as_str()))
                .with_help("declare each symbol once, with 'given' or 'unknown'"));
        }
        self.dims.insert(symbol, dimension);
        Ok(symbol)
    }

    /// The unit written at `p` (`unit_text.rs`), an error located inside it.
    fn unit(&self, p: &Pair<Rule>) -> Result<NamedUnit, Diagnostic> {
        NamedUnit::read(p.as_str()).map_err(|e| {
            let start = span(p).0;
            self.error((start + e.span.0, start + e.span.1), e.message)
                .with_help(e.help)
        })
    }

    fn unknown(&mut self, inner: Vec<Pair<Rule>>) -> Result<(), Diagnostic> {
        let unit = match inner.last() {
            Some(u) if u.as_rule() == Rule::unit => Some(self.unit(u)?),
            _ => None,
        };
        for name in inner.iter().filter(|p| p.as_rule() == Rule::name) {
            let dimension = unit
                .as_ref()
                .map_or_else(|| default_dimension(name.as_str()), |u| u.unit().dimension);
            let symbol = self.declare(name, dimension)?;
            self.scene.unknowns.push((symbol, dimension));
            if let Some(unit) = &unit {
                self.scene.unknown_units.push((symbol, unit.clone()));
            }
        }
        Ok(())
    }

    /// `lhs = rhs` of a constraint, in the scene's units, its sides in the same kind of unit.
    fn constraint_equation(&self, sides: &[Pair<Rule>]) -> Result<ConstraintKind, Diagnostic> {
        let lhs = self.math(&sides[0])?;
        let rhs = self.math(&sides[1])?;
        self.same_dimension(&lhs, &rhs, span(&sides[1]))?;
        let lhs = self.in_units(&lhs, span(&sides[0]))?;
        Ok(ConstraintKind::Equation(
            lhs,
            self.in_units(&rhs, span(&sides[1]))?,
        ))
    }

    /// The mathematics as written, a unit after a number as its marker
    /// (`units_in_math.rs`): for [`Reader::quantity`] to check and bring into the scene's units.
    fn math(&self, p: &Pair<Rule>) -> Result<Expr, Diagnostic> {
        let (start, _) = span(p);
        // A name the scene declares is itself after a number (`2 N`, twice the force N),
        // and a unit after a unit (`N*m`, with m the mass).
        let unit = |name: &str, follows: Follows| match (
            self.dims.contains_key(&Symbol::new(name)),
            follows,
        ) {
            (true, Follows::Number) => None,
            _ => marker(name),
        };
        let e = parse_expression_with_units(self.source_name, p.as_str(), &unit).map_err(|d| {
            let offset = start + d.span.offset();
            let mut moved = Diagnostic::at(
                self.source_name,
                self.source,
                offset,
                offset + d.span.len(),
                d.message.clone(),
            );
            moved.help = d.help.clone();
            moved
        })?;
        let undeclared = |s: &Symbol| !self.dims.contains_key(s) && marker_dimension(*s).is_none();
        if let Some(unknown) = e.symbols().into_iter().find(undeclared) {
            if unknown.name() == "omega" {
                return Err(self
                    .error(span(p), "omega is the body's angular velocity, a vector, where a number is expected")
                    .with_help("in a constraint, name one of its components (omega_x, omega_y, omega_z); for its magnitude, give it a name of its own ('given w = 40 rad/s')"));
            }
            let declared = self.dims.keys().map(|s| s.name());
            return Err(self
                .error(span(p), format!("unknown symbol {}", unknown.name()))
                .with_help(similar_name::undeclared_help(unknown.name(), declared)));
        }
        let e = self.vertical_in(e, span(p))?;
        self.finite_with_values(&self.in_units(&e, span(p))?, span(p))?;
        Ok(e)
    }

    /// With every symbol given a value, the expression must be a finite number.
    fn finite_with_values(&self, e: &Expr, at: (usize, usize)) -> Result<(), Diagnostic> {
        let value = |s: Symbol| {
            if matches!(s.name(), "i" | "j" | "k") {
                Some(1.0)
            } else {
                self.scene.value(s)
            }
        };
        let message = match e.eval::<f64>(&value) {
            Err(crate::algebra::AlgebraError::DivisionByZero) => {
                "division by zero: with the given values a divisor is zero".to_string()
            }
            Err(crate::algebra::AlgebraError::NotFinite { value, .. }) if value == "NaN" => {
                "with the given values this is not a number (NaN)".to_string()
            }
            Err(crate::algebra::AlgebraError::NotFinite { .. }) => "with the given values this \
                overflows the range of numbers (magnitudes up to about 1.8e308)"
                .to_string(),
            _ => return Ok(()),
        };
        Err(self
            .error(at, message)
            .with_help("check the values of the givens in this expression"))
    }

    fn dimension(&self, e: &Expr, at: (usize, usize)) -> Result<Dimension, Diagnostic> {
        let of_symbol = |s: Symbol| self.dims.get(&s).copied().or_else(|| marker_dimension(s));
        dimension_with(e, &of_symbol).map_err(|err| {
            let help = match err {
                DimensionError::Mismatch(..) => {
                    "every term of a sum must be in the same kind of unit"
                }
                _ => "check the units of the symbols",
            };
            self.error(at, err.in_words(&|d| self.unit_of(d)))
                .with_help(self.given_named_as_unit(e, help))
        })
    }

    /// The scene's unit of the dimension `d`, for a message (`lb·ft` in U.S. units;
    /// `no unit` for a pure number).
    fn unit_of(&self, d: Dimension) -> String {
        match self.scene.unit_system.unit(d, false).to_string() {
            named if named.is_empty() => "no unit".to_string(),
            named => named,
        }
    }

    fn expect_dimension(
        &self,
        e: &Expr,
        want: Dimension,
        at: (usize, usize),
    ) -> Result<(), Diagnostic> {
        let d = self.dimension(e, at)?;
        if d != want && !e.is_zero() {
            let error = self.error(
                at,
                format!(
                    "unit mismatch: expected a quantity in {}, found {}",
                    self.unit_of(want),
                    self.unit_of(d)
                ),
            );
            // A weight (lb, N) where a mass is wanted: its mass is W/g.
            if want == Dimension::MASS && d == Dimension::FORCE {
                return Err(error.with_help(
                    "this is a weight, a force: the mass is the weight over g ('mass W/g', with 'given g = 32.2 ft/s^2' or 'given g = 9.81 m/s^2'), or give the mass in slug or kg",
                ));
            }
            return Err(error.with_help(self.given_named_as_unit(
                e,
                "check the units declared for the symbols of this expression",
            )));
        }
        Ok(())
    }

    fn same_dimension(&self, a: &Expr, b: &Expr, at: (usize, usize)) -> Result<(), Diagnostic> {
        let (da, db) = (self.dimension(a, at)?, self.dimension(b, at)?);
        if da != db && !a.is_zero() && !b.is_zero() {
            return Err(self
                .error(
                    at,
                    format!(
                        "unit mismatch: the left side is in {}, the right side in {}",
                        self.unit_of(da),
                        self.unit_of(db)
                    ),
                )
                .with_help(self.given_named_as_unit(
                    &(a.clone() + b.clone()),
                    "both sides of an equation must be in the same kind of unit",
                )));
        }
        Ok(())
    }

    /// A vector written with i, j, k whose components have the given dimension.
    fn vector(&self, p: &Pair<Rule>, want: Dimension) -> Result<Vector, Diagnostic> {
        let e = self.math(p)?;
        let v = vector::components(&e).map_err(|err| {
            self.error(span(p), err.to_string())
                .with_help("write a vector with the unit vectors: a*i + b*j + c*k")
        })?;
        for c in v.iter() {
            self.expect_dimension(c, want, span(p))?;
        }
        let mut in_units = Vec::with_capacity(3);
        for c in v.iter() {
            in_units.push(self.in_units(c, span(p))?);
        }
        Ok(Vector::from_iterator(in_units))
    }

    fn point(&self, p: &Pair<Rule>) -> Result<Vector, Diagnostic> {
        let mut coords = Vec::with_capacity(3);
        for c in p.clone().into_inner() {
            coords.push(self.quantity(&c, Dimension::LENGTH)?);
        }
        Ok(Vector::from_iterator(coords))
    }
}

/// Unknowns without a unit: forces by their usual names, otherwise angular velocities; an
/// Eulerian angle is a number (in radians), its rate an angular velocity, and its second
/// rate an angular acceleration.
fn default_dimension(name: &str) -> Dimension {
    let s = Symbol::new(name);
    if matches!(s.base(), "phi" | "theta" | "psi") && s.axis().is_none() {
        return match s.dots() {
            0 => Dimension::NONE,
            1 => Dimension::ANGULAR_VELOCITY,
            _ => Dimension::ANGULAR_ACCELERATION,
        };
    }
    match s.base() {
        "w" | "omega" => Dimension::ANGULAR_VELOCITY,
        "alpha" => Dimension::ANGULAR_ACCELERATION,
        "v" | "vbar" => Dimension::VELOCITY,
        _ => Dimension::FORCE,
    }
}
