//! Random expression trees for the property tests. A tree knows three things about itself,
//! each found without the algebra: its value in plain `f64` arithmetic (the reference), the
//! text a person would type for it, and which features it uses (so that a test can check
//! what the generator covers).
//!
//! A tree holds
//! - numbers: integers -4..=4 and rationals p/q with q in {2, 3, 4, 10}; tenths are typed
//!   as decimals (`0.7`), which the parser reads as exact rationals;
//! - symbols, named by the caller (index i names `names[i]` and takes the value `x[i]`);
//! - `+ - *`, negation, and `/` by any subtree (a sum, a product, a function, ...);
//! - integer powers -2..=3 and the rational powers 1/2 (typed `sqrt(...)`), -1/2, 3/2, 1/3;
//! - `sin cos tan abs`.
//!
//! The reference value is `None` where the expression is not a real number or is near a
//! pole: a divisor, or the base of a negative power, or the cosine under a tangent, smaller
//! than [`NEAR_POLE`] in magnitude; a root of a negative number, or of one smaller than
//! [`NEAR_POLE`] (where the root's infinite slope would amplify rounding in the reference
//! without bound); a sine, cosine or tangent of an argument beyond [`LARGE_ARGUMENT`] in
//! magnitude (which multiplies the argument's rounding by the argument: `sin(b^-18)` for a
//! small `b`, evaluated as `(b^-12)^(3/2)` by the reference and as `b^-18` by the algebra,
//! differs in the seventh digit). Property tests skip those points and bound how many they
//! skip.

use kinetics::algebra::{Expr, Func, Symbol};
use proptest::prelude::*;

/// Below this magnitude a divisor (or the base of a negative power, or the cosine under a
/// tangent) counts as a pole: the reference value there is not trusted.
pub const NEAR_POLE: f64 = 1e-3;

/// Beyond this magnitude the argument of a sine, cosine or tangent is not trusted.
pub const LARGE_ARGUMENT: f64 = 1e3;

/// A random expression, kept as the operations that made it.
#[derive(Debug, Clone)]
pub enum Tree {
    /// The rational `p/q`, `q > 0`.
    Num(i64, i64),
    /// The symbol `names[i]`.
    Var(usize),
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    Div(Box<Tree>, Box<Tree>),
    /// The subtree to the power `p/q`, `q > 0`.
    Pow(Box<Tree>, i64, i64),
    Neg(Box<Tree>),
    Func(Func, Box<Tree>),
}

/// Trees over `vars` symbols, of depth at most five and about 40 nodes at most.
pub fn tree(vars: usize) -> impl Strategy<Value = Tree> {
    let leaf = prop_oneof![
        3 => (-4i64..=4).prop_map(|n| Tree::Num(n, 1)),
        2 => (
            prop_oneof![-9i64..=-1, 1i64..=9],
            prop::sample::select(vec![2i64, 3, 4, 10]),
        )
            .prop_map(|(p, q)| Tree::Num(p, q)),
        6 => (0..vars).prop_map(Tree::Var),
    ];
    leaf.prop_recursive(5, 40, 2, |inner| {
        let pair = (inner.clone(), inner.clone());
        prop_oneof![
            pair.clone()
                .prop_map(|(a, b)| Tree::Add(Box::new(a), Box::new(b))),
            pair.clone()
                .prop_map(|(a, b)| Tree::Sub(Box::new(a), Box::new(b))),
            pair.clone()
                .prop_map(|(a, b)| Tree::Mul(Box::new(a), Box::new(b))),
            pair.prop_map(|(a, b)| Tree::Div(Box::new(a), Box::new(b))),
            (
                inner.clone(),
                prop::sample::select(vec![-2i64, -1, 0, 2, 3])
            )
                .prop_map(|(a, n)| Tree::Pow(Box::new(a), n, 1)),
            (
                root_base(inner.clone()),
                prop::sample::select(vec![(1i64, 2i64), (1, 2), (-1, 2), (3, 2), (1, 3)]),
            )
                .prop_map(|(a, (p, q))| Tree::Pow(Box::new(a), p, q)),
            inner.clone().prop_map(|a| Tree::Neg(Box::new(a))),
            (
                prop::sample::select(vec![Func::Sin, Func::Cos, Func::Tan, Func::Abs, Func::Atan]),
                inner,
            )
                .prop_map(|(f, a)| Tree::Func(f, Box::new(a))),
        ]
    })
}

/// The base of a root: any subtree, or its absolute value, or its square; so that most
/// roots are of numbers that cannot be negative and most points stay in the real domain,
/// while `sqrt(|u|)` and `sqrt(u^2)` (which is `|u|`, not `u`) are tried often.
fn root_base(inner: BoxedStrategy<Tree>) -> impl Strategy<Value = Tree> {
    prop_oneof![
        inner.clone(),
        inner
            .clone()
            .prop_map(|a| Tree::Func(Func::Abs, Box::new(a))),
        inner.prop_map(|a| Tree::Pow(Box::new(a), 2, 1)),
    ]
}

/// The configuration of a property over random expressions: `cases` cases (or as many as
/// `PROPTEST_CASES` says), and a failure when more than a quarter as many are skipped, so
/// that at least four of every five cases drawn are checked.
pub fn config(cases: u32) -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(cases);
    ProptestConfig {
        cases,
        max_global_rejects: cases / 4,
        ..ProptestConfig::default()
    }
}

/// Points of `n` coordinates, each in `[-1.7, -0.3]` or `[0.3, 1.7]`: away from zero, so
/// that a symbol as a divisor is safe.
pub fn point(n: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(prop_oneof![0.3f64..1.7, -1.7f64..-0.3], n)
}

impl Tree {
    /// The expression, built with the algebra's operators (`+ - * /`, `checked_pow`,
    /// `Func::checked_apply`); none when it divides by an expression that is exactly zero
    /// or takes the tangent at its pole (`tan(6 atan(1))`, 3π/2), as the parser refuses.
    pub fn build(&self, names: &[&str]) -> Option<Expr> {
        Some(match self {
            Tree::Num(p, q) => Expr::rational(*p, *q),
            Tree::Var(i) => Expr::symbol(names[*i]),
            Tree::Add(a, b) => a.build(names)? + b.build(names)?,
            Tree::Sub(a, b) => a.build(names)? - b.build(names)?,
            Tree::Mul(a, b) => a.build(names)? * b.build(names)?,
            Tree::Div(a, b) => a.build(names)?.checked_div(&b.build(names)?).ok()?,
            Tree::Pow(a, p, q) => a.build(names)?.checked_pow(&Expr::rational(*p, *q)).ok()?,
            Tree::Neg(a) => -a.build(names)?,
            Tree::Func(f, a) => f.checked_apply(a.build(names)?).ok()?,
        })
    }

    /// The value where symbol `i` has the value `x[i]`, in `f64` without the algebra; none
    /// where it is not a finite real number or is near a pole (see the module
    /// documentation).
    pub fn value(&self, x: &[f64]) -> Option<f64> {
        let v = match self {
            Tree::Num(p, q) => *p as f64 / *q as f64,
            Tree::Var(i) => x[*i],
            Tree::Add(a, b) => a.value(x)? + b.value(x)?,
            Tree::Sub(a, b) => a.value(x)? - b.value(x)?,
            Tree::Mul(a, b) => a.value(x)? * b.value(x)?,
            Tree::Div(a, b) => {
                let divisor = b.value(x)?;
                if divisor.abs() < NEAR_POLE {
                    return None;
                }
                a.value(x)? / divisor
            }
            Tree::Pow(a, p, q) => {
                let base = a.value(x)?;
                if *p < 0 && base.abs() < NEAR_POLE {
                    return None;
                }
                match q {
                    1 => base.powi(*p as i32),
                    // A root of a negative number is not real; near zero its slope is
                    // infinite, so rounding in the base would be amplified without bound.
                    _ if base < NEAR_POLE => return None,
                    2 => base.sqrt().powi(*p as i32),
                    _ => base.powf(*p as f64 / *q as f64),
                }
            }
            Tree::Neg(a) => -a.value(x)?,
            Tree::Func(f, a) => {
                let u = a.value(x)?;
                match f {
                    Func::Sin | Func::Cos | Func::Tan if u.abs() > LARGE_ARGUMENT => return None,
                    Func::Sin => u.sin(),
                    Func::Cos => u.cos(),
                    Func::Tan if u.cos().abs() < NEAR_POLE => return None,
                    Func::Tan => u.tan(),
                    Func::Abs => u.abs(),
                    // Its slope is infinite at ±1.
                    Func::Acos if u.abs() > 1.0 - NEAR_POLE => return None,
                    Func::Acos => u.acos(),
                    Func::Atan => u.atan(),
                }
            }
        };
        v.is_finite().then_some(v)
    }

    /// The expression as a person would type it: each operation in parentheses, products
    /// by juxtaposition (`(a b)`), tenths as decimals (`0.7`), other fractions as `(p/q)`,
    /// the power 1/2 as `sqrt(...)`, others as `(...)^(p/q)`.
    pub fn input(&self, names: &[&str]) -> String {
        match self {
            Tree::Num(p, 1) if *p < 0 => format!("({p})"),
            Tree::Num(p, 1) => format!("{p}"),
            Tree::Num(p, 10) => {
                let sign = if *p < 0 { "-" } else { "" };
                let m = p.unsigned_abs();
                let decimal = format!("{sign}{}.{}", m / 10, m % 10);
                if *p < 0 {
                    format!("({decimal})")
                } else {
                    decimal
                }
            }
            Tree::Num(p, q) => format!("({p}/{q})"),
            Tree::Var(i) => names[*i].to_string(),
            Tree::Add(a, b) => format!("({} + {})", a.input(names), b.input(names)),
            Tree::Sub(a, b) => format!("({} - {})", a.input(names), b.input(names)),
            Tree::Mul(a, b) => format!("({} {})", a.input(names), b.input(names)),
            Tree::Div(a, b) => format!("({}/{})", a.input(names), b.input(names)),
            Tree::Pow(a, 1, 2) => format!("sqrt({})", a.input(names)),
            Tree::Pow(a, p, 1) => format!("({})^({p})", a.input(names)),
            Tree::Pow(a, p, q) => format!("({})^({p}/{q})", a.input(names)),
            Tree::Neg(a) => format!("(-{})", a.input(names)),
            Tree::Func(f, a) => format!("{}({})", f.name(), a.input(names)),
        }
    }

    /// Whether, at `x`, the argument of an `abs` or the base of a rational power is within
    /// [`NEAR_POLE`] of zero: where the value has a kink or an infinite slope, and the
    /// derivative no value (`d|u| = u/|u| du`, `d√u = du/(2√u)`).
    pub fn near_kink(&self, x: &[f64]) -> bool {
        self.any(&|t| match t {
            Tree::Func(Func::Abs, a) | Tree::Pow(a, _, 2..) => {
                a.value(x).is_some_and(|u| u.abs() < NEAR_POLE)
            }
            _ => false,
        })
    }

    /// Whether this tree or a subtree satisfies `holds`.
    pub fn any(&self, holds: &dyn Fn(&Tree) -> bool) -> bool {
        holds(self)
            || match self {
                Tree::Num(..) | Tree::Var(_) => false,
                Tree::Add(a, b) | Tree::Sub(a, b) | Tree::Mul(a, b) | Tree::Div(a, b) => {
                    a.any(holds) || b.any(holds)
                }
                Tree::Pow(a, ..) | Tree::Neg(a) | Tree::Func(_, a) => a.any(holds),
            }
    }
}

/// The value of `names[i]` is `x[i]`; other symbols have none.
pub fn values<'a>(names: &'a [&str], x: &'a [f64]) -> impl Fn(Symbol) -> Option<f64> + 'a {
    move |s: Symbol| names.iter().position(|n| Symbol::new(n) == s).map(|i| x[i])
}

/// Whether the algebra's value of `e` at a point agrees with the reference `expected`.
/// The tolerance is relative to the sum of the magnitudes of `e`'s terms there, so that a
/// correct expansion whose large terms cancel (the rounding of each term is relative to the
/// term) is not taken for a wrong one. Failures name the values.
pub fn agrees(
    e: &Expr,
    expected: f64,
    value: &dyn Fn(Symbol) -> Option<f64>,
) -> Result<(), String> {
    let got = e
        .eval(value)
        .map_err(|err| format!("no value where the reference is {expected}: {err}"))?;
    let magnitude: f64 = e
        .terms()
        .iter()
        .map(|t| t.eval(value).map_or(f64::INFINITY, f64::abs))
        .sum();
    let tolerance = 1e-9 * (1.0 + expected.abs() + magnitude);
    if (got - expected).abs() <= tolerance {
        Ok(())
    } else {
        Err(format!(
            "value {got}, reference {expected} (tolerance {tolerance:e})"
        ))
    }
}
