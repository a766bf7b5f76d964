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
//! The form is built bottom-up into a [`Layout`], the node store of this file: nodes in one
//! vector, the terms of each sum and the factors of each product as a contiguous run in
//! another, children collected on a stack until their parent is made. The rules read the
//! expression through borrowed views and live one concept a file:
//!
//! - `kinematic.rs`: a term's kinematic part (rule 1) and the key groups are ordered by
//!   (rule 2);
//! - `sum.rs`: a sum's terms gathered into groups, the groups ordered and written (rules 1,
//!   2 and 5);
//! - `group.rs`: a group of several terms, its common factor and its minus pulled out;
//! - `coefficient.rs`: a group's coefficient, read in place from its members (only a
//!   coefficient whose members hold sums, or a common factor other than one, is formed as a
//!   new expression), and the order of its terms (rule 3);
//! - `place.rs`: where a factor stands in a product (rule 4);
//! - `present.rs`: terms, powers, functions and the sums inside them (rules 4 to 7);
//! - `nearly_sorted.rs`: the sort the orders above go through.
//!
//! The small helpers the rules call for every term or factor from another of these files
//! are `#[inline]`: a file is a module and may be compiled apart from its callers, and
//! called rather than inlined they cost the general body's LaTeX 3% more instructions.

mod coefficient;
mod group;
mod kinematic;
mod nearly_sorted;
mod place;
mod present;
mod sum;

use crate::algebra::{Func, Symbol, Q};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;
use std::sync::Arc;
use sum::Group;

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
    /// [`sum::NO_MEMBER`] (a stack).
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
    /// A base to a positive exponent other than 1/2 and 1/3.
    Power(NodeId, NodeId),
    /// The `index`-th root (2: `√x`, 3: `∛x`), a base to the exponent 1/index.
    Root(u8, NodeId),
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

    /// A sum of the given signed terms, nodes of this layout, as a new node: the printers
    /// write a sum of some of a sum's terms (a line of a broken relation) as they write any
    /// sum. Without terms it is written as nothing: a line that continues a sum is the sum of
    /// that empty node and its terms, so that the notation writes its first sign.
    pub fn sum_of(&mut self, terms: &[(bool, NodeId)]) -> NodeId {
        let start = self.entries.len() as u32;
        self.entries.extend_from_slice(terms);
        let span = Span {
            start,
            len: terms.len() as u32,
        };
        self.push(Node::Sum(span))
    }

    /// A product of this layout's nodes as a new node (`coefficient · numerator /
    /// denominator`): a term written with one of its factors taken out.
    pub fn product_of(
        &mut self,
        coefficient: Number,
        numerator: &[(bool, NodeId)],
        denominator: &[(bool, NodeId)],
    ) -> NodeId {
        let start = self.entries.len() as u32;
        self.entries.extend_from_slice(numerator);
        self.entries.extend_from_slice(denominator);
        let above = Span {
            start,
            len: numerator.len() as u32,
        };
        let below = Span {
            start: start + above.len,
            len: denominator.len() as u32,
        };
        self.push(Node::Product(Product {
            coefficient,
            numerator: above,
            denominator: below,
        }))
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
}

/// The text of `e` parses back to `e` (compared expanded, as equality is decided).
#[cfg(test)]
fn assert_reads_back(e: &crate::algebra::Expr) {
    let printed = crate::print::text(e);
    let back = crate::parse::parse_expression("printed", &printed).unwrap();
    assert_eq!(back.expand().unwrap(), e.expand().unwrap(), "{printed}");
}

#[cfg(test)]
mod tests {
    use crate::algebra::Expr;

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
