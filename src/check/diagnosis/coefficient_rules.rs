//! The readings of coefficients: every term is in the claim and the correct form alike,
//! only coefficients differ. With `kᵢ = claimed coefficient / correct coefficient` of the
//! differing terms:
//!
//! ```text
//! scaled        every term differs, all kᵢ = k      claimed = k · correct  (k ≠ 1, two
//!                                                   terms or more: one is sign or factor)
//! sign-flipped  every kᵢ = −1                       a few signs flipped
//! factor-off    one term differs, k ≠ ±1            that term k times what it should be
//! ```

use super::comparison::Differences;
use super::words::{list, plural, term};
use crate::algebra::Q;

/// `scaled`: the claim is `k` times the correct form, `k` rational and not 1 (`2T = …`
/// written as `T = …`, the whole side's sign wrong).
pub(super) fn scaled(d: &Differences) -> Option<String> {
    // A side of one term off by a factor is that term's sign or factor, not a scaled side.
    if !d.only_wrong() || d.wrong.len() != d.correct_terms || d.wrong.len() < 2 {
        return None;
    }
    let k = d.wrong[0].ratio()?;
    if !d.wrong.iter().all(|w| w.ratio().as_ref() == Some(&k)) {
        return None;
    }
    Some(if k == Q::MINUS_ONE {
        "the whole side has the wrong sign: it is -1 times the correct one".to_string()
    } else {
        format!("the whole side is {k} times the correct one")
    })
}

/// `sign-flipped`: the only differences are terms written with the opposite sign.
pub(super) fn sign_flipped(d: &Differences) -> Option<String> {
    if !d.only_wrong() || !d.wrong.iter().all(|w| w.ratio() == Some(Q::MINUS_ONE)) {
        return None;
    }
    let n = d.wrong.len();
    Some(format!(
        "{} {} {} flipped (the correct {} {})",
        plural(n, "the sign of", "the signs of"),
        list(d.wrong.iter().map(|w| &w.claimed)),
        plural(n, "is", "are"),
        plural(n, "term is", "terms are"),
        list(d.wrong.iter().map(|w| &w.correct)),
    ))
}

/// `factor-off`: one term is `k` times what it should be (`k ≠ ±1`: ½, 2, …), the rest
/// right.
pub(super) fn factor_off(d: &Differences) -> Option<String> {
    let [w] = d.wrong.as_slice() else {
        return None;
    };
    if !d.only_wrong() {
        return None;
    }
    let k = w.ratio()?;
    if k == Q::MINUS_ONE {
        return None;
    }
    Some(format!(
        "the term {} is {k} times the correct one (the correct term is {})",
        term(&w.claimed),
        term(&w.correct)
    ))
}
