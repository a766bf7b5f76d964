//! An unknown angle u that enters only through sin u, cos u and tan u (double angles
//! multiplied out first), made polynomial in its cosine c = cos u with s = sin u kept apart:
//! with s² = 1 − c², each equation's numerator is
//!
//! ```text
//! P₀(c) + s P₁(c) = 0
//! ```
//!
//! so the angle comes from a polynomial in c alone: P₀ when P₁ = 0, P₁ (with s = 0, that
//! is c = ±1) when P₀ = 0, else P₀² − (1 − c²) P₁² (whose roots the caller checks in the
//! equations themselves). A root c₀ in [−1, 1] is u = ±arccos c₀, s = ±√(1 − c₀²).

use super::super::error::AlgebraError;
use super::super::expr::{Expr, View};
use super::super::function::Func;
use super::super::rational::Q;
use super::super::square_rewrite::SquareRule;
use super::super::symbol::Symbol;

/// `e`'s numerator as `(P₀(c), P₁(c))` with sin u = `s`, cos u = `c` (see the module
/// documentation); none when u appears other than as the whole argument of sin, cos, tan.
pub fn in_sine_and_cosine(
    e: &Expr,
    u: Symbol,
    s: Symbol,
    c: Symbol,
) -> Result<Option<(Expr, Expr)>, AlgebraError> {
    let (sine, cosine) = (Expr::sym(s), Expr::sym(c));
    let tangent = sine.checked_div(&cosine)?;
    let single = e.double_angles_multiplied_out()?;
    let Some(replaced) = replaced(&single, u, &|f| match f {
        Func::Sin => Some(sine.clone()),
        Func::Cos => Some(cosine.clone()),
        Func::Tan => Some(tangent.clone()),
        Func::Abs | Func::Acos | Func::Atan => None,
    })?
    else {
        return Ok(None);
    };
    let numerator = replaced.together_parts()?.0.expand()?;
    let square = SquareRule {
        base: &sine,
        p: Q::int(1),
        q: Q::int(-1),
        g: cosine.powi(2),
    };
    let reduced = square.rewrite(&numerator)?.expand()?;
    let (mut even, mut odd) = (Vec::new(), Vec::new());
    for group in reduced.collect(&[s])? {
        match group.monomial.is_one() {
            true => even.push(group.coefficient),
            false if group.monomial == sine => odd.push(group.coefficient),
            false => return Ok(None),
        }
    }
    Ok(Some((Expr::add_all(even), Expr::add_all(odd))))
}

/// An equation in u alone and the unknowns eliminated to reach it, each with its value.
pub type AngleAlone = (Expr, Vec<(Symbol, Expr)>);

/// An equation in the angle u alone, from `equations = 0` in u and the unknowns `others`:
/// one of them, or one left after eliminating unknowns that enter an equation linearly,
///
/// ```text
/// a w + b = 0,  a ≠ 0 free of the unknowns left   ⇒   w = −b/a
/// ```
///
/// substituted into the rest, each rest's numerator kept (a times the equation, so a root
/// where a vanishes may be spurious: the caller checks each root in the equations
/// themselves). Those whose coefficient holds no u first. Returns that equation and the
/// unknowns eliminated with their values, in order; none when no such chain reaches u alone.
pub fn angle_alone(
    equations: &[Expr],
    u: Symbol,
    others: &[Symbol],
) -> Result<Option<AngleAlone>, AlgebraError> {
    let mut remaining: Vec<Expr> = equations.to_vec();
    let mut open: Vec<Symbol> = others.to_vec();
    let mut eliminated = Vec::new();
    loop {
        let holds_open = |e: &Expr, open: &[Symbol]| open.iter().any(|&w| e.contains(w));
        if let Some(alone) = remaining
            .iter()
            .find(|e| e.contains(u) && !holds_open(e, &open))
        {
            return Ok(Some((alone.clone(), eliminated)));
        }
        let mut linear: Vec<(usize, Symbol, Expr, Expr)> = Vec::new();
        for (k, e) in remaining.iter().enumerate() {
            for &w in open.iter().filter(|&&w| e.contains(w)) {
                let (mut a, mut b) = (Vec::new(), Vec::new());
                let mut is_linear = true;
                for group in e.collect(&[w])? {
                    match (group.monomial.is_one(), group.monomial == Expr::sym(w)) {
                        (true, _) => b.push(group.coefficient),
                        (false, true) => a.push(group.coefficient),
                        (false, false) => is_linear = false,
                    }
                }
                let (a, b) = (Expr::add_all(a), Expr::add_all(b));
                if is_linear && !a.is_zero() && !holds_open(&a, &open) && !holds_open(&b, &[w]) {
                    linear.push((k, w, a, b));
                }
            }
        }
        linear.sort_by_key(|(_, _, a, _)| a.contains(u));
        let Some((k, w, a, b)) = linear.into_iter().next() else {
            return Ok(None);
        };
        let value = (-b).checked_div(&a)?;
        let substituted = |e: &Expr| -> Result<Expr, AlgebraError> {
            let e = e.subs(&|s| (s == w).then(|| value.clone()))?;
            e.together_parts()?.0.expand()
        };
        remaining = remaining
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != k)
            .map(|(_, e)| substituted(e))
            .collect::<Result<Vec<_>, _>>()?;
        remaining.retain(|e| !e.is_zero());
        open.retain(|&o| o != w);
        eliminated.push((w, value));
    }
}

/// Whether u enters `e` only as the argument of sin, cos (u + kπ/2 or 2u) and tan (u + kπ/2): a read of
/// `e` that builds nothing, so that a solver can ask it of every unknown of every equation
/// before it rewrites one ([`in_sine_and_cosine`] may still decline, past its bounds).
pub fn enters_only_through_trigonometry(e: &Expr, u: Symbol) -> bool {
    if !e.contains(u) {
        return true;
    }
    let angle = Expr::sym(u);
    match e.view() {
        View::Num(_) | View::Sym(_) => false,
        View::Add(parts) | View::Mul(parts) => {
            parts.iter().all(|p| enters_only_through_trigonometry(p, u))
        }
        View::Pow(b, exponent) => !exponent.contains(u) && enters_only_through_trigonometry(b, u),
        View::Func(Func::Sin | Func::Cos, a) => {
            quarter_turns(a, u).is_some() || *a == Expr::int(2) * angle
        }
        View::Func(Func::Tan, a) => quarter_turns(a, u).is_some(),
        View::Func(..) => false,
    }
}

/// `e` with sin u, cos u, tan u given their values `sine`, `cosine` (double angles
/// multiplied out first), expanded; none when u appears elsewhere.
pub fn at_angle(
    e: &Expr,
    u: Symbol,
    sine: &Expr,
    cosine: &Expr,
) -> Result<Option<Expr>, AlgebraError> {
    let tangent = sine.checked_div(cosine).ok();
    let single = e.double_angles_multiplied_out()?;
    replaced(&single, u, &|f| match f {
        Func::Sin => Some(sine.clone()),
        Func::Cos => Some(cosine.clone()),
        Func::Tan => tangent.clone(),
        Func::Abs | Func::Acos | Func::Atan => None,
    })?
    .map(|x| x.expand())
    .transpose()
}

/// `e` with each `f(u)` replaced by `by(f)`; none when u appears other than as the whole
/// argument of a function `by` replaces.
fn replaced(
    e: &Expr,
    u: Symbol,
    by: &dyn Fn(Func) -> Option<Expr>,
) -> Result<Option<Expr>, AlgebraError> {
    if !e.contains(u) {
        return Ok(Some(e.clone()));
    }
    let each = |parts: &[Expr]| -> Result<Option<Vec<Expr>>, AlgebraError> {
        parts.iter().map(|p| replaced(p, u, by)).collect()
    };
    Ok(match e.view() {
        View::Num(_) | View::Sym(_) => None,
        View::Add(terms) => each(terms)?.map(Expr::add_all),
        View::Mul(factors) => each(factors)?.map(Expr::mul_all),
        View::Pow(b, exponent) if !exponent.contains(u) => match replaced(b, u, by)? {
            Some(b) => Some(b.checked_pow(exponent)?),
            None => None,
        },
        View::Pow(..) => None,
        View::Func(f, a) => match quarter_turns(a, u) {
            Some(k) => shifted(f, k, by)?,
            None => None,
        },
    })
}

/// k when `a` is u + k·π/2 (k whole), as `sin(beta - 90 deg)` is written; read from the
/// canonical sum, nothing built (asked of every function of every equation).
fn quarter_turns(a: &Expr, u: Symbol) -> Option<i64> {
    let angle = Expr::sym(u);
    if *a == angle {
        return Some(0);
    }
    let View::Add(terms) = a.view() else {
        return None;
    };
    let [x, y] = terms else { return None };
    let shift = match (*x == angle, *y == angle) {
        (true, false) => y,
        (false, true) => x,
        _ => return None,
    };
    let halves = shift.as_multiple_of_pi()? * &Q::int(2);
    halves.is_integer().then(|| halves.to_i64()).flatten()
}

/// `f(u + k·π/2)` from sin u, cos u and tan u (`by`): sin(u + π/2) = cos u,
/// cos(u + π/2) = −sin u, tan(u + π/2) = −1/tan u, each a quarter turn further on.
fn shifted(
    f: Func,
    k: i64,
    by: &dyn Fn(Func) -> Option<Expr>,
) -> Result<Option<Expr>, AlgebraError> {
    let quarter = k.rem_euclid(4);
    let signed = |g: Func, negative: bool| by(g).map(|x| if negative { -x } else { x });
    Ok(match f {
        Func::Sin => match quarter {
            0 | 2 => signed(Func::Sin, quarter == 2),
            _ => signed(Func::Cos, quarter == 3),
        },
        Func::Cos => match quarter {
            0 | 2 => signed(Func::Cos, quarter == 2),
            _ => signed(Func::Sin, quarter == 1),
        },
        Func::Tan => match quarter % 2 {
            0 => by(Func::Tan),
            _ => match by(Func::Tan) {
                Some(t) => Some(-Expr::one().checked_div(&t)?),
                None => None,
            },
        },
        Func::Abs | Func::Acos | Func::Atan => by(f),
    })
}
