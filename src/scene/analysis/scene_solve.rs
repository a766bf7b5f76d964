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
use crate::algebra::{work, AlgebraError, Expr, Func, Symbol};
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
    let angles = angle_unknowns(equations, wanted);
    let what = || {
        let names: Vec<&str> = wanted.iter().map(|u| u.name()).collect();
        format!("solving the equations for {}", names.join(", "))
    };
    let solved = work::doing(what, || match angles.first() {
        Some(&u) => solve_for_angle(scene, equations, wanted, u, &context),
        None => solve_system(equations, wanted, &context),
    });
    match solved {
        // The angles are solved one at a time: that, not the nonlinear term, is the cause.
        Err(_) if angles.len() > 1 => Err(SolveError::SeveralAngles(angles)),
        solved => solved,
    }
}

/// The unknowns that enter only through sin, cos and tan of themselves (and do enter):
/// decided by reading the equations, nothing rewritten (asked of every scene's unknowns).
fn angle_unknowns(equations: &[Expr], wanted: &[Symbol]) -> Vec<Symbol> {
    let angle = |u: Symbol| {
        equations.iter().any(|e| e.contains(u))
            && equations
                .iter()
                .all(|e| enters_only_through_trigonometry(e, u))
    };
    wanted.iter().copied().filter(|&u| angle(u)).collect()
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
    let Some((alone, eliminated)) = angle_alone(equations, u, &others)? else {
        // Fewer equations than unknowns fix none of them; said so, not that the angle is no
        // polynomial.
        if equations.len() < wanted.len() {
            return Err(SolveError::UnderDetermined(wanted.to_vec()));
        }
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
        eliminated: eliminated.clone(),
    };
    for Candidate {
        sine,
        cosine,
        angle,
        by_values,
    } in candidates
    {
        if nutation && vanishes(scene, context, &sine) {
            solutions.dropped.push(vertical(u, angle));
            continue;
        }
        let at = Angle {
            u,
            sine: &sine,
            cosine: &cosine,
            by_values,
        };
        let solved = match by_elimination(scene, equations, &others, &eliminated, &at, context)? {
            Some(Found::Solved(branch)) => Ok(branch),
            Some(Found::NotHolding) => Err(SolveError::Inconsistent {
                equation: 0,
                residual: String::new(),
            }),
            None => at.solve_rest(scene, equations, &others, context),
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

/// The angle u at a candidate: its sine and cosine put in for sin u and cos u, and the
/// givens' exact values too when they decided it.
struct Angle<'a> {
    u: Symbol,
    sine: &'a Expr,
    cosine: &'a Expr,
    by_values: bool,
}

impl Angle<'_> {
    /// `e` at this angle, expanded; none when u enters otherwise than through sin, cos, tan.
    fn put_in(&self, scene: &Scene, e: &Expr) -> Result<Option<Expr>, AlgebraError> {
        let Some(at) = at_angle(e, self.u, self.sine, self.cosine)? else {
            return Ok(None);
        };
        match self.by_values {
            true => Ok(Some(at.subs(&|s| scene.exact_given(s))?.expand()?)),
            false => Ok(Some(at)),
        }
    }

    /// The equations at this angle solved for the other unknowns (the first solution).
    fn solve_rest(
        &self,
        scene: &Scene,
        equations: &[Expr],
        others: &[Symbol],
        context: &SolveContext,
    ) -> Result<Vec<(Symbol, Expr)>, SolveError> {
        let mut rest = Vec::new();
        for e in equations {
            if let Some(at) = self.put_in(scene, e)? {
                rest.push(at);
            }
        }
        rest.retain(|e| !e.is_zero());
        match rest.is_empty() {
            true => Ok(Vec::new()),
            false => solve_system(&rest, others, context)
                .map(|s| s.branches.into_iter().next().unwrap_or_default()),
        }
    }
}

/// What the elimination found at an angle.
enum Found {
    /// The other unknowns' values (every equation holds).
    Solved(Vec<(Symbol, Expr)>),
    /// An equation does not hold: a root of the squared or multiplied-through equation only.
    NotHolding,
}

/// At the angle, the unknowns eliminated to reach it (`eliminated`, in order) back-substituted,
/// last first, and every equation checked with them ([`vanishes`]). None when the
/// chain does not give every other unknown (or divides by zero at this angle): the equations
/// are then solved for them.
fn by_elimination(
    scene: &Scene,
    equations: &[Expr],
    others: &[Symbol],
    eliminated: &[(Symbol, Expr)],
    at: &Angle,
    context: &SolveContext,
) -> Result<Option<Found>, SolveError> {
    if eliminated.len() != others.len() {
        return Ok(None);
    }
    let mut values: Vec<(Symbol, Expr)> = Vec::new();
    for (w, value) in eliminated.iter().rev() {
        let lookup = |s: Symbol| values.iter().find(|(v, _)| *v == s).map(|(_, x)| x.clone());
        let value = at
            .put_in(scene, value)
            .and_then(|v| v.map(|v| v.subs(&lookup)?.expand()).transpose());
        match value {
            Ok(Some(v)) => values.push((*w, v)),
            Ok(None) | Err(AlgebraError::DivisionByZero) => return Ok(None),
            Err(e) => return Err(e.into()),
        }
    }
    let lookup = |s: Symbol| values.iter().find(|(v, _)| *v == s).map(|(_, x)| x.clone());
    for e in equations {
        let Some(residual) = at.put_in(scene, e)? else {
            return Ok(None);
        };
        let residual = residual.subs(&lookup)?.expand()?;
        if !vanishes(scene, context, &residual) {
            return Ok(Some(Found::NotHolding));
        }
    }
    values.sort_by_key(|(w, _)| others.iter().position(|o| o == w));
    Ok(Some(Found::Solved(values)))
}

/// Whether `e` is zero: exactly, or with the givens' exact values within its rounding bound
/// when every given in it has a value (nested radicals the algebra does not cancel).
fn vanishes(scene: &Scene, context: &SolveContext, e: &Expr) -> bool {
    let valued = || {
        e.symbols()
            .into_iter()
            .all(|s| s.is_pi() || scene.value(s).is_some())
    };
    e.is_zero()
        || match (context.sign)(e) {
            Some(Ordering::Equal) => true,
            Some(_) => false,
            None => valued(),
        }
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
