//! High-precision reference motion of a rigid body, free or under a body-frame moment whose
//! Taylor series is known ([`HarmonicMoment`]): Euler's equations in principal axes
//!
//! ```text
//! I₁ ω̇₁ = (I₂ − I₃) ω₂ ω₃ + M₁(t)   (and cyclically)
//! q̇ = ½ q ⊗ (0, ω)                                          (r_fixed = q r_body)
//! ```
//!
//! integrated by the Taylor series method in double-double arithmetic. Both right-hand sides
//! are bilinear in the state, so the Taylor coefficients follow exactly from Cauchy products:
//! `(k+1) ω_{k+1,i} = (I_j − I_l)/I_i Σ_r ω_{r,j} ω_{k−r,l} + M_{k,i}/I_i` and
//! `(k+1) q_{k+1} = ½ Σ_r q_r ⊗ (0, ω_{k−r})`. Each step uses [`ORDER`] terms and the step
//! size of Jorba and Zou (2005), `h = min_k (ε/‖c_k‖)^{1/k}` over the last two orders with
//! `ε = 10⁻³²` relative, so the truncation error per step sits below the double-double
//! rounding. The method shares nothing with the elliptic-function solution it checks.

use crate::numeric::error::NumericError;
use crate::numeric::integrators::harmonic_moment::HarmonicMoment;
use crate::numeric::rigid_body::inertia::validate_free_body;
use crate::numeric::scalar::double_double::DoubleDouble as Dd;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// Number of Taylor terms per step.
pub const ORDER: usize = 30;

/// Relative truncation error allowed per step.
const STEP_TOLERANCE: f64 = 1e-32;

/// The state of the reference solution at one time, rounded to `f64`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferenceState {
    /// Angular velocity in the body frame.
    pub omega: Vector3<f64>,
    /// Orientation, `r_fixed = q * r_body`.
    pub orientation: UnitQuaternion<f64>,
}

/// A rigid body integrated in double-double precision, advanced monotonically in time.
#[derive(Debug, Clone)]
pub struct ReferenceMotion {
    /// `(I_j − I_l)/I_i` for the cyclic triples (i, j, l).
    euler_coefficients: [Dd; 3],
    /// The applied moment and `1/I_i`, for a forced body.
    moment: Option<(HarmonicMoment, [Dd; 3])>,
    time: Dd,
    omega: [Dd; 3],
    /// `(w, x, y, z)`.
    quaternion: [Dd; 4],
}

impl ReferenceMotion {
    /// Starts at `t = 0` from body-frame `omega0` and orientation `q0`; the moments must be
    /// admissible and positive (a zero moment leaves Euler's equation for its axis empty).
    pub fn new(
        principal_moments: Vector3<f64>,
        omega0: Vector3<f64>,
        q0: UnitQuaternion<f64>,
    ) -> Result<Self, NumericError> {
        validate_free_body(&principal_moments, &omega0, &q0)?;
        let moment = |k: usize| Dd::from_f64(principal_moments[k]);
        let euler_coefficients =
            [0, 1, 2].map(|i| (moment((i + 1) % 3) - moment((i + 2) % 3)) / moment(i));
        let q = q0.quaternion();
        Ok(Self {
            euler_coefficients,
            moment: None,
            time: Dd::ZERO,
            omega: [0, 1, 2].map(|i| Dd::from_f64(omega0[i])),
            quaternion: [q.w, q.i, q.j, q.k].map(Dd::from_f64),
        })
    }

    /// As [`ReferenceMotion::new`], under the body-frame `moment`.
    pub fn forced(
        principal_moments: Vector3<f64>,
        omega0: Vector3<f64>,
        q0: UnitQuaternion<f64>,
        moment: HarmonicMoment,
    ) -> Result<Self, NumericError> {
        moment.validate()?;
        let mut motion = ReferenceMotion::new(principal_moments, omega0, q0)?;
        let inverse = [0, 1, 2].map(|i| Dd::ONE / Dd::from_f64(principal_moments[i]));
        motion.moment = Some((moment, inverse));
        Ok(motion)
    }

    /// Integrates forward to time `t` (not before the current time) and returns the state.
    pub fn advance_to(&mut self, t: f64) -> Result<ReferenceState, NumericError> {
        let target = Dd::from_f64(t);
        if !t.is_finite() || target < self.time {
            return Err(NumericError::InvalidInput {
                what: "reference time".into(),
                reason: format!("{t} is not a finite time at or after the current one"),
            });
        }
        while self.time < target {
            let (omega_series, quaternion_series) = self.taylor_coefficients();
            let remaining = (target - self.time).to_f64();
            let h = step_size(&omega_series, &quaternion_series).min(remaining);
            self.omega = [0, 1, 2].map(|i| horner(&omega_series, i, h));
            self.quaternion = [0, 1, 2, 3].map(|i| horner(&quaternion_series, i, h));
            self.time = if h == remaining {
                target
            } else {
                self.time + Dd::from_f64(h)
            };
        }
        Ok(self.state())
    }

    fn state(&self) -> ReferenceState {
        let [w, x, y, z] = self.quaternion.map(Dd::to_f64);
        ReferenceState {
            omega: Vector3::from(self.omega.map(Dd::to_f64)),
            orientation: UnitQuaternion::new_normalize(Quaternion::new(w, x, y, z)),
        }
    }

    /// Taylor coefficients of ω and q about the current time, orders `0..=ORDER`.
    fn taylor_coefficients(&self) -> (Vec<[Dd; 3]>, Vec<[Dd; 4]>) {
        let mut w = vec![[Dd::ZERO; 3]; ORDER + 1];
        let mut q = vec![[Dd::ZERO; 4]; ORDER + 1];
        w[0] = self.omega;
        q[0] = self.quaternion;
        // The moment's coefficients over I_i, orders 0..ORDER (zero for a free body).
        let mut forcing = [[Dd::ZERO; 3]; ORDER];
        if let Some((moment, inverse)) = &self.moment {
            moment.taylor_coefficients(self.time, &mut forcing);
            for m in &mut forcing {
                *m = [0, 1, 2].map(|i| m[i] * inverse[i]);
            }
        }
        for k in 0..ORDER {
            let inverse = Dd::ONE / Dd::from_f64((k + 1) as f64);
            for i in 0..3 {
                let (j, l) = ((i + 1) % 3, (i + 2) % 3);
                let mut sum = Dd::ZERO;
                for r in 0..=k {
                    sum += w[r][j] * w[k - r][l];
                }
                w[k + 1][i] = (self.euler_coefficients[i] * sum + forcing[k][i]) * inverse;
            }
            let mut product = [Dd::ZERO; 4];
            for r in 0..=k {
                let [a0, a1, a2, a3] = q[r];
                let [b1, b2, b3] = w[k - r];
                product[0] -= a1 * b1 + a2 * b2 + a3 * b3;
                product[1] += a0 * b1 + a2 * b3 - a3 * b2;
                product[2] += a0 * b2 + a3 * b1 - a1 * b3;
                product[3] += a0 * b3 + a1 * b2 - a2 * b1;
            }
            let half_inverse = inverse.mul_f64(0.5);
            q[k + 1] = product.map(|p| p * half_inverse);
        }
        (w, q)
    }
}

fn norm<const N: usize>(c: &[Dd; N]) -> f64 {
    c.iter().map(|x| x.to_f64().abs()).fold(0.0, f64::max)
}

/// Jorba–Zou step: the largest h with `‖c_k‖ h^k <= ε ‖c_0‖` for the last two orders, of
/// each series whose `c_0` is not zero (a forced body starting at rest has `ω = 0`, and a
/// relative bound of it would be no step at all; the attitude's series, of a unit
/// quaternion, bounds the step then).
fn step_size(omega: &[[Dd; 3]], quaternion: &[[Dd; 4]]) -> f64 {
    let mut h = f64::INFINITY;
    let scales = [norm(&omega[0]), norm(&quaternion[0])];
    for k in [ORDER - 1, ORDER] {
        for (size, scale) in [norm(&omega[k]), norm(&quaternion[k])]
            .into_iter()
            .zip(scales)
        {
            if size > 0.0 && scale > 0.0 {
                h = h.min((STEP_TOLERANCE * scale / size).powf(1.0 / k as f64));
            }
        }
    }
    h
}

fn horner<const N: usize>(series: &[[Dd; N]], component: usize, h: f64) -> Dd {
    series
        .iter()
        .rev()
        .fold(Dd::ZERO, |acc, c| acc.mul_f64(h) + c[component])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axisymmetric_body_precesses_at_the_known_rate() {
        // I = (1, 1, 2): ω₃ constant, (ω₁, ω₂) turns at (I₃−I₁)/I₁ ω₃ = 0.5.
        let mut motion = ReferenceMotion::new(
            Vector3::new(1.0, 1.0, 2.0),
            Vector3::new(0.3, 0.0, 0.5),
            UnitQuaternion::identity(),
        )
        .unwrap();
        let t = 7.0;
        let state = motion.advance_to(t).unwrap();
        let angle = 0.5 * t;
        let expected = Vector3::new(0.3 * angle.cos(), 0.3 * angle.sin(), 0.5);
        assert!((state.omega - expected).norm() < 1e-15, "{:?}", state.omega);
    }

    #[test]
    fn spin_about_a_principal_axis_turns_the_body_uniformly() {
        let mut motion = ReferenceMotion::new(
            Vector3::new(1.0, 2.0, 3.0),
            Vector3::new(0.0, 0.0, 2.0),
            UnitQuaternion::identity(),
        )
        .unwrap();
        let state = motion.advance_to(1.25).unwrap();
        let expected = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 2.5);
        assert!(state.orientation.angle_to(&expected) < 1e-15);
    }

    /// A sphere has no Euler terms, so under a moment `ω(t) = ω₀ + ∫₀ᵗ M dt / I` exactly:
    /// `M = (c, a cos pt, b sin pt)` gives `ω = (c t, a sin(pt)/p, b (1 − cos pt)/p) / I`
    /// from rest (where the step cannot be relative to `ω`, which is zero).
    #[test]
    fn a_forced_sphere_from_rest_integrates_the_moment() {
        let moment = HarmonicMoment {
            constant: Vector3::new(0.3, 0.0, 0.0),
            cosine: Vector3::new(0.0, 0.2, 0.0),
            sine: Vector3::new(0.0, 0.0, -0.1),
            frequency: Vector3::new(0.0, 3.0, 0.5),
        };
        let inertia = 2.0;
        let mut motion = ReferenceMotion::forced(
            Vector3::repeat(inertia),
            Vector3::zeros(),
            UnitQuaternion::identity(),
            moment,
        )
        .unwrap();
        for t in [0.5, 4.0, 30.0] {
            let state = motion.advance_to(t).unwrap();
            let expected = Vector3::new(
                0.3 * t,
                0.2 * (3.0 * t).sin() / 3.0,
                -0.1 * (1.0 - (0.5 * t).cos()) / 0.5,
            ) / inertia;
            assert!((state.omega - expected).amax() < 1e-15, "t = {t}");
        }
    }

    /// A steady moment along the spin axis of a body spinning about a principal axis only
    /// spins it up: `ω₃ = ω₀ + M t / I₃`, and the body turns by `ω₀ t + M t² / (2 I₃)`.
    #[test]
    fn a_steady_moment_along_a_principal_spin_spins_it_up() {
        let (spin, torque, i3) = (1.5, 0.25, 3.0);
        let mut motion = ReferenceMotion::forced(
            Vector3::new(1.0, 2.0, i3),
            Vector3::new(0.0, 0.0, spin),
            UnitQuaternion::identity(),
            HarmonicMoment::steady(Vector3::new(0.0, 0.0, torque)),
        )
        .unwrap();
        let t = 2.0;
        let state = motion.advance_to(t).unwrap();
        assert!((state.omega.z - (spin + torque * t / i3)).abs() < 1e-15);
        let angle = spin * t + torque * t * t / (2.0 * i3);
        let expected = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), angle);
        assert!(state.orientation.angle_to(&expected) < 1e-15);
    }

    #[test]
    fn going_back_in_time_or_zero_moments_are_errors() {
        let mut motion = ReferenceMotion::new(
            Vector3::new(1.0, 2.0, 3.0),
            Vector3::new(1.0, 1.0, 1.0),
            UnitQuaternion::identity(),
        )
        .unwrap();
        motion.advance_to(1.0).unwrap();
        assert!(motion.advance_to(0.5).is_err());
        assert!(motion.advance_to(f64::NAN).is_err());
        let rod = ReferenceMotion::new(
            Vector3::new(0.0, 1.0, 1.0),
            Vector3::new(1.0, 1.0, 1.0),
            UnitQuaternion::identity(),
        );
        assert!(rod.is_err());
    }
}
