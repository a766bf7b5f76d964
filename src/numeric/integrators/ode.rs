//! A first-order system of ordinary differential equations `ẏ = f(t, y)`, `y ∈ Tⁿ`, as the
//! explicit integrators ([`rk4`](super::rk4), [`dop853`](super::dop853)) see it.

use nalgebra::{RealField, SVector};

/// Right-hand side `f(t, y)` of `ẏ = f(t, y)`, with an optional projection back onto the
/// manifold the state lives on (for instance the unit sphere of the quaternions).
pub trait OdeSystem<T: RealField + Copy, const N: usize> {
    /// The derivative `f(t, y)`.
    fn derivative(&self, t: T, y: &SVector<T, N>) -> SVector<T, N>;

    /// Maps an accepted step's result back onto the state manifold. The default leaves the
    /// state alone.
    fn project(&self, _y: &mut SVector<T, N>) {}
}

/// A scalar constant given in f64, converted to the working scalar.
pub(crate) fn constant<T: RealField + Copy>(value: f64) -> T {
    nalgebra::convert(value)
}

/// A working scalar as f64 (exact for f32 and f64), for error messages and checks.
pub(crate) fn to_f64<T: RealField + Copy>(value: T) -> f64 {
    value.to_subset().unwrap_or(f64::NAN)
}
