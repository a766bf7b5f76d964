//! Radicals and absolute values simplified by the domains of the symbols, never dropping a
//! sign that cannot be proved (the signs are those of `sign.rs`):
//!
//! - `|u| = u` for `u ≥ 0`, `|u| = -u` for `u ≤ 0`, otherwise `|u|` stays; `|u|ⁿ = uⁿ` for
//!   an even integer `n`;
//! - a root `(c ∏ bᵢ^nᵢ)^(p/q)` (`q > 1`) splits over its factors that are `≥ 0`: a factor
//!   `bⁿ` with an integer `n = k q + r` (`0 ≤ r < q`) leaves `b^(k p)` outside and `bʳ`
//!   inside, where `b ≥ 0` is proved, or `b` is replaced by `-b` (`b ≤ 0`) or `|b|`
//!   (any real `b`) when `n` is even; every other factor stays inside. So `√(a²) = a` for a
//!   positive `a`, `√(x²) = |x|` for a real `x`, `√(4a²b) = 2a√b`, `∛(a³) = a`;
//! - the numeric coefficient `c = N/D` gives out its `q`-th powers found by trial division
//!   by the integers up to `TRIAL_DIVISORS` (`√8 = 2√2`); a negative sign stays inside.
//!
//! The walk rebuilds each node once; inputs larger than `MAX_EXPANDED_NODES` nodes are refused.
//!
//! ```
//! use kinetics::algebra::{Domains, Expr};
//! use kinetics::parse::parse_expression;
//! let domains = Domains::chapter_defaults();
//! let simplified = |text: &str| {
//!     parse_expression("e", text).unwrap().simplify_radicals(&domains).unwrap().to_string()
//! };
//! assert_eq!(simplified("sqrt(a^2)"), "a");
//! assert_eq!(simplified("sqrt(x^2)"), "abs(x)");
//! assert_eq!(simplified("abs(m)"), "m");
//! ```

use super::domain::Domains;
use super::error::{AlgebraError, MAX_EXPANDED_NODES};
use super::expr::{Expr, View};
use super::function::Func;
use super::rational::Q;

/// The numeric coefficient of a root is searched for `q`-th powers of the integers up to
/// this bound (a larger prime factor stays inside the root).
const TRIAL_DIVISORS: i64 = 1000;

impl Expr {
    /// `√(a²) = a`, `√(4a²b) = 2a√b`, `(a²)^(1/2) = a`, `|m| = m`, `((a+b)²)^(1/2) = a + b`
    /// for positive `a`, `b`; `(x²)^(1/2) = |x|` for a real `x`; never drops a sign it cannot
    /// prove (the rules are in the module documentation). An error for an input of more
    /// than [`MAX_EXPANDED_NODES`] nodes.
    pub fn simplify_radicals(&self, domains: &Domains) -> Result<Expr, AlgebraError> {
        if !self.has_at_most_size(MAX_EXPANDED_NODES) {
            return Err(AlgebraError::TooLargeToSimplify(MAX_EXPANDED_NODES));
        }
        Radicals { domains }.simplify(self)
    }
}

struct Radicals<'a> {
    domains: &'a Domains,
}

impl Radicals<'_> {
    fn simplify(&self, e: &Expr) -> Result<Expr, AlgebraError> {
        Ok(match e.view() {
            View::Num(_) | View::Sym(_) => e.clone(),
            View::Add(terms) => Expr::add_all(self.each(terms)?),
            View::Mul(factors) => Expr::mul_all(self.each(factors)?),
            View::Func(Func::Abs, argument) => self.abs(self.simplify(argument)?),
            View::Func(f, argument) => Expr::func(f, self.simplify(argument)?),
            View::Pow(base, exponent) => {
                let base = self.simplify(base)?;
                let exponent = self.simplify(exponent)?;
                match exponent.as_num().and_then(small_fraction) {
                    Some((p, q)) if q > 1 => self.root(&base, p, q)?,
                    Some((n, _)) => power_of_real(&base, n)?,
                    None => base.checked_pow(&exponent)?,
                }
            }
        })
    }

    fn each(&self, operands: &[Expr]) -> Result<Vec<Expr>, AlgebraError> {
        operands.iter().map(|o| self.simplify(o)).collect()
    }

    /// `|u|`: `u` for `u ≥ 0`, `-u` for `u ≤ 0`, else the absolute value.
    fn abs(&self, u: Expr) -> Expr {
        let sign = self.domains.sign(&u);
        if sign.is_nonnegative() {
            u
        } else if sign.is_nonpositive() {
            -u
        } else {
            Func::Abs.apply(u)
        }
    }

    /// `base^(p/q)` for `q > 1`, split as the module documentation says.
    fn root(&self, base: &Expr, p: i64, q: i64) -> Result<Expr, AlgebraError> {
        let (coefficient, factors) = base.coeff_and_factors();
        let (mut outside, mut inside) = (Vec::new(), Vec::new());
        let (root_out, root_in) = numeric_root(&coefficient, q);
        match root_out.checked_pow(p) {
            Some(out) => {
                outside.push(Expr::num(out));
                inside.push(Expr::num(root_in));
            }
            None => inside.push(Expr::num(coefficient.clone())),
        }
        for factor in factors {
            let integer = factor.numeric_exponent().and_then(Q::to_i64);
            let split = integer.and_then(|n| {
                let nonnegative = self.nonnegative_base(factor.base(), n)?;
                let k = n.div_euclid(q).checked_mul(p)?;
                Some((nonnegative, k, n.rem_euclid(q)))
            });
            match split {
                Some((b, k, r)) => {
                    outside.push(power_of_real(&b, k)?);
                    inside.push(power_of_real(&b, r)?);
                }
                None => inside.push(factor.clone()),
            }
        }
        let root = Expr::mul_all(inside).checked_pow(&Expr::rational(p, q))?;
        outside.push(root);
        Ok(Expr::mul_all(outside))
    }

    /// A base `≥ 0` whose `n`-th power is `bⁿ`: `b` itself when `b ≥ 0` is proved; for an
    /// even `n`, `-b` when `b ≤ 0` and `|b|` otherwise; none for an odd power of a `b` not
    /// proved `≥ 0`.
    fn nonnegative_base(&self, b: &Expr, n: i64) -> Option<Expr> {
        let sign = self.domains.sign(b);
        if sign.is_nonnegative() {
            Some(b.clone())
        } else if n % 2 == 0 {
            Some(self.abs(b.clone()))
        } else {
            None
        }
    }
}

/// `bⁿ` for a real `b` and an integer `n`, with `|u|ⁿ = uⁿ` for an even `n`.
fn power_of_real(b: &Expr, n: i64) -> Result<Expr, AlgebraError> {
    match b.view() {
        View::Func(Func::Abs, u) if n % 2 == 0 => u.checked_pow(&Expr::int(n)),
        _ => b.checked_pow(&Expr::int(n)),
    }
}

/// `p/q` of a number whose numerator and denominator fit an `i64`.
fn small_fraction(x: &Q) -> Option<(i64, i64)> {
    Some((x.numer().to_i64()?, x.denom().to_i64()?))
}

/// `c = out^q · in`, with out the product of the `q`-th powers found in `|c|`'s numerator
/// and denominator by trial division (`c`'s sign stays in `in`); `(1, c)` for a number
/// too long for an `i64`.
fn numeric_root(c: &Q, q: i64) -> (Q, Q) {
    let Some((numerator, denominator)) = small_fraction(c) else {
        return (Q::ONE, c.clone());
    };
    let (n_out, n_in) = integer_root(numerator.unsigned_abs(), q);
    let (d_out, d_in) = integer_root(denominator.unsigned_abs(), q);
    let ratio = |n: u64, d: u64| {
        Q::new(i64::try_from(n).ok()?, i64::try_from(d).ok()?).filter(|_| n > 0 && d > 0)
    };
    match (ratio(n_out, d_out), ratio(n_in, d_in)) {
        (Some(out), Some(inside)) if c.is_negative() => (out, -&inside),
        (Some(out), Some(inside)) => (out, inside),
        _ => (Q::ONE, c.clone()),
    }
}

/// `n = out^q · in` with out the product of the `q`-th powers of the divisors up to
/// `TRIAL_DIVISORS` in `n`.
fn integer_root(mut n: u64, q: i64) -> (u64, u64) {
    let Ok(q) = u32::try_from(q) else {
        return (1, n);
    };
    let (mut out, mut inside) = (1u64, 1u64);
    for d in 2..=TRIAL_DIVISORS.unsigned_abs() {
        match d.checked_pow(q) {
            Some(power) if power <= n => {}
            _ => break,
        }
        let mut multiplicity = 0;
        while n.is_multiple_of(d) {
            n /= d;
            multiplicity += 1;
        }
        out *= d.pow(multiplicity / q);
        inside *= d.pow(multiplicity % q);
    }
    (out, inside * n)
}
