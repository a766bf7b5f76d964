//! Work against precision: for a set of bodies, every method at several tolerances or
//! steps, timed, with its error against ground truth.
//!
//! Ground truth for every body is the double-double Taylor integration
//! ([`reference`](crate::numeric::integrators::reference)), which shares no code with the
//! closed form or the integrators; the forced bodies (a constant moment, and a moment
//! varying in time as a scene's couples do) carry a [`HarmonicMoment`], whose Taylor series
//! the reference sums exactly. An independent double-double RK4 with Richardson
//! extrapolation checks the forced truth (`tests/suite/work_precision_forced_truth.rs`). Every
//! method, the splitting included, runs on every body.
//! Error = max over the sample times of `|Δω|` and of the attitude angle between the
//! computed and the true orientation.

use crate::numeric::error::NumericError;
use crate::numeric::integrators::harmonic_moment::HarmonicMoment;
use crate::numeric::integrators::reference::ReferenceMotion;
use crate::numeric::integrators::splitting::SplittingOrder;
use crate::numeric::rigid_body::exact_propagation::{simulate_choice, Choice};
use crate::numeric::rigid_body::inertia::BodyInertia;
use crate::numeric::rigid_body::sample_sink::Sample;
use crate::numeric::rigid_body::simulate::{Method, Problem, Sampling};
use crate::numeric::rigid_body::state::RigidBodyState;
use crate::numeric::rigid_body::torque::Torque;
use nalgebra::{UnitQuaternion, Vector3};
use std::time::{Duration, Instant};

/// The moment on a test body, in body axes.
#[derive(Debug, Clone, Copy)]
pub enum Load {
    None,
    Constant(Vector3<f64>),
    /// A function of time alone, as a scene's couple `M_0 sin(p t)`.
    Harmonic(HarmonicMoment),
}

/// A test body.
pub struct Case {
    pub name: &'static str,
    pub moments: Vector3<f64>,
    pub omega0: Vector3<f64>,
    pub load: Load,
}

/// The moment of the time-forced body: `(0.1 cos t, −0.2, 0.05 sin 2t)`.
fn oscillating_couple() -> HarmonicMoment {
    HarmonicMoment {
        constant: Vector3::new(0.0, -0.2, 0.0),
        cosine: Vector3::new(0.1, 0.0, 0.0),
        sine: Vector3::new(0.0, 0.0, 0.05),
        frequency: Vector3::new(1.0, 0.0, 2.0),
    }
}

/// The six bodies of the work-precision study.
pub fn cases() -> Vec<Case> {
    let free = |name, moments, omega0| Case {
        name,
        moments,
        omega0,
        load: Load::None,
    };
    vec![
        free(
            "generic",
            Vector3::new(1.0, 2.0, 3.0),
            Vector3::new(1.0, 1.0, 1.0),
        ),
        free(
            "near-symmetric",
            Vector3::new(1.0, 1.0 + 1e-9, 2.0),
            Vector3::new(1.0, 1.0, 1.0),
        ),
        free(
            "intermediate-axis",
            Vector3::new(1.0, 2.0, 3.0),
            Vector3::new(1e-3, 1.0, 1e-3),
        ),
        // Near the separatrix but not so near that f64 cannot follow it for a thousand
        // seconds: at ω₀ = (1e-3, 1, 1e-3) one rounding of ω_x (1e-19) moves ω(1000) by
        // 3e-12, and the rounding of every evaluation of f leaves any f64 integrator near
        // 1e-8 there; here it is 3e-14.
        free(
            "near-separatrix",
            Vector3::new(1.0, 2.0, 3.0),
            Vector3::new(1e-2, 1.0, 1e-2),
        ),
        Case {
            name: "forced",
            moments: Vector3::new(1.0, 2.0, 3.0),
            omega0: Vector3::new(1.0, 1.0, 1.0),
            load: Load::Constant(Vector3::new(0.1, -0.2, 0.05)),
        },
        Case {
            name: "time-forced",
            moments: Vector3::new(1.0, 2.0, 3.0),
            omega0: Vector3::new(1.0, 1.0, 1.0),
            load: Load::Harmonic(oscillating_couple()),
        },
    ]
}

/// One method at one setting: its family (`dop853`, `rk4`, …), its label in the table
/// (the family and the setting, `dop853 rtol=1e-12`) and what runs.
pub struct Setting {
    pub family: &'static str,
    pub label: String,
    pub choice: Choice,
}

/// The methods and settings compared.
pub fn choices(forced: bool) -> Vec<Setting> {
    let mut out = Vec::new();
    if !forced {
        out.push(Setting {
            family: "exact",
            label: "exact".to_string(),
            choice: Choice::Exact,
        });
    }
    let mut push = |family, setting: String, method| {
        out.push(Setting {
            family,
            label: format!("{family} {setting}"),
            choice: Choice::Integrate(method),
        })
    };
    for rtol in [1e-6, 1e-8, 1e-10, 1e-11, 1e-12, 1e-13] {
        push(
            "dop853",
            format!("rtol={rtol:e}"),
            Method::dop853(rtol, rtol * 1e-3),
        );
    }
    for rtol in [1e-8, 1e-10, 1e-11, 1e-12, 1e-13] {
        push(
            "vern9",
            format!("rtol={rtol:e}"),
            Method::vern9(rtol, rtol * 1e-3),
        );
    }
    for step in [0.1, 0.03, 0.01, 0.003] {
        push("rk4", format!("h={step}"), Method::Rk4 { step });
    }
    for (order, family, steps) in [
        (SplittingOrder::Second, "splitting2", [0.1, 0.01, 0.001]),
        (SplittingOrder::Fourth, "splitting4", [0.1, 0.03, 0.01]),
    ] {
        for step in steps {
            push(
                family,
                format!("h={step}"),
                Method::Splitting { step, order },
            );
        }
    }
    out
}

/// The fastest run of a method family (`dop853`, `vern9`, …) on
/// body `case` whose `|Δω|` and attitude errors are both at most `error`: the family's cost of
/// that accuracy, for comparing families at equal error.
pub fn fastest_within<'a>(
    rows: &'a [Row],
    case: &str,
    family: &str,
    error: f64,
) -> Option<&'a Row> {
    rows.iter()
        .filter(|r| {
            r.case == case && r.family == family && r.omega_error.max(r.attitude_error) <= error
        })
        .min_by(|a, b| a.seconds_per_run.total_cmp(&b.seconds_per_run))
}

/// One line of the table.
#[derive(Debug, Clone)]
pub struct Row {
    pub case: &'static str,
    /// The method's family, as in [`Setting::family`].
    pub family: &'static str,
    /// The method and its setting, as in [`Setting::label`].
    pub method: String,
    pub seconds_per_run: f64,
    pub omega_error: f64,
    pub attitude_error: f64,
}

/// The true states of `case` at `times`, and what they come from: the double-double Taylor
/// reference, under the body's moment when it is forced.
pub fn truth(
    case: &Case,
    times: &[f64],
) -> Result<(Vec<RigidBodyState<f64>>, &'static str), NumericError> {
    let start = UnitQuaternion::identity();
    let mut reference = match case.load {
        Load::None => ReferenceMotion::new(case.moments, case.omega0, start)?,
        Load::Constant(moment) => ReferenceMotion::forced(
            case.moments,
            case.omega0,
            start,
            HarmonicMoment::steady(moment),
        )?,
        Load::Harmonic(moment) => {
            ReferenceMotion::forced(case.moments, case.omega0, start, moment)?
        }
    };
    let states = times
        .iter()
        .map(|&t| {
            reference
                .advance_to(t)
                .map(|s| RigidBodyState::new(s.omega, s.orientation))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok((states, "double-double Taylor reference"))
}

fn problem(case: &Case) -> Problem<f64> {
    Problem {
        inertia: BodyInertia::Principal(case.moments),
        torque: match case.load {
            Load::None => Torque::None,
            Load::Constant(moment) => Torque::Body(moment),
            Load::Harmonic(moment) => Torque::Time(Box::new(move |t| moment.at(t))),
        },
        initial: RigidBodyState::new(case.omega0, UnitQuaternion::identity()),
        start_time: 0.0,
    }
}

fn run(
    case: &Case,
    choice: &Choice,
    times: &[f64],
) -> Result<Vec<RigidBodyState<f64>>, NumericError> {
    let mut states = Vec::with_capacity(times.len());
    let mut sink = |s: Sample<f64>| states.push(RigidBodyState::new(s.omega, s.orientation));
    simulate_choice(
        &problem(case),
        choice,
        &Sampling::Times(times.to_vec()),
        &mut sink,
        &mut |_| {},
    )?;
    Ok(states)
}

/// Runs the study; `until` is the end time, sampled at 100 equal intervals (a fixed-step
/// method lands on each sample, so for `until < 10` its steps longer than `until / 100` are
/// cut to the spacing and give the same error). Each setting is repeated until it has run for
/// at least `budget`, and its mean time is reported. Returns the rows and one note for each
/// source of truth, naming the bodies measured against it.
pub fn study(
    until: f64,
    budget: Duration,
    progress: &mut dyn FnMut(&str),
) -> Result<(Vec<Row>, Vec<String>), NumericError> {
    let times: Vec<f64> = (1..=100).map(|k| until * k as f64 / 100.0).collect();
    let mut rows = Vec::new();
    // Each source of truth with the bodies measured against it, in the order first met.
    let mut sources: Vec<(&'static str, Vec<&'static str>)> = Vec::new();
    for case in cases() {
        let (truth, source) = truth(&case, &times)?;
        match sources.iter_mut().find(|(s, _)| *s == source) {
            Some((_, bodies)) => bodies.push(case.name),
            None => sources.push((source, vec![case.name])),
        }
        for setting in choices(!matches!(case.load, Load::None)) {
            progress(&format!("{} / {}", case.name, setting.label));
            let started = Instant::now();
            let mut runs = 0u32;
            let mut states = Vec::new();
            while runs == 0 || started.elapsed() < budget {
                states = run(&case, &setting.choice, &times)?;
                runs += 1;
            }
            let seconds_per_run = started.elapsed().as_secs_f64() / runs as f64;
            let omega_error = states
                .iter()
                .zip(&truth)
                .map(|(a, b)| (a.omega - b.omega).norm())
                .fold(0.0, f64::max);
            let attitude_error = states
                .iter()
                .zip(&truth)
                .map(|(a, b)| a.orientation.angle_to(&b.orientation))
                .fold(0.0, f64::max);
            rows.push(Row {
                case: case.name,
                family: setting.family,
                method: setting.label,
                seconds_per_run,
                omega_error,
                attitude_error,
            });
        }
    }
    let notes = sources
        .iter()
        .map(|(source, bodies)| format!("{}: errors against the {source}", bodies.join(", ")))
        .collect();
    Ok((rows, notes))
}
