//! The readings of presence: the claim has every term it writes right, and
//!
//! ```text
//! missing-term  only leaves terms out
//! extra-term    only adds terms the correct form does not have
//! ```

use super::comparison::Differences;
use super::words::{list, plural};

/// `missing-term`: the only differences are terms missing from the claim.
pub(super) fn missing_term(d: &Differences) -> Option<String> {
    if d.missing.is_empty() || !d.wrong.is_empty() || !d.extra.is_empty() {
        return None;
    }
    let n = d.missing.len();
    Some(format!(
        "{} {} {} missing",
        plural(n, "the term", "the terms"),
        list(&d.missing),
        plural(n, "is", "are"),
    ))
}

/// `extra-term`: the only differences are terms the correct form does not have.
pub(super) fn extra_term(d: &Differences) -> Option<String> {
    if d.extra.is_empty() || !d.wrong.is_empty() || !d.missing.is_empty() {
        return None;
    }
    let n = d.extra.len();
    Some(format!(
        "{} {} {} not in the correct form",
        plural(n, "the term", "the terms"),
        list(&d.extra),
        plural(n, "is", "are"),
    ))
}
