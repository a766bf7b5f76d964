//! Sums and products of two canonical expressions by merging their sorted operand lists.
//!
//! The terms of a canonical sum are ordered by monomial and the factors of a canonical
//! product by base, each at most once. So `a + b` is one merge of the two term lists,
//! adding the coefficients of a monomial found in both, and `a · b` is one merge of the two
//! factor lists, adding the exponents of a symbol found in both: `O(n + m)` comparisons and
//! no sort. When the lists share nothing (the usual case) the operands are gathered as
//! references on the stack, so the new node is the only allocation; a product that adds
//! exponents gathers its factors in a buffer on the stack too. A product whose lists
//! share a base other than a symbol to a numeric power (a power of a number, a sum or a
//! function on both sides) goes through [`Expr::mul_all`]; the results always equal
//! [`Expr::add_all`] and [`Expr::mul_all`] of the two operands.

use super::expr::{cmp_operands, cmp_slices, Expr};
use super::rational::Q;
use smallvec::SmallVec;
use std::borrow::{Borrow, Cow};
use std::cmp::Ordering;

/// How many operands a merge gathers on the stack; longer merges use a vector.
const INLINE: usize = 16;

/// The canonical sum `a + b`.
pub(super) fn sum(a: &Expr, b: &Expr) -> Expr {
    let (ca, ta) = split_constant(a.terms());
    let (cb, tb) = split_constant(b.terms());
    if ca.is_zero() && cb.is_zero() && ta.len() + tb.len() <= INLINE {
        let mut merged = [a; INLINE];
        let by_monomial = |x: &Expr, y: &Expr| cmp_slices(x.monomial(), y.monomial());
        if let Some(n) = merge_disjoint(ta, tb, &mut merged, by_monomial) {
            return Expr::sum_of_sorted(&merged[..n]);
        }
    }
    let mut out: Vec<Expr> = Vec::with_capacity(ta.len() + tb.len() + 1);
    let constant = ca + cb;
    if !constant.is_zero() {
        out.push(Expr::num(constant));
    }
    let (mut i, mut j) = (0, 0);
    while i < ta.len() && j < tb.len() {
        match cmp_slices(ta[i].monomial(), tb[j].monomial()) {
            Ordering::Less => {
                out.push(ta[i].clone());
                i += 1;
            }
            Ordering::Greater => {
                out.push(tb[j].clone());
                j += 1;
            }
            Ordering::Equal => {
                let coeff = ta[i].coefficient() + tb[j].coefficient();
                if !coeff.is_zero() {
                    out.push(Expr::term(coeff, ta[i].monomial()));
                }
                i += 1;
                j += 1;
            }
        }
    }
    out.extend_from_slice(&ta[i..]);
    out.extend_from_slice(&tb[j..]);
    Expr::sum_of_sorted(&out)
}

/// The constant of a list of terms (at most one, first) and the other terms.
fn split_constant(terms: &[Expr]) -> (&Q, &[Expr]) {
    match terms.split_first() {
        Some((first, rest)) if first.as_num().is_some() => (first.coefficient(), rest),
        _ => (&Q::ZERO, terms),
    }
}

/// The canonical product `a · b`.
pub(super) fn product(a: &Expr, b: &Expr) -> Expr {
    scaled_product(a.coefficient(), a.monomial(), b)
}

/// The canonical product `coeff · Π factors · b`, where `factors` are in canonical order
/// with distinct bases, none a number or a product (the monomial of a canonical term, or
/// part of one): `a · b` is `scaled_product(a.coefficient(), a.monomial(), b)`, and an
/// expansion multiplies the common factors of a product into each term of a sum this way
/// without forming their product first.
pub(super) fn scaled_product<F: Borrow<Expr>>(coeff: &Q, factors: &[F], b: &Expr) -> Expr {
    let coeff = coeff * b.coefficient();
    if coeff.is_zero() {
        return Expr::zero();
    }
    let (fa, fb) = (factors, b.monomial());
    if fa.len() + fb.len() <= INLINE {
        let mut merged = [b; INLINE];
        let by_base = |x: &Expr, y: &Expr| cmp_operands(x.base(), y.base());
        if let Some(n) = merge_disjoint(fa, fb, &mut merged, by_base) {
            return Expr::product_of_sorted(coeff, &merged[..n]);
        }
    }
    let mut out: SmallVec<[Cow<Expr>; INLINE]> = SmallVec::with_capacity(fa.len() + fb.len());
    let (mut i, mut j) = (0, 0);
    while i < fa.len() && j < fb.len() {
        let x = fa[i].borrow();
        match cmp_operands(x.base(), fb[j].base()) {
            Ordering::Less => {
                out.push(Cow::Borrowed(x));
                i += 1;
            }
            Ordering::Greater => {
                out.push(Cow::Borrowed(&fb[j]));
                j += 1;
            }
            Ordering::Equal => {
                match symbol_power_product(x, &fb[j]) {
                    Some(Some(power)) => out.push(Cow::Owned(power)),
                    Some(None) => {}
                    None => {
                        let all = fa.iter().map(|f| f.borrow()).chain(fb);
                        return Expr::mul_all(
                            std::iter::once(Expr::num(coeff)).chain(all.cloned()),
                        );
                    }
                }
                i += 1;
                j += 1;
            }
        }
    }
    for f in &fa[i..] {
        out.push(Cow::Borrowed(f.borrow()));
    }
    for f in &fb[j..] {
        out.push(Cow::Borrowed(f));
    }
    Expr::product_of_sorted(coeff, &out)
}

/// Merges two lists, each strictly increasing in `order`, into `out` (long enough for
/// both) when no element of one is equal in `order` to an element of the other: the
/// merged length, or `None` at the first such pair.
fn merge_disjoint<'a, F: Borrow<Expr>>(
    a: &'a [F],
    b: &'a [Expr],
    out: &mut [&'a Expr],
    order: impl Fn(&Expr, &Expr) -> Ordering,
) -> Option<usize> {
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match order(a[i].borrow(), &b[j]) {
            Ordering::Less => {
                out[i + j] = a[i].borrow();
                i += 1;
            }
            Ordering::Greater => {
                out[i + j] = &b[j];
                j += 1;
            }
            Ordering::Equal => return None,
        }
    }
    let rest = a[i..].iter().map(|x| x.borrow()).chain(&b[j..]);
    for (slot, x) in out[i + j..].iter_mut().zip(rest) {
        *slot = x;
    }
    Some(a.len() + b.len())
}

/// `s^p · s^q = s^(p+q)` for a symbol `s` and numbers `p`, `q`: `Some(None)` when the
/// powers cancel, `None` when the factors are not two numeric powers of one symbol.
fn symbol_power_product(x: &Expr, y: &Expr) -> Option<Option<Expr>> {
    let s = x.base().as_symbol()?;
    let exponent = x.numeric_exponent()? + y.numeric_exponent()?;
    Some((!exponent.is_zero()).then(|| Expr::symbol_power(s, &exponent)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::arbitrary::expr;
    use proptest::prelude::*;

    #[test]
    fn long_merges_spill_to_the_heap() {
        let powers = |name: &str| Expr::add_all((1..=10).map(|n| Expr::symbol(name).powi(n)));
        let (a, b) = (powers("x"), powers("y"));
        assert_eq!(sum(&a, &b), Expr::add_all([a.clone(), b.clone()]));
        assert_eq!(sum(&a, &b).terms().len(), 20);
        let monomial = |names: &[&str]| Expr::mul_all(names.iter().map(|n| Expr::symbol(n)));
        let p = monomial(&["a", "c", "e", "g", "i", "k", "m"]);
        let q = monomial(&["b", "d", "f", "h", "j", "l", "n"]);
        assert_eq!(product(&p, &q), Expr::mul_all([p.clone(), q.clone()]));
        assert_eq!(product(&p, &q).factors().len(), 14);
    }

    proptest! {
        #[test]
        fn merged_sum_is_the_general_sum(a in expr(), b in expr()) {
            let merged = sum(&a, &b);
            let general = Expr::add_all([a, b]);
            prop_assert_eq!(format!("{merged:?}"), format!("{general:?}"));
            prop_assert_eq!(merged, general);
        }

        #[test]
        fn merged_product_is_the_general_product(a in expr(), b in expr()) {
            let merged = product(&a, &b);
            let general = Expr::mul_all([a, b]);
            prop_assert_eq!(format!("{merged:?}"), format!("{general:?}"));
            prop_assert_eq!(merged, general);
        }
    }
}
