//! What a scene file says, after parsing and checking: givens, the body, its kinematics,
//! loads, constraints, unknowns and requests. Positions are from the origin O of the
//! reference frame; vectors are components in that frame.

use super::units::Dimension;
use crate::algebra::{Expr, Symbol, Vector};
use crate::mechanics::shapes::Shape;

/// Where a statement stands in the scene file, for diagnostics after parsing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Span {
    pub start: usize,
    pub end: usize,
}

/// A given quantity: symbolic, or with a value converted to SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Given {
    pub symbol: Symbol,
    pub dimension: Dimension,
    /// The value in SI units, if the scene gives one.
    pub value: Option<f64>,
    /// The value as written (`20 kg`), for the worked solution.
    pub written: Option<String>,
}

/// A part of the body: a standard shape with its mass, the position of its mass centre,
/// and the rotation that takes its own axes to the frame's (`frame = R · own`).
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    pub shape: Shape,
    pub mass: Expr,
    pub position: Vector,
    pub rotation: crate::algebra::Matrix,
}

/// A force with its point of application.
#[derive(Debug, Clone, PartialEq)]
pub struct Force {
    pub name: String,
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

/// A quantity asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    pub name: String,
    pub span: Span,
    /// `find D_y in N`: the answer must be a number, given in this unit (as written).
    pub unit: Option<(String, super::units::Unit)>,
}

impl Request {
    /// A request-like place in the file (a constraint, the whole file) for diagnostics.
    pub fn at(name: &str, span: Span) -> Request {
        Request {
            name: name.to_string(),
            span,
            unit: None,
        }
    }
}

/// A whole scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub source_name: String,
    pub source: String,
    pub title: Option<String>,
    pub givens: Vec<Given>,
    pub parts: Vec<Part>,
    /// Whether the origin O is a fixed point of the body.
    pub fixed_point: bool,
    pub omega: Option<Vector>,
    /// Rates of ω's components as seen in the frame (`(dω/dt)_frame`).
    pub omega_dot: Option<Vector>,
    /// Angular velocity Ω of the frame; `None` means body-fixed (Ω = ω).
    pub frame_rate: Option<Vector>,
    /// Velocity of the mass centre, if given directly.
    pub vbar: Option<Vector>,
    /// Acceleration of the mass centre, if given directly.
    pub abar: Option<Vector>,
    pub forces: Vec<Force>,
    pub couples: Vec<Vector>,
    /// Impulses `F Δt` and their points (an impact from rest).
    pub impulses: Vec<(Vector, Vector)>,
    pub constraints: Vec<Constraint>,
    pub unknowns: Vec<(Symbol, Dimension)>,
    pub requests: Vec<Request>,
}

impl Scene {
    /// The dimension of a declared symbol.
    pub fn dimension(&self, s: Symbol) -> Option<Dimension> {
        self.givens
            .iter()
            .find(|g| g.symbol == s)
            .map(|g| g.dimension)
            .or_else(|| self.unknowns.iter().find(|u| u.0 == s).map(|u| u.1))
    }

    /// The SI value of a given, if it has one.
    pub fn value(&self, s: Symbol) -> Option<f64> {
        self.givens
            .iter()
            .find(|g| g.symbol == s)
            .and_then(|g| g.value)
    }

    pub fn is_unknown(&self, s: Symbol) -> bool {
        self.unknowns.iter().any(|u| u.0 == s)
    }
}
