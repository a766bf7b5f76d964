//! Terms named in words for an explanation: `a`, `a and b`, `a, b and c`, each in ASCII
//! (the `Display` of `Expr`) between backticks, so that a report can typeset each as
//! mathematics (it reads back); a long list names its first few and counts the rest, so an
//! explanation stays a sentence whatever the claim.

use crate::algebra::Expr;

/// How many terms a list names before it counts the rest.
const MAX_NAMED: usize = 6;

/// One expression as an explanation names it: its ASCII between backticks.
pub(super) fn term(e: impl std::fmt::Display) -> String {
    format!("`{e}`")
}

/// The terms as a list in words (module documentation).
pub(super) fn list<'a>(terms: impl IntoIterator<Item = &'a Expr>) -> String {
    let terms: Vec<&Expr> = terms.into_iter().collect();
    let named: Vec<String> = terms.iter().take(MAX_NAMED).map(term).collect();
    let rest = terms.len() - named.len();
    match (named.as_slice(), rest) {
        ([], _) => String::new(),
        ([only], 0) => only.clone(),
        ([init @ .., last], 0) => format!("{} and {last}", init.join(", ")),
        (all, rest) => format!("{} and {rest} more", all.join(", ")),
    }
}

/// `term` for one item, `terms` for several: "the sign of a", "the signs of a and b".
pub(super) fn plural(count: usize, one: &'static str, several: &'static str) -> &'static str {
    if count == 1 {
        one
    } else {
        several
    }
}
