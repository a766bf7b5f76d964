//! The classical fourth-order Runge–Kutta method with a fixed step `h`:
//!
//! ```text
//! k₁ = f(t, y)              k₂ = f(t + h/2, y + h/2 k₁)
//! k₃ = f(t + h/2, y + h/2 k₂)   k₄ = f(t + h, y + h k₃)
//! y₁ = y + h/6 (k₁ + 2k₂ + 2k₃ + k₄)
//! ```
//!
//! Global error `O(h⁴)`. The increment is added with its rounding carried
//! ([`compensated`](super::compensated)), and the result projected with
//! [`OdeSystem::project`].

use super::compensated::CompensatedVector;
use super::ode::{constant, OdeSystem};
use nalgebra::RealField;

/// One step of size `h` from `(t, state)`, in place.
pub fn rk4_step<T, const N: usize, S>(system: &S, t: T, state: &mut CompensatedVector<T, N>, h: T)
where
    T: RealField + Copy,
    S: OdeSystem<T, N> + ?Sized,
{
    let half = h * constant::<T>(0.5);
    let y = *state.value();
    let y = &y;
    let k1 = system.derivative(t, y);
    let k2 = system.derivative(t + half, &(y + k1 * half));
    let k3 = system.derivative(t + half, &(y + k2 * half));
    let k4 = system.derivative(t + h, &(y + k3 * h));
    let increment = (k1 + (k2 + k3) * constant::<T>(2.0) + k4) * (h / constant::<T>(6.0));
    state.add(&increment);
    state.map_value(|y| system.project(y));
}
