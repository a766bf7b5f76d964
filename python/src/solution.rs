//! `solve`: a scene parsed, analysed and checked within its work budget, kept as a
//! [`Solved`] whose results, steps and pages are written when asked for.

use crate::error::{refused, scene_error};
use crate::expression::tree;
use kinetics::{
    analyse, analyse_results, answers, check_numeric_requests, figure, figure_svg, parse_scene_in,
    render_beside, render_numbers_beside, worked_steps, Analysis, AnswerForm, Domain, Format,
    Input, Scene, Symbol, UnitSystem, Value,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::sync::OnceLock;

/// A step as Python receives it: its title, its title in LaTeX, and its relations as
/// `(text, latex)`.
type StepRows = (String, String, Vec<(String, String)>);

/// A solved scene: its results, and its worked solution written when first asked for.
#[pyclass(frozen, module = "kinetics._native")]
pub struct Solved {
    name: String,
    text: String,
    scene: Scene,
    /// The results (`analyse_results`: the steps not written).
    results: Analysis,
    /// The whole analysis, its steps written, for a page or the steps.
    page: OnceLock<Analysis>,
}

/// Solves the scene `text` (named `name` in errors), its values shown in `units` (`"si"`,
/// `"us"`, or None for the system its givens are written in).
#[pyfunction]
#[pyo3(signature = (name, text, units=None))]
pub fn solve(py: Python<'_>, name: &str, text: &str, units: Option<&str>) -> PyResult<Solved> {
    let units = match units {
        None => None,
        Some("si") => Some(UnitSystem::Si),
        Some("us") => Some(UnitSystem::Us),
        Some(other) => return Err(refused(format!("units={other:?}: give \"si\" or \"us\""))),
    };
    py.detach(|| {
        Input::scene(name, text).within(|| {
            let scene = parse_scene_in(name, text, units)?;
            let results = analyse_results(&scene)?;
            check_numeric_requests(&scene, &results)?;
            Ok(Solved {
                name: name.to_string(),
                text: text.to_string(),
                scene,
                results,
                page: OnceLock::new(),
            })
        })
    })
    .map_err(|d| scene_error(&d))
}

impl Solved {
    /// The analysis with its steps written, made once (within the scene's budget).
    fn page(&self, py: Python<'_>) -> PyResult<&Analysis> {
        if let Some(analysis) = self.page.get() {
            return Ok(analysis);
        }
        let analysis = py
            .detach(|| Input::scene(&self.name, &self.text).within(|| analyse(&self.scene)))
            .map_err(|d| scene_error(&d))?;
        Ok(self.page.get_or_init(|| analysis))
    }
}

#[pymethods]
impl Solved {
    /// The scene's title, if it has one.
    #[getter]
    fn title(&self) -> Option<String> {
        self.scene.title.clone()
    }

    /// Each line of the results: a dict of `name`, `name_latex`, `text`, `latex`, `kind`
    /// (`expr`, `vector`, `matrix`, `words`, `number`), `form` (the expression's tree, a
    /// list of three or nine, or None), `value` (a list of numbers or None), `unit`,
    /// `value_text`, `value_latex` and `html` (the line's MathML, its style scoped to it).
    fn answers<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let domains = self.scene.domains();
        let list = PyList::empty(py);
        for a in answers(&self.scene, &self.results) {
            let d = PyDict::new(py);
            let (kind, form) = match &a.form {
                AnswerForm::Expr(e) => ("expr", tree(py, e, &domains)?.into_any()),
                AnswerForm::Vector(v) => ("vector", trees(py, v.iter(), &domains)?),
                AnswerForm::Matrix(m) => {
                    // Row by row, as the value's nine numbers.
                    ("matrix", trees(py, m.transpose().iter(), &domains)?)
                }
                AnswerForm::Words(_) => ("words", py.None().into_bound(py)),
                AnswerForm::Number => ("number", py.None().into_bound(py)),
            };
            d.set_item("name", a.name)?;
            d.set_item("name_latex", a.name_latex)?;
            d.set_item("text", a.text)?;
            d.set_item("latex", a.latex)?;
            d.set_item("kind", kind)?;
            d.set_item("form", form)?;
            d.set_item("value", a.value)?;
            d.set_item("unit", a.unit)?;
            d.set_item("value_text", a.value_text)?;
            d.set_item("value_latex", a.value_latex)?;
            d.set_item("html", a.html)?;
            list.append(d)?;
        }
        Ok(list)
    }

    /// The steps of the plan: `(title, title_latex, [(text, latex), ...])` each.
    fn steps(&self, py: Python<'_>) -> PyResult<Vec<StepRows>> {
        Ok(worked_steps(&self.scene, self.page(py)?)
            .into_iter()
            .map(|s| (s.title, s.title_latex, s.relations))
            .collect())
    }

    /// The symbols of the scene (its givens and unknowns) and of its results, each
    /// `(name, positive)`, names as the page spells them (`w1` is `w_1`).
    fn symbols(&self) -> Vec<(String, bool)> {
        let domains = self.scene.domains();
        let mut symbols: Vec<Symbol> = self.scene.givens.iter().map(|g| g.symbol).collect();
        symbols.extend(self.scene.unknowns.iter().map(|(s, _)| *s));
        for (_, value) in &self.results.results {
            let exprs: Vec<&kinetics::Expr> = match value {
                Value::Scalar(e) => vec![e],
                Value::Vector(v) => v.iter().collect(),
                Value::Tensor(m) => m.iter().collect(),
                _ => Vec::new(),
            };
            symbols.extend(exprs.into_iter().flat_map(|e| e.symbols()));
        }
        symbols.sort();
        symbols.dedup();
        symbols
            .into_iter()
            .filter(|s| !s.is_pi())
            .map(|s| (s.name().to_string(), domains.domain(s) == Domain::Positive))
            .collect()
    }

    /// The scene's figure as SVG, or None where it cannot be drawn (a size without a
    /// number).
    fn figure_svg(&self) -> Option<String> {
        figure(&self.scene).ok().map(|drawn| figure_svg(&drawn))
    }

    /// The worked solution as a page: `format` one of `text`, `latex`, `markdown`, `json`,
    /// `html`, `html-fragment`; `standalone` LaTeX a whole document; `numbers` the engineer's
    /// page (the values without the symbolic steps); a Markdown page shows its figure as the
    /// image `figure_file`, a file the caller writes (`figure_svg`).
    #[pyo3(signature = (format, standalone=false, numbers=false, figure_file=None))]
    fn render(
        &self,
        py: Python<'_>,
        format: &str,
        standalone: bool,
        numbers: bool,
        figure_file: Option<&str>,
    ) -> PyResult<String> {
        let format = page_format(format)?;
        if standalone && format != Format::Latex {
            return Err(refused("standalone goes with the LaTeX format"));
        }
        let analysis = self.page(py)?;
        let page = match numbers {
            true => render_numbers_beside(&self.scene, analysis, format, standalone, figure_file),
            false => render_beside(&self.scene, analysis, format, standalone, figure_file),
        };
        Ok(page.trim_end().to_string())
    }
}

/// The format of a page as Python names it.
pub fn page_format(name: &str) -> PyResult<Format> {
    Ok(match name {
        "text" => Format::Text,
        "latex" => Format::Latex,
        "markdown" => Format::Markdown,
        "json" => Format::Json,
        "html" => Format::Html,
        "html-fragment" => Format::HtmlFragment,
        other => {
            return Err(refused(format!(
                "format {other:?}: choose text, latex, markdown, json, html or html-fragment"
            )))
        }
    })
}

/// The trees of several expressions, as a list.
fn trees<'a, 'py>(
    py: Python<'py>,
    exprs: impl Iterator<Item = &'a kinetics::Expr>,
    domains: &kinetics::Domains,
) -> PyResult<Bound<'py, PyAny>> {
    let trees = exprs
        .map(|e| tree(py, e, domains))
        .collect::<PyResult<Vec<_>>>()?;
    Ok(PyList::new(py, trees)?.into_any())
}
