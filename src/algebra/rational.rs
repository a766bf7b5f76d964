//! Exact rational numbers `p/q` (`q > 0`, `gcd(p, q) = 1`).
//!
//! Small values live in two machine words; an operation that would overflow moves to a big
//! integer representation, and a result that fits again moves back. The algebra never
//! rounds: a decimal such as `0.1` is the rational `1/10`.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

/// An exact rational number.
#[derive(Clone)]
pub enum Q {
    /// `num/den` with `den > 0` and `gcd(num, den) = 1`.
    Small(i64, i64),
    /// A value that does not fit `Small`; never holds a value that would.
    Big(Arc<BigRational>),
}

/// Largest number of bits a folded power `p^n` may have; larger powers stay symbolic.
pub const MAX_POWER_BITS: u64 = 4096;

impl Q {
    pub const ZERO: Q = Q::Small(0, 1);
    pub const ONE: Q = Q::Small(1, 1);
    pub const MINUS_ONE: Q = Q::Small(-1, 1);

    /// The integer `n`.
    pub fn int(n: i64) -> Q {
        Q::Small(n, 1)
    }

    /// `num/den` reduced; `None` when `den` is zero.
    pub fn new(num: i64, den: i64) -> Option<Q> {
        if den == 0 {
            return None;
        }
        Some(Q::from_i128(num.into(), den.into()))
    }

    /// The number of bits of the numerator's magnitude and of the denominator.
    pub fn bit_lengths(&self) -> (u64, u64) {
        match self {
            Q::Small(n, d) => {
                let bits = |x: i64| u64::from(64 - x.unsigned_abs().leading_zeros());
                (bits(*n), bits(*d))
            }
            Q::Big(b) => (b.numer().bits(), b.denom().bits()),
        }
    }

    pub(super) fn from_big(r: BigRational) -> Q {
        match (r.numer().to_i64(), r.denom().to_i64()) {
            (Some(n), Some(d)) => Q::Small(n, d),
            _ => Q::Big(Arc::new(r)),
        }
    }

    fn to_big(&self) -> BigRational {
        match self {
            Q::Small(n, d) => BigRational::new_raw((*n).into(), (*d).into()),
            Q::Big(b) => (**b).clone(),
        }
    }

    /// Reduces `n/d` (`d != 0`) computed in 128-bit arithmetic.
    fn from_i128(n: i128, d: i128) -> Q {
        let g = n.gcd(&d);
        let (mut n, mut d) = (n / g, d / g);
        if d < 0 {
            n = -n;
            d = -d;
        }
        match (i64::try_from(n), i64::try_from(d)) {
            (Ok(n), Ok(d)) => Q::Small(n, d),
            // Reduced above, with `d > 0`.
            _ => Q::from_big(BigRational::new_raw(n.into(), d.into())),
        }
    }

    pub fn is_zero(&self) -> bool {
        matches!(self, Q::Small(0, _))
    }

    pub fn is_one(&self) -> bool {
        matches!(self, Q::Small(1, 1))
    }

    pub fn is_negative(&self) -> bool {
        match self {
            Q::Small(n, _) => *n < 0,
            Q::Big(b) => b.is_negative(),
        }
    }

    pub fn is_integer(&self) -> bool {
        match self {
            Q::Small(_, d) => *d == 1,
            Q::Big(b) => b.is_integer(),
        }
    }

    /// The value as an `i64` when it is an integer that fits.
    pub fn to_i64(&self) -> Option<i64> {
        match self {
            Q::Small(n, 1) => Some(*n),
            _ => None,
        }
    }

    /// Numerator and denominator as big integers.
    pub fn parts(&self) -> (BigInt, BigInt) {
        let b = self.to_big();
        (b.numer().clone(), b.denom().clone())
    }

    /// The numerator as a rational (an integer), keeping the sign.
    pub fn numer(&self) -> Q {
        match self {
            Q::Small(n, _) => Q::int(*n),
            Q::Big(b) => Q::from_big(BigRational::from_integer(b.numer().clone())),
        }
    }

    /// The denominator as a rational (a positive integer).
    pub fn denom(&self) -> Q {
        match self {
            Q::Small(_, d) => Q::int(*d),
            Q::Big(b) => Q::from_big(BigRational::from_integer(b.denom().clone())),
        }
    }

    /// The nearest `f64` (correctly rounded for small values, to within an ulp otherwise).
    pub fn to_f64(&self) -> f64 {
        match self {
            Q::Small(n, d) => *n as f64 / *d as f64,
            Q::Big(b) => big_to_f64(b),
        }
    }

    pub fn abs(&self) -> Q {
        if self.is_negative() {
            -self
        } else {
            self.clone()
        }
    }

    /// `1/self`, or `None` for zero.
    pub fn recip(&self) -> Option<Q> {
        match self {
            Q::Small(0, _) => None,
            Q::Small(n, d) => Some(Q::from_i128(*d as i128, *n as i128)),
            Q::Big(b) => Some(Q::from_big(b.recip())),
        }
    }

    /// The greatest common divisor of two integers, non-negative (`gcd(0, 0) = 0`); the
    /// coefficients of the polynomials are integers, and their contents are such gcds.
    pub(in crate::algebra) fn integer_gcd(&self, other: &Q) -> Q {
        debug_assert!(self.is_integer() && other.is_integer());
        match (self, other) {
            (Q::Small(a, 1), Q::Small(b, 1)) => {
                Q::from_i128(i128::from(a.unsigned_abs().gcd(&b.unsigned_abs())), 1)
            }
            _ => Q::from_big(BigRational::from_integer(unbalanced_gcd(
                &self.parts().0,
                &other.parts().0,
            ))),
        }
    }

    /// `self mod m` in `0..m` for integers, `m > 0`: a digit of `self` in base `m`.
    pub(in crate::algebra) fn integer_rem_euclid(&self, m: &Q) -> Q {
        debug_assert!(self.is_integer() && m.is_integer() && !m.is_negative() && !m.is_zero());
        match (self, m) {
            (Q::Small(a, 1), Q::Small(b, 1)) => Q::int(a.rem_euclid(*b)),
            _ => {
                let (a, b) = (self.parts().0, m.parts().0);
                Q::from_big(BigRational::from_integer(a.mod_floor(&b)))
            }
        }
    }

    /// `self / other`, or `None` when `other` is zero.
    pub fn checked_div(&self, other: &Q) -> Option<Q> {
        Some(self * &other.recip()?)
    }

    /// `self^n` for an integer `n`; `None` for `0^n` with `n < 0` or when the result would
    /// have more than `MAX_POWER_BITS` (4096) bits.
    pub fn checked_pow(&self, n: i64) -> Option<Q> {
        if n == 0 {
            return Some(Q::ONE);
        }
        let base = if n < 0 { self.recip()? } else { self.clone() };
        let (num, den) = base.parts();
        let bits = num.bits().max(den.bits()).max(1);
        if bits.saturating_mul(n.unsigned_abs()) > MAX_POWER_BITS {
            return None;
        }
        let e = n.unsigned_abs() as usize;
        // Powers of coprime integers are coprime, and `den > 0`: already in lowest terms.
        Some(Q::from_big(BigRational::new_raw(
            num_traits::pow(num, e),
            num_traits::pow(den, e),
        )))
    }

    /// The exact `k`-th root when `self` is a perfect `k`-th power (sign allowed for odd `k`).
    pub fn exact_root(&self, k: u32) -> Option<Q> {
        if k == 0 || (self.is_negative() && k.is_multiple_of(2)) {
            return None;
        }
        let (num, den) = self.parts();
        let root = |x: &BigInt| -> Option<BigInt> {
            let r = x.nth_root(k);
            (num_traits::pow(r.clone(), k as usize) == *x).then_some(r)
        };
        // Roots of coprime integers are coprime, and the denominator's root is positive.
        Some(Q::from_big(BigRational::new_raw(root(&num)?, root(&den)?)))
    }
}

/// `n/d` in lowest terms with a positive denominator, for `d != 0`.
pub(super) fn reduced_big(n: BigInt, d: BigInt) -> Q {
    let g = unbalanced_gcd(&n, &d);
    let (mut n, mut d) = if g.is_one() { (n, d) } else { (n / &g, d / &g) };
    if d.is_negative() {
        n = -n;
        d = -d;
    }
    Q::from_big(BigRational::new_raw(n, d))
}

/// `gcd(a, b)`, cheap when one is much shorter than the other: one Euclidean step
/// (`a mod b`) first, so the binary gcd that follows runs on numbers no longer than the
/// shorter one. (The binary gcd alone costs the square of the longer one's length:
/// `gcd(10^60000, 1)` took seconds.)
fn unbalanced_gcd(a: &BigInt, b: &BigInt) -> BigInt {
    let (a, b) = (a.abs(), b.abs());
    let (long, short) = if a.bits() >= b.bits() { (a, b) } else { (b, a) };
    if short.is_zero() || short.is_one() {
        return if short.is_zero() { long } else { short };
    }
    // The division's words and the binary gcd's square of the shorter length, counted
    // against the work budget: numbers of thousands of digits make each gcd costly.
    let words = |n: &BigInt| n.bits() / 64 + 1;
    let (long_words, short_words) = (words(&long), words(&short));
    super::work::count(long_words * short_words + short_words * short_words);
    (long % &short).gcd(&short)
}

/// `(a/b)(c/d)` for fractions in lowest terms: cancelling across first (`gcd(a, d)`,
/// `gcd(c, b)`) leaves the product in lowest terms; integers need no gcd at all.
fn big_product(x: &Q, y: &Q) -> Q {
    let ((a, b), (c, d)) = (x.parts(), y.parts());
    if b.is_one() && d.is_one() {
        return Q::from_big(BigRational::from_integer(a * c));
    }
    let (g, h) = (unbalanced_gcd(&a, &d), unbalanced_gcd(&c, &b));
    Q::from_big(BigRational::new_raw(
        (a / &g) * (c / &h),
        (b / &h) * (d / &g),
    ))
}

/// `a/b + c/d` for fractions in lowest terms; integers need no gcd.
fn big_sum(x: &Q, y: &Q) -> Q {
    let ((a, b), (c, d)) = (x.parts(), y.parts());
    if b.is_one() && d.is_one() {
        return Q::from_big(BigRational::from_integer(a + c));
    }
    reduced_big(a * &d + c * &b, b * d)
}

fn big_to_f64(b: &BigRational) -> f64 {
    match (b.numer().to_f64(), b.denom().to_f64()) {
        (Some(n), Some(d)) if n.is_finite() && d.is_finite() => n / d,
        _ => {
            // Scale both parts down to a common exponent before dividing.
            let shift = b.numer().bits().max(b.denom().bits()).saturating_sub(1000);
            let n = (b.numer() >> shift).to_f64().unwrap_or(f64::NAN);
            let d = (b.denom() >> shift).to_f64().unwrap_or(f64::NAN);
            n / d
        }
    }
}

impl PartialEq for Q {
    fn eq(&self, other: &Q) -> bool {
        match (self, other) {
            (Q::Small(a, b), Q::Small(c, d)) => a == c && b == d,
            (Q::Big(a), Q::Big(b)) => a == b,
            _ => false,
        }
    }
}

impl Eq for Q {}

impl Hash for Q {
    fn hash<H: Hasher>(&self, state: &mut H) {
        match self {
            Q::Small(n, d) => {
                n.hash(state);
                d.hash(state);
            }
            Q::Big(b) => b.hash(state),
        }
    }
}

impl Ord for Q {
    fn cmp(&self, other: &Q) -> Ordering {
        match (self, other) {
            (Q::Small(a, b), Q::Small(c, d)) => {
                (*a as i128 * *d as i128).cmp(&(*c as i128 * *b as i128))
            }
            _ => self.to_big().cmp(&other.to_big()),
        }
    }
}

impl PartialOrd for Q {
    fn partial_cmp(&self, other: &Q) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl std::ops::Add for &Q {
    type Output = Q;
    fn add(self, other: &Q) -> Q {
        match (self, other) {
            // Zero, the start of every sum of coefficients, is common enough to skip the gcd.
            (Q::Small(0, _), x) | (x, Q::Small(0, _)) => x.clone(),
            (Q::Small(a, b), Q::Small(c, d)) => {
                if b == d {
                    match a.checked_add(*c) {
                        Some(n) if *b == 1 => Q::Small(n, 1),
                        Some(n) => {
                            let g = n.gcd(b);
                            Q::Small(n / g, b / g)
                        }
                        None => Q::from_i128(*a as i128 + *c as i128, *b as i128),
                    }
                } else {
                    let (a, b, c, d) = (*a as i128, *b as i128, *c as i128, *d as i128);
                    Q::from_i128(a * d + c * b, b * d)
                }
            }
            _ => big_sum(self, other),
        }
    }
}

impl std::ops::Sub for &Q {
    type Output = Q;
    fn sub(self, other: &Q) -> Q {
        self + &(-other)
    }
}

impl std::ops::Mul for &Q {
    type Output = Q;
    #[inline(always)]
    fn mul(self, other: &Q) -> Q {
        match (self, other) {
            (Q::Small(a, b), Q::Small(c, d)) => small_product(*a, *b, *c, *d),
            _ => big_product(self, other),
        }
    }
}

/// `(a/b)(c/d)` for reduced fractions. The products of the usual coefficients (integers,
/// `±1` times a fraction) are decided inline, without a gcd.
#[inline(always)]
fn small_product(a: i64, b: i64, c: i64, d: i64) -> Q {
    match (a, b, c, d) {
        (a, 1, c, 1) => match a.checked_mul(c) {
            Some(n) => Q::Small(n, 1),
            None => Q::from_i128(a as i128 * c as i128, 1),
        },
        // ±1 times p/q is ±p/q, already reduced (-p overflows only for i64::MIN).
        (1, 1, n, d) | (n, d, 1, 1) => Q::Small(n, d),
        (-1, 1, n, d) | (n, d, -1, 1) if n != i64::MIN => Q::Small(-n, d),
        _ => reduced_product(a, b, c, d),
    }
}

/// `(a/b)(c/d)` for reduced fractions: cancelling across first leaves a reduced result,
/// since `gcd(a/g, d/g) = 1` and `gcd(c/h, b/h) = 1` with `g = gcd(a, d)`, `h = gcd(c, b)`.
#[inline(never)]
fn reduced_product(a: i64, b: i64, c: i64, d: i64) -> Q {
    let (g, h) = (a.gcd(&d), c.gcd(&b));
    let n = (a / g).checked_mul(c / h);
    let m = (b / h).checked_mul(d / g);
    match (n, m) {
        (Some(n), Some(m)) => Q::Small(n, m),
        _ => Q::from_i128(a as i128 * c as i128, b as i128 * d as i128),
    }
}

impl std::ops::Neg for &Q {
    type Output = Q;
    fn neg(self) -> Q {
        match self {
            Q::Small(n, d) => match n.checked_neg() {
                Some(m) => Q::Small(m, *d),
                None => Q::from_i128(-(*n as i128), *d as i128),
            },
            Q::Big(b) => Q::from_big(-(**b).clone()),
        }
    }
}

impl fmt::Display for Q {
    /// `p` for integers, `p/q` otherwise.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Q::Small(n, 1) => write!(f, "{n}"),
            Q::Small(n, d) => write!(f, "{n}/{d}"),
            Q::Big(b) if b.is_integer() => write!(f, "{}", b.numer()),
            Q::Big(b) => write!(f, "{}/{}", b.numer(), b.denom()),
        }
    }
}

impl fmt::Debug for Q {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl From<i64> for Q {
    fn from(n: i64) -> Q {
        Q::int(n)
    }
}

impl One for Q {
    fn one() -> Q {
        Q::ONE
    }
}

impl Zero for Q {
    fn zero() -> Q {
        Q::ZERO
    }
    fn is_zero(&self) -> bool {
        Q::is_zero(self)
    }
}

impl std::ops::Mul for Q {
    type Output = Q;
    fn mul(self, other: Q) -> Q {
        &self * &other
    }
}

impl std::ops::Add for Q {
    type Output = Q;
    fn add(self, other: Q) -> Q {
        &self + &other
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_are_exact() {
        assert_eq!(Q::parse_decimal("0.1"), Q::new(1, 10));
        assert_eq!(Q::parse_decimal("1.5e-3"), Q::new(3, 2000));
        assert_eq!(Q::parse_decimal(".5"), Q::new(1, 2));
        assert_eq!(Q::parse_decimal("2.4"), Q::new(12, 5));
        assert_eq!(Q::parse_decimal("."), None);
    }

    #[test]
    fn overflow_moves_to_big_and_back() {
        let big = &Q::int(i64::MAX) * &Q::int(4);
        assert!(matches!(big, Q::Big(_)));
        let back = big.checked_div(&Q::int(8)).unwrap();
        assert_eq!(back, Q::new(i64::MAX, 2).unwrap());
        assert_eq!(
            &(&Q::int(i64::MIN) + &Q::int(-1)) - &Q::int(-1),
            Q::int(i64::MIN)
        );
    }

    #[test]
    fn products_are_reduced() {
        let q = |n, d| Q::new(n, d).unwrap();
        assert_eq!(&q(2, 3) * &q(9, 4), q(3, 2));
        assert_eq!(&q(-1, 2) * &q(2, 1), Q::MINUS_ONE);
        assert_eq!(&Q::ZERO * &q(3, 4), Q::ZERO);
        assert_eq!(&q(3, 4) * &Q::ZERO, Q::ZERO);
        assert_eq!(&q(1, 2) + &q(1, 2), Q::ONE);
        assert_eq!(&q(1, 6) + &q(1, 6), q(1, 3));
        assert_eq!(&q(1, 6) + &q(-1, 6), Q::ZERO);
        assert_eq!(q(i64::MIN, -2), q(i64::MIN / -2, 1));
        let huge = &q(i64::MAX, 3) * &q(i64::MAX, 5);
        assert!(matches!(huge, Q::Big(_)));
        assert_eq!(huge.checked_div(&q(i64::MAX, 5)), Some(q(i64::MAX, 3)));
    }

    proptest::proptest! {
        #[test]
        fn sums_and_products_agree_with_big_rationals(
            a in proptest::prop_oneof![-2i64..3, proptest::num::i64::ANY],
            b in 1i64..7,
            c in proptest::prop_oneof![-2i64..3, proptest::num::i64::ANY],
            d in 1i64..7,
        ) {
            let (x, y) = (Q::new(a, b).unwrap(), Q::new(c, d).unwrap());
            let (bx, by) = (x.to_big(), y.to_big());
            proptest::prop_assert_eq!((&x + &y).to_big(), &bx + &by);
            proptest::prop_assert_eq!((&x * &y).to_big(), &bx * &by);
        }
    }

    /// Big products and sums cancel across and stay in lowest terms; integers need no gcd,
    /// so a product of many huge integers is fast (it took seconds by the binary gcd).
    #[test]
    fn big_products_and_sums_are_reduced() {
        let ten = |e: i64| Q::parse_decimal(&format!("1e{e}")).unwrap();
        let third = Q::new(1, 3).unwrap();
        let x = &ten(400) * &third;
        let y = &Q::int(3) * &ten(-399);
        assert_eq!(&x * &y, Q::int(10));
        let half = &ten(-400) + &ten(-400);
        assert_eq!(half, &Q::int(2) * &ten(-400));
        assert_eq!(half.parts().0, BigInt::one());
        assert_eq!(&(&ten(400) + &Q::ONE) - &ten(400), Q::ONE);
        let mut p = Q::ONE;
        for _ in 0..30 {
            p = &p * &ten(308);
        }
        let power = num_traits::pow(BigInt::from(10), 308 * 30);
        assert_eq!(p, Q::from_big(BigRational::from_integer(power)));
    }

    proptest::proptest! {
        /// The big paths (cross-cancelled products, sums without a gcd for integers).
        #[test]
        fn big_sums_and_products_agree_with_big_rationals(
            a in proptest::num::i64::ANY,
            b in 1i64..1000,
            c in proptest::num::i64::ANY,
            d in 1i64..1000,
            k in 0usize..60,
        ) {
            let scale = Q::from_big(BigRational::from_integer(num_traits::pow(BigInt::from(10), k)));
            let x = &Q::new(a, b).unwrap() * &scale;
            let y = Q::new(c, d).unwrap().checked_div(&scale).unwrap();
            let (bx, by) = (x.to_big(), y.to_big());
            proptest::prop_assert_eq!((&x + &y).to_big(), &bx + &by);
            proptest::prop_assert_eq!((&x * &y).to_big(), &bx * &by);
            proptest::prop_assert_eq!((&x * &x).to_big(), &bx * &bx);
            proptest::prop_assert_eq!((&y + &y).to_big(), &by + &by);
        }
    }

    #[test]
    fn powers_and_roots() {
        assert_eq!(Q::new(2, 3).unwrap().checked_pow(-2), Q::new(9, 4));
        assert_eq!(Q::ZERO.checked_pow(-1), None);
        assert_eq!(Q::int(2).checked_pow(100_000), None);
        assert_eq!(Q::new(4, 9).unwrap().exact_root(2), Q::new(2, 3));
        assert_eq!(Q::int(2).exact_root(2), None);
        assert_eq!(Q::int(-8).exact_root(3), Some(Q::int(-2)));
    }
}
