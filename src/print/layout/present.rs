//! How each kind of expression is presented: a sum goes to its groups (`sum.rs`), a term
//! is a product of its factors in place order (rule 4), a factor a power, a root, a
//! function or a parenthesised sum. The sums inside are collected as any sum except where
//! the text would not read back: in a denominator (rule 5), where they group into one
//! negative group (rule 6), and in a numerator over a sum (rule 7).

use super::nearly_sorted::sort_nearly_sorted;
use super::place::{compare_in_place, cyclic_pair_order, expr_place};
use super::{Layout, Node, NodeId, Number, Product};
use crate::algebra::{work, Axis, Expr, View, Q};

impl Layout {
    /// The presented form of `e` as a signed node: `(negative, node)`.
    pub fn present(&mut self, e: &Expr, axis: Axis) -> (bool, NodeId) {
        self.present_collected(e, axis, true)
    }

    /// The presented form of `e`, a sum's terms collected into groups (rule 1) when
    /// `collect` holds, each standing alone otherwise (rule 5). Once the work budget is
    /// spent a zero stands for the rest: the command refuses the page (`Budget::run`).
    fn present_collected(&mut self, e: &Expr, axis: Axis, collect: bool) -> (bool, NodeId) {
        if work::count_and_spent(1) {
            return self.present_product(&Q::ZERO, std::iter::empty(), axis);
        }
        match e.view() {
            View::Add(_) => self.present_sum(e, axis, collect),
            _ => self.present_term(e, axis),
        }
    }

    /// A single term (no top-level sum) as a signed product.
    pub(super) fn present_term(&mut self, e: &Expr, axis: Axis) -> (bool, NodeId) {
        self.present_product(e.coefficient(), e.monomial().iter(), axis)
    }

    /// `coefficient · factors` as a signed product, the factors of distinct bases.
    pub(super) fn present_product<'e>(
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
        if let Q::Small(1, index @ (2 | 3)) = *exponent {
            let inner = self.present_signed_inline_collected(base, axis, collect);
            return self.push(Node::Root(index as u8, inner));
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
}

#[cfg(test)]
mod tests {
    use super::super::assert_reads_back;
    use crate::algebra::{Expr, Func};

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
}
