//! A sine over a cosine of one angle written as its tangent, in each product of a sum:
//!
//! ```text
//! sinᵖx · cos⁻ᵠx = tanᵐx · sinᵖ⁻ᵐx · cos⁻⁽ᵠ⁻ᵐ⁾x,   m = min(p, q)   (whole p, q > 0)
//! ```
//!
//! so that an angle from its tangent reads as the textbook writes it, arctan(½ tan γ), not
//! arctan(sin γ / (2 cos γ)).

use super::expr::{Expr, View};
use super::function::Func;

impl Expr {
    /// `self` with each product's sines over cosines of one angle as tangents (see the
    /// module documentation); arguments of functions are left as they are.
    pub fn tangents_gathered(&self) -> Expr {
        match self.view() {
            View::Add(terms) => Expr::add_all(terms.iter().map(Expr::tangents_gathered)),
            _ => in_product(self),
        }
    }
}

/// The whole power of `f(x)` in a factor: `(x, n)` for `f(x)ⁿ`.
fn power_of(factor: &Expr, f: Func) -> Option<(Expr, i64)> {
    let (base, exponent) = factor.base_and_exponent();
    let n = exponent.as_num()?.to_i64()?;
    match base.view() {
        View::Func(g, x) if g == f => Some((x.clone(), n)),
        _ => None,
    }
}

fn in_product(product: &Expr) -> Expr {
    // A denominator kept as one power of a product, (6 r² cos γ)⁻¹, opened into its factors.
    let mut factors: Vec<Expr> = Vec::new();
    for factor in product.factors() {
        let (base, exponent) = factor.base_and_exponent();
        match (base.view(), exponent.as_num().and_then(|q| q.to_i64())) {
            (View::Mul(inner), Some(n)) => factors.extend(inner.iter().map(|f| f.powi(n))),
            _ => factors.push(factor.clone()),
        }
    }
    let mut tangents = Vec::new();
    for k in 0..factors.len() {
        let Some((angle, p)) = power_of(&factors[k], Func::Sin).filter(|(_, p)| *p > 0) else {
            continue;
        };
        let cosine = factors
            .iter()
            .position(|f| power_of(f, Func::Cos).is_some_and(|(x, q)| x == angle && q < 0));
        let Some(j) = cosine else { continue };
        let q = -power_of(&factors[j], Func::Cos).map_or(0, |(_, q)| q);
        let m = p.min(q);
        factors[k] = Func::Sin.apply(angle.clone()).powi(p - m);
        factors[j] = Func::Cos.apply(angle.clone()).powi(m - q);
        tangents.push(Func::Tan.apply(angle).powi(m));
    }
    match tangents.is_empty() {
        true => product.clone(),
        false => Expr::mul_all(factors.into_iter().chain(tangents)),
    }
}

#[cfg(test)]
mod tests {
    use crate::parse::parse_expression;

    fn gathered(text: &str) -> String {
        parse_expression("test", text)
            .expect("parses")
            .tangents_gathered()
            .to_string()
    }

    #[test]
    fn sines_over_cosines_become_tangents() {
        assert_eq!(gathered("sin(g)/(2*cos(g))"), "1/2*tan(g)");
        assert_eq!(gathered("sin(g)^3/cos(g)"), "sin(g)^2*tan(g)");
        assert_eq!(gathered("sin(g)/cos(g)^2"), "tan(g)/cos(g)");
        assert_eq!(
            gathered("a*sin(g)/cos(h) + sin(h)/cos(h)"),
            "a*sin(g)/cos(h) + tan(h)"
        );
        assert_eq!(gathered("sin(g)*cos(g)"), "sin(g)*cos(g)");
        assert_eq!(
            gathered("(h^2 + 3*r^2)*sin(g)/(6*r^2*cos(g))"),
            "(h^2 + 3*r^2)*tan(g)/(6*r^2)"
        );
    }
}
