//! A worked solution as one self-contained HTML page, a preview without LaTeX: UTF-8, its
//! style inline, no script and nothing fetched. The content and order are the LaTeX
//! output's: the title, the givens, each step (its heading, its table of parts, its
//! relations aligned at `=`), then the results with their values and units. The
//! mathematics is MathML Core from the same layout as the LaTeX (`print::mathml`), which
//! current browsers lay out natively; each step's relations are one
//! `<math display="block">` of a three-column `<mtable>` (left side, `=`, right side), a
//! long right-hand side broken into continuation rows where the LaTeX breaks it
//! (`print::broken`), scrolled sideways only where one term alone is wider than the page.

use super::mathml_value::value;
use super::page::{rows_room, Block, Heading, Page, Section};
use super::render::results_room;
use super::result::{Line, Result, Show};
use crate::algebra::{Axis, Expr};
use crate::mechanics::derivation::Table;
use crate::print::{self, markup, mathml::escaped, Notation};
use crate::scene::model::Given;

/// The page's style as rules: a column of text, headings smaller a level down (derive's
/// steps, `<h3>`, under their derivation's `<h2>`), the maths in a maths font, the left
/// sides of the relations to the right of their column and the right sides to the left
/// (Chromium aligns a table cell of maths by `-webkit-right`, not by `right`; other
/// browsers read the table's `columnalign`). The first rule is the page's own, `body`.
const RULES: [(&str, &str); 14] = [
    (
        "body",
        "font-family: 'Latin Modern Roman', 'DejaVu Serif', serif; max-width: 48em; \
      margin: 2em auto; padding: 0 1em; line-height: 1.45; color: #111;",
    ),
    (
        "math",
        "font-family: 'Latin Modern Math', 'STIX Two Math', 'DejaVu Math TeX Gyre', math;",
    ),
    (
        "math[display=\"block\"]",
        "overflow-x: auto; overflow-y: hidden; padding: 0.25em 0;",
    ),
    ("mtd", "padding: 0.2em 0;"),
    ("mtd.lhs", "text-align: right; text-align: -webkit-right;"),
    ("mtd.eq", "padding: 0.2em 0.3em;"),
    ("mtd.rhs", "text-align: left; text-align: -webkit-left;"),
    ("h2", "font-size: 1.1em; margin: 1.4em 0 0.4em;"),
    ("h2 .step", "margin-right: 0.5em;"),
    ("h3", "font-size: 1em; margin: 1em 0 0.3em;"),
    ("figure", "margin: 1em 0;"),
    ("figure svg", "max-width: 100%; height: auto;"),
    ("table.parts", "border-collapse: collapse; margin: 0.5em 0;"),
    (
        "table.parts th, table.parts td",
        "border-bottom: 1px solid #bbb; padding: 0.2em 0.8em;",
    ),
];

/// The style of a page, or (`scope`) of a fragment within the element of that class: each
/// rule's selectors prefixed by it, the page's own rule the element's.
fn style(scope: Option<&str>) -> String {
    let scoped = |selectors: &str| match scope {
        None => selectors.to_string(),
        Some(class) if selectors == "body" => format!(".{class}"),
        Some(class) => selectors
            .split(", ")
            .map(|s| format!(".{class} {s}"))
            .collect::<Vec<_>>()
            .join(", "),
    };
    RULES
        .iter()
        .map(|(selectors, declarations)| format!("{} {{ {declarations} }}\n", scoped(selectors)))
        .collect()
}

/// The head of a page titled `title` (plain words), up to its `<body>`; [`PAGE_END`] closes it.
fn page_start(title: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>{}</title>\n<style>\n{}</style>\n</head>\n<body>\n",
        escaped(title),
        style(None)
    )
}

/// The end of a page begun by [`page_start`].
const PAGE_END: &str = "</body>\n</html>\n";

/// The page as one HTML document.
pub(super) fn page(page: &Page) -> String {
    let title = page.title.map_or(page.untitled.to_string(), markup::text);
    let mut out = page_start(&title);
    content(&mut out, page);
    out.push_str(PAGE_END);
    out
}

/// The class of a fragment's element, which its style is scoped to.
const FRAGMENT_CLASS: &str = "kinetics-page";

/// The page's content as a fragment of another page (a notebook's cell): one `<div>` with
/// its style scoped to it, so nothing around it changes.
pub(super) fn fragment(page: &Page) -> String {
    let mut out = format!(
        "<div class=\"{FRAGMENT_CLASS}\">\n<style>\n{}</style>\n",
        style(Some(FRAGMENT_CLASS))
    );
    content(&mut out, page);
    out.push_str("</div>\n");
    out
}

/// The title and the sections.
fn content(out: &mut String, page: &Page) {
    if let Some(t) = page.title {
        out.push_str(&format!("<h1>{}</h1>\n", markup::html(t)));
    }
    for s in &page.sections {
        section(out, s);
    }
}

/// One line of the results as a fragment of a page: its block of maths, `name = form =
/// value unit`, with the page's style scoped to it.
pub(super) fn result_line(l: &Line) -> String {
    let room = print::aligned_room(print::width::symbol_em(&l.name.latex));
    format!(
        "<div class=\"{FRAGMENT_CLASS}\">\n<style>\n{}</style>\n{}</div>\n",
        style(Some(FRAGMENT_CLASS)),
        block_of_rows(std::iter::once(result_rows(l, room.0, room.1, false)))
    )
}

/// A section; a step's and a derivation's in a `<section>` of their own.
fn section(out: &mut String, section: &Section) {
    let enclosed = matches!(
        section.heading,
        Heading::Step { .. } | Heading::Derivation { .. }
    );
    if enclosed {
        out.push_str("<section>\n");
    }
    match &section.heading {
        Heading::Answers => return,
        Heading::Statement => {}
        Heading::Given => out.push_str("<h2>Given</h2>\n"),
        Heading::Find => out.push_str("<h2>Find</h2>\n"),
        Heading::Step { number, title } => out.push_str(&format!(
            "<h2><span class=\"step\">Step {number}</span> {}</h2>\n",
            markup::html(title)
        )),
        Heading::Results => out.push_str("<h2>Results</h2>\n"),
        Heading::Intermediate => out.push_str("<h2>Intermediate values</h2>\n"),
        Heading::Derivation { title, .. } => {
            out.push_str(&format!("<h2>{}</h2>\n", markup::html(title)))
        }
        Heading::DerivationStep(title) => {
            out.push_str(&format!("<h3>{}</h3>\n", markup::html(title)));
        }
    }
    for b in &section.blocks {
        out.push_str(&block(b));
    }
    for sub in &section.subsections {
        self::section(out, sub);
    }
    if enclosed {
        out.push_str("</section>\n");
    }
}

fn block(block: &Block) -> String {
    match block {
        Block::Words(words) => format!("<p>{}</p>\n", markup::html(words)),
        Block::Givens(givens) => inline_list(givens.iter().map(given)),
        Block::Find(names) => inline_list(names.iter().map(|n| {
            let mut name = String::new();
            print::mathml::latex_name(&mut name, &n.latex);
            format!("<math>{name}</math>")
        })),
        Block::Table(table) => parts(table),
        Block::Relations(rows) if rows.is_empty() => String::new(),
        Block::Relations(rows) => {
            let (first_em, width_em) = rows_room(rows);
            self::block_of_rows(rows.iter().map(|row| {
                let lines = row.right_lines(Notation::MathMl, first_em, width_em);
                self::rows(&row.left(Notation::MathMl), &lines)
            }))
        }
        Block::Figure(drawn) => {
            format!(
                "<figure>\n{}\n</figure>\n",
                crate::figure::svg::inline(drawn)
            )
        }
        Block::Results(results) => self::results(results, false),
        Block::Answers(results) => self::results(results, true),
        Block::Values(steps) => steps
            .iter()
            .map(|step| {
                let rows = step.values.iter().map(|n| {
                    let name = print::render(&n.name, Notation::MathMl, n.axis);
                    self::rows(&name, &[n.shown_value().render(Notation::MathMl)])
                });
                format!(
                    "<h3>{}</h3>\n{}",
                    markup::html(&step.title),
                    block_of_rows(rows)
                )
            })
            .collect(),
    }
}

/// Items of inline maths as a sentence in a paragraph.
fn inline_list(items: impl Iterator<Item = String>) -> String {
    format!("<p>{}.</p>\n", items.collect::<Vec<_>>().join(", "))
}

/// A given as inline maths: `m = 0.3 kg`, its definition by other givens, or its name
/// alone when it is symbolic.
fn given(g: &Given) -> String {
    let name = print::mathml(&Expr::sym(g.symbol));
    match (&g.definition, &g.written) {
        (Some(d), _) => format!("<math>{name}<mo>=</mo>{}</math>", print::mathml(&d.expr)),
        (None, Some(w)) => format!("<math>{name}<mo>=</mo>{}</math>", value(&w.number, &w.unit)),
        (None, None) => format!("<math>{name}</math>"),
    }
}

/// Rows of a three-column table aligned at `=`, as one block of maths, its fractions set
/// full size as in LaTeX's `align*` (a table's cells are otherwise in text style).
fn block_of_rows(rows: impl Iterator<Item = String>) -> String {
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

/// Results as one block of rows, a row per line of each ([`result_rows`]); `values_only`
/// (the answers), a line that has a value shows it alone.
fn results(results: &[Result], values_only: bool) -> String {
    let (first_em, width_em) = results_room(results);
    let lines = results.iter().flat_map(Result::lines);
    block_of_rows(lines.map(|l| result_rows(l, first_em, width_em, values_only)))
}

/// A result's line: its quantity's name, its form (broken as a relation is) and, when it
/// has one, `= value unit` after its last line; words without a name, on their own.
fn result_rows(l: &Line, first_em: f64, width_em: f64, values_only: bool) -> String {
    let mut name = String::new();
    print::mathml::latex_name(&mut name, &l.name.latex);
    let value = l.shown_value().map(|v| v.render(Notation::MathMl));
    let show = match l.show {
        Show::Both if values_only => Show::Value,
        show => show,
    };
    let mut lines = match (&l.form, show) {
        (Some(form), _) if l.name.latex.is_empty() => {
            let words = form.render(Notation::MathMl);
            return format!("<mtr><mtd></mtd><mtd></mtd><mtd class=\"rhs\">{words}</mtd></mtr>\n");
        }
        (Some(form), Show::Form | Show::Both) => form.lines(Notation::MathMl, first_em, width_em),
        (_, _) => Vec::new(),
    };
    let mut rhs = lines.pop().unwrap_or_default();
    if let Some(v) = value.filter(|_| show != Show::Form) {
        if !rhs.is_empty() {
            rhs.push_str("<mo>=</mo>");
        }
        rhs.push_str(&v);
    }
    lines.push(rhs);
    rows(&name, &lines)
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
