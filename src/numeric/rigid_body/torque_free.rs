//! Exact motion of a free rigid body (Euler–Poinsot), `I ω̇ = (Iω) × ω`, `q̇ = ½ q ⊗ (0, ω)`.
//!
//! With the principal moments relabelled `I₁, I₂, I₃` so that the polhode circles axis 3
//! (ascending moments when `|H|² > 2T I₂`, descending when `|H|² < 2T I₂`), the body-frame
//! angular velocity is (Landau & Lifshitz, Mechanics §37)
//!
//! ```text
//! ω₁ = a₁ cn τ,   ω₂ = ±a₂ sn τ,   ω₃ = a₃ dn τ,       τ = p t + τ₀   (− for descending)
//! a₁² = (2T I₃ − H²)/(I₁(I₃−I₁))   a₂² = (2T I₃ − H²)/(I₂(I₃−I₂))   a₃² = (H² − 2T I₁)/(I₃(I₃−I₁))
//! p²  = (I₃−I₂)(H² − 2T I₁)/(I₁I₂I₃)          m = (I₂−I₁)(2T I₃ − H²)/((I₃−I₂)(H² − 2T I₁))
//! m'  = (I₃−I₁)(H² − 2T I₂)/((I₃−I₂)(H² − 2T I₁))
//! ```
//!
//! On the separatrix `H² = 2T I₂` (m = 1) cn and dn become sech and sn becomes tanh.
//! Every difference of invariants is expanded as a sum of products of moment differences and
//! squared ω components (`2T I₃ − H² = I₁(I₃−I₁)ω₁² + I₂(I₃−I₂)ω₂²`, ...) and evaluated in
//! double-double, so nothing cancels except the genuine separatrix distance
//! `H² − 2T I₂ = I₃(I₃−I₂)ω₃² − I₁(I₂−I₁)ω₁²`, which is then known to ~32 digits.
//!
//! Orientation: the fixed frame is aligned with H. Body components of the unit angular
//! momentum `ĥ = Iω/|H| = (sin θ sin ψ, sin θ cos ψ, cos θ)` give θ and ψ algebraically, and
//! `q(t) = G ⊗ R_z(φ) ⊗ R_x(θ) ⊗ R_z(ψ)` with the constant `G` fixed by `q(0) = q₀`. The
//! precession angle obeys `φ̇ = 2T/|H| − ψ̇ cos θ = |H|/I₃ + |H|(I₃−I₁)/(I₁I₃) / (1 − n sn²τ)`,
//! `n = −I₃(I₂−I₁)/(I₁(I₃−I₂)) < 0`, so
//! `φ = |H| t/I₃ + |H|(I₃−I₁)/(I₁I₃p) · [Π(n; am τ|m) − Π(n; am τ₀|m)]`.
//! Long times: τ is reduced as `τ = 2K j + r` in double-double, `Π(n; am τ) = 2jΠ(n|m) +
//! Π(n; am r)`, and the secular part of φ is summed in double-double, so t = 1000 keeps the
//! accuracy of t = 1.
//!
//! Axisymmetric bodies (`I₁ = I₂ = I_t`, symmetry axis 3):
//! `q(t) = exp(Ĥ |H| t/(2I_t)) ⊗ q₀ ⊗ exp(e₃ ν t/2)` with `ν = (I_t − I₃)ω₃/I_t`; spheres
//! and rotation about a principal axis turn uniformly, `q(t) = q₀ ⊗ exp(ω t/2)`.
//!
//! Scaling: the motion of λω is the motion of ω with time scaled by λ, and the moments
//! matter only through their ratios, so ω₀ and the moments are divided by powers of two
//! (exactly) to be of order one; |H| from 1e-150 to 1e150 is handled without overflow.
//! Components of ω₀ below 2⁻⁴⁸⁰ times the largest are taken as zero: their squares would
//! leave the normal range.

use crate::numeric::error::NumericError;
use crate::numeric::rigid_body::elliptic::{
    complete_first_kind, complete_third_kind, first_kind_from_sines, half_period_sign,
    third_kind_from_sines, EllipticParameter, JacobiFunctions,
};
use crate::numeric::rigid_body::inertia::validate_free_body;
use crate::numeric::scalar::double_double::DoubleDouble as Dd;
use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};

/// Components of ω₀ below this fraction (2⁻⁴⁸⁰ ≈ 3e-145) of the largest are set to zero:
/// their squares, which the invariants are made of, would leave the normal range. (Such a
/// component matters only for a start at the intermediate axis, whose departure it would
/// delay beyond t ≈ 330/p.)
const UNRESOLVED: f64 = f64::from_bits((1023 - 480) << 52);

/// Which closed form describes the motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Regime {
    /// ω₀ = 0: the body stays at its initial orientation.
    Rest,
    /// Three equal moments: uniform rotation.
    Spherical,
    /// ω₀ along a principal axis of distinct moments: uniform rotation (stable or not).
    PrincipalAxis,
    /// Two equal moments: steady precession in elementary functions.
    Axisymmetric,
    /// Asymmetric body, `|H|² > 2T I_mid`: the polhode circles the axis of largest moment.
    AroundLargestMoment,
    /// Asymmetric body, `|H|² < 2T I_mid`: the polhode circles the axis of smallest moment.
    AroundSmallestMoment,
    /// Asymmetric body, `|H|² = 2T I_mid` exactly: the motion tends to the intermediate axis.
    Separatrix,
}

/// The closed-form motion of a torque-free rigid body.
#[derive(Debug, Clone)]
pub struct TorqueFree {
    regime: Regime,
    frame: WorkingFrame,
    /// ω₀ = `rate_scale` · (order-one vector); times are multiplied by it.
    rate_scale: f64,
    /// Initial orientation of the working frame.
    start: UnitQuaternion<f64>,
    motion: Motion,
}

/// The principal frame the formulas are written in, a signed permutation of the caller's
/// axes with determinant +1: working axis i is caller axis `axis[i]` times `sign[i]`.
#[derive(Debug, Clone)]
struct WorkingFrame {
    axis: [usize; 3],
    sign: [f64; 3],
    /// `r_caller = rotation * r_working`.
    rotation: UnitQuaternion<f64>,
}

#[derive(Debug, Clone)]
enum Motion {
    /// Constant ω (rest, sphere, principal axis).
    Uniform {
        omega: Vector3<f64>,
        speed: Dd,
    },
    Axisymmetric(Box<Axisymmetric>),
    Elliptic(Box<EllipticMotion>),
}

#[derive(Debug, Clone)]
struct Axisymmetric {
    omega0: Vector3<f64>,
    /// ν = (I_t − I₃) ω₃ / I_t: rate at which ω turns about body axis 3 (clockwise).
    spin: Dd,
    /// |H| / I_t: rate of the body about the fixed H.
    precession: Dd,
    momentum_axis: Unit<Vector3<f64>>,
}

#[derive(Debug, Clone)]
struct EllipticMotion {
    moments: Vector3<f64>,
    /// `(a₁, ±a₂, a₃)`.
    amplitude: Vector3<f64>,
    /// `p` in `τ = p t + τ₀`.
    rate: Dd,
    /// `τ₀`.
    phase0: Dd,
    /// `|H|`.
    momentum: f64,
    /// φ = `precession`·t + `coefficient`·(Π(n; am τ) − Π(n; am τ₀)) (periodic family) or
    /// the separatrix analogue.
    precession: Dd,
    coefficient: Dd,
    n: f64,
    /// `q(t) = frame ⊗ R_z(φ) ⊗ B(ĥ(t))`.
    frame: UnitQuaternion<f64>,
    phase: Phase,
}

#[derive(Debug, Clone)]
enum Phase {
    /// m < 1: sn, cn, dn with half-period 2K and the reduced third-kind integral.
    Periodic {
        functions: JacobiFunctions,
        half_period: Dd,
        half_period_integral: Dd,
        integral0: Dd,
    },
    /// m = 1: sech, tanh and `∫dτ/(1 − n tanh²τ) = (τ + √−n atan(√−n tanh τ))/(1 − n)`.
    Separatrix {
        root_minus_n: f64,
        one_minus_n: Dd,
        arctan0: f64,
    },
}

/// Where the elliptic motion is at one time: `τ = 2K·half_periods + r` and the Jacobi
/// functions of r (of τ itself on the separatrix, where they are tanh, sech, sech).
struct PhasePoint {
    omega: Vector3<f64>,
    half_periods: Dd,
    sn: f64,
    cn: f64,
    dn: f64,
}

fn invalid(what: &str, reason: String) -> NumericError {
    NumericError::InvalidInput {
        what: what.to_string(),
        reason,
    }
}

/// The power of two at or above the largest magnitude (1 for a zero vector), kept within
/// `2^±1020` so that it and its reciprocal are normal numbers.
fn power_of_two_scale(v: &Vector3<f64>) -> f64 {
    let largest = v.amax();
    if largest == 0.0 {
        1.0
    } else {
        2f64.powi((largest.log2().ceil() as i32).clamp(-1020, 1020))
    }
}

/// `angle` reduced to `[−π, π]` in double-double before rounding.
fn reduced_angle(angle: Dd) -> f64 {
    let turn = Dd::PI.mul_f64(2.0);
    (angle - (angle / turn).round() * turn).to_f64()
}

fn rotation_about(axis: &Unit<Vector3<f64>>, angle: Dd) -> UnitQuaternion<f64> {
    UnitQuaternion::from_axis_angle(axis, reduced_angle(angle))
}

fn square(x: f64) -> Dd {
    Dd::product(x, x)
}

fn difference(a: f64, b: f64) -> Dd {
    Dd::sum(a, -b)
}

impl WorkingFrame {
    fn new(axis: [usize; 3], sign: [f64; 3]) -> Self {
        let mut matrix = Matrix3::zeros();
        for i in 0..3 {
            matrix[(axis[i], i)] = sign[i];
        }
        let rotation =
            UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(matrix));
        Self {
            axis,
            sign,
            rotation,
        }
    }

    fn identity() -> Self {
        Self::new([0, 1, 2], [1.0; 3])
    }

    fn permute(&self, v: &Vector3<f64>) -> Vector3<f64> {
        Vector3::from_fn(|i, _| v[self.axis[i]])
    }

    fn to_working(&self, v: &Vector3<f64>) -> Vector3<f64> {
        Vector3::from_fn(|i, _| self.sign[i] * v[self.axis[i]])
    }

    fn to_caller(&self, v: &Vector3<f64>) -> Vector3<f64> {
        let mut out = Vector3::zeros();
        for i in 0..3 {
            out[self.axis[i]] = self.sign[i] * v[i];
        }
        out
    }
}

impl TorqueFree {
    /// The motion from principal moments (in the caller's axis order, any order), body-frame
    /// `omega0` and initial orientation `q0` (`r_fixed = q * r_body`). Moments must be
    /// admissible and positive (a zero moment, a body on a line, leaves the spin about that
    /// axis undetermined), `omega0` and `q0` finite.
    pub fn new(
        principal_moments: Vector3<f64>,
        omega0: Vector3<f64>,
        q0: UnitQuaternion<f64>,
    ) -> Result<Self, NumericError> {
        validate_free_body(&principal_moments, &omega0, &q0)?;
        let rate_scale = power_of_two_scale(&omega0);
        let omega = (omega0 / rate_scale).map(|w| if w.abs() < UNRESOLVED { 0.0 } else { w });
        let moments = principal_moments / power_of_two_scale(&principal_moments);
        let (regime, frame) = classify(&moments, &omega);
        let start = q0 * frame.rotation;
        let moments = frame.permute(&moments);
        let omega = frame.to_working(&omega);
        let motion = match regime {
            Regime::Rest | Regime::Spherical | Regime::PrincipalAxis => Motion::Uniform {
                omega,
                speed: (square(omega.x) + square(omega.y) + square(omega.z)).sqrt(),
            },
            Regime::Axisymmetric => {
                Motion::Axisymmetric(Box::new(Axisymmetric::new(&moments, &omega, &start)))
            }
            _ => Motion::Elliptic(Box::new(EllipticMotion::new(
                &moments,
                &omega,
                &start,
                regime == Regime::Separatrix,
            )?)),
        };
        Ok(Self {
            regime,
            frame,
            rate_scale,
            start,
            motion,
        })
    }

    /// Which closed form was taken.
    pub fn regime(&self) -> Regime {
        self.regime
    }

    /// Body-frame angular velocity at time `t` (any finite t, also negative), in the caller's
    /// axis order. Accuracy holds while |ω|·t stays well below 1e15; a NaN t gives NaN.
    pub fn omega(&self, t: f64) -> Vector3<f64> {
        let s = t * self.rate_scale;
        let working = match &self.motion {
            Motion::Uniform { omega, .. } => *omega,
            Motion::Axisymmetric(a) => a.omega(s),
            Motion::Elliptic(e) => e.point(s).omega,
        };
        self.frame.to_caller(&working) * self.rate_scale
    }

    /// Orientation at time `t` (`r_fixed = q * r_body`, caller's body axes), with the same
    /// range as [`TorqueFree::omega`].
    pub fn orientation(&self, t: f64) -> UnitQuaternion<f64> {
        let s = t * self.rate_scale;
        let working = match &self.motion {
            Motion::Uniform { omega, speed } => match Unit::try_new(*omega, 0.0) {
                Some(axis) => self.start * rotation_about(&axis, *speed * Dd::from_f64(s)),
                None => self.start,
            },
            Motion::Axisymmetric(a) => a.orientation(s, &self.start),
            Motion::Elliptic(e) => e.orientation(s),
        };
        working * self.frame.rotation.inverse()
    }
}

/// The regime and the working frame it is written in.
fn classify(moments: &Vector3<f64>, omega: &Vector3<f64>) -> (Regime, WorkingFrame) {
    if omega.iter().all(|&w| w == 0.0) {
        return (Regime::Rest, WorkingFrame::identity());
    }
    let equal = |i: usize, j: usize| moments[i] == moments[j];
    if equal(0, 1) && equal(1, 2) {
        return (Regime::Spherical, WorkingFrame::identity());
    }
    let steady = (0..3).all(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        equal(j, k) || omega[j] == 0.0 || omega[k] == 0.0
    });
    if steady {
        return (Regime::PrincipalAxis, WorkingFrame::identity());
    }
    if let Some(symmetry) = (0..3).find(|&i| equal((i + 1) % 3, (i + 2) % 3)) {
        // A cyclic shift (even, no sign needed) puts the symmetry axis last.
        let axis = [(symmetry + 1) % 3, (symmetry + 2) % 3, symmetry];
        return (Regime::Axisymmetric, WorkingFrame::new(axis, [1.0; 3]));
    }
    let mut ascending = [0, 1, 2];
    ascending.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
    let [i1, i2, i3] = ascending;
    let (j1, j2, j3) = (moments[i1], moments[i2], moments[i3]);
    let separatrix_distance = Dd::from_f64(j3) * difference(j3, j2) * square(omega[i3])
        - Dd::from_f64(j1) * difference(j2, j1) * square(omega[i1]);
    let (regime, axis) = if separatrix_distance > Dd::ZERO {
        (Regime::AroundLargestMoment, ascending)
    } else if separatrix_distance < Dd::ZERO {
        (Regime::AroundSmallestMoment, [i3, i2, i1])
    } else {
        (Regime::Separatrix, ascending)
    };
    // Signs: ω₃ > 0 and ω₁ >= 0 in the working frame (rotations by π about a principal axis
    // are symmetries of Euler's equations), the middle sign keeping the determinant +1.
    // Even permutations of three axes are the cyclic shifts.
    let parity = if axis[1] == (axis[0] + 1) % 3 {
        1.0
    } else {
        -1.0
    };
    let sign_of = |w: f64| if w < 0.0 { -1.0 } else { 1.0 };
    let (s1, s3) = (sign_of(omega[axis[0]]), sign_of(omega[axis[2]]));
    (regime, WorkingFrame::new(axis, [s1, parity * s1 * s3, s3]))
}

impl Axisymmetric {
    fn new(moments: &Vector3<f64>, omega: &Vector3<f64>, start: &UnitQuaternion<f64>) -> Self {
        let (transverse, axial) = (moments.x, moments.z);
        let momentum_sq = (0..3).fold(Dd::ZERO, |acc, i| {
            acc + Dd::product(moments[i], omega[i]) * Dd::product(moments[i], omega[i])
        });
        let momentum = momentum_sq.sqrt();
        let body_momentum = moments.component_mul(omega);
        Self {
            omega0: *omega,
            spin: difference(transverse, axial) * Dd::from_f64(omega.z) / Dd::from_f64(transverse),
            precession: momentum / Dd::from_f64(transverse),
            momentum_axis: Unit::new_normalize(start * body_momentum),
        }
    }

    fn omega(&self, s: f64) -> Vector3<f64> {
        let (sin, cos) = reduced_angle(self.spin * Dd::from_f64(s)).sin_cos();
        let w = &self.omega0;
        Vector3::new(cos * w.x + sin * w.y, cos * w.y - sin * w.x, w.z)
    }

    fn orientation(&self, s: f64, start: &UnitQuaternion<f64>) -> UnitQuaternion<f64> {
        let time = Dd::from_f64(s);
        rotation_about(&self.momentum_axis, self.precession * time)
            * start
            * rotation_about(&Vector3::z_axis(), self.spin * time)
    }
}

/// `R_x(θ) ⊗ R_z(ψ)`, the rotation taking the body components of `ĥ` to `e_z`.
fn momentum_alignment(h: &Vector3<f64>) -> UnitQuaternion<f64> {
    let transverse = h.x.hypot(h.y);
    let theta = transverse.atan2(h.z);
    let psi = h.x.atan2(h.y);
    UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta)
        * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), psi)
}

impl EllipticMotion {
    fn new(
        moments: &Vector3<f64>,
        omega: &Vector3<f64>,
        start: &UnitQuaternion<f64>,
        separatrix: bool,
    ) -> Result<Self, NumericError> {
        let [j1, j2, j3] = [moments.x, moments.y, moments.z];
        let [dj1, dj2, dj3] = [j1, j2, j3].map(Dd::from_f64);
        let (d21, d31, d32) = (difference(j2, j1), difference(j3, j1), difference(j3, j2));
        let [w1, w2, w3] = [omega.x, omega.y, omega.z].map(square);
        // 2T I₃ − H², H² − 2T I₁, H² − 2T I₂ as sums of products (signs follow the labelling).
        let e3 = dj1 * d31 * w1 + dj2 * d32 * w2;
        let e1 = dj2 * d21 * w2 + dj3 * d31 * w3;
        let e2 = dj3 * d32 * w3 - dj1 * d21 * w1;
        let momentum_sq = dj1 * dj1 * w1 + dj2 * dj2 * w2 + dj3 * dj3 * w3;
        let momentum = momentum_sq.sqrt();
        // With descending moments the relabelling 1 ↔ 3 is a reflection; ω₂ = −a₂ sn τ then
        // keeps p > 0, so a₂ carries the sign of I₃ − I₂.
        let amplitude = Vector3::new(
            (e3 / (dj1 * d31)).to_f64().sqrt(),
            (e3 / (dj2 * d32)).to_f64().sqrt() * d32.to_f64().signum(),
            (e1 / (dj3 * d31)).to_f64().sqrt(),
        );
        let rate = (d32 * e1 / (dj1 * dj2 * dj3)).sqrt();
        let n = -(dj3 * d21) / (dj1 * d32);
        let coefficient = momentum * d31 / (dj1 * dj3 * rate);
        let precession = momentum / dj3;
        let frame = start * momentum_alignment(&moments.component_mul(omega)).inverse();
        let (phase0, phase) = if separatrix {
            // sinh τ₀ = tanh τ₀ / sech τ₀ = (ω₂/a₂) / (ω₁/a₁).
            let tau0 = (omega.y * amplitude.x / (amplitude.y * omega.x)).asinh();
            let root_minus_n = (-n).to_f64().sqrt();
            let arctan0 = (root_minus_n * tau0.tanh()).atan();
            (
                Dd::from_f64(tau0),
                Phase::Separatrix {
                    root_minus_n,
                    one_minus_n: Dd::ONE - n,
                    arctan0,
                },
            )
        } else {
            let m = d21 * e3 / (d32 * e1);
            let mc = d31 * e2 / (d32 * e1);
            // The smaller of m, m' carries the digits; classify's labelling keeps both in [0, 1].
            let parameter = if m.to_f64() <= 0.5 {
                EllipticParameter::new(m.to_f64())
            } else {
                EllipticParameter::from_complement(mc.to_f64())
            }?;
            let half_period = complete_first_kind(mc).mul_f64(2.0);
            let half_period_integral = complete_third_kind(n, mc).mul_f64(2.0);
            // sn τ₀, cn τ₀, dn τ₀ straight from ω₀ (no amplitude angle, see
            // `first_kind_from_sines`); cn τ₀ < 0 means τ₀ = ±2K − τ' with cn τ' = −cn τ₀.
            let (sn0, cn0, dn0) = (
                omega.y / amplitude.y,
                omega.x / amplitude.x,
                omega.z / amplitude.z,
            );
            let tau0 = Dd::from_f64(first_kind_from_sines(sn0, cn0.abs(), dn0));
            let integral0 = Dd::from_f64(third_kind_from_sines(n.to_f64(), sn0, cn0.abs(), dn0));
            let (tau0, integral0) = if cn0 < 0.0 {
                let side = if sn0 < 0.0 { -1.0 } else { 1.0 };
                (
                    half_period.mul_f64(side) - tau0,
                    half_period_integral.mul_f64(side) - integral0,
                )
            } else {
                (tau0, integral0)
            };
            (
                tau0,
                Phase::Periodic {
                    functions: JacobiFunctions::new(&parameter),
                    half_period,
                    half_period_integral,
                    integral0,
                },
            )
        };
        let finite = amplitude.iter().all(|a| a.is_finite())
            && rate.to_f64().is_finite()
            && phase0.to_f64().is_finite();
        if !finite {
            return Err(invalid(
                "initial angular velocity",
                format!("{omega:?} (scaled) is too close to the separatrix to resolve in double precision"),
            ));
        }
        Ok(Self {
            moments: *moments,
            amplitude,
            rate,
            phase0,
            momentum: momentum.to_f64(),
            precession,
            coefficient,
            n: n.to_f64(),
            frame,
            phase,
        })
    }

    /// ω at scaled time s, with what the precession angle needs.
    fn point(&self, s: f64) -> PhasePoint {
        let tau = self.rate * Dd::from_f64(s) + self.phase0;
        let a = &self.amplitude;
        match &self.phase {
            Phase::Periodic {
                functions,
                half_period,
                ..
            } => {
                // τ = 2K·j + r: j from the leading parts (a double-double division costs a
                // fifth of the point), r exact in double-double; an estimate one off at a
                // boundary leaves |r| a rounding past K, which the functions take as well.
                let half_periods = Dd::from_f64((tau.hi() / half_period.hi()).round());
                let r = (tau - half_periods * *half_period).to_f64();
                let (sn, cn, dn) = functions.sn_cn_dn(r);
                // sn and cn change sign over each half-period 2K, dn does not.
                let parity = half_period_sign(half_periods.hi());
                PhasePoint {
                    omega: Vector3::new(parity * a.x * cn, parity * a.y * sn, a.z * dn),
                    half_periods,
                    sn,
                    cn,
                    dn,
                }
            }
            Phase::Separatrix { .. } => {
                let tau = tau.to_f64();
                let (sech, tanh) = (1.0 / tau.cosh(), tau.tanh());
                PhasePoint {
                    omega: Vector3::new(a.x * sech, a.y * tanh, a.z * sech),
                    half_periods: Dd::ZERO,
                    sn: tanh,
                    cn: sech,
                    dn: sech,
                }
            }
        }
    }

    /// The precession angle φ about H at scaled time s (φ(0) = 0).
    fn precession_angle(&self, s: f64, point: &PhasePoint) -> Dd {
        let time = Dd::from_f64(s);
        let secular = self.precession * time;
        match &self.phase {
            Phase::Periodic {
                half_period_integral,
                integral0,
                ..
            } => {
                // |r| <= K, so cn r >= 0 up to rounding at ±K, where Π is symmetric anyway.
                let integral = third_kind_from_sines(self.n, point.sn, point.cn.abs(), point.dn);
                secular
                    + self.coefficient
                        * (point.half_periods * *half_period_integral + Dd::from_f64(integral)
                            - *integral0)
            }
            Phase::Separatrix {
                root_minus_n,
                one_minus_n,
                arctan0,
            } => {
                let linear = self.coefficient * self.rate * time / *one_minus_n;
                let arctan = (root_minus_n * point.sn).atan() - arctan0;
                let bounded = (self.coefficient / *one_minus_n).to_f64() * root_minus_n * arctan;
                secular + linear + Dd::from_f64(bounded)
            }
        }
    }

    fn orientation(&self, s: f64) -> UnitQuaternion<f64> {
        let point = self.point(s);
        let phi = self.precession_angle(s, &point);
        let h = self.moments.component_mul(&point.omega) / self.momentum;
        self.frame * rotation_about(&Vector3::z_axis(), phi) * momentum_alignment(&h)
    }
}
