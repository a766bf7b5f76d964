//! Rendering a worked solution: the givens, each step of the plan with its component
//! equations in textbook form, and the results with values and units.
//!
//! JSON: the document `docs/solution.schema.json` describes (JSON Schema 2020-12), tested
//! against every example's output (`tests/suite/json_schema.rs`); `--numbers` gives the
//! engineer's page ([`render_numbers`]), described in the same file. A balance is four result
//! rows or more: `m_1`, `theta_1` (in `deg`; `text` "undefined" and `value` null for no
//! correction), `tan(theta_1)` where the angle is not exact, then plane 2. A tensor's value is its rows `[[…], […], […]]`, a principal frame's
//! `{"moments", "axes", "remark"}`.

use super::numbers::scene_dimensions;
use super::result::{results, Result};
use super::solution_page::solution_page;
use crate::algebra::Expr;
use crate::mechanics::derivation::Relation;
use crate::print::{self, Notation};
use crate::scene::{Analysis, Scene};

/// The output formats of a worked solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Text,
    Latex,
    Markdown,
    Json,
    /// One self-contained HTML page, the mathematics in MathML.
    Html,
    /// The HTML page's content as one `<div>` with its style scoped to it, to stand in
    /// another page (a notebook's cell).
    HtmlFragment,
}

impl Format {
    /// Whether the page shows the scene's figure (text and JSON have none, so it is not
    /// drawn for them).
    fn shows_figure(self) -> bool {
        !matches!(self, Format::Text | Format::Json)
    }
}

/// The two sides of a relation in the chosen notation, presented about its axis.
pub fn relation(r: &Relation, notation: Notation) -> (String, String) {
    (
        print::render(&r.lhs, notation, r.axis),
        print::render(&r.rhs, notation, r.axis),
    )
}

/// Renders the worked solution in the chosen format; `standalone` LaTeX is a whole document.
///
/// A sphere spinning about z: `T = 1/5 m r² w² = 1/5 · 5 · 0.1² · 2² = 0.04 J`.
///
/// ```
/// use kinetics::{analyse, parse_scene, render, Format};
///
/// let scene = parse_scene(
///     "sphere.scene",
///     "given m = 5 kg
/// given r = 0.1 m
/// given w = 2 rad/s
/// body sphere(r) mass m
/// vbar = 0
/// omega = w*k
/// find T",
/// )?;
/// let analysis = analyse(&scene)?;
/// let json = render(&scene, &analysis, Format::Json, false);
/// let t = &serde_json::from_str::<serde_json::Value>(&json)?["results"][0];
/// assert_eq!(t["name"], "T");
/// assert_eq!(t["text"], "1/5*m*r^2*w^2");
/// assert_eq!(t["unit"], "J");
/// assert!((t["value"].as_f64().unwrap() - 0.04).abs() < 1e-12);
/// let latex = render(&scene, &analysis, Format::Latex, false);
/// assert!(latex.contains(r"T &= \frac{1}{5} m r^2 \omega^2 = 0.04\,\mathrm{J}"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn render(scene: &Scene, analysis: &Analysis, format: Format, standalone: bool) -> String {
    render_beside(scene, analysis, format, standalone, None)
}

/// [`render`], a Markdown page showing its figure as the image `figure_file` (an SVG the
/// caller writes beside the page: [`crate::figure::svg::svg`]); without one, a Markdown page
/// says how to have it.
pub fn render_beside(
    scene: &Scene,
    analysis: &Analysis,
    format: Format,
    standalone: bool,
    figure_file: Option<&str>,
) -> String {
    on_the_page(scene, analysis, || {
        let dims = scene_dimensions(scene);
        let results = results(scene, analysis, &dims);
        // A scene the figure cannot be drawn for (a size without a number) has its page
        // without one; `kinetics figure` says why.
        let drawn = format
            .shows_figure()
            .then(|| crate::figure::figure(scene).ok())
            .flatten();
        let mut page = solution_page(scene, analysis, &results, drawn.as_ref());
        page.figure_file = figure_file;
        match format {
            Format::Text => super::text::page(&page),
            Format::Latex => super::latex::page(&page, standalone),
            Format::Markdown => super::markdown::page(&page),
            Format::Json => super::json::solution(&page, analysis).to_string(),
            Format::Html => super::html::page(&page),
            Format::HtmlFragment => super::html::fragment(&page),
        }
    })
}

/// `write` with the names of one page: two symbols that would print alike (`w_x` and
/// `omega_x`) are told apart, unless a relation `omega_x = w_x` states them one quantity.
pub(super) fn on_the_page<T>(scene: &Scene, analysis: &Analysis, write: impl FnOnce() -> T) -> T {
    let relations = || analysis.plan.iter().flat_map(|s| &s.relations);
    let vectors = analysis.plan.iter().flat_map(|s| &s.vectors);
    let page = scene
        .givens
        .iter()
        .map(|g| g.symbol)
        .chain(relations().flat_map(|r| r.lhs.symbols().into_iter().chain(r.rhs.symbols())))
        .chain(vectors.flat_map(|v| v.value.iter().flat_map(Expr::symbols)));
    let identities = relations().filter_map(|r| Some((r.lhs.as_symbol()?, r.rhs.as_symbol()?)));
    print::on_one_page(page, identities, write)
}

/// The engineer's page ([`super::engineer`]): the givens, each result as a number with its
/// unit and the plan's intermediate values, without the symbolic steps; JSON its own
/// document (`docs/solution.schema.json`), every other format the page in that notation.
pub fn render_numbers(
    scene: &Scene,
    analysis: &Analysis,
    format: Format,
    standalone: bool,
) -> String {
    render_numbers_beside(scene, analysis, format, standalone, None)
}

/// [`render_numbers`], a Markdown page showing its figure as the image `figure_file` (as
/// [`render_beside`]).
pub fn render_numbers_beside(
    scene: &Scene,
    analysis: &Analysis,
    format: Format,
    standalone: bool,
    figure_file: Option<&str>,
) -> String {
    on_the_page(scene, analysis, || {
        let dims = scene_dimensions(scene);
        let results = results(scene, analysis, &dims);
        let steps = super::engineer::intermediate(scene, analysis, &dims);
        let drawn = format
            .shows_figure()
            .then(|| crate::figure::figure(scene).ok())
            .flatten();
        let mut page = super::engineer::numbers_page(scene, &results, &steps, drawn.as_ref());
        page.figure_file = figure_file;
        match format {
            Format::Text => super::text::page(&page),
            Format::Latex => super::latex::page(&page, standalone),
            Format::Markdown => super::markdown::page(&page),
            Format::Json => super::json::numbers(&page).to_string(),
            Format::Html => super::html::page(&page),
            Format::HtmlFragment => super::html::fragment(&page),
        }
    })
}

pub(super) fn given_line(g: &crate::scene::model::Given) -> String {
    match (&g.definition, &g.written) {
        (Some(d), _) => format!("{} = {}", g.symbol.name(), d.expr),
        (None, Some(w)) => format!("{} = {w}", g.symbol.name()),
        (None, None) => format!("{} ({}, symbolic)", g.symbol.name(), g.dimension),
    }
}

/// The room of the results' forms ([`print::aligned_room`]), whose left-hand sides are the
/// quantities' names.
pub(super) fn results_room(results: &[Result]) -> (f64, f64) {
    let lhs_em = results
        .iter()
        .flat_map(Result::lines)
        .map(|line| print::width::symbol_em(&line.name.latex))
        .fold(0.0, f64::max);
    print::aligned_room(lhs_em)
}
