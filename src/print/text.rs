//! Plain ASCII text that the parser reads back to the same canonical form:
//! `I_x*w_x - I_xy*w_y`, `1/2*m*v^2`, `6*F*Dt/(m*b)`, `-(I_y - I_z)*w_y*w_z`,
//! `sin(beta)`, `sqrt(x)`.

use super::integer;
use super::layout::{Integer, Layout, Node, NodeId, Number, Product, Span};
use crate::algebra::Expr;
use std::fmt;

/// Appends a signed layout to `out`.
pub fn render(out: &mut String, layout: &Layout, negative: bool, root: NodeId) {
    super::signed(out, layout, negative, root, node);
}

/// A node; symbols, the most frequent, without a call.
#[inline]
fn node(out: &mut String, layout: &Layout, id: NodeId) {
    match layout.node(id) {
        Node::Symbol(s) => out.push_str(s.name()),
        other => compound(out, layout, other),
    }
}

/// Kept out of line so that [`node`] stays small enough to be quick for symbols.
#[inline(never)]
fn compound(out: &mut String, layout: &Layout, compound: &Node) {
    match compound {
        Node::Number(n) => number(out, layout, *n),
        Node::Symbol(s) => out.push_str(s.name()),
        Node::Sum(terms) => super::sum(out, layout, *terms, node),
        Node::Product(p) => product(out, layout, p),
        Node::Power(base, exponent) => {
            power_base(out, layout, *base);
            out.push('^');
            match layout.node(*exponent) {
                Node::Number(n) if layout.parts(*n).1.is_one() => number(out, layout, *n),
                _ => parenthesised(out, layout, *exponent),
            }
        }
        Node::Root(2, inner) => {
            out.push_str("sqrt");
            parenthesised(out, layout, *inner);
        }
        // No function name for it in the input syntax: the power, as it is read back.
        Node::Root(index, inner) => {
            power_base(out, layout, *inner);
            out.push_str(&format!("^(1/{index})"));
        }
        Node::Function(f, arg) => {
            out.push_str(f.name());
            parenthesised(out, layout, *arg);
        }
    }
}

/// The base of a power written `base^exponent`: in parentheses when it is itself written
/// as a power (`(x^2)^(1/3)`, `(x^(1/3))^2`).
fn power_base(out: &mut String, layout: &Layout, base: NodeId) {
    match layout.node(base) {
        Node::Power(..) => parenthesised(out, layout, base),
        Node::Root(index, _) if *index != 2 => parenthesised(out, layout, base),
        _ => factor(out, layout, base),
    }
}

fn parenthesised(out: &mut String, layout: &Layout, id: NodeId) {
    out.push('(');
    node(out, layout, id);
    out.push(')');
}

fn number(out: &mut String, layout: &Layout, n: Number) {
    let (n, d) = layout.parts(n);
    ratio(out, n, d);
}

/// `p` for integers, `p/q` otherwise.
fn ratio(out: &mut String, n: Integer, d: Integer) {
    integer(out, n);
    if !d.is_one() {
        out.push('/');
        integer(out, d);
    }
}

/// A factor inside a product or under an exponent.
fn factor(out: &mut String, layout: &Layout, id: NodeId) {
    match layout.node(id) {
        Node::Symbol(s) => out.push_str(s.name()),
        Node::Sum(_) | Node::Product(_) => parenthesised(out, layout, id),
        Node::Number(n) if !layout.parts(*n).1.is_one() => {
            out.push('(');
            number(out, layout, *n);
            out.push(')');
        }
        other => compound(out, layout, other),
    }
}

/// The factors of one side of a product joined by `*`, after the number `shown` (if any,
/// as numerator and denominator).
fn factors(out: &mut String, layout: &Layout, shown: Option<(Integer, Integer)>, span: Span) {
    if let Some((n, d)) = shown {
        ratio(out, n, d);
    }
    for (i, &(_, f)) in layout.entries(span).iter().enumerate() {
        if i > 0 || shown.is_some() {
            out.push('*');
        }
        factor(out, layout, f);
    }
}

fn product(out: &mut String, layout: &Layout, p: &Product) {
    let (cn, cd) = layout.parts(p.coefficient);
    let one = Integer::Small(1);
    let shown_numerator = !cn.is_one() || p.numerator.is_empty();
    if p.denominator.is_empty() {
        let shown = (!cd.is_one() || shown_numerator).then_some((cn, cd));
        factors(out, layout, shown, p.numerator);
        return;
    }
    factors(
        out,
        layout,
        shown_numerator.then_some((cn, one)),
        p.numerator,
    );
    out.push('/');
    let shown = (!cd.is_one()).then_some((cd, one));
    let grouped = usize::from(shown.is_some()) + layout.entries(p.denominator).len() > 1;
    if grouped {
        out.push('(');
    }
    factors(out, layout, shown, p.denominator);
    if grouped {
        out.push(')');
    }
}

/// An expression shows as its plain text, `{}` and `{:?}` alike (assertion failures then
/// read as the maths). The impls live with the printer: algebra, the bottom layer, uses
/// no other part of the crate.
impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&super::text(self))
    }
}

impl fmt::Debug for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}
