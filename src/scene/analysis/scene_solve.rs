//! The scene's unknowns solved by [`solve_system`] with what the scene knows of signs: an
//! expression's sign is proved from the symbols' domains, else told by the givens' exact
//! values (in double-double, a sign only beyond the bound on its rounding); an unknown in kg, m or kg·m² must be positive. A linear system is one solution;
//! an unknown that enters polynomially is solved when one polynomial in one unknown remains,
//! its roots that the conditions rule out dropped. Several real roots are several
//! solutions (a top's slow and fast precession), each shown as a solution of its own.

use super::super::model::Scene;
use super::super::units::Dimension;
use crate::algebra::polynomial_solve::{solve_system, Solutions, SolveContext, SolveError};
use crate::algebra::{Expr, Symbol};
use crate::numeric::rounding_error::{bounded, Bounded};
use std::cmp::Ordering;

/// `equations = 0` solved for `wanted`: each solution, the roots dropped and the polynomial
/// solved (when there was one).
pub(super) fn solve_scene(
    scene: &Scene,
    equations: &[Expr],
    wanted: &[Symbol],
) -> Result<Solutions, SolveError> {
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
        // In double-double with a bound on its rounding: a sign only where the value is
        // beyond the bound (nested radicals cancel; a scale like 1e-15 is no zero).
        let Bounded { value, error } = bounded(&exact, &|_| None)?;
        let value = value.to_f64();
        (value.abs() > error && error.is_finite()).then(|| value.total_cmp(&0.0))
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
    solve_system(equations, wanted, &context)
}
