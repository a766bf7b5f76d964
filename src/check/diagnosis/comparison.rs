//! The term-by-term comparison of two comparable sums (`common_denominator.rs`): each term
//! is a rational coefficient times a monomial, and
//!
//! ```text
//! a monomial in both, coefficients differ   -> wrong   (claimed term, correct term)
//! a monomial in the claim only              -> extra
//! a monomial in the correct form only       -> missing
//! ```
//!
//! so that `claimed − correct = Σ wrong.claimed + Σ extra − Σ wrong.correct − Σ missing`.
//! The rules read these differences; the ones that transform the differing terms (a
//! permutation of subscripts, sin for cos) read their two sums, which are formed only when
//! the differences are few and small (the work of a rule stays bounded).

use super::{Diagnosis, Reading, WrongTerm};
use crate::algebra::{Expr, Q};
use std::cmp::Ordering;

/// Most differing terms (claimed and correct together) the transforming rules read.
const MAX_TRANSFORMED_TERMS: usize = 64;

/// Most nodes of either sum of differing terms the transforming rules read.
const MAX_TRANSFORMED_NODES: usize = 4096;

/// What differs between a claimed sum and the correct one (module documentation).
pub(super) struct Differences {
    /// How many terms the correct sum has.
    pub correct_terms: usize,
    /// In the order of the correct sum's terms.
    pub wrong: Vec<WrongTerm>,
    /// In the order of the correct sum's terms.
    pub missing: Vec<Expr>,
    /// In the order of the claimed sum's terms.
    pub extra: Vec<Expr>,
    /// `(Σ claimed differing terms, Σ correct differing terms)`, when within the bounds.
    sides: Option<(Expr, Expr)>,
}

impl Differences {
    /// The differences between two comparable sums, term by term (one sort of each side's
    /// terms by monomial, then one merge).
    pub fn between(claimed: &Expr, correct: &Expr) -> Differences {
        let claimed_terms = nonzero_terms(claimed);
        let correct_terms = nonzero_terms(correct);
        let claimed_order = by_monomial(&claimed_terms);
        let correct_order = by_monomial(&correct_terms);
        let mut partner: Vec<Option<usize>> = vec![None; correct_terms.len()];
        let mut matched = vec![false; claimed_terms.len()];
        let (mut i, mut j) = (0, 0);
        while i < claimed_order.len() && j < correct_order.len() {
            let (a, b) = (claimed_order[i], correct_order[j]);
            match compare_monomials(claimed_terms[a], correct_terms[b]) {
                Ordering::Less => i += 1,
                Ordering::Greater => j += 1,
                Ordering::Equal => {
                    partner[b] = Some(a);
                    matched[a] = true;
                    i += 1;
                    j += 1;
                }
            }
        }
        let mut wrong = Vec::new();
        let mut missing = Vec::new();
        for (term, partner) in correct_terms.iter().zip(&partner) {
            match partner {
                None => missing.push((*term).clone()),
                Some(a) if claimed_terms[*a].coefficient() != term.coefficient() => {
                    wrong.push(WrongTerm {
                        claimed: claimed_terms[*a].clone(),
                        correct: (*term).clone(),
                    })
                }
                Some(_) => {}
            }
        }
        let extra: Vec<Expr> = claimed_terms
            .iter()
            .zip(&matched)
            .filter(|(_, matched)| !**matched)
            .map(|(term, _)| (*term).clone())
            .collect();
        let mut differences = Differences {
            correct_terms: correct_terms.len(),
            wrong,
            missing,
            extra,
            sides: None,
        };
        differences.sides = differences.bounded_sides();
        differences
    }

    /// The sums of the differing terms, when they are few and small enough to transform.
    fn bounded_sides(&self) -> Option<(Expr, Expr)> {
        let count = 2 * self.wrong.len() + self.missing.len() + self.extra.len();
        if count > MAX_TRANSFORMED_TERMS {
            return None;
        }
        let claimed = Expr::add_all(self.claimed_differing().cloned());
        let correct = Expr::add_all(self.correct_differing().cloned());
        (claimed.has_at_most_size(MAX_TRANSFORMED_NODES)
            && correct.has_at_most_size(MAX_TRANSFORMED_NODES))
        .then_some((claimed, correct))
    }

    /// The claimed terms that differ: the wrong ones as claimed, then the extra ones.
    pub fn claimed_differing(&self) -> impl Iterator<Item = &Expr> {
        self.wrong.iter().map(|w| &w.claimed).chain(&self.extra)
    }

    /// The correct terms the claim does not have: the wrong ones as correct, then the
    /// missing ones.
    pub fn correct_differing(&self) -> impl Iterator<Item = &Expr> {
        self.wrong.iter().map(|w| &w.correct).chain(&self.missing)
    }

    /// `(Σ claimed differing, Σ correct differing)` for the rules that transform them; none
    /// when the differences are past the bounds (then those rules do not fit).
    pub fn sides(&self) -> Option<(&Expr, &Expr)> {
        self.sides
            .as_ref()
            .map(|(claimed, correct)| (claimed, correct))
    }

    /// Whether the only differences are wrong coefficients (no term missing or extra).
    pub fn only_wrong(&self) -> bool {
        !self.wrong.is_empty() && self.missing.is_empty() && self.extra.is_empty()
    }

    /// The diagnosis these differences make, with the reading found.
    pub fn into_diagnosis(self, reading: Option<Reading>) -> Diagnosis {
        Diagnosis {
            wrong: self.wrong,
            missing: self.missing,
            extra: self.extra,
            reading,
        }
    }
}

impl WrongTerm {
    /// The claimed coefficient over the correct one: `-1` for a flipped sign, `2` for a
    /// term twice what it should be.
    pub(super) fn ratio(&self) -> Option<Q> {
        self.claimed
            .coefficient()
            .checked_div(self.correct.coefficient())
    }
}

/// The terms of a sum (zero has none).
fn nonzero_terms(sum: &Expr) -> Vec<&Expr> {
    sum.terms().iter().filter(|t| !t.is_zero()).collect()
}

/// The positions of `terms` sorted by monomial.
fn by_monomial(terms: &[&Expr]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..terms.len()).collect();
    order.sort_by(|&a, &b| compare_monomials(terms[a], terms[b]));
    order
}

fn compare_monomials(a: &Expr, b: &Expr) -> Ordering {
    a.monomial().iter().cmp(b.monomial().iter())
}
