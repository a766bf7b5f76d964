//! The document model of a page: a worked solution (`solve`) or a page of derivations
//! (`derive`) is built once into a [`Page`] — a title, then sections, each a heading and its
//! blocks — and each notation's writer walks it (`text.rs`, `latex.rs`, `markdown.rs`,
//! `html.rs`, `json.rs`). What a page holds and in what order is decided where it is built
//! (`solution_page.rs`, `derivations.rs`); how a block looks, once per writer.
//!
//! A block of relations leaves out what a reader need not read: a tautology (a quantity
//! equal to itself, as given) is not shown, and consecutive components of one quantity with
//! one value share a row, `I_xy = I_yz = I_xz = 0`.

use super::engineer::StepValues;
use super::result::{Form, Result};
use crate::algebra::{Symbol, Vector};
use crate::figure::Figure;
use crate::mechanics::derivation::{Relation, Step, Table};
use crate::print::grouped_vector::grouped;
use crate::print::markup;
use crate::print::{self, Notation};
use crate::scene::model::Given;
use std::borrow::Cow;

/// A page: its title (words with `$…$` mathematics, as a scene's `title`) and sections.
pub struct Page<'a> {
    pub title: Option<&'a str>,
    /// What the page is called where it has no title (an HTML page's `<title>`).
    pub untitled: &'static str,
    pub sections: Vec<Section<'a>>,
    /// Where a Markdown page's figure is written (an SVG beside the page), when it is.
    pub figure_file: Option<&'a str>,
}

/// A heading, what stands under it, and the sections under that (a derivation's steps).
pub struct Section<'a> {
    pub heading: Heading<'a>,
    pub blocks: Vec<Block<'a>>,
    pub subsections: Vec<Section<'a>>,
}

impl<'a> Section<'a> {
    /// A section without subsections.
    pub fn new(heading: Heading<'a>, blocks: Vec<Block<'a>>) -> Section<'a> {
        Section {
            heading,
            blocks,
            subsections: Vec::new(),
        }
    }
}

/// What a section is, which each notation heads in its own way.
pub enum Heading<'a> {
    /// What the problem says (a scene's `statement` lines) and its figure, under the title,
    /// unheaded.
    Statement,
    Given,
    Find,
    /// The results as numbers, before the steps. Only the text page shows it: the typeset
    /// pages give each value beside its result's form.
    Answers,
    /// A step of the plan, numbered from 1, titled in the markup of titles.
    Step {
        number: usize,
        title: &'a str,
    },
    Results,
    /// The plan's intermediate values (the engineer's page).
    Intermediate,
    /// A derivation of `kinetics derive` (its name, `H_G`, and its title), and one of its
    /// steps.
    Derivation {
        name: &'a str,
        title: &'a str,
    },
    DerivationStep(&'a str),
}

/// The content of a section.
pub enum Block<'a> {
    /// A paragraph in the markup of titles.
    Words(Cow<'a, str>),
    /// The givens, each its value as written or its name alone when symbolic.
    Givens(&'a [Given]),
    /// The quantities asked for, by name.
    Find(Vec<Name>),
    /// A composite body's table of parts.
    Table(&'a Table),
    /// Relations aligned at `=`, each right-hand side broken to fit the page.
    Relations(Vec<Row<'a>>),
    /// Results with their forms, values and units.
    Results(&'a [Result<'a>]),
    /// The results by their numbers alone (or words); a result without a value says so.
    Answers(&'a [Result<'a>]),
    /// The intermediate values of the plan's steps, each under its step's title.
    Values(&'a [StepValues]),
    /// The scene's figure (after the statement, before Given): TikZ in LaTeX, inline SVG in
    /// HTML, an image beside a Markdown page ([`Page::figure_file`]); none in text.
    Figure(&'a Figure),
}

/// A quantity's name in text (`H_G`) and in LaTeX (`\mathbf{H}_G`).
#[derive(Clone)]
pub struct Name {
    pub text: String,
    pub latex: String,
}

/// One row of a block of relations: `lhs = rhs`, or components of one quantity equal to
/// one value, `q₁ = q₂ = … = value`.
pub enum Row<'a> {
    Relation(&'a Relation),
    /// Relations `qₖ = value` of consecutive components of one named quantity, each with
    /// the same right-hand side (one or more).
    Equal(Vec<&'a Relation>),
    /// A named vector (its name in the LaTeX subset of titles), written as a vector (its
    /// common factor in front where that reads shorter).
    Vector(Cow<'a, str>, Form<'a>),
}

impl Row<'_> {
    /// The left of the row's first `=`: a relation's left-hand side, or the first of the
    /// equal quantities (the row aligns there, as its column does); a vector's name.
    pub fn left(&self, notation: Notation) -> String {
        if let Row::Vector(name, _) = self {
            return match notation {
                Notation::Latex => name.to_string(),
                Notation::Text => markup::text(&format!("${name}$")),
                Notation::MathMl => markup::mathml(&format!("${name}$")),
            };
        }
        self.relations().map_or_else(String::new, |(first, _, _)| {
            print::render(&first.lhs, notation, first.axis)
        })
    }

    /// The width in ems of [`Row::left`] typeset, for the room of the right-hand sides.
    pub fn left_em(&self) -> f64 {
        match self.relations() {
            Some((first, _, _)) => print::width_em(&first.lhs, first.axis),
            None => print::width::symbol_em(&self.left(Notation::Text)),
        }
    }

    /// The right of the row's first `=` in `notation`, in lines that fit from `first_em`
    /// within `width_em`: the right-hand side broken as a sum is, after the other equal
    /// quantities (`I_yz = I_xz = 0`); a vector as [`Form::lines`] breaks it.
    pub fn right_lines(&self, notation: Notation, first_em: f64, width_em: f64) -> Vec<String> {
        let Some((_, others, last)) = self.relations() else {
            return self
                .vector_form()
                .map_or_else(Vec::new, |form| form.lines(notation, first_em, width_em));
        };
        let others_em: f64 = others
            .iter()
            .map(|r| print::width_em(&r.lhs, r.axis) + print::width::RELATION_EM)
            .sum();
        let mut lines = print::broken(
            &last.rhs,
            last.axis,
            notation,
            first_em + others_em,
            width_em,
        );
        if let Some(first) = lines.first_mut() {
            *first = format!("{}{first}", others_text(others, notation));
        }
        lines
    }

    /// The row on one line in `notation`, `lhs = rhs` (for JSON and the tests).
    pub fn one_line(&self, notation: Notation) -> String {
        let right = match self.relations() {
            Some((_, others, last)) => {
                let right = print::render(&last.rhs, notation, last.axis);
                format!("{}{right}", others_text(others, notation))
            }
            None => self
                .vector_form()
                .map_or_else(String::new, |f| f.render(notation)),
        };
        format!("{} = {right}", self.left(notation))
    }

    /// A row of relations: its first, the ones after the first, and the last (whose
    /// right-hand side the row ends with); none for a vector's row.
    fn relations(&self) -> Option<(&Relation, &[&Relation], &Relation)> {
        match self {
            Row::Relation(r) => Some((r, &[], r)),
            Row::Equal(equal) => Some((equal.first()?, &equal[1..], equal.last()?)),
            Row::Vector(..) => None,
        }
    }

    fn vector_form(&self) -> Option<&Form<'_>> {
        match self {
            Row::Vector(_, form) => Some(form),
            Row::Relation(_) | Row::Equal(_) => None,
        }
    }
}

/// The equal quantities after the first, each followed by `=`.
fn others_text(others: &[&Relation], notation: Notation) -> String {
    let equals = match notation {
        Notation::MathMl => "<mo>=</mo>",
        _ => " = ",
    };
    others
        .iter()
        .map(|r| print::render(&r.lhs, notation, r.axis) + equals)
        .collect()
}

/// The rows of a step: its named vectors, then its relations' rows ([`rows`]), where the
/// three components of one vector follow each other written as that vector (`ω = ω j`,
/// not `ω_x = 0`, `ω_y = ω`, `ω_z = 0`).
pub fn step_rows(step: &Step) -> Vec<Row<'_>> {
    fn vector_row<'a>(name: Cow<'a, str>, v: Cow<'a, Vector>) -> Row<'a> {
        let grouped = grouped(&v);
        Row::Vector(name, Form::Vector(v, grouped))
    }
    let mut shown: Vec<Row> = step
        .vectors
        .iter()
        .map(|v| vector_row(Cow::Borrowed(&v.name), Cow::Borrowed(&v.value)))
        .collect();
    let relations = &step.relations;
    let (mut start, mut k) = (0, 0);
    while k < relations.len() {
        match one_vector(&relations[k..]) {
            Some((name, v)) => {
                shown.extend(rows(&relations[start..k]));
                shown.push(vector_row(Cow::Owned(name), Cow::Owned(v)));
                k += 3;
                start = k;
            }
            None => k += 1,
        }
    }
    shown.extend(rows(&relations[start..]));
    shown
}

/// The vector whose x, y and z components the first three relations give, and its name,
/// where they are `q_x`, `q_y`, `q_z` of one of the kinematic vectors the chapter writes in
/// bold (ω, Ω, α and their rates; v̄, ā, r̄), none of them saying nothing. Moments of
/// inertia are no vector, and the angular momentum and its rate stay in components: the
/// moment equations take them one by one.
fn one_vector(relations: &[Relation]) -> Option<(String, Vector)> {
    let three = relations.get(..3)?;
    let symbols: Vec<Symbol> = three
        .iter()
        .map(|r| r.lhs.as_symbol())
        .collect::<Option<_>>()?;
    let stem = |s: &Symbol| s.name().rsplit_once('_').map(|(stem, _)| stem);
    let first = symbols[0];
    let one_quantity = symbols
        .iter()
        .enumerate()
        .all(|(k, s)| s.axis() == Some(k) && s.subscript().len() == 1 && stem(s) == stem(&first));
    if !one_quantity || three.iter().any(is_tautology) {
        return None;
    }
    let name = vector_latex(first, stem(&first)?)?;
    Some((
        name,
        Vector::from_iterator(three.iter().map(|r| r.rhs.clone())),
    ))
}

/// A kinematic vector's name in bold from a component's symbol: `omegadot_x` is
/// `\dot{\boldsymbol{\omega}}`, `abar_x` is `\bar{\mathbf{a}}`; none for any other quantity.
fn vector_latex(component: Symbol, stem: &str) -> Option<String> {
    let base = component.base();
    let barred = stem
        .strip_prefix(base)
        .is_some_and(|rest| rest.starts_with("bar"));
    let name = match (base, barred) {
        ("omega" | "w", false) => r"\boldsymbol{\omega}".to_string(),
        ("Omega" | "alpha", false) => format!(r"\boldsymbol{{\{base}}}"),
        ("v" | "a" | "r", true) => format!(r"\bar{{\mathbf{{{base}}}}}"),
        _ => return None,
    };
    match component.dots() {
        0 => Some(name),
        1 => Some(format!(r"\dot{{{name}}}")),
        _ => None,
    }
}

/// The rows `relations` are shown as: tautologies left out (a quantity equal to itself, or
/// to a symbol the page prints alike: `omega_x = w_x` where `w_x` is ω_x), consecutive
/// components of one named quantity with the same value on one row (`I_xy = I_yz = I_xz =
/// 0`, `r̄_y = r̄_z = ¼c`; not `ω_z = Ω_x = 0`).
pub fn rows(relations: &[Relation]) -> Vec<Row<'_>> {
    let mut rows: Vec<Row> = Vec::new();
    for r in relations {
        if is_tautology(r) {
            continue;
        }
        let Some(name) = r.lhs.as_symbol() else {
            rows.push(Row::Relation(r));
            continue;
        };
        // One quantity: the same name before its subscript (`I_xy`, `I_yz`).
        let stem = |s: crate::algebra::Symbol| s.name().split('_').next().unwrap_or_default();
        let joins = |equal: &Vec<&Relation>| {
            equal[0].rhs == r.rhs
                && equal[0]
                    .lhs
                    .as_symbol()
                    .is_some_and(|s| stem(s) == stem(name))
        };
        match rows.last_mut() {
            Some(Row::Equal(equal)) if joins(equal) => equal.push(r),
            _ => rows.push(Row::Equal(vec![r])),
        }
    }
    rows
}

/// Whether a relation says nothing: its sides equal, or two symbols printed alike.
fn is_tautology(r: &Relation) -> bool {
    r.lhs == r.rhs
        || (r.lhs.as_symbol().is_some()
            && r.rhs.as_symbol().is_some()
            && print::latex(&r.lhs) == print::latex(&r.rhs))
}

/// The room of the right-hand sides of `rows`, from the widest left side
/// ([`print::aligned_room`]): LaTeX's `align*` and HTML's table alike.
pub fn rows_room(rows: &[Row]) -> (f64, f64) {
    let left_em = rows.iter().map(Row::left_em).fold(0.0, f64::max);
    print::aligned_room(left_em)
}

#[cfg(test)]
mod tests {
    use super::{rows, Row};
    use crate::algebra::{Axis, Expr};
    use crate::mechanics::derivation::Relation;
    use crate::print::Notation;

    fn relation(lhs: &str, rhs: Expr) -> Relation {
        Relation::new(Expr::symbol(lhs), rhs, Axis::X)
    }

    #[test]
    fn tautologies_left_out_and_consecutive_zeros_on_one_row() {
        let relations = [
            relation("vbar_x", Expr::symbol("vbar_x")),
            relation("I_x", Expr::symbol("m")),
            relation("I_xy", Expr::zero()),
            relation("I_yz", Expr::zero()),
            relation("I_xz", Expr::zero()),
            relation("H_x", Expr::symbol("m")),
            relation("H_z", Expr::zero()),
        ];
        let shown: Vec<String> = rows(&relations)
            .iter()
            .map(|row| row.one_line(Notation::Text))
            .collect();
        assert_eq!(
            shown,
            ["I_x = m", "I_xy = I_yz = I_xz = 0", "H_x = m", "H_z = 0"]
        );
    }

    /// `ω_x = 0`, `ω_y = w`, `ω_z = 0` is the vector `ω = w j`; `ā` likewise, accent and
    /// all; the components of H stay rows, and so does a triple with a tautology.
    #[test]
    fn three_components_of_one_vector_are_that_vector() {
        use crate::mechanics::derivation::Step;
        let w = Expr::symbol("w");
        let step = Step::new(
            "kinematics",
            vec![
                relation("I_x", Expr::symbol("m")),
                relation("omega_x", Expr::zero()),
                relation("omega_y", w.clone()),
                relation("omega_z", Expr::zero()),
                relation("abar_x", -&w),
                relation("abar_y", Expr::zero()),
                relation("abar_z", Expr::zero()),
                relation("H_x", Expr::zero()),
                relation("H_y", w.clone()),
                relation("H_z", Expr::zero()),
                relation("vbar_x", Expr::symbol("vbar_x")),
                relation("vbar_y", Expr::zero()),
                relation("vbar_z", Expr::zero()),
            ],
        );
        let rows = super::step_rows(&step);
        let latex: Vec<String> = rows.iter().map(|r| r.one_line(Notation::Latex)).collect();
        assert_eq!(
            latex,
            [
                "I_x = m",
                r"\boldsymbol{\omega} = \omega \mathbf{j}",
                r"\bar{\mathbf{a}} = -\omega \mathbf{i}",
                "H_x = 0",
                r"H_y = \omega",
                "H_z = 0",
                r"\bar{v}_y = \bar{v}_z = 0",
            ]
        );
    }

    #[test]
    fn a_zero_equation_that_is_no_named_quantity_stays_a_row_of_its_own() {
        let sum = &Expr::symbol("C_x") + &Expr::symbol("D_x");
        let relations = [
            relation("A_x", Expr::zero()),
            Relation::new(sum, Expr::zero(), Axis::X),
        ];
        let rows = rows(&relations);
        assert_eq!(rows.len(), 2);
        assert!(matches!(rows[1], Row::Relation(_)));
        assert!(matches!(&rows[0], Row::Equal(equal) if equal.len() == 1));
    }
}
