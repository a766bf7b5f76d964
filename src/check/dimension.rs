//! Dimensions of a claim: every written term of both sides in one dimension.
//!
//! A claim `t₁ + t₂ + … = u₁ + u₂ + …` is homogeneous when `dim tᵢ = dim uⱼ = D` for every
//! written term, where `dim` multiplies in products, scales by `p/q` in a power `b^(p/q)`,
//! and asks a function's argument to have none (`units::dimension_with`). `D`, the claim's
//! dimension, is the one most terms share; a tie is decided by the side that holds a derived
//! name (its value comes from the mechanics, so its dimension is right), else by the left
//! side. A term is judged only when every symbol in it has a known dimension (`i j k` and
//! `pi` have none); a zero term is skipped. The check is made before any algebra, so that
//! `T = ½ m v² + I_x ω_x` is reported as the odd term `I_x w_x`, not as a difference.

use crate::algebra::{Expr, Func, Role, Symbol, View};
use crate::parse::claim::{Claim, ClaimSide, WrittenTerm};
use crate::scene::unit_system::UnitSystem;
use crate::scene::units::{dimension_with, Dimension, DimensionError};
use std::collections::HashMap;

/// The reading of a claim with a term of another dimension.
pub const INHOMOGENEOUS: &str = "inhomogeneous";

/// A written term whose dimension differs from the claim's.
#[derive(Debug, Clone, PartialEq)]
pub struct OddTerm {
    /// The term as written: the source text of `span` (a leading `+` and blanks left out).
    pub text: String,
    pub span: (usize, usize),
    /// None when the term is inconsistent in itself (`(m + w_x) v`, `sin(w_x)`).
    pub dimension: Option<Dimension>,
    /// The claim's dimension (no unit when no term has one).
    pub expected: Dimension,
    /// Why, in words: "is in kg·m²/s where the other terms are in kg·m²/s²", or "the
    /// argument of sin must have no unit, but w_x is in rad/s".
    pub reason: String,
}

/// What the dimension check says of one written term.
enum Judgement {
    /// Zero, or holding a symbol of unknown dimension.
    NotJudged,
    Has(Dimension),
    Inconsistent(DimensionError),
}

/// The first odd term of `claim` in writing order (left side, then right), or None when
/// every judged term has the claim's dimension. `source` is the text the spans index;
/// `dimension_of_symbol` gives a symbol's dimension, None when unknown (a free symbol: a
/// term holding one is not judged). Linear in the claim's size.
pub fn odd_term(
    claim: &Claim,
    source: &str,
    dimension_of_symbol: &dyn Fn(Symbol) -> Option<Dimension>,
) -> Option<OddTerm> {
    odd_term_in(claim, source, dimension_of_symbol, UnitSystem::Si)
}

/// [`odd_term`] with the dimensions in its reason named in `system`'s units (lb, lb·ft on a
/// scene in U.S. units).
pub fn odd_term_in(
    claim: &Claim,
    source: &str,
    dimension_of_symbol: &dyn Fn(Symbol) -> Option<Dimension>,
    system: UnitSystem,
) -> Option<OddTerm> {
    let unit = |d: Dimension| match system.unit(d, false).to_string() {
        named if named.is_empty() => "no unit".to_string(),
        named => named,
    };
    let known = |s: Symbol| {
        if s.role() == Role::UnitVector || s.is_pi() {
            Some(Dimension::NONE)
        } else {
            dimension_of_symbol(s)
        }
    };
    let judge_side = |side: &ClaimSide| -> Vec<Judgement> {
        side.terms.iter().map(|t| judge(&t.value, &known)).collect()
    };
    let (lhs, rhs) = (judge_side(&claim.lhs), judge_side(&claim.rhs));
    let (expected, sharing) = match claim_dimension(claim, &lhs, &rhs) {
        Some((d, count)) => (Some(d), count),
        None => (None, 0),
    };
    let others = match sharing {
        1 => "the other term is",
        _ => "the other terms are",
    };
    let expected_or_none = expected.unwrap_or(Dimension::NONE);
    let odd = |(term, judgement): (&WrittenTerm, &Judgement)| {
        let (dimension, reason) = match judgement {
            Judgement::NotJudged => return None,
            Judgement::Has(d) if Some(*d) == expected => return None,
            Judgement::Has(d) => (
                Some(*d),
                format!(
                    "is in {} where {others} in {}",
                    unit(*d),
                    unit(expected_or_none)
                ),
            ),
            Judgement::Inconsistent(error) => (None, inconsistency(&term.value, error, &unit)),
        };
        let (text, span) = written_text(term, source);
        Some(OddTerm {
            text,
            span,
            dimension,
            expected: expected_or_none,
            reason,
        })
    };
    let written = claim.lhs.terms.iter().zip(&lhs);
    written
        .chain(claim.rhs.terms.iter().zip(&rhs))
        .find_map(odd)
}

/// The dimension of one term, or why it has none.
fn judge(value: &Expr, known: &dyn Fn(Symbol) -> Option<Dimension>) -> Judgement {
    if value.is_zero() || value.has_symbol_where(&|s| known(s).is_none()) {
        return Judgement::NotJudged;
    }
    match dimension_with(value, known) {
        Ok(d) => Judgement::Has(d),
        // Exponents past ±127 cannot be told apart: such a term is not judged.
        Err(DimensionError::ExponentRange(_)) => Judgement::NotJudged,
        Err(error) => Judgement::Inconsistent(error),
    }
}

/// The dimension of the side that alone names a derived quantity, when its terms agree;
/// else the one most judged terms share, and how many share it; among tied ones, the first
/// in writing order on the deciding side (the right when only it holds a derived name, else
/// the left), then on the other. None when no term has a dimension.
fn claim_dimension(
    claim: &Claim,
    lhs: &[Judgement],
    rhs: &[Judgement],
) -> Option<(Dimension, usize)> {
    let mut counts: HashMap<Dimension, usize> = HashMap::new();
    for j in lhs.iter().chain(rhs) {
        if let Judgement::Has(d) = j {
            *counts.entry(*d).or_default() += 1;
        }
    }
    let most = counts.values().copied().max()?;
    let right_decides = claim.lhs.resolved.is_empty() && !claim.rhs.resolved.is_empty();
    let left_decides = !claim.lhs.resolved.is_empty() && claim.rhs.resolved.is_empty();
    // The side that names a derived quantity (`T`) has its dimension when its terms agree:
    // `T = I_x w_x + I_y w_y` is odd in its right side, however many terms that has.
    let deciding = match (left_decides, right_decides) {
        (true, _) => Some(lhs),
        (_, true) => Some(rhs),
        _ => None,
    };
    if let Some(side) = deciding {
        let mut dims = side.iter().filter_map(|j| match j {
            Judgement::Has(d) => Some(*d),
            _ => None,
        });
        if let Some(first) = dims.next() {
            if dims.all(|d| d == first)
                && side
                    .iter()
                    .all(|j| !matches!(j, Judgement::Inconsistent(_)))
            {
                return Some((first, counts[&first]));
            }
        }
    }
    let mut in_order = if right_decides {
        rhs.iter().chain(lhs)
    } else {
        lhs.iter().chain(rhs)
    };
    in_order.find_map(|j| match j {
        Judgement::Has(d) if counts[d] == most => Some((*d, most)),
        _ => None,
    })
}

/// The text of a term as written and its span, a leading `+` and blanks left out (the
/// value of the term from the expression when the span is not in `source`).
fn written_text(term: &WrittenTerm, source: &str) -> (String, (usize, usize)) {
    let Some(raw) = source.get(term.span.0..term.span.1) else {
        return (term.value.to_string(), term.span);
    };
    let unsigned = raw.trim_start();
    let body = unsigned.strip_prefix('+').unwrap_or(unsigned).trim_start();
    let text = body.trim_end();
    let start = term.span.0 + (raw.len() - body.len());
    (text.to_string(), (start, start + text.len()))
}

/// Why a term has no dimension, in words: a function named with its argument, else the
/// error's own sentence.
fn inconsistency(
    term: &Expr,
    error: &DimensionError,
    unit: &dyn Fn(Dimension) -> String,
) -> String {
    if let DimensionError::FunctionOfDimensioned(argument, d) = error {
        if let Some(f) = function_taking(term, argument) {
            return format!(
                "the argument of {} must have no unit, but {argument} is in {}",
                f.name(),
                unit(*d)
            );
        }
    }
    error.in_words(unit)
}

/// The first function in `e` (outermost first) whose argument prints as `argument`.
fn function_taking(e: &Expr, argument: &str) -> Option<Func> {
    match e.view() {
        View::Num(_) | View::Sym(_) => None,
        View::Add(xs) | View::Mul(xs) => xs.iter().find_map(|x| function_taking(x, argument)),
        View::Pow(b, x) => function_taking(b, argument).or_else(|| function_taking(x, argument)),
        View::Func(f, a) if a.to_string() == argument => Some(f),
        View::Func(_, a) => function_taking(a, argument),
    }
}
