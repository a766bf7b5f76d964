//! Checking a hand derivation: a claim `lhs = rhs` decided against what the mechanics
//! derives (`holds`, `differs`, `undecided`), and a `differs` diagnosed: by the slip of the
//! mechanics that explains it, and term by term.

pub mod context;
pub mod derivation;
pub mod diagnosis;
pub mod dimension;
pub mod forms;
pub mod report;
pub mod second_opinion;
pub mod verdict;

/// Every name a reading of a claim may have: the slips of the mechanics first (the order
/// they are tried), then the rules read from the residual, then `inhomogeneous`.
pub fn reading_names() -> Vec<&'static str> {
    let mut names: Vec<&'static str> = Vec::new();
    for name in crate::mechanics::slip::Slip::ALL.map(|s| s.name()) {
        if !names.contains(&name) {
            names.push(name);
        }
    }
    names.extend(diagnosis::READINGS);
    names.push(dimension::INHOMOGENEOUS);
    names
}
