//! The results that are not a scalar or a vector, in every format: an inertia tensor
//! (`find I_G`, `find I_O`) as a matrix in the chapter's convention,
//!
//! ```text
//!         [  I_x  -I_xy  -I_xz ]
//! [I_G] = [ -I_xy   I_y  -I_yz ]  = [numbers] kg·m²
//!         [ -I_xz  -I_yz   I_z ]
//! ```
//!
//! and a principal frame (`find principal_G`) as rows `I_1 = …`, `I_2 = …`, `I_3 = …`
//! (ascending, with their values), then the axes `e_1 = …`, `e_2 = …`, `e_3 = …` (a
//! right-handed frame), then the remark on equal moments when there is one. A form that is a
//! number (a numeric solution) is shown by its value alone, in four significant figures.
//!
//! Values (SI) are listed moments first, then the axes' components: a principal result's
//! `value` holds 3 + 9 numbers, a tensor's 9 (row by row).

use super::mathml_value::{decimal, spaced_unit, value as mathml_value};
use super::numbers::format_value;
use super::render::Result;
use super::unit_latex::quantity;
use super::vector_value;
use crate::algebra::{Axis, Expr, Matrix, Vector};
use crate::print::PAGE_WIDTH_EM;
use crate::print::{self, markup, Notation};
use crate::scene::model::Quantity;
use crate::scene::Value;

/// One row of such a result: its name (LaTeX), its form, its numbers and unit.
struct Row<'a> {
    name: String,
    form: Form<'a>,
    numbers: Option<&'a [f64]>,
    unit: &'a str,
}

enum Form<'a> {
    Scalar(&'a Expr),
    Vector(&'a Vector),
    Matrix(&'a Matrix),
    /// Words (title markup): the remark on equal moments.
    Words(&'a str),
}

/// The rows of a tensor or principal result; `None` for a scalar or a vector.
fn rows<'a>(r: &'a Result) -> Option<Vec<Row<'a>>> {
    let unit = r.unit.as_deref().unwrap_or("");
    let numbers = |range: std::ops::Range<usize>| r.value.as_ref().map(|v| &v[range]);
    match r.form.as_deref()? {
        Value::Tensor(m) => Some(vec![Row {
            name: format!("[{}]", r.name),
            form: Form::Matrix(m),
            numbers: numbers(0..9),
            unit,
        }]),
        Value::Principal(frame) => {
            let moments = (0..3).map(|k| Row {
                name: format!("I_{}", k + 1),
                form: Form::Scalar(&frame.moments[k]),
                numbers: numbers(k..k + 1),
                unit,
            });
            let axes = (0..3).map(|k| Row {
                name: format!("e_{}", k + 1),
                form: Form::Vector(&frame.axes[k]),
                numbers: numbers(3 + 3 * k..6 + 3 * k),
                unit: "",
            });
            let remark = frame.remark.as_deref().map(|w| Row {
                name: String::new(),
                form: Form::Words(w),
                numbers: None,
                unit: "",
            });
            Some(moments.chain(axes).chain(remark).collect())
        }
        Value::Scalar(_) | Value::Vector(_) | Value::Balance(_) | Value::Precession(_) => None,
    }
}

/// `[I_G]`, `[I_O]`.
pub(super) fn tensor_name(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::InertiaAboutO => "[I_O]",
        _ => "[I_G]",
    }
}

/// The value list of a tensor (9 entries) or a principal frame (3 moments, 9 components),
/// each evaluated by `value`; `None` when one has no value.
pub(super) fn values(v: &Value, value: impl Fn(&Expr) -> Option<f64>) -> Option<Vec<f64>> {
    match v {
        Value::Tensor(m) => m.transpose().iter().map(value).collect(),
        Value::Principal(p) => p
            .moments
            .iter()
            .chain(p.axes.iter().flat_map(|e| e.iter()))
            .map(value)
            .collect(),
        Value::Scalar(_) | Value::Vector(_) | Value::Balance(_) | Value::Precession(_) => None,
    }
}

/// What a row shows: its form, its numbers, or both (`form = numbers`).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Show {
    Form,
    Numbers,
    Both,
}

/// A numeric solution's moments and axes by their numbers alone (their exact decimals say
/// nothing more), an axis `i` or `-k` by its form alone, a symbolic form with its numbers.
fn show(row: &Row) -> Show {
    let number = |e: &Expr| e.as_num().is_some();
    let fraction = |e: &Expr| e.as_num().is_some_and(|q| !q.is_integer());
    let numeric = match &row.form {
        _ if row.numbers.is_none() => return Show::Form,
        Form::Scalar(e) => number(e),
        Form::Vector(v) => v.iter().all(number) && v.iter().any(fraction),
        Form::Matrix(m) => m.iter().all(number),
        Form::Words(_) => return Show::Form,
    };
    match (numeric, &row.form) {
        (true, _) => Show::Numbers,
        // An exact axis (`i`, `-k`, or with symbols): its numbers add nothing to `i`.
        (false, Form::Vector(v)) if v.iter().all(number) => Show::Form,
        (false, _) => Show::Both,
    }
}

fn numbers_text(numbers: &[f64]) -> String {
    numbers
        .iter()
        .map(|x| format_value(*x))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The text of the form: `[[a, b, c], [d, e, f], [g, h, i]]`, `a i + b j`, `a`.
fn form_text(form: &Form) -> String {
    match form {
        Form::Scalar(e) => print::text(e),
        Form::Vector(v) => print::vector(v, Notation::Text),
        Form::Matrix(m) => matrix_rows(m, print::text, "[[", "], [", "]]", ", "),
        Form::Words(w) => markup::text(w),
    }
}

fn matrix_rows(
    m: &Matrix,
    entry: impl Fn(&Expr) -> String,
    open: &str,
    between: &str,
    close: &str,
    separator: &str,
) -> String {
    let rows: Vec<String> = (0..3)
        .map(|r| {
            let entries: Vec<String> = (0..3).map(|c| entry(&m[(r, c)])).collect();
            entries.join(separator)
        })
        .collect();
    format!("{open}{}{close}", rows.join(between))
}

/// The numbers of a row in text: `0.01 kg·m^2`, `0.6 i + 0.8 j`, `[[…], […], […]] kg·m^2`.
fn row_numbers_text(row: &Row) -> Option<String> {
    let numbers = row.numbers?;
    let body = match (&row.form, numbers.len()) {
        (_, 1) => format_value(numbers[0]),
        (Form::Matrix(_), _) => {
            let rows: Vec<String> = numbers.chunks(3).map(numbers_text).collect();
            format!("[[{}]]", rows.join("], ["))
        }
        _ => return Some(vector_value::text(numbers, row.unit)),
    };
    Some(match row.unit {
        "" => body,
        u => format!("{body} {u}"),
    })
}

/// The result's text: one line per row, under its request's name (`principal_G:`), or
/// `I_G = [[…]] = [[…]] kg·m^2` for a tensor; `numbers_only` (the engineer's page): each
/// row with numbers by its numbers alone.
pub(super) fn text(r: &Result, numbers_only: bool) -> Option<String> {
    let rows = rows(r)?;
    let mut out = String::new();
    let single = rows.len() == 1;
    if !single {
        out.push_str(&format!("  {}:\n", r.name));
    }
    for row in &rows {
        let indent = if single { "  " } else { "    " };
        let name = if single {
            r.name.to_string()
        } else {
            row.name.clone()
        };
        let numbers = row_numbers_text(row);
        let form = form_text(&row.form);
        let numbers = numbers.unwrap_or_default();
        let shown = match show(row) {
            Show::Both if numbers_only => Show::Numbers,
            shown => shown,
        };
        let line = match (&row.form, shown) {
            (Form::Words(_), _) => form,
            (_, Show::Numbers) => format!("{name} = {numbers}"),
            (_, Show::Both) => format!("{name} = {form} = {numbers}"),
            (_, Show::Form) => format!("{name} = {form}"),
        };
        out.push_str(&format!("{indent}{line}\n"));
    }
    Some(out)
}

/// The result on one line (JSON's `text` and `latex`): a tensor's matrix, or a frame's rows
/// joined, each numeric form by its four figures (`I_1 = 0.03413`, `e_1 = 0.8366 i + …`).
fn one_line_in(
    v: &Value,
    form: impl Fn(&Form) -> String,
    vector_numbers: fn(&[f64], &str) -> String,
    separator: &str,
) -> String {
    match v {
        Value::Tensor(m) => form(&Form::Matrix(m)),
        Value::Principal(p) => {
            let shown = |f: Form, numbers: Vec<f64>| match show(&Row {
                name: String::new(),
                form: f,
                numbers: Some(&numbers),
                unit: "",
            }) {
                Show::Numbers if numbers.len() == 1 => format_value(numbers[0]),
                Show::Numbers => vector_numbers(&numbers, ""),
                _ => String::new(),
            };
            let value = |e: &Expr| e.as_num().map_or(f64::NAN, crate::algebra::Q::to_f64);
            let moments = p.moments.iter().enumerate().map(|(k, m)| {
                let numeric = shown(Form::Scalar(m), vec![value(m)]);
                let text = if numeric.is_empty() {
                    form(&Form::Scalar(m))
                } else {
                    numeric
                };
                format!("I_{} = {text}", k + 1)
            });
            let axes = p.axes.iter().enumerate().map(|(k, e)| {
                let numeric = shown(Form::Vector(e), e.iter().map(value).collect());
                let text = if numeric.is_empty() {
                    form(&Form::Vector(e))
                } else {
                    numeric
                };
                format!("e_{} = {text}", k + 1)
            });
            moments.chain(axes).collect::<Vec<_>>().join(separator)
        }
        Value::Scalar(_) | Value::Vector(_) | Value::Balance(_) | Value::Precession(_) => {
            String::new()
        }
    }
}

/// [`one_line_in`] as text.
pub(super) fn one_line(v: &Value) -> String {
    one_line_in(v, form_text, vector_value::text, "; ")
}

/// The LaTeX of a form.
fn form_latex(form: &Form) -> String {
    match form {
        Form::Scalar(e) => print::latex(e),
        Form::Vector(v) => print::vector(v, Notation::Latex),
        Form::Matrix(m) => bmatrix(m, print::latex),
        Form::Words(w) => format!(r"\text{{{}}}", markup::latex(w)),
    }
}

fn bmatrix(m: &Matrix, entry: impl Fn(&Expr) -> String) -> String {
    matrix_rows(
        m,
        entry,
        r"\begin{bmatrix} ",
        r" \\ ",
        r" \end{bmatrix}",
        " & ",
    )
}

/// [`one_line_in`] in LaTeX.
pub(super) fn one_line_latex(v: &Value) -> String {
    one_line_in(v, form_latex, vector_value::latex, r",\quad ")
}

/// The numbers of a row in LaTeX, with the unit.
fn row_numbers_latex(row: &Row) -> Option<String> {
    let numbers = row.numbers?;
    let body = match (&row.form, numbers.len()) {
        (_, 1) => format_value(numbers[0]),
        (Form::Matrix(_), _) => {
            let cells: Vec<String> = numbers.iter().map(|x| format_value(*x)).collect();
            let rows: Vec<String> = cells.chunks(3).map(|c| c.join(" & ")).collect();
            format!(r"\begin{{bmatrix}} {} \end{{bmatrix}}", rows.join(r" \\ "))
        }
        _ => return Some(vector_value::latex(numbers, row.unit)),
    };
    Some(quantity(&body, row.unit))
}

/// The result's rows of the results' `align*` block.
pub(super) fn latex(r: &Result) -> Option<Vec<String>> {
    let rows = rows(r)?;
    Some(
        rows.iter()
            .map(|row| {
                // Braced: a `[` after the row break `\\` would be read as its argument.
                let name = match row.name.starts_with('[') {
                    true => format!("{{{}}}", row.name),
                    false => row.name.clone(),
                };
                let form = form_latex(&row.form);
                let n = row_numbers_latex(row).unwrap_or_default();
                // A matrix too wide for the page is shown by its numbers (its entries are the
                // tensor's step, one a line).
                let shown = match (&row.form, show(row)) {
                    (Form::Matrix(m), Show::Both) if matrix_em(m) > PAGE_WIDTH_EM => Show::Numbers,
                    (_, shown) => shown,
                };
                match (&row.form, shown) {
                    (Form::Words(_), _) => format!("& {form}"),
                    (_, Show::Numbers) => format!("{name} &= {n}"),
                    (Form::Matrix(_), Show::Both) => format!("{name} &= {form} \\\\\n&= {n}"),
                    (_, Show::Both) => format!("{name} &= {form} = {n}"),
                    (_, Show::Form) => format!("{name} &= {form}"),
                }
            })
            .collect(),
    )
}

/// The width in ems of a matrix in display style: its widest entry in each column, a
/// column gap (2 em, amsmath's) between columns, the brackets and the name before it.
fn matrix_em(m: &Matrix) -> f64 {
    let columns: f64 = (0..3)
        .map(|c| {
            (0..3)
                .map(|r| print::width_em(&m[(r, c)], Axis::X))
                .fold(0.0, f64::max)
        })
        .sum();
    columns + 2.0 * 2.0 + 4.0
}

/// A form in MathML.
fn form_mathml(form: &Form) -> String {
    match form {
        Form::Scalar(e) => print::mathml(e),
        Form::Vector(v) => print::vector(v, Notation::MathMl),
        Form::Matrix(m) => mathml_matrix(m.iter().map(print::mathml).collect()),
        Form::Words(w) => markup::html(w),
    }
}

/// Nine cells (column by column, as nalgebra stores them) in brackets.
fn mathml_matrix(cells: Vec<String>) -> String {
    let rows: String = (0..3)
        .map(|r| {
            let entries: String = (0..3)
                .map(|c| {
                    format!(
                        "<mtd style=\"padding: 0.1em 0.4em\">{}</mtd>",
                        cells[r + 3 * c]
                    )
                })
                .collect();
            format!("<mtr>{entries}</mtr>")
        })
        .collect();
    format!("<mrow><mo>[</mo><mtable>{rows}</mtable><mo>]</mo></mrow>")
}

fn name_mathml(name: &str) -> String {
    let mut out = String::new();
    match name.strip_prefix('[').and_then(|n| n.strip_suffix(']')) {
        Some(inner) => {
            out.push_str("<mrow><mo>[</mo>");
            print::mathml::latex_name(&mut out, inner);
            out.push_str("<mo>]</mo></mrow>");
        }
        None => print::mathml::latex_name(&mut out, name),
    }
    out
}

/// The numbers of a row in MathML, with the unit.
fn row_numbers_mathml(row: &Row) -> Option<String> {
    let numbers = row.numbers?;
    Some(match (&row.form, numbers.len()) {
        (_, 1) => mathml_value(&format_value(numbers[0]), row.unit),
        (Form::Matrix(_), _) => {
            // Row by row in `numbers`; the cells are read column by column.
            let cells = (0..9)
                .map(|k| decimal(&format_value(numbers[(k % 3) * 3 + k / 3])))
                .collect();
            mathml_matrix(cells) + &spaced_unit(row.unit)
        }
        _ => vector_value::mathml(numbers, row.unit),
    })
}

/// The result's rows of the results' table (`lhs`, `=`, `rhs` cells), built by `row`.
pub(super) fn mathml(r: &Result, row_cells: impl Fn(&str, &[String]) -> String) -> Option<String> {
    let rows = rows(r)?;
    Some(
        rows.iter()
            .map(|row| {
                let (name, form) = (name_mathml(&row.name), form_mathml(&row.form));
                let n = row_numbers_mathml(row).unwrap_or_default();
                match (&row.form, show(row)) {
                    (Form::Words(_), _) => format!(
                        "<mtr><mtd></mtd><mtd></mtd><mtd class=\"rhs\"><mtext>{form}</mtext></mtd></mtr>\n"
                    ),
                    (_, Show::Numbers) => row_cells(&name, &[n]),
                    (_, Show::Both) => row_cells(&name, &[format!("{form}<mo>=</mo>{n}")]),
                    (_, Show::Form) => row_cells(&name, &[form]),
                }
            })
            .collect(),
    )
}

/// JSON's `value`: a tensor's rows `[[…], […], […]]`; a frame's
/// `{"moments": [I_1, I_2, I_3], "axes": [e_1, e_2, e_3], "remark": text|null}`.
pub(super) fn json_value(r: &Result) -> Option<serde_json::Value> {
    let numbers = r.value.as_ref();
    match r.form.as_deref()? {
        Value::Tensor(_) => Some(match numbers {
            Some(v) => serde_json::json!(v.chunks(3).collect::<Vec<_>>()),
            None => serde_json::Value::Null,
        }),
        Value::Principal(p) => Some(serde_json::json!({
            "moments": numbers.map(|v| v[..3].to_vec()),
            "axes": numbers.map(|v| v[3..].chunks(3).map(<[f64]>::to_vec).collect::<Vec<_>>()),
            "remark": p.remark.as_deref().map(markup::text),
        })),
        Value::Scalar(_) | Value::Vector(_) | Value::Balance(_) | Value::Precession(_) => None,
    }
}
