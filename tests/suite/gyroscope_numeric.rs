//! The gyroscope's equations (§18.9–18.11) against an independent computation. A body
//! turned by `R = R_Z(φ) R_x(θ) R_z(ψ)` (space components = R × body components), the
//! angles quadratic in time with the chosen rates and accelerations at t = 0: its angular
//! velocity in space from `Ṙ Rᵀ` (the skew matrix [ω]×), its angular momentum
//! `H = R diag(I', I', I) Rᵀ ω` in the fixed frame, and `Ḣ` by differentiating that in time
//! with dual numbers (exact to rounding). Expressed in Oxyz (the frame `R_Z(φ) R_x(θ)`), Ḣ
//! must equal the derived ΣM as `kinetics derive` shows it, at random states, steady or not.
//! No Euler-angle kinematics of the library is used on this side.

use kinetics::algebra::{Domains, Expr, Symbol};
use kinetics::derive_general;
use kinetics::mechanics::eulerian_angles::EulerianAngles;
use kinetics::mechanics::gyroscope::gyroscope_equations;
use kinetics::mechanics::steady_precession::{steady_precession, steady_precession_at_right_angle};
use kinetics::mechanics::torque_free_axisymmetric::{
    precession_sense, torque_free_axisymmetric, PrecessionSense,
};
use kinetics::numeric::Dual;
use num_traits::Float;
use proptest::prelude::*;

type M<T> = [[T; 3]; 3];

fn product<T: Float>(a: &M<T>, b: &M<T>) -> M<T> {
    let mut out = [[T::zero(); 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = (0..3).fold(T::zero(), |s, k| s + a[i][k] * b[k][j]);
        }
    }
    out
}

fn transpose<T: Float>(a: &M<T>) -> M<T> {
    let mut out = *a;
    for (i, row) in out.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = a[j][i];
        }
    }
    out
}

fn apply<T: Float>(a: &M<T>, v: [T; 3]) -> [T; 3] {
    [0, 1, 2].map(|i| (0..3).fold(T::zero(), |s, k| s + a[i][k] * v[k]))
}

fn about_z<T: Float>(angle: T) -> M<T> {
    let (s, c, o, l) = (angle.sin(), angle.cos(), T::zero(), T::one());
    [[c, -s, o], [s, c, o], [o, o, l]]
}

fn about_x<T: Float>(angle: T) -> M<T> {
    let (s, c, o, l) = (angle.sin(), angle.cos(), T::zero(), T::one());
    [[l, o, o], [o, c, -s], [o, s, c]]
}

/// A moment of the motion: angles, their rates and accelerations at t = 0 (φ, θ, ψ), and
/// the moments of inertia I (axial) and I' (transverse).
#[derive(Debug, Clone, Copy)]
struct State {
    angle: [f64; 3],
    rate: [f64; 3],
    acceleration: [f64; 3],
    axial: f64,
    transverse: f64,
}

impl State {
    fn angles_at<T: Float>(&self, t: T) -> [T; 3] {
        let c = |x: f64| T::from(x).expect("a float");
        [0, 1, 2]
            .map(|k| c(self.angle[k]) + c(self.rate[k]) * t + c(self.acceleration[k] / 2.0) * t * t)
    }

    fn rotation<T: Float>(&self, t: T) -> M<T> {
        let [phi, theta, psi] = self.angles_at(t);
        product(&product(&about_z(phi), &about_x(theta)), &about_z(psi))
    }

    /// H in the fixed frame at time t: ω from Ṙ Rᵀ, H = R [I_body] Rᵀ ω.
    fn momentum_in_space<T: Float>(&self, t: T) -> [T; 3] {
        let moving = self.rotation(Dual::variable(t));
        let r = moving.map(|row| row.map(|x| x.re));
        let r_dot = moving.map(|row| row.map(|x| x.eps));
        let spin = product(&r_dot, &transpose(&r));
        let omega = [spin[2][1], spin[0][2], spin[1][0]];
        let c = |x: f64| T::from(x).expect("a float");
        let (o, a, b) = (T::zero(), c(self.transverse), c(self.axial));
        let body = [[a, o, o], [o, a, o], [o, o, b]];
        let inertia = product(&product(&r, &body), &transpose(&r));
        apply(&inertia, omega)
    }

    /// Ḣ at t = 0 in the components of Oxyz (x the line of nodes, z the axis).
    fn hdot_in_oxyz(&self) -> [f64; 3] {
        let hdot = self
            .momentum_in_space(Dual::variable(0.0f64))
            .map(|h| h.eps);
        let frame = product(&about_z(self.angle[0]), &about_x(self.angle[1]));
        apply(&transpose(&frame), hdot)
    }

    /// The value of each symbol of the derived equations.
    fn value(&self, s: Symbol) -> Option<f64> {
        let [phi, theta, psi] = self.angle;
        let [phidot, thetadot, psidot] = self.rate;
        let [phiddot, thetaddot, psiddot] = self.acceleration;
        Some(match s.name() {
            "phi" => phi,
            "theta" => theta,
            "psi" => psi,
            "phidot" => phidot,
            "thetadot" => thetadot,
            "psidot" => psidot,
            "phiddot" => phiddot,
            "thetaddot" => thetaddot,
            "psiddot" => psiddot,
            "omega_z" => psidot + phidot * theta.cos(),
            "I" => self.axial,
            "I'" => self.transverse,
            _ => return None,
        })
    }

    fn eval(&self, e: &Expr) -> f64 {
        e.eval(&|s| self.value(s))
            .expect("every symbol has a value")
    }
}

fn state(steady: bool) -> impl Strategy<Value = State> {
    let angle = (-3.0f64..3.0, 0.1f64..3.0, -3.0f64..3.0);
    let rates = (-5.0f64..5.0, -5.0f64..5.0, -20.0f64..20.0);
    let accelerations = (-5.0f64..5.0, -5.0f64..5.0, -5.0f64..5.0);
    // A real body: I ≤ 2I' (I_z ≤ I_x + I_y).
    let moments = (0.1f64..3.0, 0.05f64..1.0);
    (angle, rates, accelerations, moments).prop_map(move |(a, r, acc, (t, f))| {
        let rate = [r.0, if steady { 0.0 } else { r.1 }, r.2];
        let acceleration = if steady {
            [0.0; 3]
        } else {
            [acc.0, acc.1, acc.2]
        };
        State {
            angle: [a.0, a.1, a.2],
            rate,
            acceleration,
            axial: 2.0 * t * f,
            transverse: t,
        }
    })
}

/// The relations `SumM_x`, `SumM_y`, `SumM_z` of a catalogue derivation as shown: those of
/// its last step that has all three.
fn shown_moments(name: &str) -> Vec<Expr> {
    let shown = derive_general(name, false)
        .expect("a catalogue name")
        .expect("derived")
        .simplified(&Domains::chapter_defaults());
    let of_step = |step: &kinetics::mechanics::Step| -> Vec<Expr> {
        step.relations
            .iter()
            .filter(|r| r.lhs.to_string().starts_with("SumM_"))
            .map(|r| r.rhs.clone())
            .collect()
    };
    shown
        .steps
        .iter()
        .rev()
        .map(of_step)
        .find(|moments| moments.len() == 3)
        .expect("a step with the three component equations")
}

fn assert_close(derived: [f64; 3], independent: [f64; 3], what: &str) {
    let scale = 1.0 + independent.iter().map(|x| x.abs()).fold(0.0, f64::max);
    for k in 0..3 {
        assert!(
            (derived[k] - independent[k]).abs() <= 1e-10 * scale,
            "{what}, component {k}: derived {derived:?}, from the rotating body {independent:?}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// The general equations, as printed (in ω_z) and in the angles alone, at any state.
    #[test]
    fn the_general_equations_are_the_rate_of_angular_momentum(s in state(false)) {
        let independent = s.hdot_in_oxyz();
        let shown = shown_moments("gyroscope");
        assert_close([0, 1, 2].map(|k| s.eval(&shown[k])), independent, "as shown");
        let (gyro, _) = gyroscope_equations(&EulerianAngles::chapter(), "O").unwrap();
        assert_close([0, 1, 2].map(|k| s.eval(&gyro.moments[k])), independent, "in the angles");
    }

    /// Steady precession: the substituted equations at a steady state.
    #[test]
    fn steady_precession_needs_the_rate_of_angular_momentum(s in state(true)) {
        let independent = s.hdot_in_oxyz();
        let shown = shown_moments("steady_precession");
        assert_close([0, 1, 2].map(|k| s.eval(&shown[k])), independent, "steady");
        let at_right_angle = State { angle: [s.angle[0], std::f64::consts::FRAC_PI_2, s.angle[2]], ..s };
        let (moment, _) = steady_precession_at_right_angle(&EulerianAngles::chapter(), "O").unwrap();
        let moment = at_right_angle.eval(&moment);
        assert_close([moment, 0.0, 0.0], at_right_angle.hdot_in_oxyz(), "at 90 degrees");
    }

    /// Under no force, ω from the derived φ̇ and ψ̇ gives H = [I]ω along K; γ is the angle of
    /// ω from the axis, θ − γ its angle from K; the sense from I' − I; and the
    /// steady-precession moment at the derived φ̇ is zero.
    #[test]
    fn torque_free_motion_keeps_h_along_the_vertical(
        theta in 0.05f64..1.5,
        omega_z in -20.0f64..20.0,
        (transverse_milli, fraction) in (100i64..3000, 0.01f64..1.0),
    ) {
        prop_assume!(omega_z.abs() > 0.1);
        // Moments in thousandths, so that the sense is decided from exact numbers too.
        let axial_milli = ((2 * transverse_milli) as f64 * fraction).round().max(1.0) as i64;
        let (axial, transverse) = (axial_milli as f64 / 1e3, transverse_milli as f64 / 1e3);
        let (free, _) = torque_free_axisymmetric(&EulerianAngles::chapter()).unwrap();
        let value = |s: Symbol| match s.name() {
            "theta" => Some(theta),
            "omega_z" => Some(omega_z),
            "I" => Some(axial),
            "I'" => Some(transverse),
            _ => None,
        };
        let phidot = free.precession_rate.eval(&value).unwrap();
        let psidot = free.spin_rate.eval(&value).unwrap();
        let h = free.angular_momentum.eval(&value).unwrap();
        // ω in Oxyz from the rates alone (θ̇ = 0), and H = [I]ω.
        let omega = [0.0, phidot * theta.sin(), psidot + phidot * theta.cos()];
        prop_assert!((omega[2] - omega_z).abs() <= 1e-14 * omega_z.abs());
        let momentum = [0.0, transverse * omega[1], axial * omega[2]];
        let vertical = [0.0, theta.sin(), theta.cos()];
        let norm = momentum[1].hypot(momentum[2]);
        let across = momentum[1] * vertical[2] - momentum[2] * vertical[1];
        prop_assert!(across.abs() <= 1e-14 * norm, "H x K = {across}, |H| = {norm}");
        prop_assert!((h - (momentum[1] * vertical[1] + momentum[2] * vertical[2])).abs() <= 1e-13 * norm);
        // γ from the vectors: the angle of ω from z (ω in the half-plane of K from z).
        let gamma = (omega[1] / omega[2]).atan();
        let tan_gamma = free.tan_gamma.eval(&value).unwrap();
        prop_assert!((gamma.tan() - tan_gamma).abs() <= 1e-12 * (1.0 + tan_gamma.abs()));
        // The space cone: the angle between ω and K is |θ − γ| (γ as the angle in [0, 90°)).
        let gamma = gamma.abs();
        let cosine = (omega[1] * vertical[1] + omega[2] * vertical[2]).abs()
            / omega[1].hypot(omega[2]);
        prop_assert!((cosine.min(1.0).acos() - (theta - gamma).abs()).abs() <= 1e-7);
        let sense = precession_sense(
            &Expr::rational(axial_milli, 1000),
            &Expr::rational(transverse_milli, 1000),
            &Domains::chapter_defaults(),
        );
        if transverse > axial {
            prop_assert_eq!(sense, Some(PrecessionSense::Direct));
            prop_assert!(gamma < theta && phidot * psidot > 0.0);
        } else if transverse < axial {
            prop_assert_eq!(sense, Some(PrecessionSense::Retrograde));
            prop_assert!(gamma > theta && phidot * psidot < 0.0);
        }
        // No moment is needed for this precession: the steady equation at these rates.
        let (steady, _) = steady_precession(&EulerianAngles::chapter(), "G").unwrap();
        let moment = steady[0].eval(&|s| match s.name() {
            "phidot" => Some(phidot),
            other => value(Symbol::new(other)),
        }).unwrap();
        prop_assert!(moment.abs() <= 1e-12 * transverse * phidot * phidot + 1e-12 * norm * phidot.abs());
    }
}

/// Equal moments: ψ̇ = 0 and the sense says so; symbols alone leave it undecided.
#[test]
fn equal_moments_do_not_precess_relative_to_the_body() {
    let i = Expr::rational(3, 2);
    let defaults = Domains::chapter_defaults();
    assert_eq!(
        precession_sense(&i, &i, &defaults),
        Some(PrecessionSense::EqualMoments)
    );
    let (free, _) = torque_free_axisymmetric(&EulerianAngles::chapter()).unwrap();
    let spin = free
        .spin_rate
        .subs(&|s| (s.name() == "I'").then(|| Expr::symbol("I")))
        .unwrap();
    assert!(spin.expand().unwrap().is_zero());
    assert_eq!(
        precession_sense(&Expr::symbol("I"), &Expr::symbol("I'"), &defaults),
        None
    );
}
