//! The rational roots of a polynomial with rational coefficients: with the coefficients made
//! integers `a₀ … a_d` (`a₀ ≠ 0`), a root `p/q` in lowest terms has `p | a₀` and `q | a_d`
//! (the rational root theorem). Each candidate `±p/q` whose value in floating point is not
//! far from zero is tried exactly (Horner's rule), and a root's factor `u − r` divided out as
//! often as it divides (synthetic division), so a multiple root is reported once.
//!
//! The search runs only while `|a₀|` and `|a_d|` are at most [`MAX_SEARCHED`] (their
//! divisors found by trial division up to the square root); past it (or past [`MAX_CANDIDATES`] candidates) no rational root is
//! looked for and the formulas of the degree take the whole polynomial (still exact, in
//! radicals).

use crate::algebra::rational::Q;
use std::collections::BTreeSet;

/// Largest `|a₀|`, `|a_d|` whose divisors are searched: a million trial divisions at most.
const MAX_SEARCHED: i64 = 1_000_000_000_000;

/// Largest number of pairs `(p, q)` tried (twice, for the two signs).
const MAX_CANDIDATES: usize = 50_000;

/// The distinct rational roots of `Σ aₖ uᵏ` (`a₀ ≠ 0`) and the polynomial left once their
/// factors are divided out (coefficients lowest power first).
pub(super) fn rational_roots(coefficients: &[Q]) -> (Vec<Q>, Vec<Q>) {
    let mut rest = coefficients.to_vec();
    let mut roots = Vec::new();
    let approximate: Vec<f64> = coefficients.iter().map(Q::to_f64).collect();
    for r in candidates(coefficients) {
        if rest.len() < 2 {
            break;
        }
        if !near_root(&approximate, r.to_f64()) {
            continue;
        }
        let mut found = false;
        while rest.len() >= 2 && value_at(&rest, &r).is_zero() {
            rest = divided_by_root(&rest, &r);
            found = true;
        }
        if found {
            roots.push(r);
        }
    }
    (roots, rest)
}

/// Whether `Σ aₖ xᵏ` in floating point is small enough, against the size of its terms, for
/// `x` to be a root: a candidate that is not is passed over without exact arithmetic (a root
/// leaves only rounding, some 1e-16 of the terms).
fn near_root(a: &[f64], x: f64) -> bool {
    let value = a.iter().rev().fold(0.0, |acc, c| acc * x + c);
    let size = a.iter().rev().fold(0.0, |acc, c| acc * x.abs() + c.abs());
    value.abs().partial_cmp(&(1e-9 * size)) != Some(std::cmp::Ordering::Greater)
}

/// `Σ aₖ rᵏ` by Horner's rule.
fn value_at(a: &[Q], r: &Q) -> Q {
    a.iter().rev().fold(Q::ZERO, |acc, c| &(&acc * r) + c)
}

/// The quotient of `Σ aₖ uᵏ` by `u − r` (`r` a root): `b_{d−1} = a_d`,
/// `b_{k−1} = a_k + r b_k`.
fn divided_by_root(a: &[Q], r: &Q) -> Vec<Q> {
    let d = a.len() - 1;
    let mut b = vec![Q::ZERO; d];
    b[d - 1] = a[d].clone();
    for k in (1..d).rev() {
        b[k - 1] = &a[k] + &(r * &b[k]);
    }
    b
}

/// `±p/q` for every `p | a₀`, `q | a_d` of the integer coefficients, when both are small
/// enough (module documentation), in ascending order; none otherwise.
fn candidates(coefficients: &[Q]) -> BTreeSet<Q> {
    let mut out = BTreeSet::new();
    let Some(integers) = integer_coefficients(coefficients) else {
        return out;
    };
    let (Some(&first), Some(&last)) = (integers.first(), integers.last()) else {
        return out;
    };
    let (numerators, denominators) = (divisors(first), divisors(last));
    if numerators.len() * denominators.len() > MAX_CANDIDATES {
        return out;
    }
    for p in &numerators {
        for q in &denominators {
            out.extend([Q::new(*p, *q), Q::new(-*p, *q)].into_iter().flatten());
        }
    }
    out
}

/// The coefficients times the lcm of their denominators, when each then fits the search.
fn integer_coefficients(coefficients: &[Q]) -> Option<Vec<i64>> {
    let mut lcm = Q::ONE;
    for c in coefficients {
        let d = c.denom();
        let g = lcm.integer_gcd(&d);
        lcm = &lcm * &d.checked_div(&g)?;
    }
    coefficients
        .iter()
        .map(|c| (c * &lcm).to_i64().filter(|n| n.abs() <= MAX_SEARCHED))
        .collect()
}

/// The positive divisors of `n ≠ 0`, by trial division up to `√|n|`.
fn divisors(n: i64) -> Vec<i64> {
    let n = n.abs();
    let mut small = Vec::new();
    let mut large = Vec::new();
    let mut d = 1;
    while d * d <= n {
        if n % d == 0 {
            small.push(d);
            if d * d != n {
                large.push(n / d);
            }
        }
        d += 1;
    }
    small.extend(large.into_iter().rev());
    small
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Q {
        Q::new(n, d).unwrap()
    }

    #[test]
    fn finds_each_rational_root_once_and_divides_it_out() {
        // 6(u − 1/2)(u + 2/3)(u − 1)² = (6u² + u − 2)(u² − 2u + 1)
        //                             = 6u⁴ − 11u³ + 2u² + 5u − 2 (expanded by hand).
        let a = [q(-2, 1), q(5, 1), q(2, 1), q(-11, 1), q(6, 1)];
        let (mut roots, rest) = rational_roots(&a);
        roots.sort();
        assert_eq!(roots, vec![q(-2, 3), q(1, 2), q(1, 1)]);
        assert_eq!(rest, vec![q(6, 1)]);
    }

    #[test]
    fn leaves_an_irreducible_factor() {
        // (u − 3)(u² − 2) = u³ − 3u² − 2u + 6
        let a = [q(6, 1), q(-2, 1), q(-3, 1), q(1, 1)];
        let (roots, rest) = rational_roots(&a);
        assert_eq!(roots, vec![q(3, 1)]);
        assert_eq!(rest, vec![q(-2, 1), q(0, 1), q(1, 1)]);
    }
}
