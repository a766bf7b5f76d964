//! A [`Page`] as plain Unicode text: the title, then each section under its heading (a blank
//! line between sections), items indented by two spaces; a derivation's heading `#`, its
//! steps' `##`. Paragraphs are wrapped at [`WRAP_COLUMNS`].

use super::engineer::StepValues;
use super::page::{Block, Heading, Page, Section};
use super::parts_table;
use super::render::given_line;
use super::result::{Body, Line, Result, Show};
use crate::print::{self, markup, Notation};

/// The column a paragraph is wrapped at.
pub const WRAP_COLUMNS: usize = 88;

/// The page as text.
pub(super) fn page(page: &Page) -> String {
    let mut parts = Vec::new();
    if let Some(title) = page.title {
        parts.push(format!("{}\n", markup::text(title)));
    }
    // A section with nothing to say in text (the statement section of a figure alone).
    parts.extend(page.sections.iter().map(section).filter(|s| !s.is_empty()));
    parts.join("\n")
}

fn section(section: &Section) -> String {
    let mut out = match &section.heading {
        Heading::Statement => String::new(),
        Heading::Given => "Given\n".into(),
        Heading::Find => "Find\n".into(),
        Heading::Answers => "Answers\n".into(),
        Heading::Step { number, title } => format!("Step {number}: {}\n", markup::text(title)),
        Heading::Results => "Results\n".into(),
        Heading::Intermediate => "Intermediate values\n".into(),
        Heading::Derivation { title, .. } => format!("# {}\n", markup::text(title)),
        Heading::DerivationStep(title) => format!("## {}\n", markup::text(title)),
    };
    for block in &section.blocks {
        out.push_str(&match block {
            Block::Words(words) => wrapped(&markup::text(words)),
            Block::Givens(givens) => givens
                .iter()
                .map(|g| format!("  {}\n", given_line(g)))
                .collect(),
            Block::Find(names) => {
                let names: Vec<&str> = names.iter().map(|n| n.text.as_str()).collect();
                format!("  {}\n", names.join(", "))
            }
            Block::Table(table) => parts_table::text(table),
            Block::Relations(rows) => rows
                .iter()
                .map(|row| format!("  {}\n", row.one_line(Notation::Text)))
                .collect(),
            Block::Results(results) => results.iter().map(|r| result(r, false)).collect(),
            Block::Answers(results) => answers(results),
            Block::Values(steps) => values(steps),
            // Text has no figure: `kinetics figure` draws it.
            Block::Figure(_) => String::new(),
        });
    }
    for sub in &section.subsections {
        out.push('\n');
        out.push_str(&self::section(sub));
    }
    out
}

/// A result's lines, `  name = form = value unit` each, a frame's under its name;
/// `values_only` (the answers), a line that has a value shows it alone.
fn result(r: &Result, values_only: bool) -> String {
    let (mut out, indent) = match r.body {
        Body::Line(_) => (String::new(), "  "),
        Body::Frame { .. } => (format!("  {}:\n", r.name.text), "    "),
    };
    for l in r.lines() {
        out.push_str(&format!("{indent}{}\n", line(l, values_only)));
    }
    out
}

fn line(l: &Line, values_only: bool) -> String {
    let form = l.form.as_ref().map(|f| f.render(Notation::Text));
    let value = l.shown_value().map(|v| v.render(Notation::Text));
    let name = &l.name.text;
    let show = match l.show {
        Show::Both if values_only => Show::Value,
        show => show,
    };
    match (form, value) {
        (Some(form), _) if name.is_empty() => form,
        (Some(form), Some(value)) if show == Show::Both => format!("{name} = {form} = {value}"),
        (Some(_), Some(value)) if show == Show::Value => format!("{name} = {value}"),
        (Some(form), _) => format!("{name} = {form}"),
        // Known only as a number.
        (None, value) => format!("{name} = {}", value.unwrap_or_default()),
    }
}

/// The results as numbers with units, `  T_BC = 1857 N` a line; then those without one.
fn answers(results: &[Result]) -> String {
    let (valued, symbolic): (Vec<&Result>, Vec<&Result>) =
        results.iter().partition(|r| r.has_value());
    let valued = valued.into_iter().map(|r| result(r, true));
    let symbolic = symbolic.into_iter().map(|r| {
        format!(
            "  {} has no value: a given it needs is symbolic\n",
            r.name.text
        )
    });
    valued.chain(symbolic).collect()
}

/// Each step's title, then its values a line each: `    I_xy = -0.01 kg·m²`.
fn values(steps: &[StepValues]) -> String {
    let mut out = String::new();
    for step in steps {
        out.push_str(&format!("  {}\n", markup::text(&step.title)));
        for n in &step.values {
            let name = print::render(&n.name, Notation::Text, n.axis);
            out.push_str(&format!(
                "    {name} = {}\n",
                n.shown_value().render(Notation::Text)
            ));
        }
    }
    out
}

/// `words` broken between words into lines of at most [`WRAP_COLUMNS`] characters (a
/// longer word alone on its line).
fn wrapped(words: &str) -> String {
    let mut out = String::new();
    let mut line = 0;
    for word in words.split_whitespace() {
        let width = word.chars().count();
        if line > 0 && line + 1 + width > WRAP_COLUMNS {
            out.push('\n');
            line = 0;
        } else if line > 0 {
            out.push(' ');
            line += 1;
        }
        out.push_str(word);
        line += width;
    }
    out.push('\n');
    out
}
