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

/// Where one sum's groups and its terms' member links start on the layout's stacks (a sum
/// inside another's factor is presented above the outer one's).
#[derive(Clone, Copy)]
struct Frame {
    groups: usize,
    members: usize,
}

impl Layout {
    /// A sum in its presented form: its terms gathered into groups by kinematic part (rule
    /// 1), the groups ordered (rule 2), each written as its coefficient times its kinematic
    /// part, and the written terms made one node. Not collected (rule 5), each term with a
    /// kinematic part stands alone.
    pub(super) fn present_sum(&mut self, e: &Expr, axis: Axis, collect: bool) -> (bool, NodeId) {
        let terms = e.terms();
        let frame = Frame {
            groups: self.groups.len(),
            members: self.next_member.len(),
        };
        self.gather_groups(terms, frame, collect);
        self.order_groups(terms, frame);
        let only_group = self.groups.len() - frame.groups == 1;
        let mark = self.pending.len();
        for g in frame.groups..self.groups.len() {
            let group = self.groups[g];
            self.write_group(terms, group, frame, only_group, axis);
        }
        self.groups.truncate(frame.groups);
        self.next_member.truncate(frame.members);
        self.finish_terms(mark, collect)
    }

    /// Rule 1: each term joins the group of the earlier terms with its kinematic part, or
    /// starts a group; the group is found by linear search among a few groups and through a
    /// hash index among many. Not collected (rule 5), a term with a kinematic part starts a
    /// group of its own; terms free of kinematic symbols gather into one group in any case,
    /// and each is written on its own.
    fn gather_groups(&mut self, terms: &[Expr], frame: Frame, collect: bool) {
        // The groups by kinematic part, filled once there are too many to search linearly.
        let mut index: HashMap<Vec<&Expr>, usize> = HashMap::new();
        for (at, term) in terms.iter().enumerate() {
            let kinematic = kinematic_part(term);
            let shape = term_shape(term);
            let groups = &mut self.groups[frame.groups..];
            let found = if !collect && kinematic.clone().next().is_some() {
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
                    self.next_member[frame.members + group.last as usize] = at as u32;
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
    }

    /// Rule 2: the groups by the keys of their kinematic parts; keys rarely tie, and then
    /// the kinematic parts decide.
    fn order_groups(&mut self, terms: &[Expr], frame: Frame) {
        sort_nearly_sorted(&mut self.groups[frame.groups..], |a, b| {
            a.key.cmp(&b.key).then_with(|| {
                let part = |g: &Group| kinematic_part(&terms[g.first as usize]);
                compare_kinematic_parts(part(a), part(b))
            })
        });
    }

    /// The terms of a group, in the order of the sum.
    fn members<'a, 'e: 'a>(
        &'a self,
        terms: &'e [Expr],
        group: Group,
        frame: Frame,
    ) -> impl Iterator<Item = &'e Expr> + 'a {
        let next_member = &self.next_member[frame.members..];
        std::iter::successors(Some(group.first), |&at| {
            Some(next_member[at as usize]).filter(|&next| next != NO_MEMBER)
        })
        .map(|at| &terms[at as usize])
    }

    /// The coefficient of a group whose members hold sums in their coefficients, formed by
    /// the algebra: two coefficients by `+`, the quick merge of two sorted operands; more
    /// at once.
    fn formed_coefficient(&self, terms: &[Expr], group: Group, frame: Frame) -> Expr {
        let coefficients = self
            .members(terms, group, frame)
            .map(|t| t.without_factors(is_kinematic_factor));
        match group.members {
            1 | 2 => coefficients
                .reduce(|sum, c| sum + c)
                .unwrap_or_else(Expr::zero),
            _ => Expr::add_all(coefficients),
        }
    }

    /// One group written as its coefficient times its kinematic part (rule 1), the
    /// coefficient's terms in order (rule 3): a lone term as itself, terms free of
    /// kinematic symbols each on its own, a coefficient of one term as one product, and of
    /// several as a group. A coefficient that adds up to zero writes nothing.
    fn write_group(
        &mut self,
        terms: &[Expr],
        group: Group,
        frame: Frame,
        only_group: bool,
        axis: Axis,
    ) {
        let first = &terms[group.first as usize];
        if group.members == 1 && !group.sum_coefficient {
            // A coefficient of one term times the kinematic part is the term itself.
            let term = self.present_term(first, axis);
            self.pending.push(term);
            return;
        }
        // The coefficient's terms: the members themselves where no coefficient holds a
        // sum (their monomials are distinct), otherwise the terms of their formed sum.
        let formed = group
            .sum_in_coefficient
            .then(|| self.formed_coefficient(terms, group, frame));
        let mut coefficient: SmallVec<[CoefficientTerm; 8]> = match &formed {
            Some(formed) if formed.is_zero() => return,
            Some(formed) => formed.terms().iter().map(CoefficientTerm::whole).collect(),
            None => self
                .members(terms, group, frame)
                .map(CoefficientTerm::in_place)
                .collect(),
        };
        sort_nearly_sorted(&mut coefficient, |&a, &b| coefficient::compare(a, b, axis));
        let kinematic = kinematic_part(first);
        if kinematic.clone().next().is_none() && coefficient.len() > 1 {
            self.write_free_terms(&mut coefficient, only_group, axis);
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

    /// Terms free of kinematic symbols, with no kinematic part to collect them by, each on
    /// its own. A sum of them alone (a denominator, a group) starts with a positive term
    /// where it has one: `z_2 - z_1`, not `-z_1 + z_2`.
    fn write_free_terms(&mut self, terms: &mut [CoefficientTerm], only_group: bool, axis: Axis) {
        if only_group {
            positive_first(terms, |t| t.coefficient().is_negative());
        }
        for t in terms.iter() {
            let term = self.present_product(t.coefficient(), t.factors(), axis);
            self.pending.push(term);
        }
    }

    /// The terms written since `mark` as one node: zero for none, a lone term as itself,
    /// otherwise their sum. A sum written term by term (not collected) starts with a
    /// positive term where it has one.
    fn finish_terms(&mut self, mark: usize, collect: bool) -> (bool, NodeId) {
        if !collect {
            positive_first(&mut self.pending[mark..], |&(negative, _)| negative);
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

/// Moves the first term that is not negative to the front, the others keeping their order:
/// `-a + b - c` is written `b - a - c`.
fn positive_first<T>(terms: &mut [T], negative: impl Fn(&T) -> bool) {
    if let Some(at) = terms.iter().position(|t| !negative(t)) {
        terms[..=at].rotate_right(1);
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
