//! The derivations `kinetics derive` prints, in every format of a worked solution: a section
//! per derivation headed by its title, the convention it is derived in (reference point and
//! axes), then its steps (each a sub-heading and its relations) or only its result.
//!
//! Text and Markdown headings are `#`/`##` lines, LaTeX headings `\section*`/`\subsection*`
//! (never `%` comments), so a page of derivations reads like the chapter.

use super::json::relations_json;
use super::parts_table;
use super::render::{latex_relations, relation, LATEX_PREAMBLE};
use super::Format;
use crate::algebra::Axis;
use crate::mechanics::catalogue::convention;
use crate::mechanics::{Derivation, Step};
use crate::print::{markup, Notation};

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
    let Shown {
        format,
        standalone,
        axis,
        ..
    } = shown;
    match format {
        Format::Json => json(derivations, axis).to_string(),
        Format::Html => html(derivations, shown),
        _ => {
            let mut out = String::new();
            if standalone && format == Format::Latex {
                out.push_str(LATEX_PREAMBLE);
            }
            for d in derivations {
                section(&mut out, d, shown);
            }
            if standalone && format == Format::Latex {
                out.push_str("\\end{document}\n");
            }
            out.trim_end().to_string()
        }
    }
}

/// The steps shown: all of them, or the last (the result).
fn steps(d: &Derivation, all_steps: bool) -> &[Step] {
    if all_steps {
        &d.steps
    } else {
        &d.steps[d.steps.len().saturating_sub(1)..]
    }
}

fn section(out: &mut String, d: &Derivation, shown: Shown) {
    let format = shown.format;
    heading(out, format, 1, &d.title);
    if let Some(c) = convention(&d.name, shown.axis) {
        paragraph(out, format, &c);
    }
    for step in steps(d, shown.all_steps) {
        if shown.all_steps {
            heading(out, format, 2, &step.title);
        }
        relations(out, format, step);
    }
    out.push('\n');
}

/// A heading of `level` 1 (a derivation) or 2 (a step), its mathematics typeset.
fn heading(out: &mut String, format: Format, level: usize, title: &str) {
    match format {
        Format::Latex => {
            let command = if level == 1 { "section" } else { "subsection" };
            out.push_str(&format!("\\{command}*{{{}}}\n", markup::latex(title)));
        }
        Format::Markdown => {
            out.push_str(&format!(
                "{} {}\n\n",
                "#".repeat(level + 1),
                markup::markdown(title)
            ));
        }
        _ => out.push_str(&format!("{} {}\n", "#".repeat(level), markup::text(title))),
    }
}

fn paragraph(out: &mut String, format: Format, words: &str) {
    match format {
        Format::Latex => out.push_str(&format!("{}\n", markup::latex(words))),
        Format::Markdown => out.push_str(&format!("{}\n\n", markup::markdown(words))),
        _ => out.push_str(&format!("{}\n", markup::text(words))),
    }
}

fn relations(out: &mut String, format: Format, step: &Step) {
    match format {
        Format::Latex => {
            if let Some(table) = &step.table {
                out.push_str(&parts_table::latex(table));
            }
            out.push_str(&latex_relations(&step.relations));
        }
        Format::Markdown => {
            if let Some(table) = &step.table {
                out.push_str(&parts_table::markdown(table));
            }
            out.push_str(&format!("$$\n{}$$\n\n", latex_relations(&step.relations)));
        }
        _ => {
            if let Some(table) = &step.table {
                out.push_str(&parts_table::text(table));
            }
            for r in &step.relations {
                let (l, rhs) = relation(r, Notation::Text);
                out.push_str(&format!("{l} = {rhs}\n"));
            }
        }
    }
}

/// One HTML page: a section per derivation, its convention, its steps (headings `<h3>`).
fn html(derivations: &[Derivation], shown: Shown) -> String {
    let mut out = super::html::page_start("Derivations");
    for d in derivations {
        out.push_str(&format!("<section>\n<h2>{}</h2>\n", markup::html(&d.title)));
        if let Some(c) = convention(&d.name, shown.axis) {
            out.push_str(&format!("<p>{}</p>\n", markup::html(&c)));
        }
        for step in steps(d, shown.all_steps) {
            if shown.all_steps {
                out.push_str(&format!("<h3>{}</h3>\n", markup::html(&step.title)));
            }
            out.push_str(&super::html::step_body(step));
        }
        out.push_str("</section>\n");
    }
    out.push_str(super::html::PAGE_END);
    out
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
