//! A Lie–Poisson splitting integrator for the rigid body: every sub-step is an exact
//! rotation, so `|H|` is conserved to round-off and the attitude stays a rotation.
//!
//! In the principal frame with body angular momentum `H` (so `ω_i = H_i / I_i`) the free
//! rigid body is the Lie–Poisson system `Ḣ = H × ∇T(H)`, `q̇ = ½ q ⊗ (0, ∇T(H))` with
//! `T = Σ H_i² / 2I_i`. Take `I_r` the middle moment and write (McLachlan 1993)
//!
//! ```text
//! T = |H|²/(2 I_r) + ½ κ_a H_a² + ½ κ_b H_b²,   κ_i = 1/I_i − 1/I_r,
//! ```
//!
//! where `a, b` are the other two axes. Each piece has an exact flow in closed form:
//! * `½ κ_i H_i²`: `ω = κ_i H_i e_i` is constant, so `H` turns about body axis `e_i` by
//!   `−θ` and `q ← q ⊗ exp(θ e_i / 2)`, `θ = κ_i H_i h`;
//! * `|H|²/(2 I_r)`: `H` is fixed in the body and `q ← q ⊗ exp(h H / 2I_r)`, a turn about
//!   `H` by `|H| h / I_r`. This piece commutes with the other two (`|H|²` is invariant under
//!   every turn about a body axis).
//!
//! A moment adds the flow `Ḣ = M_body(t, q)` with `q` and the time frozen, exact as a kick
//! `H ← H + h M_body(t, q)` (for a moment fixed in space `M_body = q⁻¹ M_fixed`). The time is
//! a variable of the extended, autonomous system with `ṫ = 1` in the drift (the torque-free
//! pieces, which do not depend on `t`), so a moment that varies with time or attitude
//! ([`Torque::Time`], [`Torque::Attitude`]) is kicked exactly too. A moment that depends on
//! `ω` changes along its own kick and has no such exact flow: [`Torque::Function`] is
//! refused. With `A`, `B` the flows of the `a` and `b` pieces, `C` that of the `|H|²` piece,
//! `τ` the clock and `K` the kick, one step from `t` applies, in this order,
//!
//! ```text
//! K(h/2) at t, A(h/2), B(h), A(h/2), C(h), τ(h), K(h/2) at t + h
//! ```
//!
//! a symmetric (Strang) composition, since `B`, `C` and `τ` commute with one another and
//! `C`, `τ` with `A`: second order.
//! [`SplittingOrder::Fourth`] chains three such steps of sizes `w₁h, w₀h, w₁h` (Yoshida's
//! triple jump, `w₁ = 1/(2 − 2^⅓)`, `w₀ = 1 − 2w₁`), fourth order as a symmetric
//! composition of a symmetric method. Its middle step runs backward (`w₀ < 0`), so a moment
//! of time is evaluated at `t + w₁h` (beyond `t + h`) and `t + (1 − w₁)h` (before `t`) too.
//! For an axisymmetric body (`κ_a = 0` or `κ_b = 0`) and torque-free motion the pieces
//! commute and the step is exact. `|H|` is conserved by every torque-free sub-flow, and so is
//! the fixed-frame momentum `q H q⁻¹`: under a moment both change only in the kicks. A body
//! given by its full tensor is integrated in its principal frame
//! ([`BodyInertia::principal_frame`]).

use super::compensated::CompensatedVector;
use super::ode::constant;
use crate::numeric::error::NumericError;
use crate::numeric::rigid_body::inertia::{BodyInertia, PrincipalFrame};
use crate::numeric::rigid_body::state::RigidBodyState;
use crate::numeric::rigid_body::torque::{AttitudeTorqueFunction, TimeTorqueFunction, Torque};
use nalgebra::{Quaternion, RealField, UnitQuaternion, Vector3};

/// A moment the splitting can kick exactly: one that does not depend on `ω`.
#[derive(Clone, Copy)]
enum Kick<'a, T: RealField + Copy> {
    None,
    /// Constant principal-frame components.
    Body(Vector3<T>),
    /// Constant fixed-frame components.
    Fixed(Vector3<T>),
    /// Body-frame components as a function of time.
    Time(&'a TimeTorqueFunction<T>),
    /// Body-frame components as a function of time and the body's attitude.
    Attitude(&'a AttitudeTorqueFunction<T>),
}

impl<T: RealField + Copy> std::fmt::Debug for Kick<'_, T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Kick::None => write!(f, "None"),
            Kick::Body(moment) => write!(f, "Body({moment:?})"),
            Kick::Fixed(moment) => write!(f, "Fixed({moment:?})"),
            Kick::Time(_) => write!(f, "Time(..)"),
            Kick::Attitude(_) => write!(f, "Attitude(..)"),
        }
    }
}

/// Angular momentum in the principal frame, the attitude of the principal frame and the time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SplittingState<T: RealField + Copy> {
    /// `H` in principal-frame components, each turn and kick added with its rounding
    /// carried ([`compensated`](super::compensated)).
    pub momentum: CompensatedVector<T, 3>,
    /// Maps principal-frame components to fixed-frame ones.
    pub orientation: UnitQuaternion<T>,
    /// The time `t` (the clock of the drift).
    pub time: T,
}

/// Order of the composition.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SplittingOrder {
    /// One Strang step.
    Second,
    /// Yoshida's triple jump of Strang steps (three per step).
    Fourth,
}

/// The splitting integrator of one body under one moment.
#[derive(Debug, Clone)]
pub struct LiePoissonSplitting<'a, T: RealField + Copy> {
    frame: PrincipalFrame<T>,
    /// Rotation principal frame → body frame as a quaternion.
    frame_rotation: UnitQuaternion<T>,
    /// Index of the middle moment `I_r`.
    reference: usize,
    /// `κ_i = 1/I_i − 1/I_r` (zero on the reference axis).
    coefficients: Vector3<T>,
    kick: Kick<'a, T>,
    order: SplittingOrder,
    /// Yoshida's weights `(w₁, w₀)` (computed once: `cbrt` costs as much as a turn).
    triple_jump: (T, T),
}

impl<'a, T: RealField + Copy> LiePoissonSplitting<'a, T> {
    /// Validates the inertia and sets up the principal frame. A [`Torque::Function`] is
    /// refused: it may depend on `ω`, and then its kick has no exact flow.
    pub fn new(
        inertia: &BodyInertia<T>,
        torque: &'a Torque<T>,
        order: SplittingOrder,
    ) -> Result<Self, NumericError> {
        inertia.validate()?;
        let frame = inertia.principal_frame()?;
        let frame_rotation = UnitQuaternion::from_rotation_matrix(&frame.rotation);
        let kick = match torque {
            Torque::None => Kick::None,
            Torque::Body(moment) => Kick::Body(frame.rotation.inverse_transform_vector(moment)),
            Torque::Fixed(moment) => Kick::Fixed(*moment),
            Torque::Time(function) => Kick::Time(function.as_ref()),
            Torque::Attitude(function) => Kick::Attitude(function.as_ref()),
            Torque::Function(_) => {
                return Err(NumericError::InvalidInput {
                    what: "torque".to_string(),
                    reason: "the splitting applies a moment as an exact kick H ← H + h·M with \
                             ω frozen, which a moment depending on ω (a torque function of the \
                             whole state) does not allow; give a moment of time or attitude \
                             alone (Torque::Time, Torque::Attitude) or use Rk4 or Dop853"
                        .to_string(),
                })
            }
        };
        let m = frame.moments;
        let mut axes_by_moment = [0usize, 1, 2];
        axes_by_moment
            .sort_by(|&a, &b| m[a].partial_cmp(&m[b]).unwrap_or(std::cmp::Ordering::Equal));
        let reference = axes_by_moment[1];
        let coefficients = m.map(|moment| moment.recip() - m[reference].recip());
        let cube_root_of_two = constant::<T>(2.0).cbrt();
        let outer = T::one() / (constant::<T>(2.0) - cube_root_of_two);
        let inner = T::one() - constant::<T>(2.0) * outer;
        Ok(Self {
            frame,
            frame_rotation,
            reference,
            coefficients,
            kick,
            order,
            triple_jump: (outer, inner),
        })
    }

    /// The splitting's variables for a body-frame state at time `time`.
    pub fn to_splitting_state(&self, time: T, state: &RigidBodyState<T>) -> SplittingState<T> {
        let omega = self.frame.rotation.inverse_transform_vector(&state.omega);
        SplittingState {
            momentum: CompensatedVector::new(omega.component_mul(&self.frame.moments)),
            orientation: state.orientation * self.frame_rotation,
            time,
        }
    }

    /// The body-frame state of the splitting's variables.
    pub fn to_rigid_body_state(&self, state: &SplittingState<T>) -> RigidBodyState<T> {
        let omega = state.momentum.value().component_div(&self.frame.moments);
        RigidBodyState {
            omega: self.frame.rotation * omega,
            orientation: state.orientation * self.frame_rotation.inverse(),
        }
    }

    /// One step of size `h` of the chosen order; the state's time ends at `time + h`.
    pub fn step(&self, state: &mut SplittingState<T>, h: T) {
        let start = state.time;
        match self.order {
            SplittingOrder::Second => self.strang_step(state, h),
            SplittingOrder::Fourth => {
                let (outer, inner) = self.triple_jump;
                self.strang_step(state, outer * h);
                self.strang_step(state, inner * h);
                self.strang_step(state, outer * h);
            }
        }
        // The sub-steps' times add up to h only to rounding.
        state.time = start + h;
    }

    /// One Strang step of size `h`.
    fn strang_step(&self, state: &mut SplittingState<T>, h: T) {
        let half = h * constant::<T>(0.5);
        let [a, b] = [(self.reference + 1) % 3, (self.reference + 2) % 3];
        self.apply_kick(state, half);
        self.turn_about_axis(state, a, half);
        self.turn_about_axis(state, b, h);
        self.turn_about_axis(state, a, half);
        self.turn_about_momentum(state, h);
        state.time += h;
        self.apply_kick(state, half);
        state.orientation.renormalize();
    }

    /// Exact flow of `½ κ_i H_i²` over `h`.
    fn turn_about_axis(&self, state: &mut SplittingState<T>, axis: usize, h: T) {
        let momentum = *state.momentum.value();
        let theta = self.coefficients[axis] * momentum[axis] * h;
        // sin θ and the versine 1 − cos θ = 2 sin²(θ/2), both to full relative accuracy:
        // the turn is applied as a small correction, so a rounded cos θ ≈ 1 cannot bias |H|.
        let (sin_half, cos_half) = (theta * constant::<T>(0.5)).sin_cos();
        let sin = constant::<T>(2.0) * sin_half * cos_half;
        let versine = constant::<T>(2.0) * sin_half * sin_half;
        let (j, k) = ((axis + 1) % 3, (axis + 2) % 3);
        let (hj, hk) = (momentum[j], momentum[k]);
        let mut change = Vector3::zeros();
        change[j] = -(versine * hj - sin * hk);
        change[k] = -(versine * hk + sin * hj);
        state.momentum.add(&change);
        // The same half angle gives the attitude's turn exp(θ e_i / 2) directly.
        let turn = Quaternion::from_parts(cos_half, Vector3::ith(axis, sin_half));
        state.orientation *= UnitQuaternion::new_unchecked(turn);
    }

    /// Exact flow of `|H|²/(2 I_r)` over `h`.
    fn turn_about_momentum(&self, state: &mut SplittingState<T>, h: T) {
        let turn = state.momentum.value() * (h / self.frame.moments[self.reference]);
        state.orientation *= UnitQuaternion::from_scaled_axis(turn);
    }

    /// Exact flow of `Ḣ = M(t, q)` (time and attitude frozen) over `h`, in principal-frame
    /// components.
    #[inline(always)]
    fn apply_kick(&self, state: &mut SplittingState<T>, h: T) {
        let moment = match self.kick {
            Kick::None => return,
            Kick::Body(moment) => moment,
            Kick::Fixed(moment) => state.orientation.inverse_transform_vector(&moment),
            Kick::Time(function) => self
                .frame
                .rotation
                .inverse_transform_vector(&function(state.time)),
            Kick::Attitude(function) => {
                let body_attitude = state.orientation * self.frame_rotation.inverse();
                self.frame
                    .rotation
                    .inverse_transform_vector(&function(state.time, &body_attitude))
            }
        };
        state.momentum.add(&(moment * h));
    }
}
