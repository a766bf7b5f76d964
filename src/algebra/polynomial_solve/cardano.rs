//! The real roots of a cubic `a u³ + b u² + c u + d`, exactly, with numbers or symbols for
//! coefficients.
//!
//! `u = t − b/(3a)` gives the reduced cubic `t³ + p t + q = 0` with
//! `p = (3ac − b²)/(3a²)` and `q = (2b³ − 9abc + 27a²d)/(27a³)`; let `Δ = q²/4 + p³/27`.
//! Its sign (told by the context for symbols) says how many roots are real:
//!
//! - `Δ > 0`: one, Cardano's `t = ∛(−q/2 + √Δ) + ∛(−q/2 − √Δ)` with real cube roots. The
//!   sign of each radicand `α ± √Δ` (`α = −q/2`) follows from the signs of `α` and of
//!   `α² − Δ = −p³/27`. The complex pair `−(C₁ + C₂)/2 ± (C₁ − C₂)√(−3)/2` is dropped with
//!   the reason.
//! - `Δ = 0`: `t = 3q/p` and the double root `t = −3q/(2p)` (`p ≠ 0`), or `t = 0` (`p = 0`).
//! - `Δ < 0` (then `p < 0`): three, which real radicals cannot write (the casus
//!   irreducibilis), by the trigonometric form
//!   `t_k = 2√(−p/3) cos(⅓ arccos((3q/(2p))√(−3/p)) − 2πk/3)`, `k = 0, 1, 2`.
//!
//! A sign the context cannot tell is refused ([`SolveError::RootsNotExact`]) with the
//! quantity whose sign decides.

use super::quadratic::square_root;
use super::roots::Found;
use super::{Condition, DroppedRoot, SolveContext, SolveError};
use crate::algebra::error::AlgebraError;
use crate::algebra::expr::Expr;
use crate::algebra::function::Func;
use crate::algebra::symbol::Symbol;
use std::cmp::Ordering;

/// The real roots of `Σ aₖ uᵏ` (`coefficients = [d, c, b, a]`, lowest power first, `a ≠ 0`),
/// by the module documentation.
pub(super) fn cubic(
    coefficients: &[Expr; 4],
    u: Symbol,
    context: &SolveContext,
) -> Result<Found, SolveError> {
    let Reduced {
        shift,
        p,
        q,
        discriminant,
    } = &Reduced::of(coefficients)?;
    let sign = |e: &Expr| {
        if e.is_zero() {
            Some(Ordering::Equal)
        } else {
            context.sign_of(e)
        }
    };
    let undecided = |what: &str, value: &Expr| {
        // A value too long to read in a message is left out.
        let value = value.to_string();
        let what = match value.len() {
            0..=120 => format!("{what} = {value}"),
            _ => what.to_string(),
        };
        SolveError::RootsNotExact {
            unknown: u,
            reason: format!(
                "the roots of the cubic depend on the sign of {what} (for its reduced form t³ + p t + q), which the givens do not tell"
            ),
        }
    };
    let from_t = |t: Expr| (&t - shift).expand();
    let mut found = Found::default();
    match sign(discriminant) {
        None => return Err(undecided("q²/4 + p³/27", discriminant)),
        Some(Ordering::Equal) => match sign(p) {
            Some(Ordering::Equal) => found.real.push(from_t(Expr::zero())?),
            Some(_) => {
                let single = (&Expr::int(3) * q).checked_div(p)?.cancel()?;
                let double = (&Expr::rational(-3, 2) * q).checked_div(p)?.cancel()?;
                found.real.push(from_t(single)?);
                found.real.push(from_t(double)?);
            }
            None => return Err(undecided("p", p)),
        },
        Some(Ordering::Greater) => {
            let alpha_sign = sign(q).map(Ordering::reverse);
            let p_sign = sign(p);
            // The radicands −q/2 ± √Δ, their signs from those of q and p.
            let alpha = &Expr::rational(-1, 2) * q;
            let s = square_root(discriminant)?;
            let cube_root = |plus: bool| -> Result<Expr, SolveError> {
                let sign =
                    radicand_sign(plus, alpha_sign, p_sign).ok_or_else(|| match alpha_sign {
                        None => undecided("q", q),
                        Some(_) => undecided("p", p),
                    })?;
                let v = if plus { &alpha + &s } else { &alpha - &s };
                Ok(real_cube_root(v, sign)?)
            };
            let c1 = cube_root(true)?;
            let c2 = cube_root(false)?;
            found.real.push(from_t(&c1 + &c2)?);
            let mean = &Expr::rational(-1, 2) * &(&c1 + &c2);
            let imaginary = &(&Expr::rational(1, 2) * &(&c1 - &c2))
                * &Expr::int(-3).checked_pow(&Expr::rational(1, 2))?;
            for value in [&mean - &imaginary, &mean + &imaginary] {
                found.dropped.push(DroppedRoot {
                    unknown: u,
                    value: from_t(value)?,
                    reason: format!(
                        "complex: q²/4 + p³/27 = {discriminant} is positive for the reduced cubic t³ + p t + q, so one root is real and two are complex"
                    ),
                    condition: Condition {
                        words: r"complex: $q^2/4 + p^3/27$ is positive for the reduced cubic $t^3 + p t + q = 0$, so one root is real and two are complex".into(),
                        lhs: reduced_discriminant()?,
                        rhs: discriminant.clone(),
                    },
                });
            }
        }
        Some(Ordering::Less) => {
            for t in trigonometric_roots(p, q)? {
                found.real.push(from_t(t)?);
            }
        }
    }
    Ok(found)
}

/// The reduced cubic `t³ + p t + q` of `a u³ + b u² + c u + d` by `u = t − shift`, each part
/// in lowest terms.
struct Reduced {
    shift: Expr,
    p: Expr,
    q: Expr,
    /// `Δ = q²/4 + p³/27`.
    discriminant: Expr,
}

impl Reduced {
    fn of(coefficients: &[Expr; 4]) -> Result<Reduced, AlgebraError> {
        let [d, c, b, a] = coefficients;
        let int = Expr::int;
        let a2 = a * a;
        let shift = b.checked_div(&(&int(3) * a))?.cancel()?;
        let p = (&(&int(3) * &(a * c)) - &(b * b))
            .checked_div(&(&int(3) * &a2))?
            .cancel()?;
        let q = (&(&(&int(2) * &b.powi(3)) - &(&int(9) * &(&(a * b) * c)))
            + &(&int(27) * &(&a2 * d)))
            .checked_div(&(&int(27) * &(&a2 * a)))?
            .cancel()?;
        let discriminant = (&(&Expr::rational(1, 4) * &q.powi(2))
            + &(&Expr::rational(1, 27) * &p.powi(3)))
            .cancel()?;
        Ok(Reduced {
            shift,
            p,
            q,
            discriminant,
        })
    }
}

/// The sign of the radicand `v = α ± √Δ` (`α = −q/2`, `Δ > 0`), None when it is not told:
/// for `+`, `v > 0` when `α ≥ 0`, else `v` has the sign of `Δ − α² = p³/27`; for `−`,
/// `v < 0` when `α ≤ 0`, else `v` has the sign of `α² − Δ`. For `p > 0` both follow
/// whatever `α` is.
fn radicand_sign(
    plus: bool,
    alpha_sign: Option<Ordering>,
    p_sign: Option<Ordering>,
) -> Option<Ordering> {
    let toward = if plus {
        Ordering::Greater
    } else {
        Ordering::Less
    };
    match (alpha_sign, p_sign) {
        (_, Some(Ordering::Greater)) => Some(toward),
        (Some(s), _) if s == Ordering::Equal || s == toward => Some(toward),
        (Some(_), Some(p)) if plus => Some(p),
        (Some(_), Some(p)) => Some(p.reverse()),
        _ => None,
    }
}

/// The real `∛v` of a radicand of sign `sign`: `v^(1/3)` for `v > 0`, `−(−v)^(1/3)` for
/// `v < 0`, exact when `v` is a rational cube.
fn real_cube_root(v: Expr, sign: Ordering) -> Result<Expr, AlgebraError> {
    if let Some(root) = v.as_num().and_then(|x| x.exact_root(3)) {
        return Ok(Expr::num(root));
    }
    let third = Expr::rational(1, 3);
    Ok(match sign {
        Ordering::Equal => Expr::zero(),
        Ordering::Greater => v.checked_pow(&third)?,
        Ordering::Less => -(-v).checked_pow(&third)?,
    })
}

/// The three real roots of `t³ + p t + q` for `q²/4 + p³/27 < 0` (so `p < 0`), largest
/// first: `2√(−p/3) cos(θ/3 − 2πk/3)` with `cos θ = (3q/(2p))√(−3/p)`.
fn trigonometric_roots(p: &Expr, q: &Expr) -> Result<[Expr; 3], AlgebraError> {
    let amplitude = &Expr::int(2) * &square_root(&(-p).checked_div(&Expr::int(3))?.cancel()?)?;
    let cosine = &(&Expr::rational(3, 2) * q).checked_div(p)?.cancel()?
        * &square_root(&Expr::int(-3).checked_div(p)?.cancel()?)?;
    let third_of_angle = &Func::Acos.checked_apply(cosine)? * &Expr::rational(1, 3);
    let root = |k: i64| -> Expr {
        let turn = &Expr::rational(2 * k, 3) * &Expr::pi();
        &amplitude * &Func::Cos.apply(&third_of_angle - &turn)
    };
    Ok([root(0), root(1), root(2)])
}

/// `q²/4 + p³/27` in the symbols p and q of the reduced cubic `t³ + p t + q`.
fn reduced_discriminant() -> Result<Expr, AlgebraError> {
    let (p, q) = (Expr::symbol("p"), Expr::symbol("q"));
    let square = q.checked_pow(&Expr::int(2))?;
    let cube = p.checked_pow(&Expr::int(3))?;
    Ok(&(&Expr::rational(1, 4) * &square) + &(&Expr::rational(1, 27) * &cube))
}
