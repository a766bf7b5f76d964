//! `simulate`: a scene's body (or heavy top) integrated from its stated motion, as
//! `kinetics simulate` does, its samples gathered into columns for NumPy.

use crate::error::{refused, scene_error};
use kinetics::{
    heavy_top, parse_scene_to_simulate, simulate_choice, simulation_located, simulation_problem,
    Choice, Diagnostic, Input, Method, MethodUsed, NumericError, Sample, Sampling, SplittingOrder,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The default relative tolerance of dop853 and vern9 (and of auto when it integrates), and the
/// default step of rk4 and splitting: the command line's.
const DEFAULT_RTOL: f64 = 1e-10;
const DEFAULT_STEP: f64 = 1e-3;
/// Most samples gathered: each is ten numbers kept in memory.
const MAX_SAMPLES: f64 = 10_000_000.0;

/// Simulates the scene `(name, text)` from t = 0: sampled every `every` (default
/// `until/100`) up to `until`, or at the times `at`; by `method` (`auto`, `exact`, `rk4`,
/// `dop853`, `vern9`, `splitting`) with `rtol` or `step`. Returns a dict of columns: `t`, `omega`
/// (body axes, three a sample), `orientation` (the quaternion w, x, y, z), `T`, `H`, and
/// `method` (`exact` or `integrated`).
#[pyfunction]
#[pyo3(signature = (name, text, until=None, every=None, at=None, method="auto", rtol=None, step=None))]
#[allow(clippy::too_many_arguments)]
pub fn simulate<'py>(
    py: Python<'py>,
    name: &str,
    text: &str,
    until: Option<f64>,
    every: Option<f64>,
    at: Option<Vec<f64>>,
    method: &str,
    rtol: Option<f64>,
    step: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let choice = choice(method, rtol, step)?;
    let sampling = sampling(until, every, at)?;
    let (columns, used) = py
        .detach(|| run(name, text, &choice, &sampling))
        .map_err(|failure| match failure {
            Failure::Located(d) => scene_error(&d),
            Failure::Numeric(reason) => refused(format!("{name}: {reason}")),
        })?;
    let d = PyDict::new(py);
    d.set_item("t", columns.t)?;
    d.set_item("omega", columns.omega)?;
    d.set_item("orientation", columns.orientation)?;
    d.set_item("T", columns.kinetic_energy)?;
    d.set_item("H", columns.angular_momentum)?;
    d.set_item(
        "method",
        match used {
            MethodUsed::Exact => "exact",
            MethodUsed::Integrator => "integrated",
        },
    )?;
    Ok(d)
}

/// Why a simulation failed: at a place in the scene, or in the numbers as a whole.
enum Failure {
    Located(Diagnostic),
    Numeric(NumericError),
}

impl From<Diagnostic> for Failure {
    fn from(d: Diagnostic) -> Failure {
        Failure::Located(d)
    }
}

/// The scene read and its problem posed within its work budget, then integrated (bounded
/// by its sampling and its integrator's step limits).
fn run(
    name: &str,
    text: &str,
    choice: &Choice,
    sampling: &Sampling<f64>,
) -> Result<(Columns, MethodUsed), Failure> {
    let (scene, setup) = Input::scene(name, text).within(|| {
        let scene = parse_scene_to_simulate(name, text)?;
        let setup = match scene.euler_angles {
            Some(_) => Err(heavy_top(&scene)?),
            None => Ok(simulation_problem(&scene)?),
        };
        Ok::<_, Failure>((scene, setup))
    })?;
    let failure = |e: NumericError| match simulation_located(&scene, &e) {
        Some(d) => Failure::Located(d),
        None => Failure::Numeric(e),
    };
    let problem = match setup {
        Ok(problem) => problem,
        Err((top, start)) => top.problem(&start).map_err(failure)?,
    };
    let mut columns = Columns::default();
    let mut sink = |s: Sample<f64>| columns.push(&s);
    let (_, used) =
        simulate_choice(&problem, choice, sampling, &mut sink, &mut |_| {}).map_err(failure)?;
    Ok((columns, used))
}

/// The samples, a column a quantity.
#[derive(Default)]
struct Columns {
    t: Vec<f64>,
    omega: Vec<[f64; 3]>,
    orientation: Vec<[f64; 4]>,
    kinetic_energy: Vec<f64>,
    angular_momentum: Vec<f64>,
}

impl Columns {
    fn push(&mut self, s: &Sample<f64>) {
        let q = s.orientation.into_inner();
        self.t.push(s.t);
        self.omega.push([s.omega.x, s.omega.y, s.omega.z]);
        self.orientation.push([q.w, q.i, q.j, q.k]);
        self.kinetic_energy.push(s.kinetic_energy);
        self.angular_momentum.push(s.angular_momentum_magnitude);
    }
}

/// `value`, refused unless finite and positive.
fn positive(name: &str, value: f64) -> PyResult<f64> {
    match value.is_finite() && value > 0.0 {
        true => Ok(value),
        false => Err(refused(format!(
            "{name}={value}: it must be a finite positive number"
        ))),
    }
}

/// The method and its one setting; a setting the method does not use is refused.
fn choice(method: &str, rtol: Option<f64>, step: Option<f64>) -> PyResult<Choice> {
    let rtol = rtol.map(|r| positive("rtol", r)).transpose()?;
    let step = step.map(|h| positive("step", h)).transpose()?;
    let unused = |setting: &str, why: &str| {
        Err(refused(format!(
            "{setting} does not apply to method={method:?}: {why}"
        )))
    };
    match (method, rtol, step) {
        ("auto" | "dop853" | "vern9" | "exact", _, Some(_)) => {
            unused("step", "it chooses its own steps (or has none)")
        }
        ("exact", Some(_), _) => unused("rtol", "the closed form has no tolerance"),
        ("rk4" | "splitting", Some(_), _) => unused("rtol", "it takes equal steps; give step"),
        ("auto", rtol, None) => Ok(Choice::Auto {
            rtol: rtol.unwrap_or(DEFAULT_RTOL),
        }),
        ("exact", None, None) => Ok(Choice::Exact),
        ("dop853", rtol, None) => {
            let rtol = rtol.unwrap_or(DEFAULT_RTOL);
            Ok(Choice::Integrate(Method::dop853(rtol, rtol * 1e-3)))
        }
        ("vern9", rtol, None) => {
            let rtol = rtol.unwrap_or(DEFAULT_RTOL);
            Ok(Choice::Integrate(Method::vern9(rtol, rtol * 1e-3)))
        }
        ("rk4", None, step) => Ok(Choice::Integrate(Method::Rk4 {
            step: step.unwrap_or(DEFAULT_STEP),
        })),
        ("splitting", None, step) => Ok(Choice::Integrate(Method::Splitting {
            step: step.unwrap_or(DEFAULT_STEP),
            order: SplittingOrder::Fourth,
        })),
        (other, _, _) => Err(refused(format!(
            "method={other:?}: choose auto, exact, rk4, dop853, vern9 or splitting"
        ))),
    }
}

/// The sample times: every `every` up to `until`, or at the times `at` (finite, not
/// negative, strictly increasing).
fn sampling(
    until: Option<f64>,
    every: Option<f64>,
    at: Option<Vec<f64>>,
) -> PyResult<Sampling<f64>> {
    match (at, until) {
        (Some(_), Some(_)) => Err(refused("give until (with every) or at, not both")),
        (Some(times), None) => {
            if times.is_empty() {
                return Err(refused("at: no times given"));
            }
            if times.iter().any(|t| !t.is_finite() || *t < 0.0) {
                return Err(refused("at: every time must be finite and not negative"));
            }
            if times.windows(2).any(|w| w[1] <= w[0]) {
                return Err(refused("at: the times must be strictly increasing"));
            }
            Ok(Sampling::Times(times))
        }
        (None, Some(until)) => {
            let end = positive("until", until)?;
            let interval = every.map_or(Ok(end / 100.0), |e| positive("every", e))?;
            if interval > end {
                return Err(refused(format!(
                    "every={interval} is longer than until={end}: only t = 0 would be sampled"
                )));
            }
            if end / interval + 1.0 > MAX_SAMPLES {
                return Err(refused(format!(
                    "until={end}, every={interval} would gather more than {MAX_SAMPLES:.0} samples: sample less often"
                )));
            }
            Ok(Sampling::Every { interval, end })
        }
        (None, None) => Err(refused("give until=T (and every=dt) or at=[t1, t2, ...]")),
    }
}
