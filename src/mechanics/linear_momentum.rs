//! Linear momentum and its rate (§18.1): `L = m v̄`, and `L̇ = m ā`, the effective force
//! that the resultant of the external forces equals (`ΣF = m ā`).

use crate::algebra::vector::expand_each;
use crate::algebra::{AlgebraError, Expr, Vector};

/// `L = m v̄`.
pub fn linear_momentum(mass: &Expr, vbar: &Vector) -> Result<Vector, AlgebraError> {
    expand_each(&vbar.map(|v| mass * &v))
}

/// `m ā`, the rate of the linear momentum of a body of constant mass.
pub fn effective_force(mass: &Expr, abar: &Vector) -> Result<Vector, AlgebraError> {
    expand_each(&abar.map(|a| mass * &a))
}
