//! `collect`: write an expression as a sum of (monomial in chosen variables) × (coefficient
//! free of them), after expanding.
//!
//! `I_x w_x^2 + I_y w_x^2 - 2 I_xy w_x w_y` collected by the ω's is
//! `(I_x + I_y) w_x^2 + (-2 I_xy) w_x w_y`.

use super::error::AlgebraError;
use super::expr::Expr;
use super::symbol::Symbol;
use std::collections::HashMap;

/// One group of a collected expression: `coefficient · monomial`.
#[derive(Debug, Clone, PartialEq)]
pub struct Collected {
    /// A product of powers of the chosen variables (`1` for the part free of them).
    pub monomial: Expr,
    /// The rest, free of the chosen variables.
    pub coefficient: Expr,
}

impl Expr {
    /// Collects by the variables for which `is_variable` is true; groups come in the
    /// canonical order of their monomials and none has a zero coefficient.
    pub fn collect_by(
        &self,
        is_variable: &dyn Fn(Symbol) -> bool,
    ) -> Result<Vec<Collected>, AlgebraError> {
        let expanded = self.expand()?;
        let mut parts: Vec<(Expr, Vec<Expr>)> = Vec::new();
        let mut index: HashMap<Expr, usize> = HashMap::new();
        for term in expanded.terms() {
            let (variable, rest): (Vec<Expr>, Vec<Expr>) = term
                .factors()
                .iter()
                .cloned()
                .partition(|f| f.base_and_exponent().0.as_symbol().is_some_and(is_variable));
            let monomial = Expr::mul_all(variable);
            let coefficient = Expr::mul_all(rest);
            match index.get(&monomial) {
                Some(&at) => parts[at].1.push(coefficient),
                None => {
                    index.insert(monomial.clone(), parts.len());
                    parts.push((monomial, vec![coefficient]));
                }
            }
        }
        let mut groups: Vec<Collected> = parts
            .into_iter()
            .map(|(monomial, coefficients)| Collected {
                monomial,
                coefficient: Expr::add_all(coefficients),
            })
            .collect();
        groups.retain(|g| !g.coefficient.is_zero());
        groups.sort_by(|a, b| a.monomial.cmp(&b.monomial));
        Ok(groups)
    }

    /// Collects by the given variables.
    pub fn collect(&self, variables: &[Symbol]) -> Result<Vec<Collected>, AlgebraError> {
        self.collect_by(&|s| variables.contains(&s))
    }
}
