//! Printers: LaTeX in textbook form, plain text the parser reads back, and MathML Core for
//! a browser.
//!
//! All three render the same presented form ([`layout::Layout::present`]), so they always
//! agree on order and grouping; only the notation differs. Each thread keeps one layout and reuses
//! it, and a renderer appends to one string, so printing allocates no node of its own.
//!
//! ```
//! use kinetics::algebra::Expr;
//! use kinetics::print;
//! let h = Expr::symbol("I_x") * Expr::symbol("w_x") - Expr::symbol("I_xy") * Expr::symbol("w_y");
//! assert_eq!(print::latex(&h), r"I_x \omega_x - I_{xy} \omega_y");
//! assert_eq!(print::text(&h), "I_x*w_x - I_xy*w_y");
//! ```

pub mod grouped_vector;
mod growing_parentheses;
pub mod latex;
pub mod layout;
pub mod line_break;
pub mod markup;
pub mod mathml;
pub mod matrix;
mod spelling;
pub mod text;
pub mod width;

pub use line_break::{
    aligned_room, broken, broken_vector, width_em, CONTINUATION_EM, PAGE_WIDTH_EM,
};

use crate::algebra::{Axis, Expr, Symbol, Vector, View};
use layout::{Integer, Layout, Node, NodeId, Span};
pub use spelling::on_one_page;
use std::borrow::Cow;
use std::cell::RefCell;
use std::fmt::Write;

/// The notation of a printed result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Notation {
    #[default]
    Text,
    Latex,
    /// MathML Core, the elements inside a `<math>` element.
    MathMl,
}

/// How a notation writes the marks around and between terms: a leading minus, the signs
/// between terms, and the parentheses of a group, which `fit` sizes once the group is
/// written (from where its opening parenthesis starts to the end of the output).
struct Marks {
    leading_minus: &'static str,
    minus: &'static str,
    plus: &'static str,
    open: &'static str,
    close: &'static str,
    fit: fn(&mut String, usize),
}

/// The marks of text and LaTeX.
const PLAIN_MARKS: Marks = Marks {
    leading_minus: "-",
    minus: " - ",
    plus: " + ",
    open: "(",
    close: ")",
    fit: |_, _| {},
};

thread_local! {
    /// This thread's layout, reused so that printing allocates only the printed string.
    static LAYOUT: RefCell<Layout> = RefCell::new(Layout::default());
}

/// Presents `e` about `axis` and hands the layout, the sign and the root to `render` (which
/// may add nodes of its own, such as the lines of a broken sum).
fn presented<R>(e: &Expr, axis: Axis, render: impl FnOnce(&mut Layout, bool, NodeId) -> R) -> R {
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
        Notation::MathMl => mathml::render(out, layout, negative, root),
    }
}

/// Appends a signed root in text or LaTeX: `-x`, and `-(a + b)` for a sum; `node` writes a
/// node in the notation.
fn signed(
    out: &mut String,
    layout: &Layout,
    negative: bool,
    root: NodeId,
    node: impl Fn(&mut String, &Layout, NodeId),
) {
    signed_with(out, layout, negative, root, &PLAIN_MARKS, node);
}

/// Appends a signed root with the notation's `marks`.
fn signed_with(
    out: &mut String,
    layout: &Layout,
    negative: bool,
    root: NodeId,
    marks: &Marks,
    node: impl Fn(&mut String, &Layout, NodeId),
) {
    let grouped = negative && matches!(layout.node(root), Node::Sum(_));
    if negative {
        out.push_str(marks.leading_minus);
    }
    let open_at = out.len();
    if grouped {
        out.push_str(marks.open);
    }
    node(out, layout, root);
    if grouped {
        out.push_str(marks.close);
        (marks.fit)(out, open_at);
    }
}

/// Appends the terms of a sum in text or LaTeX, `a - b + c`, never `a + -b`.
fn sum(
    out: &mut String,
    layout: &Layout,
    terms: Span,
    node: impl Fn(&mut String, &Layout, NodeId),
) {
    sum_with(out, layout, terms, &PLAIN_MARKS, node);
}

/// Appends the terms of a sum with the notation's `marks`.
fn sum_with(
    out: &mut String,
    layout: &Layout,
    terms: Span,
    marks: &Marks,
    node: impl Fn(&mut String, &Layout, NodeId),
) {
    for (i, &(negative, term)) in layout.entries(terms).iter().enumerate() {
        out.push_str(match (i, negative) {
            (0, true) => marks.leading_minus,
            (0, false) => "",
            (_, true) => marks.minus,
            (_, false) => marks.plus,
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

/// The names of the unit vectors, in the order of a vector's components.
const UNIT_VECTORS: [&str; 3] = ["i", "j", "k"];

/// A vector `a i + b j + c k`; a component with several terms is parenthesised:
/// `\frac{1}{2} m r^2 \omega_1 \mathbf{i} - (...) \mathbf{j}`.
pub fn vector(v: &Vector, notation: Notation) -> String {
    let mut out = String::new();
    for (component, unit) in v.iter().zip(UNIT_VECTORS) {
        if component.is_zero() {
            continue;
        }
        let first = out.is_empty();
        let (flipped, component) = signed_component(component);
        presented(&component, Axis::X, |layout, negative, root| {
            let unit = Symbol::new(unit);
            let negative = negative != flipped;
            vector_component(&mut out, layout, negative, root, first, unit, notation);
        });
    }
    if out.is_empty() {
        out.push_str(match notation {
            Notation::Text | Notation::Latex => "0",
            Notation::MathMl => mathml::ZERO,
        });
    }
    out
}

/// A vector's component as it is written: a sum whose every term is negative with its
/// minus before the parentheses, `− (4L² + r²) j` (`true` and the sum negated).
fn signed_component(c: &Expr) -> (bool, Cow<'_, Expr>) {
    let negative_terms = |ts: &[Expr]| ts.iter().all(|t| t.coefficient().is_negative());
    match c.view() {
        View::Add(terms) if negative_terms(terms) => (true, Cow::Owned(-c)),
        _ => (false, Cow::Borrowed(c)),
    }
}

/// The marks `notation` writes around and between terms.
fn marks(notation: Notation) -> &'static Marks {
    match notation {
        Notation::Text | Notation::Latex => &PLAIN_MARKS,
        Notation::MathMl => &mathml::MARKS,
    }
}

/// Appends one component of a vector with its sign and unit vector: `(a + b) \mathbf{i}`
/// first, `- c \mathbf{j}` after another.
fn vector_component(
    out: &mut String,
    layout: &Layout,
    negative: bool,
    root: NodeId,
    first: bool,
    unit: Symbol,
    notation: Notation,
) {
    let marks = marks(notation);
    // A unit coefficient is not written: `\mathbf{i}`, not `1 \mathbf{i}`.
    let (one, times) = match notation {
        Notation::Text => ("1", "*"),
        Notation::Latex => ("1", " "),
        Notation::MathMl => (mathml::ONE, mathml::INVISIBLE_TIMES),
    };
    out.push_str(match (first, negative) {
        (true, true) => marks.leading_minus,
        (true, false) => "",
        (false, true) => marks.minus,
        (false, false) => marks.plus,
    });
    let grouped = matches!(layout.node(root), Node::Sum(_));
    // Parentheses grow around fractions in LaTeX, as a factor's do (MathML's fit them).
    let (open, close) = match notation {
        Notation::Latex if growing_parentheses::grows(layout, root) => (r"\left(", r"\right)"),
        _ => (marks.open, marks.close),
    };
    let open_at = out.len();
    if grouped {
        out.push_str(open);
    }
    let body = out.len();
    render_into(out, layout, false, root, notation);
    if grouped {
        out.push_str(close);
        (marks.fit)(out, open_at);
    } else if &out[body..] == one {
        out.truncate(body);
    }
    if out.len() > body {
        out.push_str(times);
    }
    match notation {
        Notation::Text => out.push_str(unit.name()),
        Notation::Latex => out.push_str(spelling::latex_of(unit)),
        Notation::MathMl => mathml::symbol(out, unit),
    }
}

/// MathML of an expression, inertia groups ordered as for the x-equation: the children of
/// a `<math>` element.
pub fn mathml(e: &Expr) -> String {
    render(e, Notation::MathMl, Axis::X)
}
