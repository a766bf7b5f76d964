//! A [`Page`] in LaTeX (and the LaTeX blocks the Markdown page shows between `$$`): the
//! title a `\section*`, the givens and requests a paragraph each, each step a `\paragraph`,
//! its relations one `align*` block with every right-hand side broken into lines that fit
//! the page, the results another with their values and units; a derivation a `\section*`,
//! its steps `\subsection*`. The answers section (numbers first) is text only: here each
//! value stands beside its result.

use super::inertia_results;
use super::numbers::format_value;
use super::page::{rows_room, Block, Heading, Name, Page, Row, Section};
use super::parts_table;
use super::render::{form_em, form_lines, results_room, Result};
use super::unit_latex::quantity;
use super::vector_value;
use crate::algebra::Expr;
use crate::print::{self, markup, width::RELATION_EM, Notation};
use crate::scene::model::Given;

/// The preamble of a standalone LaTeX document: article class on A4 at 11 pt with 25 mm
/// margins, amsmath and amssymb; a block of relations may break across pages
/// (`\\allowdisplaybreaks`), so a page is not left half empty before a long one; `\\sloppy`,
/// so a paragraph of long givens or a long title breaks between words rather than run past
/// the margin.
pub(super) const LATEX_PREAMBLE: &str = "\\documentclass[a4paper,11pt]{article}\n\\usepackage[margin=25mm]{geometry}\n\\usepackage{amsmath}\n\\usepackage{amssymb}\n\\allowdisplaybreaks\n\\sloppy\n\\begin{document}\n";

/// The page in LaTeX; `standalone`, a whole document.
pub(super) fn page(page: &Page, standalone: bool) -> String {
    let mut out = String::new();
    if standalone {
        out.push_str(LATEX_PREAMBLE);
    }
    if let Some(title) = page.title {
        out.push_str(&format!("\\section*{{{}}}\n", markup::latex(title)));
    }
    for s in &page.sections {
        section(&mut out, s);
    }
    if standalone {
        out.push_str("\\end{document}\n");
    }
    out
}

fn section(out: &mut String, section: &Section) {
    match &section.heading {
        Heading::Answers => return,
        Heading::Statement => {}
        Heading::Given => out.push_str("\\paragraph{Given}\n"),
        Heading::Find => out.push_str("\\paragraph{Find}\n"),
        Heading::Step { number, title } => out.push_str(&format!(
            "\\paragraph{{Step {number}}} {}\n",
            markup::latex(title)
        )),
        Heading::Results => out.push_str("\\paragraph{Results}\n"),
        Heading::Derivation(title) => {
            out.push_str(&format!("\\section*{{{}}}\n", markup::latex(title)));
        }
        Heading::DerivationStep(title) => {
            out.push_str(&format!("\\subsection*{{{}}}\n", markup::latex(title)));
        }
    }
    for block in &section.blocks {
        out.push_str(&match block {
            Block::Words(words) => format!("{}\n\n", markup::latex(words)),
            Block::Givens(givens) => inline_list(givens.iter().map(given)),
            Block::Find(names) => inline_list(names.iter().map(name)),
            Block::Table(table) => parts_table::latex(table),
            Block::Relations(rows) => relations(rows),
            Block::Results(results) => self::results(results),
            Block::Answers(_) => String::new(),
        });
    }
    for sub in &section.subsections {
        self::section(out, sub);
    }
}

/// Items of inline maths as a sentence: `$a$, $b$.` and a blank line.
fn inline_list(items: impl Iterator<Item = String>) -> String {
    format!("{}.\n\n", items.collect::<Vec<_>>().join(", "))
}

/// A given as inline maths: `$m = 0.3\,\mathrm{kg}$`, `$\beta = 60^\circ$`, or its name
/// alone when it is symbolic.
pub(super) fn given(g: &Given) -> String {
    let name = print::latex(&Expr::sym(g.symbol));
    match &g.written {
        Some(w) => {
            let (number, unit) = w.split_once(' ').unwrap_or((w.as_str(), ""));
            format!("${name} = {}$", quantity(number, unit))
        }
        None => format!("${name}$"),
    }
}

/// A quantity asked for, as inline maths.
pub(super) fn name(n: &Name) -> String {
    format!("${}$", n.latex)
}

/// Rows of relations as one `align*` block, each right-hand side broken into lines that fit
/// the page; nothing for no rows.
pub(super) fn relations(rows: &[Row]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let (first_em, width_em) = rows_room(rows);
    let rows: Vec<String> = rows
        .iter()
        .map(|row| {
            let lines = row.right_lines(Notation::Latex, first_em, width_em);
            aligned_row(&row.left(Notation::Latex), &lines)
        })
        .collect();
    align(&rows)
}

/// `lhs &= line_1 \\ &\quad line_2 …`: a right-hand side's later lines indented by a quad.
fn aligned_row(lhs: &str, lines: &[String]) -> String {
    format!("{lhs} &= {}", lines.join(" \\\\\n&\\quad "))
}

fn align(rows: &[String]) -> String {
    format!(
        "\\begin{{align*}}\n{}\n\\end{{align*}}\n",
        rows.join(" \\\\\n")
    )
}

/// Results as one `align*` block: each broken into lines that fit the page, its value and
/// unit after the last line, or on a row of their own when the result took several lines or
/// the value does not fit after it.
pub(super) fn results(results: &[Result]) -> String {
    let (first_em, width_em) = results_room(results);
    let rows: Vec<String> = results
        .iter()
        .map(|r| {
            if let Some(rows) = inertia_results::latex(r) {
                return rows.join(" \\\\\n");
            }
            let name = &r.name_latex;
            let value = value(r);
            if let Some((number, _)) = value.as_ref().filter(|_| r.is_number()) {
                return aligned_row(name, std::slice::from_ref(number));
            }
            let value = value.map(|(v, width)| (format!("= {v}"), width + RELATION_EM));
            let mut lines = form_lines(r, Notation::Latex, first_em, width_em);
            if let Some((tail, tail_em)) = value {
                if lines.len() > 1 || first_em + form_em(r) + tail_em > width_em {
                    return format!("{} \\\\\n&{tail}", aligned_row(name, &lines));
                }
                if let Some(line) = lines.first_mut() {
                    line.push(' ');
                    line.push_str(&tail);
                }
            }
            aligned_row(name, &lines)
        })
        .collect();
    align(&rows)
}

/// A result's value and unit in LaTeX (`-135\,\mathrm{m/s^2}`, a vector by its components)
/// and its width in ems.
fn value(r: &Result) -> Option<(String, f64)> {
    let unit = r.unit.as_deref().unwrap_or_default();
    Some(match r.value.as_deref()? {
        [x] => {
            let number = format_value(*x);
            // A value's digits and sign are narrower than 0.55 em; its unit is upright,
            // narrower than a symbol of the same letters.
            let width = 0.55 * number.len() as f64 + print::width::symbol_em(unit);
            (quantity(&number, unit), width)
        }
        components @ [_, _, _] => (
            vector_value::latex(components, unit),
            vector_value::latex_em(components, unit),
        ),
        _ => return None,
    })
}
