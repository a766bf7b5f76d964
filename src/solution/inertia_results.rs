//! The inertia results as lines of the page: a tensor (`find I_G`, `find I_O`) as a matrix
//! in the chapter's convention,
//!
//! ```text
//!         [  I_x  -I_xy  -I_xz ]
//! [I_G] = [ -I_xy   I_y  -I_yz ]  = [numbers] kg·m²
//!         [ -I_xz  -I_yz   I_z ]
//! ```
//!
//! and a principal frame (`find principal_G`) as lines `I_1 = …`, `I_2 = …`, `I_3 = …`
//! (ascending, with their values), then the axes `e_1 = …`, `e_2 = …`, `e_3 = …` (a
//! right-handed frame), then the remark on equal moments when there is one. A form that is a
//! number (a numeric solution) is shown by its value alone, in four significant figures; an
//! exact axis (`i`, `-k`) by its form alone.

use super::numbers::value;
use super::page::Name;
use super::result::{in_unit, Body, Form, Line, Result, Show};
use crate::algebra::{Expr, Matrix};
use crate::mechanics::principal_frame::PrincipalFrame;
use crate::scene::named_unit::NamedUnit;
use crate::scene::units::Dimension;
use crate::scene::Scene;

/// A tensor's line: its matrix and its nine values row by row, in kg·m².
pub(super) fn tensor<'a>(scene: &Scene, name: Name, m: &'a Matrix) -> Line<'a> {
    let unit = scene.unit_system.unit(Dimension::INERTIA, false);
    let value = m.transpose().iter().map(|e| value(scene, e)).collect();
    let value = in_unit(scene, value, Some(&unit));
    let numeric = m.iter().all(|e| e.as_num().is_some());
    Line {
        name,
        show: shown(value.is_some(), numeric),
        form: Some(Form::Matrix(m)),
        value,
        unit: Some(unit),
    }
}

/// A principal frame's lines, under the request's name.
pub(super) fn frame<'a>(scene: &Scene, name: Name, frame: &'a PrincipalFrame) -> Result<'a> {
    let named = |stem: &str, k: usize| Name {
        text: format!("{stem}_{}", k + 1),
        latex: format!("{stem}_{}", k + 1),
    };
    let number = |e: &Expr| e.as_num().is_some();
    let fraction = |e: &Expr| e.as_num().is_some_and(|q| !q.is_integer());
    let moments = frame
        .moments
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let unit = scene.unit_system.unit(Dimension::INERTIA, false);
            let value = in_unit(scene, value(scene, m).map(|x| vec![x]), Some(&unit));
            Line {
                name: named("I", k),
                show: shown(value.is_some(), number(m)),
                form: Some(Form::Expr(std::borrow::Cow::Borrowed(m))),
                value,
                unit: Some(unit),
            }
        })
        .collect();
    let axes = frame
        .axes
        .iter()
        .enumerate()
        .map(|(k, e)| {
            let value: Option<Vec<f64>> = e.iter().map(|c| value(scene, c)).collect();
            // An exact axis (`i`, `-k`, or with symbols): its numbers add nothing to `i`.
            let exact = e.iter().all(number) && !e.iter().any(fraction);
            Line {
                name: named("e", k),
                show: match shown(value.is_some(), e.iter().all(number) && !exact) {
                    Show::Both if exact => Show::Form,
                    shown => shown,
                },
                form: Some(Form::Vector(std::borrow::Cow::Borrowed(e), None)),
                value,
                unit: Some(NamedUnit::default()),
            }
        })
        .collect();
    let remark = frame.remark.as_deref().map(|w| {
        let nameless = Name {
            text: String::new(),
            latex: String::new(),
        };
        Line::words(nameless, w)
    });
    Result {
        name,
        body: Body::Frame {
            moments,
            axes,
            remark,
        },
    }
}

/// A numeric solution's form by its value alone (its exact decimals say nothing more), a
/// symbolic form with its value, a form without a value alone.
fn shown(has_value: bool, numeric: bool) -> Show {
    match (has_value, numeric) {
        (false, _) => Show::Form,
        (true, true) => Show::Value,
        (true, false) => Show::Both,
    }
}
