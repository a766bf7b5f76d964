//! Refusals as Python exceptions. An input refused at a place in it (a scene, a claim) is a
//! `kinetics.SceneError`, a `ValueError` whose message is the command line's (the place, the
//! line with a caret, the hint) and whose attributes carry its parts; a refusal of the
//! arguments or of the numerical work is a plain `ValueError` with its reason.

use kinetics::Diagnostic;
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

create_exception!(
    kinetics,
    SceneError,
    PyValueError,
    "An input refused at a place in it. Its message is the command line's; `source_name`, \
     `line`, `column` (1-based), `message`, `hint` (or None) and `source_line` are its parts."
);

/// The `SceneError` of a diagnostic.
pub fn scene_error(d: &Diagnostic) -> PyErr {
    Python::attach(|py| {
        let error = SceneError::new_err(d.render().trim_end().to_string());
        let value = error.value(py);
        let parts = [
            (
                "source_name",
                d.source_name.clone().into_pyobject(py)?.into_any(),
            ),
            ("line", d.line.into_pyobject(py)?.into_any()),
            ("column", d.column.into_pyobject(py)?.into_any()),
            ("message", d.message.clone().into_pyobject(py)?.into_any()),
            ("hint", d.help.clone().into_pyobject(py)?),
            (
                "source_line",
                d.source_line.clone().into_pyobject(py)?.into_any(),
            ),
        ];
        for (name, part) in parts {
            value.setattr(name, part)?;
        }
        Ok::<_, PyErr>(error)
    })
    .unwrap_or_else(|e| e)
}

/// A `ValueError` saying `reason`.
pub fn refused(reason: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(reason.to_string())
}
