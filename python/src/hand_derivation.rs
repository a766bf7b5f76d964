//! `check_derivation`: a hand derivation checked line by line, as `kinetics check
//! --derivation` does: each part (lines between blank lines) a chain of its own, a wrong
//! line that is right from an earlier wrong one `follows` it.

use crate::error::refused;
use crate::verdict::context;
use kinetics::{
    check_derivation as check_lines, derivation_parts, derivation_report_text, first_slip, Input,
    Judgement,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// Checks the derivation `text` (one equation a line, `#` comments) in the context
/// `check` takes. Returns a dict: `lines` (each `number`, `text`, `verdict` — holds,
/// differs, follows, undecided, error —, `slip`, `explanation`, `follows_from`,
/// `does_not_follow`, `error`), `first_slip` (`(line, reading)` or None) and `report`.
#[pyfunction]
#[pyo3(signature = (text, scene=None, principal=false, fixed_point=false, fixed_axis=false, rtol=None))]
pub fn check_derivation<'py>(
    py: Python<'py>,
    text: &str,
    scene: Option<(String, String)>,
    principal: bool,
    fixed_point: bool,
    fixed_axis: bool,
    rtol: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let context = context(py, scene, principal, fixed_point, fixed_axis, rtol)?;
    let name = "derivation";
    let parts = derivation_parts(text);
    if parts.is_empty() {
        return Err(refused(
            "the derivation holds no line to check: write one equation a line, like T = 1/2 m v^2",
        ));
    }
    let checked = py
        .detach(|| {
            Input::expression(name, text).within(|| Ok(check_lines(&context, name, &parts, &[])))
        })
        .map_err(|d| crate::error::scene_error(&d))?
        .parts;
    let domains = context.domains();
    let lines = PyList::empty(py);
    let mut report = String::new();
    let mut first = None;
    for part in &checked {
        report.push_str(&derivation_report_text(part, name, domains));
        if first.is_none() {
            first = first_slip(part).map(|(line, _)| {
                let reading = line.outcome.as_ref().ok().and_then(|r| r.reading());
                (line.line.number, reading)
            });
        }
        for c in part {
            let d = PyDict::new(py);
            d.set_item("number", c.line.number)?;
            d.set_item("text", &c.line.text)?;
            d.set_item("verdict", c.judgement().word())?;
            let report = c.outcome.as_ref().ok();
            let differs = matches!(c.judgement(), Judgement::Differs | Judgement::Follows);
            let slip = report.filter(|_| differs).and_then(|r| {
                r.slip
                    .as_ref()
                    .map(|s| s.slip.name())
                    .or_else(|| r.reading())
            });
            d.set_item("slip", slip)?;
            d.set_item(
                "explanation",
                report.filter(|_| differs).and_then(|r| r.reading_words()),
            )?;
            d.set_item("follows_from", c.follows_from.clone())?;
            d.set_item("does_not_follow", c.does_not_follow.clone())?;
            d.set_item("error", c.outcome.as_ref().err().map(|e| e.render()))?;
            lines.append(d)?;
        }
    }
    let d = PyDict::new(py);
    d.set_item("lines", lines)?;
    d.set_item("first_slip", first)?;
    d.set_item("report", report.trim_end())?;
    Ok(d)
}
