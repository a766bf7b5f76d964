//! The coefficient of a group of terms (rules 1 and 3 of [`super`]): the terms that
//! share a kinematic part, read without it, their order, and what they have in common.
//!
//! - A coefficient term is a number times factors. Where no member of a group has a sum in
//!   its coefficient, the members' coefficients are distinct monomials, so their sum is the
//!   members themselves with the kinematic factors skipped: they are read in place and no
//!   expression is formed. Otherwise the algebra forms the sum and its terms are read.
//! - Terms are ordered by their least inertia symbol, cyclically from the equation's axis
//!   (moments first, then products), terms without one after, lexicographically with higher
//!   powers first; ties keep the canonical order of the sum (monomials lexicographically).
//! - The common factor is the rational content (gcd of the numerators over lcm of the
//!   denominators, positive) times each base common to all terms to its least power (bases
//!   with exponents of one sign only), a symbol below the line in any term to its most
//!   negative power (the common denominator: no fraction is left inside the group); it is
//!   formed only when it is not one.

use super::kinematic::is_kinematic_factor;
use crate::algebra::{Axis, Expr, Role, Symbol, View, Q};
use std::cmp::Ordering;

/// One term of a group's coefficient.
#[derive(Debug, Clone, Copy)]
pub struct CoefficientTerm<'e> {
    term: &'e Expr,
    /// Whether `term` is a whole term of the sum, its kinematic factors not part of the
    /// coefficient (otherwise `term` is a term of a coefficient the algebra formed).
    in_place: bool,
}

impl<'e> CoefficientTerm<'e> {
    /// The coefficient of a term of the sum, read in place without its kinematic factors.
    pub fn in_place(term: &'e Expr) -> CoefficientTerm<'e> {
        CoefficientTerm {
            term,
            in_place: true,
        }
    }

    /// A term of a formed coefficient, taken whole.
    pub fn whole(term: &'e Expr) -> CoefficientTerm<'e> {
        CoefficientTerm {
            term,
            in_place: false,
        }
    }

    pub fn coefficient(self) -> &'e Q {
        self.term.coefficient()
    }

    /// The factors after the number, in canonical order.
    pub fn factors(self) -> impl Iterator<Item = &'e Expr> + Clone {
        let in_place = self.in_place;
        self.term
            .monomial()
            .iter()
            .filter(move |f| !in_place || !is_kinematic_factor(f))
    }

    /// The term as an expression of its own.
    pub fn to_expr(self) -> Expr {
        match self.in_place {
            true => self.term.without_factors(is_kinematic_factor),
            false => self.term.clone(),
        }
    }
}

/// The order of two terms of a coefficient about `axis` (rule 3), ties in canonical order.
pub fn compare(a: CoefficientTerm, b: CoefficientTerm, axis: Axis) -> Ordering {
    let key = |t: CoefficientTerm| {
        t.factors()
            .filter_map(|f| f.base().as_symbol())
            .filter(|s| s.role() == Role::Inertia)
            .map(|s| inertia_key(s, axis))
            .min()
    };
    let by_inertia = match (key(a), key(b)) {
        (Some(x), Some(y)) => x.cmp(&y),
        (Some(_), None) => Ordering::Less,
        (None, Some(_)) => Ordering::Greater,
        (None, None) => compare_lexicographic(a.factors(), b.factors()),
    };
    by_inertia.then_with(|| a.factors().cmp(b.factors()))
}

/// Lexicographic order of monomials, higher powers first: `a^3, a^2 b, a b^2, b^3`.
fn compare_lexicographic<'e>(
    mut a: impl Iterator<Item = &'e Expr>,
    mut b: impl Iterator<Item = &'e Expr>,
) -> Ordering {
    loop {
        let (x, y) = match (a.next(), b.next()) {
            (Some(x), Some(y)) => (x, y),
            (Some(_), None) => return Ordering::Less,
            (None, Some(_)) => return Ordering::Greater,
            (None, None) => return Ordering::Equal,
        };
        let ((bx, ex), (by, ey)) = (x.base_and_exponent(), y.base_and_exponent());
        let order = bx.cmp(by).then_with(|| ey.cmp(&ex));
        if order != Ordering::Equal {
            return order;
        }
    }
}

/// Ordering key of an inertia symbol for the equation about `axis` (rule 3).
pub fn inertia_key(s: Symbol, axis: Axis) -> (u8, usize, Symbol) {
    let a = axis.index();
    let subscript = s.subscript();
    // The axes the subscript names, in order: the first two and how many.
    let mut named = [0usize; 2];
    let mut count = 0;
    for k in subscript.bytes().filter_map(axis_of_letter) {
        if let Some(slot) = named.get_mut(count) {
            *slot = k;
        }
        count += 1;
    }
    match (count, named) {
        (1, [k, _]) if subscript.len() == 1 => (0, (k + 3 - a) % 3, s),
        (2, [p, q]) => {
            let pair = match (p.min(q), p.max(q)) {
                (0, 1) => 0,
                (1, 2) => 1,
                _ => 2,
            };
            (1, (pair + 3 - a) % 3, s)
        }
        _ => (2, 0, s),
    }
}

/// The axis index of one subscript letter: `x` or `X` is 0, `y` 1, `z` 2.
fn axis_of_letter(c: u8) -> Option<usize> {
    match c {
        b'x' | b'X' => Some(0),
        b'y' | b'Y' => Some(1),
        b'z' | b'Z' => Some(2),
        _ => None,
    }
}

/// The monomial that divides every term (bases to their least power) times the rational
/// content, sign excluded; `None` when it is one.
pub fn common_factor(terms: &[CoefficientTerm]) -> Option<Expr> {
    let (first, others) = terms.split_first()?;
    let content = rational_content(terms);
    let above = first
        .factors()
        .filter_map(numeric_power)
        .filter(|(base, exponent)| !(exponent.is_negative() && is_symbol(base)))
        .filter_map(|(base, exponent)| least_power(others, base, exponent));
    let common: Vec<Expr> = above
        .chain(common_denominator(terms))
        .map(|(base, exponent)| power(base, exponent))
        .collect();
    if content.is_one() && common.is_empty() {
        return None;
    }
    Some(Expr::mul_all(
        std::iter::once(Expr::num(content)).chain(common),
    ))
}

/// Each symbol below the line in any term, to its most negative power among the terms (a
/// term without it counts 0): the terms' common denominator, so that none keeps a fraction
/// inside the group (`4L + r²/L` is `(4L² + r²)/L`, never `-¼ m r (4L + r²/L) ω₁`).
fn common_denominator<'e>(terms: &[CoefficientTerm<'e>]) -> Vec<(&'e Expr, &'e Q)> {
    let mut below: Vec<(&Expr, &Q)> = Vec::new();
    for (base, exponent) in terms
        .iter()
        .flat_map(|t| t.factors().filter_map(numeric_power))
    {
        if !exponent.is_negative() || !is_symbol(base) {
            continue;
        }
        match below.iter_mut().find(|(b, _)| *b == base) {
            Some((_, least)) if exponent < *least => *least = exponent,
            Some(_) => {}
            None => below.push((base, exponent)),
        }
    }
    below
}

fn is_symbol(e: &Expr) -> bool {
    matches!(e.view(), View::Sym(_))
}

/// `base` to the exponent of least magnitude among `exponent` and its exponents in `terms`,
/// if every term has it to an exponent of the same sign.
fn least_power<'e>(
    terms: &[CoefficientTerm<'e>],
    base: &'e Expr,
    mut exponent: &'e Q,
) -> Option<(&'e Expr, &'e Q)> {
    for term in terms {
        let e = term.factors().find_map(|f| match numeric_power(f) {
            Some((b, e)) if b == base => Some(e),
            _ => None,
        })?;
        if e.is_negative() != exponent.is_negative() {
            return None;
        }
        if (e < exponent) != exponent.is_negative() {
            exponent = e;
        }
    }
    Some((base, exponent))
}

/// A factor as a base to a numeric exponent (1 for a factor that is not a power); `None`
/// for a symbolic exponent.
fn numeric_power(f: &Expr) -> Option<(&Expr, &Q)> {
    static ONE: Q = Q::ONE;
    match f.view() {
        View::Pow(base, exponent) => exponent.as_num().map(|q| (base, q)),
        _ => Some((f, &ONE)),
    }
}

/// `base^exponent`. `checked_pow` fails only for zero to a negative power, and the base of
/// a factor of a canonical term is never zero (a product with a zero factor is zero
/// itself). Were it to fail, 1 still divides every term: the group printed with it is the
/// same sum.
fn power(base: &Expr, exponent: &Q) -> Expr {
    base.checked_pow(&Expr::num(exponent.clone()))
        .unwrap_or_else(|_| Expr::one())
}

/// The largest positive rational that divides every coefficient, gcd of the numerators over
/// lcm of the denominators: `1/12 a² + 1/12 d²` has `1/12`, `r²/(8L²) + 3/4` has `1/8`.
/// A content whose numerator or denominator does not fit an `i64` is taken as 1.
fn rational_content(terms: &[CoefficientTerm]) -> Q {
    small_rational_content(terms).unwrap_or_else(|| big_rational_content(terms))
}

/// [`rational_content`] in machine integers; `None` when a coefficient is a big rational.
fn small_rational_content(terms: &[CoefficientTerm]) -> Option<Q> {
    use num_integer::Integer;
    let mut numerators = 0u64;
    let mut denominators = 1i64;
    for t in terms {
        let Q::Small(n, d) = *t.coefficient() else {
            return None;
        };
        numerators = numerators.gcd(&n.unsigned_abs());
        let Some(lcm) = (denominators / denominators.gcd(&d)).checked_mul(d) else {
            return Some(Q::ONE);
        };
        denominators = lcm;
    }
    match i64::try_from(numerators) {
        Ok(1) if denominators == 1 => Some(Q::ONE),
        Ok(n) if n > 0 => Some(Q::new(n, denominators).unwrap_or(Q::ONE)),
        _ => Some(Q::ONE),
    }
}

/// [`rational_content`] in big integers, for coefficients beyond `i64`.
fn big_rational_content(terms: &[CoefficientTerm]) -> Q {
    use num_integer::Integer;
    let mut numerators = num_bigint::BigInt::from(0);
    let mut denominators = num_bigint::BigInt::from(1);
    for t in terms {
        let (n, d) = t.coefficient().parts();
        numerators = numerators.gcd(&n);
        denominators = denominators.lcm(&d);
    }
    use num_traits::ToPrimitive;
    match (numerators.to_i64(), denominators.to_i64()) {
        (Some(n), Some(d)) if n > 0 => Q::new(n, d).unwrap_or(Q::ONE),
        _ => Q::ONE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::Func;

    /// Members whose coefficients hold no sum, read in place and put in order, are the terms
    /// of the coefficient the algebra forms, in the same order: the reading in place is the
    /// sum without forming it.
    #[test]
    fn coefficients_read_in_place_are_the_formed_sum() {
        let s = Expr::symbol;
        let w = s("w_y") * s("w_z");
        let members = [
            vec![-s("I_y") * &w, s("I_z") * &w],
            vec![
                Expr::rational(1, 2) * s("m") * s("r").powi(2) * &w,
                Expr::int(3) * &w,
            ],
            vec![
                s("I_xz") * s("L").powi(-1) * &w,
                Expr::int(-2) * s("I_x") * &w,
                s("a").powi(2) * s("b") * &w,
                s("a") * s("b").powi(2) * &w,
                Func::Sin.apply(s("beta")) * s("h") * &w,
            ],
            vec![s("a"), Expr::int(-4), s("m") * s("g")],
            vec![
                s("I_x") * s("r") * &w,
                -s("I_x") * s("m") * &w,
                s("I_y") * &w,
            ],
            vec![
                s("a").powi(2) * s("b") * &w,
                Expr::int(3) * s("a") * s("b").powi(2) * &w,
            ],
        ];
        for terms in &members {
            let sum = Expr::add_all(terms.iter().cloned());
            let axis = Axis::Y;
            let mut in_place: Vec<CoefficientTerm> =
                sum.terms().iter().map(CoefficientTerm::in_place).collect();
            in_place.sort_by(|&a, &b| compare(a, b, axis));
            let formed = Expr::add_all(
                sum.terms()
                    .iter()
                    .map(|t| t.without_factors(is_kinematic_factor)),
            );
            let mut whole: Vec<CoefficientTerm> =
                formed.terms().iter().map(CoefficientTerm::whole).collect();
            whole.sort_by(|&a, &b| compare(a, b, axis));
            let read: Vec<Expr> = in_place.iter().map(|t| t.to_expr()).collect();
            let expected: Vec<Expr> = whole.iter().map(|t| t.to_expr()).collect();
            assert_eq!(read, expected, "{sum}");
            assert_eq!(
                common_factor(&in_place).map(|c| c.to_string()),
                common_factor(&whole).map(|c| c.to_string()),
                "{sum}"
            );
        }
    }

    /// The machine-integer content agrees with the big-integer one wherever it answers,
    /// including denominators whose lcm overflows an `i64` (content 1 in both).
    #[test]
    fn small_rational_content_agrees_with_big() {
        let q = |n: i64, d: i64| Expr::num(Q::new(n, d).unwrap()) * Expr::symbol("a");
        let sets = [
            vec![q(1, 12), q(1, 12)],
            vec![q(1, 8), q(3, 4)],
            vec![q(-6, 1), q(4, 1), q(10, 3)],
            vec![q(i64::MIN, 1), q(i64::MIN, 1)],
            vec![q(1, 1 << 40), q(1, (1 << 40) - 1)],
            vec![q(1, i64::MAX), q(1, i64::MAX - 1)],
        ];
        for terms in &sets {
            let terms: Vec<CoefficientTerm> = terms.iter().map(CoefficientTerm::whole).collect();
            let small = small_rational_content(&terms).expect("small coefficients");
            assert_eq!(small, big_rational_content(&terms), "{terms:?}");
        }
    }
}
