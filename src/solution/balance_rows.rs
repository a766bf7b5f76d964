//! A balance's results, a row each: the correction mass `m_k` (kg) and its angle `θ_k` about
//! the shaft axis, in degrees in the numbers: exact (`θ_1 = π/2 = 90°`), `tan θ_k = Q_k/P_k`
//! and the number `atan2(Q_k, P_k)` from the givens' values, or undefined (no correction,
//! in general or with the givens' values exactly).

use super::numbers::value;
use super::page::Name;
use super::result::{Line, Result};
use crate::algebra::{Expr, Symbol};
use crate::mechanics::two_plane_balance::{Correction, CorrectionAngle};
use crate::scene::named_unit::NamedUnit;
use crate::scene::units::Dimension;
use crate::scene::Scene;
use std::borrow::Cow;

/// The rows of the two corrections, in the order m_1, θ_1, m_2, θ_2.
pub(super) fn rows<'a>(scene: &Scene, corrections: &'a [Correction; 2]) -> Vec<Result<'a>> {
    let mut rows = Vec::with_capacity(6);
    for correction in corrections {
        let k = &correction.label;
        // LaTeX's subscript: `\theta_1`, `\theta_{c1}`.
        let sub = if k.len() == 1 {
            k.clone()
        } else {
            format!("{{{k}}}")
        };
        let named = |text: String, latex: String| Name { text, latex };
        let mass_unit = Some(scene.unit_system.unit(Dimension::MASS, false));
        let mass = named(format!("m_{k}"), format!("m_{sub}"));
        rows.push(Line::scalar(
            scene,
            mass,
            Cow::Borrowed(&correction.mass),
            mass_unit,
        ));
        let angle = named(format!("theta_{k}"), format!(r"\theta_{sub}"));
        match &correction.angle {
            // Symbolically a correction, but none with the givens' values.
            _ if no_correction(scene, correction) => rows.push(Line::words(angle, "undefined")),
            CorrectionAngle::Exact(t) => {
                let degrees = Some(NamedUnit::named("deg"));
                rows.push(Line::scalar(scene, angle, Cow::Borrowed(t), degrees));
            }
            CorrectionAngle::Atan2 { q, p } => {
                if let Ok(tangent) = q.checked_div(p) {
                    let name = named(format!("tan(theta_{k})"), format!(r"\tan\theta_{sub}"));
                    rows.push(Line::scalar(scene, name, Cow::Owned(tangent), None));
                }
                if let (Some(q), Some(p)) = (value(scene, q), value(scene, p)) {
                    let degrees = NamedUnit::named("deg");
                    rows.push(Line::number(angle, q.atan2(p).to_degrees(), degrees));
                }
            }
            CorrectionAngle::Undefined => rows.push(Line::words(angle, "undefined")),
        }
    }
    rows.into_iter().map(Result::line).collect()
}

/// Whether `P = Q = 0` exactly with the givens' values (each the decimal it reads as).
fn no_correction(scene: &Scene, correction: &Correction) -> bool {
    let exact = |s: Symbol| scene.exact_value(s).map(Expr::num);
    let zero = |e: &Expr| e.subs(&exact).is_ok_and(|v| v.is_zero());
    zero(&correction.p) && zero(&correction.q)
}
