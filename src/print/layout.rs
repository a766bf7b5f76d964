//! The presented form of an expression: how a textbook orders and groups it.
//!
//! The canonical form decides; this form is for reading. One set of rules, over structure,
//! reproduces the chapter's forms:
//!
//! 1. A sum is split term by term into a kinematic part (ω, ω̇, α, v, a, angles and
//!    functions of them) and a coefficient (inertia, mass, lengths, numbers). Terms with the
//!    same kinematic part are collected; their coefficient becomes a group such as
//!    `(I_y - I_z)`, with a common factor and a leading minus pulled out of it.
//! 2. Groups are ordered: terms free of kinematic symbols first (`N = W + ...`), then
//!    accelerations before velocities (`I_z α` before `I_yz ω²`), translational before
//!    rotational (`½ m v²` before `½ I_x ω_x²`), pure powers before mixed products
//!    (`ω_x²` before `ω_x ω_y`), then by axis x, y, z, and mixed pairs in cyclic order
//!    xy, yz, zx.
//! 3. Inside a group, inertia symbols are ordered cyclically from the equation's own axis:
//!    moments first (`I_x, I_y, I_z` for the x-equation, `I_y, I_z, I_x` for y), then
//!    products (`I_xy, I_yz, I_xz` for x).
//! 4. In a product: the number, then inertia and mass, other quantities, lengths, groups,
//!    functions, kinematic symbols, unit vectors; factors with negative exponents form a
//!    denominator.

use crate::algebra::{axis_of_subscript, Expr, Func, Role, Symbol, View, Q};
use std::cmp::Ordering;
use std::collections::HashMap;

/// A node of the presented form. Numbers and coefficients here are never negative: signs
/// live on the terms of a [`Layout::Sum`].
#[derive(Debug, Clone, PartialEq)]
pub enum Layout {
    Number(Q),
    Symbol(Symbol),
    /// Terms with their signs (`true` = subtracted); at least two.
    Sum(Vec<(bool, Layout)>),
    Product(Product),
    /// A base to a positive exponent other than 1/2.
    Power(Box<Layout>, Box<Layout>),
    SquareRoot(Box<Layout>),
    Function(Func, Box<Layout>),
}

/// `coefficient · numerator / denominator`, coefficient positive.
#[derive(Debug, Clone, PartialEq)]
pub struct Product {
    pub coefficient: Q,
    pub numerator: Vec<Layout>,
    pub denominator: Vec<Layout>,
}

/// Which equation an expression belongs to, for ordering inertia symbols cyclically.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Axis {
    #[default]
    X,
    Y,
    Z,
}

impl Axis {
    fn index(self) -> usize {
        self as usize
    }

    /// The axis named by a subscript such as `x` in `M_x`, if it names exactly one.
    pub fn from_subscript(subscript: &str) -> Option<Axis> {
        axis_of_subscript(subscript).map(|k| [Axis::X, Axis::Y, Axis::Z][k])
    }
}

/// The presented form of `e` as a signed layout: `(negative, layout)`.
pub fn present(e: &Expr, axis: Axis) -> (bool, Layout) {
    match e.view() {
        View::Add(_) => present_sum(e, axis),
        _ => present_term(e, axis),
    }
}

/// The terms of a sum that share one kinematic part (rule 1).
struct Group<'a> {
    /// The first term with this kinematic part, and any others.
    first: &'a Expr,
    others: Vec<&'a Expr>,
    /// The ordering key of the kinematic part (rule 2).
    key: KinematicKey,
}

/// The kinematic factors of a term, in canonical order.
fn kinematic_part(term: &Expr) -> impl Iterator<Item = &Expr> + Clone {
    term.factors().iter().filter(|f| is_kinematic_factor(f))
}

/// The coefficient of a term: the product of its other factors, number included.
fn coefficient_of(term: &Expr) -> Expr {
    term.without_factors(is_kinematic_factor)
}

/// Whether the coefficient of a term is a sum (a single non-kinematic factor that is a sum).
fn has_sum_coefficient(term: &Expr) -> bool {
    let mut rest = term.monomial().iter().filter(|f| !is_kinematic_factor(f));
    matches!(
        (rest.next().map(Expr::view), rest.next()),
        (Some(View::Add(_)), None)
    )
}

/// Up to this many groups a term's group is found by linear search; beyond, by hashing.
const LINEAR_SEARCH_GROUPS: usize = 32;

fn present_sum(e: &Expr, axis: Axis) -> (bool, Layout) {
    let mut groups: Vec<Group> = Vec::with_capacity(e.terms().len());
    // The groups by kinematic part, filled once there are too many to search linearly.
    let mut index: HashMap<Vec<&Expr>, usize> = HashMap::new();
    for term in e.terms() {
        let kinematic = kinematic_part(term);
        let key = kinematic_key(kinematic.clone());
        let found = if groups.len() <= LINEAR_SEARCH_GROUPS {
            groups
                .iter()
                .position(|g| g.key == key && kinematic_part(g.first).eq(kinematic.clone()))
        } else {
            if index.is_empty() {
                for (at, g) in groups.iter().enumerate() {
                    index.insert(kinematic_part(g.first).collect(), at);
                }
            }
            index.get(&kinematic.clone().collect::<Vec<_>>()).copied()
        };
        match found {
            Some(at) => groups[at].others.push(term),
            None => {
                if !index.is_empty() {
                    index.insert(kinematic.collect(), groups.len());
                }
                groups.push(Group {
                    first: term,
                    others: Vec::new(),
                    key,
                });
            }
        }
    }
    // Keys rarely tie, so the kinematic products that break ties are seldom built.
    groups.sort_by(|a, b| {
        a.key.cmp(&b.key).then_with(|| {
            Expr::mul_all(kinematic_part(a.first).cloned())
                .cmp(&Expr::mul_all(kinematic_part(b.first).cloned()))
        })
    });
    let only_group = groups.len() == 1;
    let mut terms: Vec<(bool, Layout)> = Vec::with_capacity(groups.len());
    for group in groups {
        if group.others.is_empty() && !has_sum_coefficient(group.first) {
            // A coefficient of one term times the kinematic part is the term itself.
            terms.push(present_term(group.first, axis));
            continue;
        }
        let coefficient = match group.others[..] {
            [] => coefficient_of(group.first),
            [second] => coefficient_of(group.first) + coefficient_of(second),
            _ => {
                let members = std::iter::once(group.first).chain(group.others);
                Expr::add_all(members.map(coefficient_of))
            }
        };
        if coefficient.is_zero() {
            continue;
        }
        let kinematic: Vec<Expr> = kinematic_part(group.first).cloned().collect();
        if kinematic.is_empty() && coefficient.terms().len() > 1 {
            // No kinematic part to collect by: the terms stand on their own.
            let mut plain = coefficient.terms().to_vec();
            plain.sort_by(|a, b| compare_coefficient_terms(a, b, axis));
            if only_group && plain[0].coeff_and_factors().0.is_negative() {
                // A sum of coefficients alone (a denominator, a group) starts with a
                // positive term where it has one: `z_2 - z_1`, not `-z_1 + z_2`.
                if let Some(at) = plain
                    .iter()
                    .position(|t| !t.coeff_and_factors().0.is_negative())
                {
                    let first = plain.remove(at);
                    plain.insert(0, first);
                }
            }
            terms.extend(plain.iter().map(|t| present_term(t, axis)));
        } else if coefficient.terms().len() == 1 {
            let factors = coefficient.factors().iter().cloned().chain(kinematic);
            terms.push(present_term(&Expr::mul_all(factors), axis));
        } else {
            terms.push(present_group(&coefficient, &kinematic, axis));
        }
    }
    match terms.len() {
        0 => (false, Layout::Number(Q::ZERO)),
        1 => terms.pop().unwrap_or((false, Layout::Number(Q::ZERO))),
        _ => (false, Layout::Sum(terms)),
    }
}

/// `± common · (group) · kinematic` for a coefficient with several terms.
fn present_group(coefficient: &Expr, kinematic: &[Expr], axis: Axis) -> (bool, Layout) {
    let mut inner: Vec<Expr> = coefficient.terms().to_vec();
    inner.sort_by(|a, b| compare_coefficient_terms(a, b, axis));
    let common = common_factor(&inner);
    let inner: Vec<Expr> = inner.iter().map(|t| t / &common).collect();
    let negative = inner
        .first()
        .is_some_and(|t| t.coeff_and_factors().0.is_negative());
    let group_terms: Vec<(bool, Layout)> = inner
        .iter()
        .map(|t| {
            let (neg, layout) = present_term(t, axis);
            (neg != negative, layout)
        })
        .collect();
    let group = Layout::Sum(group_terms);
    let outer = Expr::mul_all(
        common
            .factors()
            .iter()
            .cloned()
            .chain(kinematic.iter().cloned()),
    );
    let (outer_negative, outer_layout) = present_term(&outer, axis);
    let product = match outer_layout {
        Layout::Product(mut p) => {
            let at = p
                .numerator
                .iter()
                .position(|f| placement(f) > GROUP_PLACE)
                .unwrap_or(p.numerator.len());
            p.numerator.insert(at, group);
            p
        }
        Layout::Number(q) => Product {
            coefficient: q,
            numerator: vec![group],
            denominator: vec![],
        },
        other => {
            let mut numerator = vec![group];
            if placement(&other) > GROUP_PLACE {
                numerator.push(other);
            } else {
                numerator.insert(0, other);
            }
            Product {
                coefficient: Q::ONE,
                numerator,
                denominator: vec![],
            }
        }
    };
    (negative != outer_negative, Layout::Product(product))
}

/// The monomial that divides every term (symbols to their least power), sign excluded.
fn common_factor(terms: &[Expr]) -> Expr {
    let Some(first) = terms.first() else {
        return Expr::one();
    };
    let mut common: Vec<(Expr, Q)> = first
        .coeff_and_factors()
        .1
        .iter()
        .filter_map(|f| {
            let (base, exp) = f.base_and_exponent();
            exp.as_num().map(|q| (base.clone(), q.clone()))
        })
        .collect();
    for term in &terms[1..] {
        let factors = term.coeff_and_factors().1;
        common.retain_mut(|(base, exp)| {
            let found = factors.iter().find_map(|f| {
                let (b, e) = f.base_and_exponent();
                (b == base).then(|| e.as_num().cloned()).flatten()
            });
            match found {
                Some(e) if e.is_negative() == exp.is_negative() => {
                    if (e < *exp) != exp.is_negative() {
                        *exp = e;
                    }
                    true
                }
                _ => false,
            }
        });
    }
    let content = Expr::num(rational_content(terms));
    Expr::mul_all(std::iter::once(content).chain(common.into_iter().map(|(b, e)| power(&b, e))))
}

/// The largest positive rational that divides every coefficient, gcd of the numerators over
/// lcm of the denominators: `1/12 a² + 1/12 d²` has `1/12`, `r²/(8L²) + 3/4` has `1/8`.
fn rational_content(terms: &[Expr]) -> Q {
    use num_integer::Integer;
    let mut numerators = num_bigint::BigInt::from(0);
    let mut denominators = num_bigint::BigInt::from(1);
    for t in terms {
        let (n, d) = t.coeff_and_factors().0.parts();
        numerators = numerators.gcd(&n);
        denominators = denominators.lcm(&d);
    }
    use num_traits::ToPrimitive;
    match (numerators.to_i64(), denominators.to_i64()) {
        (Some(n), Some(d)) if n > 0 => Q::new(n, d).unwrap_or(Q::ONE),
        _ => Q::ONE,
    }
}

fn power(base: &Expr, exponent: Q) -> Expr {
    base.checked_pow(&Expr::num(exponent))
        .unwrap_or_else(|_| Expr::one())
}

/// A single term (no top-level sum) as a signed product.
fn present_term(e: &Expr, axis: Axis) -> (bool, Layout) {
    let negative = e.coefficient().is_negative();
    let coefficient = e.coefficient().abs();
    let factors = e.monomial();
    let mut numerator: Vec<Layout> = Vec::new();
    let mut denominator: Vec<Layout> = Vec::new();
    // The factors with their places, in print order; on the stack unless there are many.
    let mut inline: [(u8, &Expr); 8] = [(0, e); 8];
    let mut spilled: Vec<(u8, &Expr)> = Vec::new();
    let placed = factors.iter().map(|f| (expr_place(f), f));
    let ordered: &mut [(u8, &Expr)] = if factors.len() <= inline.len() {
        inline
            .iter_mut()
            .zip(placed)
            .for_each(|(slot, f)| *slot = f);
        &mut inline[..factors.len()]
    } else {
        spilled.extend(placed);
        &mut spilled
    };
    ordered.sort_by(|(pa, a), (pb, b)| pa.cmp(pb).then_with(|| compare_in_place(a, b)));
    cyclic_pair_order(ordered);
    for &(_, f) in ordered.iter() {
        let View::Pow(base, exponent) = f.view() else {
            numerator.push(present_atom(f, axis));
            continue;
        };
        match exponent.as_num() {
            Some(q) if q.is_negative() => denominator.push(present_power(base, &q.abs(), axis)),
            Some(q) => numerator.push(present_power(base, q, axis)),
            None => numerator.push(Layout::Power(
                Box::new(present_atom(base, axis)),
                Box::new(present_signed_inline(exponent, axis)),
            )),
        }
    }
    if numerator.is_empty() && denominator.is_empty() {
        return (negative, Layout::Number(coefficient));
    }
    if coefficient.is_one() && denominator.is_empty() && numerator.len() == 1 {
        return (negative, numerator.pop().unwrap_or(Layout::Number(Q::ONE)));
    }
    (
        negative,
        Layout::Product(Product {
            coefficient,
            numerator,
            denominator,
        }),
    )
}

fn present_power(base: &Expr, exponent: &Q, axis: Axis) -> Layout {
    let base_layout = present_atom(base, axis);
    if exponent.is_one() {
        base_layout
    } else if *exponent == Q::Small(1, 2) {
        Layout::SquareRoot(Box::new(present_signed_inline(base, axis)))
    } else {
        Layout::Power(
            Box::new(base_layout),
            Box::new(Layout::Number(exponent.clone())),
        )
    }
}

/// A factor or base: a symbol, a number, a function, or a parenthesised sum.
fn present_atom(e: &Expr, axis: Axis) -> Layout {
    match e.view() {
        View::Sym(s) => Layout::Symbol(s),
        View::Num(q) if !q.is_negative() && q.is_integer() => Layout::Number(q.clone()),
        View::Func(f, arg) => Layout::Function(f, Box::new(present_signed_inline(arg, axis))),
        _ => present_signed_inline(e, axis),
    }
}

/// An expression that must stand as one unit; a leading minus becomes part of a sum.
fn present_signed_inline(e: &Expr, axis: Axis) -> Layout {
    match present(e, axis) {
        (false, l) => l,
        (true, Layout::Sum(mut terms)) => {
            terms.iter_mut().for_each(|t| t.0 = !t.0);
            Layout::Sum(terms)
        }
        (true, l) => Layout::Sum(vec![(true, l)]),
    }
}

fn is_kinematic_factor(f: &Expr) -> bool {
    match f.base().view() {
        View::Sym(s) => matches!(s.role(), Role::Kinematic | Role::UnitVector),
        View::Func(_, arg) => arg.symbols().iter().any(|s| s.role() == Role::Kinematic),
        _ => false,
    }
}

/// Where a factor stands in a product (rule 4).
const GROUP_PLACE: u8 = 6;

fn placement(l: &Layout) -> u8 {
    match l {
        Layout::Number(_) => 0,
        Layout::Symbol(s) => symbol_place(*s),
        Layout::Power(b, _) => placement(b),
        Layout::SquareRoot(b) => placement(b).min(GROUP_PLACE),
        Layout::Sum(_) | Layout::Product(_) => GROUP_PLACE,
        Layout::Function(..) => 7,
    }
}

fn symbol_place(s: Symbol) -> u8 {
    match s.role() {
        Role::Inertia => 1,
        Role::Mass => 2,
        // The interval Δt follows the force or couple it multiplies: `F \Delta t`.
        Role::Other => 3,
        Role::Length => 4,
        Role::Kinematic => 8,
        Role::UnitVector => 9,
    }
}

fn expr_place(e: &Expr) -> u8 {
    match e.base().view() {
        View::Num(_) => 0,
        View::Sym(s) => symbol_place(s),
        View::Func(_, arg) if arg.symbols().iter().any(|s| s.role() == Role::Kinematic) => 8,
        View::Func(..) => 7,
        _ => GROUP_PLACE,
    }
}

/// Translational (v, a) before rotational (ω, α) before angles and others.
fn family(s: Symbol) -> u8 {
    match s.base() {
        "v" | "a" => 0,
        "w" | "omega" | "Omega" | "alpha" => 1,
        _ => 2,
    }
}

/// The order of two factors with the same place in a product (rule 4).
fn compare_in_place(a: &Expr, b: &Expr) -> Ordering {
    let (sa, sb) = (a.base().as_symbol(), b.base().as_symbol());
    match (sa, sb) {
        (Some(x), Some(y)) if x.role() == Role::Kinematic && y.role() == Role::Kinematic => {
            family(x)
                .cmp(&family(y))
                .then_with(|| x.axis().cmp(&y.axis()))
                .then_with(|| x.cmp(&y))
        }
        (Some(x), Some(y)) if x.role() == Role::Inertia && y.role() == Role::Inertia => {
            inertia_key(x, Axis::X).cmp(&inertia_key(y, Axis::X))
        }
        (Some(x), Some(y)) => (x.base() == "Dt")
            .cmp(&(y.base() == "Dt"))
            .then_with(|| x.cmp(&y)),
        _ => a.cmp(b),
    }
}

/// Two kinematic factors on the axes z and x are written `ω_z ω_x` (cyclic order zx).
fn cyclic_pair_order(factors: &mut [(u8, &Expr)]) {
    let (first, second, third) = {
        let mut kinematic = (0..factors.len()).filter(|&i| factors[i].0 == 8);
        (kinematic.next(), kinematic.next(), kinematic.next())
    };
    if let (Some(i), Some(j), None) = (first, second, third) {
        let axis = |k: usize| factors[k].1.base().as_symbol().and_then(Symbol::axis);
        if axis(i) == Some(0) && axis(j) == Some(2) {
            factors.swap(i, j);
        }
    }
}

/// Ordering key of a kinematic monomial (rule 2): terms free of kinematic symbols, then
/// accelerations before velocities, the family (translational first), the number of
/// kinematic symbols, and the axis or the cyclic pair of axes.
type KinematicKey = (u8, u8, usize, usize);

fn kinematic_key<'a>(factors: impl Iterator<Item = &'a Expr>) -> KinematicKey {
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
    for f in factors {
        factor_count += 1;
        match f.base().as_symbol() {
            Some(s) => visit(s),
            None => f.base().symbols().into_iter().for_each(&mut visit),
        }
    }
    if count == 0 {
        return (0, 0, 0, 0);
    }
    let class = if acceleration { 1 } else { 2 };
    let axis_rank = match axes {
        0b001 | 0b011 => 0,
        0b010 | 0b110 => 1,
        0b100 | 0b101 => 2,
        _ => 3,
    };
    (class, lowest_family, count.min(factor_count), axis_rank)
}

/// Ordering key of an inertia symbol for the equation about `axis` (rule 3).
fn inertia_key(s: Symbol, axis: Axis) -> (u8, usize, Symbol) {
    let a = axis.index();
    let subscript = s.subscript();
    // The axes the subscript names, in order: the first two and how many.
    let mut named = [0usize; 2];
    let mut count = 0;
    for k in subscript.chars().filter_map(axis_of_letter) {
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
fn axis_of_letter(c: char) -> Option<usize> {
    match c {
        'x' | 'X' => Some(0),
        'y' | 'Y' => Some(1),
        'z' | 'Z' => Some(2),
        _ => None,
    }
}

fn compare_coefficient_terms(a: &Expr, b: &Expr, axis: Axis) -> Ordering {
    let key = |e: &Expr| {
        e.monomial()
            .iter()
            .filter_map(|f| f.base().as_symbol())
            .filter(|s| s.role() == Role::Inertia)
            .map(|s| inertia_key(s, axis))
            .min()
    };
    match (key(a), key(b)) {
        (Some(x), Some(y)) => x.cmp(&y),
        (Some(_), None) => Ordering::Less,
        (None, Some(_)) => Ordering::Greater,
        (None, None) => compare_lexicographic(a.monomial(), b.monomial()),
    }
}

/// Lexicographic order of monomials, higher powers first: `a^3, a^2 b, a b^2, b^3`.
fn compare_lexicographic(a: &[Expr], b: &[Expr]) -> Ordering {
    for (x, y) in a.iter().zip(b.iter()) {
        let ((bx, ex), (by, ey)) = (x.base_and_exponent(), y.base_and_exponent());
        let order = bx.cmp(by).then_with(|| ey.cmp(&ex));
        if order != Ordering::Equal {
            return order;
        }
    }
    b.len().cmp(&a.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Σ (a + b) ω_i over more kinematic parts than a linear search handles: the groups
    /// found through the hash index collect exactly like the first ones.
    #[test]
    fn many_kinematic_parts_collect_alike() {
        let n = 2 * LINEAR_SEARCH_GROUPS;
        let (a, b) = (Expr::symbol("a"), Expr::symbol("b"));
        let e = Expr::add_all((1..=n).flat_map(|i| {
            let w = Expr::symbol(&format!("w_{i}"));
            [&a * &w, &b * &w]
        }));
        let printed = crate::print::text(&e);
        for i in 1..=n {
            assert!(
                printed.contains(&format!("(a + b)*w_{i} "))
                    || printed.ends_with(&format!("(a + b)*w_{i}")),
                "w_{i} in {printed}"
            );
        }
        assert_eq!(printed.matches(" + (a + b)").count(), n - 1, "{printed}");
    }
}
