//! `expand`: multiply out products of sums and positive integer powers of sums.
//!
//! The result is a sum of monomials with rational coefficients (functions and non-integer
//! powers stay as atoms, with their arguments expanded). It is the canonical form that
//! decides equality: two polynomials, or two expressions whose denominators are monomials,
//! are equal exactly when their expansions are identical. An expansion that would produce
//! more than [`MAX_EXPANDED_TERMS`] terms is refused before any work is done, and one of
//! more than [`MAX_EXPANDED_NODES`] nodes (few terms repeating a large factor) once formed.
//!
//! The terms of a sum, and the products of terms of a product's sums, are gathered in one
//! list on the stack and summed once at the end (one sort, like terms combined then), rather
//! than each partial sum and product being made canonical on the way.

use super::error::{AlgebraError, MAX_EXPANDED_NODES, MAX_EXPANDED_TERMS};
use super::expr::{Expr, Operands, View};
use super::merge;
use super::rational::Q;
use super::work;
use smallvec::SmallVec;
use std::borrow::Cow;

impl Expr {
    /// The fully expanded form (see the module documentation).
    ///
    /// ```
    /// use kinetics::algebra::Expr;
    /// let (a, b) = (Expr::symbol("a"), Expr::symbol("b"));
    /// let square = (&a + &b).powi(2).expand().unwrap();
    /// assert_eq!(square, a.powi(2) + Expr::int(2) * &a * &b + b.powi(2));
    /// assert!((&a + &b).powi(99_999_999).expand().is_err());
    /// ```
    pub fn expand(&self) -> Result<Expr, AlgebraError> {
        let expanded = self.expanded()?;
        if !expanded.has_at_most_size(MAX_EXPANDED_NODES) {
            return Err(AlgebraError::ExpansionTooLong(MAX_EXPANDED_NODES));
        }
        Ok(expanded)
    }

    /// The expansion, its size in nodes not yet checked.
    fn expanded(&self) -> Result<Expr, AlgebraError> {
        work::check()?;
        if is_expanded(self) {
            return Ok(self.clone());
        }
        match self.view() {
            View::Num(_) | View::Sym(_) => Ok(self.clone()),
            View::Add(_) | View::Mul(_) => {
                let mut terms = Operands::new();
                expand_into(self, &mut terms)?;
                Ok(Expr::sum_of_terms(&mut terms))
            }
            View::Pow(base, exponent) => {
                let base = base.expanded()?;
                match exponent.as_num() {
                    Some(n) if n.is_integer() && !n.is_negative() && base.terms().len() > 1 => {
                        power_of_sum(&base, n)
                    }
                    _ => multiplied_out(base.checked_pow(exponent)?),
                }
            }
            View::Func(f, arg) => Ok(Expr::func(f, arg.expanded()?)),
        }
    }
}

/// Pushes the terms of the expansion of `e` onto `terms`, like terms not yet combined: the
/// terms of a sum and of a product of sums are gathered in one list and summed once.
fn expand_into(e: &Expr, terms: &mut Operands) -> Result<(), AlgebraError> {
    match e.view() {
        // Each term's expansion is bounded on its own; their sum, before like terms combine,
        // by the count gathered so far (40 products of 65,536 terms each passed 1 GiB).
        View::Add(xs) => xs.iter().try_for_each(|x| {
            expand_into(x, terms)?;
            check_uncombined(terms.len())
        }),
        View::Mul(_) => expand_product(e, terms),
        _ if is_power_of_symbol(e) => {
            terms.push(e.clone());
            Ok(())
        }
        _ => {
            terms.extend(e.expanded()?.terms().iter().cloned());
            Ok(())
        }
    }
}

/// Pushes the terms of the expansion of the product `p` onto `terms`. Its factors that are
/// powers of symbols expand to themselves; they stay a sorted monomial `c · m` and are
/// merged into each product of terms `t` of the other (expanded) factors: `c · m · t`.
/// A product of powers of symbols alone is its own expansion.
fn expand_product(p: &Expr, terms: &mut Operands) -> Result<(), AlgebraError> {
    let mut monomial: SmallVec<[&Expr; 8]> = SmallVec::new();
    let mut others: SmallVec<[Cow<Expr>; 4]> = SmallVec::new();
    for f in p.monomial() {
        if is_power_of_symbol(f) {
            monomial.push(f);
        } else if is_expanded(f) {
            others.push(Cow::Borrowed(f));
        } else {
            others.push(Cow::Owned(f.expanded()?));
        }
    }
    let size = others
        .iter()
        .fold(1usize, |n, f| n.saturating_mul(f.terms().len()));
    check_size("the product", size as f64)?;
    let coeff = p.coefficient();
    match others.split_last() {
        None => terms.push(p.clone()),
        Some((last, [])) => {
            for t in last.terms() {
                terms.push(merge::scaled_product(coeff, &monomial, t));
            }
        }
        Some((last, rest)) => {
            let mut partial: Operands = rest[0].terms().iter().cloned().collect();
            for f in &rest[1..] {
                partial = products_of_terms(&partial, f.terms())?;
            }
            for t in products_of_terms(&partial, last.terms())? {
                terms.push(merge::scaled_product(coeff, &monomial, &t));
            }
        }
    }
    Ok(())
}

/// Every product `x · y` of a term `x` of `a` and a term `y` of `b`, multiplied out,
/// uncombined.
fn products_of_terms(a: &[Expr], b: &[Expr]) -> Result<Operands, AlgebraError> {
    let mut products = Operands::with_capacity(a.len() * b.len());
    // Two terms of expanded expressions can form a whole power of a sum only if both hold a
    // power of a sum: one flag per term, not a look at every product.
    let b_powers: SmallVec<[bool; 16]> = b.iter().map(has_power_of_sum).collect();
    for x in a {
        let x_power = has_power_of_sum(x);
        for (y, &y_power) in b.iter().zip(&b_powers) {
            let product = x * y;
            if !(x_power && y_power) || is_multiplied_out(&product) {
                products.extend(product.terms().iter().cloned());
            } else {
                expand_into(&product, &mut products)?;
            }
        }
    }
    Ok(products)
}

/// `e`, a product or power of expanded expressions, multiplied out.
fn multiplied_out(e: Expr) -> Result<Expr, AlgebraError> {
    match is_multiplied_out(&e) {
        true => Ok(e),
        false => e.expanded(),
    }
}

/// Whether a product or power of expanded expressions is expanded itself. It is, unless
/// powers of one sum met in it and combined into the sum, or a positive whole power of it,
/// as a factor: `x √s · √s = x s`, `s^(3/2) · s^(3/2) = s³`, `(x √s)² = x² s`. Such a
/// factor is multiplied out in turn (its sum is of a deeper level, so this ends).
fn is_multiplied_out(e: &Expr) -> bool {
    let whole_power_of_sum = |f: &Expr| match f.view() {
        View::Add(_) => true,
        View::Pow(base, exponent) => {
            matches!(base.view(), View::Add(_))
                && exponent
                    .as_num()
                    .is_some_and(|q| q.is_integer() && !q.is_negative())
        }
        _ => false,
    };
    e.terms()
        .iter()
        .all(|t| !t.monomial().iter().any(whole_power_of_sum))
}

/// Whether `e` is a sum of monomials in symbols (or a single one), which expands to itself.
fn is_expanded(e: &Expr) -> bool {
    match e.view() {
        View::Add(terms) => terms.iter().all(is_expanded_monomial),
        _ => is_expanded_monomial(e),
    }
}

/// A number, or a product of a number and numeric powers of symbols.
fn is_expanded_monomial(e: &Expr) -> bool {
    match e.view() {
        View::Mul(factors) => factors.iter().all(is_power_of_symbol),
        _ => is_power_of_symbol(e),
    }
}

/// A number, a symbol, or a symbol to a numeric power.
fn is_power_of_symbol(e: &Expr) -> bool {
    match e.view() {
        View::Num(_) | View::Sym(_) => true,
        View::Pow(base, exponent) => base.as_symbol().is_some() && exponent.as_num().is_some(),
        _ => false,
    }
}

/// `(x₁ + … + x_t)^n` multiplied out, for an expanded sum of `t ≥ 2` terms and a whole
/// `n ≥ 2`. Its size is checked first: the number of terms, `C(t + n - 1, n)`, and the
/// digits of the coefficients, at most `t^n · Π max(|cᵢ|, 1)^n` over numerators and
/// denominators. The sum is raised by the multinomial theorem, one term per
/// `k₁ + … + k_t = n`:
///
/// `Σ n!/(k₁!⋯k_t!) · Π cᵢ^kᵢ · Π mᵢ^kᵢ` for the terms `xᵢ = cᵢ mᵢ`;
///
/// where terms hold powers of a sum (other than negative ones), a product may combine
/// them into a whole power of that sum, which is multiplied out in turn.
fn power_of_sum(base: &Expr, n: &Q) -> Result<Expr, AlgebraError> {
    let terms = base.terms();
    let t = terms.len();
    let Some(n) = n.to_i64().and_then(|n| usize::try_from(n).ok()) else {
        // n ≥ 2⁶³: more than n terms, far past the limit.
        return Err(AlgebraError::ExponentOutOfRange(n.to_string()));
    };
    check_size("the power", multinomial_terms(t, n as u64))?;
    let coefficient_bits = terms
        .iter()
        .map(|x| {
            let (num, den) = x.coefficient().bit_lengths();
            num + den
        })
        .max()
        .unwrap_or(0);
    let per_factor = coefficient_bits + u64::from(usize::BITS - t.leading_zeros());
    let coefficient_bound = per_factor.saturating_mul(n as u64);
    Q::check_bits("a coefficient of the expanded power", coefficient_bound)?;
    // Its size as `has_at_most_size` counts it, before the work: each term a number of up
    // to `coefficient_bound` bits (one node per 32) and a monomial (long names, which count
    // more, are checked once it is formed).
    let size = multinomial_terms(t, n as u64) * (2.0 + coefficient_bound as f64 / 32.0);
    if size > MAX_EXPANDED_NODES as f64 {
        return Err(AlgebraError::ExpansionTooLong(MAX_EXPANDED_NODES));
    }
    let powers: Vec<Vec<(Q, Expr)>> = terms.iter().map(|x| powers_of_term(x, n)).collect();
    let mut out = Operands::new();
    push_multinomial_terms(&powers, n, Q::ONE, &mut Vec::new(), &mut out);
    if terms.iter().any(has_power_of_sum) {
        out = whole_powers_multiplied_out(out)?;
    }
    Ok(Expr::sum_of_terms(&mut out))
}

/// The terms of a multinomial expansion with each term in which powers of a sum combined
/// into a whole power of it (`√s · √s = s`) multiplied out in turn. The terms, like terms
/// not yet combined, are bounded by [`MAX_UNCOMBINED_TERMS`]: counted before any is
/// multiplied out (a term's count is the product of its whole powers' multinomial counts),
/// and again as they are gathered, for sums nested deeper.
fn whole_powers_multiplied_out(terms: Operands) -> Result<Operands, AlgebraError> {
    let too_many = || too_many_uncombined("the power");
    let counted: f64 = terms.iter().map(multiplied_out_terms).sum();
    if counted > MAX_UNCOMBINED_TERMS as f64 {
        return Err(too_many());
    }
    let mut out = Operands::with_capacity(terms.len());
    for term in terms {
        if is_multiplied_out(&term) {
            out.push(term);
        } else {
            expand_into(&term, &mut out)?;
        }
        if out.len() > MAX_UNCOMBINED_TERMS {
            return Err(too_many());
        }
    }
    Ok(out)
}

/// How many terms a term of expanded factors gives multiplied out: the product over its
/// sums `s` and whole powers `sⁿ` of `C(t + n - 1, n)` for `t` terms of `s`.
fn multiplied_out_terms(term: &Expr) -> f64 {
    term.monomial()
        .iter()
        .map(|f| match f.view() {
            View::Add(xs) => xs.len() as f64,
            View::Pow(base, exponent) if matches!(base.view(), View::Add(_)) => {
                match exponent.as_num().and_then(Q::to_i64) {
                    Some(n) if n > 0 => multinomial_terms(base.terms().len(), n as u64),
                    _ => 1.0,
                }
            }
            _ => 1.0,
        })
        .product()
}

/// The most terms, like terms not yet combined, an expansion gathers before it is refused.
const MAX_UNCOMBINED_TERMS: usize = 4 * MAX_EXPANDED_TERMS;

/// `cᵏ` and `mᵏ` for `k = 0, …, n`, for the term `c m`.
fn powers_of_term(x: &Expr, n: usize) -> Vec<(Q, Expr)> {
    let (c, m) = (x.coefficient(), Expr::term(Q::ONE, x.monomial()));
    let mut powers = Vec::with_capacity(n + 1);
    powers.push((Q::ONE, Expr::one()));
    for k in 1..=n {
        let coefficient = &powers[k - 1].0 * c;
        powers.push((coefficient, m.powi(k as i64)));
    }
    powers
}

/// Pushes the terms of the multinomial expansion for the remaining terms' `powers` and
/// the remaining degree `n`: for the first term each `k` from `n` down to `0`, with the
/// binomial `C(n, k)` from `C(n, n) = 1` by `C(n, k - 1) = C(n, k) · k / (n - k + 1)`,
/// times the `scale` and the `factors` chosen so far.
fn push_multinomial_terms(
    powers: &[Vec<(Q, Expr)>],
    n: usize,
    scale: Q,
    factors: &mut Vec<Expr>,
    out: &mut Operands,
) {
    let Some((first, rest)) = powers.split_first() else {
        return;
    };
    if n == 0 {
        // Every remaining term to the power 0: the product so far, without walking them.
        out.push(Expr::mul_all(
            std::iter::once(Expr::num(scale)).chain(factors.iter().cloned()),
        ));
        return;
    }
    // A term's power 0 is the factor 1, left out: a leaf multiplies the at most `n` factors
    // of positive powers, not one per term of the sum (the square of a sum of t terms took
    // t³ steps).
    let chosen = |k: usize, factors: &mut Vec<Expr>| {
        if k > 0 {
            factors.push(first[k].1.clone());
        }
    };
    let unchosen = |k: usize, factors: &mut Vec<Expr>| {
        if k > 0 {
            factors.pop();
        }
    };
    if rest.is_empty() {
        chosen(n, factors);
        let term = Expr::mul_all(
            std::iter::once(Expr::num(&scale * &first[n].0)).chain(factors.iter().cloned()),
        );
        unchosen(n, factors);
        out.push(term);
        return;
    }
    let mut binomial = Q::ONE;
    for k in (0..=n).rev() {
        let c = &first[k].0;
        chosen(k, factors);
        let scale = &(&scale * &binomial) * c;
        push_multinomial_terms(rest, n - k, scale, factors, out);
        unchosen(k, factors);
        if k > 0 {
            let step = Q::new(k as i64, (n - k + 1) as i64).expect("n - k + 1 ≥ 1");
            binomial = &binomial * &step;
        }
    }
}

/// Whether a term holds a power of a sum that is not a negative number (`√(a + 1)`): two
/// such may combine into a whole power of the sum, which is multiplied out in turn. Negative
/// powers (`(a + b)⁻¹`) only combine into negative powers, which stay atoms.
fn has_power_of_sum(t: &Expr) -> bool {
    t.monomial().iter().any(|f| match f.view() {
        View::Pow(base, exponent) => {
            matches!(base.view(), View::Add(_))
                && !exponent.as_num().is_some_and(|q| q.is_negative())
        }
        _ => false,
    })
}

/// The number of monomials of degree `n` in `t` variables, C(t + n - 1, n), as a float
/// so that huge cases do not overflow.
pub(super) fn multinomial_terms(t: usize, n: u64) -> f64 {
    let k = (t as u64 - 1).min(n);
    let top = n + t as u64 - 1;
    (0..k).fold(1.0, |acc, i| acc * (top - i) as f64 / (i + 1) as f64)
}

/// Refuses a sum whose terms, gathered before like terms combine, pass
/// [`MAX_UNCOMBINED_TERMS`].
fn check_uncombined(gathered: usize) -> Result<(), AlgebraError> {
    match gathered > MAX_UNCOMBINED_TERMS {
        true => Err(too_many_uncombined("the sum")),
        false => Ok(()),
    }
}

/// The refusal of an expansion of `what` that gathers more than [`MAX_UNCOMBINED_TERMS`]
/// terms before like terms combine.
fn too_many_uncombined(what: &str) -> AlgebraError {
    AlgebraError::TooLarge {
        what: format!("expanding {what}"),
        size: format!("more than {MAX_UNCOMBINED_TERMS} uncombined"),
        limit: MAX_EXPANDED_TERMS,
    }
}

fn check_size(what: &str, size: f64) -> Result<(), AlgebraError> {
    if size > MAX_EXPANDED_TERMS as f64 {
        return Err(AlgebraError::TooLarge {
            what: format!("expanding {what}"),
            size: if size < 1e9 {
                format!("{size:.0}")
            } else {
                format!("about {size:.1e}")
            },
            limit: MAX_EXPANDED_TERMS,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::arbitrary::expr;
    use proptest::prelude::*;

    /// The product of two expanded expressions, multiplied out term by term: the reference
    /// the multinomial expansion is compared with.
    fn multiply_out(a: &Expr, b: &Expr) -> Result<Expr, AlgebraError> {
        if a.terms().len() == 1 && b.terms().len() == 1 {
            return multiplied_out(a * b);
        }
        Ok(Expr::sum_of_terms(&mut products_of_terms(
            a.terms(),
            b.terms(),
        )?))
    }

    /// The definition the gathered expansion must agree with: every product multiplied out
    /// pair by pair into a canonical sum, every sum added up with [`Expr::add_all`].
    fn pairwise(e: &Expr) -> Expr {
        match e.view() {
            View::Add(terms) => Expr::add_all(terms.iter().map(pairwise)),
            View::Mul(factors) => factors
                .iter()
                .map(pairwise)
                .fold(Expr::one(), |acc, f| multiply_out(&acc, &f).expect("small")),
            _ => e.expand().expect("small"),
        }
    }

    #[test]
    fn common_factors_merge_into_each_term() {
        let s = Expr::symbol;
        let h = s("I_x") * s("w_x") - s("I_xy") * s("w_y");
        let t = Expr::rational(1, 2) * s("w_x") * &h;
        let expected = Expr::rational(1, 2) * s("I_x") * s("w_x").powi(2)
            - Expr::rational(1, 2) * s("I_xy") * s("w_x") * s("w_y");
        assert_eq!(
            format!("{:?}", t.expand().unwrap()),
            format!("{expected:?}")
        );
    }

    /// Powers of one sum that meet in a product combine into the sum or a whole power of
    /// it, which is multiplied out in turn: with `r = √(a + 1)`,
    /// `(x r + 1)(r + 1) = a x + x + x r + r + 1`, `(x r)² = a x² + x²` and
    /// `(r³ - 1)² = (a + 1)³ - 2 r³ + 1` with the cube multiplied out; and expanding
    /// again changes nothing.
    #[test]
    fn powers_of_a_sum_that_combine_are_multiplied_out() {
        let (a, x) = (Expr::symbol("a"), Expr::symbol("x"));
        let one = Expr::one();
        let p = &a + &one;
        let r = p.checked_pow(&Expr::rational(1, 2)).unwrap();
        let cases = [
            (
                (&x * &r + &one) * (&r + &one),
                Expr::add_all([&a * &x, x.clone(), &x * &r, r.clone(), one.clone()]),
            ),
            ((&x * &r).powi(2), &a * x.powi(2) + x.powi(2)),
            (
                (r.powi(3) - &one).powi(2),
                Expr::add_all([
                    a.powi(3),
                    Expr::int(3) * a.powi(2),
                    Expr::int(3) * &a,
                    Expr::int(2),
                    Expr::int(-2) * p.checked_pow(&Expr::rational(3, 2)).unwrap(),
                ]),
            ),
        ];
        for (e, expected) in cases {
            let expanded = e.expand().unwrap();
            assert_eq!(expanded, expected, "{e}");
            assert_eq!(expanded.expand().unwrap(), expanded, "{e}");
        }
    }

    /// The multinomial expansion of a power equals the power multiplied out factor by
    /// factor, coefficients, powers and like terms included.
    #[test]
    fn multinomial_power_is_repeated_multiplication() {
        let s = Expr::symbol;
        let half = Expr::rational(1, 2);
        let bases = [
            s("a") + s("b"),
            Expr::int(2) * s("a") - s("b") * Expr::rational(1, 3) + Expr::one(),
            s("a") + s("a").powi(2) + s("a").powi(3),
            s("x").checked_pow(&half).unwrap() + s("y").powi(-1) + Expr::int(2),
            half * s("x") * s("y") - Expr::int(3) * s("x").powi(2) + s("z"),
            Expr::func(crate::algebra::Func::Sin, s("x")) + s("c"),
            s("a") + s("b") + (s("a") + s("b")).powi(-1) * s("c") - s("d"),
            (s("a") + s("b"))
                .checked_pow(&Expr::rational(-1, 2))
                .unwrap()
                + s("a"),
        ];
        for base in bases {
            for n in [2, 3, 7] {
                let mut product = base.clone();
                for _ in 1..n {
                    product = multiply_out(&product, &base).unwrap();
                }
                let power = base.powi(n).expand().unwrap();
                assert_eq!(format!("{power:?}"), format!("{product:?}"), "({base})^{n}");
            }
        }
    }

    /// Where powers of a sum in the terms combine, the multinomial keeps `mᵏ` as one power
    /// (`√(a + b)³ = (a + b)^(3/2)`) and multiplies out the whole powers
    /// (`√(a + b)² = a + b`): the value of the power, with no whole power of a sum left.
    #[test]
    fn multinomial_power_multiplies_out_whole_powers_of_inner_sums() {
        let s = Expr::symbol;
        let bases = [
            (s("a") + s("b"))
                .checked_pow(&Expr::rational(1, 2))
                .unwrap()
                + s("c"),
            (s("a") + s("b") + s("c"))
                .checked_pow(&Expr::rational(1, 3))
                .unwrap()
                * s("c")
                + s("a")
                - s("d"),
        ];
        let value = |name: &str| match name {
            "a" => 0.7,
            "b" => 1.9,
            "c" => -0.4,
            _ => 1.3,
        };
        let at = |e: &Expr| -> f64 { e.eval(&|x| Some(value(x.name()))).unwrap() };
        for base in bases {
            for n in [2, 3, 7] {
                let power = base.powi(n).expand().unwrap();
                let expected = at(&base).powi(n as i32);
                assert!(
                    (at(&power) - expected).abs() < 1e-12 * expected.abs(),
                    "({base})^{n}"
                );
                assert!(is_multiplied_out(&power), "({base})^{n} = {power}");
            }
        }
        let root = (s("a") + s("b"))
            .checked_pow(&Expr::rational(1, 2))
            .unwrap();
        let cube = (&root + s("c")).powi(3).expand().unwrap();
        assert!(cube.terms().contains(
            &(s("a") + s("b"))
                .checked_pow(&Expr::rational(3, 2))
                .unwrap()
        ));
        assert!(
            cube.terms().contains(&(Expr::int(3) * s("a") * s("c"))),
            "{cube}"
        );
    }

    /// A power too large to multiply out is refused before any work: an exponent beyond
    /// i64 (it recursed until the stack overflowed), too many terms, or too many digits.
    #[test]
    fn huge_powers_are_refused_at_once() {
        let (a, b) = (Expr::symbol("a"), Expr::symbol("b"));
        let huge = Expr::num(Q::parse_decimal("9223372036854775808").unwrap());
        let err = (&a + &b).checked_pow(&huge).unwrap().expand().unwrap_err();
        assert!(matches!(err, AlgebraError::ExponentOutOfRange(_)), "{err}");
        let err = (&a + &b + Expr::one()).powi(1000).expand().unwrap_err();
        assert!(matches!(err, AlgebraError::TooLarge { .. }), "{err}");
        let big = Expr::num(Q::parse_decimal("1e300").unwrap());
        let err = (big * &a + &b).powi(40).expand().unwrap_err();
        assert!(matches!(err, AlgebraError::NumberTooLarge { .. }), "{err}");
        assert_eq!((&a + &b).powi(800).expand().unwrap().terms().len(), 801);
        // 801 terms, few enough, each holding cos of a sum of 3,654 terms: too long.
        let inner = (&a + &b + Expr::symbol("c") + Expr::symbol("d")).powi(26);
        let long = Expr::func(crate::algebra::Func::Cos, inner) * (&a + &b).powi(800);
        let err = long.expand().unwrap_err();
        assert_eq!(err, AlgebraError::ExpansionTooLong(MAX_EXPANDED_NODES));
    }

    proptest! {
        #[test]
        fn gathered_expansion_is_the_pairwise_expansion(e in expr()) {
            let gathered = e.expand().expect("small");
            let reference = pairwise(&e);
            prop_assert_eq!(format!("{gathered:?}"), format!("{reference:?}"));
            prop_assert_eq!(gathered, reference);
        }
    }
}
