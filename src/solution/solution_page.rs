//! A scene's worked solution as a [`Page`]: what the problem says (its `statement` lines) and
//! its figure,
//! the givens, the quantities asked for, the answers as numbers when every given has a value,
//! each step of the plan that has something to say (its table of parts, its relations), then
//! the results (a last step that only states them is left to Results).

use super::page::{step_rows, Block, Heading, Name, Page, Section};
use super::result::{quantity_latex, shown_name, Body, Form, Result};
use crate::figure::Figure;
use crate::mechanics::derivation::Relation;
use crate::mechanics::Step;
use crate::scene::{Analysis, Scene};
use std::borrow::Cow;

/// The page of `scene`'s solution (`results` in the order of `analysis.results`).
pub(super) fn solution_page<'a>(
    scene: &'a Scene,
    analysis: &'a Analysis,
    results: &'a [Result<'a>],
    figure: Option<&'a Figure>,
) -> Page<'a> {
    let mut sections = Vec::new();
    let mut statement = Vec::new();
    if !scene.statement.is_empty() {
        statement.push(Block::Words(Cow::Owned(scene.statement.join(" "))));
    }
    statement.extend(figure.map(Block::Figure));
    if !statement.is_empty() {
        sections.push(Section::new(Heading::Statement, statement));
    }
    sections.push(Section::new(
        Heading::Given,
        vec![Block::Givens(&scene.givens)],
    ));
    sections.push(Section::new(
        Heading::Find,
        vec![Block::Find(requested(analysis))],
    ));
    let numbers = results.iter().any(Result::has_value);
    if numbers && scene.givens.iter().all(|g| g.value.is_some()) {
        sections.push(Section::new(
            Heading::Answers,
            vec![Block::Answers(results)],
        ));
    }
    // A last step that only states the unknowns solved for, each a result, is left to
    // Results, which gives the same forms with their numbers.
    let plan = match analysis.plan.split_last() {
        Some((last, before)) if only_solves_for_results(scene, last, results) => before,
        _ => &analysis.plan[..],
    };
    let mut number = 0;
    for step in plan {
        let rows = step_rows(step);
        // A step whose every relation says nothing (the velocity as given) is left out; one
        // with no relations says what it found in its title.
        if rows.is_empty() && !step.relations.is_empty() && step.table.is_none() {
            continue;
        }
        let mut blocks = Vec::new();
        if let Some(table) = &step.table {
            blocks.push(Block::Table(table));
        }
        blocks.push(Block::Relations(rows));
        number += 1;
        let heading = Heading::Step {
            number,
            title: &step.title,
        };
        sections.push(Section::new(heading, blocks));
    }
    sections.push(Section::new(
        Heading::Results,
        vec![Block::Results(results)],
    ));
    Page {
        title: scene.title.as_deref(),
        untitled: "Worked solution",
        sections,
        figure_file: None,
    }
}

/// Whether every relation of `step` gives one of the scene's unknowns (the step that solves
/// for them) and is a result as Results shows it, `name = form`. A step that derives a
/// quantity (`T = ½{ω}ᵀ[I]{ω}`) is no such step: its title says what it applies.
fn only_solves_for_results(scene: &Scene, step: &Step, results: &[Result]) -> bool {
    let solved_result = |relation: &Relation| {
        let Some(unknown) = relation.lhs.as_symbol() else {
            return false;
        };
        scene.unknowns.iter().any(|(s, _)| *s == unknown)
            && results.iter().any(|r| {
                matches!(&r.body, Body::Line(l)
                    if matches!(&l.form, Some(Form::Expr(form)) if **form == relation.rhs))
                    && unknown.name() == r.name.text
            })
    };
    step.table.is_none() && !step.relations.is_empty() && step.relations.iter().all(solved_result)
}

/// The quantities the scene asks for, each once (a request with several solutions is one).
fn requested(analysis: &Analysis) -> Vec<Name> {
    let mut names: Vec<Name> = Vec::new();
    for (request, _) in &analysis.results {
        let text = shown_name(request);
        if names.iter().all(|n| n.text != text) {
            names.push(Name {
                text: text.to_string(),
                latex: quantity_latex(request.quantity),
            });
        }
    }
    names
}
