//! Long radicands named for a page. A cubic's or a quartic's roots with letters for
//! coefficients (Cardano's formula, its trigonometric form, Ferrari's method) nest sums under
//! roots, `∛(… + √(…))`, and under `arccos`, that no line of a page can break. Each such
//! radicand or argument written longer than [`LONG`] characters is named `C_1`, `C_2`, …,
//! innermost first (so a later one is defined with the earlier names), the first step that
//! holds one is preceded by a step of their definitions, and the steps and results show the
//! names. Values are always computed from the whole expressions.

use super::Analysis;
use crate::algebra::Axis;
use crate::algebra::{Expr, Func, Symbol, View};
use crate::mechanics::derivation::{Relation, Step};

/// Length, in characters of the text form, past which a radicand is named.
const LONG: usize = 60;

/// The names given to long radicands, in the order defined: `(C_k, its whole expression)`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Abbreviations {
    names: Vec<(Symbol, Expr)>,
    /// Each form met of a named radicand, with its name's index in `names`.
    forms: Vec<(Expr, usize)>,
}

impl Abbreviations {
    /// The long radicands of `exprs`, each named once with the first `C_k` for which
    /// `taken` is false.
    pub(super) fn of<'e>(
        exprs: impl IntoIterator<Item = &'e Expr>,
        taken: &dyn Fn(Symbol) -> bool,
    ) -> Abbreviations {
        let mut long = Vec::new();
        for e in exprs {
            long_radicands(e, &mut long);
        }
        let mut out = Abbreviations::default();
        // Each name's radicand written with the names before it.
        let mut written: Vec<Expr> = Vec::with_capacity(long.len());
        let mut k = 0;
        for radicand in long {
            // The same quantity met in another form (each step is simplified on its own,
            // and its inner radicands may be other forms of named ones) keeps its name.
            let named = out.apply(&radicand);
            if let Some(at) = written
                .iter()
                .position(|w| *w == named || same_value(w, &named))
            {
                out.forms.push((radicand, at));
                continue;
            }
            let name = loop {
                k += 1;
                let s = Symbol::new(&format!("C_{k}"));
                if !taken(s) {
                    break s;
                }
            };
            out.forms.push((radicand.clone(), out.names.len()));
            out.names.push((name, radicand));
            written.push(named);
        }
        out
    }

    /// `e` with each named radicand written as its name.
    pub fn apply(&self, e: &Expr) -> Expr {
        self.apply_before(e, self.names.len())
    }

    /// `e` with each name replaced by its whole expression: the form a value is computed
    /// from.
    pub fn whole(&self, e: &Expr) -> Expr {
        let named = |s: Symbol| {
            self.names
                .iter()
                .find(|(name, _)| *name == s)
                .map(|(_, whole)| whole.clone())
        };
        e.subs(&named).unwrap_or_else(|_| e.clone())
    }

    /// Whether `s` is one of the names.
    pub fn is_name(&self, s: Symbol) -> bool {
        self.names.iter().any(|(name, _)| *name == s)
    }

    /// `e` with the first `count` named radicands written as their names.
    fn apply_before(&self, e: &Expr, count: usize) -> Expr {
        if let Some((_, at)) = self.forms.iter().find(|(r, at)| *at < count && r == e) {
            return Expr::sym(self.names[*at].0);
        }
        let inner = |x: &Expr| self.apply_before(x, count);
        match e.view() {
            View::Num(_) | View::Sym(_) => e.clone(),
            View::Add(terms) => Expr::add_all(terms.iter().map(inner)),
            View::Mul(factors) => Expr::mul_all(factors.iter().map(inner)),
            View::Pow(base, exponent) => inner(base)
                .checked_pow(&inner(exponent))
                .unwrap_or_else(|_| e.clone()),
            View::Func(f, argument) => Expr::func(f, inner(argument)),
        }
    }

    /// Each name `C_k = …`, its expression written with the names before it.
    pub fn relations(&self) -> Vec<Relation> {
        self.names
            .iter()
            .enumerate()
            .map(|(k, (name, radicand))| {
                Relation::new(Expr::sym(*name), self.apply_before(radicand, k), Axis::X)
            })
            .collect()
    }

    /// The step defining the names, or none.
    fn definitions(&self) -> Option<Step> {
        if self.names.is_empty() {
            return None;
        }
        let relations = self.relations();
        Some(Step::new(
            "names for the long parts (radicands, arccos arguments) of the roots below",
            relations,
        ))
    }

    /// The analysis with its long radicands named: the definitions' step before the first
    /// step that holds one, every step written with the names; the results keep their whole
    /// expressions (a page shows them with [`Abbreviations::apply`]).
    pub(super) fn name_in(analysis: &mut Analysis, taken: &dyn Fn(Symbol) -> bool) {
        let relations = analysis.plan.iter().flat_map(|s| &s.relations);
        let results = analysis.results.iter().filter_map(|(_, v)| match v {
            super::Value::Scalar(e) => Some(e),
            _ => None,
        });
        let names = Abbreviations::of(relations.map(|r| &r.rhs).chain(results), taken);
        let Some(definitions) = names.definitions() else {
            return;
        };
        let mut first = None;
        for (k, step) in analysis.plan.iter_mut().enumerate() {
            for r in &mut step.relations {
                let named = names.apply(&r.rhs);
                if named != r.rhs {
                    first.get_or_insert(k);
                    r.rhs = named;
                }
            }
        }
        analysis
            .plan
            .insert(first.unwrap_or(analysis.plan.len()), definitions);
        analysis.abbreviations = names;
    }
}

/// Whether two expressions are equal as values: their difference is zero in lowest terms.
fn same_value(a: &Expr, b: &Expr) -> bool {
    (a - b).cancel().is_ok_and(|d| d.is_zero())
}

/// Appends the long radicands and arccos arguments of `e` not yet in `out`, innermost first.
fn long_radicands(e: &Expr, out: &mut Vec<Expr>) {
    let candidate = match e.view() {
        View::Num(_) | View::Sym(_) => None,
        View::Add(xs) | View::Mul(xs) => {
            xs.iter().for_each(|x| long_radicands(x, out));
            None
        }
        View::Pow(base, exponent) => {
            long_radicands(base, out);
            exponent
                .as_num()
                .is_some_and(|q| q.to_i64().is_none())
                .then_some(base)
        }
        View::Func(f, argument) => {
            long_radicands(argument, out);
            (f == Func::Acos).then_some(argument)
        }
    };
    if let Some(c) = candidate {
        if c.to_string().len() > LONG && !out.contains(c) {
            out.push(c.clone());
        }
    }
}
