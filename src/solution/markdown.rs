//! A [`Page`] in Markdown (its figure an image beside it, [`Page::figure_file`]): headings `#` (the title), `##` (a step, the results, a
//! derivation), `###` (a derivation's step); the givens and requests a bold lead-in and
//! inline maths; the mathematics the LaTeX page's blocks between `$$` (`latex.rs`). As in
//! LaTeX, the answers section (numbers first) is left to the text page.

use super::latex;
use super::page::{Block, Heading, Page, Section};
use super::parts_table;
use crate::print::markup;

/// The page in Markdown.
pub(super) fn page(page: &Page) -> String {
    let figure_file = page.figure_file;
    let mut out = String::new();
    if let Some(title) = page.title {
        out.push_str(&format!("# {}\n\n", markup::markdown(title)));
    }
    for s in &page.sections {
        section(&mut out, s, figure_file);
    }
    out
}

fn section(out: &mut String, section: &Section, figure_file: Option<&str>) {
    match &section.heading {
        Heading::Answers => return,
        Heading::Statement => {}
        Heading::Given => out.push_str("**Given:** "),
        Heading::Find => out.push_str("**Find:** "),
        Heading::Step { number, title } => {
            out.push_str(&format!(
                "## Step {number}: {}\n\n",
                markup::markdown(title)
            ));
        }
        Heading::Results => out.push_str("## Results\n\n"),
        Heading::Intermediate => out.push_str("## Intermediate values\n\n"),
        Heading::Derivation { title, .. } => {
            out.push_str(&format!("## {}\n\n", markup::markdown(title)))
        }
        Heading::DerivationStep(title) => {
            out.push_str(&format!("### {}\n\n", markup::markdown(title)));
        }
    }
    for block in &section.blocks {
        out.push_str(&match block {
            Block::Words(words) => format!("{}\n\n", markup::markdown(words)),
            Block::Givens(givens) => inline_list(givens.iter().map(latex::given)),
            Block::Find(names) => inline_list(names.iter().map(latex::name)),
            Block::Table(table) => parts_table::markdown(table),
            Block::Relations(rows) if rows.is_empty() => String::new(),
            Block::Relations(rows) => format!("$$\n{}$$\n\n", latex::relations(rows)),
            Block::Results(results) => format!("$$\n{}$$\n", latex::results(results, false)),
            Block::Answers(results) => format!("$$\n{}$$\n", latex::results(results, true)),
            Block::Figure(_) => match figure_file {
                Some(file) => format!("![The figure of the problem]({})\n\n", markdown_link(file)),
                None => "*The figure is drawn beside a page written to a file: `kinetics solve -o \
                     FILE.md` writes `FILE.svg`, Python's `to_markdown(figure=\"FILE.svg\")` \
                     the file it names.*\n\n"
                    .into(),
            },
            Block::Values(steps) => steps
                .iter()
                .map(|step| {
                    let title = markup::markdown(&step.title);
                    format!("{title}\n\n$$\n{}$$\n\n", latex::step_values(step))
                })
                .collect(),
        });
    }
    for sub in &section.subsections {
        self::section(out, sub, figure_file);
    }
}

/// A file name as a Markdown link target: `<…>` around it when it holds a space or a
/// parenthesis, `<` and `>` escaped.
fn markdown_link(file: &str) -> String {
    let escaped = file.replace('<', "%3C").replace('>', "%3E");
    match escaped.contains([' ', '(', ')']) {
        true => format!("<{escaped}>"),
        false => escaped,
    }
}

/// Items of inline maths on the line of their lead-in, then a blank line.
fn inline_list(items: impl Iterator<Item = String>) -> String {
    format!("{}\n\n", items.collect::<Vec<_>>().join(", "))
}
