//! `simplify_trig`: `sin²θ + cos²θ = 1` in any multiple and combination, and the double
//! angle where it is shorter.
//!
//! Reduction modulo `s² + c² − 1` (`s = sin θ`, `c = cos θ`) for each angle θ: a sum is
//! read as a polynomial in `s` and `c` and written in its two normal forms, all in `s`
//! (`c² → 1 − s²`) and all in `c` (`s² → 1 − c²`); the shortest of the sum and its forms by
//! [`Expr::operation_count`] is kept (the sum itself on a tie). So `a sin²θ + a cos²θ = a`,
//! `1 − sin²θ = cos²θ`, `sin²θ cos²φ + cos²θ cos²φ = cos²φ`, and `sin²θ + cos²φ` stays.
//! A product of sums holding `sin` or `cos` is also tried multiplied out
//! (`(1 − sin θ)(1 + sin θ) = cos²θ`), unless `expand` refuses it as too large: that form
//! is only tried, and the product itself stays a valid answer.
//!
//! Two passes, each bottom-up through every argument, power, factor and term (a quotient's
//! numerator and denominator apart): the Pythagorean forms first over the whole
//! expression, then the double-angle forms (`double_angle.rs`) over that result, so that
//! `sin θ cos θ` is not made `sin 2θ / 2` before a sum could have cancelled it. The
//! result is never longer than the input; it is refused like an expansion when it would
//! have more than [`MAX_EXPANDED_TERMS`](super::MAX_EXPANDED_TERMS) terms at one step or
//! [`MAX_EXPANDED_NODES`] nodes.

use super::double_angle::double_angle_forms;
use super::error::{AlgebraError, MAX_EXPANDED_NODES};
use super::expr::{Expr, View};
use super::function::Func;
use super::rational::Q;
use super::square_rewrite::SquareRule;
use super::work;
use std::collections::HashSet;

impl Expr {
    /// The expression with `sin²θ + cos²θ = 1` applied for each angle, and the double
    /// angle where it shortens it (see the module documentation); never longer than `self`
    /// by [`Expr::operation_count`].
    ///
    /// ```
    /// use kinetics::algebra::{Expr, Func};
    /// let (a, x) = (Expr::symbol("a"), Expr::symbol("x"));
    /// let e = &a * Func::Sin.apply(x.clone()).powi(2) + &a * Func::Cos.apply(x).powi(2);
    /// assert_eq!(e.simplify_trig().unwrap(), a);
    /// ```
    pub fn simplify_trig(&self) -> Result<Expr, AlgebraError> {
        // Without a sine, cosine or tangent each pass rebuilds the expression as it is.
        if !self.has_function_where(&|f| matches!(f, Func::Sin | Func::Cos | Func::Tan)) {
            return Ok(self.clone());
        }
        let pythagorean = bottom_up(self, &Pass::Pythagorean)?;
        let result = bottom_up(&pythagorean, &Pass::DoubleAngle)?;
        if !result.has_at_most_size(MAX_EXPANDED_NODES) {
            return Err(AlgebraError::ExpansionTooLong(MAX_EXPANDED_NODES));
        }
        Ok(shortest(vec![self.clone(), result]))
    }
}

/// Which forms a pass tries at each node.
enum Pass {
    Pythagorean,
    DoubleAngle,
}

/// The node with its operands simplified first, then the shortest of it and its forms.
fn bottom_up(e: &Expr, pass: &Pass) -> Result<Expr, AlgebraError> {
    work::check()?;
    let each = |xs: &[Expr]| -> Result<Vec<Expr>, AlgebraError> {
        xs.iter().map(|x| bottom_up(x, pass)).collect()
    };
    let rebuilt = match e.view() {
        View::Num(_) | View::Sym(_) => return Ok(e.clone()),
        View::Add(terms) => Expr::add_all(each(terms)?),
        View::Mul(factors) => Expr::mul_all(each(factors)?),
        View::Pow(base, exponent) => {
            bottom_up(base, pass)?.checked_pow(&bottom_up(exponent, pass)?)?
        }
        View::Func(f, argument) => f.apply(bottom_up(argument, pass)?),
    };
    let mut candidates = vec![e.clone(), each_angle(rebuilt.clone(), pass)?];
    if matches!(pass, Pass::Pythagorean) && is_product_of_trigonometric_sums(&rebuilt) {
        match rebuilt.expand() {
            Ok(expanded) => candidates.push(each_angle(expanded, pass)?),
            Err(AlgebraError::TooLarge { .. })
            | Err(AlgebraError::ExpansionTooLong(_))
            | Err(AlgebraError::NumberTooLarge { .. }) => {}
            Err(other) => return Err(other),
        }
    }
    Ok(shortest(candidates))
}

/// `e` through the shortest form for each of its angles in turn.
fn each_angle(e: Expr, pass: &Pass) -> Result<Expr, AlgebraError> {
    let mut best = e;
    for angle in rewritable_angles(&best) {
        work::check()?;
        best = forms_for_angle(&best, &angle, pass)?;
    }
    Ok(best)
}

/// The shortest of `e` and its forms for one angle.
fn forms_for_angle(e: &Expr, angle: &Expr, pass: &Pass) -> Result<Expr, AlgebraError> {
    let (sine, cosine) = (
        Func::Sin.apply(angle.clone()),
        Func::Cos.apply(angle.clone()),
    );
    let in_sines = SquareRule {
        base: &cosine,
        p: Q::ONE,
        q: Q::MINUS_ONE,
        g: sine.powi(2),
    }
    .rewrite(e)?;
    let in_cosines = SquareRule {
        base: &sine,
        p: Q::ONE,
        q: Q::MINUS_ONE,
        g: cosine.powi(2),
    }
    .rewrite(e)?;
    let mut candidates = vec![e.clone()];
    match pass {
        Pass::Pythagorean => candidates.extend([in_sines, in_cosines]),
        Pass::DoubleAngle => {
            candidates.extend(double_angle_forms(e, &in_sines, &in_cosines, angle)?)
        }
    }
    Ok(shortest(candidates))
}

/// The angles θ of the `sin θ` and `cos θ` (to positive integer powers) among the factors
/// of the terms of `e`, each once, in the order met, that a rewrite can change: those whose
/// sine and cosine reach the second degree together in some term (a term of degree one in
/// them has no square to replace and no product to double), and the doubles 2θ of those
/// (a double angle rewrite of θ makes `sin²2θ` of `4 sin²θ cos²θ`). So a sum of `sin θᵢ` of
/// many angles is passed in one reading, not rewritten once per angle.
fn rewritable_angles(e: &Expr) -> Vec<Expr> {
    let mut met: Vec<&Expr> = Vec::new();
    let mut seen: HashSet<&Expr> = HashSet::new();
    let mut rewritable: HashSet<Expr> = HashSet::new();
    for term in e.terms() {
        let mut degrees: Vec<(&Expr, u64)> = Vec::new();
        for (angle, degree) in term.factors().iter().filter_map(trigonometric_power) {
            if seen.insert(angle) {
                met.push(angle);
            }
            match degrees.iter_mut().find(|(a, _)| *a == angle) {
                Some((_, total)) => *total = total.saturating_add(degree),
                None => degrees.push((angle, degree)),
            }
        }
        let squared = degrees.into_iter().filter(|(_, degree)| *degree >= 2);
        rewritable.extend(squared.map(|(angle, _)| angle.clone()));
    }
    // The doubles of rewritable angles, and their doubles in turn.
    let half = Expr::rational(1, 2);
    loop {
        let doubles: Vec<Expr> = met
            .iter()
            .filter(|a| !rewritable.contains(**a) && rewritable.contains(&(&half * **a)))
            .map(|a| (*a).clone())
            .collect();
        if doubles.is_empty() {
            break;
        }
        rewritable.extend(doubles);
    }
    met.into_iter()
        .filter(|a| rewritable.contains(*a))
        .cloned()
        .collect()
}

/// The angle and degree of a factor `sin θ` or `cos θ` to a positive integer power.
fn trigonometric_power(factor: &Expr) -> Option<(&Expr, u64)> {
    let (base, exponent) = match factor.view() {
        View::Pow(base, exponent) => (base, exponent.as_num()?),
        _ => (factor, &Q::ONE),
    };
    let degree = exponent.to_i64()?;
    match base.view() {
        View::Func(Func::Sin | Func::Cos, angle) if degree > 0 => Some((angle, degree as u64)),
        _ => None,
    }
}

/// Whether `e` is a product or power with a factor that is a sum holding `sin` or `cos`.
fn is_product_of_trigonometric_sums(e: &Expr) -> bool {
    let sum_with_trig = |f: &Expr| {
        let (base, exponent) = f.base_and_exponent();
        matches!(base.view(), View::Add(_))
            && exponent.as_num().is_some_and(|n| !n.is_negative())
            && base
                .terms()
                .iter()
                .flat_map(Expr::factors)
                .any(|factor| trigonometric_power(factor).is_some())
    };
    matches!(e.view(), View::Mul(_) | View::Pow(..)) && e.factors().iter().any(sum_with_trig)
}

/// The form with the fewest operations, the first on a tie.
fn shortest(candidates: Vec<Expr>) -> Expr {
    candidates
        .into_iter()
        .map(|e| (e.operation_count(), e))
        .min_by_key(|(count, _)| *count)
        .map(|(_, e)| e)
        .expect("at least one form")
}
