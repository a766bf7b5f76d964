//! Dormand–Prince 8(5,3): the explicit Runge–Kutta pair of order 8 with adaptive step size
//! control and a continuous extension of order 7, after Hairer's `DOP853` (Hairer, Nørsett
//! & Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., section II.10).
//!
//! A step of size `h` takes 12 stages `kᵢ = f(t + cᵢh, y + h Σⱼ aᵢⱼ kⱼ)` and advances
//! `y₁ = y + h Σ bᵢ kᵢ` (order 8). Two embedded estimates, `err₅ = h Σ e⁵ᵢ kᵢ` (order 5)
//! and `err₃ = h Σ (bᵢ − b̂ᵢ) kᵢ` (order 3), are combined as in Hairer's code:
//!
//! ```text
//! sᵢ = atol + rtol · max(|yᵢ|, |y₁ᵢ|)
//! err = |h| Σ(err₅ᵢ/sᵢ)² / sqrt(n (Σ(err₅ᵢ/sᵢ)² + 0.01 Σ(err₃ᵢ/sᵢ)²))
//! ```
//!
//! The step is accepted when `err ≤ 1`; the next step is `h / clamp(err^⅛ / 0.9, 1/6, 3)`,
//! and after a rejection it may not grow. The derivative at the end of an accepted step is
//! the first stage of the next (FSAL). The initial step follows Hairer's `HINIT`, measured in
//! the problem's own time unit so that a body spinning at 1e150 or 1e-150 rad/s starts as one
//! spinning at 1 rad/s; the norms and the error estimate are scaled before squaring.
//!
//! Dense output: three more stages give a degree-7 polynomial on each accepted step, so
//! samples at any time inside the step are interpolated to the accuracy of the method.
//! They are evaluated only when a sample falls inside the step. Integration runs forward
//! in time; stages see the true time `t + cᵢh`, so time-dependent right-hand sides are
//! handled exactly as autonomous ones.

// The coefficients are kept with the digits Hairer published, beyond f64 resolution.
#![allow(clippy::excessive_precision)]

use super::ode::{constant, to_f64, OdeSystem};
use crate::numeric::error::NumericError;
use nalgebra::{RealField, SVector};

/// Number of stages of the method proper (the 13th evaluation is the FSAL derivative).
const STAGES: usize = 12;
/// Stages including the three of the continuous extension.
const EXTENDED_STAGES: usize = 16;
/// Step-size controller: safety factor and the bounds of the step-size ratio.
const SAFETY: f64 = 0.9;
const MIN_RATIO: f64 = 1.0 / 3.0;
const MAX_RATIO: f64 = 6.0;
/// Default budget of steps (accepted and rejected) of one integration.
pub const DEFAULT_MAX_STEPS: usize = 10_000_000;

/// Nodes `cᵢ`.
const C: [f64; EXTENDED_STAGES] = [
    0.0,
    0.526001519587677318785587544488e-01,
    0.789002279381515978178381316732e-01,
    0.118350341907227396726757197510,
    0.281649658092772603273242802490,
    0.333333333333333333333333333333,
    0.25,
    0.307692307692307692307692307692,
    0.651282051282051282051282051282,
    0.6,
    0.857142857142857142857142857142,
    1.0,
    1.0,
    0.1,
    0.2,
    0.777777777777777777777777777778,
];

/// Coupling coefficients `aᵢⱼ`, row by row, as `(j, aᵢⱼ)` for the non-zero entries. Row 12
/// holds the weights `bⱼ` of the eighth-order solution.
const A: [&[(usize, f64)]; EXTENDED_STAGES] = [
    &[],
    &[(0, 5.26001519587677318785587544488e-2)],
    &[
        (0, 1.97250569845378994544595329183e-2),
        (1, 5.91751709536136983633785987549e-2),
    ],
    &[
        (0, 2.95875854768068491816892993775e-2),
        (2, 8.87627564304205475450678981324e-2),
    ],
    &[
        (0, 2.41365134159266685502369798665e-1),
        (2, -8.84549479328286085344864962717e-1),
        (3, 9.24834003261792003115737966543e-1),
    ],
    &[
        (0, 3.7037037037037037037037037037e-2),
        (3, 1.70828608729473871279604482173e-1),
        (4, 1.25467687566822425016691814123e-1),
    ],
    &[
        (0, 3.7109375e-2),
        (3, 1.70252211019544039314978060272e-1),
        (4, 6.02165389804559606850219397283e-2),
        (5, -1.7578125e-2),
    ],
    &[
        (0, 3.70920001185047927108779319836e-2),
        (3, 1.70383925712239993810214054705e-1),
        (4, 1.07262030446373284651809199168e-1),
        (5, -1.53194377486244017527936158236e-2),
        (6, 8.27378916381402288758473766002e-3),
    ],
    &[
        (0, 6.24110958716075717114429577812e-1),
        (3, -3.36089262944694129406857109825),
        (4, -8.68219346841726006818189891453e-1),
        (5, 2.75920996994467083049415600797e1),
        (6, 2.01540675504778934086186788979e1),
        (7, -4.34898841810699588477366255144e1),
    ],
    &[
        (0, 4.77662536438264365890433908527e-1),
        (3, -2.48811461997166764192642586468),
        (4, -5.90290826836842996371446475743e-1),
        (5, 2.12300514481811942347288949897e1),
        (6, 1.52792336328824235832596922938e1),
        (7, -3.32882109689848629194453265587e1),
        (8, -2.03312017085086261358222928593e-2),
    ],
    &[
        (0, -9.3714243008598732571704021658e-1),
        (3, 5.18637242884406370830023853209),
        (4, 1.09143734899672957818500254654),
        (5, -8.14978701074692612513997267357),
        (6, -1.85200656599969598641566180701e1),
        (7, 2.27394870993505042818970056734e1),
        (8, 2.49360555267965238987089396762),
        (9, -3.0467644718982195003823669022),
    ],
    &[
        (0, 2.27331014751653820792359768449),
        (3, -1.05344954667372501984066689879e1),
        (4, -2.00087205822486249909675718444),
        (5, -1.79589318631187989172765950534e1),
        (6, 2.79488845294199600508499808837e1),
        (7, -2.85899827713502369474065508674),
        (8, -8.87285693353062954433549289258),
        (9, 1.23605671757943030647266201528e1),
        (10, 6.43392746015763530355970484046e-1),
    ],
    &[
        (0, 5.42937341165687622380535766363e-2),
        (5, 4.45031289275240888144113950566),
        (6, 1.89151789931450038304281599044),
        (7, -5.8012039600105847814672114227),
        (8, 3.1116436695781989440891606237e-1),
        (9, -1.52160949662516078556178806805e-1),
        (10, 2.01365400804030348374776537501e-1),
        (11, 4.47106157277725905176885569043e-2),
    ],
    &[
        (0, 5.61675022830479523392909219681e-2),
        (6, 2.53500210216624811088794765333e-1),
        (7, -2.46239037470802489917441475441e-1),
        (8, -1.24191423263816360469010140626e-1),
        (9, 1.5329179827876569731206322685e-1),
        (10, 8.20105229563468988491666602057e-3),
        (11, 7.56789766054569976138603589584e-3),
        (12, -8.298e-3),
    ],
    &[
        (0, 3.18346481635021405060768473261e-2),
        (5, 2.83009096723667755288322961402e-2),
        (6, 5.35419883074385676223797384372e-2),
        (7, -5.49237485713909884646569340306e-2),
        (10, -1.08347328697249322858509316994e-4),
        (11, 3.82571090835658412954920192323e-4),
        (12, -3.40465008687404560802977114492e-4),
        (13, 1.41312443674632500278074618366e-1),
    ],
    &[
        (0, -4.28896301583791923408573538692e-1),
        (5, -4.69762141536116384314449447206),
        (6, 7.68342119606259904184240953878),
        (7, 4.06898981839711007970213554331),
        (8, 3.56727187455281109270669543021e-1),
        (12, -1.39902416515901462129418009734e-3),
        (13, 2.9475147891527723389556272149),
        (14, -9.15095847217987001081870187138),
    ],
];

/// Weights `b̂ⱼ` of the third-order embedded solution that differ from zero; the
/// third-order estimate is `Σ (bⱼ − b̂ⱼ) kⱼ`.
const B_HAT_3: [(usize, f64); 3] = [
    (0, 0.244094488188976377952755905512),
    (8, 0.733846688281611857341361741547),
    (11, 0.220588235294117647058823529412e-1),
];

/// Coefficients `e⁵ⱼ` of the fifth-order error estimate.
const E5: [(usize, f64); 8] = [
    (0, 0.1312004499419488073250102996e-1),
    (5, -0.1225156446376204440720569753e1),
    (6, -0.4957589496572501915214079952),
    (7, 0.1664377182454986536961530415e1),
    (8, -0.3503288487499736816886487290),
    (9, 0.3341791187130174790297318841),
    (10, 0.8192320648511571246570742613e-1),
    (11, -0.2235530786388629525884427845e-1),
];

/// Coefficients of the four highest terms of the continuous extension, over the stages
/// `0, 5, 6, …, 15`.
const D: [[f64; 12]; 4] = [
    [
        -0.84289382761090128651353491142e1,
        0.56671495351937776962531783590,
        -0.30689499459498916912797304727e1,
        0.23846676565120698287728149680e1,
        0.21170345824450282767155149946e1,
        -0.87139158377797299206789907490,
        0.22404374302607882758541771650e1,
        0.63157877876946881815570249290,
        -0.88990336451333310820698117400e-1,
        0.18148505520854727256656404962e2,
        -0.91946323924783554000451984436e1,
        -0.44360363875948939664310572000e1,
    ],
    [
        0.10427508642579134603413151009e2,
        0.24228349177525818288430175319e3,
        0.16520045171727028198505394887e3,
        -0.37454675472269020279518312152e3,
        -0.22113666853125306036270938578e2,
        0.77334326684722638389603898808e1,
        -0.30674084731089398182061213626e2,
        -0.93321305264302278729567221706e1,
        0.15697238121770843886131091075e2,
        -0.31139403219565177677282850411e2,
        -0.93529243588444783865713862664e1,
        0.35816841486394083752465898540e2,
    ],
    [
        0.19985053242002433820987653617e2,
        -0.38703730874935176555105901742e3,
        -0.18917813819516756882830838328e3,
        0.52780815920542364900561016686e3,
        -0.11573902539959630126141871134e2,
        0.68812326946963000169666922661e1,
        -0.10006050966910838403183860980e1,
        0.77771377980534432092869265740,
        -0.27782057523535084065932004339e1,
        -0.60196695231264120758267380846e2,
        0.84320405506677161018159903784e2,
        0.11992291136182789328035130030e2,
    ],
    [
        -0.25693933462703749003312586129e2,
        -0.15418974869023643374053993627e3,
        -0.23152937917604549567536039109e3,
        0.35763911791061412378285349910e3,
        0.93405324183624310003907691704e2,
        -0.37458323136451633156875139351e2,
        0.10409964950896230045147246184e3,
        0.29840293426660503123344363579e2,
        -0.43533456590011143754432175058e2,
        0.96324553959188282948394950600e2,
        -0.39177261675615439165231486172e2,
        -0.14972683625798562581422125276e3,
    ],
];

/// The stages the rows of [`D`] run over.
const D_STAGES: [usize; 12] = [0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15];

/// Tolerances and step budget of [`Dop853`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dop853Settings<T> {
    /// Relative tolerance; at least 10 machine epsilons of the scalar.
    pub rtol: T,
    /// Absolute tolerance, non-negative.
    pub atol: T,
    /// Most steps (accepted and rejected) one integration may take.
    pub max_steps: usize,
}

impl<T: RealField + Copy> Dop853Settings<T> {
    /// Tolerances with the [`DEFAULT_MAX_STEPS`] budget.
    pub fn new(rtol: T, atol: T) -> Self {
        Self {
            rtol,
            atol,
            max_steps: DEFAULT_MAX_STEPS,
        }
    }

    /// Checks the tolerances: `rtol ≥ 10 ε` and finite, `atol ≥ 0` and finite, at least
    /// one step allowed.
    pub fn validate(&self) -> Result<(), NumericError> {
        let invalid = |what: &str, reason: String| {
            Err(NumericError::InvalidInput {
                what: what.to_string(),
                reason,
            })
        };
        let smallest_rtol = T::default_epsilon() * constant(10.0);
        if !self.rtol.is_finite() || self.rtol < smallest_rtol {
            return invalid(
                "rtol",
                format!(
                    "{} must be finite and at least 10 machine epsilons ({:e})",
                    to_f64(self.rtol),
                    to_f64(smallest_rtol)
                ),
            );
        }
        if !self.atol.is_finite() || self.atol < T::zero() {
            return invalid(
                "atol",
                format!("{} must be finite and non-negative", to_f64(self.atol)),
            );
        }
        if self.max_steps == 0 {
            return invalid("max_steps", "at least one step must be allowed".to_string());
        }
        Ok(())
    }
}

/// Counters of an integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Dop853Statistics {
    /// Steps whose error estimate passed.
    pub accepted_steps: usize,
    /// Steps retried with a smaller size.
    pub rejected_steps: usize,
    /// Evaluations of the right-hand side, dense-output stages included.
    pub evaluations: usize,
}

/// The integrator between steps: the current point, the last accepted step (kept for dense
/// output) and the controller's memory.
#[derive(Debug, Clone)]
pub struct Dop853<T: RealField + Copy, const N: usize> {
    settings: Dop853Settings<T>,
    t_end: T,
    t: T,
    y: SVector<T, N>,
    /// `f(t, y)`, the first stage of the next step.
    derivative: SVector<T, N>,
    /// Proposed size of the next step.
    step: T,
    /// Start, state and size of the last accepted step.
    t_old: T,
    y_old: SVector<T, N>,
    last_step: T,
    stages: [SVector<T, N>; EXTENDED_STAGES],
    /// Coefficients of the continuous extension of the last step, once computed.
    dense: Option<[SVector<T, N>; 7]>,
    last_rejected: bool,
    statistics: Dop853Statistics,
}

impl<T: RealField + Copy, const N: usize> Dop853<T, N> {
    /// Prepares an integration of `system` from `(t0, y0)` forward to `t_end > t0`.
    pub fn new<S: OdeSystem<T, N> + ?Sized>(
        system: &S,
        t0: T,
        y0: SVector<T, N>,
        t_end: T,
        settings: Dop853Settings<T>,
    ) -> Result<Self, NumericError> {
        settings.validate()?;
        if !(t0.is_finite() && t_end.is_finite() && t_end > t0) {
            return Err(NumericError::InvalidInput {
                what: "time interval".to_string(),
                reason: format!(
                    "from {} to {}: both must be finite and the end after the start",
                    to_f64(t0),
                    to_f64(t_end)
                ),
            });
        }
        let derivative = system.derivative(t0, &y0);
        let mut integrator = Self {
            settings,
            t_end,
            t: t0,
            y: y0,
            derivative,
            step: T::zero(),
            t_old: t0,
            y_old: y0,
            last_step: T::zero(),
            stages: [SVector::zeros(); EXTENDED_STAGES],
            dense: None,
            last_rejected: false,
            statistics: Dop853Statistics {
                evaluations: 1,
                ..Default::default()
            },
        };
        integrator.step = integrator.initial_step(system);
        Ok(integrator)
    }

    /// Current time.
    pub fn t(&self) -> T {
        self.t
    }

    /// Current state.
    pub fn y(&self) -> &SVector<T, N> {
        &self.y
    }

    /// Steps and evaluations so far.
    pub fn statistics(&self) -> Dop853Statistics {
        self.statistics
    }

    /// Error-scaled norm `sqrt(Σ(vᵢ/sᵢ)²)` with weights `sᵢ = atol + rtol |yᵢ|`, computed
    /// without overflow or underflow (see [`scaled_norm`]): for a derivative the ratios are
    /// rates, `1/rtol` times the problem's frequency, and for a body spinning at 1e150 rad/s
    /// their squares overflowed (a zero first step).
    fn weighted_norm(&self, v: &SVector<T, N>, y: &SVector<T, N>) -> T {
        scaled_norm(&v.zip_map(y, |vi, yi| {
            vi / (self.settings.atol + self.settings.rtol * yi.abs())
        }))
    }

    /// Hairer's starting step (`HINIT`), measured in the problem's own time unit `τ`.
    ///
    /// `HINIT` compares the weighted norms `d₁ = ‖f₀‖` (per unit time) and
    /// `d₂ ≈ ‖y''‖` (per unit time squared) with absolute constants and falls back to an
    /// absolute `1e-6`, all in the caller's unit of time. For a body spinning at 1e150 rad/s
    /// `d₂` is about 1e311 s⁻², not representable, and the first step was zero (a step-size
    /// underflow at `t = 0`); at 1e-150 rad/s the start was `1e-6` s against a natural step
    /// near 1e149 s, and climbing to it took about two hundred extra steps (577 instead of
    /// 379 for the body of `tests/simulate_extreme_momentum.rs`). Here the same rules run in
    /// the unit `τ`:
    /// * `τ = d₀/d₁`, with `d₀ = ‖y₀‖`: the time in which the initial rate changes the state
    ///   by its own weighted size (Hairer's trial step is `0.01 τ` already);
    /// * `τ = 1/d₁` when the state is below its tolerances (`d₀ ≤ 1e-5`): the time to move by
    ///   one tolerance;
    /// * `τ = t_end − t₀` when nothing moves (`d₁ = 0`) or `τ` is not representable.
    ///
    /// In that unit `d₁τ`, `d₂τ²` and the steps are the same numbers whatever the problem's
    /// time scale (exactly so when it is scaled by a power of two, with `atol = 0`), and for a
    /// problem whose natural unit is the caller's the rules are Hairer's: make the explicit
    /// Euler step's change and the estimated second derivative's contribution small, bounded
    /// by the whole interval.
    fn initial_step<S: OdeSystem<T, N> + ?Sized>(&mut self, system: &S) -> T {
        let max_step = self.t_end - self.t;
        let state_norm = self.weighted_norm(&self.y, &self.y);
        let derivative_norm = self.weighted_norm(&self.derivative, &self.y);
        let tiny = constant::<T>(1e-5);
        let own_unit = if state_norm > tiny {
            state_norm / derivative_norm
        } else {
            derivative_norm.recip()
        };
        let unit = if own_unit.is_finite() && own_unit > T::zero() {
            own_unit
        } else {
            max_step
        };
        // Hairer's HINIT on the quantities in the unit `τ`; steps `h` are in that unit.
        let max_step_in_unit = max_step / unit;
        let derivative_norm = derivative_norm * unit;
        let mut h = if derivative_norm <= tiny || state_norm <= tiny {
            constant(1e-6)
        } else {
            state_norm / derivative_norm * constant(0.01)
        };
        h = h.min(max_step_in_unit);
        let euler = self.y + self.derivative * (h * unit);
        let derivative_after = system.derivative(self.t + h * unit, &euler);
        self.statistics.evaluations += 1;
        // ‖Δf‖ / (h τ) is the second derivative per unit time squared; times τ².
        let second = self.weighted_norm(&(derivative_after - self.derivative), &self.y) * unit / h;
        let scale = second.max(derivative_norm);
        let by_second = if scale <= constant(1e-15) {
            (h * constant(1e-3)).max(constant(1e-6))
        } else {
            (constant::<T>(0.01) / scale).powf(constant(1.0 / 8.0))
        };
        (h * constant(100.0)).min(by_second).min(max_step_in_unit) * unit
    }

    /// `y + h Σⱼ aᵢⱼ kⱼ` for stage `i` of a step of size `h` from `y`.
    fn stage_point(&self, stage: usize, y: &SVector<T, N>, h: T) -> SVector<T, N> {
        let mut sum = SVector::<T, N>::zeros();
        for &(j, a) in A[stage] {
            sum += self.stages[j] * constant::<T>(a);
        }
        y + sum * h
    }

    /// Evaluates the stages `range` of a step of size `h` from `(t, y)`.
    fn evaluate_stages<S: OdeSystem<T, N> + ?Sized>(
        &mut self,
        system: &S,
        range: std::ops::Range<usize>,
        t: T,
        y: &SVector<T, N>,
        h: T,
    ) {
        self.statistics.evaluations += range.len();
        for stage in range {
            let point = self.stage_point(stage, y, h);
            self.stages[stage] = system.derivative(t + constant::<T>(C[stage]) * h, &point);
        }
    }

    /// Takes one accepted step, never past the end time; rejected attempts are retried
    /// with a smaller step.
    pub fn step<S: OdeSystem<T, N> + ?Sized>(&mut self, system: &S) -> Result<(), NumericError> {
        if self.t >= self.t_end {
            return Err(NumericError::InvalidInput {
                what: "step".to_string(),
                reason: format!(
                    "the integration already reached its end {}",
                    to_f64(self.t_end)
                ),
            });
        }
        self.dense = None;
        self.stages[0] = self.derivative;
        let uround = T::default_epsilon();
        loop {
            let attempts = self.statistics.accepted_steps + self.statistics.rejected_steps;
            if attempts >= self.settings.max_steps {
                return Err(NumericError::StepLimit {
                    max_steps: self.settings.max_steps,
                    t: to_f64(self.t),
                });
            }
            let resolvable = self.step.abs() * constant(0.1) > self.t.abs() * uround;
            if !resolvable || !self.step.is_finite() {
                return Err(NumericError::StepSizeUnderflow {
                    t: to_f64(self.t),
                    step: to_f64(self.step),
                });
            }
            let remaining = self.t_end - self.t;
            let last = self.step * constant(1.01) >= remaining;
            let h = if last { remaining } else { self.step };
            let (t, y) = (self.t, self.y);
            self.evaluate_stages(system, 1..STAGES, t, &y, h);
            let mut y_new = self.stage_point(STAGES, &y, h);
            let error = self.error_norm(&y_new, h);
            // err^⅛ as three square roots, much cheaper than a power.
            let error_root = error.sqrt().sqrt().sqrt();
            if error <= T::one() {
                let ratio = (error_root / constant(SAFETY))
                    .max(constant(1.0 / MAX_RATIO))
                    .min(constant(1.0 / MIN_RATIO));
                let mut next = h / ratio;
                if self.last_rejected {
                    next = next.min(h);
                }
                system.project(&mut y_new);
                let t_new = if last { self.t_end } else { self.t + h };
                let derivative = system.derivative(t_new, &y_new);
                self.statistics.evaluations += 1;
                self.statistics.accepted_steps += 1;
                self.stages[STAGES] = derivative;
                self.t_old = self.t;
                self.y_old = self.y;
                self.last_step = h;
                self.t = t_new;
                self.y = y_new;
                self.derivative = derivative;
                self.step = next;
                self.last_rejected = false;
                if !y_new.iter().all(|v| v.is_finite()) {
                    return Err(NumericError::NonFinite { t: to_f64(t_new) });
                }
                return Ok(());
            }
            // Rejected (a non-finite estimate counts as a failure by the largest factor).
            let ratio = if error.is_finite() {
                (error_root / constant(SAFETY)).min(constant(1.0 / MIN_RATIO))
            } else {
                constant(1.0 / MIN_RATIO)
            };
            self.step = h / ratio;
            self.last_rejected = true;
            self.statistics.rejected_steps += 1;
        }
    }

    /// Hairer's combined 5th/3rd-order error estimate of a step (≤ 1 means accept), in the
    /// form `err = Σaᵢ² / sqrt(n (Σaᵢ² + 0.01 Σbᵢ²))` with `aᵢ = h err₅ᵢ / sᵢ` and
    /// `bᵢ = h err₃ᵢ / sᵢ`: the module's formula with `|h|` taken inside the sums (`h > 0`).
    ///
    /// `err₅ᵢ/sᵢ` is a rate (per unit time), `1/h` for a step at its tolerance: for a body
    /// spinning at 1e150 rad/s its square overflowed as soon as a trial step missed its
    /// tolerance by a factor of about 1e4, and the estimate `inf/inf` cut the step by the
    /// largest factor instead of by its error. The `aᵢ, bᵢ` are dimensionless and near 1 for
    /// a step near acceptance; `h` multiplies the coefficients (not the sums, which for a slow
    /// body's tiny derivatives could fall into subnormals first), and where their squares
    /// overflow or vanish the `aᵢ, bᵢ` are divided by the largest before squaring, so no
    /// estimate overflows or underflows.
    fn error_norm(&self, y_new: &SVector<T, N>, h: T) -> T {
        let mut err5 = SVector::<T, N>::zeros();
        for &(j, e) in &E5 {
            err5 += self.stages[j] * (constant::<T>(e) * h);
        }
        let mut err3 = y_new - self.y;
        for &(j, b) in &B_HAT_3 {
            err3 -= self.stages[j] * (constant::<T>(b) * h);
        }
        let weights = self.y.zip_map(y_new, |y, y_new| {
            self.settings.atol + self.settings.rtol * y.abs().max(y_new.abs())
        });
        let (a, b) = (err5.component_div(&weights), err3.component_div(&weights));
        let (sum5, sum3) = (a.norm_squared(), b.norm_squared());
        if sum5 > T::zero() && sum5.is_finite() && sum3.is_finite() {
            // The usual case: squares of numbers near one. Rescaling them first (below)
            // costs two dozen divisions a step, 18% of an attitude run at rtol 1e-12.
            return sum5 / ((sum5 + sum3 * constant(0.01)) * constant(N as f64)).sqrt();
        }
        let largest = largest_magnitude(a.iter().chain(b.iter()));
        if largest == T::zero() || !largest.is_finite() {
            // A zero estimate is a perfect step; a non-finite one fails.
            return largest;
        }
        let sum5 = a.unscale(largest).norm_squared();
        let sum3 = b.unscale(largest).norm_squared();
        largest * sum5 / ((sum5 + sum3 * constant(0.01)) * constant(N as f64)).sqrt()
    }

    /// The solution at `t` inside the last accepted step `[t_old, t_now]`, from the
    /// seventh-order continuous extension (times outside are clamped to the step). Before
    /// the first step it is the initial state.
    pub fn dense_output<S: OdeSystem<T, N> + ?Sized>(&mut self, system: &S, t: T) -> SVector<T, N> {
        if t == self.t || self.statistics.accepted_steps == 0 {
            return self.y;
        }
        let coefficients = match self.dense {
            Some(coefficients) => coefficients,
            None => {
                let coefficients = self.continuous_extension(system);
                self.dense = Some(coefficients);
                coefficients
            }
        };
        let h = self.last_step;
        let theta = ((t - self.t_old) / h).max(T::zero()).min(T::one());
        let complement = T::one() - theta;
        // y_old + θ(F₀ + (1−θ)(F₁ + θ(F₂ + (1−θ)(F₃ + θ(F₄ + (1−θ)(F₅ + θF₆))))))
        let mut sum = coefficients[6];
        for (k, coefficient) in coefficients[..6].iter().enumerate().rev() {
            let factor = if k % 2 == 1 { theta } else { complement };
            sum = coefficient + sum * factor;
        }
        self.y_old + sum * theta
    }

    /// The three extra stages and the seven vector coefficients of the interpolant.
    fn continuous_extension<S: OdeSystem<T, N> + ?Sized>(
        &mut self,
        system: &S,
    ) -> [SVector<T, N>; 7] {
        let h = self.last_step;
        let (t_old, y_old) = (self.t_old, self.y_old);
        self.evaluate_stages(system, STAGES + 1..EXTENDED_STAGES, t_old, &y_old, h);
        let delta = self.y - self.y_old;
        let f_old = self.stages[0];
        let mut coefficients = [SVector::<T, N>::zeros(); 7];
        coefficients[0] = delta;
        coefficients[1] = f_old * h - delta;
        coefficients[2] = delta * constant::<T>(2.0) - (self.derivative + f_old) * h;
        for (row, d) in D.iter().enumerate() {
            let mut sum = SVector::<T, N>::zeros();
            for (&j, &coefficient) in D_STAGES.iter().zip(d) {
                sum += self.stages[j] * constant::<T>(coefficient);
            }
            coefficients[3 + row] = sum * h;
        }
        coefficients
    }
}

/// The 2-norm of `v` without overflow or underflow: the components are divided by the
/// largest magnitude before squaring (and the norm of a vector scaled by a power of two is
/// scaled exactly). Zero for a zero vector; not finite when a component is not.
fn scaled_norm<T: RealField + Copy, const N: usize>(v: &SVector<T, N>) -> T {
    let largest = largest_magnitude(v.iter());
    if largest == T::zero() || !largest.is_finite() {
        return largest;
    }
    v.unscale(largest).norm() * largest
}

/// The largest `|vᵢ|`; not finite if a component is not (where a plain maximum would skip
/// a NaN).
fn largest_magnitude<'a, T: RealField + Copy>(v: impl Iterator<Item = &'a T>) -> T {
    v.fold(T::zero(), |largest, x| {
        let x = x.abs();
        if !largest.is_finite() {
            return largest;
        }
        match x.partial_cmp(&largest) {
            // `None`: x is NaN.
            Some(std::cmp::Ordering::Greater) | None => x,
            _ => largest,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each row of the tableau must sum to its node (the stages are consistent), the
    /// weights of the solution to 1 and the error weights to 0; a mistyped coefficient
    /// breaks one of these.
    #[test]
    fn tableau_is_consistent() {
        for (i, row) in A.iter().enumerate().skip(1) {
            let sum: f64 = row.iter().map(|&(_, a)| a).sum();
            let node = if i == STAGES { 1.0 } else { C[i] };
            assert!((sum - node).abs() < 1e-14, "row {i}: {sum} vs {node}");
        }
        let hat: f64 = B_HAT_3.iter().map(|&(_, b)| b).sum();
        assert!(
            (hat - 1.0).abs() < 1e-14,
            "third-order weights sum to {hat}"
        );
        let e5: f64 = E5.iter().map(|&(_, e)| e).sum();
        assert!(e5.abs() < 1e-14, "fifth-order error weights sum to {e5}");
    }

    /// `y' = (y₂, −y₁)`, a rotation, for a stepper to hold.
    struct Rotation;

    impl OdeSystem<f64, 2> for Rotation {
        fn derivative(&self, _t: f64, y: &SVector<f64, 2>) -> SVector<f64, 2> {
            SVector::<f64, 2>::new(y[1], -y[0])
        }
    }

    /// The error estimate is homogeneous of degree one in the stages: with the state (so the
    /// weights) fixed and `y_new = y`, scaling every stage by `c` scales each `aᵢ, bᵢ`, and so
    /// the estimate, by `c`. With `c = 2^±600` their squares overflow or vanish, so the
    /// estimate must come from the rescaled path, and still be `c` times the plain one (to
    /// rounding; powers of two scale exactly).
    #[test]
    fn error_estimate_survives_squares_that_overflow_or_vanish() {
        let y0 = SVector::<f64, 2>::new(1.0, 0.5);
        let mut stepper = Dop853::new(&Rotation, 0.0, y0, 1.0, Dop853Settings::new(1e-9, 0.0))
            .expect("a valid problem");
        let h = 0.25;
        let stages: Vec<SVector<f64, 2>> = (0..stepper.stages.len())
            .map(|j| SVector::<f64, 2>::new(0.3 + 0.01 * j as f64, -0.2 * j as f64))
            .collect();
        stepper.stages.copy_from_slice(&stages);
        let plain = stepper.error_norm(&y0, h);
        assert!(plain.is_finite() && plain > 0.0, "{plain}");
        for c in [2f64.powi(600), 2f64.powi(-600)] {
            for (stage, original) in stepper.stages.iter_mut().zip(&stages) {
                *stage = original * c;
            }
            let estimate = stepper.error_norm(&y0, h);
            let expected = plain * c;
            assert!(
                ((estimate - expected) / expected).abs() < 1e-14,
                "c = {c:e}: {estimate:e} against {expected:e}"
            );
        }
    }
}
