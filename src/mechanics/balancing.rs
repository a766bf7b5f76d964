//! Dynamic balancing (§18.8): add two masses in chosen planes `z = z_1` and `z = z_2` so
//! that the mass centre lies on the axis and `I_xz = I_yz = 0`; then no bearing reaction
//! depends on ω. With the body's first moments `S_x = m x̄`, `S_y = m ȳ` and products
//! `I_xz`, `I_yz` about the bearing origin, the corrections `(m_k x_k, m_k y_k)` solve
//!
//! ```text
//! m_1 x_1 + m_2 x_2         = -S_x        m_1 y_1 + m_2 y_2         = -S_y
//! m_1 x_1 z_1 + m_2 x_2 z_2 = -I_xz       m_1 y_1 z_1 + m_2 y_2 z_2 = -I_yz
//! ```
//!
//! so `m_2 x_2 = (S_x z_1 - I_xz)/(z_2 - z_1)`, `m_1 x_1 = -S_x - m_2 x_2`, and likewise in y.

use super::derivation::{Derivation, Relation, Step};
use crate::algebra::{AlgebraError, Axis, Expr};

/// The body's unbalance: first moments and products of inertia about the bearing origin.
pub struct Unbalance<'a> {
    pub first_moment: (&'a Expr, &'a Expr),
    /// `(I_xz, I_yz)`.
    pub products: (&'a Expr, &'a Expr),
}

/// The corrective mass moments `m_k x_k`, `m_k y_k` in the planes `z_1`, `z_2`.
pub fn dynamic_balancing(
    body: &Unbalance,
    z_1: &Expr,
    z_2: &Expr,
) -> Result<Derivation, AlgebraError> {
    let gap = z_2 - z_1;
    let solve = |s: &Expr, p: &Expr| -> Result<(Expr, Expr), AlgebraError> {
        let second = (s * z_1 - p).checked_div(&gap)?;
        let first = -s - &second;
        Ok((first.expand()?, second.expand()?))
    };
    let (x1, x2) = solve(body.first_moment.0, body.products.0)?;
    let (y1, y2) = solve(body.first_moment.1, body.products.1)?;
    let s = Expr::symbol;
    Ok(Derivation {
        name: "balancing".into(),
        title: "dynamic balancing with two corrective masses".into(),
        steps: vec![Step {
            table: None,
            title: "static balance (mass centre on the axis) and $I_{xz} = I_{yz} = 0$ after correction"
                .into(),
            relations: vec![
                Relation::new(s("m_1") * s("x_1"), x1, Axis::X),
                Relation::new(s("m_2") * s("x_2"), x2, Axis::X),
                Relation::new(s("m_1") * s("y_1"), y1, Axis::Y),
                Relation::new(s("m_2") * s("y_2"), y2, Axis::Y),
            ],
        }],
    })
}
