//! `kinetics bench work-precision [--until T] [--budget-ms N] [--plot PREFIX]`: run time
//! against error for every method on the five bodies of the study, as a table and (with the
//! `plot` feature) plots.

use super::error::CliError;
use kinetics::numeric::work_precision::study::study;
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
    out.push_str(&format!("\nt from 0 to {} s, 100 samples; ", args.until));
    out.push_str(&notes.join("; "));
    Ok(out)
}
