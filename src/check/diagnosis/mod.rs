//! The diagnosis of a claim that differs: the claimed expression against the correct one,
//! term by term (wrong, missing, extra), and a named reading of the slip when one fits.

use crate::algebra::Expr;

/// A term the claim has with another coefficient than the correct form.
#[derive(Debug, Clone, PartialEq)]
pub struct WrongTerm {
    pub claimed: Expr,
    pub correct: Expr,
}

/// A named reading of the slip (`sign-flipped`: "the sign of I_xz w_z is flipped").
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// The rule's name, one of [`READINGS`].
    pub name: &'static str,
    /// What the slip is, in words, naming the terms (plain text; expressions in ASCII).
    pub explanation: String,
}

/// The names of the readings, in the order the rules are tried.
pub const READINGS: [&str; 10] = [
    "scaled",
    "sign-flipped",
    "factor-off",
    "swapped-subscripts",
    "cyclic-order",
    "product-sign-convention",
    "sin-for-cos",
    "repeated-term",
    "missing-term",
    "extra-term",
];

/// What differs between a claimed expression and the correct one.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnosis {
    pub wrong: Vec<WrongTerm>,
    pub missing: Vec<Expr>,
    pub extra: Vec<Expr>,
    pub reading: Option<Reading>,
}
