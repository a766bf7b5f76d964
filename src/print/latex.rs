//! LaTeX as a textbook writes it: `I_x \omega_x - I_{xy} \omega_y`, `\frac{1}{2} m v^2`,
//! `\frac{6 F \Delta t}{m b}`, `-(I_y - I_z) \omega_y \omega_z`, `\sin\beta`, `\sqrt{x}`,
//! with no redundant parentheses or braces and never `a + -b`; a thin space where a product
//! would otherwise read another way (`F\,\Delta t\,b`, `\cos\beta\,\omega^2`).

use super::growing_parentheses::grows;
use super::integer;
use super::layout::{Integer, Layout, Node, NodeId, Number, Product, Span};
use super::spelling::latex_of;
use crate::algebra::{reads_as_several_letters, Func};

/// Appends a signed layout to `out`.
pub fn render(out: &mut String, layout: &Layout, negative: bool, root: NodeId) {
    super::signed(out, layout, negative, root, node);
}

/// A node; symbols, the most frequent, without a call.
#[inline]
fn node(out: &mut String, layout: &Layout, id: NodeId) {
    match layout.node(id) {
        Node::Symbol(s) => out.push_str(latex_of(*s)),
        other => compound(out, layout, other),
    }
}

/// Kept out of line so that [`node`] stays small enough to be quick for symbols.
#[inline(never)]
fn compound(out: &mut String, layout: &Layout, compound: &Node) {
    match compound {
        Node::Number(n) => number(out, layout, *n),
        Node::Symbol(s) => out.push_str(latex_of(*s)),
        Node::Sum(terms) => super::sum(out, layout, *terms, node),
        Node::Product(p) => product(out, layout, p),
        Node::Power(base, exponent) => match layout.node(*base) {
            Node::Function(f, arg) => {
                function_name(out, *f);
                superscript(out, layout, *exponent);
                function_argument(out, layout, *arg);
            }
            // A power of a power: `(\omega_x^2)^{\frac{3}{2}}`, never a double superscript.
            Node::Power(..) => {
                out.push('(');
                node(out, layout, *base);
                out.push(')');
                superscript(out, layout, *exponent);
            }
            _ => {
                factor(out, layout, *base);
                superscript(out, layout, *exponent);
            }
        },
        Node::Root(index, inner) => {
            out.push_str(r"\sqrt");
            if *index != 2 {
                out.push_str(&format!("[{index}]"));
            }
            out.push('{');
            node(out, layout, *inner);
            out.push('}');
        }
        Node::Function(Func::Abs, arg) => {
            out.push_str(r"\left|");
            node(out, layout, *arg);
            out.push_str(r"\right|");
        }
        Node::Function(f, arg) => {
            function_name(out, *f);
            function_argument(out, layout, *arg);
        }
    }
}

/// `^e` for an exponent of one character, `^{...}` otherwise.
fn superscript(out: &mut String, layout: &Layout, exponent: NodeId) {
    out.push('^');
    // A digit, the usual exponent, without measuring what was written.
    if let Node::Number(Number::Small(digit @ 0..=9, 1)) = *layout.node(exponent) {
        out.push(char::from(b'0' + digit as u8));
        return;
    }
    let start = out.len();
    node(out, layout, exponent);
    if out[start..].chars().count() != 1 {
        out.insert(start, '{');
        out.push('}');
    }
}

fn function_name(out: &mut String, f: Func) {
    out.push('\\');
    out.push_str(f.page_name());
}

/// `\sin\beta`, `\sin x`, `\sin(\beta + \theta)`.
fn function_argument(out: &mut String, layout: &Layout, arg: NodeId) {
    match layout.node(arg) {
        Node::Symbol(s) => {
            let name = latex_of(*s);
            if !name.starts_with('\\') {
                out.push(' ');
            }
            out.push_str(name);
        }
        _ => {
            out.push('(');
            node(out, layout, arg);
            out.push(')');
        }
    }
}

fn number(out: &mut String, layout: &Layout, n: Number) {
    match layout.parts(n) {
        (n, d) if d.is_one() => integer(out, n),
        (n, d) => fraction(out, n, d),
    }
}

/// `\frac{n}{d}`.
fn fraction(out: &mut String, n: Integer, d: Integer) {
    out.push_str(r"\frac{");
    integer(out, n);
    out.push_str("}{");
    integer(out, d);
    out.push('}');
}

/// A factor inside a product or under an exponent: sums, products and fractions get
/// parentheses, which grow around a fraction.
fn factor(out: &mut String, layout: &Layout, id: NodeId) {
    match layout.node(id) {
        Node::Symbol(s) => out.push_str(latex_of(*s)),
        Node::Sum(_) | Node::Product(_) | Node::Number(_) if grows(layout, id) => {
            out.push_str(r"\left(");
            node(out, layout, id);
            out.push_str(r"\right)");
        }
        Node::Sum(_) | Node::Product(_) => {
            out.push('(');
            node(out, layout, id);
            out.push(')');
        }
        other => compound(out, layout, other),
    }
}

/// Factors separated by spaces, after whatever `out` already holds of the same product. The
/// space is a thin one, `\,`, beside a name of several letters (`F_2\,\Delta t\,b`, never
/// `F_2 \Delta t b`), and after a function whose argument has no parentheses unless another
/// function follows (`\sin\beta\, L`, not `\sin\beta L`, which reads as the sine of βL;
/// `\sin\beta \cos\beta`).
fn factors(out: &mut String, layout: &Layout, mut separate: bool, span: Span) {
    let mut previous = None;
    for &(_, f) in layout.entries(span) {
        if separate {
            let thin = previous.is_some_and(|p| {
                is_long_name(layout, p)
                    || is_long_name(layout, f)
                    || (is_function(layout, p, true) && !is_function(layout, f, false))
            });
            out.push_str(if thin { r"\," } else { " " });
        }
        factor(out, layout, f);
        separate = true;
        previous = Some(f);
    }
}

/// A symbol (or a power of one) printed as several letters: `\Delta t`, `\mathit{Lb}`.
fn is_long_name(layout: &Layout, id: NodeId) -> bool {
    match layout.node(id) {
        Node::Power(base, _) => is_long_name(layout, *base),
        Node::Symbol(s) => reads_as_several_letters(latex_of(*s)),
        _ => false,
    }
}

/// A function written with its name, `\sin\beta` or `\sin^2\beta`; with `bare_argument`,
/// only one whose argument is a symbol without parentheses.
fn is_function(layout: &Layout, id: NodeId, bare_argument: bool) -> bool {
    match layout.node(id) {
        Node::Power(base, _) => is_function(layout, *base, bare_argument),
        Node::Function(Func::Abs, _) => false,
        Node::Function(_, arg) => !bare_argument || matches!(layout.node(*arg), Node::Symbol(_)),
        _ => false,
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
    if p.denominator.is_empty() {
        if !cd.is_one() {
            fraction(out, cn, cd);
        } else if shown {
            integer(out, cn);
        }
        factors(out, layout, !cd.is_one() || shown, p.numerator);
        return;
    }
    out.push_str(r"\frac{");
    if shown {
        integer(out, cn);
    }
    fraction_part(out, layout, shown, p.numerator);
    out.push_str("}{");
    if !cd.is_one() {
        integer(out, cd);
    }
    fraction_part(out, layout, !cd.is_one(), p.denominator);
    out.push('}');
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::{Axis, Expr, Q};

    fn printed(q: Q) -> String {
        let mut layout = Layout::default();
        let (negative, root) = layout.present(&Expr::num(q), Axis::X);
        let mut out = String::new();
        render(&mut out, &layout, negative, root);
        out
    }

    #[test]
    fn numbers_of_any_width() {
        for n in [0, 7, 9, 10, 123, -4, i64::MAX] {
            assert_eq!(printed(Q::int(n)), n.to_string());
        }
        assert_eq!(printed(Q::new(-12, 7).unwrap()), r"-\frac{12}{7}");
    }
}
