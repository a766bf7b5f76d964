//! LaTeX as a textbook writes it: `I_x \omega_x - I_{xy} \omega_y`, `\frac{1}{2} m v^2`,
//! `\frac{6 F \Delta t}{m b}`, `-(I_y - I_z) \omega_y \omega_z`, `\sin\beta`, `\sqrt{x}`,
//! with no redundant parentheses or braces and never `a + -b`.

use super::layout::{Layout, Product};
use crate::algebra::{Func, Q};
use std::fmt::Write;

/// Renders a signed layout.
pub fn render(negative: bool, layout: &Layout) -> String {
    let mut out = String::with_capacity(256);
    let grouped = negative && matches!(layout, Layout::Sum(_));
    if negative {
        out.push('-');
    }
    if grouped {
        out.push('(');
    }
    node(&mut out, layout);
    if grouped {
        out.push(')');
    }
    out
}

fn node(out: &mut String, layout: &Layout) {
    match layout {
        Layout::Number(q) => number(out, q),
        Layout::Symbol(s) => out.push_str(s.latex()),
        Layout::Sum(terms) => {
            for (i, (negative, term)) in terms.iter().enumerate() {
                out.push_str(match (i, negative) {
                    (0, true) => "-",
                    (0, false) => "",
                    (_, true) => " - ",
                    (_, false) => " + ",
                });
                node(out, term);
            }
        }
        Layout::Product(p) => product(out, p),
        Layout::Power(base, exponent) => match &**base {
            Layout::Function(f, arg) => {
                function_name(out, *f);
                superscript(out, exponent);
                function_argument(out, arg);
            }
            b => {
                factor(out, b);
                superscript(out, exponent);
            }
        },
        Layout::SquareRoot(inner) => {
            out.push_str(r"\sqrt{");
            node(out, inner);
            out.push('}');
        }
        Layout::Function(Func::Abs, arg) => {
            out.push_str(r"\left|");
            node(out, arg);
            out.push_str(r"\right|");
        }
        Layout::Function(f, arg) => {
            function_name(out, *f);
            function_argument(out, arg);
        }
    }
}

/// `^e` for an exponent of one character, `^{...}` otherwise.
fn superscript(out: &mut String, exponent: &Layout) {
    out.push('^');
    let start = out.len();
    node(out, exponent);
    if out[start..].chars().count() != 1 {
        out.insert(start, '{');
        out.push('}');
    }
}

fn function_name(out: &mut String, f: Func) {
    out.push('\\');
    out.push_str(f.name());
}

/// `\sin\beta`, `\sin x`, `\sin(\beta + \theta)`.
fn function_argument(out: &mut String, arg: &Layout) {
    match arg {
        Layout::Symbol(s) => {
            if !s.latex().starts_with('\\') {
                out.push(' ');
            }
            out.push_str(s.latex());
        }
        other => {
            out.push('(');
            node(out, other);
            out.push(')');
        }
    }
}

fn number(out: &mut String, q: &Q) {
    if q.is_integer() {
        integer(out, q);
    } else {
        fraction(out, &q.numer(), &q.denom());
    }
}

/// `\frac{n}{d}`.
fn fraction(out: &mut String, n: &Q, d: &Q) {
    out.push_str(r"\frac{");
    integer(out, n);
    out.push_str("}{");
    integer(out, d);
    out.push('}');
}

/// An integer-valued rational in decimal digits.
fn integer(out: &mut String, q: &Q) {
    match q.to_i64().and_then(|n| u8::try_from(n).ok()) {
        Some(digit @ 0..=9) => out.push(char::from(b'0' + digit)),
        // Formatting into a `String` cannot fail.
        _ => {
            let _ = write!(out, "{q}");
        }
    }
}

/// A factor inside a product or under an exponent: sums and products get parentheses.
fn factor(out: &mut String, layout: &Layout) {
    match layout {
        Layout::Sum(_) | Layout::Product(_) => {
            out.push('(');
            node(out, layout);
            out.push(')');
        }
        Layout::Number(q) if !q.is_integer() => {
            out.push('(');
            number(out, q);
            out.push(')');
        }
        other => node(out, other),
    }
}

/// Factors separated by spaces, after whatever `out` already holds of the same product.
fn factors(out: &mut String, mut separate: bool, layouts: &[Layout]) {
    for f in layouts {
        if separate {
            out.push(' ');
        }
        factor(out, f);
        separate = true;
    }
}

/// Above or below a fraction bar, which groups on its own: a lone sum needs no parentheses.
fn fraction_part(out: &mut String, after_number: bool, layouts: &[Layout]) {
    match layouts {
        [alone] if !after_number => node(out, alone),
        _ => factors(out, after_number, layouts),
    }
}

fn product(out: &mut String, p: &Product) {
    let (cn, cd) = (p.coefficient.numer(), p.coefficient.denom());
    let shown = !cn.is_one() || p.numerator.is_empty();
    if p.denominator.is_empty() {
        if !cd.is_one() {
            fraction(out, &cn, &cd);
        } else if shown {
            integer(out, &cn);
        }
        factors(out, !cd.is_one() || shown, &p.numerator);
        return;
    }
    out.push_str(r"\frac{");
    if shown {
        integer(out, &cn);
    }
    fraction_part(out, shown, &p.numerator);
    out.push_str("}{");
    if !cd.is_one() {
        integer(out, &cd);
    }
    fraction_part(out, !cd.is_one(), &p.denominator);
    out.push('}');
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_of_any_width() {
        for n in [0, 7, 9, 10, 123, -4, i64::MAX] {
            assert_eq!(render(false, &Layout::Number(Q::int(n))), n.to_string());
        }
        let q = Q::new(12, 7).unwrap();
        assert_eq!(render(true, &Layout::Number(q)), r"-\frac{12}{7}");
    }
}
