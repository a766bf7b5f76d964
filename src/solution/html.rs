//! A worked solution as one self-contained HTML page, a preview without LaTeX: UTF-8, its
//! style inline, no script and nothing fetched. The content and order are the LaTeX
//! output's: the title, the givens, each step (its heading, its table of parts, its
//! relations aligned at `=`), then the results with their values and units. The
//! mathematics is MathML Core from the same layout as the LaTeX (`print::mathml`), which
//! current browsers lay out natively; each step's relations are one
//! `<math display="block">` of a three-column `<mtable>` (left side, `=`, right side), a
//! long right-hand side broken into continuation rows where the LaTeX breaks it
//! (`print::broken`), scrolled sideways only where one term alone is wider than the page.

use super::inertia_results;
use super::mathml_value::{decimal, spaced_unit, value};
use super::numbers::format_value;
use super::render::{form_lines, relations_room, results_room, Result};
use crate::algebra::{Axis, Expr};
use crate::mechanics::derivation::{Relation, Step, Table};
use crate::print::{self, markup, mathml::escaped, Notation};
use crate::scene::model::Given;
use crate::scene::{Analysis, Scene};

/// The page's style: a column of text, headings smaller a level down (derive's steps,
/// `<h3>`, under their derivation's `<h2>`), the maths in a maths font, the left sides of the
/// relations to the right of their column and the right sides to the left (Chromium aligns
/// a table cell of maths by `-webkit-right`, not by `right`; other browsers read the
/// table's `columnalign`).
const STYLE: &str = "\
body { font-family: 'Latin Modern Roman', 'DejaVu Serif', serif; max-width: 48em; \
margin: 2em auto; padding: 0 1em; line-height: 1.45; color: #111; }
math { font-family: 'Latin Modern Math', 'STIX Two Math', 'DejaVu Math TeX Gyre', math; }
math[display=\"block\"] { overflow-x: auto; overflow-y: hidden; padding: 0.25em 0; }
mtd { padding: 0.2em 0; }
mtd.lhs { text-align: right; text-align: -webkit-right; }
mtd.eq { padding: 0.2em 0.3em; }
mtd.rhs { text-align: left; text-align: -webkit-left; }
h2 { font-size: 1.1em; margin: 1.4em 0 0.4em; }
h2 .step { margin-right: 0.5em; }
h3 { font-size: 1em; margin: 1em 0 0.3em; }
table.parts { border-collapse: collapse; margin: 0.5em 0; }
table.parts th, table.parts td { border-bottom: 1px solid #bbb; padding: 0.2em 0.8em; }
";

/// The head of a page titled `title` (plain words), up to its `<body>`; [`PAGE_END`] closes it.
pub(super) fn page_start(title: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>{}</title>\n<style>\n{STYLE}</style>\n</head>\n<body>\n",
        escaped(title)
    )
}

/// The end of a page begun by [`page_start`].
pub(super) const PAGE_END: &str = "</body>\n</html>\n";

/// A step's table of parts (if any) and its relations aligned at `=`.
pub(super) fn step_body(step: &Step) -> String {
    let mut out = String::new();
    if let Some(table) = &step.table {
        out.push_str(&parts(table));
    }
    if step.relations.is_empty() {
        return out;
    }
    let (first_em, width_em) = relations_room(&step.relations);
    let rows = step
        .relations
        .iter()
        .map(|r| relation_rows(r, first_em, width_em));
    out.push_str(&block(rows));
    out
}

/// The page of a worked solution (`results` in the order of `analysis.results`).
pub fn page(scene: &Scene, analysis: &Analysis, results: &[Result]) -> String {
    let title = scene.title.as_deref().unwrap_or("Worked solution");
    let mut out = page_start(&markup::text(title));
    if let Some(t) = &scene.title {
        out.push_str(&format!("<h1>{}</h1>\n", markup::html(t)));
    }
    let givens: Vec<String> = scene.givens.iter().map(given).collect();
    out.push_str(&format!("<h2>Given</h2>\n<p>{}.</p>\n", givens.join(", ")));
    for (k, step) in analysis.plan.iter().enumerate() {
        out.push_str(&format!(
            "<section>\n<h2><span class=\"step\">Step {}</span> {}</h2>\n",
            k + 1,
            markup::html(&step.title)
        ));
        out.push_str(&step_body(step));
        out.push_str("</section>\n");
    }
    out.push_str("<h2>Results</h2>\n");
    let (first_em, width_em) = results_room(results);
    let rows = results.iter().map(|r| result_rows(r, first_em, width_em));
    out.push_str(&block(rows));
    out.push_str(PAGE_END);
    out
}

/// A given as inline maths: `m = 0.3 kg`, or its name alone when it is symbolic.
fn given(g: &Given) -> String {
    let name = print::mathml(&Expr::sym(g.symbol));
    match &g.written {
        Some(w) => {
            let (number, unit) = w.split_once(' ').unwrap_or((w.as_str(), ""));
            format!("<math>{name}<mo>=</mo>{}</math>", value(number, unit))
        }
        None => format!("<math>{name}</math>"),
    }
}

/// Rows of a three-column table aligned at `=`, as one block of maths, its fractions set
/// full size as in LaTeX's `align*` (a table's cells are otherwise in text style).
fn block(rows: impl Iterator<Item = String>) -> String {
    format!(
        "<math display=\"block\"><mtable displaystyle=\"true\" columnalign=\"right center left\">\n{}</mtable></math>\n",
        rows.collect::<String>()
    )
}

/// `lhs = line₁`, then a row per continuation line (indented by a quad, as in the LaTeX).
fn rows(lhs: &str, lines: &[String]) -> String {
    let mut out = String::new();
    for (k, line) in lines.iter().enumerate() {
        if k == 0 {
            out.push_str(&format!(
                "<mtr><mtd class=\"lhs\">{lhs}</mtd><mtd class=\"eq\"><mo>=</mo></mtd>\
                 <mtd class=\"rhs\">{line}</mtd></mtr>\n"
            ));
        } else {
            out.push_str(&format!(
                "<mtr><mtd></mtd><mtd></mtd>\
                 <mtd class=\"rhs\"><mspace width=\"1em\"></mspace>{line}</mtd></mtr>\n"
            ));
        }
    }
    out
}

fn relation_rows(r: &Relation, first_em: f64, width_em: f64) -> String {
    let lhs = print::render(&r.lhs, Notation::MathMl, r.axis);
    let lines = print::broken(&r.rhs, r.axis, Notation::MathMl, first_em, width_em);
    rows(&lhs, &lines)
}

/// A result: its quantity's name, its form (broken as a relation is) and, when every given
/// has a value, `= value unit` after its last line.
fn result_rows(r: &Result, first_em: f64, width_em: f64) -> String {
    if let Some(table) = inertia_results::mathml(r, rows) {
        return table;
    }
    let mut name = String::new();
    print::mathml::latex_name(&mut name, &r.name_latex);
    let mut lines = form_lines(r, Notation::MathMl, first_em, width_em);
    let mut rhs = lines.pop().unwrap_or_default();
    match value_mathml(r) {
        // A form that is a plain number is its value: shown once, with its unit.
        Some(v) if r.is_number() => rhs = v,
        Some(v) => {
            rhs.push_str("<mo>=</mo>");
            rhs.push_str(&v);
        }
        None => {}
    }
    lines.push(rhs);
    rows(&name, &lines)
}

/// A result's value and unit in MathML: `−135 m/s²`, or `(0, 0, 0.024) kg·m²/s`.
fn value_mathml(r: &Result) -> Option<String> {
    let values = r.value.as_ref()?;
    let unit = r.unit.as_deref().unwrap_or("");
    Some(match values.as_slice() {
        [x] => value(&format_value(*x), unit),
        components => {
            let numbers: Vec<String> = components
                .iter()
                .map(|x| decimal(&format_value(*x)))
                .collect();
            // The unit of a vector stands after its parenthesis, as in the LaTeX.
            format!(
                "<mrow><mo>(</mo>{}<mo>)</mo></mrow>{}",
                numbers.join("<mo>,</mo>"),
                spaced_unit(unit)
            )
        }
    })
}

/// A composite body's table of parts: a row per part, a column per quantity.
fn parts(table: &Table) -> String {
    let cell = |e: &Expr| {
        format!(
            "<math>{}</math>",
            print::render(e, Notation::MathMl, Axis::X)
        )
    };
    let header: String = table
        .columns
        .iter()
        .map(|c| format!("<th>{}</th>", cell(c)))
        .collect();
    let rows: String = table
        .rows
        .iter()
        .map(|row| {
            let cells: String = row
                .cells
                .iter()
                .map(|c| format!("<td>{}</td>", cell(c)))
                .collect();
            format!("<tr><th>{}</th>{cells}</tr>\n", escaped(&row.label))
        })
        .collect();
    format!("<table class=\"parts\">\n<tr><th>part</th>{header}</tr>\n{rows}</table>\n")
}
