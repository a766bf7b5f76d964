//! The constructors that keep every `Expr` canonical (sums, products, powers, quotients,
//! functions); each returns the canonical form:
//!
//! - sums and products are n-ary and flat (no sum directly inside a sum, no product directly
//!   inside a product), their operands sorted by a fixed total order;
//! - like terms are combined (`2x + 3x = 5x`, `x - x = 0`) and so are powers of a common
//!   base (`x·x² = x³`, `x^0 = 1`, `x^1 = x`);
//! - numbers are exact rationals and are folded (`0·x = 0`), a product holds at most one, first;
//! - a number times a sum is distributed (`2(x + y) = 2x + 2y`), so `(a+b) - (a+b) = 0`.
//!
//! Products of sums are not multiplied out on construction; [`Expr::expand`] does that, and
//! the expanded form decides equality of polynomials (and of expressions whose denominators
//! are monomials): two such expressions are equal exactly when their expansions are
//! identical.
//!
//! ```
//! use kinetics::algebra::Expr;
//! let x = Expr::symbol("x");
//! let y = Expr::symbol("y");
//! assert_eq!(&x + &y - &x, y);
//! assert_eq!(&x * &x * &x, x.powi(3));
//! assert!((&(&x + &y) * &(&x - &y)).expand().unwrap() == x.powi(2) - y.powi(2));
//! ```

use super::{cmp_slices, Expr, Operands, Repr};
use crate::algebra::{work, AlgebraError, Func, Symbol, Q};
use std::borrow::Borrow;
use std::sync::Arc;

impl Expr {
    /// The term with the factors for which `drop` holds taken out, its numeric coefficient
    /// kept: `-2 I_xy w_x w_y` without its kinematic factors is `-2 I_xy`. Equal to
    /// [`Expr::mul_all`] of the remaining factors, without sorting them again.
    pub fn without_factors(&self, drop: impl Fn(&Expr) -> bool) -> Expr {
        let kept: Vec<&Expr> = self.monomial().iter().filter(|f| !drop(f)).collect();
        Expr::product_of_sorted(self.coefficient().clone(), &kept)
    }

    /// The canonical sum of the given terms.
    pub fn add_all<I: IntoIterator<Item = Expr>>(terms: I) -> Expr {
        let terms = terms.into_iter();
        let mut flat = Operands::with_capacity(terms.size_hint().0);
        let mut constant = Q::ZERO;
        for t in terms {
            match &t.0 {
                Repr::Add(inner) => {
                    for u in inner.iter() {
                        match &u.0 {
                            Repr::Num(q) => constant = &constant + q,
                            _ => flat.push(u.clone()),
                        }
                    }
                }
                Repr::Num(q) => constant = &constant + q,
                _ => flat.push(t),
            }
        }
        Expr::sum_of_like_terms(constant, &mut flat)
    }

    /// The canonical sum of terms that are not sums (numbers allowed), moved out of `terms`.
    pub(in crate::algebra) fn sum_of_terms(terms: &mut Operands) -> Expr {
        let (mut sums, mut numbers) = (false, false);
        for t in terms.iter() {
            sums |= matches!(t.0, Repr::Add(_));
            numbers |= matches!(t.0, Repr::Num(_));
        }
        if sums {
            return Expr::add_all(terms.drain(..));
        }
        let mut constant = Q::ZERO;
        if numbers {
            terms.retain(|t| match &t.0 {
                Repr::Num(q) => {
                    constant = &constant + q;
                    false
                }
                _ => true,
            });
        }
        Expr::sum_of_like_terms(constant, terms)
    }

    /// `constant + Σ terms` for terms that are neither numbers nor sums, in any order:
    /// sorts them by monomial, combines like terms in place and moves them into the sum.
    /// Terms already in strictly increasing order (a row of a matrix product, say) have
    /// distinct monomials, so they need neither the sort nor the combining.
    fn sum_of_like_terms(constant: Q, terms: &mut Operands) -> Expr {
        let by_monomial = |a: &Expr, b: &Expr| cmp_slices(a.monomial(), b.monomial());
        let mut kept = terms.len();
        if !terms.windows(2).all(|w| by_monomial(&w[0], &w[1]).is_lt()) {
            // Terms with equal monomials are combined below, so their order does not matter.
            work::count(comparisons_to_sort(terms.len()));
            terms.sort_unstable_by(by_monomial);
            kept = combine_like_terms(terms);
        }
        let constant = (!constant.is_zero()).then(|| Expr::num(constant));
        let mut take = |i: usize| std::mem::replace(&mut terms[i], Expr::zero());
        match (constant, kept) {
            (None, 0) => Expr::zero(),
            (Some(c), 0) => c,
            (None, 1) => take(0),
            (c, _) => Expr(Repr::Add(node_operands(c, kept, take))),
        }
    }

    /// The canonical product of the given factors.
    pub fn mul_all<I: IntoIterator<Item = Expr>>(factors: I) -> Expr {
        let factors = factors.into_iter();
        let mut coeff = Q::ONE;
        let mut flat: Vec<Expr> = Vec::with_capacity(factors.size_hint().0);
        for f in factors {
            match &f.0 {
                Repr::Num(q) => coeff = &coeff * q,
                Repr::Mul(inner) => {
                    for g in inner.iter() {
                        match &g.0 {
                            Repr::Num(q) => coeff = &coeff * q,
                            _ => flat.push(g.clone()),
                        }
                    }
                }
                _ => flat.push(f),
            }
        }
        if coeff.is_zero() {
            return Expr::zero();
        }
        // The sort, and the comparisons of neighbours that merge like bases.
        work::count(comparisons_to_sort(flat.len()) + flat.len() as u64);
        flat.sort_by(|a, b| a.base().cmp(b.base()));
        let mut out: Vec<Expr> = Vec::with_capacity(flat.len() + 1);
        let mut merged = false;
        let mut renormalise = false;
        let mut i = 0;
        while i < flat.len() {
            let base = flat[i].base();
            let mut j = i + 1;
            while j < flat.len() && flat[j].base() == base {
                j += 1;
            }
            if j == i + 1 {
                out.push(flat[i].clone());
            } else {
                merged = true;
                let exponent = Expr::add_all(flat[i..j].iter().map(|f| f.base_and_exponent().1));
                let power = power_or_unevaluated(base, &exponent);
                match &power.0 {
                    Repr::Num(q) => coeff = &coeff * q,
                    Repr::Mul(_) => {
                        renormalise = true;
                        out.push(power);
                    }
                    _ => out.push(power),
                }
            }
            i = j;
        }
        if merged {
            out.sort_by(|a, b| a.base().cmp(b.base()));
            // A merged power may have a new base that another factor has too:
            // `x² · √(x²) · √(x²)` merges the roots into `x²`, whose base is `x`.
            renormalise |= out.windows(2).any(|w| w[0].base() == w[1].base());
        }
        if renormalise {
            out.push(Expr::num(coeff));
            return Expr::mul_all(out);
        }
        Expr::product_of_sorted(coeff, &out)
    }

    /// `coeff · factors` in canonical form, for factors in canonical order with distinct
    /// bases, none of them a number or a product.
    pub(in crate::algebra) fn product_of_sorted<F: Borrow<Expr>>(coeff: Q, factors: &[F]) -> Expr {
        if coeff.is_zero() {
            return Expr::zero();
        }
        match factors {
            [] => Expr::num(coeff),
            [only] => {
                let only = only.borrow();
                if coeff.is_one() {
                    return only.clone();
                }
                if let Repr::Add(terms) = &only.0 {
                    // A number times a sum is distributed, so that sums cancel as wholes.
                    // Scaling keeps the terms' monomials, so their order and distinctness.
                    let c = Expr::num(coeff);
                    return Expr(Repr::Add(terms.iter().map(|t| &c * t).collect()));
                }
                Expr(Repr::Mul(operands(Some(Expr::num(coeff)), factors)))
            }
            _ => {
                let coeff = (!coeff.is_one()).then(|| Expr::num(coeff));
                Expr(Repr::Mul(operands(coeff, factors)))
            }
        }
    }

    /// The canonical sum of terms in canonical order with distinct monomials, none zero.
    #[inline]
    pub(in crate::algebra) fn sum_of_sorted<T: Borrow<Expr>>(terms: &[T]) -> Expr {
        match terms {
            [] => Expr::zero(),
            [only] => only.borrow().clone(),
            _ => Expr(Repr::Add(operands(None, terms))),
        }
    }

    /// `coeff · monomial` as a canonical term, for the monomial of a canonical term.
    pub(in crate::algebra) fn term(coeff: Q, monomial: &[Expr]) -> Expr {
        Expr::product_of_sorted(coeff, monomial)
    }

    /// `self^exponent`, or an error for `0` to a negative power.
    pub fn checked_pow(&self, exponent: &Expr) -> Result<Expr, AlgebraError> {
        if self.is_zero() {
            if let Some(e) = exponent.as_num() {
                if e.is_negative() {
                    return Err(AlgebraError::DivisionByZero);
                }
            }
        }
        Ok(power_or_unevaluated(self, exponent))
    }

    /// `self^n` for an integer `n`. Panics for `0^n` with `n < 0` (a programming error;
    /// parsed input goes through [`Expr::checked_pow`]).
    pub fn powi(&self, n: i64) -> Expr {
        self.checked_pow(&Expr::int(n))
            .expect("zero raised to a negative power")
    }

    /// `self / other`, or an error when `other` is zero.
    pub fn checked_div(&self, other: &Expr) -> Result<Expr, AlgebraError> {
        if other.is_one() {
            return Ok(self.clone());
        }
        Ok(Expr::mul_all([
            self.clone(),
            other.checked_pow(&Expr::int(-1))?,
        ]))
    }

    /// `f(arg)` with the function's simplifications applied.
    pub fn func(f: Func, arg: Expr) -> Expr {
        f.apply(arg)
    }

    /// A function node with no simplification; only for [`Func::apply`].
    pub(crate) fn func_node(f: Func, arg: Expr) -> Expr {
        work::count(1);
        Expr(Repr::Func(f, Arc::new(arg)))
    }
}

/// Combines runs of like terms in terms sorted by monomial, moving the results to the
/// front; returns how many there are (terms whose coefficients cancel are dropped).
fn combine_like_terms(terms: &mut Operands) -> usize {
    let mut kept = 0;
    let mut i = 0;
    while i < terms.len() {
        let mut j = i + 1;
        while j < terms.len() && cmp_slices(terms[j].monomial(), terms[i].monomial()).is_eq() {
            j += 1;
        }
        // Once the work budget is spent, like terms are left apart: their coefficients may be
        // numbers of thousands of digits, each sum a costly gcd, and the result is refused
        // whole by the budget's run anyway (`work::Budget::run`).
        if j == i + 1 || work::count_and_spent(0) {
            for k in i..j {
                terms.swap(kept, k);
                kept += 1;
            }
        } else {
            let coeff = terms[i..j]
                .iter()
                .fold(Q::ZERO, |sum, t| &sum + t.coefficient());
            if !coeff.is_zero() {
                terms[kept] = Expr::term(coeff, terms[i].monomial());
                kept += 1;
            }
        }
        i = j;
    }
    kept
}

/// The comparisons a sort of `n` operands takes, `n log₂ n`, for the work budget.
fn comparisons_to_sort(n: usize) -> u64 {
    let n = n as u64;
    n * u64::from(n.max(1).ilog2())
}

/// The operands of a sum or product node: `first` (a coefficient), then copies of `rest`.
#[inline]
fn operands<T: Borrow<Expr>>(first: Option<Expr>, rest: &[T]) -> Arc<[Expr]> {
    node_operands(first, rest.len(), |i| rest[i].borrow().clone())
}

/// The operands of a sum or product node: `first` (a coefficient), then `at(0)`, …,
/// `at(len - 1)`. The usual short lists are built as arrays, without an iterator.
#[inline(always)]
fn node_operands(
    first: Option<Expr>,
    len: usize,
    mut at: impl FnMut(usize) -> Expr,
) -> Arc<[Expr]> {
    work::count(len as u64 + 1);
    match (first, len) {
        (None, 2) => Arc::new([at(0), at(1)]),
        (None, 3) => Arc::new([at(0), at(1), at(2)]),
        (None, 4) => Arc::new([at(0), at(1), at(2), at(3)]),
        (None, 5) => Arc::new([at(0), at(1), at(2), at(3), at(4)]),
        (Some(c), 1) => Arc::new([c, at(0)]),
        (Some(c), 2) => Arc::new([c, at(0), at(1)]),
        (Some(c), 3) => Arc::new([c, at(0), at(1), at(2)]),
        (first, _) => first.into_iter().chain((0..len).map(at)).collect(),
    }
}

/// `base^exponent` in canonical form; a numeric power too large to fold, or `0` to a
/// negative power, stays as an unevaluated power node.
fn power_or_unevaluated(base: &Expr, exponent: &Expr) -> Expr {
    if exponent.is_zero() {
        return Expr::one();
    }
    if exponent.is_one() {
        return base.clone();
    }
    if base.is_one() {
        return Expr::one();
    }
    let int_exp = exponent.as_num().and_then(Q::to_i64);
    match (&base.0, exponent.as_num()) {
        (Repr::Num(b), Some(e)) => {
            if b.is_zero() && !e.is_negative() {
                return Expr::zero();
            }
            if let Some(n) = int_exp {
                if let Some(v) = b.checked_pow(n) {
                    return Expr::num(v);
                }
            } else if let (Some(p), Some(q)) = (e.numer().to_i64(), e.denom().to_i64()) {
                if let Some(root) = u32::try_from(q).ok().and_then(|q| b.exact_root(q)) {
                    if let Some(v) = root.checked_pow(p) {
                        return Expr::num(v);
                    }
                }
                if let Some(split) = whole_part_of_numeric_power(b, p, q) {
                    return split;
                }
            }
        }
        (Repr::Pow(p), _) if int_exp.is_some() => {
            let combined = Expr::mul_all([p.1.clone(), exponent.clone()]);
            return power_or_unevaluated(&p.0, &combined);
        }
        (Repr::Mul(factors), _) if int_exp.is_some() => {
            return Expr::mul_all(factors.iter().map(|f| power_or_unevaluated(f, exponent)));
        }
        (Repr::Sym(s), Some(e)) => return Expr::symbol_power(*s, e),
        _ => {}
    }
    power_node(base.clone(), exponent.clone())
}

impl Expr {
    /// `s^e` in canonical form for a symbol `s` and a number `e`: `1` for `e = 0`, `s` for
    /// `e = 1`, the power node otherwise.
    pub(in crate::algebra) fn symbol_power(s: Symbol, e: &Q) -> Expr {
        if e.is_zero() {
            Expr::one()
        } else if e.is_one() {
            Expr::sym(s)
        } else {
            power_node(Expr::sym(s), Expr::num(e.clone()))
        }
    }
}

/// `b^(p/q)` for a positive number `b` that is no perfect `q`-th power, written as SymPy
/// writes it, with the exponent's whole part `k = ⌊p/q⌋` taken out as a number:
/// `b^(p/q) = b^k · b^(p/q − k)`, `0 < p/q − k < 1` (`2^(-2/3) = 2^(1/3)/2`), so that
/// `2 · 2^(-2/3)` and `√2 √2 2^(-2/3)` are both `2^(1/3)`. None when the exponent is
/// already in (0, 1), or when `b^k` is too long to fold.
fn whole_part_of_numeric_power(b: &Q, p: i64, q: i64) -> Option<Expr> {
    let whole = p.div_euclid(q);
    if whole == 0 || b.is_negative() {
        return None;
    }
    let factor = b.checked_pow(whole)?;
    let fraction = Q::new(p.rem_euclid(q), q)?;
    let root = power_node(Expr::num(b.clone()), Expr::num(fraction));
    Some(Expr::product_of_sorted(factor, &[root]))
}

/// The unevaluated node `base^exponent`.
fn power_node(base: Expr, exponent: Expr) -> Expr {
    work::count(1);
    Expr(Repr::Pow(Arc::new((base, exponent))))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::View;

    fn s(n: &str) -> Expr {
        Expr::symbol(n)
    }

    #[test]
    fn like_terms_and_powers_combine() {
        let (x, y) = (s("x"), s("y"));
        assert_eq!(
            Expr::add_all([x.clone(), x.clone(), y.clone()]),
            Expr::add_all([Expr::mul_all([Expr::int(2), x.clone()]), y.clone()])
        );
        assert!(Expr::add_all([x.clone(), Expr::mul_all([Expr::int(-1), x.clone()])]).is_zero());
        assert_eq!(Expr::mul_all([x.clone(), x.clone(), x.clone()]), x.powi(3));
        assert!(x.powi(0).is_one());
        assert_eq!(x.powi(1), x);
        assert!(Expr::mul_all([Expr::zero(), x.clone()]).is_zero());
    }

    /// Powers merged into one whose base is new merge again with the factors of that
    /// base: `x² · √(x²) · √(x²) = x⁴`, in any order of the factors.
    #[test]
    fn merged_powers_merge_with_the_factors_of_their_new_base() {
        let x2 = s("x").powi(2);
        let root = x2.checked_pow(&Expr::rational(1, 2)).unwrap();
        let expected = s("x").powi(4);
        assert_eq!(
            Expr::mul_all([x2.clone(), root.clone(), root.clone()]),
            expected
        );
        assert_eq!(
            Expr::mul_all([root.clone(), s("y"), x2.clone(), root.clone()]),
            Expr::mul_all([expected, s("y")])
        );
    }

    #[test]
    fn sums_cancel_as_wholes_and_roots_fold() {
        let sum = Expr::add_all([s("a"), s("b")]);
        let neg = Expr::mul_all([Expr::int(-1), sum.clone()]);
        assert!(Expr::add_all([sum, neg]).is_zero());
        let root2 = Expr::int(2).checked_pow(&Expr::rational(1, 2)).unwrap();
        assert_eq!(Expr::mul_all([root2.clone(), root2]), Expr::int(2));
        assert_eq!(
            Expr::int(4).checked_pow(&Expr::rational(1, 2)).unwrap(),
            Expr::int(2)
        );
    }

    #[test]
    fn zero_to_negative_power_is_an_error() {
        assert_eq!(
            Expr::zero().checked_pow(&Expr::int(-1)),
            Err(AlgebraError::DivisionByZero)
        );
        assert!(Expr::one().checked_div(&Expr::zero()).is_err());
    }

    #[test]
    fn huge_numeric_power_stays_symbolic() {
        let p = Expr::int(2).checked_pow(&Expr::int(99_999_999)).unwrap();
        assert!(matches!(p.view(), View::Pow(..)));
    }
}
