//! `Expr`: an immutable expression, cheap to clone, always in canonical form.
//!
//! Its representation is private to this module and its children, so the constructors of
//! `canonical.rs` are the only way in: every `Expr` is canonical by construction. Here are
//! the type, the borrowed [`View`] of its top node, the accessors (a term's coefficient and
//! monomial, the terms of a sum, the factors of a product, base and exponent) and the total
//! order operands are sorted by: numbers < symbols < powers < products < sums < functions,
//! two nodes of one kind compared operand by operand, a shorter list first on a common prefix.

use super::function::Func;
use super::rational::Q;
use super::symbol::Symbol;
use smallvec::SmallVec;
use std::cmp::Ordering;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

mod canonical;

/// Operands gathered before they become one sum or product node: short lists (the usual
/// case) stay on the stack.
pub(super) type Operands = SmallVec<[Expr; 16]>;

/// An expression in canonical form. See the module documentation.
#[derive(Clone)]
pub struct Expr(Repr);

#[derive(Clone)]
enum Repr {
    Num(Q),
    Sym(Symbol),
    Add(Arc<[Expr]>),
    Mul(Arc<[Expr]>),
    Pow(Arc<(Expr, Expr)>),
    Func(Func, Arc<Expr>),
}

/// A borrowed look at the top node of an expression.
#[derive(Clone, Copy, Debug)]
pub enum View<'a> {
    Num(&'a Q),
    Sym(Symbol),
    /// At least two terms; at most one number, first.
    Add(&'a [Expr]),
    /// At least two factors; at most one number (never 0 or 1), first.
    Mul(&'a [Expr]),
    Pow(&'a Expr, &'a Expr),
    Func(Func, &'a Expr),
}

impl Expr {
    pub fn num(q: Q) -> Expr {
        Expr(Repr::Num(q))
    }

    pub fn int(n: i64) -> Expr {
        Expr::num(Q::int(n))
    }

    /// The rational `num/den`. Panics when `den` is zero (a programming error; parsed input
    /// goes through [`Expr::checked_div`]).
    pub fn rational(num: i64, den: i64) -> Expr {
        Expr::num(Q::new(num, den).expect("rational with zero denominator"))
    }

    pub fn sym(s: Symbol) -> Expr {
        Expr(Repr::Sym(s))
    }

    /// The symbol with this ASCII name, as an expression.
    pub fn symbol(name: &str) -> Expr {
        Expr::sym(Symbol::new(name))
    }

    pub fn zero() -> Expr {
        Expr::num(Q::ZERO)
    }

    pub fn one() -> Expr {
        Expr::num(Q::ONE)
    }

    pub fn view(&self) -> View<'_> {
        match &self.0 {
            Repr::Num(q) => View::Num(q),
            Repr::Sym(s) => View::Sym(*s),
            Repr::Add(t) => View::Add(t),
            Repr::Mul(f) => View::Mul(f),
            Repr::Pow(p) => View::Pow(&p.0, &p.1),
            Repr::Func(f, a) => View::Func(*f, a),
        }
    }

    pub fn as_num(&self) -> Option<&Q> {
        match &self.0 {
            Repr::Num(q) => Some(q),
            _ => None,
        }
    }

    pub fn as_symbol(&self) -> Option<Symbol> {
        match &self.0 {
            Repr::Sym(s) => Some(*s),
            _ => None,
        }
    }

    pub fn is_zero(&self) -> bool {
        matches!(&self.0, Repr::Num(q) if q.is_zero())
    }

    pub fn is_one(&self) -> bool {
        matches!(&self.0, Repr::Num(q) if q.is_one())
    }

    /// Splits a term into its numeric coefficient and the remaining factors:
    /// `-3 x y` gives `(-3, [x, y])`, `x` gives `(1, [x])`, `5` gives `(5, [])`.
    pub fn coeff_and_factors(&self) -> (Q, &[Expr]) {
        (self.coefficient().clone(), self.monomial())
    }

    /// The numeric coefficient of a term: `-3` for `-3 x y`, `1` for `x`, `5` for `5`.
    pub fn coefficient(&self) -> &Q {
        static ONE: Q = Q::ONE;
        match &self.0 {
            Repr::Num(q) => q,
            Repr::Mul(f) => match &f[0].0 {
                Repr::Num(q) => q,
                _ => &ONE,
            },
            _ => &ONE,
        }
    }

    /// The factors of a term after its numeric coefficient: `[x, y]` for `-3 x y`, `[x]`
    /// for `x`, `[]` for a number. Like terms of a sum have equal monomials.
    pub fn monomial(&self) -> &[Expr] {
        match &self.0 {
            Repr::Num(_) => &[],
            Repr::Mul(f) => match &f[0].0 {
                Repr::Num(_) => &f[1..],
                _ => f,
            },
            _ => std::slice::from_ref(self),
        }
    }

    /// The terms of a sum, or the expression itself as a single term.
    pub fn terms(&self) -> &[Expr] {
        match &self.0 {
            Repr::Add(t) => t,
            _ => std::slice::from_ref(self),
        }
    }

    /// The factors of a product (coefficient included), or the expression itself.
    pub fn factors(&self) -> &[Expr] {
        match &self.0 {
            Repr::Mul(f) => f,
            _ => std::slice::from_ref(self),
        }
    }

    /// Base and exponent: `x^n` gives `(x, n)`, anything else `(self, 1)`.
    pub fn base_and_exponent(&self) -> (&Expr, Expr) {
        match &self.0 {
            Repr::Pow(p) => (&p.0, p.1.clone()),
            _ => (self, Expr::one()),
        }
    }

    /// The exponent when it is a number: `n` for `x^n`, 1 for anything not a power, none
    /// for a power with a symbolic exponent.
    pub(super) fn numeric_exponent(&self) -> Option<&Q> {
        static ONE: Q = Q::ONE;
        match &self.0 {
            Repr::Pow(p) => p.1.as_num(),
            _ => Some(&ONE),
        }
    }

    /// The base of a power, or the expression itself: `x` for `x^n` and for `x`. Factors
    /// of a product are ordered by their bases.
    pub fn base(&self) -> &Expr {
        match &self.0 {
            Repr::Pow(p) => &p.0,
            _ => self,
        }
    }

    fn rank(&self) -> u8 {
        match &self.0 {
            Repr::Num(_) => 0,
            Repr::Sym(_) => 1,
            Repr::Pow(_) => 2,
            Repr::Mul(_) => 3,
            Repr::Add(_) => 4,
            Repr::Func(..) => 5,
        }
    }
}

/// `x.cmp(y)`, with the common case of two symbols decided inline.
#[inline]
pub(crate) fn cmp_operands(x: &Expr, y: &Expr) -> Ordering {
    match (&x.0, &y.0) {
        (Repr::Sym(p), Repr::Sym(q)) => p.cmp(q),
        _ => x.cmp(y),
    }
}

/// Lexicographic order of two slices of expressions, shorter first on a common prefix.
pub(crate) fn cmp_slices(a: &[Expr], b: &[Expr]) -> Ordering {
    for (x, y) in a.iter().zip(b.iter()) {
        match cmp_operands(x, y) {
            Ordering::Equal => {}
            other => return other,
        }
    }
    a.len().cmp(&b.len())
}

impl Ord for Expr {
    fn cmp(&self, other: &Expr) -> Ordering {
        match (&self.0, &other.0) {
            (Repr::Num(a), Repr::Num(b)) => a.cmp(b),
            (Repr::Sym(a), Repr::Sym(b)) => a.cmp(b),
            (Repr::Add(a), Repr::Add(b)) | (Repr::Mul(a), Repr::Mul(b)) => {
                if Arc::ptr_eq(a, b) {
                    Ordering::Equal
                } else {
                    cmp_slices(a, b)
                }
            }
            (Repr::Pow(a), Repr::Pow(b)) => {
                if Arc::ptr_eq(a, b) {
                    Ordering::Equal
                } else {
                    cmp_operands(&a.0, &b.0).then_with(|| a.1.cmp(&b.1))
                }
            }
            (Repr::Func(f, a), Repr::Func(g, b)) => {
                if Arc::ptr_eq(a, b) {
                    f.cmp(g)
                } else {
                    f.cmp(g).then_with(|| a.cmp(b))
                }
            }
            _ => self.rank().cmp(&other.rank()),
        }
    }
}

impl PartialOrd for Expr {
    fn partial_cmp(&self, other: &Expr) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq for Expr {
    fn eq(&self, other: &Expr) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Expr {}

impl Hash for Expr {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.rank().hash(state);
        match &self.0 {
            Repr::Num(q) => q.hash(state),
            Repr::Sym(s) => s.hash(state),
            Repr::Add(xs) | Repr::Mul(xs) => xs.iter().for_each(|x| x.hash(state)),
            Repr::Pow(p) => {
                p.0.hash(state);
                p.1.hash(state);
            }
            Repr::Func(f, a) => {
                f.hash(state);
                a.hash(state);
            }
        }
    }
}

impl From<Symbol> for Expr {
    fn from(s: Symbol) -> Expr {
        Expr::sym(s)
    }
}

impl From<i64> for Expr {
    fn from(n: i64) -> Expr {
        Expr::int(n)
    }
}

impl From<Q> for Expr {
    fn from(q: Q) -> Expr {
        Expr::num(q)
    }
}
