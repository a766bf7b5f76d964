//! The classical fourth-order Runge–Kutta method with a fixed step `h`:
//!
//! ```text
//! k₁ = f(t, y)              k₂ = f(t + h/2, y + h/2 k₁)
//! k₃ = f(t + h/2, y + h/2 k₂)   k₄ = f(t + h, y + h k₃)
//! y₁ = y + h/6 (k₁ + 2k₂ + 2k₃ + k₄)
//! ```
//!
//! Global error `O(h⁴)`; the step's result is projected with [`OdeSystem::project`].

use super::ode::{constant, OdeSystem};
use nalgebra::{RealField, SVector};

/// One step of size `h` from `(t, y)`.
pub fn rk4_step<T, const N: usize, S>(system: &S, t: T, y: &SVector<T, N>, h: T) -> SVector<T, N>
where
    T: RealField + Copy,
    S: OdeSystem<T, N> + ?Sized,
{
    let half = h * constant::<T>(0.5);
    let k1 = system.derivative(t, y);
    let k2 = system.derivative(t + half, &(y + k1 * half));
    let k3 = system.derivative(t + half, &(y + k2 * half));
    let k4 = system.derivative(t + h, &(y + k3 * h));
    let mut next = y + (k1 + (k2 + k3) * constant::<T>(2.0) + k4) * (h / constant::<T>(6.0));
    system.project(&mut next);
    next
}
