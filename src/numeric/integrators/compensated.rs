//! A quantity advanced by many small increments, `y ← y + Δ`, with the rounding error of
//! each addition carried into the next (Kahan–Babuška compensated summation; Hairer,
//! Lubich & Wanner, *Geometric Numerical Integration*, 2nd ed., section VIII.5):
//!
//! ```text
//! (s, r) = two_sum(y, Δ);   (y′, e′) = two_sum(s, e + r)
//! two_sum(a, b) = (fl(a + b), the rounding error of that sum):
//!     (a − s) + b  when |a| ≥ |b|,  (b − s) + a  otherwise
//! ```
//!
//! `two_sum`'s error is exact (the comparison by magnitude is Babuška's: it keeps the error
//! exact when an increment exceeds the value, as when a component of `ω` crosses zero), so
//! `y + e` carries the sum to about twice the working precision and the stored `y` is the
//! true sum rounded once, not the sum of every step's rounding. An integrator taking a
//! million steps otherwise loses up to `ulp(y)/2` a step, which swamps a local error below
//! `rtol · |y|` at tight tolerances (on a body near the separatrix the error at t = 1000
//! grew as the tolerance was tightened from 1e-12 to 1e-13). Folding `e` into the next
//! increment instead (Kahan's form) loses it when that increment cancels the value.

use nalgebra::{RealField, SVector};

/// A scalar with its carried rounding error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compensated<T> {
    value: T,
    error: T,
}

impl<T: RealField + Copy> Compensated<T> {
    /// `value` with no rounding error carried.
    pub fn new(value: T) -> Self {
        Self {
            value,
            error: T::zero(),
        }
    }

    /// The sum so far, rounded once.
    pub fn value(&self) -> T {
        self.value
    }

    /// `y ← y + increment`, the rounding error kept for the next addition.
    pub fn add(&mut self, increment: T) {
        let (sum, rounding) = two_sum(self.value, increment);
        (self.value, self.error) = two_sum(sum, self.error + rounding);
    }

    /// The value after `increment`, without changing `self`.
    pub fn plus(mut self, increment: T) -> Self {
        self.add(increment);
        self
    }
}

/// `fl(a + b)` and its rounding error, exactly (`a + b = s + e` in real arithmetic).
fn two_sum<T: RealField + Copy>(a: T, b: T) -> (T, T) {
    let sum = a + b;
    let error = if a.abs() >= b.abs() {
        (a - sum) + b
    } else {
        (b - sum) + a
    };
    (sum, error)
}

/// A vector with its carried rounding error, component by component.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompensatedVector<T: RealField + Copy, const N: usize> {
    value: SVector<T, N>,
    error: SVector<T, N>,
}

impl<T: RealField + Copy, const N: usize> CompensatedVector<T, N> {
    /// `value` with no rounding error carried.
    pub fn new(value: SVector<T, N>) -> Self {
        Self {
            value,
            error: SVector::zeros(),
        }
    }

    /// The sum so far, rounded once per component.
    pub fn value(&self) -> &SVector<T, N> {
        &self.value
    }

    /// `y ← y + increment`, the rounding errors kept for the next addition.
    pub fn add(&mut self, increment: &SVector<T, N>) {
        for i in 0..N {
            let mut component = Compensated {
                value: self.value[i],
                error: self.error[i],
            };
            component.add(increment[i]);
            self.value[i] = component.value;
            self.error[i] = component.error;
        }
    }

    /// The value after `increment`, without changing `self`.
    pub fn plus(mut self, increment: &SVector<T, N>) -> Self {
        self.add(increment);
        self
    }

    /// Replaces the value by `map(value)` (a projection back onto the state's manifold):
    /// the carried error stays where a component is unchanged and is dropped where the map
    /// moved it, since the error belongs to the sum the map replaced.
    pub fn map_value(&mut self, map: impl FnOnce(&mut SVector<T, N>)) {
        let before = self.value;
        map(&mut self.value);
        for i in 0..N {
            if self.value[i] != before[i] {
                self.error[i] = T::zero();
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A million additions of 0.1 to 1: the plain sum drifts by over 1e-7; the compensated
    /// one is the correctly rounded total of 1 + 10⁶ · fl(0.1), which is 100001 (the excess
    /// 5.6e-12 is under half an ulp, 7.3e-12).
    #[test]
    fn a_million_increments_sum_to_the_correctly_rounded_total() {
        let mut plain = 1.0f64;
        let mut compensated = Compensated::new(1.0f64);
        for _ in 0..1_000_000 {
            plain += 0.1;
            compensated.add(0.1);
        }
        // fl(0.1) = 3602879701896397 / 2⁵⁵ exactly.
        let exact = 1.0 + 1e6 * (3602879701896397.0 / 2f64.powi(55));
        assert!((plain - exact).abs() > 1e-7, "plain sum {plain}");
        assert_eq!(compensated.value(), exact);
    }

    /// An increment larger than the value (a component crossing zero) keeps its error:
    /// 1e-20 + 1 − 1 leaves 1e-20, which the value alone cannot hold past the first sum.
    #[test]
    fn an_increment_larger_than_the_value_keeps_the_small_part() {
        let mut sum = CompensatedVector::new(SVector::<f64, 2>::new(1e-20, 3.0));
        sum.add(&SVector::<f64, 2>::new(1.0, 0.0));
        sum.add(&SVector::<f64, 2>::new(-1.0, 0.0));
        assert_eq!(sum.value()[0], 1e-20);
        assert_eq!(sum.value()[1], 3.0);
    }

    /// A projection that moves a component drops its carried error; one it leaves alone
    /// keeps it.
    #[test]
    fn a_projection_drops_the_error_of_the_components_it_moves() {
        // 6e-17 is over half an ulp of 0.5 but under half an ulp of 1.
        let mut sum = CompensatedVector::new(SVector::<f64, 2>::new(1.0, 1.0));
        sum.add(&SVector::<f64, 2>::new(6e-17, 6e-17));
        sum.map_value(|v| v[0] = 0.5);
        sum.add(&SVector::<f64, 2>::new(0.0, 6e-17));
        assert_eq!(sum.value()[0], 0.5);
        assert_eq!(sum.value()[1], 1.0 + f64::EPSILON);
    }
}
