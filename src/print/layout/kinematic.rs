//! The kinematic part of a term (rule 1) and the key its group is ordered by (rule 2).
//!
//! A term's kinematic part is its factors that are kinematic symbols (ω, ω̇, α, v, a,
//! angles), unit vectors, powers of them, or functions of arguments that mention them; the
//! rest is its coefficient. Groups are ordered by a key: terms free of kinematic symbols
//! first, accelerations before velocities, translational before rotational, pure powers
//! before mixed products, then by axis x, y, z and mixed pairs in cyclic order xy, yz, zx.

use crate::algebra::{work, Expr, Role, Symbol, View};
use std::cmp::Ordering;

/// The kinematic factors of a term, in canonical order.
#[derive(Clone)]
pub(super) struct KinematicPart<'a>(std::slice::Iter<'a, Expr>);

impl<'a> Iterator for KinematicPart<'a> {
    type Item = &'a Expr;

    fn next(&mut self) -> Option<&'a Expr> {
        self.0.by_ref().find(|f| is_kinematic_factor(f))
    }
}

/// The kinematic part of a term, read in place among its factors.
#[inline]
pub(super) fn kinematic_part(term: &Expr) -> KinematicPart<'_> {
    KinematicPart(term.factors().iter())
}

/// Whether a factor belongs to a term's kinematic part (rule 1): a kinematic symbol or unit
/// vector, a power of one, or a function of an argument that mentions a kinematic symbol.
#[inline]
pub(super) fn is_kinematic_factor(f: &Expr) -> bool {
    match f.base().view() {
        View::Sym(s) => matches!(s.role(), Role::Kinematic | Role::UnitVector),
        View::Func(_, arg) => mentions_kinematic(arg),
        _ => false,
    }
}

/// Whether a kinematic symbol occurs anywhere in `e`.
pub(super) fn mentions_kinematic(e: &Expr) -> bool {
    !kinematic_symbols(e, true).is_empty()
}

/// The kinematic symbols of `e` as met (repeats included), or with `first_only` at most the
/// first. Every node walked counts against the work budget: a function's argument may be as
/// long as the input, and each term of a sum asks about its own.
fn kinematic_symbols(e: &Expr, first_only: bool) -> Vec<Symbol> {
    fn walk(e: &Expr, first_only: bool, nodes: &mut u64, found: &mut Vec<Symbol>) {
        if first_only && !found.is_empty() {
            return;
        }
        *nodes += 1;
        match e.view() {
            View::Num(_) => {}
            View::Sym(s) => {
                if s.role() == Role::Kinematic {
                    found.push(s);
                }
            }
            View::Add(xs) | View::Mul(xs) => {
                xs.iter().for_each(|x| walk(x, first_only, nodes, found));
            }
            View::Pow(b, x) => {
                walk(b, first_only, nodes, found);
                walk(x, first_only, nodes, found);
            }
            View::Func(_, a) => walk(a, first_only, nodes, found),
        }
    }
    let mut nodes = 0;
    let mut found = Vec::new();
    walk(e, first_only, &mut nodes, &mut found);
    work::count(nodes);
    found
}

/// Translational (v, a) before rotational (ω, α) before angles and others.
#[inline]
pub(super) fn family(s: Symbol) -> u8 {
    match s.base() {
        "v" | "a" => 0,
        "w" | "omega" | "Omega" | "alpha" => 1,
        _ => 2,
    }
}

/// Ordering key of a kinematic monomial (rule 2): terms free of kinematic symbols, then
/// accelerations before velocities, the family (translational first), the number of
/// kinematic symbols, and the axis or the cyclic pair of axes; packed into one integer in
/// that order of significance (class and family a byte each, the count 40 bits, the axis a
/// byte), so that comparing keys is one comparison.
pub(super) type KinematicKey = u64;

/// What grouping needs to know of a term, found in one pass over its factors.
pub(super) struct TermShape {
    /// The key of its kinematic part.
    pub(super) key: KinematicKey,
    /// Whether the coefficient is a sum: a single non-kinematic factor that is a sum.
    pub(super) sum_coefficient: bool,
    /// Whether any non-kinematic factor is a sum.
    pub(super) sum_in_coefficient: bool,
}

/// The [`TermShape`] of a term.
#[inline]
pub(super) fn term_shape(term: &Expr) -> TermShape {
    let mut others = 0usize;
    let mut other_is_sum = false;
    let mut sum_in_coefficient = false;
    let mut factor_count = 0usize;
    let mut count = 0usize;
    let mut acceleration = false;
    let mut lowest_family = 2u8;
    // Bit k is set when a symbol on axis k occurs.
    let mut axes = 0u8;
    let mut visit = |s: Symbol| {
        if s.role() == Role::Kinematic {
            count += 1;
            acceleration |= s.is_acceleration();
            lowest_family = lowest_family.min(family(s));
            if let Some(k) = s.axis() {
                axes |= 1 << k;
            }
        }
    };
    for f in term.factors() {
        // As `is_kinematic_factor`, visiting the kinematic symbols on the way.
        let kinematic = match f.base().view() {
            View::Sym(s) => {
                visit(s);
                matches!(s.role(), Role::Kinematic | Role::UnitVector)
            }
            View::Func(_, arg) => {
                let mut found = kinematic_symbols(arg, false);
                found.sort();
                found.dedup();
                found.iter().for_each(|&s| visit(s));
                !found.is_empty()
            }
            _ => false,
        };
        if kinematic {
            factor_count += 1;
        } else if f.as_num().is_none() {
            others += 1;
            other_is_sum = matches!(f.view(), View::Add(_));
            sum_in_coefficient |= other_is_sum;
        }
    }
    let mut shape = TermShape {
        key: 0,
        sum_coefficient: others == 1 && other_is_sum,
        sum_in_coefficient,
    };
    if count == 0 {
        return shape;
    }
    let class = if acceleration { 1 } else { 2 };
    let axis_rank = match axes {
        0b001 | 0b011 => 0,
        0b010 | 0b110 => 1,
        0b100 | 0b101 => 2,
        _ => 3,
    };
    let count = count.min(factor_count).min((1 << 40) - 1) as u64;
    shape.key = (class << 56) | (u64::from(lowest_family) << 48) | (count << 8) | axis_rank;
    shape
}

/// The order of two kinematic parts whose keys tie: the order of their products, without
/// forming them where the order of the factor lists is the same (both empty, both a single
/// factor, or both several factors, whose products are compared factor by factor).
pub(super) fn compare_kinematic_parts(a: KinematicPart, b: KinematicPart) -> Ordering {
    let size = |p: &KinematicPart| p.clone().take(2).count();
    if size(&a) == size(&b) {
        a.cmp(b)
    } else {
        Expr::mul_all(a.cloned()).cmp(&Expr::mul_all(b.cloned()))
    }
}
