//! No answer without its equations of motion. A scene that states its loads (a force, a
//! couple or an impulse; or none at all, when it asks for a torque-free `precession`) has the
//! motion it reports checked against them:
//!
//! ```text
//! ΣF − m ā = 0,   ΣM − Ḣ = 0                     (each component)
//! m v̄₁ + ΣF Δt − m v̄₂ = 0,   H₁ + Σ r × F Δt − H₂ = 0      (an impact)
//! ```
//!
//! Where those equations solved the unknowns they hold by construction (the solver refuses
//! a contradiction). Where the givens and the constraints fixed the motion alone, they are
//! formed here, after every request, with the constraints' values put in, and each residual
//! must vanish: exactly (one fraction, its numerator in single angles, sin² + cos² = 1), or
//! within round-off with the givens' values (an identity the exact route missed). A
//! component that holds an unknown the constraints leave open is an equation for that
//! unknown, not a statement about the motion, and is left alone. The check's steps are not
//! on the page: it adds nothing to a motion that obeys its loads.

use super::super::model::{Quantity, Scene, Span};
use super::super::units::{dimension_with, Dimension};
use super::Analyser;
use crate::algebra::{
    four_significant_figures, significant_figures, AlgebraError, Axis, Expr, Symbol,
};
use crate::mechanics::derivation::Relation;
use crate::parse::Diagnostic;

/// A residual this small beside its largest term is round-off, not a missing load.
const ROUND_OFF: f64 = 1e-9;

/// A relation longer than this is not quoted in the message (its residual's value is).
const QUOTED_RELATION_CHARS: usize = 120;

impl Analyser<'_> {
    /// Refuses, at the constraint that fixed the motion (else the first load, else the first
    /// request), a motion the scene's loads cannot produce; see the module documentation.
    pub(super) fn motion_obeys_loads(&mut self) -> Result<(), Diagnostic> {
        let scene = self.scene;
        let torque_free = scene
            .requests
            .iter()
            .any(|r| r.quantity == Quantity::Precession);
        let solved_by_them = self.unknowns.is_some();
        if solved_by_them || !scene.motion_follows_from_loads() {
            return Ok(());
        }
        let places = &scene.places;
        let at = scene
            .constraints
            .first()
            .map(|c| c.span)
            .or_else(|| places.forces.first().or(places.couples.first()).copied())
            .or_else(|| scene.requests.first().map(|r| r.span))
            .unwrap_or_default();
        let shown = self.plan.len();
        let derivation = match !scene.impulses.is_empty() {
            true => self.impulse_momentum(at)?,
            false => self.equations_of_motion(at)?,
        };
        self.plan.truncate(shown);
        for relation in derivation.result() {
            let residual = self.known(&relation.residual()).map_err(self.algebra(at))?;
            if scene.unknowns.iter().any(|u| residual.contains(u.0)) {
                continue;
            }
            if let Some(off) = violation(scene, &residual).map_err(self.algebra(at))? {
                return Err(self.violated(at, relation, &residual, off, torque_free));
            }
        }
        Ok(())
    }

    /// The refusal: which equation, about which axis, is out by how much, and what to change.
    fn violated(
        &self,
        at: Span,
        relation: &Relation,
        residual: &Expr,
        (value, scale): (f64, f64),
        torque_free: bool,
    ) -> Diagnostic {
        let scene = self.scene;
        let dimension = dimension_with(residual, &|s| scene.dimension(s)).ok();
        let equation = equation_named(scene, dimension, relation.axis);
        let written = format!("{} = {}", relation.lhs, relation.rhs);
        let quoted = match written.chars().count() <= QUOTED_RELATION_CHARS {
            true => format!(" ({written})"),
            false => String::new(),
        };
        let unit = dimension.map_or(String::new(), |d| format!(" {}", d.si_unit()));
        let fixed: Vec<&str> = self
            .kinematics
            .as_ref()
            .map(|k| k.solved.iter().map(|(u, _)| u.name()).collect())
            .unwrap_or_default();
        let by = match fixed.is_empty() {
            true => "the givens".to_string(),
            false => format!("the constraints (they fix {})", fixed.join(", ")),
        };
        let message = format!(
            "this motion does not satisfy {equation}{quoted}: with the givens' values its two sides differ by {}{unit} ({} of its largest term); {by} state a motion the scene's loads cannot produce",
            four_significant_figures(value.abs()),
            percentage(value.abs() / scale),
        );
        let help = match torque_free {
            true => "under no force the motion must satisfy ΣM_G = Ḣ_G = 0, which ties the axis's angle θ to γ (tan γ = (I/I') tan θ) and the rates to each other: give fewer of them (make one an unknown), or drop a constraint",
            false => "drop a constraint or a given that over-states the motion (or make one of its quantities an unknown), or add the load that drives it",
        };
        scene.error_at(at, message, help)
    }
}

/// The equation a residual of this dimension comes from, about `axis`: `ΣM_G = Ḣ_G (x)`.
pub(super) fn equation_named(scene: &Scene, dimension: Option<Dimension>, axis: Axis) -> String {
    let linear_impulse = Dimension::new(1, 1, -1);
    let angular_impulse = Dimension::new(1, 2, -1);
    let name = match dimension {
        Some(Dimension::FORCE) => "ΣF = m ā",
        Some(Dimension::MOMENT) => match (scene.fixed_point, scene.about_mass_centre) {
            (true, false) => "ΣM_O = Ḣ_O",
            (true, true) => "ΣM_O = Ḣ_G + r̄ × m ā",
            (false, _) => "ΣM_G = Ḣ_G",
        },
        Some(d) if d == linear_impulse => "m v̄₁ + ΣF Δt = m v̄₂",
        Some(d) if d == angular_impulse => "H₁ + Σ r × F Δt = H₂",
        _ => "the equations of motion",
    };
    let axis = ['x', 'y', 'z'][axis as usize];
    format!("{name} about {axis}")
}

/// A fraction as a percentage in two significant figures (`0.021 %`, `35 %`).
fn percentage(fraction: f64) -> String {
    format!("{} %", significant_figures(100.0 * fraction, 2))
}

/// The residual's value with the givens' values and its largest term's size, when it is not
/// zero (see the module documentation); givens without a value take fixed generic ones.
fn violation(scene: &Scene, residual: &Expr) -> Result<Option<(f64, f64)>, AlgebraError> {
    let terms = residual.expand()?;
    if terms.is_zero() {
        return Ok(None);
    }
    let exact = residual.subs(&|s| scene.exact_given(s))?;
    let numerator = exact.together_parts()?.0;
    if numerator
        .in_single_angles()?
        .expand()?
        .simplify_trig()?
        .is_zero()
    {
        return Ok(None);
    }
    let value = |s: Symbol| {
        scene.value(s).or_else(|| {
            let k = scene.givens.iter().position(|g| g.symbol == s)?;
            Some(1.0 + 0.618_033_988_75 * (k + 1) as f64 % 1.0)
        })
    };
    let Ok(r) = residual.eval(&value) else {
        return Ok(None);
    };
    let scale = terms
        .terms()
        .iter()
        .filter_map(|t| t.eval(&value).ok())
        .fold(0.0_f64, |m, t: f64| m.max(t.abs()));
    Ok((r.abs() > ROUND_OFF * scale).then_some((r, scale)))
}
