//! The energy of an impact: `T_1` from the motion just before the blow (`before vbar`,
//! `before omega`; at rest when not given), `T_2` (the scene's `T`, just after it) and
//! `T_lost = T_1 − T_2`, each from a mechanics function.
//!
//! ```text
//! T₁ = ½ m v̄₁² + ½ {ω₁}ᵀ[Ī]{ω₁}        (about G; with a fixed point O and no v̄₁, ½ {ω₁}ᵀ[I_O]{ω₁})
//! T_lost = T₁ − T₂
//! ```

use super::super::model::Span;
use super::{zero_vector, Analyser};
use crate::algebra::Expr;
use crate::mechanics::derivation::{Relation, Step};
use crate::mechanics::kinematics::velocity_of_mass_centre;
use crate::mechanics::kinetic_energy::{energy_lost, kinetic_energy_before};
use crate::parse::Diagnostic;

impl Analyser<'_> {
    /// Refuses `name` (`T_1`, `T_2`, `T_lost`) in a scene without an impulse.
    pub(super) fn in_an_impact(&self, at: Span, name: &str) -> Result<(), Diagnostic> {
        match self.scene.impulses.is_empty() {
            true => Err(self.fail(
                at,
                format!("{name} is an energy of an impact (T_1 just before the blow, T_2 just after, T_lost their difference), and this scene has no impulse"),
                "ask for T, or state the blow: 'impulse F*Dt*i at (x, y, z)' with the motion before it ('before vbar = ...', 'before omega = ...')",
            )),
            false => Ok(()),
        }
    }

    /// `T_1`, the kinetic energy just before the impact.
    pub(super) fn energy_before(&mut self, at: Span) -> Result<Expr, Diagnostic> {
        self.in_an_impact(at, "T_1")?;
        if let Some(t) = &self.energy_before {
            return Ok(t.clone());
        }
        let scene = self.scene;
        let omega = scene.omega_before.clone().unwrap_or_else(zero_vector);
        // The motion before, as given: a body at rest unless a `before` line says otherwise.
        let at_rest = match (&scene.vbar_before, &scene.omega_before) {
            (None, None) => " (no `before` line: at rest)",
            _ => "",
        };
        let vbar_before = scene.vbar_before.clone().unwrap_or_else(zero_vector);
        self.plan.push(Step::new(
            format!("the motion just before the impact{at_rest}"),
            [
                Relation::components_named(&vbar_before, |axis| format!("vbar_1{axis}")),
                Relation::components_named(&omega, |axis| format!("omega_1{axis}")),
            ]
            .concat(),
        ));
        let d = if scene.about_fixed_point() && scene.vbar_before.is_none() {
            let inertia = self.inertia_about_o(at)?;
            kinetic_energy_before(&inertia, &omega, None)
        } else {
            let body = self.body(at)?.clone();
            let vbar = match (&scene.vbar_before, scene.fixed_point) {
                (Some(v), _) => v.clone(),
                (None, true) => {
                    let d = velocity_of_mass_centre(&omega, &body.centroid)
                        .map_err(self.algebra(at))?;
                    let v = d.result().iter().map(|r| r.rhs.clone());
                    crate::algebra::Vector::from_iterator(v)
                }
                (None, false) => zero_vector(),
            };
            kinetic_energy_before(&body.inertia, &omega, Some((&body.mass, &vbar)))
        }
        .map_err(self.algebra(at))?;
        let t = self.record(d).remove(0);
        self.energy_before = Some(t.clone());
        Ok(t)
    }

    /// `T_lost = T_1 − T_2`, `T_2` the kinetic energy just after the impact (`T`).
    pub(super) fn energy_lost(&mut self, at: Span) -> Result<Expr, Diagnostic> {
        self.in_an_impact(at, "T_lost")?;
        let before = self.energy_before(at)?;
        let after = self.kinetic_energy(at)?;
        let d = energy_lost(&before, &after).map_err(self.algebra(at))?;
        Ok(self.record(d).remove(0))
    }
}
