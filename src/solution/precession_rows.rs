//! A torque-free precession's results (`find precession`), a row each: `tan(gamma)`, the
//! tangent of the angle γ between ω and the axis of symmetry, `gamma` in degrees (the number
//! `atan` of its value, where the givens have values), and the sense in words, "direct
//! precession (I' > I)" or "retrograde precession (I' < I)" ("no precession (I' = I)": ω is
//! along H_G).

use super::balance_rows::{in_words, number};
use super::numbers::value;
use super::render::{scalar, Result};
use crate::mechanics::torque_free_axisymmetric::{Precession, PrecessionSense};
use crate::scene::Scene;
use std::borrow::Cow;

/// The rows `tan(gamma)`, `gamma` (when it has a value) and `precession`.
pub(super) fn rows<'a>(scene: &Scene, precession: &Precession) -> Vec<Result<'a>> {
    let tangent = &precession.tan_gamma;
    let mut rows = vec![scalar(
        scene,
        Cow::Borrowed("tan(gamma)"),
        r"\tan\gamma".into(),
        tangent.clone(),
        None,
    )];
    if let Some(t) = value(scene, tangent) {
        rows.push(number(
            "gamma".into(),
            r"\gamma".into(),
            t.atan().to_degrees(),
        ));
    }
    let (words, relation) = match precession.sense {
        PrecessionSense::Direct => ("direct precession", "(I' > I)"),
        PrecessionSense::Retrograde => ("retrograde precession", "(I' < I)"),
        PrecessionSense::EqualMoments => ("no precession", "(I' = I)"),
    };
    rows.push(in_words(
        "precession".into(),
        r"\text{precession}".into(),
        &format!("{words} {relation}"),
        format!(r"\text{{{words}}}\ {relation}"),
    ));
    rows
}
