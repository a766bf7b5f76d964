//! Walks that read an expression without rebuilding it: its size in nodes (the measure the
//! size limits use), whether a symbol occurs in it, and the set of its symbols.

use super::expr::{Expr, View};
use super::function::Func;
use super::symbol::Symbol;
use super::work;

/// The base of a factor below the line: a power with a negative number for exponent.
fn denominator_base(f: &Expr) -> Option<&Expr> {
    match f.view() {
        View::Pow(base, exponent) if exponent.as_num().is_some_and(|q| q.is_negative()) => {
            Some(base)
        }
        _ => None,
    }
}

impl Expr {
    /// Whether a fraction stands inside a fraction or a product as printed: a sum that is a
    /// factor (or a power's base) holds a term with a denominator that is not a number,
    /// `-¼ m r (4L + r²/L) ω₁`, `1/(a + b/c)`. A sum on its own, `W + m r³ω²/(2L²)`, is none.
    pub fn has_nested_fraction(&self) -> bool {
        let denominator = |term: &Expr| {
            term.factors()
                .iter()
                .any(|f| denominator_base(f).is_some_and(|base| base.as_num().is_none()))
        };
        let fraction_in_sum =
            |e: &Expr| matches!(e.view(), View::Add(terms) if terms.iter().any(denominator));
        match self.view() {
            View::Num(_) | View::Sym(_) => false,
            View::Add(xs) => xs.iter().any(Expr::has_nested_fraction),
            View::Mul(xs) => xs
                .iter()
                .any(|x| fraction_in_sum(x.base()) || x.has_nested_fraction()),
            View::Pow(b, e) => {
                fraction_in_sum(b) || b.has_nested_fraction() || e.has_nested_fraction()
            }
            View::Func(_, a) => a.has_nested_fraction(),
        }
    }

    /// Number of nodes in the tree (a measure of size, for limits).
    pub fn node_count(&self) -> usize {
        match self.view() {
            View::Num(_) | View::Sym(_) => 1,
            View::Add(xs) | View::Mul(xs) => 1 + xs.iter().map(Expr::node_count).sum::<usize>(),
            View::Pow(b, e) => 1 + b.node_count() + e.node_count(),
            View::Func(_, a) => 1 + a.node_count(),
        }
    }

    /// Whether the tree's size is at most `limit`, counted only up to `limit + 1`: a bound
    /// checked in time proportional to the bound, however large the tree. A node counts 1,
    /// a number one more per 32 bits of its numerator and denominator (about ten digits), a
    /// symbol one more per 16 bytes of its name, so that the size follows the printed length
    /// (an expansion of sums of names 1,500 letters long printed 270 MB within the nodes).
    pub fn has_at_most_size(&self, limit: usize) -> bool {
        fn count(e: &Expr, budget: &mut usize) -> bool {
            let cost = match e.view() {
                View::Num(q) => {
                    let (num, den) = q.bit_lengths();
                    1 + usize::try_from((num + den) / 32).unwrap_or(usize::MAX)
                }
                View::Sym(s) => 1 + s.name().len() / 16,
                _ => 1,
            };
            if *budget < cost {
                return false;
            }
            *budget -= cost;
            match e.view() {
                View::Num(_) | View::Sym(_) => true,
                View::Add(xs) | View::Mul(xs) => xs.iter().all(|x| count(x, budget)),
                View::Pow(b, x) => count(b, budget) && count(x, budget),
                View::Func(_, a) => count(a, budget),
            }
        }
        let mut budget = limit;
        let within = count(self, &mut budget);
        work::count((limit - budget) as u64);
        within
    }

    /// Whether `s` occurs anywhere in the expression.
    pub fn contains(&self, s: Symbol) -> bool {
        self.has_symbol_where(&|t| t == s)
    }

    /// Whether a symbol for which `holds` is true occurs anywhere in the expression.
    pub fn has_symbol_where(&self, holds: &dyn Fn(Symbol) -> bool) -> bool {
        match self.view() {
            View::Num(_) => false,
            View::Sym(t) => holds(t),
            View::Add(xs) | View::Mul(xs) => xs.iter().any(|x| x.has_symbol_where(holds)),
            View::Pow(b, e) => b.has_symbol_where(holds) || e.has_symbol_where(holds),
            View::Func(_, a) => a.has_symbol_where(holds),
        }
    }

    /// Whether a function for which `holds` is true is applied anywhere in the expression.
    pub fn has_function_where(&self, holds: &dyn Fn(Func) -> bool) -> bool {
        match self.view() {
            View::Num(_) | View::Sym(_) => false,
            View::Add(xs) | View::Mul(xs) => xs.iter().any(|x| x.has_function_where(holds)),
            View::Pow(b, e) => b.has_function_where(holds) || e.has_function_where(holds),
            View::Func(f, a) => holds(f) || a.has_function_where(holds),
        }
    }

    /// The symbols in the expression, sorted by name, each once.
    pub fn symbols(&self) -> Vec<Symbol> {
        fn walk(e: &Expr, out: &mut Vec<Symbol>) {
            match e.view() {
                View::Num(_) => {}
                View::Sym(s) => out.push(s),
                View::Add(xs) | View::Mul(xs) => xs.iter().for_each(|x| walk(x, out)),
                View::Pow(b, x) => {
                    walk(b, out);
                    walk(x, out);
                }
                View::Func(_, a) => walk(a, out),
            }
        }
        let mut out = Vec::new();
        walk(self, &mut out);
        out.sort();
        out.dedup();
        out
    }
}
