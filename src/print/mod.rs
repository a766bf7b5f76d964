//! Printers: LaTeX in textbook form and plain text the parser reads back.
//!
//! Both render the same presented form ([`layout::present`]), so they always agree on
//! order and grouping; only the notation differs.
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
pub mod text;

use crate::algebra::{Expr, Symbol, Vector};
pub use layout::Axis;
use layout::{present, Layout};

/// The notation of a printed result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Notation {
    #[default]
    Text,
    Latex,
}

/// LaTeX of an expression, inertia groups ordered as for the x-equation.
pub fn latex(e: &Expr) -> String {
    latex_about(e, Axis::X)
}

/// LaTeX of an expression that belongs to the equation about `axis`.
pub fn latex_about(e: &Expr, axis: Axis) -> String {
    let (negative, layout) = present(e, axis);
    latex::render(negative, &layout)
}

/// Plain text of an expression.
pub fn text(e: &Expr) -> String {
    text_about(e, Axis::X)
}

/// Plain text of an expression that belongs to the equation about `axis`.
pub fn text_about(e: &Expr, axis: Axis) -> String {
    let (negative, layout) = present(e, axis);
    text::render(negative, &layout)
}

/// An expression in the chosen notation.
pub fn render(e: &Expr, notation: Notation, axis: Axis) -> String {
    match notation {
        Notation::Text => text_about(e, axis),
        Notation::Latex => latex_about(e, axis),
    }
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
        let (negative, layout) = present(component, Axis::X);
        let body = match notation {
            Notation::Text => text::render(false, &layout),
            Notation::Latex => latex::render(false, &layout),
        };
        let grouped = matches!(layout, Layout::Sum(_));
        let unit = match notation {
            Notation::Text => unit.name(),
            Notation::Latex => unit.latex(),
        };
        let body = match (grouped, notation, body.as_str()) {
            (true, _, _) => format!("({body})"),
            (false, _, "1") => String::new(),
            _ => body,
        };
        let joined = match (body.is_empty(), notation) {
            (true, _) => unit.to_string(),
            (false, Notation::Text) => format!("{body}*{unit}"),
            (false, Notation::Latex) => format!("{body} {unit}"),
        };
        match (out.is_empty(), negative) {
            (true, true) => out.push('-'),
            (true, false) => {}
            (false, true) => out.push_str(" - "),
            (false, false) => out.push_str(" + "),
        }
        out.push_str(&joined);
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}
