//! `kinetics simulate SCENE (--until T [--every dt] | --at t1,t2,...) [--method ...]
//! [--rtol R | --step h] [--format csv|json] [--plot out.svg]`: integrate Euler's equations
//! and the orientation for the scene's body, streaming the samples (memory stays flat).
//!
//! Each row is formatted and written as its sample arrives; only the plot (`--plot`, with
//! the `plot` feature) keeps points, a bounded number of them. A scene with `euler angles`
//! is a heavy top, and its rows are its Eulerian angles (`simulate_top`). `--rtol` belongs to dop853
//! and vern9 (and to auto, which may integrate with them) and `--step` to rk4 and splitting: a flag the
//! chosen method does not use is refused with the reason, not ignored.
//!
//! Nothing is written before everything that can be checked is: the flags (by name, see
//! `simulate_flags`), the plot's path, the scene and the problem it poses (an initial
//! kinetic energy that overflows, say); the header goes out with the first sample. An
//! overflow found later stops the run with an error at the body, never an `inf` row.

use super::error::CliError;
use super::sample_rows::SampleRows;
use super::simulate_flags::{positive, sampling};
use kinetics::numeric::integrators::splitting::SplittingOrder;
use kinetics::numeric::rigid_body::eulerian_angles::EulerianAngles;
use kinetics::numeric::rigid_body::exact_propagation::{simulate_choice, Choice, MethodUsed};
use kinetics::numeric::rigid_body::heavy_top::HeavyTop;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{Method, Problem, SimulationStatistics};
use kinetics::numeric::NumericError;
use kinetics::scene::{parse_scene_to_simulate, simulation, top_simulation, Scene};
use kinetics::Input;

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum MethodName {
    Auto,
    Exact,
    Rk4,
    Dop853,
    Vern9,
    Splitting,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Output {
    Csv,
    Json,
}

#[derive(clap::Args)]
#[command(
    after_help = "Example:\n  kinetics simulate examples/scenes/spun_up_sphere.scene --at 1,2.5,10"
)]
pub struct Args {
    /// The scene file; `-` reads standard input.
    pub scene: String,
    /// Simulate until this time (s), positive.
    #[arg(
        long,
        conflicts_with = "at",
        required_unless_present = "at",
        allow_negative_numbers = true
    )]
    pub until: Option<f64>,
    /// Sample interval with --until (s), positive; default: until/100. More than
    /// 10000000 samples (until/every + 1) need --force.
    #[arg(long, requires = "until", allow_negative_numbers = true)]
    pub every: Option<f64>,
    /// Sample at these times (s), comma-separated, not negative and increasing.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pub at: Option<Vec<f64>>,
    /// auto: the closed form when the body is torque-free, otherwise vern9 below --rtol 1e-9
    /// (as by default) and dop853 above.
    #[arg(long, value_enum, default_value_t = MethodName::Auto)]
    pub method: MethodName,
    /// Relative tolerance of dop853 and vern9 (and of auto when it integrates); default 1e-10.
    #[arg(long, conflicts_with = "step", allow_negative_numbers = true)]
    pub rtol: Option<f64>,
    /// Step of rk4 and splitting (s), positive; default 1e-3.
    #[arg(long, allow_negative_numbers = true)]
    pub step: Option<f64>,
    #[arg(long, value_enum, default_value_t = Output::Csv)]
    pub format: Output,
    /// Also draw ω(t) into this SVG file (for a scene with `euler angles`: the path of the
    /// axis seen from above, and θ(t)).
    #[cfg(feature = "plot")]
    #[arg(long)]
    pub plot: Option<std::path::PathBuf>,
    /// Write more than 10000000 samples; and overwrite the plot file if it exists, or write
    /// through it if it is a symbolic link.
    #[arg(long)]
    pub force: bool,
}

/// Relative tolerance of dop853 and vern9 (and of auto) without `--rtol`.
const DEFAULT_RTOL: f64 = 1e-10;
/// Step of rk4 and splitting without `--step` (s).
const DEFAULT_STEP: f64 = 1e-3;

/// The method with its parameter. A parameter the method does not use is an error rather
/// than ignored: `--method dop853 --step 1e-4` would otherwise run at the default tolerance
/// while the user believes the step was set.
fn method_choice(
    method: MethodName,
    rtol: Option<f64>,
    step: Option<f64>,
) -> Result<Choice, CliError> {
    let rtol = rtol.map(|r| positive("--rtol", r)).transpose()?;
    let step = step.map(|h| positive("--step", h)).transpose()?;
    let refuse = |flag: &str, name: &str, reason: &str| {
        Err(CliError::Usage(format!(
            "{flag} does not apply to --method {name}: {reason}"
        )))
    };
    let fixed_steps = "it takes equal steps; give --step (default 1e-3 s) instead";
    match method {
        MethodName::Auto => match step {
            Some(_) => refuse(
                "--step",
                "auto",
                "auto takes the closed form or an adaptive pair, which chooses its own steps; give \
                 --rtol, or choose --method rk4 or splitting",
            ),
            None => Ok(Choice::Auto {
                rtol: rtol.unwrap_or(DEFAULT_RTOL),
            }),
        },
        MethodName::Exact => {
            let given = [("--rtol", rtol), ("--step", step)];
            match given.iter().find(|(_, value)| value.is_some()) {
                Some((flag, _)) => refuse(
                    flag,
                    "exact",
                    "the closed form is evaluated at each sample time, with neither a \
                     tolerance nor steps",
                ),
                None => Ok(Choice::Exact),
            }
        }
        MethodName::Dop853 | MethodName::Vern9 => {
            let vern9 = method == MethodName::Vern9;
            let name = if vern9 { "vern9" } else { "dop853" };
            match step {
                Some(_) => refuse(
                    "--step",
                    name,
                    &format!("{name} chooses its own steps to meet --rtol (default 1e-10)"),
                ),
                None => {
                    let rtol = rtol.unwrap_or(DEFAULT_RTOL);
                    Ok(Choice::Integrate(if vern9 {
                        Method::vern9(rtol, rtol * 1e-3)
                    } else {
                        Method::dop853(rtol, rtol * 1e-3)
                    }))
                }
            }
        }
        MethodName::Rk4 => match rtol {
            Some(_) => refuse("--rtol", "rk4", fixed_steps),
            None => Ok(Choice::Integrate(Method::Rk4 {
                step: step.unwrap_or(DEFAULT_STEP),
            })),
        },
        MethodName::Splitting => match rtol {
            Some(_) => refuse("--rtol", "splitting", fixed_steps),
            None => Ok(Choice::Integrate(Method::Splitting {
                step: step.unwrap_or(DEFAULT_STEP),
                order: SplittingOrder::Fourth,
            })),
        },
    }
}

pub fn run(args: Args) -> Result<String, CliError> {
    let choice = method_choice(args.method, args.rtol, args.step)?;
    let sampling = sampling(args.until, args.every, args.at.as_deref(), args.force)?;
    #[cfg(feature = "plot")]
    if let Some(path) = &args.plot {
        super::plot::writable_path(path, args.force).map_err(CliError::Plot)?;
    }
    let (name, text) = super::input::read_file(&args.scene)?;
    // The symbolic work before the run is bounded by the scene's budget; the run by its
    // sampling and its integrator's step limits.
    let (scene, setup) = Input::scene(&name, &text).within(|| {
        let scene = parse_scene_to_simulate(&name, &text)?;
        let setup = match scene.euler_angles {
            Some(_) => Setup::Top(top_simulation::heavy_top(&scene)?),
            None => Setup::Body(simulation::problem(&scene)?),
        };
        Ok::<_, CliError>((scene, setup))
    })?;
    let problem = match setup {
        Setup::Top((top, start)) => {
            return super::simulate_top::run(&args, &scene, name, top, start, &choice, &sampling)
        }
        Setup::Body(problem) => problem,
    };
    #[cfg(feature = "plot")]
    let mut plot = args
        .plot
        .as_ref()
        .map(|path| super::plot::OmegaPlot::new(path, &sampling));
    let mut rows = SampleRows::new(
        std::io::BufWriter::new(std::io::stdout().lock()),
        args.format,
        "t,w_x,w_y,w_z,q_w,q_x,q_y,q_z,T,H",
    );
    let mut sink = |s: Sample<f64>| {
        let q = s.orientation.into_inner();
        rows.push(&[
            s.t,
            s.omega.x,
            s.omega.y,
            s.omega.z,
            q.w,
            q.i,
            q.j,
            q.k,
            s.kinetic_energy,
            s.angular_momentum_magnitude,
        ]);
        #[cfg(feature = "plot")]
        if let Some(plot) = &mut plot {
            plot.add(&s);
        }
    };
    let (statistics, used) = super::progress::with_bar(|progress| {
        simulate_choice(&problem, &choice, &sampling, &mut sink, progress)
    })
    .map_err(|source| located(&scene, name.clone(), source))?;
    rows.finish()?;
    #[cfg(feature = "plot")]
    if let Some(plot) = plot {
        plot.draw().map_err(CliError::Plot)?;
    }
    eprintln!(
        "{} samples; method: {}",
        statistics.samples,
        method_report(&statistics, used)
    );
    Ok(String::new())
}

/// What a scene is simulated as, derived within its work budget: a heavy top with its
/// starting angles (`euler angles`), or a body under its loads.
enum Setup {
    Top((HeavyTop, EulerianAngles)),
    Body(Problem<f64>),
}

/// A failed run's error at the scene's statement it comes from, else about the file.
pub(super) fn located(scene: &Scene, name: String, source: NumericError) -> CliError {
    match simulation::located(scene, &source) {
        Some(located) => CliError::from(located),
        None => CliError::Numeric {
            name: Some(name),
            source,
        },
    }
}

/// The method as the closing line reports it: the closed form, or the steps taken.
pub(super) fn method_report(statistics: &SimulationStatistics, used: MethodUsed) -> String {
    match used {
        MethodUsed::Exact => "exact (closed form)".to_string(),
        MethodUsed::Integrator => format!(
            "{} steps, {} rejected",
            statistics.steps, statistics.rejected_steps
        ),
    }
}
