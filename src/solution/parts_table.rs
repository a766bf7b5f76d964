//! A composite body's table of parts (a row per part, a column per quantity: `m`, `x̄`, …,
//! `I_xz`) in each format, as a student lays it out before summing. The columns are shown
//! in groups (mass and position; moments; products) so that a table never runs wider than
//! the page: each group is a table of its own with the parts' labels in front.

use crate::algebra::{Axis, Expr};
use crate::mechanics::Table;
use crate::print::{self, markup, Notation};

/// The groups of at most this many columns each table shows.
const COLUMNS_PER_GROUP: usize = 4;

/// The column groups: mass and position first, then the moments, then the products (the
/// chapter's order), or runs of [`COLUMNS_PER_GROUP`] for another table.
fn groups(table: &Table) -> Vec<std::ops::Range<usize>> {
    let n = table.columns.len();
    if n == 10 {
        return vec![0..4, 4..7, 7..10];
    }
    (0..n)
        .step_by(COLUMNS_PER_GROUP)
        .map(|start| start..(start + COLUMNS_PER_GROUP).min(n))
        .collect()
}

fn cell(e: &Expr, notation: Notation) -> String {
    print::render(e, notation, Axis::X)
}

/// Plain text: columns padded to their widest cell, a rule under the header.
pub fn text(table: &Table) -> String {
    let mut out = String::new();
    for group in groups(table) {
        let mut rows: Vec<Vec<String>> = vec![std::iter::once("part".to_string())
            .chain(
                table.columns[group.clone()]
                    .iter()
                    .map(|c| cell(c, Notation::Text)),
            )
            .collect()];
        for row in &table.rows {
            rows.push(
                std::iter::once(row.label.clone())
                    .chain(
                        row.cells[group.clone()]
                            .iter()
                            .map(|c| cell(c, Notation::Text)),
                    )
                    .collect(),
            );
        }
        let widths: Vec<usize> = (0..rows[0].len())
            .map(|k| rows.iter().map(|r| r[k].chars().count()).max().unwrap_or(0))
            .collect();
        for (i, row) in rows.iter().enumerate() {
            let line: Vec<String> = row
                .iter()
                .zip(&widths)
                .map(|(c, w)| format!("{c:<w$}"))
                .collect();
            out.push_str(&format!("  {}\n", line.join("   ").trim_end()));
            if i == 0 {
                let rule: Vec<String> = widths.iter().map(|w| "-".repeat(*w)).collect();
                out.push_str(&format!("  {}\n", rule.join("   ")));
            }
        }
    }
    out
}

/// LaTeX: a display-math `array` per group, a rule under the header.
pub fn latex(table: &Table) -> String {
    let mut out = String::new();
    for group in groups(table) {
        let columns = "l".to_string() + &"c".repeat(group.len());
        let header: Vec<String> = std::iter::once(r"\text{part}".to_string())
            .chain(
                table.columns[group.clone()]
                    .iter()
                    .map(|c| cell(c, Notation::Latex)),
            )
            .collect();
        let rows: Vec<String> = table
            .rows
            .iter()
            .map(|row| {
                std::iter::once(format!(r"\text{{{}}}", markup::latex_words(&row.label)))
                    .chain(
                        row.cells[group.clone()]
                            .iter()
                            .map(|c| cell(c, Notation::Latex)),
                    )
                    .collect::<Vec<_>>()
                    .join(" & ")
            })
            .collect();
        out.push_str(&format!(
            "\\[\n\\begin{{array}}{{{columns}}}\n{} \\\\\n\\hline\n{}\n\\end{{array}}\n\\]\n",
            header.join(" & "),
            rows.join(" \\\\\n")
        ));
    }
    out
}

/// Markdown: a pipe table per group, cells as inline maths.
pub fn markdown(table: &Table) -> String {
    let mut out = String::new();
    for group in groups(table) {
        let header: Vec<String> = std::iter::once("part".to_string())
            .chain(
                table.columns[group.clone()]
                    .iter()
                    .map(|c| format!("${}$", cell(c, Notation::Latex))),
            )
            .collect();
        out.push_str(&format!("| {} |\n", header.join(" | ")));
        out.push_str(&format!("|{}\n", "---|".repeat(header.len())));
        for row in &table.rows {
            let cells: Vec<String> = std::iter::once(row.label.replace('|', "\\|"))
                .chain(
                    row.cells[group.clone()]
                        .iter()
                        .map(|c| format!("${}$", cell(c, Notation::Latex))),
                )
                .collect();
            out.push_str(&format!("| {} |\n", cells.join(" | ")));
        }
        out.push('\n');
    }
    out
}

/// JSON: the columns and each part's row, every cell in text and LaTeX.
pub fn json(table: &Table) -> serde_json::Value {
    let forms = |e: &Expr| serde_json::json!({"text": cell(e, Notation::Text), "latex": cell(e, Notation::Latex)});
    serde_json::json!({
        "columns": table.columns.iter().map(forms).collect::<Vec<_>>(),
        "rows": table.rows.iter().map(|row| serde_json::json!({
            "label": row.label,
            "cells": row.cells.iter().map(forms).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanics::TableRow;

    fn two_rods() -> Table {
        let s = Expr::symbol;
        Table {
            columns: vec![s("m"), s("xbar"), s("I_x")],
            rows: vec![
                TableRow {
                    label: "1".into(),
                    cells: vec![s("m_1"), s("a") / Expr::int(2), Expr::zero()],
                },
                TableRow {
                    label: "rod_2".into(),
                    cells: vec![s("m_2"), s("a"), s("m_2") * s("b").powi(2) / Expr::int(3)],
                },
            ],
        }
    }

    #[test]
    fn text_columns_line_up() {
        let t = text(&two_rods());
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines.len(), 4, "{t}");
        assert!(lines[0].starts_with("  part"), "{t}");
        let column = lines[0].find("xbar").unwrap();
        assert_eq!(&lines[2][column..column + 5], "1/2*a", "{t}");
    }

    #[test]
    fn latex_is_an_array_with_escaped_labels() {
        let t = latex(&two_rods());
        assert!(t.contains(r"\begin{array}{lccc}"), "{t}");
        assert!(
            t.contains(r"\text{rod\_2} & m_2 & a & \frac{1}{3} m_2 b^2"),
            "{t}"
        );
        assert!(t.contains(r"\bar{x}"), "{t}");
    }

    #[test]
    fn markdown_is_a_pipe_table() {
        let t = markdown(&two_rods());
        assert!(t.starts_with("| part | $m$ | $\\bar{x}$ | $I_x$ |\n|---|---|---|---|\n"));
    }
}
