//! The work budget of one command: a count of operations shared by every routine the
//! command runs (building expressions, simplifying, expanding, polynomial arithmetic,
//! printing), bounded by the size of the input, so that no input can run for long.
//!
//! The unit is one operand of a node built ([`count`] in the canonical constructors), one
//! term operation of polynomial arithmetic, one node laid out by a printer: each costs tens
//! of nanoseconds. An input of `b` bytes may spend
//!
//! ```text
//! limit(b) = FLOOR + PER_BYTE · b
//! ```
//!
//! operations: the floor is six times what the largest example spends (8.5·10⁵) and at
//! most about half a second of work, the heaviest kind measured being a short power
//! expanded into tens of thousands of terms and printed in three notations; `PER_BYTE`
//! keeps a megabyte of input, read and printed, under about two seconds on one core.
//!
//! Counting never fails, so infallible routines count too (and a long walk stops early
//! once the budget is spent, [`count_and_spent`]); a fallible routine asks [`check`] at its
//! steps and refuses with [`AlgebraError::OutOfWork`] once the budget is spent. That error
//! is not "beyond bounds": it is not passed over by a route of `simplify` but ends the
//! command, and [`Budget::run`] refuses a result reached after the
//! budget was spent, so no form is ever silently left less simplified for lack of work.
//!
//! The count is per thread: a command that fans out (claims checked in parallel) gives each
//! piece of input its share of the budget on the thread that does its work. Outside [`Budget::run`]
//! nothing is bounded (the library's own callers and tests).

use super::error::AlgebraError;
use std::cell::{Cell, RefCell};

/// Operations every input may spend, however short.
pub const FLOOR: u64 = 5_000_000;
/// Operations each byte of input adds to the floor.
pub const PER_BYTE: u64 = 10;

thread_local! {
    /// Operations counted on this thread since the budget began.
    static SPENT: Cell<u64> = const { Cell::new(0) };
    /// The operations this thread may spend; `u64::MAX` outside a budget.
    static LIMIT: Cell<u64> = const { Cell::new(u64::MAX) };
    /// What the budgeted work is doing, innermost last ([`doing`]).
    static DOING: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
    /// What it was doing when the budget was first found spent.
    static RAN_OUT_IN: RefCell<Option<String>> = const { RefCell::new(None) };
    /// What the last [`Budget::run`] on this thread that ran out was doing then.
    static LAST_RAN_OUT_IN: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Runs `work` named by `what` (a step's title, a solve: words that finish "it ran out …"),
/// so that a refusal for work says where the work went. Named only within a budget (the
/// name is not built otherwise).
pub fn doing<T>(what: impl FnOnce() -> String, work: impl FnOnce() -> T) -> T {
    if LIMIT.with(Cell::get) == u64::MAX {
        return work();
    }
    DOING.with(|d| d.borrow_mut().push(what()));
    let _done = Done;
    work()
}

/// Ends the innermost [`doing`] however its work ends (a panic caught further up too).
struct Done;

impl Drop for Done {
    fn drop(&mut self) {
        let what = DOING.with(|d| d.borrow_mut().pop());
        // Work that only counts (never asks `check`) is found spent as it ends.
        if SPENT.with(Cell::get) > LIMIT.with(Cell::get) {
            RAN_OUT_IN.with(|r| {
                r.borrow_mut()
                    .get_or_insert_with(|| what.unwrap_or_default());
            });
        }
    }
}

/// What the last budgeted run on this thread that ran out of work was doing when it did
/// (the innermost [`doing`]), once: for the refusal's words.
pub fn ran_out_in() -> Option<String> {
    LAST_RAN_OUT_IN.with(|l| l.borrow_mut().take())
}

/// Notes what the work is doing as the budget is found spent (the first time only).
#[cold]
fn note_running_out() {
    RAN_OUT_IN.with(|r| {
        let mut r = r.borrow_mut();
        if r.is_none() {
            *r = DOING.with(|d| d.borrow().last().cloned());
        }
    });
}

/// Counts `operations` against this thread's budget (never fails; see [`check`]).
#[inline]
pub fn count(operations: u64) {
    SPENT.with(|spent| spent.set(spent.get().saturating_add(operations)));
}

/// Counts `operations` and refuses once the budget is spent.
#[inline]
pub fn spend(operations: u64) -> Result<(), AlgebraError> {
    count(operations);
    check()
}

/// Counts `operations` and tells whether the budget is now spent: an infallible walk may
/// stop there with any value, since [`Budget::run`] refuses every result reached after it
/// (a count over a shared subexpression, met once per use, could otherwise run for ever).
#[inline]
pub fn count_and_spent(operations: u64) -> bool {
    count(operations);
    check().is_err()
}

/// Refuses once this thread's budget is spent.
#[inline]
pub fn check() -> Result<(), AlgebraError> {
    let limit = LIMIT.with(Cell::get);
    if SPENT.with(Cell::get) > limit {
        note_running_out();
        return Err(AlgebraError::OutOfWork { limit });
    }
    Ok(())
}

/// The operations one input may spend.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Budget {
    limit: u64,
}

impl Budget {
    /// The budget of an input of `bytes` bytes: `FLOOR + PER_BYTE · bytes`.
    pub fn for_input(bytes: usize) -> Budget {
        Budget {
            limit: FLOOR.saturating_add(PER_BYTE.saturating_mul(bytes as u64)),
        }
    }

    /// The share of this budget for `part` bytes of an input of `whole` bytes, in proportion
    /// (the claims of one file: together they spend at most the file's budget).
    pub fn share(self, part: usize, whole: usize) -> Budget {
        let share = self.limit as u128 * part as u128 / whole.max(1) as u128;
        Budget {
            limit: u64::try_from(share).unwrap_or(u64::MAX),
        }
    }

    /// A budget of exactly `limit` operations (tests, and callers with a bound of their own).
    pub fn of(limit: u64) -> Budget {
        Budget { limit }
    }

    /// The operations this budget allows.
    pub fn limit(self) -> u64 {
        self.limit
    }

    /// Runs `work` on this thread within the budget: its result and the operations it
    /// spent, or [`AlgebraError::OutOfWork`] when it spent more than the budget, whatever
    /// it returned. A budget already running on this thread is suspended meanwhile and
    /// charged with what `work` spent.
    pub fn run<T>(self, work: impl FnOnce() -> T) -> Result<(T, u64), AlgebraError> {
        let outer = Suspended {
            spent: SPENT.with(|s| s.replace(0)),
            limit: LIMIT.with(|l| l.replace(self.limit)),
            ran_out_in: RAN_OUT_IN.with(|r| r.borrow_mut().take()),
        };
        let outcome = work();
        let spent = SPENT.with(Cell::get);
        let ran_out_in = RAN_OUT_IN.with(|r| r.borrow_mut().take());
        drop(outer);
        if spent > self.limit {
            LAST_RAN_OUT_IN.with(|l| *l.borrow_mut() = ran_out_in);
            return Err(AlgebraError::OutOfWork { limit: self.limit });
        }
        Ok((outcome, spent))
    }
}

impl Budget {
    /// [`Budget::run`] for work that belongs to another input than the one whose budget is
    /// running on this thread (the checker's context derived again with a slip, once, for
    /// every claim that needs it): the running budget is suspended and not charged.
    pub fn run_apart<T>(self, work: impl FnOnce() -> T) -> Result<(T, u64), AlgebraError> {
        let outer = Apart {
            spent: SPENT.with(Cell::get),
            limit: LIMIT.with(Cell::get),
        };
        let outcome = self.run(work);
        drop(outer);
        outcome
    }
}

/// The budget a [`Budget::run_apart`] leaves as it found it.
struct Apart {
    spent: u64,
    limit: u64,
}

impl Drop for Apart {
    fn drop(&mut self) {
        SPENT.with(|s| s.set(self.spent));
        LIMIT.with(|l| l.set(self.limit));
    }
}

/// The budget a [`Budget::run`] suspends, restored when the run ends, however it ends (a
/// panic caught further up leaves this thread's budget as it was): charged with the run's
/// work.
struct Suspended {
    spent: u64,
    limit: u64,
    ran_out_in: Option<String>,
}

impl Drop for Suspended {
    fn drop(&mut self) {
        let inner = SPENT.with(Cell::get);
        SPENT.with(|s| s.set(self.spent.saturating_add(inner)));
        LIMIT.with(|l| l.set(self.limit));
        RAN_OUT_IN.with(|r| *r.borrow_mut() = self.ran_out_in.take());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::Expr;

    fn polynomial_work() -> Result<Expr, AlgebraError> {
        let (a, b) = (Expr::symbol("a"), Expr::symbol("b"));
        (&a + &b).powi(12).expand()
    }

    #[test]
    fn building_expressions_is_counted() {
        let (outcome, spent) = Budget::of(u64::MAX).run(polynomial_work).unwrap();
        // (a + b)^12 has 13 terms, each built with its operands.
        assert_eq!(outcome.unwrap().terms().len(), 13);
        assert!(spent >= 13, "spent {spent}");
    }

    #[test]
    fn a_spent_budget_refuses_the_result_and_the_steps() {
        let (_, needed) = Budget::of(u64::MAX).run(polynomial_work).unwrap();
        let outcome = Budget::of(needed / 2).run(polynomial_work);
        assert_eq!(
            outcome.unwrap_err(),
            AlgebraError::OutOfWork { limit: needed / 2 }
        );
        // The same work within a budget just large enough.
        assert!(Budget::of(needed).run(polynomial_work).is_ok());
    }

    #[test]
    fn nested_budgets_charge_the_outer_one_and_restore_it() {
        let outer = Budget::of(1_000_000).run(|| {
            let (_, inner) = Budget::of(u64::MAX).run(polynomial_work).unwrap();
            assert!(check().is_ok());
            inner
        });
        let (inner, outer_spent) = outer.unwrap();
        assert_eq!(inner, outer_spent);
        // Outside every budget nothing is refused.
        assert!(spend(u64::MAX).is_ok());
    }

    /// A refusal names the innermost work it ran out in; work outside a budget is not named.
    #[test]
    fn a_refusal_names_what_the_work_was_doing() {
        let (_, needed) = Budget::of(u64::MAX).run(polynomial_work).unwrap();
        let named = || doing(|| "multiplying out (a + b)^12".into(), polynomial_work);
        let outcome = Budget::of(needed / 2).run(|| doing(|| "the whole".into(), named));
        assert!(outcome.is_err());
        assert_eq!(ran_out_in().as_deref(), Some("multiplying out (a + b)^12"));
        // Taken once; a run that does not run out leaves nothing.
        assert_eq!(ran_out_in(), None);
        assert!(Budget::of(needed * 2).run(named).is_ok());
        assert_eq!(ran_out_in(), None);
        assert_eq!(
            doing(|| unreachable!("not named outside a budget"), || 1),
            1
        );
    }

    #[test]
    fn the_budget_grows_with_the_input() {
        assert_eq!(Budget::for_input(0).limit(), FLOOR);
        assert_eq!(
            Budget::for_input(1 << 20).limit(),
            FLOOR + PER_BYTE * (1 << 20)
        );
    }
}
