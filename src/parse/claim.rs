//! A claim: an equation `lhs = rhs` as a person types it in a hand derivation, read for
//! `kinetics check`. Beyond an expression it has the cross product (`×`, `cross(a, b)`, and
//! ` x ` between two vectors) and names the checker resolves to derived quantities (`T`,
//! `H_O`) while it is read, so that `r × m vbar` is formed from their vectors. Each side keeps
//! its top-level terms with the text they were read from, so that a report can name the term
//! the user wrote.

use crate::algebra::Expr;

/// One top-level term of a side, with its sign, and the byte span of its text (the sign
/// included) in the claim.
#[derive(Debug, Clone, PartialEq)]
pub struct WrittenTerm {
    pub value: Expr,
    pub span: (usize, usize),
}

/// One side of a claim: its value (derived names resolved, cross products formed), the
/// span of its text, its top-level terms as written, and the derived names it uses.
#[derive(Debug, Clone, PartialEq)]
pub struct ClaimSide {
    pub value: Expr,
    pub span: (usize, usize),
    pub terms: Vec<WrittenTerm>,
    /// Names the resolver gave a value for, in the order first written, each once.
    pub resolved: Vec<String>,
}

/// A claim `lhs = rhs`.
#[derive(Debug, Clone, PartialEq)]
pub struct Claim {
    pub lhs: ClaimSide,
    pub rhs: ClaimSide,
}

/// What a name in a claim stands for, as the checker's context says.
#[derive(Debug, Clone, PartialEq)]
pub enum Name {
    /// A symbol of its own (a given, a coordinate): lowered as `Expr::symbol`.
    Symbol,
    /// A derived quantity: lowered as this value (a scalar, or a vector `a i + b j + c k`).
    Derived(Expr),
    /// Not known in this context: an error at the name, with this help (a suggestion).
    Unknown(String),
}
