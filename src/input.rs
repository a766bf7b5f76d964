//! Every caller's work on an input (each command of the command line, each call of the
//! Python binding) runs within the input's work budget
//! ([`crate::algebra::work`]: a floor plus a number of operations per byte), so that any
//! input ends in bounded time: answered, or refused at a place in it with the reason.
//!
//! With the environment variable `KINETICS_WORK_REPORT` set, each budgeted piece of work
//! writes `work: SPENT of LIMIT operations` to standard error (a refusal as `LIMIT + 1`):
//! the tests measure the work of hostile inputs by it, not by the wall clock.

use crate::algebra::work::{self, Budget};
use crate::algebra::AlgebraError;
use crate::parse::Diagnostic;
use crate::print::markup;
use std::ops::Range;

/// An input a caller works on: its name in diagnostics, its text, and the place a refusal
/// for work stands at (the whole expression, or a scene's first request).
pub struct Input<'a> {
    pub name: &'a str,
    pub source: &'a str,
    pub place: Range<usize>,
    /// The operations the work on it may spend: its bytes' budget, or a share of a larger
    /// input's.
    pub budget: Budget,
}

impl<'a> Input<'a> {
    /// An expression or a claim: a refusal stands at all of it.
    pub fn expression(name: &'a str, source: &'a str) -> Input<'a> {
        Input {
            name,
            source,
            place: 0..source.trim_end().len(),
            budget: Budget::for_input(source.len()),
        }
    }

    /// A scene: a refusal stands at its first `find` (what pulls the work), else at its
    /// first statement. Found in the text, since the scene is parsed within the budget.
    pub fn scene(name: &'a str, source: &'a str) -> Input<'a> {
        let mut first_statement = None;
        let mut start = 0;
        for line in source.split_inclusive('\n') {
            let statement = line.trim();
            let from = start + (line.len() - line.trim_start().len());
            let place = from..from + statement.len();
            start += line.len();
            if statement.is_empty() || statement.starts_with('#') {
                continue;
            }
            if statement.starts_with("find ") {
                first_statement = Some(place);
                break;
            }
            first_statement.get_or_insert(place);
        }
        Input {
            name,
            source,
            place: first_statement.unwrap_or(0..0),
            budget: Budget::for_input(source.len()),
        }
    }

    /// Runs `work` within this input's budget. A result reached after the
    /// budget was spent is refused too: no answer is ever the product of cut-short work.
    pub fn within<T, E: From<Diagnostic>>(
        &self,
        work: impl FnOnce() -> Result<T, E>,
    ) -> Result<T, E> {
        let budget = self.budget;
        match budget.run(work) {
            Ok((outcome, spent)) => {
                report(spent, budget);
                outcome
            }
            Err(out_of_work) => {
                report(budget.limit().saturating_add(1), budget);
                Err(self.refusal(out_of_work).into())
            }
        }
    }

    /// The refusal for a spent budget, located at [`Input::place`], with what the work was
    /// doing when it ran out (`work::doing`: a step's title in the markup of titles).
    fn refusal(&self, out_of_work: AlgebraError) -> Diagnostic {
        let Range { start, end } = self.place;
        let message = match work::ran_out_in() {
            Some(doing) => format!("{out_of_work}: it ran out {}", markup::text(&doing)),
            None => out_of_work.to_string(),
        };
        Diagnostic::at(self.name, self.source, start, end, message)
            .with_help("simplify the input or split it into smaller parts")
    }
}

/// Writes the work spent when `KINETICS_WORK_REPORT` is set (module documentation).
fn report(spent: u64, budget: Budget) {
    if std::env::var_os("KINETICS_WORK_REPORT").is_some() {
        eprintln!("work: {spent} of {} operations", budget.limit());
    }
}
