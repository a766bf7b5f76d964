//! The derivations `kinetics derive` prints, in every format of a worked solution: a section
//! per derivation headed by its title, the convention it is derived in (reference point and
//! axes), then its steps (each a sub-heading and its relations) or only its result.
//!
//! Text and Markdown headings are `#`/`##` lines, LaTeX headings `\section*`/`\subsection*`
//! (never `%` comments), so a page of derivations reads like the chapter.

use super::page::{step_rows, Block, Heading, Page, Section};
use super::Format;
use crate::algebra::Axis;
use crate::mechanics::catalogue::convention;
use crate::mechanics::{Derivation, Step};
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
    // JSON holds every step and the result apart.
    let all_steps = shown.all_steps || matches!(shown.format, Format::Json);
    let page = page(derivations, &conventions, all_steps);
    match shown.format {
        Format::Json => super::json::derivations(&page).to_string(),
        Format::Html => super::html::page(&page),
        Format::HtmlFragment => super::html::fragment(&page),
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
            let heading = Heading::Derivation {
                name: &d.name,
                title: &d.title,
            };
            let mut section = Section::new(heading, Vec::new());
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
        figure_file: None,
    }
}

/// A step's table of parts, if any, and its relations.
fn blocks(step: &Step) -> Vec<Block<'_>> {
    let mut blocks = Vec::new();
    if let Some(table) = &step.table {
        blocks.push(Block::Table(table));
    }
    blocks.push(Block::Relations(step_rows(step)));
    blocks
}
