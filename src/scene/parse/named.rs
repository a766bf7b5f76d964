//! Named things of a scene other than symbols: body points (`point A at (x, y, z)`, asked for
//! as `v_A` and `a_A`) and impulses (`impulse R = ... at (...)`, asked for as `R`), with the
//! state before the impact (`before vbar = ...`, `before omega = ...`). Forces, points and
//! impulses share one set of names, so that a name says which one it is.

use super::super::model::{Impulse, NamedPoint, Quantity};
use super::super::units::Dimension;
use super::{span, Reader, Rule};
use crate::algebra::Symbol;
use crate::parse::Diagnostic;
use pest::iterators::Pair;

/// The prefixes of the requests about a named point: its velocity and its acceleration.
const POINT_REQUESTS: [&str; 2] = ["v_", "a_"];

impl Reader<'_> {
    /// `point A at (x, y, z)`.
    pub(super) fn named_point(&mut self, inner: &[Pair<Rule>]) -> Result<(), Diagnostic> {
        let name = inner[0].as_str();
        self.unused_name(name, span(&inner[0]))?;
        let position = self.point(&inner[1])?;
        self.scene.points.push(NamedPoint {
            name: name.to_string(),
            position,
        });
        Ok(())
    }

    /// `impulse F*Dt*k at (...)`, or named: `impulse R = R_x*i + R_y*j at (...)`.
    pub(super) fn impulse(&mut self, inner: &[Pair<Rule>]) -> Result<(), Diagnostic> {
        let name = match inner.len() {
            3 => {
                self.unused_name(inner[0].as_str(), span(&inner[0]))?;
                Some(Symbol::new(inner[0].as_str()))
            }
            _ => None,
        };
        let [.., value, point] = inner else {
            return Err(self.error(span(&inner[0]), "expected an impulse and its point"));
        };
        let value = self.vector(value, Dimension::new(1, 1, -1))?;
        let point = self.point(point)?;
        self.scene.impulses.push(Impulse { name, value, point });
        Ok(())
    }

    /// `before vbar = ...` or `before omega = ...`: the motion just before an impact.
    pub(super) fn before(&mut self, p: &Pair<Rule>, at: (usize, usize)) -> Result<(), Diagnostic> {
        let (already, dimension) = match p.as_rule() {
            Rule::vbar => (self.scene.vbar_before.is_some(), Dimension::VELOCITY),
            _ => (
                self.scene.omega_before.is_some(),
                Dimension::ANGULAR_VELOCITY,
            ),
        };
        if already {
            return Err(self
                .error(
                    at,
                    format!(
                        "'before {}' is given twice",
                        p.as_str().split_whitespace().next().unwrap_or_default()
                    ),
                )
                .with_help("keep one of the two lines: the second would replace the first"));
        }
        let math = p.clone().into_inner().next();
        let math = math.ok_or_else(|| self.error(at, "expected a vector"))?;
        let v = Some(self.vector(&math, dimension)?);
        match p.as_rule() {
            Rule::vbar => self.scene.vbar_before = v,
            _ => self.scene.omega_before = v,
        }
        Ok(())
    }

    /// The state before an impact means nothing without the impulses of one; and an impulse
    /// determines the motion just after the blow only through the unknowns the scene
    /// declares (with none, impulse and momentum were never applied, and the motion as
    /// written, at rest by default, was reported as the answer).
    pub(super) fn impact_is_determined(&self) -> Result<(), Diagnostic> {
        match (self.scene.places.before, self.scene.places.impulse) {
            (Some(at), _) if self.scene.impulses.is_empty() => Err(self
                .error((at.start, at.end), "'before' describes the motion before an impact, and the scene has no impulse")
                .with_help("add the impulse of the blow ('impulse F*Dt*k at (x, y, z)'), or remove this line")),
            (_, Some(at)) if self.scene.unknowns.is_empty() => Err(self
                .error((at.start, at.end), "an impulse, and nothing for impulse and momentum to find: the scene declares no unknown")
                .with_help("declare the motion just after the blow as unknowns: 'unknown w_x, w_y, w_z : rad/s' with 'omega = w_x*i + w_y*j + w_z*k' (and vbar likewise)")),
            _ => Ok(()),
        }
    }

    /// A force, a point or an impulse may not take a name one of the others has.
    pub(super) fn unused_name(&self, name: &str, at: (usize, usize)) -> Result<(), Diagnostic> {
        let scene = &self.scene;
        let symbol = Symbol::new(name);
        let taken = if scene.forces.iter().any(|f| f.name == name) {
            Some("a force")
        } else if scene.points.iter().any(|p| p.name == name) {
            Some("a point")
        } else if scene.impulses.iter().any(|i| i.name == Some(symbol)) {
            Some("an impulse")
        } else {
            None
        };
        match taken {
            None => Ok(()),
            Some(kind) => Err(self
                .error(at, format!("{name} is already the name of {kind}"))
                .with_help("give each force, point and impulse its own name")),
        }
    }

    /// What a request names among the scene's points, impulses and forces: `v_A`, `a_A` of
    /// a named point A, a named impulse, or a named force.
    pub(super) fn named_request(&self, name: &str) -> Option<Quantity> {
        let scene = &self.scene;
        let symbol = Symbol::new(name);
        if scene.impulses.iter().any(|i| i.name == Some(symbol)) {
            return Some(Quantity::NamedImpulse(symbol));
        }
        if scene.forces.iter().any(|f| f.name == name) {
            return Some(Quantity::NamedForce(symbol));
        }
        let (prefix, point) = POINT_REQUESTS
            .iter()
            .find_map(|p| Some((*p, name.strip_prefix(p)?)))?;
        let point = scene.points.iter().find(|q| q.name == point)?;
        let point = Symbol::new(&point.name);
        Some(match prefix {
            "v_" => Quantity::PointVelocity(point),
            _ => Quantity::PointAcceleration(point),
        })
    }

    /// A request `v_B` or `a_B` (a capital after the prefix) for a point the scene does not
    /// name: refused with the names it knows.
    pub(super) fn unnamed_point(&self, name: &str, at: (usize, usize)) -> Option<Diagnostic> {
        let point = POINT_REQUESTS
            .iter()
            .find_map(|p| name.strip_prefix(p))
            .filter(|p| p.starts_with(|c: char| c.is_ascii_uppercase()))?;
        let known: Vec<&str> = self.scene.points.iter().map(|p| p.name.as_str()).collect();
        let help = if known.is_empty() {
            format!("name the point first: 'point {point} at (x, y, z)'")
        } else {
            format!(
                "the named points are {}; or name this one: 'point {point} at (x, y, z)'",
                known.join(", ")
            )
        };
        Some(
            self.error(at, format!("'{name}': no point is named {point}"))
                .with_help(help),
        )
    }
}
