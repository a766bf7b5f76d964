//! LaTeX as a textbook writes it: `I_x \omega_x - I_{xy} \omega_y`, `\frac{1}{2} m v^2`,
//! `\frac{6 F \Delta t}{m b}`, `-(I_y - I_z) \omega_y \omega_z`, `\sin\beta`, `\sqrt{x}`,
//! with no redundant parentheses or braces and never `a + -b`.

use super::layout::{Layout, Product};
use crate::algebra::{Func, Q};

/// Renders a signed layout.
pub fn render(negative: bool, layout: &Layout) -> String {
    let body = node(layout);
    if negative {
        match layout {
            Layout::Sum(_) => format!("-({body})"),
            _ => format!("-{body}"),
        }
    } else {
        body
    }
}

fn node(layout: &Layout) -> String {
    match layout {
        Layout::Number(q) => number(q),
        Layout::Symbol(s) => s.latex().to_string(),
        Layout::Sum(terms) => {
            let mut out = String::new();
            for (i, (negative, term)) in terms.iter().enumerate() {
                match (i, negative) {
                    (0, true) => out.push('-'),
                    (0, false) => {}
                    (_, true) => out.push_str(" - "),
                    (_, false) => out.push_str(" + "),
                }
                out.push_str(&node(term));
            }
            out
        }
        Layout::Product(p) => product(p),
        Layout::Power(base, exponent) => {
            let e = node(exponent);
            let e = if e.chars().count() == 1 {
                e
            } else {
                format!("{{{e}}}")
            };
            match &**base {
                Layout::Function(f, arg) => {
                    format!("{}^{e}{}", function_name(*f), function_argument(arg))
                }
                b => format!("{}^{e}", factor(b)),
            }
        }
        Layout::SquareRoot(inner) => format!(r"\sqrt{{{}}}", node(inner)),
        Layout::Function(Func::Abs, arg) => format!(r"\left|{}\right|", node(arg)),
        Layout::Function(f, arg) => format!("{}{}", function_name(*f), function_argument(arg)),
    }
}

fn function_name(f: Func) -> String {
    format!(r"\{}", f.name())
}

/// `\sin\beta`, `\sin x`, `\sin(\beta + \theta)`.
fn function_argument(arg: &Layout) -> String {
    match arg {
        Layout::Symbol(s) if s.latex().starts_with('\\') => s.latex().to_string(),
        Layout::Symbol(s) => format!(" {}", s.latex()),
        other => format!("({})", node(other)),
    }
}

fn number(q: &Q) -> String {
    if q.is_integer() {
        q.to_string()
    } else {
        format!(r"\frac{{{}}}{{{}}}", q.numer(), q.denom())
    }
}

/// A factor inside a product or under an exponent: sums and products get parentheses.
fn factor(layout: &Layout) -> String {
    match layout {
        Layout::Sum(_) | Layout::Product(_) => format!("({})", node(layout)),
        Layout::Number(q) if !q.is_integer() => format!("({})", number(q)),
        other => node(other),
    }
}

fn product(p: &Product) -> String {
    let (cn, cd) = (p.coefficient.numer(), p.coefficient.denom());
    let numerator: Vec<String> = p.numerator.iter().map(factor).collect();
    if p.denominator.is_empty() {
        let mut parts = Vec::new();
        if !cd.is_one() {
            parts.push(format!(r"\frac{{{cn}}}{{{cd}}}"));
        } else if !cn.is_one() || numerator.is_empty() {
            parts.push(cn.to_string());
        }
        parts.extend(numerator);
        return parts.join(" ");
    }
    let mut top = Vec::new();
    if !cn.is_one() || numerator.is_empty() {
        top.push(cn.to_string());
    }
    // A fraction bar groups on its own: a lone sum above or below it needs no parentheses.
    let alone = |parts: &[Layout], number_is_one: bool| number_is_one && parts.len() == 1;
    if alone(&p.numerator, top.is_empty()) {
        top.push(node(&p.numerator[0]));
    } else {
        top.extend(numerator);
    }
    let mut bottom = Vec::new();
    if !cd.is_one() {
        bottom.push(cd.to_string());
    }
    if alone(&p.denominator, bottom.is_empty()) {
        bottom.push(node(&p.denominator[0]));
    } else {
        bottom.extend(p.denominator.iter().map(factor));
    }
    format!(r"\frac{{{}}}{{{}}}", top.join(" "), bottom.join(" "))
}
