//! A vector with the factor common to its components in front, as the textbook writes
//! `ω = (6FΔt/mab)(a i − b j)` and `H_G = ½FΔt(b i − a j)`:
//!
//! `Σ c_k u_k = (g/D) Σ (N_k/g) u_k`
//!
//! where `D` is the components' common denominator (`together`), `N_k = c_k D` their
//! numerators and `g` the content and common powers of the numerators (`factor_terms`).
//! The vector is grouped when at least two components are not zero, the factor is not
//! ±1, and the grouped form has fewer operations than the components apart
//! ([`Expr::operation_count`]); else it is written component by component.

use super::{render, vector, Notation};
use crate::algebra::vector::{components, unit_vectors};
use crate::algebra::{Axis, Expr, Vector, View};

/// A vector as `factor · (inner)`.
pub struct GroupedVector {
    pub factor: Expr,
    pub inner: Vector,
}

/// The vector's common factor and what it multiplies, when grouping reads shorter.
pub fn grouped(v: &Vector) -> Option<GroupedVector> {
    if v.iter().filter(|c| !c.is_zero()).count() < 2 {
        return None;
    }
    let sum = Expr::add_all(v.iter().zip(unit_vectors()).map(|(c, u)| c * &u));
    let (numerator, denominator) = sum.together_parts().ok()?;
    let factored = numerator.factor_terms().ok()?;
    // The factored numerator is g times the one factor that holds the unit vectors.
    let (inner, content): (Vec<Expr>, Vec<Expr>) = match factored.view() {
        View::Mul(factors) => factors
            .iter()
            .cloned()
            .partition(crate::algebra::vector::has_unit_vectors),
        _ => return None,
    };
    let [inner] = <[Expr; 1]>::try_from(inner).ok()?;
    let factor = &Expr::mul_all(content) / &denominator;
    if factor.is_one() || (-&factor).is_one() {
        return None;
    }
    // Each component with its own common factor out where that is shorter:
    // `(m_1 + 2 m_2) a i`, not `(m_1 a + 2 m_2 a) i`.
    let inner = components(&inner).ok()?.map(|c| match c.factor_terms() {
        Ok(f) if f.operation_count() < c.operation_count() => f,
        _ => c,
    });
    let apart: usize = v.iter().map(Expr::operation_count).sum();
    let together =
        factor.operation_count() + 1 + inner.iter().map(Expr::operation_count).sum::<usize>();
    (together < apart).then_some(GroupedVector { factor, inner })
}

impl GroupedVector {
    /// The width in ems of the grouped vector on one line.
    pub fn width_em(&self) -> f64 {
        let parentheses = if self.factor_is_sum() { 1.0 } else { 0.0 };
        super::width_em(&self.factor, Axis::X)
            + parentheses
            + 1.0
            + super::line_break::vector_width_em(&self.inner)
    }

    /// A factor of several terms stands in parentheses: `(Iω_z − I′φ̇ cos θ)(φ̇ sin θ i − θ̇ j)`.
    fn factor_is_sum(&self) -> bool {
        matches!(self.factor.view(), View::Add(_))
    }

    /// `factor (inner)` in `notation`: `6*F*Dt/(m*a*b)*(a*i - b*j)` in text (which reads
    /// back as the same vector), `\frac{6 F \Delta t}{m a b}\,(a \mathbf{i} - b
    /// \mathbf{j})` in LaTeX; brackets where the components hold parentheses, and they grow
    /// around fractions.
    pub fn render(&self, notation: Notation) -> String {
        let factor = render(&self.factor, notation, Axis::X);
        let factor = match (self.factor_is_sum(), notation) {
            (false, _) => factor,
            (true, Notation::Text) => format!("({factor})"),
            (true, Notation::Latex) if factor.contains(r"\frac") => {
                format!(r"\left({factor}\right)")
            }
            (true, Notation::Latex) => format!("({factor})"),
            (true, Notation::MathMl) => format!("<mrow><mo>(</mo>{factor}<mo>)</mo></mrow>"),
        };
        let inner = vector(&self.inner, notation);
        let nested = match notation {
            Notation::MathMl => inner.contains("<mo>(</mo>") || inner.contains("<mo stretchy"),
            _ => inner.contains('('),
        };
        let (open, close) = if nested { ("[", "]") } else { ("(", ")") };
        match notation {
            Notation::Text => format!("{factor}*({inner})"),
            Notation::Latex if inner.contains(r"\frac") => {
                format!(r"{factor}\,\left{open}{inner}\right{close}")
            }
            Notation::Latex => format!(r"{factor}\,{open}{inner}{close}"),
            Notation::MathMl => format!(
                "<mrow>{factor}<mo>\u{2062}</mo><mrow><mo>{open}</mo>{inner}<mo>{close}</mo></mrow></mrow>"
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::grouped;
    use crate::algebra::Vector;
    use crate::parse::parse_expression;
    use crate::print::Notation;

    fn vector(components: [&str; 3]) -> Vector {
        Vector::from_iterator(components.map(|c| parse_expression("", c).unwrap()))
    }

    /// `factor · inner_k − v_k` over one denominator is zero for every component.
    fn regrouped_is_the_vector(v: &Vector) {
        let g = grouped(v).expect("grouped");
        for (inner, whole) in g.inner.iter().zip(v.iter()) {
            let difference = &(&g.factor * inner) - whole;
            assert!(difference.cancel().unwrap().is_zero(), "{difference}");
        }
    }

    #[test]
    fn the_angular_velocity_of_sample_problem_18_1() {
        let omega = vector(["6*F*Dt/(m*b)", "-6*F*Dt/(m*a)", "0"]);
        regrouped_is_the_vector(&omega);
        let g = grouped(&omega).unwrap();
        assert_eq!(g.render(Notation::Text), "6*F*Dt/(m*a*b)*(a*i - b*j)");
        let h = vector(["1/2*F*Dt*b", "-1/2*F*Dt*a", "0"]);
        regrouped_is_the_vector(&h);
        assert_eq!(
            grouped(&h).unwrap().render(Notation::Text),
            "1/2*F*Dt*(b*i - a*j)"
        );
    }

    /// A factor that is a sum is set in parentheses, so the product reads as one: the
    /// transport term of a top, `(I ω_z − I′ φ̇ cos θ)(φ̇ sin θ i − θ̇ j)`.
    #[test]
    fn a_factor_of_several_terms_is_in_parentheses() {
        let transport = vector([
            "I*omega_z*phidot*sin(theta) - I'*phidot^2*sin(theta)*cos(theta)",
            "-I*omega_z*thetadot + I'*phidot*thetadot*cos(theta)",
            "0",
        ]);
        regrouped_is_the_vector(&transport);
        let g = grouped(&transport).expect("grouped");
        let text = g.render(Notation::Text);
        assert!(text.starts_with('(') && text.contains(")*("), "{text}");
        assert!(g.render(Notation::Latex).starts_with('('));
        // Read back, the text is the vector.
        let read = parse_expression("", &text).unwrap();
        let whole = crate::algebra::vector::components(&read).unwrap();
        for (a, b) in whole.iter().zip(transport.iter()) {
            assert!((a - b).cancel().unwrap().is_zero(), "{a} vs {b}");
        }
    }

    #[test]
    fn a_vector_is_grouped_only_when_that_is_shorter() {
        // One component: nothing to group.
        assert!(grouped(&vector(["6*F*Dt/(m*b)", "0", "0"])).is_none());
        // No common factor, or one that leaves it as long.
        assert!(grouped(&vector(["a", "b", "0"])).is_none());
        assert!(grouped(&vector(["w_1", "-r*w_1/L", "0"])).is_none());
    }
}
