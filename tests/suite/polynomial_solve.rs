//! Systems with one unknown that enters polynomially, solved exactly (issue 19): each real
//! root a branch of its own, the roots ruled out named with their reason, a linear system
//! exactly as `solve_linear` solves it.
//!
//! Each root is checked independently of the solver: put back into the equations it must
//! give zero exactly (expanded, in lowest terms), and at numbers it must agree with the
//! closed form evaluated in f64 here (the quadratic formula written out in the test), or
//! with the polynomial's value (Cardano's cube roots, which the algebra does not multiply
//! out).

use kinetics::algebra::linear_solve::{solve_linear, SolveError};
use kinetics::algebra::polynomial_solve::{solve_system, Solutions, SolveContext};
use kinetics::algebra::{Expr, Symbol, Q};
use kinetics::numeric::scalar::double_double::DoubleDouble as Dd;
use kinetics::parse_expression;
use proptest::prelude::*;
use std::cmp::Ordering;
use std::time::{Duration, Instant};

fn e(s: &str) -> Expr {
    parse_expression("t", s).unwrap()
}

fn exprs(list: &[&str]) -> Vec<Expr> {
    list.iter().map(|s| e(s)).collect()
}

fn symbols(list: &[&str]) -> Vec<Symbol> {
    list.iter().map(|s| Symbol::new(s)).collect()
}

/// A top (section 18.9): I' = 0.02 kg m², I = 0.01 kg m², ω_z = 200 rad/s, W = 10 N,
/// c = 0.05 m, θ = 0.5 rad, m = 1.02 kg, r = 0.04 m; any other symbol 1.3.
fn top_value(s: Symbol) -> f64 {
    match s.name() {
        "I_p" => 0.02,
        "I" => 0.01,
        "omega_z" => 200.0,
        "W" => 10.0,
        "c" => 0.05,
        "theta" => 0.5,
        "m" => 1.02,
        "r" => 0.04,
        _ => 1.3,
    }
}

fn value_at(x: &Expr, values: &dyn Fn(Symbol) -> f64) -> f64 {
    x.eval(&|s: Symbol| Some(values(s))).unwrap()
}

/// The sign of an expression at the values: zero below 1e-12, unknown below 1e-9.
fn sign_at(x: &Expr, values: &dyn Fn(Symbol) -> f64) -> Option<Ordering> {
    let v: f64 = x.eval(&|s: Symbol| Some(values(s))).ok()?;
    match v.abs() {
        a if a < 1e-12 => Some(Ordering::Equal),
        a if a < 1e-9 => None,
        _ => v.partial_cmp(&0.0),
    }
}

fn solve(
    equations: &[Expr],
    unknowns: &[Symbol],
    values: &dyn Fn(Symbol) -> f64,
    positive: &dyn Fn(Symbol) -> bool,
) -> Result<Solutions, SolveError> {
    let sign = |x: &Expr| sign_at(x, values);
    let context = SolveContext {
        sign: &sign,
        positive,
    };
    solve_system(equations, unknowns, &context)
}

/// Each equation with the branch's values put in: expanded and in lowest terms.
fn residuals(equations: &[Expr], branch: &[(Symbol, Expr)]) -> Vec<Expr> {
    let value = |s: Symbol| branch.iter().find(|(u, _)| *u == s).map(|(_, v)| v.clone());
    equations
        .iter()
        .map(|eq| eq.subs(&value).unwrap().expand().unwrap().cancel().unwrap())
        .collect()
}

fn value_of(branch: &[(Symbol, Expr)], name: &str) -> Expr {
    branch
        .iter()
        .find(|(u, _)| u.name() == name)
        .map(|(_, v)| v.clone())
        .unwrap_or_else(|| panic!("{name} is not solved in {branch:?}"))
}

#[test]
fn a_linear_system_is_solved_as_solve_linear_solves_it() {
    let no_values = |_: Symbol| 1.0;
    let cases: [(&[&str], &[&str]); 4] = [
        (&["a x + y - 3", "x - y - b"], &["x", "y"]),
        (&["x + y - 1"], &["x", "y"]),
        (
            &["R_x - m r w^2", "R_y - m g", "R_x + R_y - F"],
            &["R_x", "R_y", "F"],
        ),
        (&["x - 1", "x - 2"], &["x"]),
    ];
    for (equations, unknowns) in cases {
        let (equations, unknowns) = (exprs(equations), symbols(unknowns));
        let linear = solve_linear(&equations, &unknowns);
        let solved = solve(&equations, &unknowns, &no_values, &|_| true);
        match linear {
            Ok(l) => assert_eq!(
                solved.unwrap(),
                Solutions {
                    branches: vec![l.values],
                    dropped: vec![],
                    free: l.free,
                    polynomial: None,
                    eliminated: vec![],
                }
            ),
            Err(l) => assert_eq!(solved.unwrap_err(), l),
        }
    }
}

/// The quadratic formula for I' cos θ φ̇² − I ω_z φ̇ + W c = 0, in f64.
fn precession_rates(v: &dyn Fn(Symbol) -> f64) -> (f64, f64) {
    let n = |s: &str| v(Symbol::new(s));
    let a = n("I_p") * n("theta").cos();
    let b = -n("I") * n("omega_z");
    let c = n("W") * n("c");
    let root = (b * b - 4.0 * a * c).sqrt();
    ((-b - root) / (2.0 * a), (-b + root) / (2.0 * a))
}

const PRECESSION: &str = "I_p cos(theta) phidot^2 - I omega_z phidot + W c";

#[test]
fn a_top_precesses_steadily_slow_or_fast() {
    let equations = exprs(&[PRECESSION]);
    let unknowns = symbols(&["phidot"]);
    let solved = solve(&equations, &unknowns, &top_value, &|_| false).unwrap();
    assert_eq!(solved.branches.len(), 2, "{solved:?}");
    assert!(solved.dropped.is_empty());
    assert_eq!(solved.polynomial, Some((unknowns[0], equations[0].clone())));
    let (slow, fast) = precession_rates(&top_value);
    for (branch, expected) in solved.branches.iter().zip([slow, fast]) {
        assert!(residuals(&equations, branch).iter().all(Expr::is_zero));
        let got = value_at(&value_of(branch, "phidot"), &top_value);
        assert!(
            (got - expected).abs() < 1e-12 * expected.abs(),
            "{got} vs {expected}"
        );
    }
    // The slow rate first (ascending), whatever the order the formula gave them in.
    assert!(slow < fast);
}

#[test]
fn reactions_and_precession_give_two_full_branches() {
    // The reactions at the support with the precession: R_x = m r̄ φ̇² (the centripetal
    // force), R_y = W, and the moment equation.
    let equations = exprs(&["R_x - m r phidot^2", "R_y - W", PRECESSION]);
    let unknowns = symbols(&["R_x", "R_y", "phidot"]);
    let solved = solve(&equations, &unknowns, &top_value, &|_| false).unwrap();
    assert_eq!(solved.branches.len(), 2);
    let (slow, fast) = precession_rates(&top_value);
    for (branch, rate) in solved.branches.iter().zip([slow, fast]) {
        let names: Vec<&str> = branch.iter().map(|(u, _)| u.name()).collect();
        assert_eq!(names, ["R_x", "R_y", "phidot"]);
        assert!(residuals(&equations, branch).iter().all(Expr::is_zero));
        let r_x = value_at(&value_of(branch, "R_x"), &top_value);
        let expected = 1.02 * 0.04 * rate * rate;
        // The expanded form subtracts I²ω_z² and I ω_z √Δ, nearly equal for the slow rate:
        // about eight digits are lost in f64.
        assert!(
            (r_x - expected).abs() < 1e-7 * expected,
            "{r_x} vs {expected}"
        );
        assert_eq!(value_of(branch, "R_y"), e("W"));
    }
}

#[test]
fn a_top_spinning_too_slowly_has_no_steady_precession() {
    // ω_z = 10 rad/s: I²ω_z² = 0.01 < 4 I' cos θ W c = 0.0351.
    let slow_spin = |s: Symbol| {
        if s.name() == "omega_z" {
            10.0
        } else {
            top_value(s)
        }
    };
    let equations = exprs(&[PRECESSION]);
    let solved = solve(&equations, &symbols(&["phidot"]), &slow_spin, &|_| false).unwrap();
    assert!(solved.branches.is_empty());
    assert_eq!(solved.dropped.len(), 2);
    for d in &solved.dropped {
        assert!(d.reason.starts_with("complex"), "{}", d.reason);
        assert!(
            d.reason.contains("I^2*omega_z^2 - 4*I_p*W*c*cos(theta)"),
            "{}",
            d.reason
        );
        assert!(d.reason.ends_with("is negative"), "{}", d.reason);
    }
}

#[test]
fn a_discriminant_of_unknown_sign_keeps_both_roots() {
    let equations = exprs(&[PRECESSION]);
    let unknowns = symbols(&["phidot"]);
    let context = SolveContext {
        sign: &|_| None,
        positive: &|_| false,
    };
    let solved = solve_system(&equations, &unknowns, &context).unwrap();
    assert_eq!(solved.branches.len(), 2);
    assert!(solved.dropped.is_empty());
    // A number's sign needs no context: x² + 1 has no real root whatever it says.
    let solved = solve_system(&exprs(&["x^2 + 1"]), &symbols(&["x"]), &context).unwrap();
    assert!(solved.branches.is_empty());
    assert_eq!(solved.dropped.len(), 2);
}

#[test]
fn a_negative_root_of_a_positive_unknown_is_dropped() {
    // m² − m − 6 = (m − 3)(m + 2).
    let equations = exprs(&["m^2 - m - 6"]);
    let unknowns = symbols(&["m"]);
    let solved = solve(&equations, &unknowns, &top_value, &|s| s.name() == "m").unwrap();
    assert_eq!(solved.branches, vec![vec![(unknowns[0], Expr::int(3))]]);
    assert_eq!(solved.dropped.len(), 1);
    assert_eq!(solved.dropped[0].value, Expr::int(-2));
    assert_eq!(solved.dropped[0].reason, "negative, but m must be positive");
}

#[test]
fn a_root_that_makes_another_positive_unknown_negative_is_dropped() {
    // x² = 4 and L = x + 1 (a length): x = −2 gives L = −1.
    let equations = exprs(&["x^2 - 4", "L - x - 1"]);
    let unknowns = symbols(&["L", "x"]);
    let solved = solve(&equations, &unknowns, &top_value, &|s| s.name() == "L").unwrap();
    assert_eq!(solved.branches.len(), 1);
    assert_eq!(value_of(&solved.branches[0], "L"), Expr::int(3));
    assert_eq!(
        solved.dropped[0].reason,
        "gives L = -1, negative, but L must be positive"
    );
}

#[test]
fn a_root_that_zeroes_a_pivot_is_dropped() {
    // x (y − 1) = 0 and x² = x: at x = 0 the elimination of y divided by x.
    let equations = exprs(&["x y - x", "x^2 - x"]);
    let unknowns = symbols(&["y", "x"]);
    let solved = solve(&equations, &unknowns, &top_value, &|_| false).unwrap();
    assert_eq!(solved.branches.len(), 1);
    assert_eq!(value_of(&solved.branches[0], "x"), Expr::one());
    assert_eq!(value_of(&solved.branches[0], "y"), Expr::one());
    assert_eq!(solved.dropped[0].value, Expr::zero());
    assert!(
        solved.dropped[0].reason.contains("divides by zero"),
        "{}",
        solved.dropped[0].reason
    );
}

#[test]
fn a_linear_unknown_behind_a_pivot_holding_the_polynomial_unknown() {
    // x y = 1, x + y = 3: y = 1/x, x² − 3x + 1 = 0.
    let equations = exprs(&["x y - 1", "x + y - 3"]);
    let unknowns = symbols(&["x", "y"]);
    let solved = solve(&equations, &unknowns, &top_value, &|_| false).unwrap();
    assert_eq!(solved.branches.len(), 2);
    for (branch, sign) in solved.branches.iter().zip([-1.0, 1.0]) {
        assert!(residuals(&equations, branch).iter().all(Expr::is_zero));
        let x = value_at(&value_of(branch, "x"), &top_value);
        assert!((x - (3.0 + sign * 5f64.sqrt()) / 2.0).abs() < 1e-14);
        // y = 1/x is written with no root in its denominator: y = 3 − x = (3 ∓ √5)/2.
        assert_eq!(
            value_of(branch, "y"),
            (&Expr::int(3) - &value_of(branch, "x"))
        );
    }
}

#[test]
fn a_value_at_a_quadratic_root_has_no_root_in_its_denominator() {
    // F = m/(phidot − a) at the roots of the precession: the conjugate clears √Δ below.
    let equations = exprs(&["F (phidot - a) - m", PRECESSION]);
    let unknowns = symbols(&["F", "phidot"]);
    let solved = solve(&equations, &unknowns, &top_value, &|_| false).unwrap();
    assert_eq!(solved.branches.len(), 2);
    for branch in &solved.branches {
        let f = value_of(branch, "F");
        let (_, denominator) = f.cancelled_parts().unwrap();
        assert!(!denominator.to_string().contains("sqrt"), "{f}");
        assert!(
            residuals(&equations, branch).iter().all(Expr::is_zero),
            "{f}"
        );
        let rate = value_at(&value_of(branch, "phidot"), &top_value);
        let expected = 1.02 / (rate - 1.3);
        let got = value_at(&f, &top_value);
        assert!(
            (got - expected).abs() < 1e-9 * expected.abs(),
            "{got} vs {expected}"
        );
    }
}

#[test]
fn a_degree_above_four_is_refused_with_a_clear_error() {
    let err = solve(
        &exprs(&["x^5 - x - 1"]),
        &symbols(&["x"]),
        &top_value,
        &|_| false,
    )
    .unwrap_err();
    assert_eq!(
        err,
        SolveError::DegreeTooHigh {
            unknown: Symbol::new("x"),
            degree: 5
        }
    );
    assert_eq!(
        err.to_string(),
        "the equations reduce to a polynomial of degree 5 in x; only polynomials of degree up to 4 are solved exactly"
    );
    // The root 0 pulled out first: x⁶ − x² = x²(x⁴ − 1) is a quartic.
    let solved = solve(
        &exprs(&["x^6 - x^2"]),
        &symbols(&["x"]),
        &top_value,
        &|_| false,
    )
    .unwrap();
    let roots: Vec<Expr> = solved.branches.iter().map(|b| b[0].1.clone()).collect();
    assert_eq!(roots, [Expr::int(-1), Expr::zero(), Expr::one()]);
}

#[test]
fn an_unknown_inside_a_function_is_refused() {
    let err = solve(
        &exprs(&["sin(x) x^2 - 1"]),
        &symbols(&["x"]),
        &top_value,
        &|_| false,
    )
    .unwrap_err();
    assert!(matches!(err, SolveError::NotPolynomial { .. }), "{err}");
}

#[test]
fn two_unknowns_that_both_enter_nonlinearly_are_refused() {
    let err = solve(
        &exprs(&["x^2 + y^2 - 1", "x - y"]),
        &symbols(&["x", "y"]),
        &top_value,
        &|_| false,
    )
    .unwrap_err();
    assert!(
        matches!(err, SolveError::NoSinglePolynomial { .. }),
        "{err}"
    );
}

#[test]
fn a_biquadratic_gives_its_four_real_roots() {
    // (x² − 2)(x² − 3)
    let solved = solve(
        &exprs(&["x^4 - 5 x^2 + 6"]),
        &symbols(&["x"]),
        &top_value,
        &|_| false,
    )
    .unwrap();
    let roots: Vec<f64> = solved
        .branches
        .iter()
        .map(|b| value_at(&b[0].1, &top_value))
        .collect();
    let expected = [-(3f64.sqrt()), -(2f64.sqrt()), 2f64.sqrt(), 3f64.sqrt()];
    assert_eq!(roots.len(), 4);
    for (got, want) in roots.iter().zip(expected) {
        assert!((got - want).abs() < 1e-14, "{roots:?}");
    }
}

#[test]
fn a_cubic_with_one_real_root_by_cardano() {
    // x³ + x + 1: q²/4 + p³/27 = 1/4 + 1/27 > 0, one real root near −0.6823278.
    let equations = exprs(&["x^3 + x + 1"]);
    let solved = solve(&equations, &symbols(&["x"]), &top_value, &|_| false).unwrap();
    assert_eq!(solved.branches.len(), 1);
    assert_eq!(solved.dropped.len(), 2);
    let x = value_at(&solved.branches[0][0].1, &top_value);
    assert!((x * x * x + x + 1.0).abs() < 1e-14, "{x}");
    assert!((x + 0.682_327_803_828_019).abs() < 1e-14);
}

/// x³ − 3x + 1 (p = −3, q = 1, q²/4 + p³/27 = −3/4): three real roots no real radicals
/// write, by the trigonometric form 2 cos(⅓ arccos(−½) − 2πk/3) = 2 cos(2π/9 − 2πk/3); the
/// arccos is exact (2π/3). Checked against 2 cos(2π/9), 2 cos(4π/9), 2 cos(8π/9) written
/// here, the roots of the Chebyshev identity 8c³ − 6c = 2cos 3φ = −1 at 3φ = 2π/3 + 2πk.
#[test]
fn a_cubic_with_three_irrational_real_roots_by_the_trigonometric_form() {
    let solved = solve(
        &exprs(&["x^3 - 3 x + 1"]),
        &symbols(&["x"]),
        &top_value,
        &|_| false,
    )
    .unwrap();
    assert!(solved.dropped.is_empty());
    let roots: Vec<f64> = solved
        .branches
        .iter()
        .map(|b| value_at(&b[0].1, &top_value))
        .collect();
    let ninth = std::f64::consts::PI / 9.0;
    let expected = [
        2.0 * (8.0 * ninth).cos(),
        2.0 * (4.0 * ninth).cos(),
        2.0 * (2.0 * ninth).cos(),
    ];
    assert_eq!(roots.len(), 3, "{roots:?}");
    for (got, want) in roots.iter().zip(expected) {
        assert!((got - want).abs() < 1e-14, "{roots:?} vs {expected:?}");
    }
    let printed: Vec<String> = solved.branches.iter().map(|b| b[0].1.to_string()).collect();
    assert!(printed.iter().all(|r| !r.contains("acos")), "{printed:?}");
}

/// A cubic with letters for coefficients, a x³ + b x + c, is solved once the values tell
/// the sign of q²/4 + p³/27: one real root by Cardano (a = 1, b = 2, c = −3 has the root 1)
/// or three by the trigonometric form (a = 1, b = −7, c = 6: roots −3, 1, 2); without values
/// the number of real roots is not known and the solver says which sign decides.
#[test]
fn a_symbolic_cubic_is_solved_at_the_values_that_tell_its_discriminant() {
    let equations = exprs(&["a x^3 + b x + c"]);
    let one_root = |s: Symbol| match s.name() {
        "a" => 1.0,
        "b" => 2.0,
        "c" => -3.0,
        _ => f64::NAN,
    };
    let solved = solve(&equations, &symbols(&["x"]), &one_root, &|_| false).unwrap();
    assert_eq!((solved.branches.len(), solved.dropped.len()), (1, 2));
    assert!((value_at(&solved.branches[0][0].1, &one_root) - 1.0).abs() < 1e-14);
    let three_roots = |s: Symbol| match s.name() {
        "a" => 1.0,
        "b" => -7.0,
        "c" => 6.0,
        _ => f64::NAN,
    };
    let solved = solve(&equations, &symbols(&["x"]), &three_roots, &|_| false).unwrap();
    let roots: Vec<f64> = solved
        .branches
        .iter()
        .map(|b| value_at(&b[0].1, &three_roots))
        .collect();
    assert_eq!(roots.len(), 3);
    for (got, want) in roots.iter().zip([-3.0, 1.0, 2.0]) {
        assert!((got - want).abs() < 1e-13, "{roots:?}");
    }
    let unknown = |x: &Expr| -> Option<Ordering> { x.as_num().map(|q| q.cmp(&Q::ZERO)) };
    let context = SolveContext {
        sign: &unknown,
        positive: &|_| false,
    };
    let err = solve_system(&equations, &symbols(&["x"]), &context).unwrap_err();
    assert!(
        matches!(err, SolveError::RootsNotExact { .. }) && err.to_string().contains("q²/4 + p³/27"),
        "{err}"
    );
}

/// Quartics with odd powers and no rational root, by Ferrari's method:
/// (x² − 2x − 1)(x² − 2x − 2) multiplied out has the roots 1 ± √2 and 1 ± √3; x⁴ + x + 1
/// has no real root, its four complex roots dropped with the reason.
#[test]
fn a_quartic_with_odd_powers_by_ferrari() {
    let equations = vec![e("(x^2 - 2 x - 1) (x^2 - 2 x - 2)").expand().unwrap()];
    let solved = solve(&equations, &symbols(&["x"]), &top_value, &|_| false).unwrap();
    let roots: Vec<f64> = solved
        .branches
        .iter()
        .map(|b| value_at(&b[0].1, &top_value))
        .collect();
    let (r2, r3) = (2f64.sqrt(), 3f64.sqrt());
    let expected = [1.0 - r3, 1.0 - r2, 1.0 + r2, 1.0 + r3];
    assert_eq!(roots.len(), 4, "{roots:?}");
    for (got, want) in roots.iter().zip(expected) {
        assert!((got - want).abs() < 1e-13, "{roots:?} vs {expected:?}");
    }
    // (x + 1)⁴ + 3(x + 1)² + 2 multiplied out: Q = 0, a quadratic in y² with y = x + 1, whose
    // roots y² = −1, −2 are dropped in words about y.
    let shifted = e("(x + 1)^4 + 3 (x + 1)^2 + 2").expand().unwrap();
    let solved = solve(&[shifted], &symbols(&["x"]), &top_value, &|_| false).unwrap();
    assert!(solved.branches.is_empty());
    assert_eq!(solved.dropped.len(), 4);
    assert!(
        solved
            .dropped
            .iter()
            .all(|d| d.reason.contains("where y = x + 1")),
        "{:?}",
        solved.dropped
    );
    let none = solve(
        &exprs(&["x^4 + x + 1"]),
        &symbols(&["x"]),
        &top_value,
        &|_| false,
    )
    .unwrap();
    assert!(none.branches.is_empty());
    assert_eq!(none.dropped.len(), 4);
    assert!(
        none.dropped.iter().all(|d| d.reason.contains("Ferrari")),
        "{:?}",
        none.dropped
    );
}

#[test]
fn a_large_polynomial_is_refused_or_solved_quickly() {
    // A quadratic whose coefficients are powers of a sum of twelve symbols: the ninth power
    // has 167,960 terms, past the bound on an expansion, and is refused for its size; the
    // squares are solved.
    let sum = "(a1 + a2 + a3 + a4 + a5 + a6 + a7 + a8 + a9 + a10 + a11 + a12)";
    for (powers, solved) in [((9, 7, 8), false), ((2, 1, 2), true)] {
        let (p2, p1, p0) = powers;
        let equations = exprs(&[&format!("{sum}^{p2} x^2 - {sum}^{p1} x - {sum}^{p0}")]);
        let started = Instant::now();
        let outcome = solve(&equations, &symbols(&["x"]), &top_value, &|_| false);
        assert!(
            started.elapsed() < Duration::from_secs(20),
            "{:?}",
            started.elapsed()
        );
        match outcome {
            Ok(s) => {
                assert!(solved);
                assert_eq!(s.branches.len(), 2);
                for branch in &s.branches {
                    assert!(residuals(&equations, branch).iter().all(Expr::is_zero));
                }
            }
            Err(SolveError::Algebra(e)) => assert!(!solved && e.is_beyond_bounds(), "{e}"),
            Err(e) => panic!("{e}"),
        }
    }
}

/// `k Π (x − rᵢ)` expanded, as a string.
fn from_roots(k: i64, roots: &[(i64, i64)]) -> Expr {
    let factors: Vec<String> = roots
        .iter()
        .map(|(p, q)| format!("(x - ({p})/({q}))"))
        .collect();
    e(&format!("{k} * {}", factors.join(" * ")))
        .expand()
        .unwrap()
}

/// The number of distinct real roots of `Σ aₖ xᵏ` (integer coefficients, lowest power
/// first) by Sturm's theorem: the sign changes of the Sturm sequence `p, p′, −rem(…)` at
/// −∞ less those at +∞.
fn distinct_real_roots_by_sturm(coefficients: &[f64]) -> usize {
    type Poly = Vec<Q>;
    let trim = |mut p: Poly| {
        while p.len() > 1 && p.last().is_some_and(Q::is_zero) {
            p.pop();
        }
        p
    };
    let remainder = |a: &Poly, b: &Poly| -> Poly {
        let mut r = a.clone();
        while r.len() >= b.len() && !(r.len() == 1 && r[0].is_zero()) {
            let factor = r.last().unwrap().checked_div(b.last().unwrap()).unwrap();
            let shift = r.len() - b.len();
            for (i, bi) in b.iter().enumerate() {
                r[i + shift] = &r[i + shift] - &(&factor * bi);
            }
            r.pop();
            r = trim(r);
            if r.is_empty() {
                r.push(Q::ZERO);
            }
        }
        r
    };
    let p: Poly = coefficients.iter().map(|&c| Q::int(c as i64)).collect();
    let derivative: Poly = (1..p.len()).map(|k| &Q::int(k as i64) * &p[k]).collect();
    let mut sequence = vec![p, derivative];
    loop {
        let n = sequence.len();
        let r = remainder(&sequence[n - 2], &sequence[n - 1]);
        if r.len() == 1 && r[0].is_zero() {
            break;
        }
        sequence.push(r.into_iter().map(|c| -&c).collect());
    }
    let changes = |at_plus_infinity: bool| {
        let signs: Vec<bool> = sequence
            .iter()
            .map(|p| {
                let positive = p.last().unwrap() > &Q::ZERO;
                let odd = (p.len() - 1) % 2 == 1;
                if at_plus_infinity || !odd {
                    positive
                } else {
                    !positive
                }
            })
            .collect();
        signs.windows(2).filter(|w| w[0] != w[1]).count()
    };
    changes(false) - changes(true)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A polynomial built from chosen rational roots gives each of them back once, exactly.
    #[test]
    fn chosen_rational_roots_are_recovered(
        k in prop::sample::select(vec![-6i64, -1, 1, 2, 5]),
        roots in prop::collection::vec((-20i64..20, 1i64..6), 1..5),
    ) {
        let p = from_roots(k, &roots);
        let solved = solve(&[p], &symbols(&["x"]), &top_value, &|_| false).unwrap();
        let mut got: Vec<Expr> = solved.branches.iter().map(|b| b[0].1.clone()).collect();
        let mut want: Vec<Expr> = roots.iter().map(|&(p, q)| Expr::rational(p, q)).collect();
        want.sort_by(|a, b| value_at(a, &top_value).total_cmp(&value_at(b, &top_value)));
        want.dedup();
        prop_assert_eq!(&got, &want);
        got.dedup();
        prop_assert_eq!(got.len(), want.len());
    }

    /// The roots of an integer quadratic put back give zero exactly, and there are as many
    /// as the sign of b² − 4ac says.
    #[test]
    fn quadratic_roots_satisfy_the_equation(a in -9i64..10, b in -30i64..30, c in -30i64..30) {
        prop_assume!(a != 0);
        let equations = vec![e(&format!("({a}) x^2 + ({b}) x + ({c})"))];
        let solved = solve(&equations, &symbols(&["x"]), &top_value, &|_| false).unwrap();
        let d = b * b - 4 * a * c;
        let expected = match d.cmp(&0) { Ordering::Less => 0, Ordering::Equal => 1, Ordering::Greater => 2 };
        prop_assert_eq!(solved.branches.len(), expected);
        prop_assert_eq!(solved.dropped.len(), if d < 0 { 2 } else { 0 });
        for branch in &solved.branches {
            prop_assert!(residuals(&equations, branch).iter().all(Expr::is_zero), "{:?}", branch);
        }
    }

    /// An integer cubic: each real root makes the cubic vanish in double-double arithmetic
    /// (Cardano's form subtracts nearly equal cube roots: f64 keeps only ten digits of
    /// them), and there are as many distinct real roots as the sign of the discriminant
    /// 18abcd − 4b³d + b²c² − 4ac³ − 27a²d² says: three when positive, one when negative.
    #[test]
    fn cubic_roots_satisfy_the_equation(a in 1i64..5, b in -9i64..10, c in -9i64..10, d in -9i64..10) {
        let equations = vec![e(&format!("({a}) x^3 + ({b}) x^2 + ({c}) x + ({d})"))];
        let n = |k: i64| Dd::from_f64(k as f64);
        let cubic = |x: Dd| ((n(a) * x + n(b)) * x + n(c)) * x + n(d);
        let solved = solve(&equations, &symbols(&["x"]), &top_value, &|_| false).unwrap();
        for branch in &solved.branches {
            let x: Dd = branch[0].1.eval(&|_| None).unwrap();
            let scale = 1.0 + (n(a) * x * x * x).abs().to_f64() + (n(b) * x * x).abs().to_f64() + (n(c) * x).abs().to_f64();
            prop_assert!(cubic(x).abs().to_f64() < 1e-26 * scale, "{:?} at {:?}", cubic(x), branch);
        }
        let discriminant = 18 * a * b * c * d - 4 * b.pow(3) * d + b * b * c * c
            - 4 * a * c.pow(3) - 27 * a * a * d * d;
        match discriminant.cmp(&0) {
            Ordering::Greater => prop_assert_eq!(solved.branches.len(), 3),
            Ordering::Less => prop_assert_eq!(solved.branches.len(), 1),
            Ordering::Equal => prop_assert!((1..=2).contains(&solved.branches.len())),
        }
    }

    /// An integer quartic: each real root makes it vanish in double-double arithmetic, and
    /// there are as many as Sturm's theorem counts (exact rational arithmetic, written here).
    #[test]
    fn quartic_roots_satisfy_the_equation(
        b in -9i64..10, c in -9i64..10, d in -9i64..10, k in -9i64..10,
    ) {
        prop_assume!(d != 0 && k != 0);
        let equations = vec![e(&format!("x^4 + ({b}) x^3 + ({c}) x^2 + ({d}) x + ({k})"))];
        let n = |v: i64| Dd::from_f64(v as f64);
        let quartic = |x: Dd| (((x + n(b)) * x + n(c)) * x + n(d)) * x + n(k);
        let solved = solve(&equations, &symbols(&["x"]), &top_value, &|_| false).unwrap();
        for branch in &solved.branches {
            let x: Dd = branch[0].1.eval(&|_| None).unwrap();
            let terms = [x.powi(4), n(b) * x.powi(3), n(c) * x * x, n(d) * x, n(k)];
            let scale: f64 = terms.iter().map(|t| t.abs().to_f64()).sum();
            prop_assert!(quartic(x).abs().to_f64() < 1e-24 * scale, "{:?} at {:?}", quartic(x), branch);
        }
        prop_assert_eq!(
            solved.branches.len(),
            distinct_real_roots_by_sturm(&[k as f64, d as f64, c as f64, b as f64, 1.0])
        );
    }
}

#[test]
fn a_leading_coefficient_the_values_make_zero_leaves_a_lower_degree() {
    // θ = 90°: I' cos θ = 0 and the precession is W c/(I ω_z), the one root of a linear
    // equation (the quadratic formula would divide by zero).
    let upright = |s: Symbol| match s.name() {
        "theta" => std::f64::consts::FRAC_PI_2,
        _ => top_value(s),
    };
    let equations = exprs(&[PRECESSION]);
    let solved = solve(&equations, &symbols(&["phidot"]), &upright, &|_| false).unwrap();
    assert_eq!(solved.branches.len(), 1);
    let rate = value_at(&solved.branches[0][0].1, &upright);
    let expected = 10.0 * 0.05 / (0.01 * 200.0);
    assert!((rate - expected).abs() < 1e-15, "{rate} vs {expected}");
}

/// (x − a)(x + b) multiplied out: the discriminant (b − a)² + 4ab is the square (a + b)², so
/// the roots come out as a and −b, with no square root left.
#[test]
fn a_square_discriminant_leaves_no_square_root() {
    let solved = solve(
        &exprs(&["x^2 + (b - a) x - a b"]),
        &symbols(&["x"]),
        &top_value,
        &|_| false,
    )
    .unwrap();
    let mut roots: Vec<Expr> = solved.branches.iter().map(|b| b[0].1.clone()).collect();
    roots.sort_by_key(|r| r.to_string());
    assert_eq!(roots, [e("-b"), e("a")]);
}

#[test]
fn a_double_root_is_one_branch() {
    // (x − a)² = x² − 2ax + a²: the discriminant expands to zero.
    let solved = solve(
        &exprs(&["x^2 - 2 a x + a^2"]),
        &symbols(&["x"]),
        &top_value,
        &|_| false,
    )
    .unwrap();
    assert_eq!(solved.branches, vec![vec![(Symbol::new("x"), e("a"))]]);
    assert!(solved.dropped.is_empty());
}

/// Each dropped root's condition is a well-formed title (words, mathematics in the markup's
/// subset) about its relation: the complex pair of `x² + 1` (the discriminant Δ = −4), of a
/// biquadratic `x⁴ + 3x² + 2` (x² = −1, −2), of the cubic `x³ + x + 1` by Cardano
/// (q²/4 + p³/27 = 31/108), and a root that makes a positive unknown negative (L = −1); the
/// cubic's left side, q²/4 + p³/27 in the symbols of its reduced form, is not compared (zero
/// in the table).
#[test]
fn each_dropped_roots_condition_is_a_title_about_its_relation() {
    let ones = |_: Symbol| 1.0;
    let cases: [(&[&str], &[&str], Expr, Expr); 4] = [
        (&["x^2 + 1"], &["x"], Expr::symbol("Delta"), Expr::int(-4)),
        (
            &["x^4 + 3*x^2 + 2"],
            &["x"],
            Expr::symbol("x").checked_pow(&Expr::int(2)).unwrap(),
            Expr::int(-1),
        ),
        (
            &["x^3 + x + 1"],
            &["x"],
            Expr::zero(),
            Expr::rational(31, 108),
        ),
        (
            &["x^2 - 4", "L - x - 1"],
            &["L", "x"],
            Expr::symbol("L"),
            Expr::int(-1),
        ),
    ];
    for (equations, unknowns, lhs, rhs) in cases {
        let solved = solve(&exprs(equations), &symbols(unknowns), &ones, &|s| {
            s.name() == "L"
        })
        .unwrap();
        assert!(!solved.dropped.is_empty(), "{equations:?}");
        for d in &solved.dropped {
            let words = &d.condition.words;
            kinetics::print::markup::validate(words).unwrap_or_else(|e| panic!("{words:?}: {e:?}"));
        }
        assert!(
            solved.dropped.iter().any(|d| d.condition.rhs == rhs),
            "{equations:?}: {:?}",
            solved.dropped
        );
        if !lhs.is_zero() {
            assert!(
                solved.dropped.iter().any(|d| d.condition.lhs == lhs),
                "{equations:?}"
            );
        }
    }
}
