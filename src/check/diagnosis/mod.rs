//! The diagnosis of a claim that differs: the claimed expression against the correct one,
//! term by term (wrong, missing, extra), and a named reading of the slip when one fits.

use crate::algebra::{AlgebraError, Expr};

mod coefficient_rules;
mod common_denominator;
mod comparison;
mod presence_rules;
mod product_sign;
mod rules;
mod sin_for_cos;
mod subscript_maps;
mod subscript_rules;
mod words;

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

/// The names of the readings, in the order the rules are tried (the table of `rules.rs`):
/// the more specific first, so that a gyroscopic term with its moments' difference reversed
/// reads as `cyclic-order`, not as two signs flipped, and a flipped product of inertia as
/// `product-sign-convention`, not as the whole side scaled by -1.
pub const READINGS: [&str; 10] = rules::names();

/// What differs between a claimed expression and the correct one.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnosis {
    pub wrong: Vec<WrongTerm>,
    pub missing: Vec<Expr>,
    pub extra: Vec<Expr>,
    pub reading: Option<Reading>,
}

/// What differs between `claimed` and `correct` (two scalar expressions, any form: they are
/// brought to single angles and comparable sums of terms here, `common_denominator.rs`), term by term
/// (`comparison.rs`), and the first reading of the rule table that fits (`rules.rs`).
/// Never panics; an expression beyond the algebra's bounds gives its `AlgebraError`.
///
/// ```
/// use kinetics::check::diagnosis::diagnose;
/// use kinetics::parse_expression;
/// let claimed = parse_expression("", "I_x*w_x - I_xy*w_y + I_xz*w_z").unwrap();
/// let correct = parse_expression("", "I_x*w_x - I_xy*w_y - I_xz*w_z").unwrap();
/// let diagnosis = diagnose(&claimed, &correct).unwrap();
/// assert_eq!(diagnosis.wrong.len(), 1);
/// assert_eq!(diagnosis.reading.unwrap().name, "product-sign-convention");
/// ```
pub fn diagnose(claimed: &Expr, correct: &Expr) -> Result<Diagnosis, AlgebraError> {
    // In single angles, so that `½ sin 2θ` for `sin θ cos θ` is one term, not one missing
    // and one extra.
    let (claimed, correct) = (
        claimed.double_angles_multiplied_out()?,
        correct.double_angles_multiplied_out()?,
    );
    let (claimed, correct) = common_denominator::comparable_sums(&claimed, &correct)?;
    let differences = comparison::Differences::between(&claimed, &correct);
    let reading = rules::first_reading(&differences);
    Ok(differences.into_diagnosis(reading))
}
