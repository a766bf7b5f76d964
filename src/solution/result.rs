//! A result as the page shows it, built once from the analysis and written by every
//! notation: its name, and a line `name = form = value unit` — or, for a principal frame,
//! a line per moment and axis and the remark on equal moments. A line's form is a
//! mathematical object (an expression, a vector with its common factor in front, a matrix,
//! words); its value, the numbers in the unit shown; [`Show`] says which of the two the
//! page gives.
//!
//! A balance's corrections (`balance_rows.rs`) and a precession's angle and sense
//! (`precession_rows.rs`) are results of their own, a line each.

use super::inertia_results;
use super::numbers::{result_unit, value};
use super::page::Name;
use super::shown_value::ShownValue;
use crate::algebra::{Axis, Expr, Matrix, Vector};
use crate::print::grouped_vector::{grouped, GroupedVector};
use crate::print::{self, markup, matrix, Notation};
use crate::scene::analysis::Abbreviations;
use crate::scene::model::{Quantity, Request};
use crate::scene::named_unit::{NamedUnit, NO_UNIT};
use crate::scene::units::Dimensions;
use crate::scene::{Analysis, Scene, Value};
use std::borrow::Cow;

/// A requested quantity's result.
pub(super) struct Result<'a> {
    /// The quantity as the page names it (`H_G`, `principal_G`, `m_1`).
    pub name: Name,
    pub body: Body<'a>,
}

/// What a result shows.
pub(super) enum Body<'a> {
    /// One line (its name the result's).
    Line(Line<'a>),
    /// A principal frame: the moments `I_1 ≤ I_2 ≤ I_3`, the axes `e_1, e_2, e_3`, and the
    /// remark on equal moments.
    Frame {
        moments: Vec<Line<'a>>,
        axes: Vec<Line<'a>>,
        remark: Option<Line<'a>>,
    },
}

/// One line of a result: `name = form = value unit`, or part of it.
pub(super) struct Line<'a> {
    pub name: Name,
    /// None for a number found only from the values (a balance's angle by atan2).
    pub form: Option<Form<'a>>,
    /// The numbers (one, a vector's three, a tensor's nine row by row) in `unit`.
    pub value: Option<Vec<f64>>,
    /// The unit of the value (and of the form).
    pub unit: Option<NamedUnit>,
    pub show: Show,
}

/// A line's form.
pub(super) enum Form<'a> {
    Expr(Cow<'a, Expr>),
    /// A vector, with its common factor in front where that reads shorter ([`grouped`]):
    /// found once, shown by every notation.
    Vector(Cow<'a, Vector>, Option<GroupedVector>),
    Matrix(&'a Matrix),
    /// Words in the markup of titles: a precession's sense, no balance correction.
    Words(Cow<'a, str>),
}

/// What a line shows of its form and its value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Show {
    Form,
    Value,
    /// `form = value`.
    Both,
}

impl Form<'_> {
    /// The form on one line.
    pub(super) fn render(&self, notation: Notation) -> String {
        match self {
            Form::Expr(e) => print::render(e, notation, Axis::X),
            Form::Vector(_, Some(g)) => g.render(notation),
            Form::Vector(v, None) => print::vector(v, notation),
            Form::Matrix(m) => matrix::matrix(m, notation),
            Form::Words(w) => match notation {
                Notation::Text => markup::text(w),
                Notation::Latex => format!(r"\text{{{}}}", markup::latex(w)),
                Notation::MathMl => markup::mathml(w),
            },
        }
    }

    /// The form broken into lines that fit `width_em`, the first starting at `first_em`: an
    /// expression as a relation's side is, a grouped vector that does not fit written
    /// component by component; a matrix and words on one line.
    pub(super) fn lines(&self, notation: Notation, first_em: f64, width_em: f64) -> Vec<String> {
        match self {
            Form::Expr(e) => print::broken(e, Axis::X, notation, first_em, width_em),
            Form::Vector(_, Some(g)) if first_em + g.width_em() <= width_em => {
                vec![g.render(notation)]
            }
            Form::Vector(v, _) => print::broken_vector(v, notation, first_em, width_em),
            Form::Matrix(_) | Form::Words(_) => vec![self.render(notation)],
        }
    }

    /// The width in ems of the form on one line in LaTeX.
    pub(super) fn width_em(&self) -> f64 {
        match self {
            Form::Expr(e) => print::width_em(e, Axis::X),
            Form::Vector(_, Some(g)) => g.width_em(),
            Form::Vector(v, None) => print::line_break::vector_width_em(v),
            Form::Matrix(m) => matrix::matrix_em(m),
            Form::Words(w) => print::width::symbol_em(&markup::text(w)),
        }
    }
}

impl<'a> Line<'a> {
    /// The line's right side on one line: its form, or its numbers (without the unit) where
    /// it shows only its value.
    pub(super) fn one_line(&self, notation: Notation) -> String {
        match (&self.form, self.show) {
            (Some(form), Show::Form | Show::Both) => form.render(notation),
            (_, _) => self.value.as_deref().map_or_else(String::new, |numbers| {
                let unit = &NO_UNIT;
                ShownValue { numbers, unit }.render(notation)
            }),
        }
    }

    /// The value with its unit, where the line has one.
    pub(super) fn shown_value(&self) -> Option<ShownValue<'_>> {
        Some(ShownValue {
            numbers: self.value.as_deref()?,
            unit: self.unit.as_ref().unwrap_or(&NO_UNIT),
        })
    }

    /// A scalar line: the form with its value, or the value alone where the form is an
    /// integer (its digits are the value).
    pub(super) fn scalar(
        scene: &Scene,
        name: Name,
        e: Cow<'a, Expr>,
        unit: Option<NamedUnit>,
    ) -> Self {
        let value = in_unit(scene, value(scene, &e).map(|x| vec![x]), unit.as_ref());
        let integer = e.as_num().is_some_and(|q| q.is_integer());
        Line {
            name,
            show: match value {
                Some(_) if integer => Show::Value,
                Some(_) => Show::Both,
                None => Show::Form,
            },
            form: Some(Form::Expr(e)),
            value,
            unit,
        }
    }

    /// A line said in words, with no number.
    pub(super) fn words(name: Name, words: impl Into<Cow<'a, str>>) -> Self {
        Line {
            name,
            form: Some(Form::Words(words.into())),
            value: None,
            unit: None,
            show: Show::Form,
        }
    }

    /// A number known only as a number, in `unit`.
    pub(super) fn number(name: Name, x: f64, unit: NamedUnit) -> Self {
        Line {
            name,
            form: None,
            value: Some(vec![x]),
            unit: Some(unit),
            show: Show::Value,
        }
    }
}

impl<'a> Result<'a> {
    /// A result of one line, named as the line.
    pub(super) fn line(line: Line<'a>) -> Self {
        Result {
            name: line.name.clone(),
            body: Body::Line(line),
        }
    }

    /// Its lines in the page's order.
    pub(super) fn lines(&self) -> Box<dyn Iterator<Item = &Line<'a>> + '_> {
        match &self.body {
            Body::Line(line) => Box::new(std::iter::once(line)),
            Body::Frame {
                moments,
                axes,
                remark,
            } => Box::new(moments.iter().chain(axes).chain(remark)),
        }
    }

    /// Whether the result has its numbers (or is said in words, which is all there is to
    /// say): a frame, when its moments have values.
    pub(super) fn has_value(&self) -> bool {
        match &self.body {
            Body::Line(l) => l.value.is_some() || matches!(l.form, Some(Form::Words(_))),
            Body::Frame { moments, .. } => moments.iter().all(|l| l.value.is_some()),
        }
    }

    /// The result on one line (JSON's `text` and `latex`): a line's form, or its number
    /// where it shows only its value; a frame's moments and axes `I_1 = …` joined.
    pub(super) fn one_line(&self, notation: Notation) -> String {
        let shown = |l: &Line| l.one_line(notation);
        match &self.body {
            Body::Line(line) => shown(line),
            Body::Frame { moments, axes, .. } => {
                let separator = match notation {
                    Notation::Latex => r",\quad ",
                    Notation::Text | Notation::MathMl => "; ",
                };
                let rows: Vec<String> = moments
                    .iter()
                    .chain(axes)
                    .map(|l| format!("{} = {}", l.name.text, shown(l)))
                    .collect();
                rows.join(separator)
            }
        }
    }
}

/// The results of `analysis`, in its order.
pub(super) fn results<'a>(
    scene: &Scene,
    analysis: &'a Analysis,
    dims: &Dimensions,
) -> Vec<Result<'a>> {
    analysis
        .results
        .iter()
        .flat_map(|(request, v)| computed(scene, request, v, dims, &analysis.abbreviations))
        .collect()
}

/// A request's result: one, or a balance's or a precession's lines, each a result.
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
    let name = match request.solution {
        None => Name {
            text: shown_name(request).into(),
            latex: quantity_latex(request.quantity),
        },
        Some(k) => Name {
            text: format!("{} (solution {k})", shown_name(request)),
            latex: format!("{{{}}}^{{({k})}}", quantity_latex(request.quantity)),
        },
    };
    let unit = result_unit(request, dims, scene.unit_system);
    let result = match v {
        Value::Scalar(e) => {
            let mut line = Line::scalar(scene, name, Cow::Borrowed(e), unit);
            let shown = names.apply(e);
            if shown != *e {
                line.form = Some(Form::Expr(Cow::Owned(shown)));
            }
            Result::line(line)
        }
        Value::Vector(vec) => {
            let value = in_unit(
                scene,
                vec.iter().map(|c| value(scene, c)).collect(),
                unit.as_ref(),
            );
            // A zero vector's value says all its form does.
            let zero = vec.iter().all(Expr::is_zero);
            Result::line(Line {
                name,
                form: Some(Form::Vector(Cow::Borrowed(vec), grouped(vec))),
                show: match value {
                    Some(_) if zero => Show::Value,
                    Some(_) => Show::Both,
                    None => Show::Form,
                },
                value,
                unit,
            })
        }
        Value::Tensor(m) => Result::line(inertia_results::tensor(scene, name, m)),
        Value::Principal(frame) => inertia_results::frame(scene, name, frame),
        Value::Balance(corrections) => return super::balance_rows::rows(scene, corrections),
        Value::Precession(p) => return super::precession_rows::rows(scene, p),
    };
    vec![in_requested_unit(request, result)]
}

/// Values in the scene's unit system given in `unit` (divided by one `unit` in the system;
/// as they are without one).
pub(super) fn in_unit(
    scene: &Scene,
    values: Option<Vec<f64>>,
    unit: Option<&NamedUnit>,
) -> Option<Vec<f64>> {
    let one = unit.map_or(1.0, |u| scene.unit_system.of_one(u));
    values.map(|v| v.into_iter().map(|x| x / one).collect())
}

/// A value asked for `in UNIT` (else an unknown's declared unit) is converted from the unit
/// it is in and labelled with the unit as written (a principal frame's moments; its axes
/// have no unit).
fn in_requested_unit<'a>(request: &Request, mut result: Result<'a>) -> Result<'a> {
    let Some(unit) = request.unit.as_ref().or(request.shown_in.as_ref()) else {
        return result;
    };
    let to_si = unit.unit().to_si;
    let convert = |line: &mut Line| {
        let from_si = line.unit.as_ref().map_or(1.0, |u| u.unit().to_si);
        if let Some(v) = &mut line.value {
            v.iter_mut().for_each(|x| *x *= from_si / to_si);
        }
        line.unit = Some(unit.clone());
    };
    match &mut result.body {
        Body::Line(line) => convert(line),
        Body::Frame { moments, .. } => moments.iter_mut().for_each(convert),
    }
    result
}

/// The name a result is shown under: the quantity as written (`H_G`, `m*vbar`), but an
/// unknown in its symbol's one spelling (`M_1` for `M1`), as the steps print it.
pub(super) fn shown_name(request: &Request) -> &str {
    match request.quantity {
        Quantity::Unknown(s) => s.name(),
        _ => &request.name,
    }
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
        Quantity::KineticEnergyBefore => "T_1".into(),
        Quantity::KineticEnergyAfter => "T_2".into(),
        Quantity::EnergyLost => r"T_{\text{lost}}".into(),
        Quantity::PointVelocity(p) => format!(r"\mathbf{{v}}_{{{}}}", p.latex()),
        Quantity::PointAcceleration(p) => format!(r"\mathbf{{a}}_{{{}}}", p.latex()),
        // A vector named by one letter in bold, as the textbook writes `\mathbf{R}`.
        Quantity::NamedImpulse(s) | Quantity::NamedForce(s) => match s.latex() {
            letter if letter.len() == 1 && letter.chars().all(|c| c.is_ascii_alphabetic()) => {
                format!(r"\mathbf{{{letter}}}")
            }
            _ => print::latex(&Expr::sym(s)),
        },
        Quantity::InertiaAboutG => "[I_G]".into(),
        Quantity::InertiaAboutO => "[I_O]".into(),
        Quantity::PrincipalAboutG | Quantity::PrincipalAboutO => "I_1".into(),
        Quantity::Unknown(s) => print::latex(&Expr::sym(s)),
        Quantity::Balance => r"\text{balance}".into(),
        Quantity::Precession => r"\text{precession}".into(),
    }
}
