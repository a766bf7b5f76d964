//! The square-free part `p/gcd(p, p′)` of a polynomial in one unknown: each root of `p`
//! once. A multiple root would leave a discriminant exactly zero, whose sign a value in
//! floating point cannot tell; without it every discriminant left is nonzero.
//!
//! With numbers for coefficients Euclid's algorithm runs on the rationals (`p mod p′`, …);
//! with letters, the gcd is `polynomial_gcd` of the numerator, in all the symbols.

use super::SolveError;
use crate::algebra::expr::Expr;
use crate::algebra::polynomial_gcd;
use crate::algebra::rational::Q;
use crate::algebra::symbol::Symbol;

/// The coefficients of `p/gcd(p, p′)`, which has each root of `p` once (a multiple root
/// would make a discriminant zero, whose sign a value in floating point cannot tell).
pub(super) fn square_free(coefficients: &[Expr], u: Symbol) -> Result<Vec<Expr>, SolveError> {
    if coefficients.len() < 3 {
        return Ok(coefficients.to_vec());
    }
    let x = Expr::sym(u);
    // Denominators free of u (symbolic coefficients) multiplied out: the same roots.
    let (p, _) = Expr::add_all(
        coefficients
            .iter()
            .enumerate()
            .map(|(k, a)| a * &x.powi(k as i64)),
    )
    .cancelled_parts()?;
    let derivative = p.diff(u)?;
    let common = polynomial_gcd(&p, &derivative)?;
    if !common.contains(u) {
        return Ok(coefficients.to_vec());
    }
    let quotient = p.checked_div(&common)?.cancel()?.expand()?;
    let mut out: Vec<Expr> = Vec::new();
    for group in quotient.collect(&[u])? {
        let power = if group.monomial.is_one() {
            0
        } else {
            let (_, exponent) = group.monomial.base_and_exponent();
            exponent.as_num().and_then(Q::to_i64).unwrap_or(0) as usize
        };
        if out.len() <= power {
            out.resize(power + 1, Expr::zero());
        }
        out[power] = group.coefficient;
    }
    Ok(out)
}

/// The square-free part of `Σ aₖ uᵏ` with rational coefficients (lowest power first),
/// monic.
pub(super) fn square_free_numeric(a: &[Q]) -> Vec<Q> {
    if a.len() < 3 {
        return a.to_vec();
    }
    let derivative: Vec<Q> = (1..a.len()).map(|k| &Q::int(k as i64) * &a[k]).collect();
    let common = gcd(a.to_vec(), derivative);
    if common.len() < 2 {
        return a.to_vec();
    }
    let (quotient, _) = divided(a, &common);
    monic(quotient)
}

/// The monic gcd of two polynomials (Euclid's algorithm); `[1]` when they are coprime.
fn gcd(mut p: Vec<Q>, mut q: Vec<Q>) -> Vec<Q> {
    while !q.is_empty() {
        let (_, remainder) = divided(&p, &q);
        p = q;
        q = remainder;
    }
    monic(p)
}

/// Quotient and remainder of `p` by `q` (`q`'s leading coefficient nonzero); a zero
/// remainder is empty.
fn divided(p: &[Q], q: &[Q]) -> (Vec<Q>, Vec<Q>) {
    let mut r = p.to_vec();
    let lead = q.last().expect("a divisor is not empty");
    let mut quotient = vec![Q::ZERO; p.len().saturating_sub(q.len()) + 1];
    while r.len() >= q.len() {
        let shift = r.len() - q.len();
        let factor = r
            .last()
            .and_then(|top| top.checked_div(lead))
            .expect("the divisor's leading coefficient is not zero");
        for (k, c) in q.iter().enumerate() {
            r[k + shift] = &r[k + shift] - &(&factor * c);
        }
        quotient[shift] = factor;
        r.pop();
        while r.last().is_some_and(Q::is_zero) {
            r.pop();
        }
    }
    (quotient, r)
}

/// `p` divided by its leading coefficient.
fn monic(p: Vec<Q>) -> Vec<Q> {
    match p.last().cloned() {
        Some(lead) if !lead.is_zero() => p
            .iter()
            .map(|c| c.checked_div(&lead).expect("a nonzero leading coefficient"))
            .collect(),
        _ => p,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Q {
        Q::int(n)
    }

    /// (u² − 2)² (u + 3) = u⁵ + 3u⁴ − 4u³ − 12u² + 4u + 12 (multiplied out by hand) has the
    /// square-free part (u² − 2)(u + 3) = u³ + 3u² − 2u − 6.
    #[test]
    fn a_repeated_irrational_factor_is_kept_once() {
        let p = [q(12), q(4), q(-12), q(-4), q(3), q(1)];
        assert_eq!(square_free_numeric(&p), vec![q(-6), q(-2), q(3), q(1)]);
        let coprime = [q(1), q(1), q(0), q(1)];
        assert_eq!(square_free_numeric(&coprime), coprime.to_vec());
    }
}
