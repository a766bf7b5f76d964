//! A group of terms with one kinematic part and a coefficient of several terms (rule 1):
//! `± common · (group) · kinematic`, the coefficient's common factor and the minus of its
//! first term pulled out: `-(I_y - I_z) ω_y ω_z`. The group stands among the product's
//! factors where rule 4 places a group.

use super::coefficient::{self, CoefficientTerm};
use super::kinematic::KinematicPart;
use super::nearly_sorted::sort_nearly_sorted;
use super::place::GROUP_PLACE;
use super::{Layout, Node, NodeId, Product, Span};
use crate::algebra::{Axis, Expr, View, Q};

impl Layout {
    /// `± common · (group) · kinematic` for a coefficient of several terms, in order.
    pub(super) fn present_group<'e>(
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
}

#[cfg(test)]
mod tests {
    use super::super::assert_reads_back;
    use crate::algebra::Expr;

    /// Terms over a common sum whose numerators add up to that sum, `a ω/(a + b) +
    /// b ω/(a + b)`, are not printed as a group divided by itself (which reads back as `ω`,
    /// another expression to the algebra): the text parses back to the expression.
    #[test]
    fn a_group_is_not_divided_by_itself() {
        let (a, b, w) = (Expr::symbol("a"), Expr::symbol("b"), Expr::symbol("w_x"));
        let over = (&a + &b).powi(-1);
        assert_reads_back(&(&a * &w * &over + &b * &w * &over));
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
}
