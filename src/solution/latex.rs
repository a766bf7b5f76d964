//! A [`Page`] in LaTeX (and the LaTeX blocks the Markdown page shows between `$$`): the
//! title a `\section*`, the givens and requests a paragraph each, each step a `\paragraph`,
//! its relations one `align*` block with every right-hand side broken into lines that fit
//! the page, the results another with their values and units; a derivation a `\section*`,
//! its steps `\subsection*`. The answers section (numbers first) is text only: here each
//! value stands beside its result.

use super::engineer::StepValues;
use super::page::{rows_room, Block, Heading, Name, Page, Row, Section};
use super::parts_table;
use super::render::results_room;
use super::result::{Form, Line, Result, Show};
use super::unit_latex::quantity;
use crate::algebra::Expr;
use crate::print::{self, markup, width::RELATION_EM, Notation};
use crate::scene::model::Given;

/// The preamble of a standalone LaTeX document: article class on A4 at 11 pt with 25 mm
/// margins, amsmath and amssymb, TikZ for the figure; a block of relations may break across pages
/// (`\\allowdisplaybreaks`), so a page is not left half empty before a long one; `\\sloppy`,
/// so a paragraph of long givens or a long title breaks between words rather than run past
/// the margin.
pub(super) const LATEX_PREAMBLE: &str = "\\documentclass[a4paper,11pt]{article}\n\\usepackage[margin=25mm]{geometry}\n\\usepackage{amsmath}\n\\usepackage{amssymb}\n\\usepackage{tikz}\n\\allowdisplaybreaks\n\\sloppy\n\\begin{document}\n";

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
        Heading::Statement => {
            if let [Block::Words(words), Block::Figure(drawn)] = &section.blocks[..] {
                if let Some(side_by_side) = beside(words, drawn) {
                    out.push_str(&side_by_side);
                    return;
                }
            }
        }
        Heading::Given => out.push_str("\\paragraph{Given}\n"),
        Heading::Find => out.push_str("\\paragraph{Find}\n"),
        Heading::Step { number, title } => out.push_str(&format!(
            "\\paragraph{{Step {number}}} {}\n",
            markup::latex(title)
        )),
        Heading::Results => out.push_str("\\paragraph{Results}\n"),
        // The heading on its own line: each step title is a paragraph of its own.
        Heading::Intermediate => out.push_str("\\paragraph{Intermediate values}\\mbox{}\n\n"),
        Heading::Derivation { title, .. } => {
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
            Block::Results(results) => self::results(results, false),
            Block::Answers(results) => self::results(results, true),
            Block::Values(steps) => values(steps),
            Block::Figure(drawn) => figure(drawn),
        });
    }
    for sub in &section.subsections {
        self::section(out, sub);
    }
}

/// The figure centred, its TikZ picture no wider than the text.
pub(super) fn figure(drawn: &crate::figure::Figure) -> String {
    format!(
        "\\begin{{center}}\n{}\n\\end{{center}}\n\n",
        crate::figure::tikz::tikz(drawn)
    )
}

/// The page's text width (A4 less two 25 mm margins), the body's font size and line
/// height, the gap between the statement and its figure, and the narrowest column the
/// statement is set in.
const TEXT_WIDTH_PT: f64 = 455.24;
const FONT_PT: f64 = 11.0;
const LINE_PT: f64 = 13.6;
const GUTTER_PT: f64 = 12.0;
const NARROWEST_PT: f64 = 150.0;
/// What a paragraph loses to its line breaks, and the space `center` puts about the figure.
const RAGGED: f64 = 1.15;
const CENTER_SKIPS_PT: f64 = 20.0;

/// The statement in a column beside its figure, as a textbook sets a problem, when that
/// takes less height than the statement above the figure (a narrow figure, a short
/// statement): the statement's lines estimated from its width in em,
///
/// ```text
/// beside  = max(⌈w·f·r / (T − W − g)⌉ · ℓ, H)      stacked = ⌈w·f·r / T⌉ · ℓ + H + s
/// ```
///
/// (`w` the words' width in em, `f` the font size, `r` the ragged loss, `T` the text width,
/// `W` × `H` the figure, `g` the gutter, `ℓ` the line height, `s` the centring's skips).
fn beside(words: &str, drawn: &crate::figure::Figure) -> Option<String> {
    let (width, height) = (
        (drawn.max.x - drawn.min.x) * 0.75,
        (drawn.max.y - drawn.min.y) * 0.75,
    );
    let column = TEXT_WIDTH_PT - width - GUTTER_PT;
    let text_pt = markup::svg(words).1.width * FONT_PT * RAGGED;
    let lines = |room: f64| (text_pt / room).ceil() * LINE_PT;
    if column < NARROWEST_PT
        || lines(column).max(height) >= lines(TEXT_WIDTH_PT) + height + CENTER_SKIPS_PT
    {
        return None;
    }
    Some(format!(
        "\\noindent\\begin{{minipage}}[t]{{\\dimexpr\\linewidth-{width:.1}pt-{GUTTER_PT}pt\\relax}}\\vspace{{0pt}}\\raggedright\n{}\n\\end{{minipage}}\\hfill\\begin{{minipage}}[t]{{{width:.1}pt}}\\vspace{{0pt}}\n{}\n\\end{{minipage}}\n\n",
        markup::latex(words),
        crate::figure::tikz::tikz(drawn)
    ))
}

/// Items of inline maths as a sentence: `$a$, $b$.` and a blank line.
fn inline_list(items: impl Iterator<Item = String>) -> String {
    format!("{}.\n\n", items.collect::<Vec<_>>().join(", "))
}

/// A given as inline maths: `$m = 0.3\,\mathrm{kg}$`, `$\beta = 60^\circ$`, its
/// definition by other givens (`$\dot\psi = v/r_w$`), or its name alone when it is symbolic.
pub(super) fn given(g: &Given) -> String {
    let name = print::latex(&Expr::sym(g.symbol));
    match (&g.definition, &g.written) {
        (Some(d), _) => format!("${name} = {}$", print::latex(&d.expr)),
        (None, Some(w)) => format!("${name} = {}$", quantity(&w.number, &w.unit)),
        (None, None) => format!("${name}$"),
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

/// Results as one `align*` block, a row per line of each ([`line`]); `values_only` (the
/// answers), a line that has a value shows it alone.
pub(super) fn results(results: &[Result], values_only: bool) -> String {
    let room = results_room(results);
    let rows: Vec<String> = results
        .iter()
        .flat_map(Result::lines)
        .map(|l| line(l, room, values_only))
        .collect();
    align(&rows)
}

/// Each step's title, then its values ([`step_values`]).
fn values(steps: &[StepValues]) -> String {
    steps
        .iter()
        .map(|step| {
            format!(
                "\\noindent {}\n{}",
                markup::latex(&step.title),
                step_values(step)
            )
        })
        .collect()
}

/// A step's values as one `align*` block, `I_{xy} &= -0.01\,\mathrm{kg\cdot m^2}` a row.
pub(super) fn step_values(step: &StepValues) -> String {
    let rows: Vec<String> = step
        .values
        .iter()
        .map(|n| {
            let name = print::render(&n.name, Notation::Latex, n.axis);
            aligned_row(&name, &[n.shown_value().render(Notation::Latex)])
        })
        .collect();
    align(&rows)
}

/// A result's line: its form broken into lines that fit the page (`room`: where the first
/// starts, the width), its value and unit after the last line, or on a row of their own
/// when the form took several lines or the value does not fit after it; a matrix too wide
/// for the page by its value alone; words without a name, on their own.
fn line(l: &Line, (first_em, width_em): (f64, f64), values_only: bool) -> String {
    // Braced: a `[` after the row break `\\` would be read as its argument.
    let name = match l.name.latex.starts_with('[') {
        true => format!("{{{}}}", l.name.latex),
        false => l.name.latex.clone(),
    };
    let value = l
        .shown_value()
        .map(|v| (v.render(Notation::Latex), v.latex_em()));
    let Some(form) = &l.form else {
        return aligned_row(&name, &[value.map(|(v, _)| v).unwrap_or_default()]);
    };
    if name.is_empty() {
        return format!("& {}", form.render(Notation::Latex));
    }
    let form_em = form.width_em();
    let fits = first_em + form_em <= width_em;
    let show = match l.show {
        Show::Both if values_only => Show::Value,
        show => show,
    };
    match (value, show) {
        (Some((value, _)), Show::Value) => aligned_row(&name, &[value]),
        (Some((value, _)), Show::Both) if matches!(form, Form::Matrix(_)) && !fits => {
            aligned_row(&name, &[value])
        }
        (Some((value, value_em)), Show::Both) => {
            let mut lines = form.lines(Notation::Latex, first_em, width_em);
            let tail = format!("= {value}");
            let on_its_row = matches!(form, Form::Matrix(_))
                || lines.len() > 1
                || first_em + form_em + RELATION_EM + value_em > width_em;
            if on_its_row {
                return format!("{} \\\\\n&{tail}", aligned_row(&name, &lines));
            }
            if let Some(last) = lines.last_mut() {
                last.push(' ');
                last.push_str(&tail);
            }
            aligned_row(&name, &lines)
        }
        (_, _) => aligned_row(&name, &form.lines(Notation::Latex, first_em, width_em)),
    }
}
