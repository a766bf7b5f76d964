//! Cardano's formula for a cubic `a u³ + b u² + c u + d` with rational coefficients.
//!
//! `u = t − b/(3a)` gives the reduced cubic `t³ + p t + q = 0` with
//! `p = (3ac − b²)/(3a²)` and `q = (2b³ − 9abc + 27a²d)/(27a³)`; let `Δ = q²/4 + p³/27`.
//!
//! - `Δ > 0`: one real root `t = ∛(−q/2 + √Δ) + ∛(−q/2 − √Δ)` (real cube roots: the sign of
//!   each radicand `α ± √Δ` is decided exactly, by comparing `α²` with `Δ`); the complex
//!   pair `−(C₁ + C₂)/2 ± (C₁ − C₂)√(−3)/2` is dropped with the reason.
//! - `Δ = 0`: `t = 3q/p` and the double root `t = −3q/(2p)` (`p ≠ 0`), or `t = 0` (`p = 0`).
//! - `Δ < 0`: three real roots that no formula in real radicals gives (the casus
//!   irreducibilis), and the trigonometric form needs the inverse cosine, which the algebra
//!   does not have: refused ([`SolveError::RootsNotExact`]). A cubic with three rational
//!   roots never gets here: its roots were found first.

use super::quadratic::square_root;
use super::roots::Found;
use super::{Condition, DroppedRoot, SolveError};
use crate::algebra::error::AlgebraError;
use crate::algebra::expr::Expr;
use crate::algebra::rational::Q;
use crate::algebra::symbol::Symbol;
use std::cmp::Ordering;

/// The real roots of `Σ aₖ uᵏ` (`a = [d, c, b, a]`, lowest power first), by the module
/// documentation.
pub(super) fn cubic(coefficients: &[Q; 4], u: Symbol) -> Result<Found, SolveError> {
    let [d, c, b, a] = coefficients;
    let quotient = |n: Q, m: Q| n.checked_div(&m).ok_or(AlgebraError::DivisionByZero);
    let q_int = |n: i64| Q::int(n);
    let shift = quotient(b.clone(), &q_int(3) * a)?;
    let a2 = a * a;
    let p = quotient(&(&(&q_int(3) * a) * c) - &(b * b), &q_int(3) * &a2)?;
    let q = quotient(
        &(&(&q_int(2) * &(&(b * b) * b)) - &(&(&q_int(9) * a) * &(b * c)))
            + &(&(&q_int(27) * &a2) * d),
        &(&q_int(27) * &a2) * a,
    )?;
    let half_q = quotient(q.clone(), q_int(2))?;
    let discriminant = &(&half_q * &half_q) + &quotient(&(&p * &p) * &p, q_int(27))?;
    let from_t = |t: Expr| &t - &Expr::num(shift.clone());
    let mut found = Found::default();
    match discriminant.cmp(&Q::ZERO) {
        Ordering::Less => {
            return Err(SolveError::RootsNotExact {
                unknown: u,
                reason: format!(
                    "the cubic has three real roots that are not rational (q²/4 + p³/27 = {discriminant} is negative for its reduced form t³ + p t + q), which real square and cube roots cannot write, and the trigonometric form needs the inverse cosine"
                ),
            })
        }
        Ordering::Equal if p.is_zero() => found.real.push(from_t(Expr::zero())),
        Ordering::Equal => {
            let single = quotient(&q_int(3) * &q, p.clone())?;
            let double = quotient(-&(&q_int(3) * &q), &q_int(2) * &p)?;
            found.real.push(from_t(Expr::num(single)));
            found.real.push(from_t(Expr::num(double)));
        }
        Ordering::Greater => {
            let s = square_root(&Expr::num(discriminant.clone()))?;
            let alpha = -&half_q;
            let c1 = real_cube_root(&alpha, &s, true, &discriminant)?;
            let c2 = real_cube_root(&alpha, &s, false, &discriminant)?;
            found.real.push(from_t(&c1 + &c2).expand()?);
            let mean = &Expr::rational(-1, 2) * &(&c1 + &c2);
            let imaginary = &(&Expr::rational(1, 2) * &(&c1 - &c2))
                * &Expr::int(-3).checked_pow(&Expr::rational(1, 2))?;
            for value in [&mean - &imaginary, &mean + &imaginary] {
                found.dropped.push(DroppedRoot {
                    unknown: u,
                    value: from_t(value),
                    reason: format!(
                        "complex: q²/4 + p³/27 = {discriminant} is positive for the reduced cubic t³ + p t + q, so one root is real and two are complex"
                    ),
                    condition: Condition {
                        words: r"complex: $q^2/4 + p^3/27$ is positive for the reduced cubic $t^3 + p t + q = 0$, so one root is real and two are complex".into(),
                        lhs: reduced_discriminant()?,
                        rhs: Expr::num(discriminant.clone()),
                    },
                });
            }
        }
    }
    Ok(found)
}

/// The real `∛(α ± √Δ)` (`s = √Δ`, `Δ > 0`): `v^(1/3)` for `v > 0`, `−(−v)^(1/3)` for
/// `v < 0`, exact when `v` is a rational cube.
fn real_cube_root(alpha: &Q, s: &Expr, plus: bool, discriminant: &Q) -> Result<Expr, AlgebraError> {
    let root_sign = if plus {
        Ordering::Greater
    } else {
        Ordering::Less
    };
    let v = if plus {
        &Expr::num(alpha.clone()) + s
    } else {
        &Expr::num(alpha.clone()) - s
    };
    if let Some(root) = v.as_num().and_then(|x| x.exact_root(3)) {
        return Ok(Expr::num(root));
    }
    let alpha_sign = alpha.cmp(&Q::ZERO);
    let sign = if alpha_sign == Ordering::Equal || alpha_sign == root_sign {
        root_sign
    } else {
        match (alpha * alpha).cmp(discriminant) {
            Ordering::Greater => alpha_sign,
            Ordering::Less => root_sign,
            Ordering::Equal => Ordering::Equal,
        }
    };
    let third = Expr::rational(1, 3);
    Ok(match sign {
        Ordering::Equal => Expr::zero(),
        Ordering::Greater => v.checked_pow(&third)?,
        Ordering::Less => -(-v).checked_pow(&third)?,
    })
}

/// `q²/4 + p³/27` in the symbols p and q of the reduced cubic `t³ + p t + q`.
fn reduced_discriminant() -> Result<Expr, AlgebraError> {
    let (p, q) = (Expr::symbol("p"), Expr::symbol("q"));
    let square = q.checked_pow(&Expr::int(2))?;
    let cube = p.checked_pow(&Expr::int(3))?;
    Ok(&(&Expr::rational(1, 4) * &square) + &(&Expr::rational(1, 27) * &cube))
}
