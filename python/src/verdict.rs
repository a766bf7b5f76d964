//! `check`: one hand-written claim checked against the derivations of a scene, or of the
//! general body (principal axes, a fixed point, rotation about a fixed axis), as
//! `kinetics check` does, within the claim's work budget.

use crate::error::{refused, scene_error};
use crate::expression::tree;
use kinetics::{
    check_claim, claim_numbers_sentence, claim_report_latex, claim_report_text, markup_html,
    parse_scene, render_expr, Axis, Context, Diagnostic, Forms, Input, Notation,
    DEFAULT_RELATIVE_TOLERANCE,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// Checks `claim`. The context is the scene `(name, text)` when given, else the general
/// body as `principal`, `fixed_point` and `fixed_axis` say. Returns a dict: `claim`,
/// `verdict` (`holds`, `differs`, `undecided`), `slip` (the named rule or reading, or
/// None), `explanation`, `correct_side`, `claimed_side`, `report` and `report_latex` (the
/// command line's report), and `components` (`axis`, `verdict`, `correct`, `claimed` as
/// trees, and each side's `_text`, `_latex` and `_mathml`, `numbers`: a claim in numbers'
/// sentence), `explanation_html`.
#[pyfunction]
#[pyo3(signature = (claim, scene=None, principal=false, fixed_point=false, fixed_axis=false, rtol=None))]
pub fn check<'py>(
    py: Python<'py>,
    claim: &str,
    scene: Option<(String, String)>,
    principal: bool,
    fixed_point: bool,
    fixed_axis: bool,
    rtol: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let context = context(py, scene, principal, fixed_point, fixed_axis, rtol)?;
    let label = "claim";
    let report = py
        .detach(|| Input::expression(label, claim).within(|| check_claim(&context, label, claim)))
        .map_err(|d| scene_error(&d))?;
    let domains = context.domains();
    let forms = Forms::new(domains);
    let d = PyDict::new(py);
    d.set_item("claim", &report.claim)?;
    d.set_item("verdict", report.verdict.word())?;
    let slip = report
        .slip
        .as_ref()
        .map(|s| s.slip.name())
        .or_else(|| report.reading());
    d.set_item("slip", slip)?;
    d.set_item("explanation", report.reading_words())?;
    // The named slip's concept with its maths in MathML (else the explanation is words).
    let concept_html = report.slip.as_ref().map(|s| markup_html(s.slip.concept()));
    d.set_item("explanation_html", concept_html)?;
    d.set_item("correct_side", &report.correct_side)?;
    d.set_item("claimed_side", &report.claimed_side)?;
    d.set_item(
        "report",
        claim_report_text(&report, label, &forms).trim_end(),
    )?;
    d.set_item(
        "report_latex",
        claim_report_latex(&report, label, &forms).trim_end(),
    )?;
    let components = PyList::empty(py);
    for c in &report.components {
        let component = PyDict::new(py);
        component.set_item("axis", c.axis.map(|a| ["x", "y", "z"][a as usize]))?;
        component.set_item("verdict", c.verdict.word())?;
        let numbers = c.numbers.as_ref().map(claim_numbers_sentence);
        component.set_item("numbers", numbers)?;
        component.set_item("correct", tree(py, &c.correct_in_symbols, domains)?)?;
        component.set_item("claimed", tree(py, &c.claimed_in_symbols, domains)?)?;
        for (side, e) in [
            ("correct", &c.correct_in_symbols),
            ("claimed", &c.claimed_in_symbols),
        ] {
            let axis = c.axis.unwrap_or(Axis::X);
            for (format, notation) in [
                ("text", Notation::Text),
                ("latex", Notation::Latex),
                ("mathml", Notation::MathMl),
            ] {
                component.set_item(format!("{side}_{format}"), render_expr(e, notation, axis))?;
            }
        }
        components.append(component)?;
    }
    d.set_item("components", components)?;
    Ok(d)
}

/// The context claims are checked in: the scene `(name, text)`, read within its budget,
/// else the general body as `principal`, `fixed_point` and `fixed_axis` say; numbers
/// within `rtol` (default 0.005).
pub fn context(
    py: Python<'_>,
    scene: Option<(String, String)>,
    principal: bool,
    fixed_point: bool,
    fixed_axis: bool,
    rtol: Option<f64>,
) -> PyResult<Context> {
    let rtol = rtol.unwrap_or(DEFAULT_RELATIVE_TOLERANCE);
    if !(0.0..1.0).contains(&rtol) {
        return Err(refused(format!(
            "rtol={rtol}: give a relative tolerance from 0 up to 1, like 0.005 for 0.5 %"
        )));
    }
    let context = match &scene {
        Some(_) if principal || fixed_point || fixed_axis => {
            return Err(refused(
                "principal, fixed_point and fixed_axis describe the general body: a scene \
                 says all of that itself",
            ))
        }
        Some((name, text)) => py
            .detach(|| {
                Input::scene(name, text)
                    .within(|| Ok::<_, Diagnostic>(Context::scene(&parse_scene(name, text)?)))
            })
            .map_err(|d| scene_error(&d))?,
        None if fixed_axis && (principal || fixed_point) => {
            return Err(refused(
                "fixed_axis goes alone: rotation about z is its own context",
            ))
        }
        None if fixed_axis => Context::fixed_axis().map_err(refused)?,
        None => Context::general(principal, fixed_point).map_err(refused)?,
    };
    Ok(context.with_relative_tolerance(rtol))
}
