//! A body-frame moment whose Taylor series about any time is known in closed form, so that
//! the double-double reference (`reference.rs`) can integrate a forced body as exactly as a
//! free one. On each axis `i`, a constant and one harmonic:
//!
//! ```text
//! M_i(t) = c_i + a_i cos(p_i t) + b_i sin(p_i t)
//! ```
//!
//! About `t₀`, with `θ = p t₀`, `cos(θ + p s) = Σ_n u_n sⁿ` and `sin(θ + p s) = Σ_n v_n sⁿ`
//! where `u_n = pⁿ/n! cos(θ + nπ/2)` and `v_n = pⁿ/n! sin(θ + nπ/2)`; a quarter turn more
//! gives the recurrence
//!
//! ```text
//! u₀ = cos θ,  v₀ = sin θ,    u_{n+1} = −p v_n / (n+1),    v_{n+1} = p u_n / (n+1)
//! ```
//!
//! and `M_{n,i} = c_i δ_{n0} + a_i u_n + b_i v_n`.

use crate::numeric::error::NumericError;
use crate::numeric::scalar::double_double::DoubleDouble as Dd;
use nalgebra::Vector3;

/// `M_i(t) = constant_i + cosine_i cos(frequency_i t) + sine_i sin(frequency_i t)` in body
/// axes (N·m, rad/s).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HarmonicMoment {
    pub constant: Vector3<f64>,
    pub cosine: Vector3<f64>,
    pub sine: Vector3<f64>,
    pub frequency: Vector3<f64>,
}

impl HarmonicMoment {
    /// A moment that does not change.
    pub fn steady(moment: Vector3<f64>) -> HarmonicMoment {
        HarmonicMoment {
            constant: moment,
            ..HarmonicMoment::default()
        }
    }

    /// The moment at time `t`, in `f64` (as an integrator evaluates it).
    pub fn at(&self, t: f64) -> Vector3<f64> {
        Vector3::from_fn(|i, _| {
            let (sin, cos) = (self.frequency[i] * t).sin_cos();
            self.constant[i] + self.cosine[i] * cos + self.sine[i] * sin
        })
    }

    /// Refuses a moment with a component that is not a finite number.
    pub fn validate(&self) -> Result<(), NumericError> {
        let parts = [
            ("constant", self.constant),
            ("cosine amplitude", self.cosine),
            ("sine amplitude", self.sine),
            ("frequency", self.frequency),
        ];
        for (what, part) in parts {
            if let Some(v) = part.iter().find(|v| !v.is_finite()) {
                return Err(NumericError::InvalidInput {
                    what: format!("moment {what}"),
                    reason: format!("{v} is not a finite number"),
                });
            }
        }
        Ok(())
    }

    /// The Taylor coefficients `M_n` about `t0` for `n = 0 .. series.len()`, written into
    /// `series` (see the module documentation).
    pub(super) fn taylor_coefficients(&self, t0: Dd, series: &mut [[Dd; 3]]) {
        for i in 0..3 {
            let p = self.frequency[i];
            let (mut v, mut u) = (t0.mul_f64(p)).sin_cos();
            for (n, coefficient) in series.iter_mut().enumerate() {
                let harmonic = u.mul_f64(self.cosine[i]) + v.mul_f64(self.sine[i]);
                coefficient[i] = if n == 0 {
                    harmonic + Dd::from_f64(self.constant[i])
                } else {
                    harmonic
                };
                let step = Dd::from_f64(p) / Dd::from_f64((n + 1) as f64);
                (u, v) = (-(v * step), u * step);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series summed at a small offset equals the moment evaluated there, and the
    /// first-order coefficient is the derivative.
    #[test]
    fn series_sums_to_the_moment() {
        let moment = HarmonicMoment {
            constant: Vector3::new(0.5, -0.2, 0.0),
            cosine: Vector3::new(0.1, 0.0, -0.3),
            sine: Vector3::new(0.0, 0.7, 0.05),
            frequency: Vector3::new(1.0, 3.0, 2.0),
        };
        let (t0, s) = (7.25, 0.125);
        let mut series = [[Dd::ZERO; 3]; 30];
        moment.taylor_coefficients(Dd::from_f64(t0), &mut series);
        let summed: Vec<f64> = (0..3)
            .map(|i| {
                series
                    .iter()
                    .rev()
                    .fold(Dd::ZERO, |acc, c| acc.mul_f64(s) + c[i])
                    .to_f64()
            })
            .collect();
        let expected = moment.at(t0 + s);
        for i in 0..3 {
            assert!((summed[i] - expected[i]).abs() < 1e-15, "axis {i}");
            let p = moment.frequency[i];
            let derivative =
                p * (-moment.cosine[i] * (p * t0).sin() + moment.sine[i] * (p * t0).cos());
            assert!(
                (series[1][i].to_f64() - derivative).abs() < 1e-15,
                "axis {i}"
            );
        }
    }

    #[test]
    fn a_non_finite_part_is_refused() {
        let mut moment = HarmonicMoment::steady(Vector3::new(1.0, 0.0, 0.0));
        assert!(moment.validate().is_ok());
        moment.frequency.y = f64::NAN;
        assert!(moment.validate().is_err());
    }
}
