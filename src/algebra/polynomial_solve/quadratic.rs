//! The quadratic formula: the roots of `a u² + b u + c` (`a ≠ 0`) are
//! `u = (−b ± √Δ)/(2a)` with the discriminant `Δ = b² − 4ac`, each in lowest terms. They are
//! real for `Δ > 0`, one double root `−b/(2a)` for `Δ = 0`, a complex pair (dropped, with the
//! reason) for `Δ < 0`; a `Δ` of unknown sign keeps both. A biquadratic `a u⁴ + b u² + c` is
//! the quadratic in `u²`: each real `u² = y` gives `u = ±√y` for `y > 0`, `u = 0` for
//! `y = 0`, and none for `y < 0`.

use super::roots::Found;
use super::{exact, Condition, DroppedRoot, SolveContext};
use crate::algebra::common_factor::content_and_primitive;
use crate::algebra::error::AlgebraError;
use crate::algebra::expr::{Expr, View};
use crate::algebra::polynomial_gcd;
use crate::algebra::rational::Q;
use crate::algebra::symbol::Symbol;
use std::cmp::Ordering;

/// The roots of `a u² + b u + c` (module documentation), as the pair `(−b ∓ √Δ)/(2a)` (a
/// square factor of `Δ` taken out up to its sign, so in either order).
pub(super) fn quadratic(
    a: &Expr,
    b: &Expr,
    c: &Expr,
    u: Symbol,
    context: &SolveContext,
) -> Result<Found, AlgebraError> {
    let discriminant = (&(b * b) - &(&Expr::int(4) * &(a * c))).expand()?;
    let two_a = &Expr::int(2) * a;
    let root = |root_of_discriminant: &Expr| -> Result<Expr, AlgebraError> {
        (&(-b) + root_of_discriminant).checked_div(&two_a)?.cancel()
    };
    let sign = if discriminant.is_zero() {
        Some(Ordering::Equal)
    } else {
        context.sign_of(&discriminant)
    };
    let mut found = Found::default();
    if sign == Some(Ordering::Equal) {
        found.real.push(root(&Expr::zero())?);
        return Ok(found);
    }
    let s = square_root_up_to_sign(&discriminant)?;
    let pair = [root(&-&s)?, root(&s)?];
    if sign == Some(Ordering::Less) {
        found.dropped = pair
            .into_iter()
            .map(|value| DroppedRoot {
                unknown: u,
                value,
                reason: format!("complex: the discriminant b² − 4ac = {discriminant} is negative"),
                condition: Condition {
                    words: format!(
                        r"complex: the discriminant $\Delta = b^2 - 4ac$ of the quadratic $a {u}^2 + b {u} + c = 0$ is negative",
                        u = u.latex()
                    ),
                    lhs: Expr::sym(Symbol::new("Delta")),
                    rhs: discriminant.clone(),
                },
            })
            .collect();
    } else {
        found.real.extend(pair);
    }
    Ok(found)
}

/// The roots of `a u⁴ + b u² + c` (module documentation).
pub(super) fn biquadratic(
    a: &Expr,
    b: &Expr,
    c: &Expr,
    u: Symbol,
    context: &SolveContext,
) -> Result<Found, AlgebraError> {
    let squares = quadratic(a, b, c, u, context)?;
    let u_squared = Expr::sym(u).checked_pow(&Expr::int(2))?;
    let mut found = Found::default();
    let roots_of = |y: &Expr| -> Result<[Expr; 2], AlgebraError> {
        let s = square_root(y)?;
        Ok([-&s, s])
    };
    for d in squares.dropped {
        found
            .dropped
            .extend(roots_of(&d.value)?.into_iter().map(|value| DroppedRoot {
                unknown: u,
                value,
                reason: format!("complex: {}² is complex ({})", u.name(), d.reason),
                condition: Condition {
                    words: format!(
                        r"complex: ${u}^2$ is complex, the discriminant $\Delta$ of the quadratic in ${u}^2$ being negative",
                        u = u.latex()
                    ),
                    ..d.condition.clone()
                },
            }));
    }
    for y in squares.real {
        let y = exact(&y)?;
        let sign = if y.is_zero() {
            Some(Ordering::Equal)
        } else {
            context.sign_of(&y)
        };
        match sign {
            Some(Ordering::Equal) => found.real.push(Expr::zero()),
            Some(Ordering::Less) => {
                found
                    .dropped
                    .extend(roots_of(&y)?.into_iter().map(|value| DroppedRoot {
                        unknown: u,
                        value,
                        reason: format!("complex: {}² = {y} is negative", u.name()),
                        condition: Condition {
                            words: format!("complex: ${}^2$ is negative", u.latex()),
                            lhs: u_squared.clone(),
                            rhs: y.clone(),
                        },
                    }))
            }
            _ => found.real.extend(roots_of(&y)?),
        }
    }
    Ok(found)
}

/// `±√e` for a pair of roots `… ± √e`, whose sign does not matter: a square polynomial
/// factor `g²` of `e`'s numerator or denominator comes out as `g` (`√(a² + 2ab + b²) = ±(a + b)`),
/// the rest by [`square_root`].
fn square_root_up_to_sign(e: &Expr) -> Result<Expr, AlgebraError> {
    if e.as_num().is_some() || !is_rational_in_symbols(e) {
        return square_root(e);
    }
    let (numerator, denominator) = e.cancelled_parts()?;
    let (g_numerator, h_numerator) = square_factor(numerator)?;
    let (g_denominator, h_denominator) = square_factor(denominator)?;
    let outside = g_numerator.checked_div(&g_denominator)?;
    Ok(&outside * &square_root(&h_numerator.checked_div(&h_denominator)?)?)
}

/// Whether `e` is built of numbers and symbols by sums, products and integer powers (no
/// root, no function), so that its parts are polynomials.
fn is_rational_in_symbols(e: &Expr) -> bool {
    match e.view() {
        View::Num(_) | View::Sym(_) => true,
        View::Add(xs) | View::Mul(xs) => xs.iter().all(is_rational_in_symbols),
        View::Pow(base, exponent) => {
            exponent.as_num().is_some_and(|q| q.to_i64().is_some()) && is_rational_in_symbols(base)
        }
        View::Func(..) => false,
    }
}

/// `(g, h)` with `p = g² h` for a polynomial `p`: for each symbol `s` in turn,
/// `c = gcd(p, ∂p/∂s)` holds each repeated factor once, and `c²` is taken out while it
/// divides `h` exactly.
fn square_factor(p: Expr) -> Result<(Expr, Expr), AlgebraError> {
    let mut g = Expr::one();
    let mut h = p;
    for s in h.symbols() {
        let repeated = polynomial_gcd(&h, &h.diff(s)?)?;
        if repeated.symbols().is_empty() {
            continue;
        }
        let (rest, below) = h.checked_div(&repeated.powi(2))?.cancelled_parts()?;
        if below.as_num().is_some() {
            g = &g * &repeated;
            h = rest.checked_div(&below)?;
        }
    }
    Ok((g, h))
}

/// `√e`, exact for a square number, with the square factors of its numeric content taken
/// out otherwise (`√(8x + 12y) = 2√(2x + 3y)`).
pub(super) fn square_root(e: &Expr) -> Result<Expr, AlgebraError> {
    if e.is_zero() {
        return Ok(Expr::zero());
    }
    if let Some(root) = e.as_num().and_then(|q| q.exact_root(2)) {
        return Ok(Expr::num(root));
    }
    let (content, _) = content_and_primitive(e.terms());
    let outside = largest_square_divisor(&content.abs());
    let inside = e.checked_div(&Expr::num(&outside * &outside))?;
    Ok(&Expr::num(outside) * &inside.checked_pow(&Expr::rational(1, 2))?)
}

/// The largest `s` with `s²` dividing the positive rational `q` (numerator and denominator
/// searched by trial division up to 1000).
fn largest_square_divisor(q: &Q) -> Q {
    let part = |n: &Q| -> Q {
        let Some(mut n) = n.to_i64() else {
            return Q::ONE;
        };
        let mut out = 1i64;
        let mut d = 2i64;
        while d <= 1000 && d * d <= n {
            while n % (d * d) == 0 {
                n /= d * d;
                out *= d;
            }
            d += 1;
        }
        Q::int(out)
    };
    let (numerator, denominator) = (part(&q.numer()), part(&q.denom()));
    numerator.checked_div(&denominator).unwrap_or(Q::ONE)
}
