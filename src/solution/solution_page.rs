//! A scene's worked solution as a [`Page`]: what the problem says (its `statement` lines),
//! the givens, the quantities asked for, the answers as numbers when every given has a value,
//! each step of the plan (its table of parts, its relations), then the results.

use super::page::{rows, Block, Heading, Name, Page, Section};
use super::render::{quantity_latex, shown_name, Result};
use crate::scene::{Analysis, Scene};
use std::borrow::Cow;

/// The page of `scene`'s solution (`results` in the order of `analysis.results`).
pub(super) fn solution_page<'a>(
    scene: &'a Scene,
    analysis: &'a Analysis,
    results: &'a [Result<'a>],
) -> Page<'a> {
    let mut sections = Vec::new();
    if !scene.statement.is_empty() {
        let words = Cow::Owned(scene.statement.join(" "));
        sections.push(Section::new(Heading::Statement, vec![Block::Words(words)]));
    }
    sections.push(Section::new(
        Heading::Given,
        vec![Block::Givens(&scene.givens)],
    ));
    sections.push(Section::new(
        Heading::Find,
        vec![Block::Find(requested(analysis))],
    ));
    let numbers = results.iter().any(|r| r.value.is_some() || r.is_words());
    if numbers && scene.givens.iter().all(|g| g.value.is_some()) {
        sections.push(Section::new(
            Heading::Answers,
            vec![Block::Answers(results)],
        ));
    }
    for (k, step) in analysis.plan.iter().enumerate() {
        let mut blocks = Vec::new();
        if let Some(table) = &step.table {
            blocks.push(Block::Table(table));
        }
        blocks.push(Block::Relations(rows(&step.relations)));
        let heading = Heading::Step {
            number: k + 1,
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
    }
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
