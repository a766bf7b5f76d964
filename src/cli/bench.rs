//! `kinetics bench work-precision [--until T] [--budget-ms N] [--plot PREFIX]`: run time
//! against error for every method on the six bodies of the study, as a table and (with the
//! `plot` feature) plots.

use super::error::CliError;
use kinetics::numeric::work_precision::equal_error::time_at;
use kinetics::numeric::work_precision::study::{cases, fastest_within, study};
use std::time::Duration;

#[derive(clap::Subcommand)]
pub enum Bench {
    /// Time against error for every method and setting (build with --release).
    WorkPrecision(WorkPrecisionArgs),
}

#[derive(clap::Args)]
#[command(after_help = "Example:\n  kinetics bench work-precision --until 10 --budget-ms 5")]
pub struct WorkPrecisionArgs {
    /// End time of each run (s); samples at 100 equal intervals. Below 10 s the spacing is
    /// shorter than the coarsest fixed step (0.1 s): fixed steps longer than the spacing are
    /// cut to it and give the same error.
    #[arg(long, default_value_t = 100.0)]
    pub until: f64,
    /// Minimum time spent timing each setting (ms).
    #[arg(long, default_value_t = 50)]
    pub budget_ms: u64,
    /// Write one SVG per body: PREFIX-<body>.svg (log10 error against log10 time).
    #[cfg(feature = "plot")]
    #[arg(long)]
    pub plot: Option<std::path::PathBuf>,
}

/// The error at which the families are compared: tight enough that the higher order pays.
const EQUAL_ERROR: f64 = 1e-11;

pub fn run(bench: Bench) -> Result<String, CliError> {
    let Bench::WorkPrecision(args) = bench;
    if !(args.until.is_finite() && args.until > 0.0) {
        return Err(CliError::Usage(format!(
            "--until {} must be a positive number",
            args.until
        )));
    }
    let (rows, notes) = super::progress::with_spinner(|progress| {
        study(args.until, Duration::from_millis(args.budget_ms), progress)
    })
    .map_err(|source| CliError::Numeric { name: None, source })?;
    #[cfg(feature = "plot")]
    if let Some(prefix) = &args.plot {
        super::plot::work_precision(prefix, &rows).map_err(CliError::Plot)?;
    }
    let mut out = format!(
        "{:<18} {:<24} {:>14} {:>12} {:>12}\n",
        "body", "method", "time/run [s]", "max |Δω|", "attitude"
    );
    for r in &rows {
        out.push_str(&format!(
            "{:<18} {:<24} {:>14.3e} {:>12.2e} {:>12.2e}\n",
            r.case, r.method, r.seconds_per_run, r.omega_error, r.attitude_error
        ));
    }
    out.push_str(&format!(
        "\nvern9 against dop853, the fastest setting of each with both errors ≤ {EQUAL_ERROR:e}:\n"
    ));
    for case in cases() {
        let fastest = |family| fastest_within(&rows, case.name, family, EQUAL_ERROR);
        out.push_str(&match (fastest("dop853"), fastest("vern9")) {
            (Some(dop853), Some(vern9)) => format!(
                "{:<18} {} {:.3e} s, {} {:.3e} s: vern9 {:.2}× as fast\n",
                case.name,
                dop853.method,
                dop853.seconds_per_run,
                vern9.method,
                vern9.seconds_per_run,
                dop853.seconds_per_run / vern9.seconds_per_run
            ),
            _ => format!("{:<18} not reached by both\n", case.name),
        });
    }
    out.push_str(&format!(
        "\nvern9 against dop853 at equal error {EQUAL_ERROR:e}, each one's time read off its \
         line between the settings that bracket it (log-log):\n"
    ));
    for case in cases() {
        let at_equal_error = |family: &str| {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.case == case.name && r.family == family)
                .map(|r| (r.omega_error.max(r.attitude_error), r.seconds_per_run))
                .collect();
            time_at(&points, EQUAL_ERROR)
        };
        out.push_str(&match (at_equal_error("dop853"), at_equal_error("vern9")) {
            (Some(dop853), Some(vern9)) => format!(
                "{:<18} dop853 {dop853:.3e} s, vern9 {vern9:.3e} s: vern9 {:.2}× as fast\n",
                case.name,
                dop853 / vern9
            ),
            _ => format!("{:<18} not bracketed by both\n", case.name),
        });
    }
    out.push_str(&format!("\nt from 0 to {} s, 100 samples; ", args.until));
    out.push_str(&notes.join("; "));
    Ok(out)
}
