//! Parentheses that grow: around a factor that holds a fraction, LaTeX writes
//! `\left(\frac{a}{b} + c\right)`, sized to what they enclose; around a factor of one line's
//! height, plain `(a + b)`.
//!
//! A node is tall when it holds a fraction outside any exponent: a fractional number
//! (`\frac{1}{2}`), a product with a denominator, or any node with such a part (an exponent is
//! set small and never makes its base taller).

use super::layout::{Layout, Node, NodeId};

/// Whether parentheses around `id` grow (`\left(`…`\right)`): it holds a fraction.
pub(crate) fn grows(layout: &Layout, id: NodeId) -> bool {
    match layout.node(id) {
        Node::Symbol(_) => false,
        Node::Number(n) => !layout.parts(*n).1.is_one(),
        Node::Sum(terms) => layout
            .entries(*terms)
            .iter()
            .any(|&(_, term)| grows(layout, term)),
        Node::Product(p) => {
            !p.denominator.is_empty()
                || !layout.parts(p.coefficient).1.is_one()
                || layout
                    .entries(p.numerator)
                    .iter()
                    .any(|&(_, f)| grows(layout, f))
        }
        Node::Power(base, _) => grows(layout, *base),
        Node::Root(_, inner) | Node::Function(_, inner) => grows(layout, *inner),
    }
}
