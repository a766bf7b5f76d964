//! Printers: LaTeX in textbook form and plain text the parser reads back.
//!
//! Both render the same presented form ([`layout::Layout::present`]), so they always agree
//! on order and grouping; only the notation differs. Each thread keeps one layout and reuses
//! it, and a renderer appends to one string, so printing allocates no node of its own.
//!
//! ```
//! use kinetics::algebra::Expr;
//! use kinetics::print;
//! let h = Expr::symbol("I_x") * Expr::symbol("w_x") - Expr::symbol("I_xy") * Expr::symbol("w_y");
//! assert_eq!(print::latex(&h), r"I_x \omega_x - I_{xy} \omega_y");
//! assert_eq!(print::text(&h), "I_x*w_x - I_xy*w_y");
//! ```

pub mod latex;
pub mod layout;
pub mod markup;
mod spelling;
pub mod text;

use crate::algebra::{Axis, Expr, Symbol, Vector};
use layout::{Integer, Layout, Node, NodeId, Span};
pub use spelling::on_one_page;
use std::cell::RefCell;
use std::fmt::Write;

/// The notation of a printed result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Notation {
    #[default]
    Text,
    Latex,
}

thread_local! {
    /// This thread's layout, reused so that printing allocates only the printed string.
    static LAYOUT: RefCell<Layout> = RefCell::new(Layout::default());
}

/// Presents `e` about `axis` and hands the layout, the sign and the root to `render`.
fn presented<R>(e: &Expr, axis: Axis, render: impl FnOnce(&Layout, bool, NodeId) -> R) -> R {
    let present = |layout: &mut Layout| {
        layout.clear();
        let (negative, root) = layout.present(e, axis);
        render(layout, negative, root)
    };
    LAYOUT.with(|cell| match cell.try_borrow_mut() {
        Ok(mut shared) => present(&mut shared),
        // A printer that runs while another is rendering takes a layout of its own.
        Err(_) => present(&mut Layout::default()),
    })
}

/// The printed form of `e` about `axis` in `notation`, appended to `out`.
fn render_into(
    out: &mut String,
    layout: &Layout,
    negative: bool,
    root: NodeId,
    notation: Notation,
) {
    match notation {
        Notation::Text => text::render(out, layout, negative, root),
        Notation::Latex => latex::render(out, layout, negative, root),
    }
}

/// Appends a signed root in either notation: `-x`, and `-(a + b)` for a sum; `node` writes a
/// node in the notation.
fn signed(
    out: &mut String,
    layout: &Layout,
    negative: bool,
    root: NodeId,
    node: impl Fn(&mut String, &Layout, NodeId),
) {
    let grouped = negative && matches!(layout.node(root), Node::Sum(_));
    if negative {
        out.push('-');
    }
    if grouped {
        out.push('(');
    }
    node(out, layout, root);
    if grouped {
        out.push(')');
    }
}

/// Appends the terms of a sum in either notation, `a - b + c`, never `a + -b`.
fn sum(
    out: &mut String,
    layout: &Layout,
    terms: Span,
    node: impl Fn(&mut String, &Layout, NodeId),
) {
    for (i, &(negative, term)) in layout.entries(terms).iter().enumerate() {
        out.push_str(match (i, negative) {
            (0, true) => "-",
            (0, false) => "",
            (_, true) => " - ",
            (_, false) => " + ",
        });
        node(out, layout, term);
    }
}

/// An integer in decimal digits, a single digit without the formatter.
fn integer(out: &mut String, n: Integer) {
    match n {
        Integer::Small(digit @ 0..=9) => out.push(char::from(b'0' + digit as u8)),
        // Formatting into a `String` cannot fail.
        Integer::Small(n) => {
            let _ = write!(out, "{n}");
        }
        Integer::Big(n) => {
            let _ = write!(out, "{n}");
        }
    }
}

/// LaTeX of an expression, inertia groups ordered as for the x-equation.
pub fn latex(e: &Expr) -> String {
    latex_about(e, Axis::X)
}

/// LaTeX of an expression that belongs to the equation about `axis`.
pub fn latex_about(e: &Expr, axis: Axis) -> String {
    render(e, Notation::Latex, axis)
}

/// Plain text of an expression.
pub fn text(e: &Expr) -> String {
    text_about(e, Axis::X)
}

/// Plain text of an expression that belongs to the equation about `axis`.
pub fn text_about(e: &Expr, axis: Axis) -> String {
    render(e, Notation::Text, axis)
}

/// An expression in the chosen notation.
pub fn render(e: &Expr, notation: Notation, axis: Axis) -> String {
    // Room for a typical term of each top-level term, so that the string rarely grows.
    let mut out = String::with_capacity(16 + 32 * e.terms().len());
    presented(e, axis, |layout, negative, root| {
        render_into(&mut out, layout, negative, root, notation)
    });
    out
}

/// A vector `a i + b j + c k`; a component with several terms is parenthesised:
/// `\frac{1}{2} m r^2 \omega_1 \mathbf{i} - (...) \mathbf{j}`.
pub fn vector(v: &Vector, notation: Notation) -> String {
    let units = ["i", "j", "k"].map(Symbol::new);
    let mut out = String::new();
    for (component, unit) in v.iter().zip(units) {
        if component.is_zero() {
            continue;
        }
        let unit = match notation {
            Notation::Text => unit.name(),
            Notation::Latex => unit.latex(),
        };
        presented(component, Axis::X, |layout, negative, root| {
            match (out.is_empty(), negative) {
                (true, true) => out.push('-'),
                (true, false) => {}
                (false, true) => out.push_str(" - "),
                (false, false) => out.push_str(" + "),
            }
            let grouped = matches!(layout.node(root), Node::Sum(_));
            if grouped {
                out.push('(');
            }
            let body = out.len();
            render_into(&mut out, layout, false, root, notation);
            if grouped {
                out.push(')');
            } else if &out[body..] == "1" {
                // A unit coefficient is not written: `\mathbf{i}`, not `1 \mathbf{i}`.
                out.truncate(body);
            }
            if out.len() > body {
                out.push_str(match notation {
                    Notation::Text => "*",
                    Notation::Latex => " ",
                });
            }
            out.push_str(unit);
        });
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}
