//! A sum as a textbook writes it: its terms gathered into groups by kinematic part (rule 1),
//! the groups ordered (rule 2), each group written as its coefficient times its kinematic
//! part; in a denominator every term stands on its own (rule 5).

use super::coefficient::{self, CoefficientTerm};
use super::kinematic::{
    compare_kinematic_parts, is_kinematic_factor, kinematic_part, term_shape, KinematicKey,
};
use super::nearly_sorted::sort_nearly_sorted;
use super::{Layout, Node, NodeId};
use crate::algebra::{Axis, Expr, Q};
use smallvec::SmallVec;
use std::collections::HashMap;

/// The terms of a sum that share one kinematic part (rule 1).
#[derive(Debug, Clone, Copy)]
pub(super) struct Group {
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
pub(super) const NO_MEMBER: u32 = u32::MAX;

/// Up to this many groups a term's group is found by linear search; beyond, by hashing.
const LINEAR_SEARCH_GROUPS: usize = 32;

impl Layout {
    pub(super) fn present_sum(&mut self, e: &Expr, axis: Axis, collect: bool) -> (bool, NodeId) {
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
