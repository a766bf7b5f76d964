//! Checking a hand derivation: a claim `lhs = rhs` decided against what the mechanics
//! derives (`holds`, `differs`, `undecided`), and a `differs` diagnosed term by term.

pub mod context;
pub mod diagnosis;
pub mod dimension;
pub mod report;
pub mod second_opinion;
pub mod verdict;
