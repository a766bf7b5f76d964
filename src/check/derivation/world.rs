//! The student's world: the values a derivation's lines, taken as true, give the derived
//! names they use. A wrong line fixes a wrong value, and a later line that holds there
//! follows from it (error carried forward).
//!
//! Each derived scalar a line names (`D_y`, `Hdot_z`, `alpha`, `I_xz`) is an unknown. A line
//! `lhs = rhs` is the equation `lhs − rhs = 0` in those unknowns, with the values the earlier
//! lines fixed put in; it is solved for its subject, the first unknown written on its left
//! (then on its right) in which the equation's numerator is linear: `u = −b/a` from
//! `a u + b = 0`. A line that writes no unknown met for the first time and holds at the
//! values it leaves open is a rearrangement or a substitution of the truth, and fixes
//! nothing (`D_y = ⅛ m c α − ¼ m c ω²` after `D_y = (I_xz α − I_xy ω²)/L` puts in I_xz and
//! I_xy; solved for α it would fix α at 0/0). The value is put into every earlier value that
//! holds `u`, so the world
//! stays solved: each value holds only the unknowns no line has fixed yet. Those take the
//! value the mechanics derives when the world is read ([`World::values`]), so a line that
//! holds never moves a value off the truth.

use crate::algebra::vector::{components, has_unit_vectors};
use crate::algebra::{AlgebraError, Expr, Symbol};
use crate::check::context::Context;
use crate::check::verdict::{is_zero, plain_value, value_and_scale};
use crate::parse::claim::{Claim, Name};
use crate::parse::{ClaimSyntax, Follows};
use crate::scene::units_in_math::in_system;
use std::collections::{BTreeSet, HashMap, HashSet};

/// An unknown of the world: the derived name it stands for and the value the mechanics
/// derives for it.
struct Unknown {
    name: String,
    truth: Expr,
}

/// A value a line fixed, and the lines it rests on (that line and those whose values went
/// into it).
struct Fixed {
    value: Expr,
    lines: BTreeSet<usize>,
}

/// What a derivation's lines give a quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Given {
    /// The derived names its value is left in (none when in the givens alone).
    pub left_in: Vec<String>,
    /// Whether the value (those names at the mechanics' values) is the mechanics' own:
    /// exactly, or within the tolerance for a value in numbers.
    pub agrees: bool,
    /// The lines the value rests on.
    pub lines: Vec<usize>,
}

/// The values a derivation's lines give the derived names, line by line.
pub struct World<'c> {
    context: &'c Context,
    /// Each unknown's symbol in the equations, and what it stands for.
    unknowns: HashMap<Symbol, Unknown>,
    /// The unknowns by the name written, in the order first met.
    by_name: Vec<(String, Symbol)>,
    fixed: HashMap<Symbol, Fixed>,
    /// The unknowns the lines taken so far wrote.
    met: HashSet<Symbol>,
}

impl<'c> World<'c> {
    pub fn new(context: &'c Context) -> World<'c> {
        World {
            context,
            unknowns: HashMap::new(),
            by_name: Vec::new(),
            fixed: HashMap::new(),
            met: HashSet::new(),
        }
    }

    /// The symbol standing for the derived name `written` in the equations: one for the
    /// spellings of one quantity (`M_x`, `SumM_x`), named by a name no claim can spell
    /// (`__world` is not a name a person writes).
    fn unknown(&mut self, written: &str, truth: Expr) -> Symbol {
        if let Some((_, s)) = self.by_name.iter().find(|(n, _)| n == written) {
            return *s;
        }
        let canonical = self.context.canonical(written);
        let symbol = Symbol::new(&format!("{canonical}__world"));
        self.unknowns.entry(symbol).or_insert(Unknown {
            name: canonical.to_string(),
            truth,
        });
        self.by_name.push((written.to_string(), symbol));
        symbol
    }

    /// Takes the line `text` (number `line`) as true: solves it for its subject and puts the
    /// value into the world. A line that cannot be read, fixes nothing new (every unknown it
    /// holds is fixed) or is not linear in any of its unknowns leaves the world as it was.
    /// `carried`: the earlier lines whose slip the line carries, which what it fixes rests on.
    pub fn take(&mut self, line: usize, syntax: &ClaimSyntax, carried: &[usize]) {
        let Some((claim, written)) = self.read(syntax) else {
            return;
        };
        let residual = &claim.lhs.value - &claim.rhs.value;
        let equations = match has_unit_vectors(&residual) {
            true => match components(&residual) {
                Ok(v) => v.iter().cloned().collect(),
                Err(_) => return,
            },
            false => vec![residual],
        };
        let new: Vec<Symbol> = written
            .iter()
            .copied()
            .filter(|s| !self.met.contains(s))
            .collect();
        let mut lines = BTreeSet::from([line]);
        lines.extend(carried);
        for equation in equations {
            let _ = self.solve(&lines, &equation, &written, !new.is_empty());
        }
        self.met.extend(written);
    }

    /// The claim read with each derived scalar as its unknown, in the context's units, and
    /// the unknowns in the order written (left side first).
    fn read(&mut self, syntax: &ClaimSyntax) -> Option<(Claim, Vec<Symbol>)> {
        let context = self.context;
        let met = std::cell::RefCell::new(Vec::new());
        let resolve = |name: &str| match context.derived_scalar(name) {
            Some(truth) => {
                met.borrow_mut().push((name.to_string(), truth));
                Name::Symbol
            }
            None => context.name(name),
        };
        let unit = |name: &str, follows: Follows| context.unit(name, follows);
        let claim = syntax.read(&resolve, Some(&unit)).ok()?;
        let written: Vec<Symbol> = met
            .into_inner()
            .into_iter()
            .map(|(name, truth)| self.unknown(&name, truth))
            .collect();
        // The names were lowered as their own symbols: rename them to the unknowns'.
        let rename = |s: Symbol| {
            let (_, u) = self.by_name.iter().find(|(n, _)| Symbol::new(n) == s)?;
            Some(Expr::from(*u))
        };
        let side = |e: &Expr| -> Option<Expr> {
            let e = e.subs(&rename).ok()?;
            Some(in_system(&e, context.unit_system()).unwrap_or(e))
        };
        let mut claim = claim;
        claim.lhs.value = side(&claim.lhs.value)?;
        claim.rhs.value = side(&claim.rhs.value)?;
        Some((claim, written))
    }

    /// Solves `equation = 0` for its subject and fixes it: the first of `written` (fixed or
    /// not: a line that says again what a name is, differently, is the student's latest
    /// word on it) in which the equation, with the other names' values put in, is linear.
    /// A line that meets no new name and holds as the world stands changes nothing, unless
    /// it states its subject in fewer of the names no line fixed (`SumM_x = I_x wdot_x`
    /// after `SumM_x = I_x wdot_x + w_y H_z - w_z H_y`): then that is the subject's value.
    fn solve(
        &mut self,
        line: &BTreeSet<usize>,
        equation: &Expr,
        written: &[Symbol],
        meets_new: bool,
    ) -> Result<(), AlgebraError> {
        let in_world = equation.subs(&|s| self.fixed.get(&s).map(|f| f.value.clone()))?;
        if !meets_new && self.holds_at_truth(&in_world)? {
            let Some(&subject) = written.first() else {
                return Ok(());
            };
            let Some(current) = self.fixed.get(&subject).map(|f| self.open_names(&f.value)) else {
                return Ok(());
            };
            if let Some((value, lines)) = self.solved_for(subject, line, equation)? {
                if self.open_names(&value) < current {
                    self.fix(subject, value, lines);
                }
            }
            return Ok(());
        }
        for &u in written {
            if let Some((value, lines)) = self.solved_for(u, line, equation)? {
                self.fix(u, value, lines);
                return Ok(());
            }
        }
        Ok(())
    }

    /// How many unknowns no line fixed `value` holds.
    fn open_names(&self, value: &Expr) -> usize {
        value
            .symbols()
            .into_iter()
            .filter(|s| self.unknowns.contains_key(s))
            .count()
    }

    /// `equation = 0` solved for `u`, the other names' values put in, when it is linear in
    /// `u`; with the lines the value rests on (`line`, and those of the values put in).
    fn solved_for(
        &self,
        u: Symbol,
        line: &BTreeSet<usize>,
        equation: &Expr,
    ) -> Result<Option<(Expr, BTreeSet<usize>)>, AlgebraError> {
        let others = |s: Symbol| match s == u {
            true => None,
            false => self.fixed.get(&s).map(|f| f.value.clone()),
        };
        let (numerator, _) = equation.subs(&others)?.together_parts()?;
        let numerator = numerator.expand()?;
        if !numerator.contains(u) {
            return Ok(None);
        }
        let a = numerator.diff(u)?;
        if a.is_zero() || a.contains(u) {
            return Ok(None);
        }
        let b = numerator.subs(&|s| (s == u).then(Expr::zero))?;
        let mut lines = line.clone();
        for s in equation.symbols().into_iter().filter(|s| *s != u) {
            if let Some(f) = self.fixed.get(&s) {
                lines.extend(&f.lines);
            }
        }
        Ok(Some((-(&b / &a), lines)))
    }

    /// Whether `equation = 0` holds with the unknowns no line fixed at the mechanics' values:
    /// exactly, or, for an equation left in numbers, within the context's tolerance of the
    /// scale of its terms (`D_y = -11.25 + 118.5` against -11.25 + 118.5037).
    fn holds_at_truth(&self, equation: &Expr) -> Result<bool, AlgebraError> {
        let at_truth = equation.subs(&|s| self.unknowns.get(&s).map(|u| u.truth.clone()))?;
        if let Some((value, scale)) = self.in_numbers(&at_truth) {
            return Ok(value.abs() <= self.context.relative_tolerance() * scale);
        }
        is_zero(&at_truth, self.context.domains())
    }

    /// `e`'s value at the givens' values and the sum of its terms' magnitudes, when it is a
    /// number there.
    fn in_numbers(&self, e: &Expr) -> Option<(f64, f64)> {
        // Each term valued apart: put in together, the numbers would fold into one.
        value_and_scale(e, &|t| {
            plain_value(&t.subs(&|s| self.context.value(s)).ok()?)
        })
    }

    /// Fixes `u` at `value` and puts it into every value that holds `u`.
    fn fix(&mut self, u: Symbol, value: Expr, lines: BTreeSet<usize>) {
        for fixed in self.fixed.values_mut() {
            if fixed.value.contains(u) {
                if let Ok(v) = fixed.value.subs(&|s| (s == u).then(|| value.clone())) {
                    fixed.value = v;
                    fixed.lines.extend(&lines);
                }
            }
        }
        self.fixed.insert(u, Fixed { value, lines });
    }

    /// The value of each name a line fixed, the unknowns no line fixed taking the value the
    /// mechanics derives.
    pub fn values(&self) -> HashMap<String, Expr> {
        let truth = |s: Symbol| self.unknowns.get(&s).map(|u| u.truth.clone());
        self.fixed
            .iter()
            .filter_map(|(s, f)| {
                Some((
                    self.unknowns.get(s)?.name.clone(),
                    f.value.subs(&truth).ok()?,
                ))
            })
            .collect()
    }

    /// Whether every name of `names` was written by an earlier line: a line that meets no
    /// new quantity only relates ones the derivation has already (algebra, not mechanics).
    pub fn all_met(&self, names: &[String]) -> bool {
        names.iter().all(|n| {
            self.by_name
                .iter()
                .find(|(m, _)| m == n)
                .is_some_and(|(_, s)| self.met.contains(s))
        })
    }

    /// What the lines give `name` (any spelling of its quantity), if a line fixed it.
    pub fn given(&self, name: &str) -> Option<Given> {
        let canonical = self.context.canonical(name);
        let (symbol, unknown) = self.unknowns.iter().find(|(_, u)| u.name == canonical)?;
        let fixed = self.fixed.get(symbol)?;
        let left_in: Vec<String> = fixed
            .value
            .symbols()
            .into_iter()
            .filter_map(|s| Some(self.unknowns.get(&s)?.name.clone()))
            .collect();
        let truth = |s: Symbol| self.unknowns.get(&s).map(|u| u.truth.clone());
        let value = fixed.value.subs(&truth).ok()?;
        // The truth, or where the scene's equations have several solutions, one of them.
        let agrees = self
            .context
            .derived_scalar_values(&unknown.name)
            .iter()
            .any(
                |truth| match (self.in_numbers(&value), self.in_numbers(truth)) {
                    (Some((v, _)), Some((t, _))) => {
                        (v - t).abs() <= self.context.relative_tolerance() * t.abs()
                    }
                    _ => is_zero(&(&value - truth), self.context.domains()).unwrap_or(false),
                },
            );
        Some(Given {
            left_in,
            agrees,
            lines: fixed.lines.iter().copied().collect(),
        })
    }

    /// The lines the values of `names` rest on.
    pub fn lines_under<'a>(&self, names: impl Iterator<Item = &'a String>) -> BTreeSet<usize> {
        names
            .filter_map(|n| self.by_name.iter().find(|(m, _)| m == n))
            .filter_map(|(_, s)| self.fixed.get(s))
            .flat_map(|f| f.lines.iter().copied())
            .collect()
    }
}
