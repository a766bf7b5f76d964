//! The named things a scene asks for: the velocity and acceleration of a named body point,
//! each from [`crate::mechanics::kinematics`] (about the fixed point O, or through the mass
//! centre G), and a named impulse, its unknown components solved with the rest.
//!
//! ```text
//! v_A = ω × r_A,            a_A = α × r_A + ω × (ω × r_A)                 (O fixed)
//! v_A = v̄ + ω × r_{A/G},    a_A = ā + α × r_{A/G} + ω × (ω × r_{A/G})     (otherwise)
//! ```

use super::super::model::Span;
use super::Analyser;
use crate::algebra::{Symbol, Vector};
use crate::mechanics::kinematics::{
    acceleration_of_body_point, velocity_of_body_point, BodyPoint, Through,
};
use crate::parse::Diagnostic;

impl<'a> Analyser<'a> {
    /// The position from O of the point the scene names `point`, and its name as written.
    fn named_point(&self, at: Span, point: Symbol) -> Result<(&'a str, Vector), Diagnostic> {
        let scene: &'a super::super::model::Scene = self.scene;
        scene
            .points
            .iter()
            .find(|p| Symbol::new(&p.name) == point)
            .map(|p| (p.name.as_str(), p.position.clone()))
            .ok_or_else(|| {
                self.fail(
                    at,
                    format!("no point is named {}", point.name()),
                    "name it first: 'point A at (x, y, z)'",
                )
            })
    }

    /// `v_A`: about the fixed point O, or from the velocity of G.
    pub(super) fn point_velocity(&mut self, at: Span, point: Symbol) -> Result<Vector, Diagnostic> {
        let (name, position) = self.named_point(at, point)?;
        let omega = self.kinematics(at)?.omega.clone();
        let d = if self.scene.fixed_point {
            velocity_of_body_point(
                BodyPoint::Named(name),
                &omega,
                &position,
                Through::FixedPoint,
            )
        } else {
            let motion = self.vbar(at)?;
            let position_g = self.mass_centre(at)?.centroid;
            let through = Through::MassCentre {
                position: &position_g,
                motion: &motion,
            };
            velocity_of_body_point(BodyPoint::Named(name), &omega, &position, through)
        };
        Ok(self.record_vector(d.map_err(self.algebra(at))?))
    }

    /// `a_A`, with the absolute angular acceleration α: about the fixed point O, or from the
    /// acceleration of G.
    pub(super) fn point_acceleration(
        &mut self,
        at: Span,
        point: Symbol,
    ) -> Result<Vector, Diagnostic> {
        let (name, position) = self.named_point(at, point)?;
        let k = self.kinematics(at)?;
        let (omega, omega_dot, frame) =
            (k.omega.clone(), k.omega_dot.clone(), k.frame_rate.clone());
        let point = BodyPoint::Named(name);
        let d = if self.scene.fixed_point {
            let through = Through::FixedPoint;
            acceleration_of_body_point(point, &omega, &omega_dot, &frame, &position, through)
        } else {
            let motion = self.abar(at)?;
            let position_g = self.mass_centre(at)?.centroid;
            let through = Through::MassCentre {
                position: &position_g,
                motion: &motion,
            };
            acceleration_of_body_point(point, &omega, &omega_dot, &frame, &position, through)
        };
        // The step shows α, then a_A: the acceleration is its last three relations.
        let relations = self.record(d.map_err(self.algebra(at))?);
        Ok(Vector::from_iterator(relations.into_iter().skip(3)))
    }

    /// A named force's vector as written (its unknowns solved with the other results).
    pub(super) fn named_force(&self, at: Span, name: Symbol) -> Result<Vector, Diagnostic> {
        let force = self.scene.forces.iter().find(|f| f.name == name.name());
        self.named_vector(at, name, "force", force.map(|f| &f.value))
    }

    /// A named impulse as the scene gives it; its unknown components are solved with the
    /// others when the result is put in the givens.
    pub(super) fn named_impulse(&self, at: Span, name: Symbol) -> Result<Vector, Diagnostic> {
        let impulse = self.scene.impulses.iter().find(|i| i.name == Some(name));
        self.named_vector(at, name, "impulse", impulse.map(|i| &i.value))
    }

    /// The vector of the `kind` (force, impulse) named `name`, or the error at `at` that
    /// says how to name one.
    fn named_vector(
        &self,
        at: Span,
        name: Symbol,
        kind: &str,
        found: Option<&Vector>,
    ) -> Result<Vector, Diagnostic> {
        found.cloned().ok_or_else(|| {
            self.fail(
                at,
                format!("no {kind} is named {}", name.name()),
                format!("name it: '{kind} R = R_x*i + R_y*j at (x, y, z)'"),
            )
        })
    }
}
