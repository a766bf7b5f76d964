//! Ferrari's method for the real roots of a quartic `a u⁴ + b u³ + c u² + d u + e`, with
//! numbers or symbols for coefficients.
//!
//! `u = y − b/(4a)` gives the reduced quartic `y⁴ + P y² + Q y + R = 0` with
//! `P = (8ac − 3b²)/(8a²)`, `Q = (b³ − 4abc + 8a²d)/(8a³)`,
//! `R = (16ab²c − 3b⁴ − 64a²bd + 256a³e)/(256a⁴)`. For `Q = 0` it is a quadratic in `y²`.
//! Otherwise, for any root `m` of the resolvent cubic `8m³ + 8P m² + (2P² − 8R) m − Q² = 0`,
//!
//! `y⁴ + P y² + Q y + R = (y² + P/2 + m)² − (s y − Q/(2s))²` with `s = √(2m)`,
//!
//! so for `m > 0` (the resolvent is `−Q² < 0` at `m = 0` and grows without bound, so it has
//! a positive root) the quartic is the product of the two real quadratics
//! `y² ∓ s y + P/2 + m ± Q/(2s)`, each solved by the quadratic formula: its complex pair is
//! dropped with the reason.

use super::quadratic::{biquadratic, quadratic, square_root};
use super::roots::{distinct_real_roots, Found};
use super::{exact, SolveContext, SolveError};
use crate::algebra::error::AlgebraError;
use crate::algebra::expr::Expr;
use crate::algebra::symbol::Symbol;
use std::cmp::Ordering;

/// The real roots of `Σ aₖ uᵏ` (`coefficients = [e, d, c, b, a]`, lowest power first,
/// `a ≠ 0`), by the module documentation.
pub(super) fn quartic(
    coefficients: &[Expr; 5],
    u: Symbol,
    context: &SolveContext,
) -> Result<Found, SolveError> {
    let [e, d, c, b, a] = coefficients;
    let int = Expr::int;
    let lowest = |numerator: Expr, denominator: Expr| -> Result<Expr, AlgebraError> {
        numerator.checked_div(&denominator)?.cancel()
    };
    let shift = lowest(b.clone(), &int(4) * a)?;
    let capital_p = lowest(
        &(&int(8) * &(a * c)) - &(&int(3) * &b.powi(2)),
        &int(8) * &a.powi(2),
    )?;
    let capital_q = lowest(
        &(&b.powi(3) - &(&int(4) * &(&(a * b) * c))) + &(&int(8) * &(&a.powi(2) * d)),
        &int(8) * &a.powi(3),
    )?;
    let capital_r = lowest(
        Expr::add_all([
            &int(16) * &(&(a * &b.powi(2)) * c),
            &int(-3) * &b.powi(4),
            &int(-64) * &(&(&a.powi(2) * b) * d),
            &int(256) * &(&a.powi(3) * e),
        ]),
        &int(256) * &a.powi(4),
    )?;
    let in_u = |found: Found| shifted(found, &shift);
    if capital_q.is_zero() || context.sign_of(&capital_q) == Some(Ordering::Equal) {
        // A quadratic in y²: its words name y, which is u only when there is no shift.
        let y = if shift.is_zero() { u } else { Symbol::new("y") };
        let mut found = biquadratic(&Expr::one(), &capital_p, &capital_r, y, context)?;
        for dropped in &mut found.dropped {
            dropped.unknown = u;
            if y != u {
                let y_is = &Expr::sym(u) + &shift;
                dropped.reason = format!("{}, where y = {y_is}", dropped.reason);
            }
        }
        return in_u(found);
    }
    let m = positive_resolvent_root(&capital_p, &capital_q, &capital_r, u, context)?;
    let s = square_root(&(&int(2) * &m))?;
    let half_p_plus_m = &(&Expr::rational(1, 2) * &capital_p) + &m;
    let q_over_2s = capital_q.checked_div(&(&int(2) * &s))?;
    let mut found = Found::default();
    for side in [-1, 1] {
        let side = int(side);
        let linear = &side * &s;
        let constant = exact(&(&half_p_plus_m - &(&side * &q_over_2s)))?;
        // A factor whose discriminant's sign the values leave open could hold a real pair
        // or a complex one; the quadratic formula would keep both.
        let discriminant = exact(&(&linear.powi(2) - &(&int(4) * &constant)))?;
        if !discriminant.is_zero() && context.sign_of(&discriminant).is_none() {
            return Err(SolveError::RootsNotExact {
                unknown: u,
                reason: "the sign of the discriminant of a quadratic factor of the reduced quartic (Ferrari's method) is not told by the givens' values".into(),
            });
        }
        let mut factor = quadratic(&Expr::one(), &linear, &constant, u, context)?;
        for dropped in &mut factor.dropped {
            dropped.reason = format!(
                "{}, for a quadratic factor y² ± s y + … of the reduced quartic (Ferrari's method)",
                dropped.reason
            );
            dropped.condition.words = format!(
                r"{}, for a quadratic factor of the reduced quartic (Ferrari's method)",
                dropped.condition.words
            );
        }
        found.extend(in_u(factor)?);
    }
    Ok(found)
}

/// A positive root of the resolvent `8m³ + 8P m² + (2P² − 8R) m − Q² = 0` (the shortest
/// written, by its count of nodes, when several are known to be positive).
fn positive_resolvent_root(
    capital_p: &Expr,
    capital_q: &Expr,
    capital_r: &Expr,
    u: Symbol,
    context: &SolveContext,
) -> Result<Expr, SolveError> {
    let int = Expr::int;
    let resolvent = [
        -capital_q.powi(2),
        (&(&int(2) * &capital_p.powi(2)) - &(&int(8) * capital_r)).expand()?,
        &int(8) * capital_p,
        int(8),
    ];
    let within_resolvent = |e: SolveError| match e {
        SolveError::RootsNotExact { reason, .. } => SolveError::RootsNotExact {
            unknown: u,
            reason: format!("for the resolvent cubic of Ferrari's method, {reason}"),
        },
        other => other,
    };
    // Its unknown by a name no input can hold (a letter m would be a scene's mass).
    let roots = distinct_real_roots(&resolvent, Symbol::new("Ferrari's m"), context)
        .map_err(within_resolvent)?
        .real;
    roots
        .into_iter()
        .filter(|m| context.sign_of(m) == Some(Ordering::Greater))
        .min_by_key(Expr::node_count)
        .ok_or_else(|| SolveError::RootsNotExact {
            unknown: u,
            reason:
                "no root of Ferrari's resolvent cubic is known to be positive at the givens' values"
                    .into(),
        })
}

/// The roots in `y` as roots in `u = y − shift`.
fn shifted(found: Found, shift: &Expr) -> Result<Found, SolveError> {
    let to_u = |y: &Expr| (y - shift).expand();
    let mut out = Found::default();
    for y in &found.real {
        out.real.push(to_u(y)?);
    }
    for mut dropped in found.dropped {
        dropped.value = to_u(&dropped.value)?;
        out.dropped.push(dropped);
    }
    Ok(out)
}
