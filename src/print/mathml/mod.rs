//! MathML Core, the maths a browser lays out natively, for the same layout LaTeX prints:
//! `\frac{a}{b}` is `<mfrac>`, a power `<msup>` (`<msubsup>` on a subscripted symbol, as
//! `\omega_x^2` is set), `\sqrt{x}` `<msqrt>`, `\sqrt[3]{x}` `<mroot>`, `\sin\beta` `<mi>sin</mi><mo>&#x2061;</mo>`
//! (function application) and `β`, factors joined by invisible times (`&#x2062;`), and
//! parentheses `<mo>(</mo> … <mo>)</mo>`, which stretch to a fraction they enclose, as
//! `\left( … \right)` does, and keep the size of the text otherwise (a stretched glyph
//! around `m_1 + m_2`, taller than the text by its subscripts, would stand apart). A symbol's
//! MathML is read from its LaTeX spelling on the page being printed ([`spelling`]; the plain
//! `w_x` where [`crate::print::on_one_page`] keeps it apart from `omega_x`), so the two never
//! name it apart.
//!
//! The output is the content of a `<math>` element; wrapping it is the caller's.

mod spelling;

use super::layout::{Integer, Layout, Node, NodeId, Number, Product, Span};
use super::spelling::latex_of;
use super::{integer, Marks};
use crate::algebra::{Func, Symbol};

pub use spelling::escaped;

/// The marks of MathML: the minus sign U+2212 (a hyphen is too short), parentheses of the
/// text's size until [`fit_parentheses`] lets them grow.
pub(super) const MARKS: Marks = Marks {
    leading_minus: "<mo>\u{2212}</mo>",
    minus: "<mo>\u{2212}</mo>",
    plus: "<mo>+</mo>",
    open: FIXED_OPEN,
    close: FIXED_CLOSE,
    fit: fit_parentheses,
};

const FIXED_OPEN: &str = r#"<mrow><mo stretchy="false">(</mo>"#;
const FIXED_CLOSE: &str = r#"<mo stretchy="false">)</mo></mrow>"#;
const GROWING_OPEN: &str = "<mrow><mo>(</mo>";
const GROWING_CLOSE: &str = "<mo>)</mo></mrow>";

/// The group written in `out` from `open_at` (between [`FIXED_OPEN`] and [`FIXED_CLOSE`])
/// with parentheses that stretch when it holds a fraction.
fn fit_parentheses(out: &mut String, open_at: usize) {
    let Some(group) = out.get(open_at..) else {
        return;
    };
    let fenced = group.starts_with(FIXED_OPEN) && group.ends_with(FIXED_CLOSE);
    let inner = group.get(FIXED_OPEN.len()..group.len().saturating_sub(FIXED_CLOSE.len()));
    if fenced && inner.is_some_and(|inner| inner.contains("<mfrac")) {
        out.truncate(out.len() - FIXED_CLOSE.len());
        out.push_str(GROWING_CLOSE);
        out.replace_range(open_at..open_at + FIXED_OPEN.len(), GROWING_OPEN);
    }
}

/// The number one, as [`number`] writes it.
pub(super) const ONE: &str = "<mn>1</mn>";

/// The number zero.
pub(super) const ZERO: &str = "<mn>0</mn>";

/// The invisible operator between the factors of a product.
pub(super) const INVISIBLE_TIMES: &str = "<mo>&#x2062;</mo>";

/// Function application, between a function's name and its argument.
const APPLY: &str = "<mo>&#x2061;</mo>";

/// A thin space, the space TeX leaves between a function's argument and what follows.
const THIN_SPACE: &str = r#"<mspace width="0.1667em"/>"#;

/// Appends a signed layout to `out`.
pub fn render(out: &mut String, layout: &Layout, negative: bool, root: NodeId) {
    super::signed_with(out, layout, negative, root, &MARKS, node);
}

/// Appends the MathML of a symbol.
pub fn symbol(out: &mut String, s: Symbol) {
    spelling::write(out, latex_of(s), None);
}

/// Appends the MathML of a name spelt in LaTeX as symbols are (`\mathbf{H}_G`,
/// `\bar{\mathbf{v}}`, `\boldsymbol{\omega}`; see [`spelling`] for the subset); a
/// matrix's name in its brackets, `[I_G]`.
pub fn latex_name(out: &mut String, latex: &str) {
    match latex.strip_prefix('[').and_then(|n| n.strip_suffix(']')) {
        Some(inner) => {
            out.push_str("<mrow><mo>[</mo>");
            spelling::write(out, inner, None);
            out.push_str("<mo>]</mo></mrow>");
        }
        None => spelling::write(out, latex, None),
    }
}

fn node(out: &mut String, layout: &Layout, id: NodeId) {
    match layout.node(id) {
        Node::Number(n) => number(out, layout, *n),
        Node::Symbol(s) => symbol(out, *s),
        Node::Sum(terms) => {
            out.push_str("<mrow>");
            super::sum_with(out, layout, *terms, &MARKS, node);
            out.push_str("</mrow>");
        }
        Node::Product(p) => product(out, layout, p),
        Node::Power(base, exponent) => power(out, layout, *base, *exponent),
        Node::Root(2, inner) => {
            out.push_str("<msqrt>");
            node(out, layout, *inner);
            out.push_str("</msqrt>");
        }
        // Two children: the radicand one element (a sum is its own <mrow>), then the index.
        Node::Root(index, inner) => {
            out.push_str("<mroot>");
            match layout.node(*inner) {
                Node::Sum(_) | Node::Symbol(_) | Node::Number(_) => node(out, layout, *inner),
                _ => {
                    out.push_str("<mrow>");
                    node(out, layout, *inner);
                    out.push_str("</mrow>");
                }
            }
            out.push_str(&format!("<mn>{index}</mn></mroot>"));
        }
        Node::Function(Func::Abs, arg) => {
            out.push_str("<mrow><mo>|</mo>");
            node(out, layout, *arg);
            out.push_str("<mo>|</mo></mrow>");
        }
        Node::Function(f, arg) => {
            out.push_str("<mrow>");
            function_name(out, *f);
            out.push_str(APPLY);
            function_argument(out, layout, *arg);
            out.push_str("</mrow>");
        }
    }
}

/// `base^exponent`: a function's power on its name (`sin²β`), a power of a power
/// parenthesised, a symbol's exponent beside its subscript.
fn power(out: &mut String, layout: &Layout, base: NodeId, exponent: NodeId) {
    let mut raised = String::new();
    node(&mut raised, layout, exponent);
    match layout.node(base) {
        Node::Function(f, arg) => {
            out.push_str("<mrow><msup>");
            function_name(out, *f);
            row(out, &raised);
            out.push_str("</msup>");
            out.push_str(APPLY);
            function_argument(out, layout, *arg);
            out.push_str("</mrow>");
        }
        Node::Symbol(s) => spelling::write(out, latex_of(*s), Some(&raised)),
        Node::Power(..) => {
            out.push_str("<msup>");
            parenthesised(out, layout, base);
            row(out, &raised);
            out.push_str("</msup>");
        }
        _ => {
            out.push_str("<msup><mrow>");
            factor(out, layout, base);
            out.push_str("</mrow>");
            row(out, &raised);
            out.push_str("</msup>");
        }
    }
}

/// `<mrow>inner</mrow>`: one child of a script or fraction, whatever `inner` holds.
fn row(out: &mut String, inner: &str) {
    out.push_str("<mrow>");
    out.push_str(inner);
    out.push_str("</mrow>");
}

fn function_name(out: &mut String, f: Func) {
    out.push_str("<mi>");
    out.push_str(f.page_name());
    out.push_str("</mi>");
}

/// `sin β`, `sin(β + θ)`.
fn function_argument(out: &mut String, layout: &Layout, arg: NodeId) {
    match layout.node(arg) {
        Node::Symbol(s) => symbol(out, *s),
        _ => parenthesised(out, layout, arg),
    }
}

fn parenthesised(out: &mut String, layout: &Layout, id: NodeId) {
    let open_at = out.len();
    out.push_str(MARKS.open);
    node(out, layout, id);
    out.push_str(MARKS.close);
    fit_parentheses(out, open_at);
}

fn number(out: &mut String, layout: &Layout, n: Number) {
    match layout.parts(n) {
        (n, d) if d.is_one() => digits(out, n),
        (n, d) => fraction(out, n, d),
    }
}

/// `<mn>n</mn>`.
fn digits(out: &mut String, n: Integer) {
    out.push_str("<mn>");
    integer(out, n);
    out.push_str("</mn>");
}

/// `<mfrac><mn>n</mn><mn>d</mn></mfrac>`.
fn fraction(out: &mut String, n: Integer, d: Integer) {
    out.push_str("<mfrac>");
    digits(out, n);
    digits(out, d);
    out.push_str("</mfrac>");
}

/// A factor inside a product or under an exponent: sums and products get parentheses.
fn factor(out: &mut String, layout: &Layout, id: NodeId) {
    match layout.node(id) {
        Node::Sum(_) | Node::Product(_) => parenthesised(out, layout, id),
        Node::Number(n) if !layout.parts(*n).1.is_one() => parenthesised(out, layout, id),
        _ => node(out, layout, id),
    }
}

/// Factors joined by invisible times, after whatever `out` already holds of the same
/// product; a thin space before a factor that follows a function's argument or a name of
/// several letters (`sin β  L`, `Δt  b`), which would otherwise run into it.
fn factors(out: &mut String, layout: &Layout, mut separate: bool, span: Span) {
    let mut spaced = false;
    for &(_, f) in layout.entries(span) {
        if spaced {
            out.push_str(THIN_SPACE);
        }
        if separate {
            out.push_str(INVISIBLE_TIMES);
        }
        factor(out, layout, f);
        separate = true;
        spaced = match layout.node(f) {
            Node::Function(..) => true,
            Node::Power(base, _) => matches!(layout.node(*base), Node::Function(..)),
            Node::Symbol(s) => spelling::is_several_letters(latex_of(*s)),
            _ => false,
        };
    }
}

/// Above or below a fraction bar, which groups on its own: a lone sum needs no parentheses.
fn fraction_part(out: &mut String, layout: &Layout, after_number: bool, span: Span) {
    match layout.entries(span) {
        [(_, alone)] if !after_number => node(out, layout, *alone),
        _ => factors(out, layout, after_number, span),
    }
}

fn product(out: &mut String, layout: &Layout, p: &Product) {
    let (cn, cd) = layout.parts(p.coefficient);
    let shown = !cn.is_one() || p.numerator.is_empty();
    out.push_str("<mrow>");
    if p.denominator.is_empty() {
        if !cd.is_one() {
            fraction(out, cn, cd);
        } else if shown {
            digits(out, cn);
        }
        factors(out, layout, !cd.is_one() || shown, p.numerator);
    } else {
        out.push_str("<mfrac><mrow>");
        if shown {
            digits(out, cn);
        }
        fraction_part(out, layout, shown, p.numerator);
        out.push_str("</mrow><mrow>");
        if !cd.is_one() {
            digits(out, cd);
        }
        fraction_part(out, layout, !cd.is_one(), p.denominator);
        out.push_str("</mrow></mfrac>");
    }
    out.push_str("</mrow>");
}
