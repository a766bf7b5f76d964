//! Claims generated for `kinetics check`: `lhs = rhs`, each side a scalar expression of the
//! grammar ([`crate::generate::expression`]) over the names a claim uses — derived names
//! (`T`, `H_x`, `H_G`, `H_O`, `SumM_x`), aliases (`omega_x`, `v`), the chapter's symbols and
//! `i j k` — or a vector: `a i + b j + c k`, and products of two vectors written `×`,
//! `cross(a, b)`, ` x ` between parentheses, or `dot(a, b)`.

use crate::generate::expression;
use crate::hostile;
use crate::random::Random;

/// Names that stand for a scalar in a claim: derived, aliases and the chapter's symbols (a
/// scene knows only its own, so there most are unknown names, refused).
const SCALARS: [&str; 24] = [
    "T", "H_x", "H_y", "H_z", "SumM_x", "M_y", "Hdot_z", "omega_x", "v", "v_y", "alpha_z", "w",
    "alpha", "I_x", "I_y", "I_z", "I_xy", "I_xz", "I_yz", "w_x", "w_y", "wdot_z", "m", "r",
];
/// Names that stand for a vector.
const VECTORS: [&str; 7] = ["H_G", "H_O", "SumM", "omega", "wdot", "vbar", "rbar"];
const UNIT_VECTORS: [&str; 3] = ["i", "j", "k"];

/// A claim, one line.
pub fn claim(r: &mut Random) -> String {
    let lhs = side(r);
    let rhs = side(r);
    // Now and then a claim without `=`, or with two, as people mistype them.
    match r.below(40) {
        0 => lhs,
        1 => format!("{lhs} = {rhs} = {}", side(r)),
        _ => format!("{lhs} = {rhs}"),
    }
}

/// One side: a scalar expression, or a vector.
fn side(r: &mut Random) -> String {
    if r.one_in(3) {
        vector(r, 2)
    } else {
        let depth = r.size(5);
        expression(r, depth, scalar_atom)
    }
}

/// A vector of at most `depth` nested products.
fn vector(r: &mut Random, depth: usize) -> String {
    let d = depth.saturating_sub(1);
    match r.below(if depth == 0 { 3 } else { 8 }) {
        0 => r.pick(&VECTORS).to_string(),
        1 => components(r),
        2 => format!("{} {}", scalar(r), r.pick(&VECTORS)),
        3 => format!("({}) × ({})", vector(r, d), vector(r, d)),
        4 => format!("cross({}, {})", vector(r, d), vector(r, d)),
        5 => format!("({}) x ({})", vector(r, d), vector(r, d)),
        6 => format!("{} {} {}", vector(r, d), r.pick(&["+", "-"]), vector(r, d)),
        // A scalar written as a product of vectors: the sides then disagree in kind.
        _ => format!("dot({}, {})", vector(r, d), vector(r, d)),
    }
}

/// `a i + b j + c k`, some components left out.
fn components(r: &mut Random) -> String {
    let mut terms = Vec::new();
    for u in UNIT_VECTORS {
        if !r.one_in(3) {
            terms.push(format!("{} {u}", scalar(r)));
        }
    }
    if terms.is_empty() {
        r.pick(&UNIT_VECTORS).to_string()
    } else {
        terms.join(" + ")
    }
}

/// A short scalar factor, parenthesised.
fn scalar(r: &mut Random) -> String {
    format!("({})", expression(r, 1, scalar_atom))
}

/// A scalar name, a hostile number or a small integer.
fn scalar_atom(r: &mut Random) -> String {
    match r.below(10) {
        0..=6 => r.pick(&SCALARS).to_string(),
        7 => hostile::number(r),
        _ => (1 + r.below(4)).to_string(),
    }
}
