//! The `euler angles` statement (§18.9): the frame Oxyz follows the body's axis of symmetry z
//! but not its spin, and ω, ω̇, Ω come from the Eulerian angles' rates. What it asks of the
//! rest of the scene is checked here:
//!
//! - `omega`, `omegadot` and `frame` are derived, so writing them too is refused;
//! - θ and the rates the kinematics use are declared (givens or unknowns) with the right
//!   units; with `steady`, `θ̇ = φ̈ = θ̈ = ψ̈ = 0` and they are not declared; without it a
//!   second rate (`phiddot`, `thetaddot`, `psiddot`) not declared is an unknown, which the
//!   equations of motion give (a top to simulate declares only its state);
//! - `K`, the fixed vertical, is `sin θ j + cos θ k` in the scene's mathematics;
//! - the body is axisymmetric about z (`I_x = I_y`, no product of inertia; about O with a
//!   fixed point, else about G): otherwise `[I]` would not be constant in Oxyz, which does
//!   not spin with the body.

use super::super::model::{EulerAnglesStatement, Span};
use super::super::units::Dimension;
use super::{span, Reader, Rule};
use crate::algebra::{Expr, Func, Symbol};
use crate::parse::Diagnostic;
use pest::iterators::Pair;

/// The name of the fixed vertical in the scene's mathematics.
const VERTICAL: &str = "K";

impl Reader<'_> {
    /// Reads `euler angles` (`steady`) at `at`.
    pub(super) fn euler_angles(
        &mut self,
        inner: &[Pair<Rule>],
        at: (usize, usize),
    ) -> Result<(), Diagnostic> {
        self.only_once(self.scene.euler_angles.is_some(), at)?;
        let places = &self.scene.places;
        if let Some(earlier) = [places.omega, places.omega_dot, places.frame]
            .into_iter()
            .flatten()
            .min_by_key(|p| p.start)
        {
            return Err(derived(self, (earlier.start, earlier.end)));
        }
        let statement = EulerAnglesStatement {
            steady: inner.iter().any(|p| p.as_rule() == Rule::steady),
            span: Span {
                start: at.0,
                end: at.1,
            },
        };
        if let Some(zero) = statement
            .zero()
            .into_iter()
            .find(|s| self.dims.contains_key(s))
        {
            return Err(self
                .error(
                    at,
                    format!(
                        "{} is declared, but 'euler angles steady' makes it zero",
                        zero.name()
                    ),
                )
                .with_help(
                    "remove its declaration: in steady precession thetadot = phiddot = thetaddot = psiddot = 0",
                ));
        }
        let vertical = Symbol::new(VERTICAL);
        if self.dims.contains_key(&vertical) {
            return Err(self
                .error(
                    at,
                    "K is declared, and with 'euler angles' K is the fixed vertical",
                )
                .with_help(
                    "rename the symbol K: with the Eulerian angles K = sin(theta)*j + cos(theta)*k",
                ));
        }
        self.dims.insert(vertical, Dimension::NONE);
        self.scene.euler_angles = Some(statement);
        Ok(())
    }

    /// `omega`, `omegadot` and `frame` at `at` are refused after `euler angles`.
    pub(super) fn not_derived_from_euler_angles(
        &self,
        at: (usize, usize),
    ) -> Result<(), Diagnostic> {
        match self.scene.euler_angles {
            Some(_) => Err(derived(self, at)),
            None => Ok(()),
        }
    }

    /// A name declared after `euler angles`: not `K`, nor a rate `steady` makes zero.
    pub(super) fn declarable_with_euler_angles(&self, name: &Pair<Rule>) -> Result<(), Diagnostic> {
        let Some(statement) = self.scene.euler_angles else {
            return Ok(());
        };
        let symbol = Symbol::new(name.as_str());
        if name.as_str() == VERTICAL {
            return Err(self
                .error(span(name), "with 'euler angles', K is the fixed vertical")
                .with_help("choose another name: K = sin(theta)*j + cos(theta)*k"));
        }
        if statement.zero().contains(&symbol) {
            return Err(self
                .error(
                    span(name),
                    format!("'euler angles steady' makes {} zero", name.as_str()),
                )
                .with_help(
                    "remove this declaration: in steady precession thetadot = phiddot = thetaddot = psiddot = 0",
                ));
        }
        Ok(())
    }

    /// `e` with the vertical `K` written as `sin θ j + cos θ k` (θ declared before).
    pub(super) fn vertical_in(&self, e: Expr, at: (usize, usize)) -> Result<Expr, Diagnostic> {
        let vertical = Symbol::new(VERTICAL);
        if self.scene.euler_angles.is_none() || !e.contains(vertical) {
            return Ok(e);
        }
        let theta = EulerAnglesStatement::angles().nutation;
        if !self.dims.contains_key(&theta) {
            return Err(self
                .error(
                    at,
                    "K is sin(theta)*j + cos(theta)*k, and theta is not declared yet",
                )
                .with_help(
                    "declare theta before this line: 'given theta = 30 deg' or 'unknown theta'",
                ));
        }
        if let Some(d) = self.dims.get(&theta).filter(|d| **d != Dimension::NONE) {
            return Err(self
                .error(
                    at,
                    format!(
                        "K is sin(theta)*j + cos(theta)*k, and theta is in {}, not an angle",
                        self.unit_of(*d)
                    ),
                )
                .with_help("declare theta in deg (or rad): 'given theta = 30 deg'"));
        }
        let theta = Expr::sym(theta);
        let k = Expr::func(Func::Sin, theta.clone()) * Expr::symbol("j")
            + Expr::func(Func::Cos, theta) * Expr::symbol("k");
        e.subs(&|s| (s == vertical).then(|| k.clone()))
            .map_err(|err| {
                self.error(at, err.to_string())
                    .with_help("simplify the expression")
            })
    }

    /// At the end of the file: the angles and first rates are declared with their units, a
    /// second rate not declared is an unknown, and the body is axisymmetric about z.
    pub(super) fn euler_angles_complete(&mut self) -> Result<(), Diagnostic> {
        let Some(statement) = self.scene.euler_angles else {
            return Ok(());
        };
        let at = (statement.span.start, statement.span.end);
        for s in statement.declared() {
            if s.dots() == 2 && self.scene.dimension(s).is_none() {
                self.scene
                    .unknowns
                    .push((s, Dimension::ANGULAR_ACCELERATION));
            }
            let want = match s.dots() {
                0 => Dimension::NONE,
                1 => Dimension::ANGULAR_VELOCITY,
                _ => Dimension::ANGULAR_ACCELERATION,
            };
            let unit = match s.dots() {
                0 => "deg",
                1 => "rpm",
                _ => "rad/s^2",
            };
            let name = s.name();
            match self.scene.dimension(s) {
                None => {
                    return Err(self
                        .error(at, format!("the Eulerian angles need {name}, which is not declared"))
                        .with_help(format!(
                            "declare it: 'given {name} = <value> {unit}', 'given {name} : {unit}' or 'unknown {name}'"
                        )))
                }
                Some(d) if d != want => {
                    let given = self.scene.givens.iter().find(|g| g.symbol == s);
                    let place = given.map_or(at, |g| (g.span.start, g.span.end));
                    return Err(self
                        .error(place, format!("{name} is in {}, and an Eulerian {} is in {}", self.unit_of(d), what(s), self.unit_of(want)))
                        .with_help(format!("declare {name} in {unit}")));
                }
                Some(_) => {}
            }
        }
        self.axisymmetric_about_z()
    }

    /// `I_x = I_y` and no product of inertia (about O with a fixed point, else G), decided
    /// symbolically or, failing that, with the givens' exact values.
    fn axisymmetric_about_z(&self) -> Result<(), Diagnostic> {
        let scene = &self.scene;
        let Some(first) = scene.places.body.first() else {
            return Ok(());
        };
        let at = (first.start, first.end);
        let algebra = |e: crate::algebra::AlgebraError| {
            self.error(at, e.to_string()).with_help("simplify the body")
        };
        let about_o = scene.about_fixed_point();
        let inertia = scene.inertia_of_body(about_o).map_err(algebra)?.0;
        let about = if about_o { "O" } else { "G" };
        let [i_x, i_y, _] = &inertia.moments;
        let is_zero = |e: &Expr| scene.is_exactly_zero(e);
        let broken = if !is_zero(&(i_x - i_y)) {
            Some(format!("I_x ≠ I_y about {about}"))
        } else {
            ["I_xy", "I_yz", "I_xz"]
                .into_iter()
                .zip(&inertia.products)
                .find(|(_, p)| !is_zero(p))
                .map(|(name, _)| format!("the product of inertia {name} about {about} is not zero"))
        };
        match broken {
            None => Ok(()),
            Some(reason) => Err(self
                .error(at, format!("the body is not axisymmetric about z: {reason}"))
                .with_help(
                    "with 'euler angles' the frame Oxyz follows the axis z but not the spin, so [I] is constant in it only for a body symmetric about z: put the axis of symmetry along z (disk(r) ... along z) with the mass centre on it",
                )),
        }
    }
}

/// `omega`, `omegadot` or `frame` at `at`, with `euler angles`.
fn derived(reader: &Reader, at: (usize, usize)) -> Diagnostic {
    let keyword = reader.source[at.0..at.1]
        .split_whitespace()
        .next()
        .unwrap_or_default();
    reader
        .error(
            at,
            format!("with 'euler angles', {keyword} is derived from the Eulerian angles' rates"),
        )
        .with_help(
            "remove this line: omega = thetadot i + phidot sin(theta) j + (psidot + phidot cos(theta)) k, and the frame turns at Omega = phidot K + thetadot i",
        )
}

/// What an Eulerian symbol is: the angle, its rate, its second rate.
fn what(s: Symbol) -> &'static str {
    match s.dots() {
        0 => "angle",
        1 => "rate",
        _ => "second rate",
    }
}

#[cfg(test)]
mod tests {
    use crate::parse::parse_expression;
    use crate::scene::parse_scene;
    use crate::scene::units::Dimension;

    const TOP: &str = "given m = 2 kg
given r = 100 mm
given c = 150 mm
given g = 9.81 m/s^2
given theta = 30 deg
given psidot = 1200 rpm
unknown phidot
euler angles steady
fixed point
body disk(r) mass m at (0, 0, c) along z
force W = -m*g*K at (0, 0, c)
find phidot";

    #[test]
    fn the_statement_is_stored_and_k_is_the_vertical_in_oxyz() {
        let scene = parse_scene("top.scene", TOP).unwrap();
        let statement = scene.euler_angles.expect("the statement is stored");
        assert!(statement.steady);
        assert_eq!(
            &TOP[statement.span.start..statement.span.end],
            "euler angles steady"
        );
        let hand = |t: &str| parse_expression("by hand", t).unwrap();
        let weight = &scene.forces[0].value;
        assert!(weight[0].is_zero());
        assert_eq!(weight[1], hand("-m g sin(theta)"));
        assert_eq!(weight[2], hand("-m g cos(theta)"));
        let names: Vec<String> = statement
            .zero()
            .iter()
            .map(|s| s.name().to_string())
            .collect();
        assert_eq!(names, ["thetadot", "phiddot", "thetaddot", "psiddot"]);
    }

    #[test]
    fn without_steady_every_rate_is_declared_and_none_is_zero() {
        let general = TOP.replace("euler angles steady", "euler angles");
        let error = parse_scene("top.scene", &general).unwrap_err();
        assert!(error.message.contains("need thetadot"), "{}", error.message);
        let declared = general.replace(
            "unknown phidot",
            "unknown phidot\ngiven thetadot = 0 rad/s\ngiven phiddot = 0 rad/s^2",
        );
        let scene = parse_scene("top.scene", &declared).unwrap();
        assert!(scene
            .euler_angles
            .is_some_and(|s| !s.steady && s.zero().is_empty()));
        assert_eq!(scene.omega, None::<crate::algebra::Vector>);
        // The second rates not declared are unknowns, in rad/s².
        let implicit: Vec<&str> = scene
            .unknowns
            .iter()
            .filter(|u| u.1 == Dimension::ANGULAR_ACCELERATION)
            .map(|u| u.0.name())
            .collect();
        assert_eq!(implicit, ["thetaddot", "psiddot"]);
    }
}
