//! What a scene file says, after parsing and checking: givens, the body, its kinematics,
//! loads, constraints, unknowns and requests. Positions are from the origin O of the
//! reference frame; vectors are components in that frame.

use super::named_unit::NamedUnit;
use super::unit_system::UnitSystem;
use super::units::Dimension;
use crate::algebra::{AlgebraError, Axis, Domain, Domains, Expr, Symbol, Vector, Q};
use crate::mechanics::composite_body::composite_body;
use crate::mechanics::eulerian_angles::EulerianAngles;
use crate::mechanics::inertia::{InertiaTensor, MassPart};
use crate::mechanics::inertia_about_point::inertia_about_fixed_point;
use crate::mechanics::shapes::Shape;
use crate::parse::Diagnostic;

/// The exact rational a finite number reads as in its shortest decimal form: `1e200` is
/// 10²⁰⁰ exactly, `0.1` is 1/10 (not the binary fraction nearest to it).
pub fn exact_decimal(x: f64) -> Option<Q> {
    let q = Q::parse_decimal(&format!("{:e}", x.abs()))?;
    Some(if x < 0.0 { -&q } else { q })
}

/// Where a statement stands in the scene file, for diagnostics after parsing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Span {
    pub start: usize,
    pub end: usize,
}

/// Where the statements a simulation draws on stand, so that what is found wrong with
/// their values after parsing (an overflow, a missing value) is shown at the statement.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Places {
    /// Each `body` statement, in the order of [`Scene::parts`].
    pub body: Vec<Span>,
    /// The `omega` statement.
    pub omega: Option<Span>,
    /// Each `force` statement, in the order of [`Scene::forces`].
    pub forces: Vec<Span>,
    /// Each `couple` statement, in the order of [`Scene::couples`].
    pub couples: Vec<Span>,
    /// The first `before` statement (the state before an impact: the scene needs one).
    pub before: Option<Span>,
    /// The first `impulse` statement (an impact: the scene must leave something to find).
    pub impulse: Option<Span>,
    /// The `omegadot` statement.
    pub omega_dot: Option<Span>,
    /// The `frame` statement (`frame rate = ...` or `frame body-fixed`).
    pub frame: Option<Span>,
}

/// `euler angles` (§18.9): the frame Oxyz follows the body's axis of symmetry z but not its
/// spin, and the motion is given by the Eulerian angles φ (precession about the fixed
/// vertical Z), θ (nutation), ψ (spin) and their rates, each a given or an unknown:
/// `Ω = φ̇ K + θ̇ i`, `ω = Ω + ψ̇ k`, `K = sin θ j + cos θ k`
/// ([`crate::mechanics::eulerian_angles`]). `steady` is steady precession:
/// `θ̇ = φ̈ = θ̈ = ψ̈ = 0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EulerAnglesStatement {
    pub steady: bool,
    pub span: Span,
}

impl EulerAnglesStatement {
    /// The angles' chapter names (`phi`, `theta`, `psi`).
    pub fn angles() -> EulerianAngles {
        EulerianAngles::chapter()
    }

    /// The symbols of the kinematics: θ and the six rates (φ and ψ themselves do not enter
    /// ω, ω̇ or Ω).
    pub fn symbols() -> [Symbol; 7] {
        let a = Self::angles();
        let [phi, theta, psi] = [a.precession, a.nutation, a.spin];
        [
            theta,
            phi.dot(),
            theta.dot(),
            psi.dot(),
            phi.dot().dot(),
            theta.dot().dot(),
            psi.dot().dot(),
        ]
    }

    /// The rates steady precession makes zero: `θ̇, φ̈, θ̈, ψ̈` (none without `steady`).
    pub fn zero(&self) -> Vec<Symbol> {
        let a = Self::angles();
        match self.steady {
            true => vec![
                a.nutation.dot(),
                a.precession.dot().dot(),
                a.nutation.dot().dot(),
                a.spin.dot().dot(),
            ],
            false => vec![],
        }
    }

    /// The symbols the scene must declare, as givens or unknowns.
    pub fn declared(&self) -> Vec<Symbol> {
        let zero = self.zero();
        Self::symbols()
            .into_iter()
            .filter(|s| !zero.contains(s))
            .collect()
    }
}

/// A given's value as written: its number (`0.3`, `1.5e5`, `-2`) and its unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    pub number: String,
    pub unit: NamedUnit,
}

/// `20 kg`, `6 N·m`, `0.5` (no unit).
impl std::fmt::Display for Written {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.unit.is_none() {
            true => f.write_str(&self.number),
            false => write!(f, "{} {}", self.number, self.unit),
        }
    }
}

/// A given quantity: symbolic, or with a value converted to the scene's unit system.
#[derive(Debug, Clone, PartialEq)]
pub struct Given {
    pub symbol: Symbol,
    pub dimension: Dimension,
    /// The value in the scene's unit system (`unit_system.rs`), if the scene gives one.
    pub value: Option<f64>,
    /// The value as written (`20 kg`), for the worked solution.
    pub written: Option<Written>,
    /// `given psidot = v/r_w`: the given defined by earlier givens.
    pub definition: Option<Definition>,
    /// Positive for a given in kg, m, s, N or kg·m² not written `real` and not negative;
    /// real otherwise (`parse/given.rs`).
    pub domain: Domain,
    /// Where the given's name stands, for errors found where it is used.
    pub span: Span,
}

/// A given defined by earlier givens: the expression in their names (in the scene's units), and its exact
/// value when each of them has one (their exact values put in when it was read, so a chain of
/// definitions is worked out once, not again at each use).
#[derive(Debug, Clone, PartialEq)]
pub struct Definition {
    pub expr: Expr,
    pub exact: Option<Expr>,
}

/// A part of the body: a standard shape with its mass, the position of its mass centre,
/// and the rotation that takes its own axes to the frame's (`frame = R · own`), with the
/// turns about an axis the scene states it by (`rotated beta about z`), for the figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    pub shape: Shape,
    pub mass: Expr,
    pub position: Vector,
    pub rotation: crate::algebra::Matrix,
    pub turns: Vec<Turn>,
}

/// A turn of a part through `angle` about the frame's direction `axis`, from the orientation
/// `from` (the rotation before it): `rotation = R_axis(angle) · from`.
#[derive(Debug, Clone, PartialEq)]
pub struct Turn {
    pub angle: Expr,
    pub axis: Vector,
    pub from: crate::algebra::Matrix,
}

impl Part {
    /// The part as mechanics takes it: its centroidal inertia turned into the frame's axes.
    pub fn mass_part(&self) -> Result<MassPart, AlgebraError> {
        Ok(MassPart {
            mass: self.mass.clone(),
            position: self.position.clone(),
            inertia: self
                .shape
                .centroidal_inertia(&self.mass)?
                .rotated(&self.rotation)?,
        })
    }
}

/// A force with its point of application.
#[derive(Debug, Clone, PartialEq)]
pub struct Force {
    pub name: String,
    pub value: Vector,
    pub point: Vector,
}

/// A fixed support the scene draws round the body: a taut wire it hangs from (`wire from P
/// to Q`, from its point on the body to its anchor), or a post it strikes or rests on (`post
/// from P to Q`, from its base to its top). The figure draws it; the equations take what it
/// does from the constraints, loads and impulses the scene states (SP 18.1's wires keep v̄_y
/// and ω_z zero; a post's blow is the impulse at its top).
#[derive(Debug, Clone, PartialEq)]
pub struct Support {
    pub kind: SupportKind,
    pub from: Vector,
    pub to: Vector,
}

/// What a [`Support`] is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SupportKind {
    Wire,
    Post,
}

/// A body point named by the scene (`point A at (x, y, z)`), whose velocity `v_A` and
/// acceleration `a_A` a scene can ask for.
#[derive(Debug, Clone, PartialEq)]
pub struct NamedPoint {
    /// As written: `A`, `P1` (its velocity's components are `v_Ax`, `v_P1x`).
    pub name: String,
    pub position: Vector,
}

/// An impulse `F Δt` at its point, named when the scene asks for it (`impulse R = ... at`).
#[derive(Debug, Clone, PartialEq)]
pub struct Impulse {
    pub name: Option<Symbol>,
    pub value: Vector,
    pub point: Vector,
}

/// A kinematic condition.
#[derive(Debug, Clone, PartialEq)]
pub enum ConstraintKind {
    /// The body point at this position has zero velocity (rolling contact, a pin).
    VelocityZero(Vector),
    /// `lhs = rhs` among the kinematic quantities.
    Equation(Expr, Expr),
}

/// A kinematic condition and where the scene states it.
#[derive(Debug, Clone, PartialEq)]
pub struct Constraint {
    pub kind: ConstraintKind,
    pub span: Span,
}

/// A quantity a scene can ask for with `find`: one of the chapter's quantities by its ASCII
/// name, or a declared unknown. Decided once, when the scene is parsed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// `omega`: the angular velocity ω.
    AngularVelocity,
    /// `vbar`: the velocity v̄ of the mass centre.
    MassCentreVelocity,
    /// `mvbar` (or `m*vbar`): the linear momentum m v̄.
    LinearMomentum,
    /// `abar`: the acceleration ā of the mass centre.
    MassCentreAcceleration,
    /// `mabar` (or `m*abar`): the effective force m ā.
    EffectiveForce,
    /// `H_G`: the angular momentum about the mass centre.
    AngularMomentumAboutG,
    /// `H_O`: the angular momentum about the origin O.
    AngularMomentumAboutO,
    /// `T`: the kinetic energy.
    KineticEnergy,
    /// `Hdot_G`: the rate of change of the angular momentum about G.
    RateOfAngularMomentum,
    /// `Hdot_O`: the rate of change of the angular momentum about the fixed point O.
    RateOfAngularMomentumAboutO,
    /// `T_trans`, `T_rot`: the kinetic energy of the motion of G, and of the rotation about G.
    TranslationalKineticEnergy,
    RotationalKineticEnergy,
    /// `T_1`, `T_2`: in an impact, the kinetic energy just before and just after the blow
    /// (`T_2` is `T`); `T_lost = T_1 − T_2`.
    KineticEnergyBefore,
    KineticEnergyAfter,
    EnergyLost,
    /// `v_A`, `a_A`: the velocity and acceleration of the named point A.
    PointVelocity(Symbol),
    PointAcceleration(Symbol),
    /// A named impulse with its unknown components solved (`impulse R = ... at`, `find R`).
    NamedImpulse(Symbol),
    /// A named force (`force R = R_x*i + R_y*j at ...`, `find R`): its vector, the unknowns
    /// among its components solved.
    NamedForce(Symbol),
    /// `I_G`, `I_O`: the inertia tensor `[I]` about G, about O (the frame's axes).
    InertiaAboutG,
    InertiaAboutO,
    /// `principal_G`, `principal_O`: principal moments (ascending) and axes about G, about O.
    PrincipalAboutG,
    PrincipalAboutO,
    /// A declared unknown, solved from the equations of the scene.
    Unknown(Symbol),
    /// `balance in planes z = a, z = b at radius r`: two correction masses ([`Scene::balance`]).
    Balance,
    /// `precession`: with `euler angles` and no loads, the angle γ between ω and the axis
    /// and the sense of the torque-free precession (direct or retrograde).
    Precession,
}

impl Quantity {
    /// The chapter's quantities by the names a scene writes them with.
    pub const NAMED: [(&'static str, Quantity); 22] = [
        ("omega", Quantity::AngularVelocity),
        ("vbar", Quantity::MassCentreVelocity),
        ("mvbar", Quantity::LinearMomentum),
        ("m*vbar", Quantity::LinearMomentum),
        ("abar", Quantity::MassCentreAcceleration),
        ("mabar", Quantity::EffectiveForce),
        ("m*abar", Quantity::EffectiveForce),
        ("H_G", Quantity::AngularMomentumAboutG),
        ("H_O", Quantity::AngularMomentumAboutO),
        ("T", Quantity::KineticEnergy),
        ("Hdot_G", Quantity::RateOfAngularMomentum),
        ("Hdot_O", Quantity::RateOfAngularMomentumAboutO),
        ("T_trans", Quantity::TranslationalKineticEnergy),
        ("T_rot", Quantity::RotationalKineticEnergy),
        ("T_1", Quantity::KineticEnergyBefore),
        ("T_2", Quantity::KineticEnergyAfter),
        ("T_lost", Quantity::EnergyLost),
        ("I_G", Quantity::InertiaAboutG),
        ("I_O", Quantity::InertiaAboutO),
        ("principal_G", Quantity::PrincipalAboutG),
        ("principal_O", Quantity::PrincipalAboutO),
        ("precession", Quantity::Precession),
    ];

    /// What the quantity is, in words (`the kinetic energy`).
    pub fn description(self) -> &'static str {
        match self {
            Quantity::AngularVelocity => "the angular velocity",
            Quantity::MassCentreVelocity => "the velocity of the mass centre",
            Quantity::LinearMomentum => "the linear momentum",
            Quantity::MassCentreAcceleration => "the acceleration of the mass centre",
            Quantity::EffectiveForce => "the effective force m ā",
            Quantity::AngularMomentumAboutG => "the angular momentum about G",
            Quantity::AngularMomentumAboutO => "the angular momentum about O",
            Quantity::KineticEnergy => "the kinetic energy",
            Quantity::RateOfAngularMomentum => "the rate of change of the angular momentum about G",
            Quantity::RateOfAngularMomentumAboutO => {
                "the rate of change of the angular momentum about O"
            }
            Quantity::TranslationalKineticEnergy => "the kinetic energy of translation",
            Quantity::RotationalKineticEnergy => "the kinetic energy of rotation about G",
            Quantity::KineticEnergyBefore => "the kinetic energy just before the impact",
            Quantity::KineticEnergyAfter => "the kinetic energy just after the impact",
            Quantity::EnergyLost => "the kinetic energy lost in the impact",
            Quantity::PointVelocity(_) => "the velocity of a named point",
            Quantity::PointAcceleration(_) => "the acceleration of a named point",
            Quantity::NamedImpulse(_) => "a named impulse",
            Quantity::NamedForce(_) => "a named force",
            Quantity::InertiaAboutG => "the inertia tensor about G",
            Quantity::InertiaAboutO => "the inertia tensor about O",
            Quantity::PrincipalAboutG => "the principal moments and axes about G",
            Quantity::PrincipalAboutO => "the principal moments and axes about O",
            Quantity::Unknown(_) => "an unknown",
            Quantity::Balance => "the two-plane balance",
            Quantity::Precession => "the angle γ and the sense of the torque-free precession",
        }
    }

    /// The chapter's quantity with this name, if it is one.
    pub fn named(name: &str) -> Option<Quantity> {
        Quantity::NAMED
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, q)| *q)
    }
}

/// `find balance in planes z = a, z = b at radius r`: the shaft axis the planes are across,
/// the planes' positions along it and the radius of the correction masses.
#[derive(Debug, Clone, PartialEq)]
pub struct BalancePlanes {
    pub axis: crate::algebra::Axis,
    pub planes: (Expr, Expr),
    pub radius: Expr,
}

/// A quantity asked for, by the name written in the scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    pub quantity: Quantity,
    /// The name as written (`m*vbar`, `D_y`).
    pub name: String,
    pub span: Span,
    /// `find D_y in N`: the answer must be a number, given in this unit.
    pub unit: Option<NamedUnit>,
    /// The unit the result's number is shown in where no `in` asks for one: an unknown's
    /// declared unit (`unknown C_x : lb` shows C_x in lb when the givens make it a number).
    pub shown_in: Option<NamedUnit>,
    /// When the equations have several real solutions (a top's slow and fast precession) and
    /// this result differs between them: which solution (1, 2, …) this row is.
    pub solution: Option<usize>,
}

impl Request {
    /// The request as written: `T_BC in N`, `H_G`.
    pub fn as_written(&self) -> String {
        match &self.unit {
            Some(unit) => format!("{} in {unit}", self.name),
            None => self.name.clone(),
        }
    }
}

/// A whole scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub source_name: String,
    pub source: String,
    pub title: Option<String>,
    /// What the problem says, its `statement` lines in order (words with `$…$` mathematics,
    /// as a title), printed first on the worked solution.
    pub statement: Vec<String>,
    pub givens: Vec<Given>,
    pub parts: Vec<Part>,
    /// Whether the origin O is a fixed point of the body.
    pub fixed_point: bool,
    /// `up y`: the axis drawn up in the figure (the vertical of a problem whose axes have y
    /// up), where the scene says.
    pub up: Option<Axis>,
    /// `about G`: with a fixed point, derive about the mass centre G (`H_G`, then
    /// `H_O = H_G + r̄ × m v̄`, `ΣM_O = Ḣ_G + r̄ × m ā`) instead of about O with `[I_O]`.
    pub about_mass_centre: bool,
    /// `euler angles` (`steady`): ω, ω̇ and Ω come from the Eulerian angles' rates.
    pub euler_angles: Option<EulerAnglesStatement>,
    pub omega: Option<Vector>,
    /// Rates of ω's components as seen in the frame (`(dω/dt)_frame`).
    pub omega_dot: Option<Vector>,
    /// Angular velocity Ω of the frame; `None` means body-fixed (Ω = ω).
    pub frame_rate: Option<Vector>,
    /// Velocity of the mass centre, if given directly.
    pub vbar: Option<Vector>,
    /// `before vbar = ...`: the velocity of the mass centre just before an impact (at rest
    /// if not given).
    pub vbar_before: Option<Vector>,
    /// `before omega = ...`: the angular velocity just before an impact (0 if not given).
    pub omega_before: Option<Vector>,
    /// Acceleration of the mass centre, if given directly.
    pub abar: Option<Vector>,
    pub forces: Vec<Force>,
    pub couples: Vec<Vector>,
    /// Impulses `F Δt` and their points (an impact).
    pub impulses: Vec<Impulse>,
    /// The named body points (`point A at (x, y, z)`).
    pub points: Vec<NamedPoint>,
    /// The wires and posts round the body (`wire from ... to ...`, `post from ... to ...`),
    /// for the figure.
    pub supports: Vec<Support>,
    pub constraints: Vec<Constraint>,
    pub unknowns: Vec<(Symbol, Dimension)>,
    /// The unit each unknown was declared in, where one was written (`unknown C_x : lb`):
    /// its result's number is shown in it.
    pub unknown_units: Vec<(Symbol, NamedUnit)>,
    /// The unit system every value is in, and the page shows: the givens'
    /// (`unit_system.rs`), unless `--units` chose it when the scene was read
    /// ([`parse_scene_in`](super::parse_scene_in)). Set by reading; changing it after would
    /// leave the values in the other system.
    pub unit_system: UnitSystem,
    pub requests: Vec<Request>,
    /// Where `find balance ...` puts the correction masses.
    pub balance: Option<BalancePlanes>,
    pub places: Places,
}

impl Scene {
    /// The dimension of a declared symbol (π: none).
    pub fn dimension(&self, s: Symbol) -> Option<Dimension> {
        if s.is_pi() {
            return Some(Dimension::NONE);
        }
        self.givens
            .iter()
            .find(|g| g.symbol == s)
            .map(|g| g.dimension)
            .or_else(|| self.unknowns.iter().find(|u| u.0 == s).map(|u| u.1))
    }

    /// The value of a given in the scene's unit system, if it has one.
    pub fn value(&self, s: Symbol) -> Option<f64> {
        self.givens
            .iter()
            .find(|g| g.symbol == s)
            .and_then(|g| g.value)
    }

    /// The value of a given as the exact rational its value reads as in its shortest
    /// decimal form (`1e200`, `0.1`), for deciding exactly what the values make of a result.
    pub fn exact_value(&self, s: Symbol) -> Option<Q> {
        self.value(s).and_then(exact_decimal)
    }

    /// A given as the user wrote it, with its line, for a help text: `L = 0 m (given on
    /// line 9)`.
    pub fn cite(&self, given: &Given) -> String {
        let line = self.line_of(given.span);
        let written = given
            .written
            .as_ref()
            .map_or("no value".to_string(), ToString::to_string);
        format!("{} = {written} (given on line {line})", given.symbol.name())
    }

    /// The line (from 1) where `span` starts.
    pub fn line_of(&self, span: Span) -> usize {
        let start = self.source.floor_char_boundary(span.start);
        self.source[..start].matches('\n').count() + 1
    }

    /// The request at `at` (written `named`) has no finite value: with the givens' values, the
    /// expressions `e` it comes from divide by zero. The help names the givens of `e` whose
    /// value is zero.
    pub fn division_by_zero_at(&self, at: Span, named: &str, e: &Expr) -> Diagnostic {
        let zeros = self.cite_givens_in(e, |v| v == 0.0);
        let help = if zeros.is_empty() {
            "a divisor is zero with the values of the givens; check them".to_string()
        } else {
            format!("{} makes a divisor zero; check the value", zeros.join(", "))
        };
        let message =
            format!("{named} is not a finite number with the given values: it divides by zero");
        self.error_at(at, message, help)
    }

    /// The givens in `e` whose value makes `bad` true, cited (`d = 0 m (given on line 5)`).
    pub fn cite_givens_in(&self, e: &Expr, bad: impl Fn(f64) -> bool) -> Vec<String> {
        self.givens
            .iter()
            .filter(|g| e.contains(g.symbol) && g.value.is_some_and(&bad))
            .map(|g| self.cite(g))
            .collect()
    }

    /// Which symbols are positive: the chapter's defaults, then each given's domain.
    pub fn domains(&self) -> Domains {
        let mut domains = Domains::chapter_defaults();
        for given in &self.givens {
            domains.declare(given.symbol, given.domain);
        }
        domains
    }

    /// Whether the scene states the loads its motion follows from: a force, a couple or an
    /// impulse (or none at all, when it asks for a torque-free `precession`), on a body whose
    /// motion is stated (a fixed point, ā given, or v̄ after an impact). Its motion is then
    /// what ΣF = m ā and ΣM = Ḣ (impulse and momentum in an impact) allow.
    pub fn motion_follows_from_loads(&self) -> bool {
        let torque_free = self
            .requests
            .iter()
            .any(|r| r.quantity == Quantity::Precession);
        let impact = !self.impulses.is_empty();
        let loaded = !self.forces.is_empty() || !self.couples.is_empty() || impact;
        // ΣF = m ā needs ā (given, or from a fixed point); an impact needs v̄ after it.
        let motion_stated = self.fixed_point
            || match impact {
                true => self.vbar.is_some(),
                false => self.abar.is_some(),
            };
        (loaded || torque_free) && motion_stated && !self.parts.is_empty()
    }

    /// Whether the scene states a body under no force by its Eulerian angles and ā, with no
    /// load on it: its motion is what ΣM_G = Ḣ_G = 0 allows, `find precession` or not.
    pub fn under_no_force(&self) -> bool {
        self.euler_angles.is_some()
            && self.abar.is_some()
            && self.forces.is_empty()
            && self.couples.is_empty()
            && self.impulses.is_empty()
    }

    /// Whether the solution works about the fixed point O with `[I_O]`, as §18.7–18.8 do: the
    /// scene has a fixed point and does not ask for the centroidal route (`about G`).
    pub fn about_fixed_point(&self) -> bool {
        self.fixed_point && !self.about_mass_centre
    }

    /// The body's moments and products of inertia in the frame's axes and the point they are
    /// about: the fixed point O (the origin) when `about_o`, else the mass centre G.
    pub fn inertia_of_body(&self, about_o: bool) -> Result<(InertiaTensor, Vector), AlgebraError> {
        let parts: Vec<MassPart> = self
            .parts
            .iter()
            .map(Part::mass_part)
            .collect::<Result<_, _>>()?;
        Ok(if about_o {
            let inertia = inertia_about_fixed_point(&parts)?.0;
            (inertia, Vector::from_element(Expr::zero()))
        } else {
            let body = composite_body(&parts)?.0;
            (body.inertia, body.centroid)
        })
    }

    pub fn is_unknown(&self, s: Symbol) -> bool {
        self.unknowns.iter().any(|u| u.0 == s)
    }

    /// The located error at `at` in the scene's file, with what to do about it.
    pub fn error_at(
        &self,
        at: Span,
        message: impl Into<String>,
        help: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic::at(&self.source_name, &self.source, at.start, at.end, message).with_help(help)
    }

    /// For `map_err`: an algebra error met while deriving what the statement at `at` needs.
    pub fn algebra_error_at(&self, at: Span) -> impl Fn(AlgebraError) -> Diagnostic + '_ {
        move |e| self.error_at(at, e.to_string(), "simplify the scene")
    }
}
