//! The claimed and the correct expression as two sums of terms that can be compared term by
//! term: coefficient (rational) × monomial.
//!
//! Expanded, a polynomial or an expression whose denominators are monomials
//! (`m r³ ω₁/(4L)`) is already such a sum, and two like terms have equal monomials. A sum
//! below the line is not: `x/(2(a + b))` and `x/(2a + 2b)` are one value in two forms. When
//! either side has one, both are brought over one denominator:
//!
//! ```text
//! claimed = p₁/q₁, correct = p₂/q₂           (lowest terms, `cancelled_parts`)
//! D = q₁·(q₂/g) = q₂·(q₁/g),  g = gcd(q₁, q₂)
//! claimed = p₁(q₂/g)/D,  correct = p₂(q₁/g)/D
//! D = c·μ·D₀                                 (c integer content, μ monomial, D₀ the rest)
//! ```
//!
//! and each term `t` of an expanded numerator becomes the term `t/(c μ) · D₀⁻¹`: the
//! content and the monomial of the denominator go into the terms' coefficients and
//! monomials (`x/(4L + 4r)` reads as `1/4·x/(L + r)`), `D₀⁻¹` is a factor every term shares.

use crate::algebra::{polynomial_gcd, AlgebraError, Expr, View};
use num_integer::Integer;

/// `claimed` and `correct` as comparable sums of terms (module documentation).
pub(super) fn comparable_sums(
    claimed: &Expr,
    correct: &Expr,
) -> Result<(Expr, Expr), AlgebraError> {
    let (expanded_claimed, expanded_correct) = (claimed.expand()?, correct.expand()?);
    if !has_sum_below_the_line(&expanded_claimed) && !has_sum_below_the_line(&expanded_correct) {
        return Ok((expanded_claimed, expanded_correct));
    }
    over_one_denominator(claimed, correct)
}

/// Whether a term of the expanded `e` divides by a sum (a sum to a negative power).
fn has_sum_below_the_line(e: &Expr) -> bool {
    e.terms().iter().any(|term| {
        term.monomial().iter().any(|factor| match factor.view() {
            View::Pow(base, exponent) => {
                matches!(base.view(), View::Add(_)) && exponent.coefficient().is_negative()
            }
            _ => false,
        })
    })
}

/// Both sides over the common denominator `D = c·μ·D₀` (module documentation).
fn over_one_denominator(claimed: &Expr, correct: &Expr) -> Result<(Expr, Expr), AlgebraError> {
    let (p1, q1) = claimed.cancelled_parts()?;
    let (p2, q2) = correct.cancelled_parts()?;
    let g = polynomial_gcd(&q1, &q2)?;
    let times_for_claimed = q2.checked_div(&g)?.cancel()?;
    let times_for_correct = q1.checked_div(&g)?.cancel()?;
    let denominator = (&q1 * &times_for_claimed).expand()?;
    let content_and_monomial = content_and_monomial(&denominator);
    let rest = denominator.checked_div(&content_and_monomial)?.expand()?;
    let per_term = Expr::mul_all([
        content_and_monomial.checked_pow(&Expr::int(-1))?,
        rest.checked_pow(&Expr::int(-1))?,
    ]);
    let over = |numerator: &Expr, times: &Expr| -> Result<Expr, AlgebraError> {
        let expanded = (numerator * times).expand()?;
        Ok(Expr::add_all(
            expanded.terms().iter().map(|term| term * &per_term),
        ))
    };
    Ok((
        over(&p1, &times_for_claimed)?,
        over(&p2, &times_for_correct)?,
    ))
}

/// `c·μ` of an expanded polynomial: the gcd of its integer coefficients (when they fit a
/// machine word; 1 otherwise) times the factors every term has, each to the least power
/// any term has it.
fn content_and_monomial(polynomial: &Expr) -> Expr {
    let terms = polynomial.terms();
    let content = terms
        .iter()
        .try_fold(0i64, |gcd, term| {
            let c = term.coefficient().to_i64()?.checked_abs()?;
            Some(gcd.gcd(&c))
        })
        .filter(|&gcd| gcd > 0)
        .unwrap_or(1);
    let Some((first, others)) = terms.split_first() else {
        return Expr::one();
    };
    let common = first.monomial().iter().filter_map(|factor| {
        let (base, exponent) = factor.base_and_exponent();
        let mut least = exponent.as_num()?.clone();
        for term in others {
            let power = term.monomial().iter().find(|f| f.base() == base)?;
            let exponent = power.base_and_exponent().1;
            let exponent = exponent.as_num()?;
            if exponent < &least {
                least = exponent.clone();
            }
        }
        (!least.is_negative()).then(|| base.checked_pow(&Expr::num(least)).ok())?
    });
    Expr::mul_all(std::iter::once(Expr::int(content)).chain(common))
}
