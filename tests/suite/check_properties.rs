//! Random true rearrangements of every derived equation are never reported `differs` by
//! `kinetics check`. The equations are the library's own (`derive_general`: H_G's three
//! components, T and Euler's three equations, general and principal; the three fixed-axis
//! equations), printed with `Display` (which parses back). Each claim is one equation
//! `lhs = rhs` rearranged by the rules that keep it true:
//! - a term moved across `=` changes its sign (`a = b + c` ⇔ `a - c = b`);
//! - a common factor `f` of some terms is pulled out, `f t₁ + f t₂ = f (t₁/f + t₂/f)`
//!   (a number or one factor of a term), or a side is left as derived, grouped;
//! - both sides multiplied by one nonzero rational or a symbol;
//! - the sides swapped.
//!
//! The rearrangements are drawn with a fixed seed; each context's claims go to the binary
//! as one claims file.

use crate::common::check::{check_file, judged, ClaimsFile};
use kinetics::algebra::Expr;
use kinetics::derive_general;
use kinetics::Relation;
use proptest::prelude::Rng;
use proptest::test_runner::{RngAlgorithm, TestRng};

/// Claims drawn per context, all in one claims file (a class set's size).
const CLAIMS_PER_CONTEXT: usize = 300;

/// The derived relations that are identities in `context`.
fn relations(context: &str) -> Vec<Relation> {
    let names: &[&str] = match context {
        "fixed-axis" => &["fixed_axis"],
        _ => &["H_G", "T", "euler"],
    };
    names
        .iter()
        .flat_map(|name| {
            derive_general(name, context == "principal")
                .expect("a known derivation")
                .expect("derived within the algebra's bounds")
                .result()
                .to_vec()
        })
        .collect()
}

/// A number below `n` (n > 0).
fn below(rng: &mut TestRng, n: usize) -> usize {
    (rng.next_u64() % n as u64) as usize
}

fn chance(rng: &mut TestRng, one_in: usize) -> bool {
    below(rng, one_in) == 0
}

/// A nonzero rational `p/q` as text, or a symbol.
fn multiplier(rng: &mut TestRng) -> String {
    const SYMBOLS: [&str; 2] = ["m", "L"];
    if chance(rng, 3) {
        return SYMBOLS[below(rng, SYMBOLS.len())].to_owned();
    }
    let p = below(rng, 9) as i64 + 1;
    let q = below(rng, 9) as i64 + 1;
    let sign = if chance(rng, 2) { "-" } else { "" };
    format!("({sign}{p}/{q})")
}

/// One side written from its terms: each in parentheses, and at times a common factor of
/// some of them pulled out (`f*((t₁/f) + (t₂/f))`).
fn side_text(rng: &mut TestRng, terms: &[Expr]) -> String {
    if terms.is_empty() {
        return "0".to_owned();
    }
    let mut pieces = Vec::new();
    let mut rest: Vec<Expr> = terms.to_vec();
    if rest.len() >= 2 && chance(rng, 2) {
        // The factor: a number, or one factor of a term, shared by the terms that have it.
        let first = rest[below(rng, rest.len())].clone();
        let factors = first.monomial();
        let factor = if factors.is_empty() || chance(rng, 4) {
            Expr::rational(below(rng, 5) as i64 + 2, below(rng, 3) as i64 + 1)
        } else {
            factors[below(rng, factors.len())].clone()
        };
        let (group, others): (Vec<Expr>, Vec<Expr>) = rest
            .into_iter()
            .partition(|t| factor.as_num().is_some() || t.monomial().contains(&factor));
        let inside: Vec<String> = group.iter().map(|t| format!("({})", t / &factor)).collect();
        pieces.push(format!("({factor})*({})", inside.join(" + ")));
        rest = others;
    }
    pieces.extend(rest.iter().map(|t| format!("({t})")));
    pieces.join(" + ")
}

/// A true rearrangement of `lhs = rhs`.
fn rearranged(rng: &mut TestRng, relation: &Relation) -> String {
    let rhs_terms = relation
        .rhs
        .expand()
        .expect("a derived side expands")
        .terms()
        .to_vec();
    let (mut left, mut right) = (vec![relation.lhs.clone()], Vec::new());
    let mut moved = false;
    for t in rhs_terms {
        if chance(rng, 3) {
            left.push(-t);
            moved = true;
        } else {
            right.push(t);
        }
    }
    if chance(rng, 4) {
        right.push(-relation.lhs.clone());
        left.remove(0);
    }
    // Left as derived (grouped, not multiplied out) when nothing was moved.
    let (mut lhs, mut rhs) = if !moved && left.len() == 1 && chance(rng, 3) {
        (relation.lhs.to_string(), relation.rhs.to_string())
    } else {
        (side_text(rng, &left), side_text(rng, &right))
    };
    if chance(rng, 2) {
        let c = multiplier(rng);
        for side in [&mut lhs, &mut rhs] {
            if side != "0" {
                *side = format!("{c}*({side})");
            }
        }
    }
    if chance(rng, 2) {
        std::mem::swap(&mut lhs, &mut rhs);
    }
    format!("{lhs} = {rhs}")
}

#[test]
fn true_rearrangements_of_the_derived_equations_never_differ() {
    let mut rng = TestRng::deterministic_rng(RngAlgorithm::ChaCha);
    let mut failures = Vec::new();
    let mut undecided = 0;
    let mut total = 0;
    for context in ["general", "principal", "fixed-axis"] {
        let relations = relations(context);
        let claims: Vec<String> = (0..CLAIMS_PER_CONTEXT)
            .map(|n| rearranged(&mut rng, &relations[n % relations.len()]))
            .collect();
        let file = ClaimsFile::new(
            &format!("properties-{context}"),
            &(claims.join("\n") + "\n"),
        );
        let run = check_file(context, &file);
        let (judged, _) = judged(&run);
        total += claims.len();
        for (n, claim) in claims.iter().enumerate() {
            let verdict = judged
                .iter()
                .find(|j| j.line == n as u64 + 1)
                .map(|j| j.verdict.as_str());
            match verdict {
                Some("holds") => {}
                Some("undecided") => undecided += 1,
                other => failures.push(format!("{context}: {claim}\n    {other:?}")),
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {total} true claims not judged to hold ({undecided} more undecided):\n{}",
        failures.len(),
        failures.join("\n")
    );
}
