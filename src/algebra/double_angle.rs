//! The double-angle forms of a sum, for one angle θ:
//!
//! ```text
//! 2 sin θ cos θ = sin 2θ          (sinᵃθ cosᵇθ = sinᵃ⁻ᵐθ cosᵇ⁻ᵐθ (sin 2θ / 2)ᵐ, m = min(a, b))
//! sin²θ = (1 − cos 2θ)/2          cos²θ = (1 + cos 2θ)/2
//! ```
//!
//! the last two applied to the Pythagorean normal forms (all in `sin θ`, all in `cos θ`),
//! where they turn `cos²θ − sin²θ = 1 − 2 sin²θ` into `cos 2θ`. `simplify_trig` keeps one of
//! these only when it is shorter.

use super::error::AlgebraError;
use super::expr::Expr;
use super::function::Func;
use super::rational::Q;
use super::square_rewrite::SquareRule;

/// The double-angle forms of `sum`, given its forms all in `sin θ` and all in `cos θ`.
pub(super) fn double_angle_forms(
    sum: &Expr,
    in_sines: &Expr,
    in_cosines: &Expr,
    angle: &Expr,
) -> Result<Vec<Expr>, AlgebraError> {
    let (sine, cosine) = (
        Func::Sin.apply(angle.clone()),
        Func::Cos.apply(angle.clone()),
    );
    let double = Expr::int(2) * angle;
    let cosine_of_double = Func::Cos.apply(double.clone());
    let half = Q::new(1, 2).expect("2 is not zero");
    let from_sine = SquareRule {
        base: &sine,
        p: half.clone(),
        q: -&half,
        g: cosine_of_double.clone(),
    };
    let from_cosine = SquareRule {
        base: &cosine,
        p: half.clone(),
        q: half,
        g: cosine_of_double,
    };
    let products = |e: &Expr| sine_of_double(e, &sine, &cosine, &double);
    Ok(vec![
        products(sum)?,
        from_sine.rewrite(in_sines)?,
        from_cosine.rewrite(in_cosines)?,
        products(in_sines)?,
        products(in_cosines)?,
    ])
}

/// Every term's `sinᵃθ cosᵇθ` (`a, b ≥ 1`) as `sinᵃ⁻ᵐθ cosᵇ⁻ᵐθ (sin 2θ)ᵐ / 2ᵐ`.
fn sine_of_double(
    sum: &Expr,
    sine: &Expr,
    cosine: &Expr,
    double: &Expr,
) -> Result<Expr, AlgebraError> {
    let sine_of_double = Func::Sin.apply(double.clone());
    let mut out = Vec::with_capacity(sum.terms().len());
    for term in sum.terms() {
        let (a, b) = (power_in(term, sine), power_in(term, cosine));
        let m = a.min(b);
        if m == 0 {
            out.push(term.clone());
            continue;
        }
        Q::check_bits("the power of 2 of a double angle", m as u64)?;
        let scale = Q::new(1, 2)
            .and_then(|half| half.checked_pow(m))
            .expect("a power of 1/2");
        let rest = term
            .factors()
            .iter()
            .filter(|f| f.base() != sine && f.base() != cosine)
            .cloned();
        out.push(Expr::mul_all(rest.chain([
            sine.powi(a - m),
            cosine.powi(b - m),
            sine_of_double.powi(m),
            Expr::num(scale),
        ])));
    }
    Ok(Expr::add_all(out))
}

/// The exponent of `base` among the term's factors when it is a positive integer, else 0.
pub(super) fn power_in(term: &Expr, base: &Expr) -> i64 {
    term.factors()
        .iter()
        .find(|f| f.base() == base)
        .and_then(|f| f.base_and_exponent().1.as_num().and_then(Q::to_i64))
        .filter(|&n| n > 0)
        .unwrap_or(0)
}
