//! A balance's results, a row each: the correction mass `m_k` (kg) and its angle `θ_k` about
//! the shaft axis, in degrees in the numbers: exact (`θ_1 = π/2 = 90°`), `tan θ_k = Q_k/P_k`
//! and the number `atan2(Q_k, P_k)` from the givens' values, or undefined (no correction,
//! in general or with the givens' values exactly).

use super::numbers::{format_value, value};
use super::render::{scalar, Result};
use crate::algebra::{Expr, Symbol};
use crate::mechanics::two_plane_balance::{Correction, CorrectionAngle};
use crate::scene::units::Dimension;
use crate::scene::{Scene, Value};
use std::borrow::Cow;

/// The rows of the two corrections, in the order m_1, θ_1, m_2, θ_2.
pub(super) fn rows<'a>(scene: &Scene, corrections: &[Correction; 2]) -> Vec<Result<'a>> {
    let mut rows = Vec::with_capacity(6);
    for correction in corrections {
        let k = &correction.label;
        // LaTeX's subscript: `\theta_1`, `\theta_{c1}`.
        let sub = if k.len() == 1 {
            k.clone()
        } else {
            format!("{{{k}}}")
        };
        let mass_unit = Some(Dimension::MASS.si_unit());
        rows.push(scalar(
            scene,
            Cow::Owned(format!("m_{k}")),
            format!("m_{sub}"),
            correction.mass.clone(),
            mass_unit,
        ));
        let (name, name_latex) = (format!("theta_{k}"), format!(r"\theta_{sub}"));
        let in_degrees = |radians: f64| radians.to_degrees();
        match &correction.angle {
            // Symbolically a correction, but none with the givens' values.
            _ if no_correction(scene, correction) => rows.push(undefined(name, name_latex)),
            CorrectionAngle::Exact(t) => {
                let mut row = scalar(scene, Cow::Owned(name), name_latex, t.clone(), None);
                row.value = row.value.map(|v| v.into_iter().map(in_degrees).collect());
                row.unit = Some("deg".into());
                rows.push(row);
            }
            CorrectionAngle::Atan2 { q, p } => {
                if let Ok(tangent) = q.checked_div(p) {
                    let tan_name = format!(r"\tan\theta_{sub}");
                    let named = Cow::Owned(format!("tan(theta_{k})"));
                    rows.push(scalar(scene, named, tan_name, tangent, None));
                }
                if let (Some(q), Some(p)) = (value(scene, q), value(scene, p)) {
                    let degrees = in_degrees(q.atan2(p));
                    rows.push(number(name, name_latex, degrees));
                }
            }
            CorrectionAngle::Undefined => rows.push(undefined(name, name_latex)),
        }
    }
    rows
}

/// Whether `P = Q = 0` exactly with the givens' values (each the decimal it reads as).
fn no_correction(scene: &Scene, correction: &Correction) -> bool {
    let exact = |s: Symbol| scene.exact_value(s).map(Expr::num);
    let zero = |e: &Expr| e.subs(&exact).is_ok_and(|v| v.is_zero());
    zero(&correction.p) && zero(&correction.q)
}

/// The angle of no correction.
fn undefined<'a>(name: String, name_latex: String) -> Result<'a> {
    in_words(name, name_latex, "undefined", r"\text{undefined}".into())
}

/// A result said in words (`text`; `latex`, its words in `\text{…}`), with no number.
pub(super) fn in_words<'a>(
    name: String,
    name_latex: String,
    text: &str,
    latex: String,
) -> Result<'a> {
    Result {
        name: Cow::Owned(name),
        name_latex,
        text: text.into(),
        latex,
        value: None,
        unit: None,
        form: None,
        grouped: None,
    }
}

/// An angle known only as a number, in degrees.
pub(super) fn number<'a>(name: String, name_latex: String, degrees: f64) -> Result<'a> {
    let text = format_value(degrees);
    Result {
        name: Cow::Owned(name),
        name_latex,
        latex: text.clone(),
        text,
        value: Some(vec![degrees]),
        unit: Some("deg".into()),
        form: None::<Cow<'a, Value>>,
        grouped: None,
    }
}
