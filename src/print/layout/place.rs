//! Where a factor stands in a product (rule 4): the number, then inertia and mass, other
//! quantities, lengths, groups, functions, kinematic symbols, unit vectors. Factors with the
//! same place: kinematic symbols translational first, then by axis (a pair on z and x in
//! cyclic order, `ω_z ω_x`); inertia symbols as in the x-equation; `Δt` after the force or
//! couple it multiplies.

use super::coefficient::inertia_key;
use super::kinematic::{family, mentions_kinematic};
use super::{Layout, Node, NodeId};
use crate::algebra::{Axis, Expr, Role, Symbol, View};
use std::cmp::Ordering;

/// The place of a group, a parenthesised sum or product, among a product's factors.
pub(super) const GROUP_PLACE: u8 = 6;

/// The place of a symbol, by its role.
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

/// The place of a factor, by its base: a function of a kinematic argument stands with the
/// kinematic symbols.
#[inline]
pub(super) fn expr_place(e: &Expr) -> u8 {
    match e.base().view() {
        View::Num(_) => 0,
        View::Sym(s) => symbol_place(s),
        View::Func(_, arg) if mentions_kinematic(arg) => 8,
        View::Func(..) => 7,
        _ => GROUP_PLACE,
    }
}

impl Layout {
    /// Where a node stands in a product (rule 4): a power where its base does, a square
    /// root no later than a group.
    ///
    /// A loop, not recursion: rustc 1.95 in release builds compiled the recursive form so
    /// that `placement(ω) > GROUP_PLACE` was false although `placement(ω)` was 8, which put
    /// a group after the kinematic factor (`ω_y (a + b)`) where debug builds and the
    /// snapshots have `(a + b) ω_y`.
    pub(super) fn placement(&self, mut id: NodeId) -> u8 {
        let mut latest = u8::MAX;
        loop {
            let place = match *self.node(id) {
                Node::Power(base, _) => {
                    id = base;
                    continue;
                }
                Node::Root(_, inner) => {
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

/// The order of two factors with the same place in a product (rule 4).
pub(super) fn compare_in_place(a: &Expr, b: &Expr) -> Ordering {
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
#[inline]
pub(super) fn cyclic_pair_order(factors: &mut [(u8, &Expr)]) {
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
