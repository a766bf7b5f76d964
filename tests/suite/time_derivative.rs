//! `d/dt` through time-dependent symbols and the functions: the rules on small cases,
//! written out by hand, and an independent numeric check of the derivative along smooth
//! trajectories against central finite differences, on chosen expressions and on random ones.
//!
//! Which symbols depend on time is the naming convention of `Symbol`: kinematic ones (`w_x`,
//! `theta`, `v_y`, ...) do, and `d/dt` turns them into their dotted forms (`wdot_x`,
//! `thetadot`, `vdot_y`, then `wddot_x`, ...); inertia, mass, lengths and other quantities
//! (among them the constant angle `beta`) do not.

use crate::common::expression_tree::{point, tree};
use kinetics::algebra::{AlgebraError, Expr, Func, Symbol};
use kinetics::parse::parse_expression;
use proptest::prelude::*;

fn s(name: &str) -> Expr {
    Expr::symbol(name)
}

fn parsed(input: &str) -> Expr {
    parse_expression("test", input).expect("the test's input parses")
}

/// `u^(p/q)`.
fn power(u: &Expr, p: i64, q: i64) -> Expr {
    u.checked_pow(&Expr::rational(p, q))
        .expect("not zero to a negative power")
}

/// `d/dt sin θ = cos θ θ̇`, `d/dt cos θ = -sin θ θ̇`, `d/dt tan θ = (1 + tan² θ) θ̇`,
/// `d/dt |ω_x| = ω_x/|ω_x| ω̇_x`: the derivative of each function times that of its argument.
#[test]
fn each_function_differentiates_by_the_chain_rule() {
    let (theta, thetadot) = (s("theta"), s("thetadot"));
    let (sin, cos, tan) = (
        Func::Sin.apply(theta.clone()),
        Func::Cos.apply(theta.clone()),
        Func::Tan.apply(theta.clone()),
    );
    assert_eq!(sin.d_dt().unwrap(), &cos * &thetadot);
    assert_eq!(cos.d_dt().unwrap(), -(&sin * &thetadot));
    assert_eq!(
        tan.d_dt().unwrap().expand().unwrap(),
        (&thetadot + &tan.powi(2) * &thetadot).expand().unwrap()
    );
    let w = s("w_x");
    let abs = Func::Abs.apply(w.clone());
    assert_eq!(abs.d_dt().unwrap(), &w / &abs * s("wdot_x"));
}

/// The chain rule through nested functions and powers: `d/dt sin(θ²) = 2 θ θ̇ cos(θ²)` and
/// `d/dt cos(ω_x θ) = -(ω̇_x θ + ω_x θ̇) sin(ω_x θ)`.
#[test]
fn chain_rule_goes_through_nested_arguments() {
    let (theta, thetadot) = (s("theta"), s("thetadot"));
    let inner = theta.powi(2);
    let e = Func::Sin.apply(inner.clone());
    assert_eq!(
        e.d_dt().unwrap(),
        Expr::int(2) * &theta * &thetadot * Func::Cos.apply(inner)
    );
    let product = s("w_x") * &theta;
    let e = Func::Cos.apply(product.clone());
    let rate = s("wdot_x") * &theta + s("w_x") * &thetadot;
    assert_eq!(
        e.d_dt().unwrap().expand().unwrap(),
        (-(rate * Func::Sin.apply(product))).expand().unwrap()
    );
}

/// The product rule with the chain rule: `d/dt (I_x ω_x cos θ) = I_x ω̇_x cos θ
/// - I_x ω_x θ̇ sin θ`; `I_x` is constant.
#[test]
fn product_rule_with_a_function_factor() {
    let (i, w, theta) = (s("I_x"), s("w_x"), s("theta"));
    let e = &i * &w * Func::Cos.apply(theta.clone());
    let expected = &i * s("wdot_x") * Func::Cos.apply(theta.clone())
        - &i * &w * s("thetadot") * Func::Sin.apply(theta);
    assert_eq!(e.d_dt().unwrap(), expected);
}

/// Powers: `d/dt ω_x³ = 3 ω_x² ω̇_x`, `d/dt √ω_x = ω̇_x / (2 √ω_x)`,
/// `d/dt (1/v_y) = -v̇_y / v_y²`, and the root of a sum
/// `d/dt √(ω_x² + v_y²) = (ω_x ω̇_x + v_y v̇_y) / √(ω_x² + v_y²)`.
#[test]
fn powers_differentiate_with_their_exponent() {
    let (w, wdot, v, vdot) = (s("w_x"), s("wdot_x"), s("v_y"), s("vdot_y"));
    assert_eq!(w.powi(3).d_dt().unwrap(), Expr::int(3) * w.powi(2) * &wdot);
    assert_eq!(
        power(&w, 1, 2).d_dt().unwrap(),
        Expr::rational(1, 2) * power(&w, -1, 2) * &wdot
    );
    assert_eq!(v.powi(-1).d_dt().unwrap(), -(&vdot * v.powi(-2)));
    let squares = w.powi(2) + v.powi(2);
    let root = power(&squares, 1, 2);
    let expected = (&w * &wdot + &v * &vdot) * power(&squares, -1, 2);
    assert_eq!(
        root.d_dt().unwrap().expand().unwrap(),
        expected.expand().unwrap()
    );
    assert_eq!(
        parsed("sqrt(w_x)").d_dt().unwrap(),
        power(&w, 1, 2).d_dt().unwrap()
    );
}

/// Derivatives of derivatives: `d/dt ω̇_x = ω̈_x`, and
/// `d²/dt² sin θ = cos θ θ̈ - sin θ θ̇²`.
#[test]
fn second_derivatives_dot_the_dotted_symbols() {
    assert_eq!(s("wdot_x").d_dt().unwrap(), s("wddot_x"));
    let theta = s("theta");
    let second = Func::Sin
        .apply(theta.clone())
        .d_dt()
        .unwrap()
        .d_dt()
        .unwrap();
    let expected = Func::Cos.apply(theta.clone()) * s("thetaddot")
        - Func::Sin.apply(theta) * s("thetadot").powi(2);
    assert_eq!(second, expected);
}

/// An expression of constants only (inertia, mass, lengths, numbers, and the constant
/// angle `beta`) has the time derivative zero, through every function and power.
#[test]
fn constants_have_no_time_derivative() {
    let e =
        parsed("I_x sin(beta)^2 L^2/m + sqrt(2) b + tan(a/(b + c)) - abs(h - 3/4) + cos(0.1 L)");
    assert!(e.d_dt().unwrap().is_zero(), "{}", e.d_dt().unwrap());
    assert!(parsed("7/3").d_dt().unwrap().is_zero());
}

/// A power whose exponent depends on time is refused, not differentiated wrongly.
#[test]
fn time_dependent_exponent_is_an_error() {
    let e = s("a").checked_pow(&s("theta")).unwrap();
    assert!(matches!(
        e.d_dt(),
        Err(AlgebraError::TimeDependentExponent(_))
    ));
}

/// A smooth motion of one time-dependent quantity, `q(t) = s (1 + 0.4 sin(k t + φ))`,
/// which stays in `±[0.6, 1.4]`, with its rate and acceleration in closed form.
#[derive(Debug, Clone)]
struct Motion {
    sign: f64,
    frequency: f64,
    phase: f64,
}

impl Motion {
    fn at(&self, t: f64) -> f64 {
        self.sign * (1.0 + 0.4 * (self.frequency * t + self.phase).sin())
    }

    fn rate(&self, t: f64) -> f64 {
        self.sign * 0.4 * self.frequency * (self.frequency * t + self.phase).cos()
    }

    fn acceleration(&self, t: f64) -> f64 {
        -self.sign * 0.4 * self.frequency.powi(2) * (self.frequency * t + self.phase).sin()
    }
}

fn motion() -> impl Strategy<Value = Motion> {
    (
        prop::sample::select(vec![-1.0, 1.0]),
        0.5f64..2.0,
        0.0f64..std::f64::consts::TAU,
    )
        .prop_map(|(sign, frequency, phase)| Motion {
            sign,
            frequency,
            phase,
        })
}

/// Symbols that move along motions and symbols that keep constant values.
struct Trajectory<'a> {
    moving: &'a [(&'a str, Motion)],
    constant: &'a [(&'a str, f64)],
}

impl Trajectory<'_> {
    /// The value at time `t` of a symbol, of its rate (the dotted symbol) or of its
    /// acceleration (the double-dotted symbol).
    fn value(&self, symbol: Symbol, t: f64) -> Option<f64> {
        for (name, m) in self.moving {
            let q = Symbol::new(name);
            if symbol == q {
                return Some(m.at(t));
            } else if symbol == q.dot() {
                return Some(m.rate(t));
            } else if symbol == q.dot().dot() {
                return Some(m.acceleration(t));
            }
        }
        self.constant
            .iter()
            .find(|(name, _)| Symbol::new(name) == symbol)
            .map(|&(_, v)| v)
    }

    fn eval(&self, e: &Expr, t: f64) -> f64 {
        e.eval(&|s| self.value(s, t))
            .unwrap_or_else(|err| panic!("{e} at t = {t}: {err}"))
    }
}

/// The first derivative of `f` at `t` by central differences, Richardson-extrapolated
/// from the steps `h` and `h/2`, and again from `h/2` and `h/4`: error `O(h⁴)` from
/// truncation and about `ε |f| / h` from rounding. Returns the finer estimate and its
/// distance from the coarser one, which bounds the error of the finer estimate (it is
/// about 15 times that error when truncation dominates).
fn first_difference(f: &dyn Fn(f64) -> Option<f64>, t: f64, h: f64) -> Option<(f64, f64)> {
    let d = |h: f64| Some((f(t + h)? - f(t - h)?) / (2.0 * h));
    let (d1, d2, d4) = (d(h)?, d(h / 2.0)?, d(h / 4.0)?);
    let (coarse, fine) = ((4.0 * d2 - d1) / 3.0, (4.0 * d4 - d2) / 3.0);
    Some((fine, (coarse - fine).abs()))
}

/// The second derivative likewise, from `(f(t+h) - 2 f(t) + f(t-h)) / h²`: error `O(h⁴)`
/// from truncation and about `ε |f| / h²` from rounding.
fn second_difference(f: &dyn Fn(f64) -> Option<f64>, t: f64, h: f64) -> Option<f64> {
    let d = |h: f64| Some((f(t + h)? - 2.0 * f(t)? + f(t - h)?) / (h * h));
    let (coarse, fine) = (d(h)?, d(h / 2.0)?);
    Some((4.0 * fine - coarse) / 3.0)
}

/// Along a concrete smooth trajectory, the symbolic first and second time derivatives of
/// chosen expressions (functions, roots, quotients by sums, products) agree with finite
/// differences of the expression's own values at each of 20 times: to `1e-7` relative for
/// the first derivative (steps `1e-3` to `2.5e-4`, rounding about `1e-12`) and `1e-6` for
/// the second (steps `1e-2` and `5e-3`, truncation about `1e-8`).
#[test]
fn derivatives_agree_with_finite_differences_along_a_trajectory() {
    let moving = [
        (
            "w_x",
            Motion {
                sign: 1.0,
                frequency: 1.3,
                phase: 0.2,
            },
        ),
        (
            "theta",
            Motion {
                sign: 1.0,
                frequency: 0.7,
                phase: 1.1,
            },
        ),
        (
            "v_y",
            Motion {
                sign: -1.0,
                frequency: 1.9,
                phase: 2.5,
            },
        ),
    ];
    let constant = [("I_x", 2.5), ("m", 3.0), ("L", 0.8), ("beta", 0.4)];
    let path = Trajectory {
        moving: &moving,
        constant: &constant,
    };
    let expressions = [
        "I_x w_x cos(theta)",
        "sqrt(w_x^2 + v_y^2)",
        "tan(theta)/(L + w_x^2)",
        "abs(v_y) sin(theta)^3",
        "1/2 m v_y^2 + 1/2 I_x w_x^2",
        "w_x^(3/2) cos(beta + theta/2) - 0.1 m L v_y^(-2)",
        "sin(w_x theta)/(2 + cos(v_y))",
    ];
    for input in expressions {
        let e = parsed(input);
        let first = e.d_dt().unwrap();
        let second = first.d_dt().unwrap();
        let f = |t: f64| Some(path.eval(&e, t));
        for k in 0..20 {
            let t = 0.37 * k as f64;
            let (numeric, _) = first_difference(&f, t, 1e-3).unwrap();
            let symbolic = path.eval(&first, t);
            assert!(
                (symbolic - numeric).abs() <= 1e-7 * (1.0 + numeric.abs()),
                "d/dt {input} at t = {t}: {symbolic} symbolically, {numeric} numerically"
            );
            let numeric = second_difference(&f, t, 1e-2).unwrap();
            let symbolic = path.eval(&second, t);
            assert!(
                (symbolic - numeric).abs() <= 1e-6 * (1.0 + numeric.abs()),
                "d²/dt² {input} at t = {t}: {symbolic} symbolically, {numeric} numerically"
            );
        }
    }
}

/// Symbols of the random expressions: three that move, three constants.
const NAMES: [&str; 6] = ["w_x", "theta", "v_y", "I_x", "m", "L"];

/// Random expressions the derivative is checked on.
const CASES: u32 = 20_000;

proptest! {
    #![proptest_config(crate::common::expression_tree::config(CASES))]

    /// For random expressions, the symbolic time derivative agrees with a Richardson
    /// extrapolated central difference (steps `1e-3` to `2.5e-4`) of the expression's reference
    /// value, computed without the algebra, along random smooth motions of `w_x`, `theta`
    /// and `v_y`. Tolerance `1e-6` relative to the derivative and the value (rounding in
    /// the differences is about `1e-12` of the value). Times where the difference has not
    /// converged (its two extrapolations differ by more than `1e-7` relative: a pole, a
    /// kink of `abs` or fast oscillation nearby), where the reference has no value, or
    /// where it has no derivative (`abs` of zero, a root of zero) are skipped.
    #[test]
    fn derivative_agrees_with_finite_differences(
        t in tree(NAMES.len()),
        motions in [motion(), motion(), motion()],
        constants in point(3),
        at in 0.0f64..10.0,
    ) {
        let moving: Vec<(&str, Motion)> = NAMES[..3].iter().copied().zip(motions.clone()).collect();
        let constant: Vec<(&str, f64)> = NAMES[3..].iter().copied().zip(constants.clone()).collect();
        let path = Trajectory { moving: &moving, constant: &constant };
        let state = |time: f64| -> Vec<f64> {
            motions.iter().map(|m| m.at(time)).chain(constants.iter().copied()).collect()
        };
        let reference = |time: f64| t.value(&state(time));
        let Some(value) = reference(at) else {
            return Err(TestCaseError::reject("no reference value"));
        };
        if t.near_kink(&state(at)) {
            return Err(TestCaseError::reject("a kink or a root of zero"));
        }
        let Some((numeric, spread)) = first_difference(&reference, at, 1e-3) else {
            return Err(TestCaseError::reject("no reference value nearby"));
        };
        if spread > 1e-7 * (1.0 + numeric.abs()) {
            return Err(TestCaseError::reject("the difference has not converged"));
        }
        let e = t.build(&NAMES);
        prop_assert!(e.is_some(), "divides by an exact zero where the reference is {}", value);
        let e = e.unwrap();
        let derivative = e.d_dt().unwrap();
        let symbolic = derivative.eval(&|s| path.value(s, at));
        prop_assert!(symbolic.is_ok(), "d/dt {} = {} has no value: {:?}", e, derivative, symbolic);
        let symbolic = symbolic.unwrap();
        prop_assert!(
            (symbolic - numeric).abs() <= 1e-6 * (1.0 + numeric.abs() + value.abs()),
            "d/dt {} = {}: {} symbolically, {} numerically", e, derivative, symbolic, numeric
        );
    }
}
