//! A second opinion by evaluation: both sides of a claim at random points in double-double.
//!
//! At each point `x`, `l = lhs(x)` and `r = rhs(x)` are computed to about 32 digits, each
//! with a bound on its rounding error (`numeric/rounding_error.rs`); the sides agree there when
//! `|l − r| ≤ 10⁻²⁵ · max(|l|, |r|)` (or both are exactly 0), and differ clearly when
//! `|l − r| ≥ 10⁻¹² · max(|l|, |r|)` and `|l − r|` is beyond what rounding may cause there
//! (a cancellation in a true identity, `(a − b)⁹` expanded near `a = b`, is no difference).
//! The values drawn have at most 22 significant bits (multiples of 2⁻²⁰ no larger than 3),
//! so the products of a polynomial of modest degree are exact in double-double and a
//! near-cancellation that `f64` would lose (`(10⁸ + x)² − 10¹⁶ − 2·10⁸ x = x²`) is decided
//! right. The points are deterministic in the seed (splitmix64), so a verdict can be
//! reproduced.

use crate::algebra::{Domain, Domains, Expr, Symbol};
use crate::numeric::rounding_error::bounded;
use crate::numeric::scalar::double_double::DoubleDouble;
use crate::numeric::splitmix::SplitMix64;
use num_traits::{Float, Zero};

/// How many points must agree for [`Opinion::Zero`].
pub const POINTS: usize = 6;

/// How many points are drawn at most, those where a side has no finite value included.
const MAX_DRAWS: usize = 4 * POINTS;

/// Agreement to 25 digits: rounding in double-double, not a difference.
const AGREES: f64 = 1e-25;

/// A relative difference at least this large is a difference, not rounding.
const DIFFERS: f64 = 1e-12;

/// How far beyond the first-order bounds on the rounding errors a clear difference must be.
const SAFETY: f64 = 64.0;

/// The grid the values are drawn on: multiples of 2⁻²⁰.
const GRID: f64 = 1.0 / (1u64 << 20) as f64;

/// What evaluation says of `lhs − rhs`.
#[derive(Debug, Clone, PartialEq)]
pub enum Opinion {
    /// Every point agrees to 25 digits: |l − r| ≤ 1e-25 · max(|l|, |r|) (or both exactly 0).
    Zero,
    /// At some point the sides differ clearly (relative difference ≥ 1e-12, and beyond
    /// the bound on the rounding errors there): the point.
    Nonzero {
        relative: f64,
        point: Vec<(Symbol, f64)>,
    },
    /// Neither: too few points could be evaluated, or a difference between the two bounds,
    /// or one that rounding may explain.
    Unsure(String),
}

/// lhs and rhs (scalars, no unit vectors) evaluated in double-double at [`POINTS`] random
/// points, deterministic in `seed`. Symbols `domains` proves positive draw from [0.5, 3],
/// others from ±[0.2, 3]; `pi` is the constant. A point where either side does not
/// evaluate to a finite value (a division by zero, sqrt of a negative) is drawn again, up
/// to [`MAX_DRAWS`] draws in all. Each point costs one evaluation of each side, with the
/// bound on its rounding error.
pub fn second_opinion(lhs: &Expr, rhs: &Expr, domains: &Domains, seed: u64) -> Opinion {
    let symbols = symbols_of(lhs, rhs);
    let positive: Vec<bool> = symbols
        .iter()
        .map(|&s| domains.domain(s) == Domain::Positive)
        .collect();
    let mut random = SplitMix64(seed);
    let mut values = vec![0.0; symbols.len()];
    let (mut evaluated, mut unclear) = (0, None);
    for _ in 0..MAX_DRAWS {
        if evaluated == POINTS {
            break;
        }
        for (v, &positive) in values.iter_mut().zip(&positive) {
            *v = value(&mut random, positive);
        }
        let value = |s: Symbol| {
            let at = symbols.iter().position(|&t| t == s)?;
            Some(DoubleDouble::from_f64(values[at]))
        };
        let Some(difference) = Difference::at(lhs, rhs, &value) else {
            continue;
        };
        evaluated += 1;
        let unexplained = match difference.relative {
            r if r <= AGREES => continue,
            r if r < DIFFERS => Unexplained::Between(r),
            r if difference.beyond_rounding => {
                let point = symbols.iter().copied().zip(values).collect();
                return Opinion::Nonzero { relative: r, point };
            }
            r => Unexplained::Cancellation(r),
        };
        if unclear
            .as_ref()
            .is_none_or(|u: &Unexplained| u.relative() < unexplained.relative())
        {
            unclear = Some(unexplained);
        }
    }
    match unclear {
        Some(Unexplained::Between(relative)) => Opinion::Unsure(format!(
            "the sides differ by {relative:.1e} of their size at a point: more than the \
             rounding of double-double ({AGREES:.0e}), less than a clear difference \
             ({DIFFERS:.0e})"
        )),
        Some(Unexplained::Cancellation(relative)) => Opinion::Unsure(format!(
            "the sides differ by {relative:.1e} of their size at a point, no more than the \
             rounding error a cancellation in evaluating them may cause"
        )),
        None if evaluated < POINTS => Opinion::Unsure(format!(
            "only {evaluated} of {MAX_DRAWS} random points gave both sides a finite value \
             ({POINTS} needed)"
        )),
        None => Opinion::Zero,
    }
}

/// A relative difference at a point that is neither agreement nor a clear difference.
enum Unexplained {
    /// Between [`AGREES`] and [`DIFFERS`].
    Between(f64),
    /// At least [`DIFFERS`], but within what rounding may cause (`rounding_error`).
    Cancellation(f64),
}

impl Unexplained {
    fn relative(&self) -> f64 {
        match self {
            Unexplained::Between(r) | Unexplained::Cancellation(r) => *r,
        }
    }
}

/// The symbols of both sides, each once, `pi` left out (it is the constant).
fn symbols_of(lhs: &Expr, rhs: &Expr) -> Vec<Symbol> {
    let mut symbols = lhs.symbols();
    symbols.extend(rhs.symbols());
    symbols.sort();
    symbols.dedup();
    symbols.retain(|s| !s.is_pi());
    symbols
}

/// The two sides compared at a point.
struct Difference {
    /// `|l − r| / max(|l|, |r|)` (0 when both are 0).
    relative: f64,
    /// Whether `|l − r|` is beyond [`SAFETY`] times the bounds on both sides' rounding.
    beyond_rounding: bool,
}

impl Difference {
    /// The sides at the point, None when a side has no finite value there.
    fn at(
        lhs: &Expr,
        rhs: &Expr,
        value: &dyn Fn(Symbol) -> Option<DoubleDouble>,
    ) -> Option<Difference> {
        let (l, r) = (bounded(lhs, value)?, bounded(rhs, value)?);
        let difference = (l.value - r.value).abs();
        let scale = l.value.abs().max(r.value.abs());
        Some(Difference {
            relative: if scale.is_zero() {
                0.0
            } else {
                (difference / scale).to_f64()
            },
            beyond_rounding: difference.to_f64() > SAFETY * (l.error + r.error),
        })
    }
}

/// A multiple of [`GRID`] uniform in [0.5, 3] when `positive`, else in ±[0.2, 3].
fn value(random: &mut SplitMix64, positive: bool) -> f64 {
    let bits = random.next_u64();
    let low: f64 = if positive { 0.5 } else { 0.2 };
    let (low, high) = ((low / GRID).ceil() as u64, (3.0 / GRID) as u64);
    let magnitude = (low + (bits >> 1) % (high - low + 1)) as f64 * GRID;
    if positive || bits & 1 == 0 {
        magnitude
    } else {
        -magnitude
    }
}
