//! Rendering a worked solution: the givens, each step of the plan with its component
//! equations in textbook form, and the results with values and units.
//!
//! JSON: the document `docs/solution.schema.json` describes (JSON Schema 2020-12), tested
//! against every example's output (`tests/suite/json_schema.rs`); `--numbers` gives the
//! engineer's page ([`render_numbers`]), described in the same file. A balance is four result
//! rows or more: `m_1`, `theta_1` (in `deg`; `text` "undefined" and `value` null for no
//! correction), `tan(theta_1)` where the angle is not exact, then plane 2. A tensor's value is its rows `[[…], […], […]]`, a principal frame's
//! `{"moments", "axes", "remark"}`.

use super::inertia_results;
use super::numbers::{format_value, result_unit, scene_dimensions, value};
use super::solution_page::solution_page;
use super::vector_value;
use crate::algebra::Vector;
use crate::algebra::{Axis, Expr};
use crate::mechanics::derivation::Relation;
use crate::print::grouped_vector::{grouped, GroupedVector};
use crate::print::{self, Notation};
use crate::scene::analysis::Abbreviations;
use crate::scene::model::{Quantity, Request};
use crate::scene::units::{Dimension, Dimensions};
use crate::scene::{Analysis, Scene, Value};
use std::borrow::Cow;

/// The output formats of a worked solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Text,
    Latex,
    Markdown,
    Json,
    /// One self-contained HTML page, the mathematics in MathML.
    Html,
}

/// A result with its forms and value.
pub(super) struct Result<'a> {
    pub(super) name: Cow<'a, str>,
    /// The quantity's name in LaTeX (`\mathbf{H}_G`, `T`, `m_1`).
    pub(super) name_latex: String,
    pub(super) text: String,
    pub(super) latex: String,
    pub(super) value: Option<Vec<f64>>,
    pub(super) unit: Option<String>,
    /// The symbolic form; none for a number found only from the values (an angle by atan2).
    pub(super) form: Option<Cow<'a, Value>>,
    /// A vector form with its common factor in front, where that reads shorter: found once
    /// (a `together` and a `factor_terms`), shown by every notation.
    pub(super) grouped: Option<GroupedVector>,
}

impl Result<'_> {
    /// Whether the result is a plain number (its value with its unit is all there is to show).
    pub(super) fn is_number(&self) -> bool {
        self.form.is_none() || self.text.parse::<f64>().is_ok()
    }

    /// Whether the result is said in words (a balance's angle "undefined", a precession's
    /// sense), with neither a form nor a number.
    pub(super) fn is_words(&self) -> bool {
        self.form.is_none() && self.value.is_none()
    }
}

fn results<'a>(scene: &Scene, analysis: &'a Analysis, dims: &Dimensions) -> Vec<Result<'a>> {
    analysis
        .results
        .iter()
        .flat_map(|(request, v)| computed(scene, request, v, dims, &analysis.abbreviations))
        .collect()
}

/// A value asked for `in UNIT` is converted from SI and labelled with the unit as written.
fn in_requested_unit<'a>(request: &Request, mut r: Result<'a>) -> Result<'a> {
    if let Some((written, unit)) = &request.unit {
        // A principal frame's axes (after its three moments) have no unit.
        let scaled = if matches!(r.form.as_deref(), Some(Value::Principal(_))) {
            3
        } else {
            usize::MAX
        };
        r.value = r.value.map(|v| {
            let to = |(k, x): (usize, &f64)| if k < scaled { x / unit.to_si } else { *x };
            v.iter().enumerate().map(to).collect()
        });
        r.unit = Some(written.clone());
    }
    r
}

/// A scalar result named `name` (`name_latex` in LaTeX), in `unit`.
pub(super) fn scalar<'a>(
    scene: &Scene,
    name: Cow<'a, str>,
    name_latex: String,
    e: Expr,
    unit: Option<String>,
) -> Result<'a> {
    Result {
        name,
        name_latex,
        text: print::text(&e),
        latex: print::latex(&e),
        value: value(scene, &e).map(|x| vec![x]),
        unit,
        form: Some(Cow::Owned(Value::Scalar(e))),
        grouped: None,
    }
}

/// A request's result: one, or a balance's rows ([`super::balance_rows`]).
/// A scalar is shown with the analysis's names for long radicands (`names`), its value
/// computed from the whole expression.
fn computed<'a>(
    scene: &Scene,
    request: &'a Request,
    v: &'a Value,
    dims: &Dimensions,
    names: &Abbreviations,
) -> Vec<Result<'a>> {
    // One of several solutions: `phidot (solution 1)`, `{\dot{\phi}}^{(1)}`.
    let (name, name_latex) = match request.solution {
        None => (
            Cow::Borrowed(shown_name(request)),
            quantity_latex(request.quantity),
        ),
        Some(k) => (
            Cow::Owned(format!("{} (solution {k})", shown_name(request))),
            format!("{{{}}}^{{({k})}}", quantity_latex(request.quantity)),
        ),
    };
    let unit = result_unit(request, dims);
    let result = match v {
        Value::Scalar(e) => {
            let mut result = scalar(scene, name, name_latex, e.clone(), unit);
            let shown = names.apply(e);
            if shown != *e {
                result.text = print::text(&shown);
                result.latex = print::latex(&shown);
                result.form = Some(Cow::Owned(Value::Scalar(shown)));
            }
            result
        }
        Value::Vector(vec) => {
            let grouped = grouped(vec);
            Result {
                name,
                name_latex,
                text: vector_form(vec, grouped.as_ref(), Notation::Text),
                latex: vector_form(vec, grouped.as_ref(), Notation::Latex),
                value: vec.iter().map(|c| value(scene, c)).collect(),
                unit,
                form: Some(Cow::Borrowed(v)),
                grouped,
            }
        }
        // Inertia is in kg·m², whether its form has symbols or is a number.
        Value::Tensor(_) | Value::Principal(_) => Result {
            name,
            name_latex,
            text: inertia_results::one_line(v),
            latex: inertia_results::one_line_latex(v),
            value: inertia_results::values(v, |e| value(scene, e)),
            unit: Some(Dimension::INERTIA.si_unit()),
            form: Some(Cow::Borrowed(v)),
            grouped: None,
        },
        Value::Balance(corrections) => return super::balance_rows::rows(scene, corrections),
        Value::Precession(p) => return super::precession_rows::rows(scene, p),
    };
    vec![in_requested_unit(request, result)]
}

/// A vector result's form: its common factor in front where that reads shorter
/// ([`grouped`]), else component by component.
fn vector_form(v: &Vector, grouped: Option<&GroupedVector>, notation: Notation) -> String {
    match grouped {
        Some(g) => g.render(notation),
        None => print::vector(v, notation),
    }
}

/// The width in ems of a result's form on one line (none for a form of rows).
pub(super) fn form_em(r: &Result) -> f64 {
    match r.form.as_deref() {
        Some(Value::Scalar(e)) => print::width_em(e, Axis::X),
        Some(Value::Vector(v)) => match &r.grouped {
            Some(g) => g.width_em(),
            None => print::line_break::vector_width_em(v),
        },
        Some(Value::Balance(_) | Value::Tensor(_) | Value::Principal(_) | Value::Precession(_))
        | None => 0.0,
    }
}

/// The lines of a result's form in `notation`, broken to fit (a balance: its rows, each a
/// result of its own, have them). A grouped vector that does not fit on its line is
/// written component by component, broken as a sum is.
pub(super) fn form_lines(
    r: &Result,
    notation: Notation,
    first_em: f64,
    width_em: f64,
) -> Vec<String> {
    match r.form.as_deref() {
        Some(Value::Scalar(e)) => print::broken(e, Axis::X, notation, first_em, width_em),
        Some(Value::Vector(v)) => match &r.grouped {
            Some(g) if first_em + g.width_em() <= width_em => vec![g.render(notation)],
            _ => print::broken_vector(v, notation, first_em, width_em),
        },
        // Their rows are rendered by inertia_results; a balance's rows are results of their own.
        Some(Value::Balance(_) | Value::Tensor(_) | Value::Principal(_) | Value::Precession(_)) => {
            Vec::new()
        }
        // Known only as a number (shown as its value), or undefined (said in words).
        None if r.value.is_some() => Vec::new(),
        None => vec![match notation {
            Notation::MathMl => format!("<mtext>{}</mtext>", print::mathml::escaped(&r.text)),
            _ => r.latex.clone(),
        }],
    }
}

/// The name a result is shown under: the quantity as written (`H_G`, `m*vbar`), but an
/// unknown in its symbol's one spelling (`M_1` for `M1`), as the steps print it.
pub(super) fn shown_name(request: &Request) -> &str {
    match request.quantity {
        Quantity::Unknown(s) => s.name(),
        _ => &request.name,
    }
}

/// The two sides of a relation in the chosen notation, presented about its axis.
pub fn relation(r: &Relation, notation: Notation) -> (String, String) {
    (
        print::render(&r.lhs, notation, r.axis),
        print::render(&r.rhs, notation, r.axis),
    )
}

/// The quantity in LaTeX, as a textbook names it (`\mathbf{H}_G`, `T`, an unknown's symbol).
pub(super) fn quantity_latex(quantity: Quantity) -> String {
    match quantity {
        Quantity::AngularVelocity => r"\boldsymbol{\omega}".into(),
        Quantity::MassCentreVelocity => r"\bar{\mathbf{v}}".into(),
        Quantity::LinearMomentum => r"m\bar{\mathbf{v}}".into(),
        Quantity::MassCentreAcceleration => r"\bar{\mathbf{a}}".into(),
        Quantity::EffectiveForce => r"m\bar{\mathbf{a}}".into(),
        Quantity::AngularMomentumAboutG => r"\mathbf{H}_G".into(),
        Quantity::AngularMomentumAboutO => r"\mathbf{H}_O".into(),
        Quantity::KineticEnergy => "T".into(),
        Quantity::RateOfAngularMomentum => r"\dot{\mathbf{H}}_G".into(),
        Quantity::RateOfAngularMomentumAboutO => r"\dot{\mathbf{H}}_O".into(),
        Quantity::TranslationalKineticEnergy => r"T_{\text{trans}}".into(),
        Quantity::RotationalKineticEnergy => r"T_{\text{rot}}".into(),
        Quantity::PointVelocity(p) => format!(r"\mathbf{{v}}_{{{}}}", p.latex()),
        Quantity::PointAcceleration(p) => format!(r"\mathbf{{a}}_{{{}}}", p.latex()),
        // A vector named by one letter in bold, as the textbook writes `\mathbf{R}`.
        Quantity::NamedImpulse(s) | Quantity::NamedForce(s) => match s.latex() {
            letter if letter.len() == 1 && letter.chars().all(|c| c.is_ascii_alphabetic()) => {
                format!(r"\mathbf{{{letter}}}")
            }
            _ => print::latex(&Expr::sym(s)),
        },
        Quantity::InertiaAboutG | Quantity::InertiaAboutO => {
            inertia_results::tensor_name(quantity).into()
        }
        Quantity::PrincipalAboutG | Quantity::PrincipalAboutO => "I_1".into(),
        Quantity::Unknown(s) => print::latex(&Expr::sym(s)),
        Quantity::Balance => r"\text{balance}".into(),
        Quantity::Precession => r"\text{precession}".into(),
    }
}

/// A result's value with its unit in text: `-129.8 N·m`, a vector by its components
/// (`vector_value.rs`); none for a tensor's or a frame's numbers, which their rows show
/// (`inertia_results.rs`).
pub(super) fn value_text(r: &Result) -> Option<String> {
    let unit = r.unit.as_deref().unwrap_or_default();
    Some(match r.value.as_deref()? {
        [x] if unit.is_empty() => format_value(*x),
        [x] => format!("{} {unit}", format_value(*x)),
        components @ [_, _, _] => vector_value::text(components, unit),
        _ => return None,
    })
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
    // One page: two symbols that would print alike (`w_x` and `omega_x`) are told apart,
    // unless a relation `omega_x = w_x` states them one quantity.
    let relations = || analysis.plan.iter().flat_map(|s| &s.relations);
    let page = scene
        .givens
        .iter()
        .map(|g| g.symbol)
        .chain(relations().flat_map(|r| r.lhs.symbols().into_iter().chain(r.rhs.symbols())));
    let identities = relations().filter_map(|r| Some((r.lhs.as_symbol()?, r.rhs.as_symbol()?)));
    print::on_one_page(page, identities, || {
        let dims = scene_dimensions(scene);
        let results = results(scene, analysis, &dims);
        let page = solution_page(scene, analysis, &results);
        match format {
            Format::Text => super::text::page(&page),
            Format::Latex => super::latex::page(&page, standalone),
            Format::Markdown => super::markdown::page(&page),
            Format::Json => super::json::solution(&page, analysis).to_string(),
            Format::Html => super::html::page(&page),
        }
    })
}

/// The engineer's page ([`super::engineer`]): the givens, each result as a number with its
/// unit and the plan's intermediate values, without the symbolic steps; in text or JSON
/// (`None` for the other formats, whose pages are the worked solution).
pub fn render_numbers(scene: &Scene, analysis: &Analysis, format: Format) -> Option<String> {
    let dims = scene_dimensions(scene);
    let results = results(scene, analysis, &dims);
    match format {
        Format::Text => Some(super::engineer::text(scene, analysis, &results, &dims)),
        Format::Json => Some(super::engineer::json(scene, analysis, &results, &dims).to_string()),
        Format::Latex | Format::Markdown | Format::Html => None,
    }
}

pub(super) fn given_line(g: &crate::scene::model::Given) -> String {
    match &g.written {
        Some(w) => format!("{} = {w}", g.symbol.name()),
        None => format!("{} ({}, symbolic)", g.symbol.name(), g.dimension),
    }
}

/// The room of the results' forms ([`print::aligned_room`]), whose left-hand sides are the
/// quantities' names.
pub(super) fn results_room(results: &[Result]) -> (f64, f64) {
    let lhs_em = results
        .iter()
        .map(|r| print::width::symbol_em(&r.name_latex))
        .fold(0.0, f64::max);
    print::aligned_room(lhs_em)
}
