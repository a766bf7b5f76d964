//! The reading `product-sign-convention`: products of inertia written with the opposite
//! sign. The chapter's products are positive integrals, `I_xy = ∫xy dm`, and its tensor has
//! them negated off the diagonal (`H_x = I_x ω_x − I_xy ω_y − I_xz ω_z`); a claim built on
//! the other convention has `+I_xy ω_y`. With `C` and `K` the sums of the differing claimed
//! and correct terms:
//!
//! ```text
//! every differing term holds a product of inertia P (base I, two axis letters),
//! and C with every P replaced by −P is K
//! ```

use super::comparison::Differences;
use super::subscript_maps::substitute;
use super::words::{list, plural};
use crate::algebra::{Expr, Symbol};

/// `product-sign-convention` (module documentation).
pub(super) fn product_sign_convention(d: &Differences) -> Option<String> {
    let (claimed, correct) = d.sides()?;
    let every_term_holds_one = d
        .claimed_differing()
        .chain(d.correct_differing())
        .all(|term| term.has_symbol_where(&is_product_of_inertia));
    if !every_term_holds_one {
        return None;
    }
    let products: Vec<Symbol> = claimed
        .symbols()
        .into_iter()
        .filter(|&s| is_product_of_inertia(s))
        .collect();
    let negated: Vec<(Symbol, Expr)> = products.iter().map(|&p| (p, -Expr::sym(p))).collect();
    if substitute(claimed, &negated).ok().as_ref() != Some(correct) {
        return None;
    }
    let named: Vec<Expr> = products.iter().map(|&p| -Expr::sym(p)).collect();
    let claimed_terms: Vec<&Expr> = d.claimed_differing().collect();
    let correct_terms: Vec<&Expr> = d.correct_differing().collect();
    let n = products.len();
    Some(format!(
        "{} in {} {} the wrong sign: the chapter's inertia tensor has {} off the diagonal \
         (the correct {} {})",
        plural(n, "the product of inertia", "the products of inertia"),
        list(claimed_terms.iter().copied()),
        plural(n, "has", "have"),
        list(&named),
        plural(correct_terms.len(), "term is", "terms are"),
        list(correct_terms.iter().copied()),
    ))
}

/// `I_xy`, `I_yz`, `I_xz` (and `I_yx` …): base `I`, a subscript of two different axes.
fn is_product_of_inertia(s: Symbol) -> bool {
    let axes = s.subscript().as_bytes();
    s.base() == "I"
        && axes.len() == 2
        && axes[0] != axes[1]
        && axes.iter().all(|a| matches!(a, b'x' | b'y' | b'z'))
}
