//! The scene's unknowns solved by [`solve_system`] with what the scene knows of signs: an
//! expression's sign is proved from the symbols' domains, else told by the givens' exact
//! values; an unknown in kg, m or kg·m² must be positive. A linear system is one solution;
//! an unknown that enters polynomially is solved when one polynomial in one unknown remains,
//! its roots that the conditions rule out dropped. Several real roots are several
//! solutions, which a worked solution does not show yet: they are refused with the roots.

use super::super::model::{Scene, Span};
use super::super::units::Dimension;
use crate::algebra::polynomial_solve::{solve_system, Solutions, SolveContext, SolveError};
use crate::algebra::{Expr, Symbol};
use crate::parse::Diagnostic;
use std::cmp::Ordering;

/// `equations = 0` solved for `wanted`: one solution, with the roots dropped and the
/// polynomial solved (when there was one); several solutions are refused at `at`.
pub(super) fn solve_scene(
    scene: &Scene,
    equations: &[Expr],
    wanted: &[Symbol],
    at: Span,
) -> Result<Result<Solutions, SolveError>, Diagnostic> {
    let domains = scene.domains();
    let sign = |e: &Expr| -> Option<Ordering> {
        if let Some(proved) = domains.strict_sign(e) {
            return Some(proved);
        }
        let exact = e
            .subs(&|s| scene.exact_given(s))
            .and_then(|x| x.expand())
            .ok()?;
        if exact.is_zero() {
            return Some(Ordering::Equal);
        }
        let value: f64 = exact.eval(&|_| None).ok()?;
        (value.abs() > 1e-12).then(|| value.total_cmp(&0.0))
    };
    let positive = |s: Symbol| {
        scene
            .dimension(s)
            .is_some_and(|d| [Dimension::MASS, Dimension::LENGTH, Dimension::INERTIA].contains(&d))
    };
    let context = SolveContext {
        sign: &sign,
        positive: &positive,
    };
    let solutions = match solve_system(equations, wanted, &context) {
        Ok(solutions) => solutions,
        Err(e) => return Ok(Err(e)),
    };
    if solutions.branches.len() <= 1 {
        return Ok(Ok(solutions));
    }
    let (unknown, _) = solutions
        .polynomial
        .clone()
        .unwrap_or_else(|| (wanted[0], Expr::zero()));
    let roots: Vec<String> = solutions
        .branches
        .iter()
        .filter_map(|b| b.iter().find(|(u, _)| *u == unknown))
        .map(|(_, v)| format!("{} = {v}", unknown.name()))
        .collect();
    Err(scene.error_at(
        at,
        format!(
            "the equations have {} solutions, {}: each is a solution of its own, and a worked solution shows one",
            roots.len(),
            roots.join("; ")
        ),
        format!(
            "give {} as a given with the value you want (one of these), or ask for the unknowns that do not depend on it",
            unknown.name()
        ),
    ))
}
