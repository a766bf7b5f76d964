//! The worked solution as data a program reads (the Python binding, a notebook): each line
//! of the page's results as an [`Answer`] — its name, its form in text and LaTeX, the
//! exact expression behind it, its numbers in its unit, the line in HTML — and each step of the plan as a
//! [`WorkedStep`], its title and its relations as the page shows them.
//!
//! Sample Problem 18.4's reaction at D, `D_y = −3M/(16c) − m c ω²/4`:
//!
//! ```
//! use kinetics::{analyse, answers, parse_expression, parse_scene, AnswerForm};
//!
//! let source = std::fs::read_to_string("examples/scenes/sp18_4_shaft_reactions.scene")?;
//! let scene = parse_scene("sp18_4.scene", &source)?;
//! let analysis = analyse(&scene)?;
//! let d_y = answers(&scene, &analysis).into_iter().find(|a| a.name == "D_y").unwrap();
//! let AnswerForm::Expr(form) = &d_y.form else { panic!("D_y is a scalar") };
//! assert_eq!(*form, parse_expression("by hand", "-3 M/(16 c) - m c w^2/4")?);
//! assert_eq!(d_y.text, "-3*M/(16*c) - 1/4*m*c*w^2");
//! assert_eq!(d_y.unit.as_deref(), Some("N"));
//! // −3 · 6/(16 · 0.1) − 0.3 · 0.1 · 125.7²/4 = −11.25 − 118.5 N
//! let by_hand = -3.0 * 6.0 / (16.0 * 0.1) - 0.3 * 0.1 * 125.7f64.powi(2) / 4.0;
//! assert!((d_y.value.unwrap()[0] - by_hand).abs() < 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::page::{Block, Heading, Section};
use super::render::on_the_page;
use super::result::{results, Form, Line};
use super::solution_page::solution_page;
use crate::algebra::{Expr, Matrix, Vector};
use crate::print::{markup, Notation};
use crate::scene::{Analysis, Scene};

/// One line of a worked solution's results.
#[derive(Debug, Clone)]
pub struct Answer {
    /// The name as the page writes it in text (`D_y`, `H_G`, `I_1`, `m_1`).
    pub name: String,
    pub name_latex: String,
    /// The right side on one line, in text and in LaTeX: the form, or the number where the
    /// page shows only the number.
    pub text: String,
    pub latex: String,
    /// The exact object behind it, long radicands written out in full.
    pub form: AnswerForm,
    /// Its numbers in `unit` (one, a vector's three, a tensor's nine row by row); none
    /// where a given has no value.
    pub value: Option<Vec<f64>>,
    /// The unit of the numbers (`N`, `rad/s^2`), none for a pure number.
    pub unit: Option<String>,
    /// The numbers with their unit, in text (`-129.8 N`) and in LaTeX (`-129.8\,\mathrm{N}`).
    pub value_text: Option<String>,
    pub value_latex: Option<String>,
    /// The whole line, `name = form = value unit`, as a fragment of HTML: a block of MathML
    /// with the page's style scoped to it.
    pub html: String,
}

/// What an answer is, exactly.
#[derive(Debug, Clone)]
pub enum AnswerForm {
    Expr(Expr),
    Vector(Vector),
    Matrix(Matrix),
    /// Said in words: a precession's sense, "no correction needed".
    Words(String),
    /// Known only as a number: a balance's angle found by atan2.
    Number,
}

/// A step of the plan as the page shows it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WorkedStep {
    pub title: String,
    pub title_latex: String,
    /// Its rows of relations, `lhs = rhs` (equal components on one row), each in text and
    /// in LaTeX.
    pub relations: Vec<(String, String)>,
}

/// The lines of the results of `analysis`, in its order (a principal frame's moments and
/// axes, a balance's masses and angles, each a line of its own).
pub fn answers(scene: &Scene, analysis: &Analysis) -> Vec<Answer> {
    on_the_page(scene, analysis, || {
        let dims = super::numbers::scene_dimensions(scene);
        let results = results(scene, analysis, &dims);
        let whole = |e: &Expr| analysis.abbreviations.whole(e);
        results
            .iter()
            .flat_map(|r| r.lines())
            .map(|line: &Line| Answer {
                name: line.name.text.clone(),
                name_latex: line.name.latex.clone(),
                text: line.one_line(Notation::Text),
                latex: line.one_line(Notation::Latex),
                form: match &line.form {
                    Some(Form::Expr(e)) => AnswerForm::Expr(whole(e)),
                    Some(Form::Vector(v, _)) => AnswerForm::Vector(v.map(|c| whole(&c))),
                    Some(Form::Matrix(m)) => AnswerForm::Matrix(m.map(|c| whole(&c))),
                    Some(Form::Words(w)) => AnswerForm::Words(markup::text(w)),
                    None => AnswerForm::Number,
                },
                value: line.value.clone(),
                unit: line
                    .unit
                    .as_ref()
                    .filter(|u| !u.is_none())
                    .map(ToString::to_string),
                value_text: line.shown_value().map(|v| v.render(Notation::Text)),
                value_latex: line.shown_value().map(|v| v.render(Notation::Latex)),
                html: super::html::result_line(line),
            })
            .collect()
    })
}

/// The steps of the plan as the worked solution shows them (a step with nothing to say
/// left out, as on the page).
pub fn worked_steps(scene: &Scene, analysis: &Analysis) -> Vec<WorkedStep> {
    on_the_page(scene, analysis, || {
        let dims = super::numbers::scene_dimensions(scene);
        let results = results(scene, analysis, &dims);
        let page = solution_page(scene, analysis, &results, None);
        page.sections
            .iter()
            .filter(|s| matches!(s.heading, Heading::Step { .. }))
            .map(WorkedStep::of)
            .collect()
    })
}

impl WorkedStep {
    /// A section of a page headed by a step of the plan or of a derivation.
    pub(super) fn of(section: &Section) -> WorkedStep {
        let title = match section.heading {
            Heading::Step { title, .. } | Heading::DerivationStep(title) => title,
            _ => "",
        };
        let relations = section
            .blocks
            .iter()
            .filter_map(|block| match block {
                Block::Relations(rows) => Some(rows),
                _ => None,
            })
            .flatten()
            .map(|row| (row.one_line(Notation::Text), row.one_line(Notation::Latex)))
            .collect();
        WorkedStep {
            title: markup::text(title),
            title_latex: markup::latex(title),
            relations,
        }
    }
}
