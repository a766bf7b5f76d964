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
//! 5. A sum in a denominator is written term by term (in the order of rule 2), never
//!    collected: `1/(I_x*theta - theta)`, not `1/((I_x - 1)*theta)`. A group is a product,
//!    and the reciprocal of a product reads back as the product of the reciprocals, a
//!    different canonical form from the reciprocal of the sum (and expanding does not join
//!    them), so the printed text would not parse back to the expression.
//! 6. A function's argument that is a sum is collected as any sum, unless it collects into
//!    a single negative group: then it is written term by term, since the group's minus
//!    would leave the function by its parity when read back. So is such a sum standing as
//!    a factor or a base: `sin(a*(1/theta - I_xy/theta))`, not `sin(a*(-(I_xy - 1)/theta))`.
//! 7. In a product whose denominator holds a sum, a sum in the numerator is written term by
//!    term: `(a*w_x - w_x)/(a - 1)`, not `((a - 1)*w_x)/(a - 1)`, whose group reads back as
//!    a factor that cancels the denominator (the canonical form does not cancel a sum
//!    against a factor of another sum, so the expression itself keeps both).
//!
//! The form is built bottom-up into a [`Layout`]: nodes in one vector, the terms of each sum
//! and the factors of each product as a contiguous run in another, children collected on a
//! stack until their parent is made. The rules read the expression through borrowed views;
//! a group's coefficient is read in place from its members (`coefficient.rs`), and
//! only a coefficient whose members hold sums, or a common factor other than one, is formed
//! as a new expression.

use super::coefficient::{self, inertia_key, CoefficientTerm};
use crate::algebra::{Axis, Expr, Func, Role, Symbol, View, Q};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;
use smallvec::SmallVec;
use std::cmp::Ordering;
use std::collections::HashMap;
use std::sync::Arc;

/// The presented form of one expression: its nodes, stored flat so that presenting an
/// expression allocates nothing once a [`Layout`] has grown to size (the printers keep one
/// per thread and [`Layout::clear`] it between expressions).
#[derive(Debug, Default)]
pub struct Layout {
    nodes: Vec<Node>,
    /// The signed terms of sums and the factors of products, each node's run contiguous.
    entries: Vec<(bool, NodeId)>,
    /// The children of the nodes being built, innermost last (a stack).
    pending: Vec<(bool, NodeId)>,
    /// The groups of the sums being presented, innermost last (a stack).
    groups: Vec<Group>,
    /// For each term of the sums being presented, the next term of its group, or
    /// [`NO_MEMBER`] (a stack).
    next_member: Vec<u32>,
    /// The numbers too big for a [`Number`] to hold in place.
    big_numbers: Vec<Arc<BigRational>>,
}

/// A number of a [`Layout`]: a small rational in place, a big one in the layout's table, so
/// that nodes are plain data and forgetting them costs nothing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Number {
    Small(i64, i64),
    Big(u32),
}

/// A node of a [`Layout`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NodeId(u32);

/// A run of [`Layout`] entries: the terms of a sum or one side of a product.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Span {
    start: u32,
    len: u32,
}

impl Span {
    pub fn is_empty(self) -> bool {
        self.len == 0
    }
}

/// A node of the presented form. Numbers and coefficients here are never negative: signs
/// live on the terms of a [`Node::Sum`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Node {
    Number(Number),
    Symbol(Symbol),
    /// Terms with their signs (`true` = subtracted); at least one, one only when subtracted.
    Sum(Span),
    Product(Product),
    /// A base to a positive exponent other than 1/2.
    Power(NodeId, NodeId),
    SquareRoot(NodeId),
    Function(Func, NodeId),
}

/// `coefficient · numerator / denominator`, coefficient positive.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Product {
    pub coefficient: Number,
    pub numerator: Span,
    pub denominator: Span,
}

/// The numerator or the denominator of a [`Number`], as the renderers write it.
#[derive(Debug, Clone, Copy)]
pub enum Integer<'a> {
    Small(i64),
    Big(&'a BigInt),
}

impl Integer<'_> {
    pub fn is_one(self) -> bool {
        match self {
            Integer::Small(n) => n == 1,
            Integer::Big(n) => n.is_one(),
        }
    }
}

/// The terms of a sum that share one kinematic part (rule 1).
#[derive(Debug, Clone, Copy)]
struct Group {
    /// The ordering key of the kinematic part (rule 2).
    key: KinematicKey,
    /// Whether the coefficient of the first term is a sum.
    sum_coefficient: bool,
    /// Whether the coefficient of any member has a sum among its factors.
    sum_in_coefficient: bool,
    /// The indices of the first and the last term with this kinematic part, and how many
    /// terms have it.
    first: u32,
    last: u32,
    members: u32,
}

/// The end of a group's list of members.
const NO_MEMBER: u32 = u32::MAX;

/// The kinematic factors of a term, in canonical order.
#[derive(Clone)]
struct KinematicPart<'a>(std::slice::Iter<'a, Expr>);

impl<'a> Iterator for KinematicPart<'a> {
    type Item = &'a Expr;

    fn next(&mut self) -> Option<&'a Expr> {
        self.0.by_ref().find(|f| is_kinematic_factor(f))
    }
}

fn kinematic_part(term: &Expr) -> KinematicPart<'_> {
    KinematicPart(term.factors().iter())
}

/// Up to this many groups a term's group is found by linear search; beyond, by hashing.
const LINEAR_SEARCH_GROUPS: usize = 32;

impl Layout {
    /// Forgets every node, keeping the storage for the next expression.
    pub fn clear(&mut self) {
        self.nodes.clear();
        self.entries.clear();
        self.pending.clear();
        self.groups.clear();
        self.next_member.clear();
        self.big_numbers.clear();
    }

    fn number(&mut self, q: &Q) -> Number {
        match q {
            Q::Small(n, d) => Number::Small(*n, *d),
            Q::Big(b) => {
                self.big_numbers.push(b.clone());
                Number::Big((self.big_numbers.len() - 1) as u32)
            }
        }
    }

    /// The absolute value of `q` as a number of this layout.
    fn magnitude(&mut self, q: &Q) -> Number {
        match *q {
            Q::Small(n, d) if n != i64::MIN => Number::Small(n.abs(), d),
            _ => self.number(&q.abs()),
        }
    }

    /// The numerator and the denominator of a number of this layout (an integer's is one).
    pub fn parts(&self, n: Number) -> (Integer<'_>, Integer<'_>) {
        match n {
            Number::Small(n, d) => (Integer::Small(n), Integer::Small(d)),
            Number::Big(at) => {
                let b = &self.big_numbers[at as usize];
                (Integer::Big(b.numer()), Integer::Big(b.denom()))
            }
        }
    }

    pub fn node(&self, id: NodeId) -> &Node {
        &self.nodes[id.0 as usize]
    }

    /// The signed entries of a run: the terms of a sum or the factors of a product.
    pub fn entries(&self, span: Span) -> &[(bool, NodeId)] {
        &self.entries[span.start as usize..(span.start + span.len) as usize]
    }

    fn push(&mut self, node: Node) -> NodeId {
        self.nodes.push(node);
        NodeId((self.nodes.len() - 1) as u32)
    }

    /// The factors pending since `mark` as a product's numerator and denominator (those
    /// marked `true`), each in the order given.
    fn finish_product(&mut self, mark: usize) -> (Span, Span) {
        let start = self.entries.len() as u32;
        let pending = &self.pending[mark..];
        if pending.iter().any(|(d, _)| *d) {
            self.entries.extend(pending.iter().filter(|(d, _)| !d));
            let above = self.entries.len() as u32 - start;
            self.entries.extend(pending.iter().filter(|(d, _)| *d));
            self.pending.truncate(mark);
            let below = self.entries.len() as u32 - start - above;
            let denominator = Span {
                start: start + above,
                len: below,
            };
            return (Span { start, len: above }, denominator);
        }
        // No denominator, the usual case: the factors in one copy.
        self.entries.extend_from_slice(pending);
        let above = self.entries.len() as u32 - start;
        let below = 0;
        self.pending.truncate(mark);
        (
            Span { start, len: above },
            Span {
                start: start + above,
                len: below,
            },
        )
    }

    /// The terms pending since `mark`, with their signs, as one sum.
    fn finish_sum(&mut self, mark: usize) -> NodeId {
        let start = self.entries.len() as u32;
        self.entries.extend_from_slice(&self.pending[mark..]);
        let span = Span {
            start,
            len: self.entries.len() as u32 - start,
        };
        self.pending.truncate(mark);
        self.push(Node::Sum(span))
    }

    /// The presented form of `e` as a signed node: `(negative, node)`.
    pub fn present(&mut self, e: &Expr, axis: Axis) -> (bool, NodeId) {
        self.present_collected(e, axis, true)
    }

    /// The presented form of `e`, a sum's terms collected into groups (rule 1) when
    /// `collect` holds, each standing alone otherwise (rule 5).
    fn present_collected(&mut self, e: &Expr, axis: Axis, collect: bool) -> (bool, NodeId) {
        match e.view() {
            View::Add(_) => self.present_sum(e, axis, collect),
            _ => self.present_term(e, axis),
        }
    }

    fn present_sum(&mut self, e: &Expr, axis: Axis, collect: bool) -> (bool, NodeId) {
        let terms = e.terms();
        let base = self.groups.len();
        let term_base = self.next_member.len();
        // The groups by kinematic part, filled once there are too many to search linearly.
        let mut index: HashMap<Vec<&Expr>, usize> = HashMap::new();
        for (at, term) in terms.iter().enumerate() {
            let kinematic = kinematic_part(term);
            let shape = term_shape(term);
            let groups = &mut self.groups[base..];
            let found = if !collect && kinematic.clone().next().is_some() {
                // Not collected (rule 5); terms free of kinematic symbols stand on their own
                // in any case.
                None
            } else if groups.len() <= LINEAR_SEARCH_GROUPS {
                groups.iter().position(|g| {
                    g.key == shape.key
                        && kinematic_part(&terms[g.first as usize]).eq(kinematic.clone())
                })
            } else {
                if index.is_empty() {
                    for (k, g) in groups.iter().enumerate() {
                        index.insert(kinematic_part(&terms[g.first as usize]).collect(), k);
                    }
                }
                index.get(&kinematic.clone().collect::<Vec<_>>()).copied()
            };
            self.next_member.push(NO_MEMBER);
            match found {
                Some(k) => {
                    let group = &mut groups[k];
                    self.next_member[term_base + group.last as usize] = at as u32;
                    group.last = at as u32;
                    group.members += 1;
                    group.sum_in_coefficient |= shape.sum_in_coefficient;
                }
                None => {
                    if !index.is_empty() {
                        index.insert(kinematic.collect(), groups.len());
                    }
                    self.groups.push(Group {
                        key: shape.key,
                        sum_coefficient: shape.sum_coefficient,
                        sum_in_coefficient: shape.sum_in_coefficient,
                        first: at as u32,
                        last: at as u32,
                        members: 1,
                    });
                }
            }
        }
        // Keys rarely tie; then the kinematic parts decide.
        sort_nearly_sorted(&mut self.groups[base..], |a, b| {
            a.key.cmp(&b.key).then_with(|| {
                let part = |g: &Group| kinematic_part(&terms[g.first as usize]);
                compare_kinematic_parts(part(a), part(b))
            })
        });
        let only_group = self.groups.len() - base == 1;
        let mark = self.pending.len();
        for g in base..self.groups.len() {
            let group = self.groups[g];
            let first = &terms[group.first as usize];
            if group.members == 1 && !group.sum_coefficient {
                // A coefficient of one term times the kinematic part is the term itself.
                let term = self.present_term(first, axis);
                self.pending.push(term);
                continue;
            }
            let next_member = &self.next_member[term_base..];
            let members = std::iter::successors(Some(group.first), |&at| {
                Some(next_member[at as usize]).filter(|&next| next != NO_MEMBER)
            })
            .map(|at| &terms[at as usize]);
            // The coefficient's terms: the members themselves where no coefficient holds a
            // sum (their monomials are distinct), otherwise the terms of their formed sum.
            let formed: Expr;
            let mut coefficient: SmallVec<[CoefficientTerm; 8]> = if group.sum_in_coefficient {
                let coefficients = members.map(|t| t.without_factors(is_kinematic_factor));
                // Two coefficients by `+`, the quick merge of two sorted operands; more at once.
                formed = match group.members {
                    1 | 2 => coefficients
                        .reduce(|sum, c| sum + c)
                        .unwrap_or_else(Expr::zero),
                    _ => Expr::add_all(coefficients),
                };
                if formed.is_zero() {
                    continue;
                }
                formed.terms().iter().map(CoefficientTerm::whole).collect()
            } else {
                members.map(CoefficientTerm::in_place).collect()
            };
            sort_nearly_sorted(&mut coefficient, |&a, &b| coefficient::compare(a, b, axis));
            let kinematic = kinematic_part(first);
            if kinematic.clone().next().is_none() && coefficient.len() > 1 {
                // No kinematic part to collect by: the terms stand on their own.
                if only_group && coefficient[0].coefficient().is_negative() {
                    // A sum of coefficients alone (a denominator, a group) starts with a
                    // positive term where it has one: `z_2 - z_1`, not `-z_1 + z_2`.
                    if let Some(at) = coefficient
                        .iter()
                        .position(|t| !t.coefficient().is_negative())
                    {
                        coefficient[..=at].rotate_right(1);
                    }
                }
                for t in coefficient {
                    let term = self.present_product(t.coefficient(), t.factors(), axis);
                    self.pending.push(term);
                }
            } else if let [only] = coefficient[..] {
                // The coefficient and the kinematic part have no base in common.
                let factors = only.factors().chain(kinematic);
                let term = self.present_product(only.coefficient(), factors, axis);
                self.pending.push(term);
            } else {
                let term = self.present_group(&coefficient, kinematic, axis);
                self.pending.push(term);
            }
        }
        self.groups.truncate(base);
        self.next_member.truncate(term_base);
        if !collect {
            // A sum written term by term starts with a positive term where it has one.
            let terms = &mut self.pending[mark..];
            if let Some(at) = terms.iter().position(|&(negative, _)| !negative) {
                terms[..=at].rotate_right(1);
            }
        }
        match self.pending[mark..] {
            [] => {
                let zero = self.number(&Q::ZERO);
                (false, self.push(Node::Number(zero)))
            }
            [term] => {
                self.pending.truncate(mark);
                term
            }
            _ => (false, self.finish_sum(mark)),
        }
    }

    /// `± common · (group) · kinematic` for a coefficient of several terms, in order.
    fn present_group<'e>(
        &mut self,
        terms: &[CoefficientTerm<'e>],
        kinematic: KinematicPart<'e>,
        axis: Axis,
    ) -> (bool, NodeId) {
        let mut common = coefficient::common_factor(terms);
        let divide = |common: &Option<Expr>| -> Vec<Expr> {
            match common {
                Some(common) => terms.iter().map(|t| t.to_expr() / common).collect(),
                None => Vec::new(),
            }
        };
        let mut divided = divide(&common);
        if let Some(c) = &common {
            // A common factor whose base is the group itself stays in the group: the
            // group and the factor would merge when read back, so `a ω/(a + b) + b ω/(a + b)`
            // is not `(a + b) ω/(a + b)`, which reads back as `ω`.
            let sum_base = |f: &Expr| matches!(f.base().view(), View::Add(_));
            if c.monomial().iter().any(sum_base) {
                let group = Expr::add_all(divided.iter().cloned());
                if c.monomial().iter().any(|f| *f.base() == group) {
                    let kept = c.without_factors(|f| *f.base() == group);
                    common = (!kept.is_one()).then_some(kept);
                    divided = divide(&common);
                }
            }
        }
        let quotient_is_sum = divided.iter().any(|d| matches!(d.view(), View::Add(_)));
        if quotient_is_sum {
            // A quotient that is itself a sum (`(a - 1)/I_xy` over `-1/(2 I_xy)` is
            // `-2 a + 2`) joins the others as its terms, like terms combined: standing as
            // one term of the group, the sign pulled out of the group would reach only its
            // first term when written out.
            divided = Expr::add_all(divided).terms().to_vec();
            if divided.len() < 2 {
                // Combined into one term: no group is left, only a product.
                let whole = common.into_iter().chain(divided).chain(kinematic.cloned());
                return self.present(&Expr::mul_all(whole), axis);
            }
        }
        let mut divided: Vec<CoefficientTerm> =
            divided.iter().map(CoefficientTerm::whole).collect();
        if quotient_is_sum {
            sort_nearly_sorted(&mut divided, |&a, &b| coefficient::compare(a, b, axis));
        }
        let inner = match common {
            Some(_) => &divided[..],
            None => terms,
        };
        let negative = inner[0].coefficient().is_negative();
        let mark = self.pending.len();
        for t in inner {
            let (neg, id) = self.present_product(t.coefficient(), t.factors(), axis);
            self.pending.push((neg != negative, id));
        }
        let group = self.finish_sum(mark);
        // The common factor and the kinematic part have no base in common.
        let (outer_negative, outer_id) = match &common {
            Some(common) => {
                let outer = common.monomial().iter().chain(kinematic);
                self.present_product(common.coefficient(), outer, axis)
            }
            None => self.present_product(&Q::ONE, kinematic, axis),
        };
        let mark = self.pending.len();
        let (coefficient, denominator) = match *self.node(outer_id) {
            Node::Product(p) => {
                let start = p.numerator.start as usize;
                self.pending
                    .extend_from_slice(&self.entries[start..start + p.numerator.len as usize]);
                (p.coefficient, p.denominator)
            }
            Node::Number(q) => (q, Span::default()),
            _ => {
                self.pending.push((false, outer_id));
                (self.number(&Q::ONE), Span::default())
            }
        };
        // The group stands before the first factor placed after groups (rule 4).
        let at = self.pending[mark..]
            .iter()
            .position(|&(_, f)| self.placement(f) > GROUP_PLACE)
            .map_or(self.pending.len(), |k| mark + k);
        self.pending.insert(at, (false, group));
        let (numerator, _) = self.finish_product(mark);
        let product = self.push(Node::Product(Product {
            coefficient,
            numerator,
            denominator,
        }));
        (negative != outer_negative, product)
    }

    /// A single term (no top-level sum) as a signed product.
    fn present_term(&mut self, e: &Expr, axis: Axis) -> (bool, NodeId) {
        self.present_product(e.coefficient(), e.monomial().iter(), axis)
    }

    /// `coefficient · factors` as a signed product, the factors of distinct bases.
    fn present_product<'e>(
        &mut self,
        coefficient: &Q,
        factors: impl Iterator<Item = &'e Expr>,
        axis: Axis,
    ) -> (bool, NodeId) {
        let negative = coefficient.is_negative();
        let magnitude = self.magnitude(coefficient);
        // The factors with their places, in print order; on the stack unless there are many.
        let mut factors = factors.map(|f| (expr_place(f), f));
        let Some(first) = factors.next() else {
            return (negative, self.push(Node::Number(magnitude)));
        };
        let mut inline = [first; 8];
        let mut spilled: Vec<(u8, &Expr)> = Vec::new();
        let mut count = 1;
        for placed in factors {
            match inline.get_mut(count) {
                Some(slot) => *slot = placed,
                None => {
                    if spilled.is_empty() {
                        spilled.extend_from_slice(&inline);
                    }
                    spilled.push(placed);
                }
            }
            count += 1;
        }
        let ordered: &mut [(u8, &Expr)] = match spilled.is_empty() {
            true => &mut inline[..count],
            false => &mut spilled,
        };
        sort_nearly_sorted(ordered, |(pa, a), (pb, b)| {
            pa.cmp(pb).then_with(|| compare_in_place(a, b))
        });
        cyclic_pair_order(ordered);
        let sum_in_denominator = ordered.iter().any(|(_, f)| match f.view() {
            View::Pow(base, exponent) => {
                matches!(base.view(), View::Add(_)) && exponent.as_num().is_some_and(Q::is_negative)
            }
            _ => false,
        });
        // Rule 7: no group in the numerator over a sum.
        let collect = !sum_in_denominator;
        let mark = self.pending.len();
        // Each factor with whether it belongs to the denominator.
        for &(_, f) in ordered.iter() {
            let (base, exponent) = match f.view() {
                View::Pow(base, exponent) => (base, exponent),
                // The most frequent factor, without the call of `present_atom`.
                View::Sym(s) => {
                    let symbol = self.push(Node::Symbol(s));
                    self.pending.push((false, symbol));
                    continue;
                }
                View::Add(_) => {
                    let sum = self.present_signed_inline_collected(f, axis, collect);
                    self.pending.push((false, sum));
                    continue;
                }
                _ => {
                    let atom = self.present_atom(f, axis);
                    self.pending.push((false, atom));
                    continue;
                }
            };
            let factor = match exponent.as_num() {
                Some(q) if q.is_negative() => {
                    (true, self.present_power(base, &q.abs(), axis, false))
                }
                Some(q) => (false, self.present_power(base, q, axis, collect)),
                None => {
                    let base = self.present_atom(base, axis);
                    let exponent = self.present_signed_inline(exponent, axis);
                    (false, self.push(Node::Power(base, exponent)))
                }
            };
            self.pending.push(factor);
        }
        let node = match &self.pending[mark..] {
            [(false, alone)] if magnitude == Number::Small(1, 1) => {
                let alone = *alone;
                self.pending.truncate(mark);
                return (negative, alone);
            }
            _ => {
                let (numerator, denominator) = self.finish_product(mark);
                Node::Product(Product {
                    coefficient: magnitude,
                    numerator,
                    denominator,
                })
            }
        };
        (negative, self.push(node))
    }

    /// `base^exponent` for a positive exponent; a sum as the base is collected into groups
    /// when `collect` holds (not in a denominator, rule 5).
    fn present_power(&mut self, base: &Expr, exponent: &Q, axis: Axis, collect: bool) -> NodeId {
        if *exponent == Q::Small(1, 2) {
            let inner = self.present_signed_inline_collected(base, axis, collect);
            return self.push(Node::SquareRoot(inner));
        }
        let base = match base.view() {
            View::Add(_) => self.present_signed_inline_collected(base, axis, collect),
            _ => self.present_atom(base, axis),
        };
        if exponent.is_one() {
            base
        } else {
            let exponent = self.number(exponent);
            let exponent = self.push(Node::Number(exponent));
            self.push(Node::Power(base, exponent))
        }
    }

    /// A factor or base: a symbol, a number, a function, or a parenthesised sum.
    fn present_atom(&mut self, e: &Expr, axis: Axis) -> NodeId {
        match e.view() {
            View::Sym(s) => self.push(Node::Symbol(s)),
            View::Num(q) if !q.is_negative() && q.is_integer() => {
                let q = self.number(q);
                self.push(Node::Number(q))
            }
            View::Func(f, arg) => {
                let arg = self.present_signed_inline(arg, axis);
                self.push(Node::Function(f, arg))
            }
            _ => self.present_signed_inline(e, axis),
        }
    }

    /// An expression that must stand as one unit; a leading minus becomes part of a sum.
    fn present_signed_inline(&mut self, e: &Expr, axis: Axis) -> NodeId {
        self.present_signed_inline_collected(e, axis, true)
    }

    /// [`Layout::present_signed_inline`], a sum's terms collected when `collect` holds.
    fn present_signed_inline_collected(&mut self, e: &Expr, axis: Axis, collect: bool) -> NodeId {
        match self.present_collected(e, axis, collect) {
            (false, id) => id,
            (true, id) => {
                if let Node::Sum(span) = *self.node(id) {
                    let start = span.start as usize;
                    self.entries[start..start + span.len as usize]
                        .iter_mut()
                        .for_each(|t| t.0 = !t.0);
                    id
                } else if collect && matches!(e.view(), View::Add(_)) {
                    // A sum that collects into one negative group is written term by term
                    // (rule 6): the group's minus, a factor -1 of its own, would move when
                    // read back, out of a function by its parity (`sin(-x) = -sin x`) or into
                    // a product's coefficient. The grouped form's nodes stay behind, unused.
                    self.present_signed_inline_collected(e, axis, false)
                } else {
                    let mark = self.pending.len();
                    self.pending.push((true, id));
                    self.finish_sum(mark)
                }
            }
        }
    }

    /// Where a node stands in a product (rule 4): a power where its base does, a square
    /// root no later than a group.
    ///
    /// A loop, not recursion: rustc 1.95 in release builds compiled the recursive form so
    /// that `placement(ω) > GROUP_PLACE` was false although `placement(ω)` was 8, which put
    /// a group after the kinematic factor (`ω_y (a + b)`) where debug builds and the
    /// snapshots have `(a + b) ω_y`.
    fn placement(&self, mut id: NodeId) -> u8 {
        let mut latest = u8::MAX;
        loop {
            let place = match *self.node(id) {
                Node::Power(base, _) => {
                    id = base;
                    continue;
                }
                Node::SquareRoot(inner) => {
                    latest = GROUP_PLACE;
                    id = inner;
                    continue;
                }
                Node::Number(_) => 0,
                Node::Symbol(s) => symbol_place(s),
                Node::Sum(_) | Node::Product(_) => GROUP_PLACE,
                Node::Function(..) => 7,
            };
            return place.min(latest);
        }
    }
}

/// Whether a factor belongs to a term's kinematic part (rule 1): a kinematic symbol or unit
/// vector, a power of one, or a function of an argument that mentions a kinematic symbol.
pub(super) fn is_kinematic_factor(f: &Expr) -> bool {
    match f.base().view() {
        View::Sym(s) => matches!(s.role(), Role::Kinematic | Role::UnitVector),
        View::Func(_, arg) => mentions_kinematic(arg),
        _ => false,
    }
}

/// Whether a kinematic symbol occurs anywhere in `e`.
fn mentions_kinematic(e: &Expr) -> bool {
    match e.view() {
        View::Num(_) => false,
        View::Sym(s) => s.role() == Role::Kinematic,
        View::Add(xs) | View::Mul(xs) => xs.iter().any(mentions_kinematic),
        View::Pow(b, x) => mentions_kinematic(b) || mentions_kinematic(x),
        View::Func(_, a) => mentions_kinematic(a),
    }
}

/// Where a factor stands in a product (rule 4).
const GROUP_PLACE: u8 = 6;

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
        View::Func(_, arg) if mentions_kinematic(arg) => 8,
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
/// The factors are in place order, so the kinematic ones (place 8) stand together.
fn cyclic_pair_order(factors: &mut [(u8, &Expr)]) {
    let Some(i) = factors.iter().position(|f| f.0 == 8) else {
        return;
    };
    let place = |k: usize| factors.get(k).map(|f| f.0);
    if place(i + 1) == Some(8) && place(i + 2) != Some(8) {
        let axis = |k: usize| factors[k].1.base().as_symbol().and_then(Symbol::axis);
        if axis(i) == Some(0) && axis(i + 1) == Some(2) {
            factors.swap(i, i + 1);
        }
    }
}

/// Sorts a short slice that is often in order already (the factors of a term, the groups
/// of a sum) as `sort_by` would, stably: by insertion, comparing each neighbouring pair once
/// when nothing is out of place. Long slices go to the standard sort.
fn sort_nearly_sorted<T: Copy>(items: &mut [T], mut order: impl FnMut(&T, &T) -> Ordering) {
    if items.len() > 16 {
        items.sort_by(order);
        return;
    }
    for i in 1..items.len() {
        if order(&items[i - 1], &items[i]) != Ordering::Greater {
            continue;
        }
        let item = items[i];
        let mut j = i - 1;
        items[i] = items[j];
        while j > 0 && order(&items[j - 1], &item) == Ordering::Greater {
            items[j] = items[j - 1];
            j -= 1;
        }
        items[j] = item;
    }
}

/// Ordering key of a kinematic monomial (rule 2): terms free of kinematic symbols, then
/// accelerations before velocities, the family (translational first), the number of
/// kinematic symbols, and the axis or the cyclic pair of axes; packed into one integer in
/// that order of significance (class and family a byte each, the count 40 bits, the axis a
/// byte), so that comparing keys is one comparison.
type KinematicKey = u64;

/// What grouping needs to know of a term, found in one pass over its factors.
struct TermShape {
    key: KinematicKey,
    /// Whether the coefficient is a sum: a single non-kinematic factor that is a sum.
    sum_coefficient: bool,
    /// Whether any non-kinematic factor is a sum.
    sum_in_coefficient: bool,
}

fn term_shape(term: &Expr) -> TermShape {
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
            View::Func(_, arg) if mentions_kinematic(arg) => {
                for s in f.base().symbols() {
                    visit(s);
                }
                true
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
fn compare_kinematic_parts(a: KinematicPart, b: KinematicPart) -> Ordering {
    let size = |p: &KinematicPart| p.clone().take(2).count();
    if size(&a) == size(&b) {
        a.cmp(b)
    } else {
        Expr::mul_all(a.cloned()).cmp(&Expr::mul_all(b.cloned()))
    }
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

    /// Terms over a common sum whose numerators add up to that sum, `a ω/(a + b) +
    /// b ω/(a + b)`, are not printed as a group divided by itself (which reads back as `ω`,
    /// another expression to the algebra): the text parses back to the expression.
    #[test]
    fn a_group_is_not_divided_by_itself() {
        let (a, b, w) = (Expr::symbol("a"), Expr::symbol("b"), Expr::symbol("w_x"));
        let over = (&a + &b).powi(-1);
        assert_reads_back(&(&a * &w * &over + &b * &w * &over));
    }

    /// The text of `e` parses back to `e` (compared expanded, as equality is decided).
    fn assert_reads_back(e: &Expr) {
        let printed = crate::print::text(e);
        let back = crate::parse::parse_expression("printed", &printed).unwrap();
        assert_eq!(back.expand().unwrap(), e.expand().unwrap(), "{printed}");
    }

    /// A group whose common factor divides a member into a sum: in
    /// `θ(a - 1)/I_xy - m θ/(2 I_xy²)` the factor `-θ/(2 I_xy)` leaves `-2(a - 1) = -2a + 2`
    /// of the first, whose terms join the group's (`-(m/I_xy - 2 a + 2)`); standing as one
    /// term, it was written `- 2*a - 2`.
    #[test]
    fn a_member_divided_into_a_sum_joins_the_group() {
        let (a, m, theta) = (Expr::symbol("a"), Expr::symbol("m"), Expr::symbol("theta"));
        let i_xy = Expr::symbol("I_xy");
        let e = &theta * (&a - Expr::one()) / &i_xy - &m * &theta / (Expr::int(2) * i_xy.powi(2));
        assert_reads_back(&e);
    }

    /// Rule 7: over a sum, a sum in the numerator is not grouped, so the group cannot cancel
    /// the denominator when read back: `(a w_x - w_x)/(a - 1)`.
    #[test]
    fn a_numerator_over_a_sum_is_not_grouped() {
        let (a, w) = (Expr::symbol("a"), Expr::symbol("w_x"));
        let e = (&a * &w - &w) * (&a - Expr::one()).powi(-1);
        assert_eq!(crate::print::text(&e), "(a*w_x - w_x)/(a - 1)");
        assert_reads_back(&e);
    }

    /// A sum standing as a factor that would collect into one negative group is written
    /// term by term (rule 6 in any product): `sin(a (1/θ - I_xy/θ))`.
    #[test]
    fn a_factor_that_groups_negatively_is_written_term_by_term() {
        let (a, theta) = (Expr::symbol("a"), Expr::symbol("theta"));
        let factor = theta.powi(-1) - Expr::symbol("I_xy") * theta.powi(-1);
        assert_reads_back(&Func::Sin.apply(&a * &factor));
        assert_reads_back(&(&a * &factor));
    }

    /// Sums in denominators that would collect into a group, `I_xy θ - θ`, are written
    /// term by term, so that the text parses back to the expression.
    #[test]
    fn denominators_read_back() {
        let theta = Expr::symbol("theta");
        let denominator = Expr::symbol("I_xy") * &theta - &theta;
        for e in [
            -denominator.powi(-1),
            Expr::symbol("m") * denominator.powi(-2),
            denominator.checked_pow(&Expr::rational(-1, 2)).unwrap(),
        ] {
            assert_reads_back(&e);
        }
    }

    /// Sums under functions that would collect into one negative group, `w_x/2 - w_x/a`,
    /// are written term by term, so that the text parses back to the expression.
    #[test]
    fn function_arguments_read_back() {
        let (a, w) = (Expr::symbol("a"), Expr::symbol("w_x"));
        let argument = Expr::rational(1, 2) * &w - &w / &a;
        for e in [
            Func::Abs.apply(argument.clone()),
            Func::Sin.apply(argument.clone()),
            Func::Cos.apply(-argument),
        ] {
            assert_reads_back(&e);
        }
    }

    /// Numbers beyond `i64` go to the layout's side table and print in full.
    #[test]
    fn big_numbers_print_in_full() {
        let big = Expr::int(1 << 35).powi(2);
        assert_eq!(
            crate::print::text(&(Expr::symbol("m") * &big)),
            "1180591620717411303424*m"
        );
        assert_eq!(
            crate::print::latex(&(Expr::rational(1, 3) / &big)),
            r"\frac{1}{3541774862152233910272}"
        );
    }
}
