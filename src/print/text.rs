//! Plain ASCII text that the parser reads back to the same canonical form:
//! `I_x*w_x - I_xy*w_y`, `1/2*m*v^2`, `6*F*Dt/(m*b)`, `-(I_y - I_z)*w_y*w_z`,
//! `sin(beta)`, `sqrt(x)`.

use super::layout::{Layout, Product};

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
        Layout::Number(q) => q.to_string(),
        Layout::Symbol(s) => s.name().to_string(),
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
            let e = match &**exponent {
                Layout::Number(q) if q.is_integer() => q.to_string(),
                other => format!("({})", node(other)),
            };
            let base = match &**base {
                Layout::Power(..) => format!("({})", node(base)),
                other => factor(other),
            };
            format!("{base}^{e}")
        }
        Layout::SquareRoot(inner) => format!("sqrt({})", node(inner)),
        Layout::Function(f, arg) => format!("{}({})", f.name(), node(arg)),
    }
}

/// A factor inside a product or under an exponent.
fn factor(layout: &Layout) -> String {
    match layout {
        Layout::Sum(_) | Layout::Product(_) => format!("({})", node(layout)),
        Layout::Number(q) if !q.is_integer() => format!("({q})"),
        other => node(other),
    }
}

fn product(p: &Product) -> String {
    let (cn, cd) = (p.coefficient.numer(), p.coefficient.denom());
    let mut top: Vec<String> = Vec::new();
    if p.denominator.is_empty() {
        if !cd.is_one() {
            top.push(format!("{cn}/{cd}"));
        } else if !cn.is_one() || p.numerator.is_empty() {
            top.push(cn.to_string());
        }
        top.extend(p.numerator.iter().map(factor));
        return top.join("*");
    }
    if !cn.is_one() || p.numerator.is_empty() {
        top.push(cn.to_string());
    }
    top.extend(p.numerator.iter().map(factor));
    let mut bottom: Vec<String> = Vec::new();
    if !cd.is_one() {
        bottom.push(cd.to_string());
    }
    bottom.extend(p.denominator.iter().map(factor));
    let bottom = if bottom.len() == 1 {
        bottom.remove(0)
    } else {
        format!("({})", bottom.join("*"))
    };
    format!("{}/{}", top.join("*"), bottom)
}
