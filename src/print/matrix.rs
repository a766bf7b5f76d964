//! A 3 × 3 matrix in brackets, as the chapter writes `[I]`: in text its rows
//! `[[a, b, c], [d, e, f], [g, h, i]]`, in LaTeX a `bmatrix`, in MathML a table in brackets.
//! The entries arrive written (an expression, a number with no unit), so a tensor's form
//! and its numbers share the brackets.

use super::{render, width_em, Notation};
use crate::algebra::{Axis, Matrix};

/// The matrix whose entry in row `r`, column `c` is `entry(r, c)`, in `notation`.
pub fn bracketed(entry: impl Fn(usize, usize) -> String, notation: Notation) -> String {
    let row = |r: usize, separator: &str| {
        (0..3)
            .map(|c| entry(r, c))
            .collect::<Vec<_>>()
            .join(separator)
    };
    match notation {
        Notation::Text => {
            let rows: Vec<String> = (0..3).map(|r| format!("[{}]", row(r, ", "))).collect();
            format!("[{}]", rows.join(", "))
        }
        Notation::Latex => {
            let rows: Vec<String> = (0..3).map(|r| row(r, " & ")).collect();
            format!(r"\begin{{bmatrix}} {} \end{{bmatrix}}", rows.join(r" \\ "))
        }
        Notation::MathMl => {
            let rows: String = (0..3)
                .map(|r| {
                    let cells: String = (0..3)
                        .map(|c| {
                            format!("<mtd style=\"padding: 0.1em 0.4em\">{}</mtd>", entry(r, c))
                        })
                        .collect();
                    format!("<mtr>{cells}</mtr>")
                })
                .collect();
            format!("<mrow><mo>[</mo><mtable>{rows}</mtable><mo>]</mo></mrow>")
        }
    }
}

/// A matrix of expressions in `notation`.
pub fn matrix(m: &Matrix, notation: Notation) -> String {
    bracketed(|r, c| render(&m[(r, c)], notation, Axis::X), notation)
}

/// The width in ems of a matrix in display style: its widest entry in each column, a
/// column gap (2 em, amsmath's) between columns, and the brackets.
pub fn matrix_em(m: &Matrix) -> f64 {
    let columns: f64 = (0..3)
        .map(|c| {
            (0..3)
                .map(|r| width_em(&m[(r, c)], Axis::X))
                .fold(0.0, f64::max)
        })
        .sum();
    columns + 2.0 * 2.0 + 2.0
}

#[cfg(test)]
mod tests {
    use super::bracketed;
    use crate::print::Notation;

    #[test]
    fn rows_in_brackets() {
        let entry = |r: usize, c: usize| (3 * r + c).to_string();
        assert_eq!(
            bracketed(entry, Notation::Text),
            "[[0, 1, 2], [3, 4, 5], [6, 7, 8]]"
        );
        assert_eq!(
            bracketed(entry, Notation::Latex),
            r"\begin{bmatrix} 0 & 1 & 2 \\ 3 & 4 & 5 \\ 6 & 7 & 8 \end{bmatrix}"
        );
        let mathml = bracketed(entry, Notation::MathMl);
        assert_eq!(mathml.matches("<mtr>").count(), 3);
        assert!(mathml.contains("<mtd style=\"padding: 0.1em 0.4em\">5</mtd></mtr>"));
    }
}
