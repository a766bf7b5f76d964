//! `derive`: the chapter's equations for a general body (`kinetics derive --general`), kept
//! as a [`Derived`] whose relations and pages are written when asked for.

use crate::error::refused;
use crate::expression::tree;
use kinetics::{
    derive_general_along, markup_text, relation, render_derivations, Axis, Derivation, Domains,
    Format, Notation, Shown, DERIVATION_NAMES,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// Derived equations, each derivation with its steps.
#[pyclass(frozen, module = "kinetics._native")]
pub struct Derived {
    derivations: Vec<Derivation>,
    axis: Axis,
}

/// Derives `only` (all of `DERIVATION_NAMES` when empty) for a general body, in principal
/// axes when `principal`, the fixed-axis derivations about `axis` (`"x"`, `"y"`, `"z"`).
#[pyfunction]
#[pyo3(signature = (only, principal=false, axis="z"))]
pub fn derive(py: Python<'_>, only: Vec<String>, principal: bool, axis: &str) -> PyResult<Derived> {
    let axis = match axis {
        "x" => Axis::X,
        "y" => Axis::Y,
        "z" => Axis::Z,
        other => {
            return Err(refused(format!(
                "axis={other:?}: give \"x\", \"y\" or \"z\""
            )))
        }
    };
    let names: Vec<&str> = match only.is_empty() {
        true => DERIVATION_NAMES.to_vec(),
        false => only.iter().map(String::as_str).collect(),
    };
    let mut derivations = Vec::new();
    for name in names {
        let derived = py
            .detach(|| derive_general_along(name, principal, axis))
            .ok_or_else(|| {
                refused(format!(
                    "unknown derivation {name:?}: choose from {}",
                    DERIVATION_NAMES.join(", ")
                ))
            })?
            .map_err(|e| refused(format!("{name}: {e}")))?;
        derivations.push(derived.simplified(&Domains::chapter_defaults()));
    }
    Ok(Derived { derivations, axis })
}

#[pymethods]
impl Derived {
    /// Each derivation's result: a dict of `name`, `title` and `relations`, each relation
    /// `(lhs tree, rhs tree, text, latex)`.
    fn results<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let domains = Domains::chapter_defaults();
        let list = PyList::empty(py);
        for d in &self.derivations {
            let relations = PyList::empty(py);
            for r in d.result() {
                let (lhs_text, rhs_text) = relation(r, Notation::Text);
                let (lhs_latex, rhs_latex) = relation(r, Notation::Latex);
                relations.append((
                    tree(py, &r.lhs, &domains)?,
                    tree(py, &r.rhs, &domains)?,
                    format!("{lhs_text} = {rhs_text}"),
                    format!("{lhs_latex} = {rhs_latex}"),
                ))?;
            }
            let entry = PyDict::new(py);
            entry.set_item("name", &d.name)?;
            entry.set_item("title", markup_text(&d.title))?;
            entry.set_item("relations", relations)?;
            list.append(entry)?;
        }
        Ok(list)
    }

    /// The derivations as a page: `format` one of `text`, `latex`, `markdown`, `json`,
    /// `html`, `html-fragment`; `steps` every step (else each result alone); `standalone`
    /// LaTeX a whole document.
    #[pyo3(signature = (format, steps=false, standalone=false))]
    fn render(&self, format: &str, steps: bool, standalone: bool) -> PyResult<String> {
        let format = crate::solution::page_format(format)?;
        if standalone && format != Format::Latex {
            return Err(refused("standalone goes with the LaTeX format"));
        }
        Ok(render_derivations(
            &self.derivations,
            Shown {
                format,
                all_steps: steps,
                standalone,
                axis: self.axis,
            },
        )
        .trim_end()
        .to_string())
    }
}
