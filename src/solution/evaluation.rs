//! A result's number from the givens' values, rounded once, never floating-point noise.
//!
//! Each given is put in exactly ([`Scene::exact_given`]: `0.1 m` is 1/10, `30 deg` is π/6),
//! so the algebra folds what the values make of the result: a rational is exact
//! (`vbar_y = w L cos θ` at θ = 90° is 0, not 6e-17), the sines and cosines of multiples of
//! 15° are exact (`algebra/exact_angle.rs`). What is left (π, a root, the sine of 20°) is
//! evaluated in double-double with a bound on its rounding error
//! ([`crate::numeric::rounding_error`]); a value within its bound of zero is zero (the ~32
//! digits cannot tell it from 0, and a double would print their noise). The one rounding is
//! to the `f64` returned; the page rounds that to four figures.
//!
//! ```text
//! e(givens) = q ∈ Q           →  q rounded to f64
//! e(givens) = v̂ ± ε (DD)      →  0 when |v̂| ≤ ε, else v̂ rounded to f64
//! ```

use crate::algebra::{AlgebraError, Expr, Symbol};
use crate::numeric::rounding_error::bounded;
use crate::scene::Scene;

/// The value of `e` when every symbol in it has a given value and the value is finite;
/// `None` otherwise, and the answer stays symbolic. (An answer asked for `in UNIT` must
/// have a value: [`super::numbers::check_numeric_requests`] refuses it when it has none.)
pub fn value(scene: &Scene, e: &Expr) -> Option<f64> {
    if e.symbols()
        .into_iter()
        .any(|s| !s.is_pi() && scene.value(s).is_none())
    {
        return None;
    }
    let exact = |s: Symbol| {
        scene
            .exact_given(s)
            .or_else(|| scene.exact_value(s).map(Expr::num))
    };
    let substituted = match e.subs(&exact) {
        Ok(x) => x,
        Err(AlgebraError::DivisionByZero) => return None,
        // Too many digits to fold exactly: the values as the doubles they are.
        Err(_) => return e.eval(&|s: Symbol| scene.value(s)).ok(),
    };
    let x = match substituted.as_num() {
        Some(q) => q.to_f64(),
        None => {
            let b = bounded(&substituted, &|_| None)?;
            if b.value.abs().to_f64() <= b.error {
                0.0
            } else {
                b.value.to_f64()
            }
        }
    };
    x.is_finite().then_some(x)
}

#[cfg(test)]
mod tests {
    use super::value;
    use crate::parse::parse_expression;
    use crate::scene::parse_scene;

    fn at(expression: &str) -> Option<f64> {
        let scene = parse_scene(
            "t.scene",
            "given L = 0.3 m\ngiven theta = 90 deg\ngiven beta = 20 deg\ngiven w = 7 rad/s\n\
             given M = 1 kg\nbody sphere(L) mass M\nfind T",
        )
        .unwrap();
        value(&scene, &parse_expression("t", expression).unwrap())
    }

    #[test]
    fn exact_where_the_values_fold() {
        assert_eq!(at("w*L*cos(theta)"), Some(0.0));
        assert_eq!(at("L*sin(theta) - 3/10"), Some(0.0));
        assert_eq!(at("0.1 + 0.2 - L"), Some(0.0));
        assert_eq!(at("L/3"), Some(0.1));
    }

    #[test]
    fn noise_within_the_rounding_bound_is_zero() {
        assert_eq!(at("sin(beta)^2 + cos(beta)^2 - 1"), Some(0.0));
        assert_eq!(at("L*sin(beta) - L*cos(pi/2 - beta)"), Some(0.0));
        let v = at("w*sin(beta)").unwrap();
        assert!((v / (7.0 * 20f64.to_radians().sin()) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn no_value_or_no_finite_value() {
        assert_eq!(at("L/(theta - pi/2)"), None);
        assert_eq!(at("L*x"), None);
    }
}
