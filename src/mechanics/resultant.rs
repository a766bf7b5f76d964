//! The resultant of the loads on a body: forces at points, and couples.
//!
//! ```text
//! ΣF   = Σ Fᵢ
//! ΣM_P = Σ (rᵢ − r_P) × Fᵢ + Σ Cⱼ
//! ```
//!
//! The same sums give the impulses of an impact, with `Fᵢ Δt` in place of `Fᵢ`.

use crate::algebra::vector::expand_each;
use crate::algebra::vector_products::cross;
use crate::algebra::{AlgebraError, Expr, Vector};

/// A force (or an impulse `F Δt`) and the position of its point of application from O.
#[derive(Debug, Clone, Copy)]
pub struct AppliedForce<'a> {
    pub value: &'a Vector,
    pub point: &'a Vector,
}

fn zero() -> Vector {
    Vector::from_element(Expr::zero())
}

/// `ΣF = Σ Fᵢ`.
pub fn resultant_force(forces: &[AppliedForce]) -> Result<Vector, AlgebraError> {
    expand_each(&forces.iter().fold(zero(), |sum, f| sum + f.value))
}

/// `ΣM_P = Σ (rᵢ − r_P) × Fᵢ + Σ Cⱼ`, the moment about the point at `about` from O.
pub fn resultant_moment(
    forces: &[AppliedForce],
    couples: &[Vector],
    about: &Vector,
) -> Result<Vector, AlgebraError> {
    let of_forces = forces
        .iter()
        .fold(zero(), |sum, f| sum + cross(&(f.point - about), f.value));
    expand_each(&couples.iter().fold(of_forces, |sum, c| sum + c))
}
