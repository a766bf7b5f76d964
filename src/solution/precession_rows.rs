//! A torque-free precession's results (`find precession`), a row each: `tan(gamma)`, the
//! tangent of the angle γ between ω and the axis of symmetry, `gamma` in degrees (the number
//! `atan` of its value, where the givens have values), and the sense in words, "direct
//! precession (I' > I)" or "retrograde precession (I' < I)" ("no precession (I' = I)": ω is
//! along H_G).

use super::numbers::value;
use super::page::Name;
use super::result::{Line, Result};
use crate::mechanics::torque_free_axisymmetric::{Precession, PrecessionSense};
use crate::scene::named_unit::NamedUnit;
use crate::scene::Scene;
use std::borrow::Cow;

/// The rows `tan(gamma)`, `gamma` (when it has a value) and `precession`.
pub(super) fn rows<'a>(scene: &Scene, precession: &'a Precession) -> Vec<Result<'a>> {
    let named = |text: &str, latex: &str| Name {
        text: text.into(),
        latex: latex.into(),
    };
    let tangent = &precession.tan_gamma;
    let given = scene.givens.iter().any(|g| g.symbol.name() == "gamma");
    let tan_gamma = named("tan(gamma)", r"\tan\gamma");
    let mut rows = Vec::new();
    if !given {
        rows.push(Line::scalar(scene, tan_gamma, Cow::Borrowed(tangent), None));
    }
    if let Some(t) = value(scene, tangent).filter(|_| !given) {
        rows.push(Line::number(
            named("gamma", r"\gamma"),
            t.atan().to_degrees(),
            NamedUnit::named("deg"),
        ));
    }
    let words = match precession.sense {
        PrecessionSense::Direct => "direct precession ($I' > I$)",
        PrecessionSense::Retrograde => "retrograde precession ($I' < I$)",
        PrecessionSense::EqualMoments => "no precession ($I' = I$)",
    };
    rows.push(Line::words(
        named("precession", r"\text{precession}"),
        words,
    ));
    rows.into_iter().map(Result::line).collect()
}
