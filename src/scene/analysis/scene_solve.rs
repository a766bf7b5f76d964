//! The scene's unknowns solved by [`solve_system`] with what the scene knows of signs: an
//! expression's sign is proved from the symbols' domains, else told by the givens' exact
//! values (in double-double, a sign only beyond the bound on its rounding); an unknown in kg, m or kg·m² must be positive. A linear system is one solution;
//! an unknown that enters polynomially is solved when one polynomial in one unknown remains,
//! its roots that the conditions rule out dropped. Several real roots are several
//! solutions (a top's slow and fast precession), each shown as a solution of its own.

use super::super::model::{EulerAnglesStatement, Scene};
use super::super::units::Dimension;
use crate::algebra::polynomial_solve::unknown_angle::{
    angle_alone, at_angle, enters_only_through_trigonometry, in_sine_and_cosine,
};
use crate::algebra::polynomial_solve::{
    solve_system, Condition, DroppedRoot, Solutions, SolveContext, SolveError,
};
use crate::algebra::{Expr, Func, Symbol};
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
    match angle_unknown(equations, wanted) {
        Some(u) => solve_for_angle(scene, equations, wanted, u, &context),
        None => solve_system(equations, wanted, &context),
    }
}

/// The first unknown that enters only through sin, cos and tan of itself (and does enter):
/// decided by reading the equations, nothing rewritten (asked of every scene's unknowns).
fn angle_unknown(equations: &[Expr], wanted: &[Symbol]) -> Option<Symbol> {
    wanted.iter().copied().find(|&u| {
        equations.iter().any(|e| e.contains(u))
            && equations
                .iter()
                .all(|e| enters_only_through_trigonometry(e, u))
    })
}

/// The sine and cosine of the angle `u` as unknowns of their own: `s_theta`, `c_theta`.
fn sine_and_cosine(u: Symbol) -> (Symbol, Symbol) {
    (
        Symbol::new(&format!("s_{}", u.name())),
        Symbol::new(&format!("c_{}", u.name())),
    )
}

/// What the symbols of an angle's equation in its sine and cosine stand for, when
/// `polynomial_in` is such a cosine (`c_theta`): `c_theta = cos(theta)`,
/// `s_theta = sin(theta)`, for the page.
pub(super) fn sine_and_cosine_of(
    scene: &Scene,
    polynomial_in: Symbol,
) -> Option<[(Symbol, Expr); 2]> {
    let angle = scene
        .unknowns
        .iter()
        .map(|u| u.0)
        .find(|&u| sine_and_cosine(u).1 == polynomial_in)?;
    let (s, c) = sine_and_cosine(angle);
    let of = |f: Func| f.apply(Expr::sym(angle));
    Some([(c, of(Func::Cos)), (s, of(Func::Sin))])
}

/// The equations solved with the angle `u` through its sine and cosine (`unknown_angle.rs`):
/// an equation in u alone (one of them, or one left after eliminating the unknowns that
/// enter linearly) is `P₀(c) + s P₁(c) = 0`. When it is `A s + B c = 0` (A, B free of c), u
/// comes from its tangent, tan u = −B/A: u = arctan(−B/A) and arctan(−B/A) + π. Else a
/// polynomial in c = cos u gives each real root in [−1, 1] as u = arccos c (and −arccos c).
/// The Eulerian angle θ is in [0, π] (its sine ≥ 0), and ruled out at 0 or π, where φ and ψ
/// are not told apart. At each angle the equations are solved for the other unknowns, a root
/// they contradict ruled out.
fn solve_for_angle(
    scene: &Scene,
    equations: &[Expr],
    wanted: &[Symbol],
    u: Symbol,
    context: &SolveContext,
) -> Result<Solutions, SolveError> {
    let (s, c) = sine_and_cosine(u);
    let others: Vec<Symbol> = wanted.iter().copied().filter(|&w| w != u).collect();
    let Some(alone) = angle_alone(equations, u, &others)? else {
        return solve_system(equations, wanted, context);
    };
    let Some((even, odd)) = in_sine_and_cosine(&alone, u, s, c)? else {
        return solve_system(equations, wanted, context);
    };
    let nutation = scene.euler_angles.is_some() && u == EulerAnglesStatement::angles().nutation;
    let (candidates, ruled_out, polynomial) = match tangent(&even, &odd, c)? {
        Some(t) => from_tangent(u, t, nutation, context)?,
        None => from_cosine(u, (s, c), even, odd, nutation, context)?,
    };
    let mut solutions = Solutions {
        branches: Vec::new(),
        dropped: ruled_out,
        free: Vec::new(),
        polynomial: Some(polynomial),
    };
    for Candidate {
        sine,
        cosine,
        angle,
        by_values,
    } in candidates
    {
        if nutation && sine.is_zero() {
            solutions.dropped.push(vertical(u, angle));
            continue;
        }
        let at: Option<Vec<Expr>> = equations
            .iter()
            .map(|e| at_angle(e, u, &sine, &cosine))
            .collect::<Result<_, _>>()?;
        let with_values = |e: Expr| match by_values {
            true => e.subs(&|s| scene.exact_given(s))?.expand(),
            false => Ok(e),
        };
        let rest: Vec<Expr> = at
            .unwrap_or_default()
            .into_iter()
            .map(with_values)
            .collect::<Result<Vec<_>, _>>()?
            .into_iter()
            .filter(|e| !e.is_zero())
            .collect();
        let solved = match rest.is_empty() {
            true => Ok(Vec::new()),
            false => solve_system(&rest, &others, context)
                .map(|s| s.branches.into_iter().next().unwrap_or_default()),
        };
        match solved {
            Ok(mut branch) => {
                branch.insert(0, (u, angle));
                solutions.branches.push(branch);
            }
            Err(SolveError::Inconsistent { .. }) => solutions.dropped.push(dropped(
                u,
                angle,
                "the other equations do not hold at this angle",
                "the other equations do not hold at this angle",
            )),
            Err(e) => return Err(e),
        }
    }
    Ok(solutions)
}

/// An angle to try: its sine, its cosine and itself; `by_values` when the givens' values
/// decided it (the other unknowns are then solved with those values put in).
struct Candidate {
    sine: Expr,
    cosine: Expr,
    angle: Expr,
    by_values: bool,
}

/// The angles to try, the roots already ruled out, and the equation shown (in the symbol it
/// is solved for).
type Tried = (Vec<Candidate>, Vec<DroppedRoot>, (Symbol, Expr));

/// `−B/A` when `P₀ + s P₁` is `A s + B c` with A ≠ 0 and neither holding c.
fn tangent(even: &Expr, odd: &Expr, c: Symbol) -> Result<Option<Expr>, SolveError> {
    if odd.is_zero() || odd.contains(c) {
        return Ok(None);
    }
    let groups = even.collect(&[c])?;
    let b = match groups.as_slice() {
        [] => Expr::zero(),
        [only] if only.monomial == Expr::sym(c) => only.coefficient.clone(),
        _ => return Ok(None),
    };
    Ok(Some((-b).checked_div(odd)?.cancel()?))
}

/// tan u = t = n/d: u = arctan t (t's sines over cosines as tangents), where
/// cos u = d/√(n² + d²) and sin u = n/√(n² + d²) (d > 0; else d = 1), and arctan t + π,
/// where both change sign. With the givens' values d = 0 is u = ±π/2. The Eulerian θ, in
/// [0, π], is the one whose sine n is positive; n = 0 is its vertical axis, ruled out.
fn from_tangent(
    u: Symbol,
    t: Expr,
    nutation: bool,
    context: &SolveContext,
) -> Result<Tried, SolveError> {
    // As the textbook writes it (tan γ / 2); the sine and cosine from t as it is.
    let written = t.factor_terms()?.tangents_gathered();
    let shown = (Func::Tan.apply(Expr::sym(u)) - written.clone()).expand()?;
    let (mut n, mut d) = t.together_parts()?;
    let mut ruled_out = Vec::new();
    let quarter = Expr::pi() / Expr::int(2);
    let (first, turned) = match (context.sign)(&d) {
        Some(Ordering::Equal) => {
            let up = |sign: i64| Candidate {
                sine: Expr::int(sign),
                cosine: Expr::zero(),
                angle: Expr::int(sign) * quarter.clone(),
                by_values: true,
            };
            n = Expr::one();
            (up(1), up(-1))
        }
        sign => {
            match sign {
                Some(Ordering::Greater) => {}
                Some(Ordering::Less) => (n, d) = (-n, -d),
                _ => (n, d) = (t.clone(), Expr::one()),
            }
            let hypotenuse = (n.powi(2) + d.powi(2))
                .expand()?
                .checked_pow(&Expr::rational(-1, 2))?;
            let (sine, cosine) = ((&n * &hypotenuse).expand()?, (&d * &hypotenuse).expand()?);
            let angle = Func::Atan.apply(written);
            let turned = Candidate {
                sine: -sine.clone(),
                cosine: -cosine.clone(),
                angle: &angle + &Expr::pi(),
                by_values: false,
            };
            let first = Candidate {
                sine,
                cosine,
                angle,
                by_values: false,
            };
            (first, turned)
        }
    };
    let candidates = match (nutation, (context.sign)(&n)) {
        (true, Some(Ordering::Greater)) => vec![first],
        (true, Some(Ordering::Less)) => vec![turned],
        (true, Some(Ordering::Equal)) => {
            ruled_out.push(vertical(u, Expr::zero()));
            vec![]
        }
        _ => vec![first, turned],
    };
    Ok((candidates, ruled_out, (u, shown)))
}

/// `P₀ + s P₁ = 0` through a polynomial in c (see [`solve_for_angle`]): each real root c₀
/// in [−1, 1] is arccos c₀ (sine √(1 − c₀²)) and −arccos c₀, but for the Eulerian θ; a root
/// beyond ±1 is ruled out.
fn from_cosine(
    u: Symbol,
    (s, c): (Symbol, Symbol),
    even: Expr,
    odd: Expr,
    nutation: bool,
    context: &SolveContext,
) -> Result<Tried, SolveError> {
    // s P₁(c) = 0 also holds at s = 0, c = ±1; the page shows the equation as it is.
    let shown = Expr::sym(s) * odd.clone() + even.clone();
    let (polynomial, sine_zero) = match (even.is_zero(), odd.is_zero()) {
        (_, true) => (even, false),
        (true, false) => (odd, true),
        (false, false) => {
            let one_less = Expr::one() - Expr::sym(c).powi(2);
            ((even.powi(2) - one_less * odd.powi(2)).expand()?, false)
        }
    };
    let roots = solve_system(&[polynomial], &[c], context)?;
    let mut cosines: Vec<Expr> = roots
        .branches
        .iter()
        .filter_map(|b| b.first().map(|(_, v)| v.clone()))
        .collect();
    if sine_zero {
        for end in [Expr::one(), -Expr::one()] {
            if !cosines.contains(&end) {
                cosines.push(end);
            }
        }
    }
    let mut ruled_out = roots.dropped;
    let mut candidates = Vec::new();
    for cosine in cosines {
        let one_less = (Expr::one() - cosine.powi(2)).expand()?;
        if (context.sign)(&one_less) == Some(Ordering::Less) {
            // The angle's root, its cosine the value shown (`c_theta = -2.05`).
            let mut beyond = dropped(
                c,
                cosine,
                "its cosine would be beyond ±1, which is no angle",
                r"a cosine beyond $\pm 1$: no angle",
            );
            beyond.unknown = u;
            ruled_out.push(beyond);
            continue;
        }
        let sine = one_less.checked_pow(&Expr::rational(1, 2))?;
        let angle = Func::Acos.apply(cosine.clone());
        let negative = (!nutation && !sine.is_zero()).then(|| Candidate {
            sine: -sine.clone(),
            cosine: cosine.clone(),
            angle: -angle.clone(),
            by_values: false,
        });
        candidates.push(Candidate {
            sine,
            cosine,
            angle,
            by_values: false,
        });
        candidates.extend(negative);
    }
    Ok((candidates, ruled_out, (c, shown)))
}

/// The Eulerian θ at 0 or π ruled out: the axis along K, where φ and ψ are not told apart.
fn vertical(u: Symbol, angle: Expr) -> DroppedRoot {
    dropped(
        u,
        angle,
        "the axis is vertical there, where the Eulerian angles φ and ψ are not told apart",
        r"the axis vertical: $\phi$ and $\psi$ not told apart at $\theta = 0$ or $\pi$",
    )
}

/// A root ruled out for `reason` (`words` as a page shows it).
fn dropped(unknown: Symbol, value: Expr, reason: &str, words: &str) -> DroppedRoot {
    DroppedRoot {
        unknown,
        value: value.clone(),
        reason: reason.into(),
        condition: Condition {
            words: words.into(),
            lhs: Expr::sym(unknown),
            rhs: value,
        },
    }
}
