//! Expressions generated from the grammar people type (`grammar/expr.pest`): symbols,
//! numbers, unit vectors, `+ - * / ^`, juxtaposition, `sin cos tan sqrt abs`, parentheses
//! and equations, with hostile numbers, exponents and constructs ([`crate::hostile`]) mixed
//! in. Most of what comes out is well formed, so the work after parsing is exercised too.

use crate::hostile;
use crate::random::Random;

const SYMBOLS: [&str; 14] = [
    "a", "b", "c", "m", "r", "v", "t", "w_x", "w_y", "I_xy", "I_z", "alpha", "Dt", "wdot_z",
];
const UNIT_VECTORS: [&str; 3] = ["i", "j", "k"];
const FUNCTIONS: [&str; 6] = ["sin", "cos", "tan", "sqrt", "abs", "f"];
const OPERATORS: [&str; 6] = ["+", "-", "*", "/", " ", "^"];

/// An expression, or now and then an equation `lhs = rhs` or one of issue 29's shapes
/// ([`hostile::Shape`]), with a control character inside now and then.
pub fn statement(r: &mut Random) -> String {
    if r.one_in(8) {
        return hostile::any_shape(r);
    }
    if r.one_in(16) {
        let e = expression(r, 3, atom);
        let at = (0..=e.len()).filter(|&i| e.is_char_boundary(i)).count();
        let at = e
            .char_indices()
            .nth(r.below(at))
            .map_or(e.len(), |(i, _)| i);
        return format!("{}{}{}", &e[..at], hostile::control(r), &e[at..]);
    }
    let depth = r.size(8);
    let e = expression(r, depth, atom);
    if r.one_in(6) {
        format!("{} = {e}", expression(r, 2, atom))
    } else {
        e
    }
}

/// An expression of at most `depth` levels over the leaves `atom` gives (a claim's names
/// for `check`, else symbols, unit vectors and numbers).
pub fn expression(r: &mut Random, depth: usize, atom: fn(&mut Random) -> String) -> String {
    if depth == 0 {
        return atom(r);
    }
    let d = depth - 1;
    match r.below(10) {
        0..=3 => {
            let op = *r.pick(&OPERATORS);
            let right = if op == "^" {
                power_exponent(r)
            } else {
                expression(r, d, atom)
            };
            format!("{}{op}{right}", expression(r, d, atom))
        }
        4 => format!("({})", expression(r, d, atom)),
        5 => format!("{}({})", r.pick(&FUNCTIONS), expression(r, d, atom)),
        6 => format!("-{}", expression(r, d, atom)),
        7 => format!("({})^{}", expression(r, d, atom), power_exponent(r)),
        8 if r.one_in(4) => hostile::construct(r),
        _ => atom(r),
    }
}

fn power_exponent(r: &mut Random) -> String {
    if r.one_in(3) {
        hostile::exponent(r)
    } else {
        r.pick(&["2", "3", "-1", "(1/2)", "n", "10"]).to_string()
    }
}

/// A symbol, a unit vector, a hostile number or a small integer.
fn atom(r: &mut Random) -> String {
    match r.below(8) {
        0..=3 => r.pick(&SYMBOLS).to_string(),
        4 => r.pick(&UNIT_VECTORS).to_string(),
        5 => hostile::number(r),
        _ => (1 + r.below(12)).to_string(),
    }
}
