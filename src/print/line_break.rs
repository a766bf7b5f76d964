//! Long relations broken across lines so that no page overflows: the right-hand side is cut at
//! a `+` or `−` between top-level terms, each line as full as fits (greedy, measured by
//! [`super::width`]), each later line starting with its sign:
//!
//! ```text
//! T = ½ (m₁ + m₂) v_x² + ½ (m₁ + m₂) v_y²
//!       + ½ (m₁ + m₂) v_z² + …
//! ```
//!
//! The terms are the unbroken rendering's, in its order: the lines joined with spaces give it
//! back. In LaTeX a single term too wide for a line alone, a product with a long sum among its
//! factors, is written with the sum taken out and broken inside big parentheses:
//! `\frac{\omega_z}{12 (m_1 + m_2)} \bigl(m_1^2 L_1^2 + …` on one line, `+ … \bigr)` on the
//! next. In text such a line stays long. Every line is rendered through the notation's own
//! printer ([`super::render_into`]), so a new notation breaks without change.

use super::growing_parentheses::grows;
use super::layout::{Layout, Node, NodeId};
use super::width::{self, BIG_PARENTHESIS_EM, BINARY_OPERATOR_EM, RELATION_EM, UNARY_MINUS_EM};
use super::{presented, render_into, Notation};
use crate::algebra::{Axis, Expr, Symbol, Vector};

/// The narrowest text width a page of ours has, in ems of its font, less a margin: the
/// article class sets 345 pt at 10 pt (34.5 em) and 390 pt at 12 pt (32.5 em), on A4 and
/// letter alike.
pub const PAGE_WIDTH_EM: f64 = 31.5;

/// Where a continuation line starts, from the left of a displayed relation: the left-hand
/// side's column (up to 3 em) and a `\quad`.
pub const CONTINUATION_EM: f64 = 4.0;

/// A `\quad`, the indent of a continuation line after the alignment point.
const QUAD_EM: f64 = 1.0;

/// The room a block of aligned rows (`lhs &= rhs`, continued `&\quad + …`) leaves its
/// right-hand sides, from its widest left-hand side: `(first_em, width_em)` for [`broken`] on
/// a page. A left column wider than [`CONTINUATION_EM`] less the quad narrows the width.
pub fn aligned_room(lhs_em: f64) -> (f64, f64) {
    let overhang = (lhs_em + QUAD_EM - CONTINUATION_EM).max(0.0);
    (lhs_em + RELATION_EM, PAGE_WIDTH_EM - overhang)
}

/// Lines of `rhs` rendered in `notation`: the first fits in `width_em - first_em` (the
/// left-hand side and `=` take `first_em`), each later one in `width_em - CONTINUATION_EM`
/// and starts with its sign (`+ ` / `- ` as the notation writes it).
pub fn broken(
    rhs: &Expr,
    axis: Axis,
    notation: Notation,
    first_em: f64,
    width_em: f64,
) -> Vec<String> {
    let later = width_em - CONTINUATION_EM;
    let pieces = presented(rhs, axis, |layout, negative, root| {
        let mut pieces = Vec::new();
        match *layout.node(root) {
            Node::Sum(terms) if !negative => {
                let terms = layout.entries(terms).to_vec();
                for (i, (negative, term)) in terms.into_iter().enumerate() {
                    let sign = Sign::of(i == 0, negative);
                    term_pieces(&mut pieces, layout, sign, term, later, notation, false);
                }
            }
            _ => {
                let sign = Sign::of(true, negative);
                term_pieces(&mut pieces, layout, sign, root, later, notation, false);
            }
        }
        pieces
    });
    lines(pieces, width_em - first_em, later)
}

/// The width of `e` about `axis` as LaTeX displays it, in ems.
pub fn width_em(e: &Expr, axis: Axis) -> f64 {
    presented(e, axis, |layout, negative, root| {
        width::signed(layout, negative, root)
    })
}

/// Lines of a vector `(…)\mathbf{i} + (…)\mathbf{j} + (…)\mathbf{k}` as
/// [`super::vector`] writes it, fitted as [`broken`] fits a sum: each component on its own
/// line when long, and in LaTeX a component too wide alone broken inside big parentheses.
pub fn broken_vector(v: &Vector, notation: Notation, first_em: f64, width_em: f64) -> Vec<String> {
    let later = width_em - CONTINUATION_EM;
    // A vector that does not fit on its first line has a line for each component.
    let line_each = vector_width_em(v) > width_em - first_em;
    let mut pieces = Vec::new();
    for (component, unit) in v.iter().zip(super::UNIT_VECTORS) {
        if component.is_zero() {
            continue;
        }
        let unit = Symbol::new(unit);
        let first = pieces.is_empty();
        let start = pieces.len();
        let (flipped, component) = super::signed_component(component);
        presented(&component, Axis::X, |layout, negative, root| {
            let negative = negative != flipped;
            let mut text = String::new();
            super::vector_component(&mut text, layout, negative, root, first, unit, notation);
            let sign = Sign::of(first, negative);
            let width = sign.width() + vector_component_width(layout, root, unit);
            let text = text.trim_start().to_string();
            if width <= later || notation != Notation::Latex {
                pieces.push(Piece::alone(text, width));
                return;
            }
            let suffix = format!(" {}", unit.latex());
            if let Node::Sum(_) = layout.node(root) {
                // `(a + b) \mathbf{i}` too wide: `\bigl(a \\ + b\bigr) \mathbf{i}`.
                let opening = Piece::alone(sign.latex().to_string(), sign.width());
                sum_pieces(&mut pieces, layout, opening, root, &suffix, later);
            } else if !split_term(&mut pieces, layout, sign, root, &suffix, later, false) {
                pieces.push(Piece::alone(text, width));
            }
        });
        if let Some(piece) = pieces.get_mut(start) {
            piece.new_line = line_each;
        }
    }
    if pieces.is_empty() {
        return vec![super::vector(v, notation)];
    }
    lines(pieces, width_em - first_em, later)
}

/// The width of a vector as [`super::vector`] writes it on one line, in ems.
pub fn vector_width_em(v: &Vector) -> f64 {
    let mut width = 0.0;
    for (k, (component, unit)) in v.iter().zip(super::UNIT_VECTORS).enumerate() {
        if !component.is_zero() {
            let sign = if k == 0 {
                UNARY_MINUS_EM
            } else {
                BINARY_OPERATOR_EM
            };
            width += sign
                + presented(component, Axis::X, |layout, _, root| {
                    vector_component_width(layout, root, Symbol::new(unit))
                });
        }
    }
    width
}

/// A vector component's width with its parentheses and unit vector (the sign apart).
fn vector_component_width(layout: &Layout, root: NodeId, unit: Symbol) -> f64 {
    let parentheses = match layout.node(root) {
        Node::Sum(_) => width::parenthesised(layout, root) - width::node(layout, root),
        _ => 0.0,
    };
    parentheses + width::node(layout, root) + width::symbol_em(unit.latex())
}

/// How a term is signed where it stands: first in its sum (`a`, `-a`) or after another
/// (`+ a`, `- a`).
#[derive(Debug, Clone, Copy)]
struct Sign {
    first: bool,
    negative: bool,
}

impl Sign {
    fn of(first: bool, negative: bool) -> Sign {
        Sign { first, negative }
    }

    fn width(self) -> f64 {
        match (self.first, self.negative) {
            (true, false) => 0.0,
            (true, true) => UNARY_MINUS_EM,
            (false, _) => BINARY_OPERATOR_EM,
        }
    }

    /// The sign in LaTeX, as the sum printer writes it.
    fn latex(self) -> &'static str {
        match (self.first, self.negative) {
            (true, false) => "",
            (true, true) => "-",
            (false, false) => "+ ",
            (false, true) => "- ",
        }
    }
}

/// A term (or several words of one) as placed on a line.
#[derive(Debug)]
struct Piece {
    text: String,
    width: f64,
    /// Stays on the line of the piece before it (a big parenthesis and what it opens or
    /// closes on).
    joined: bool,
    /// Starts a line of its own (a vector's component).
    new_line: bool,
}

impl Piece {
    fn alone(text: String, width: f64) -> Piece {
        Piece {
            text,
            width,
            joined: false,
            new_line: false,
        }
    }
}

/// `term` signed as `sign` says, as the notation writes it inside a sum: the sum of the term
/// alone, or for a later term the sum of an empty node and the term, whose first sign the
/// notation writes (`+ a`).
fn signed_term(layout: &mut Layout, sign: Sign, term: NodeId, notation: Notation) -> String {
    let mut text = String::new();
    if sign.first {
        render_into(&mut text, layout, sign.negative, term, notation);
    } else {
        let empty = layout.sum_of(&[]);
        let line = layout.sum_of(&[(false, empty), (sign.negative, term)]);
        render_into(&mut text, layout, false, line, notation);
    }
    text.trim_start().to_string()
}

/// The pieces of one term: itself, or in LaTeX when it is wider than a line, as
/// [`split_term`] writes it; `joined` to the piece before it or not.
fn term_pieces(
    pieces: &mut Vec<Piece>,
    layout: &mut Layout,
    sign: Sign,
    term: NodeId,
    line_em: f64,
    notation: Notation,
    joined: bool,
) {
    let width = sign.width() + width::node(layout, term);
    if width > line_em
        && notation == Notation::Latex
        && split_term(pieces, layout, sign, term, "", line_em, joined)
    {
        return;
    }
    let text = signed_term(layout, sign, term, notation);
    pieces.push(Piece {
        text,
        width,
        joined,
        new_line: false,
    });
}

/// In LaTeX, a product with a sum among its factors as the rest of the product before big
/// parentheses around the sum, broken term by term, then `suffix`; false (and nothing
/// pushed) for a term without such a sum.
fn split_term(
    pieces: &mut Vec<Piece>,
    layout: &mut Layout,
    sign: Sign,
    term: NodeId,
    suffix: &str,
    line_em: f64,
    joined: bool,
) -> bool {
    let Some((rest, sum)) = taken_out_sum(layout, term) else {
        return false;
    };
    let opening = Piece {
        text: signed_term(layout, sign, rest, Notation::Latex),
        width: sign.width() + width::node(layout, rest),
        joined,
        new_line: false,
    };
    sum_pieces(pieces, layout, opening, sum, suffix, line_em);
    true
}

/// The widest sum among a product's numerator factors (two terms or more), and the product
/// without it.
fn taken_out_sum(layout: &mut Layout, term: NodeId) -> Option<(NodeId, NodeId)> {
    let Node::Product(p) = *layout.node(term) else {
        return None;
    };
    let numerator = layout.entries(p.numerator).to_vec();
    let (at, &(_, sum)) = numerator
        .iter()
        .enumerate()
        .filter(
            |&(_, &(_, f))| matches!(layout.node(f), Node::Sum(s) if layout.entries(*s).len() > 1),
        )
        .max_by(|a, b| {
            let width = |id: NodeId| width::node(layout, id);
            width(a.1 .1).total_cmp(&width(b.1 .1))
        })?;
    let mut rest = numerator.clone();
    rest.remove(at);
    let denominator = layout.entries(p.denominator).to_vec();
    let rest = layout.product_of(p.coefficient, &rest, &denominator);
    Some((rest, sum))
}

/// Big parentheses of a sum broken across lines: `\biggl(` around fractions, `\bigl(`
/// otherwise (`\left(` cannot span lines).
fn big_parentheses(layout: &Layout, sum: NodeId) -> (&'static str, &'static str) {
    if grows(layout, sum) {
        (r"\biggl(", r"\biggr)")
    } else {
        (r"\bigl(", r"\bigr)")
    }
}

/// The pieces of a sum broken inside big parentheses: `opening` (what comes before them on
/// its line) with the opening parenthesis, the terms (each split again if too wide), then
/// the closing parenthesis and `suffix`.
fn sum_pieces(
    pieces: &mut Vec<Piece>,
    layout: &mut Layout,
    mut opening: Piece,
    sum: NodeId,
    suffix: &str,
    line_em: f64,
) {
    let Node::Sum(terms) = *layout.node(sum) else {
        return;
    };
    let (open, close) = big_parentheses(layout, sum);
    if !opening.text.is_empty() && !opening.text.ends_with(' ') {
        opening.text.push(' ');
    }
    opening.text.push_str(open);
    opening.width += BIG_PARENTHESIS_EM;
    pieces.push(opening);
    let terms = layout.entries(terms).to_vec();
    for (i, (negative, term)) in terms.into_iter().enumerate() {
        let sign = Sign::of(i == 0, negative);
        term_pieces(pieces, layout, sign, term, line_em, Notation::Latex, i == 0);
    }
    pieces.push(Piece {
        text: format!("{close}{suffix}"),
        // A unit vector after it is narrower than an em.
        width: BIG_PARENTHESIS_EM + if suffix.is_empty() { 0.0 } else { 1.0 },
        joined: true,
        new_line: false,
    });
}

/// The pieces laid into lines greedily: the first line `first_em` wide, the later ones
/// `later_em`; a run of joined pieces stays on one line, a run wider than a line has a
/// line of its own, and a piece marked `new_line` starts one.
fn lines(pieces: Vec<Piece>, first_em: f64, later_em: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    let mut used = 0.0;
    let mut runs: Vec<Vec<Piece>> = Vec::new();
    for piece in pieces {
        match runs.last_mut() {
            Some(run) if piece.joined => run.push(piece),
            _ => runs.push(vec![piece]),
        }
    }
    for run in runs {
        let width: f64 = run.iter().map(|p| p.width).sum();
        let room = if lines.is_empty() { first_em } else { later_em };
        if !line.is_empty() && (used + width > room || run[0].new_line) {
            lines.push(std::mem::take(&mut line));
            used = 0.0;
        }
        for piece in run {
            if !line.is_empty() && !line.ends_with('(') {
                line.push(' ');
            }
            line.push_str(&piece.text);
        }
        used += width;
    }
    lines.push(line);
    lines
}
