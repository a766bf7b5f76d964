//! The readings of subscripts: the differing claimed terms are the correct ones with their
//! subscripts changed. With `C` the sum of the differing claimed terms and `K` that of the
//! correct ones:
//!
//! ```text
//! cyclic-order        terms c I_a X and −c I_b X both flipped: (I_b − I_a) X for (I_a − I_b) X
//!                     (the gyroscopic term of Euler's equations, its moments' difference
//!                     reversed); or σ(C) = K for σ = x→y→z→x or its inverse, σ moving at
//!                     least two symbols of C (one moved symbol is a swap)
//! swapped-subscripts  C with s ↔ t is K, s and t one stem, different subscripts
//! repeated-term       a term n times its correct coefficient (n ≥ 2), the n − 1 missing
//!                     terms its images under permutations of the axes
//! ```
//!
//! Bounded: two cycles, at most `MAX_SWAP_SYMBOLS²` transpositions and five permutations
//! per missing term are tried, each on the few differing terms (`comparison.rs`).

use super::comparison::Differences;
use super::subscript_maps::{stem, transpose, AxisPermutation};
use super::words::{list, term};
use crate::algebra::{Expr, Symbol, Q};

/// Most distinct symbols on either side whose pairs are tried as swaps.
const MAX_SWAP_SYMBOLS: usize = 16;

/// `cyclic-order`: the moments' difference of a gyroscopic term reversed, or the axis
/// subscripts of the differing terms permuted cyclically (module documentation).
pub(super) fn cyclic_order(d: &Differences) -> Option<String> {
    reversed_difference(d).or_else(|| permuted_cyclically(d))
}

/// Pairs `c I_a X`, `−c I_b X` of flipped terms, and nothing else different.
fn reversed_difference(d: &Differences) -> Option<String> {
    if !d.only_wrong() || d.sides().is_none() {
        return None;
    }
    let mut terms: Vec<(Expr, Symbol, &Q)> = Vec::new();
    for w in &d.wrong {
        if w.ratio() != Some(Q::MINUS_ONE) {
            return None;
        }
        let [moment] = principal_moments(&w.correct)[..] else {
            return None;
        };
        let rest = Expr::mul_all(
            w.correct
                .monomial()
                .iter()
                .filter(|f| f.as_symbol() != Some(moment))
                .cloned(),
        );
        terms.push((rest, moment, w.correct.coefficient()));
    }
    let mut reversed = Vec::new();
    for (i, (rest, moment, k)) in terms.iter().enumerate() {
        let partners: Vec<_> = terms
            .iter()
            .enumerate()
            .filter(|(j, other)| *j != i && other.0 == *rest)
            .collect();
        let [(_, (_, other, other_k))] = partners[..] else {
            return None;
        };
        if other == moment || &-*k != *other_k {
            return None;
        }
        // Each pair once, written from its moment with the negative coefficient, as the
        // chapter writes −(I_y − I_z) ω_y ω_z.
        if k.is_negative() {
            reversed.push(format!(
                "{} where the correct form has {}",
                difference(k, *other, *moment, rest),
                difference(k, *moment, *other, rest),
            ));
        }
    }
    Some(format!(
        "the difference of the moments of inertia is reversed: {}",
        reversed.join("; ")
    ))
}

/// `k (I_a − I_b) X` in ASCII: `-(I_y - I_z)*w_y*w_z`.
fn difference(k: &Q, a: Symbol, b: Symbol, rest: &Expr) -> String {
    let factor = match k {
        k if k.is_one() => String::new(),
        k if *k == Q::MINUS_ONE => "-".to_string(),
        k => format!("{k}*"),
    };
    let rest = if rest.is_one() {
        String::new()
    } else {
        format!("*{rest}")
    };
    term(format!("{factor}({a} - {b}){rest}"))
}

/// The principal moments (`I_x`, `I_y`, `I_z`: base `I`, one axis subscript) that are
/// factors of a term, to the first power.
fn principal_moments(term: &Expr) -> Vec<Symbol> {
    term.monomial()
        .iter()
        .filter_map(Expr::as_symbol)
        .filter(|s| s.base() == "I" && s.axis().is_some())
        .collect()
}

/// `σ(C) = K` for one of the two cycles, `σ` moving at least two symbols of `C`.
fn permuted_cyclically(d: &Differences) -> Option<String> {
    let (claimed, correct) = d.sides()?;
    let (_, inverse) = [
        (AxisPermutation::CYCLIC, AxisPermutation::ANTICYCLIC),
        (AxisPermutation::ANTICYCLIC, AxisPermutation::CYCLIC),
    ]
    .into_iter()
    .find(|(sigma, _)| {
        sigma.moved_symbols(claimed) >= 2 && sigma.apply(claimed).ok().as_ref() == Some(correct)
    })?;
    Some(format!(
        "the axes are in the wrong cyclic order: {} is the correct {} with its \
         subscripts taken {}",
        term(claimed),
        term(correct),
        inverse.describe()
    ))
}

/// `swapped-subscripts`: exchanging two symbols of one stem (`I_xz`, `I_yz`) turns the
/// differing claimed terms into the correct ones.
pub(super) fn swapped_subscripts(d: &Differences) -> Option<String> {
    let (claimed, correct) = d.sides()?;
    let (in_claimed, in_correct) = (claimed.symbols(), correct.symbols());
    if in_claimed.len() > MAX_SWAP_SYMBOLS || in_correct.len() > MAX_SWAP_SYMBOLS {
        return None;
    }
    let (written, belongs) = in_claimed
        .iter()
        .flat_map(|&s| in_correct.iter().map(move |&t| (s, t)))
        .filter(|&(s, t)| {
            s != t && !s.subscript().is_empty() && !t.subscript().is_empty() && stem(s) == stem(t)
        })
        .find(|&(s, t)| transpose(claimed, s, t).ok().as_ref() == Some(correct))?;
    Some(
        if in_correct.contains(&written) || in_claimed.contains(&belongs) {
            format!("{} and {} are exchanged", term(written), term(belongs))
        } else {
            format!(
                "{} is written where {} belongs",
                term(written),
                term(belongs)
            )
        },
    )
}

/// `repeated-term`: one term written `n ≥ 2` times (its coefficient `n` times the correct
/// one) where the correct form has it and its `n − 1` images under permutations of the
/// axes (`I_x ω_x²` three times for `I_x ω_x² + I_y ω_y² + I_z ω_z²`).
pub(super) fn repeated_term(d: &Differences) -> Option<String> {
    let [w] = d.wrong.as_slice() else {
        return None;
    };
    d.sides()?; // the differing terms are within the bounds the permutations work in
    let n = w.ratio()?.to_i64()?;
    if n < 2 || !d.extra.is_empty() || d.missing.len() as i64 != n - 1 {
        return None;
    }
    let images: Vec<Expr> = AxisPermutation::NOT_IDENTITY
        .iter()
        .filter_map(|p| p.apply(&w.correct).ok())
        .collect();
    if !d.missing.iter().all(|m| images.contains(m)) {
        return None;
    }
    Some(format!(
        "{} is written {n} times where the correct form has {}",
        term(&w.correct),
        list(std::iter::once(&w.correct).chain(&d.missing))
    ))
}
