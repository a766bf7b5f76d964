//! The derivations `kinetics derive` prints, in every format of a worked solution: a section
//! per derivation headed by its title, the convention it is derived in (reference point and
//! axes), then its steps (each a sub-heading and its relations) or only its result.
//!
//! Text and Markdown headings are `#`/`##` lines, LaTeX headings `\section*`/`\subsection*`
//! (never `%` comments), so a page of derivations reads like the chapter.

use super::json::relations_json;
use super::page::{rows, Block, Heading, Page, Section};
use super::parts_table;
use super::Format;
use crate::algebra::Axis;
use crate::mechanics::catalogue::convention;
use crate::mechanics::{Derivation, Step};
use crate::print::markup;
use std::borrow::Cow;

/// How `kinetics derive` shows its derivations.
#[derive(Debug, Clone, Copy)]
pub struct Shown {
    pub format: Format,
    /// Every step, or each derivation's result alone.
    pub all_steps: bool,
    /// LaTeX as a whole document.
    pub standalone: bool,
    /// The axis of rotation the fixed-axis derivations were derived about.
    pub axis: Axis,
}

/// Renders `derivations` as `shown` says.
pub fn render_derivations(derivations: &[Derivation], shown: Shown) -> String {
    let conventions: Vec<Option<String>> = derivations
        .iter()
        .map(|d| convention(&d.name, shown.axis))
        .collect();
    let page = page(derivations, &conventions, shown.all_steps);
    match shown.format {
        Format::Json => json(derivations, shown.axis).to_string(),
        Format::Html => super::html::page(&page),
        Format::Latex => super::latex::page(&page, shown.standalone)
            .trim_end()
            .to_string(),
        Format::Markdown => super::markdown::page(&page).trim_end().to_string(),
        Format::Text => super::text::page(&page).trim_end().to_string(),
    }
}

/// The page: a section per derivation, its convention, then its steps as subsections (or
/// its result's relations alone).
fn page<'a>(
    derivations: &'a [Derivation],
    conventions: &'a [Option<String>],
    all_steps: bool,
) -> Page<'a> {
    let sections = derivations
        .iter()
        .zip(conventions)
        .map(|(d, convention)| {
            let mut section = Section::new(Heading::Derivation(&d.title), Vec::new());
            if let Some(c) = convention {
                section.blocks.push(Block::Words(Cow::Borrowed(c)));
            }
            if all_steps {
                section.subsections = d
                    .steps
                    .iter()
                    .map(|step| Section::new(Heading::DerivationStep(&step.title), blocks(step)))
                    .collect();
            } else if let Some(last) = d.steps.last() {
                section.blocks.extend(blocks(last));
            }
            section
        })
        .collect();
    Page {
        title: None,
        untitled: "Derivations",
        sections,
    }
}

/// A step's table of parts, if any, and its relations.
fn blocks(step: &Step) -> Vec<Block<'_>> {
    let mut blocks = Vec::new();
    if let Some(table) = &step.table {
        blocks.push(Block::Table(table));
    }
    blocks.push(Block::Relations(rows(&step.relations)));
    blocks
}

fn json(derivations: &[Derivation], axis: Axis) -> serde_json::Value {
    serde_json::Value::Array(
        derivations
            .iter()
            .map(|d| {
                serde_json::json!({
                    "name": d.name,
                    "title": markup::text(&d.title),
                    "title_latex": markup::latex(&d.title),
                    "convention": convention(&d.name, axis).map(|c| markup::text(&c)),
                    "result": relations_json(d.result()),
                    "steps": d.steps.iter().map(|s| serde_json::json!({
                        "title": markup::text(&s.title),
                        "title_latex": markup::latex(&s.title),
                        "table": s.table.as_ref().map(parts_table::json),
                        "relations": relations_json(&s.relations),
                    })).collect::<Vec<_>>(),
                })
            })
            .collect(),
    )
}
