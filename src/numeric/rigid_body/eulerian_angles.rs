//! Eulerian angles (Beer & Johnston §18.9) of a body's attitude, and back: φ the precession
//! about the fixed vertical `Z`, θ the nutation about the line of nodes `x`, ψ the spin about
//! the body's axis `z`, so that the attitude is
//!
//! ```text
//! q = R_Z(φ) R_x(θ) R_z(ψ)            (r_fixed = q * r_body)
//! ```
//!
//! and in the frame Oxyz that follows the axis but not the spin
//! `ω = θ̇ i + φ̇ sin θ j + (ψ̇ + φ̇ cos θ) k`; the body axes are Oxyz turned by ψ about z, so
//! `ω_body = R_z(−ψ) ω_Oxyz`.
//!
//! Back from an attitude: the axis in fixed components is `k = (sin θ sin φ, −sin θ cos φ,
//! cos θ)` and the vertical in body components `K = (sin θ sin ψ, sin θ cos ψ, cos θ)`, so
//! `θ = atan2(√(k_X² + k_Y²), k_Z)`, `φ = atan2(k_X, −k_Y)`, `ψ = atan2(K_x, K_y)`, and the
//! rates are `θ̇ = ω_x`, `φ̇ = ω_y / sin θ`, `ψ̇ = ω_z − φ̇ cos θ` (components in Oxyz).
//! With the axis vertical (`sin θ = 0`) only `φ ± ψ` is defined: φ keeps its last value
//! and `φ̇ = 0`, ψ takes the whole turn.

use nalgebra::{UnitQuaternion, Vector3};
use std::f64::consts::TAU;

/// The three angles (rad) and their rates (rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerianAngles {
    /// θ, between the vertical `Z` and the axis `z`.
    pub theta: f64,
    /// φ, the precession about `Z`.
    pub phi: f64,
    /// ψ, the spin about `z`.
    pub psi: f64,
    /// θ̇.
    pub theta_dot: f64,
    /// φ̇.
    pub phi_dot: f64,
    /// ψ̇.
    pub psi_dot: f64,
}

impl EulerianAngles {
    /// The attitude `q = R_Z(φ) R_x(θ) R_z(ψ)`.
    pub fn attitude(&self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), self.phi)
            * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), self.theta)
            * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), self.psi)
    }

    /// `ω_z = ψ̇ + φ̇ cos θ`, the spin about the axis.
    pub fn axial_rate(&self) -> f64 {
        self.psi_dot + self.phi_dot * self.theta.cos()
    }

    /// Body-frame components of ω: `R_z(−ψ) (θ̇, φ̇ sin θ, ψ̇ + φ̇ cos θ)`.
    pub fn angular_velocity(&self) -> Vector3<f64> {
        let oxyz = Vector3::new(
            self.theta_dot,
            self.phi_dot * self.theta.sin(),
            self.axial_rate(),
        );
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), -self.psi) * oxyz
    }

    /// Every angle and rate finite.
    pub fn is_finite(&self) -> bool {
        [
            self.theta,
            self.phi,
            self.psi,
            self.theta_dot,
            self.phi_dot,
            self.psi_dot,
        ]
        .iter()
        .all(|v| v.is_finite())
    }
}

/// The angles of a sampled motion, φ and ψ unwrapped: each new value is the one (of all
/// `value + 2πk`) nearest the previous value plus its expected growth `rate Δt`, the rate
/// the middle of its band when one is known (over the nutation the growth over `Δt` lies
/// within the band times `Δt`, so the turns are counted exactly while the band is narrower
/// than `2π/Δt`), else the mean of the rates at the two samples (exact only when the samples
/// resolve the rate's changes).
#[derive(Debug, Clone, Copy)]
pub struct AnglesAlongMotion {
    previous: EulerianAngles,
    time: f64,
    phi_dot_band: Option<(f64, f64)>,
    psi_dot_band: Option<(f64, f64)>,
}

impl AnglesAlongMotion {
    /// Follows a motion that starts at `initial` at time `start` (its φ and ψ as given,
    /// beyond ±π too), with the bands of φ̇ and ψ̇ if known.
    pub fn starting_at(
        initial: EulerianAngles,
        start: f64,
        phi_dot_band: Option<(f64, f64)>,
        psi_dot_band: Option<(f64, f64)>,
    ) -> Self {
        Self {
            previous: initial,
            time: start,
            phi_dot_band,
            psi_dot_band,
        }
    }

    /// The angles and rates at time `t` (not before the previous one) of the attitude `q`
    /// with body-frame angular velocity `omega`.
    pub fn next(
        &mut self,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega: &Vector3<f64>,
    ) -> EulerianAngles {
        let axis = q * Vector3::z();
        let vertical = q.inverse_transform_vector(&Vector3::z());
        let horizontal = axis.x.hypot(axis.y);
        let theta = horizontal.atan2(axis.z);
        let previous = self.previous;
        let (phi, psi) = if horizontal == 0.0 {
            // Axis vertical: q = R_Z(φ + ψ) at θ = 0, R_Z(φ − ψ) R_x(π) at θ = π, so the
            // body's x points along the angle φ ± ψ; φ held.
            let body_x = q * Vector3::x();
            let turn = body_x.y.atan2(body_x.x);
            let phi = previous.phi;
            (phi, if theta == 0.0 { turn - phi } else { phi - turn })
        } else {
            (axis.x.atan2(-axis.y), vertical.x.atan2(vertical.y))
        };
        // ω in Oxyz: the body components turned back by ψ about z.
        let (sin_psi, cos_psi) = psi.sin_cos();
        let omega_y = sin_psi * omega.x + cos_psi * omega.y;
        let phi_dot = match horizontal {
            0.0 => 0.0,
            _ => omega_y / theta.sin(),
        };
        let psi_dot = omega.z - phi_dot * theta.cos();
        let step = t - self.time;
        let expected = |band: Option<(f64, f64)>, before: f64, now: f64| match band {
            Some((low, high)) => 0.5 * (low + high) * step,
            None => 0.5 * (before + now) * step,
        };
        let angles = EulerianAngles {
            theta,
            phi: match horizontal {
                0.0 => phi,
                _ => unwrap(
                    phi,
                    previous.phi + expected(self.phi_dot_band, previous.phi_dot, phi_dot),
                ),
            },
            psi: unwrap(
                psi,
                previous.psi + expected(self.psi_dot_band, previous.psi_dot, psi_dot),
            ),
            theta_dot: cos_psi * omega.x - sin_psi * omega.y,
            phi_dot,
            psi_dot,
        };
        self.previous = angles;
        self.time = t;
        angles
    }
}

/// `angle + 2πk` nearest `previous`.
fn unwrap(angle: f64, previous: f64) -> f64 {
    angle + TAU * ((previous - angle) / TAU).round()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Angles given, turned into an attitude and ω, read back: the same angles and rates,
    /// φ and ψ beyond ±π included (the reading starts next to them).
    #[test]
    fn angles_read_back_from_their_attitude() {
        for (theta, phi, psi) in [(0.4, 0.3, -2.0), (2.9, 4.0, 7.5), (1.2, -3.5, 0.1)] {
            let given = EulerianAngles {
                theta,
                phi,
                psi,
                theta_dot: 0.7,
                phi_dot: -1.3,
                psi_dot: 25.0,
            };
            let mut near = given;
            near.phi += 0.5;
            near.psi -= 0.5;
            let read = AnglesAlongMotion::starting_at(near, 0.0, None, None).next(
                0.0,
                &given.attitude(),
                &given.angular_velocity(),
            );
            let pairs = [
                (read.theta, theta),
                (read.phi, phi),
                (read.psi, psi),
                (read.theta_dot, 0.7),
                (read.phi_dot, -1.3),
                (read.psi_dot, 25.0),
            ];
            for (got, want) in pairs {
                assert!((got - want).abs() < 1e-13, "{read:?} against {given:?}");
            }
        }
    }

    /// The axis vertical (up, then down): φ stays at its last value, ψ takes the turn,
    /// `φ̇ = 0` and `ψ̇ = ω_z` (a sleeping top), never a 0/0.
    #[test]
    fn a_vertical_axis_holds_phi_and_gives_the_turn_to_psi() {
        let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 1.0);
        let start = EulerianAngles {
            theta: 0.0,
            phi: 0.25,
            psi: 0.0,
            theta_dot: 0.0,
            phi_dot: 0.0,
            psi_dot: 0.0,
        };
        let mut along = AnglesAlongMotion::starting_at(start, 0.0, None, None);
        let read = along.next(0.0, &q, &Vector3::new(0.0, 0.0, 30.0));
        assert_eq!((read.theta, read.phi, read.phi_dot), (0.0, 0.25, 0.0));
        assert!((read.psi - 0.75).abs() < 1e-15, "{read:?}");
        assert_eq!(read.psi_dot, 30.0);
        // Upside down, q = R_Z(φ − ψ) R_x(π): a half turn about the horizontal line at
        // (φ − ψ)/2 = 0.1, so ψ = 0.25 − 0.2 with φ still held.
        let half_turn = UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(
            0.0,
            0.1f64.cos(),
            0.1f64.sin(),
            0.0,
        ));
        let read = along.next(0.0, &half_turn, &Vector3::zeros());
        assert_eq!((read.theta, read.phi), (std::f64::consts::PI, 0.25));
        assert!((read.psi - 0.05).abs() < 1e-15, "{read:?}");
    }
}
