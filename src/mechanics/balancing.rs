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
//! About another axis the letters turn cyclically (a shaft along x: planes `x = x_1`, `x_2`,
//! corrections `m_k y_k`, `m_k z_k`, products `I_xy`, `I_xz`).

use super::derivation::{Derivation, Relation, Step};
use crate::algebra::{AlgebraError, Axis, Expr};

const AXES: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];
const LETTERS: [&str; 3] = ["x", "y", "z"];

/// The body's unbalance: first moments and products of inertia about the bearing origin.
pub struct Unbalance<'a> {
    pub first_moment: (&'a Expr, &'a Expr),
    /// `(I_xz, I_yz)`.
    pub products: (&'a Expr, &'a Expr),
}

/// The corrective mass moments `m_k x_k`, `m_k y_k` in the planes `z_1`, `z_2` along the
/// axis of rotation z (for `axis` x or y, the letters turned cyclically: `first_moment`
/// and `products` are then across that axis in cyclic order, `(S_y, S_z)`, `(I_xy, I_xz)`).
pub fn dynamic_balancing(
    body: &Unbalance,
    z_1: &Expr,
    z_2: &Expr,
    axis: Axis,
) -> Result<Derivation, AlgebraError> {
    let gap = z_2 - z_1;
    let solve = |s: &Expr, p: &Expr| -> Result<(Expr, Expr), AlgebraError> {
        let second = (s * z_1 - p).checked_div(&gap)?;
        let first = -s - &second;
        Ok((first.expand()?, second.expand()?))
    };
    let (x1, x2) = solve(body.first_moment.0, body.products.0)?;
    let (y1, y2) = solve(body.first_moment.1, body.products.1)?;
    let a = axis.index();
    let (la, lb, lc) = (LETTERS[a], LETTERS[(a + 1) % 3], LETTERS[(a + 2) % 3]);
    let product = |p: &str, q: &str| {
        let mut pair = [p, q];
        pair.sort_unstable();
        format!("I_{{{}{}}}", pair[0], pair[1])
    };
    let s = |name: &str, letter: &str, k: u8| {
        Expr::symbol(&format!("{name}_{k}")) * Expr::symbol(&format!("{letter}_{k}"))
    };
    Ok(Derivation {
        name: "balancing".into(),
        title: "dynamic balancing with two corrective masses".into(),
        steps: vec![Step {
            vectors: Vec::new(),
            table: None,
            title: format!(
                "static balance (mass centre on the axis ${la}$) and ${} = {} = 0$ after correction",
                product(la, lb),
                product(la, lc)
            ),
            relations: vec![
                Relation::new(s("m", lb, 1), x1, AXES[(a + 1) % 3]),
                Relation::new(s("m", lb, 2), x2, AXES[(a + 1) % 3]),
                Relation::new(s("m", lc, 1), y1, AXES[(a + 2) % 3]),
                Relation::new(s("m", lc, 2), y2, AXES[(a + 2) % 3]),
            ],
        }],
    })
}
