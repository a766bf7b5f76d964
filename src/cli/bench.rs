//! `kinetics bench work-precision [--until T] [--budget-ms N] [--plot PREFIX]`: run time
//! against error for every method on the five bodies of the study, as a table and plots.

use kinetics::numeric::work_precision::plot::{line_chart, Series};
use kinetics::numeric::work_precision::study::{study, Row};
use std::path::PathBuf;
use std::time::Duration;

#[derive(clap::Subcommand)]
pub enum Bench {
    /// Time against error for every method and setting (build with --release).
    WorkPrecision(WorkPrecisionArgs),
}

#[derive(clap::Args)]
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
    #[arg(long)]
    pub plot: Option<PathBuf>,
}

pub fn run(bench: Bench) -> Result<String, String> {
    let Bench::WorkPrecision(args) = bench;
    if !(args.until.is_finite() && args.until > 0.0) {
        return Err(format!(
            "error: --until {} must be a positive number",
            args.until
        ));
    }
    let bar = indicatif::ProgressBar::new_spinner();
    let (rows, notes) = study(
        args.until,
        Duration::from_millis(args.budget_ms),
        &mut |what| {
            bar.set_message(what.to_string());
            bar.tick();
        },
    )
    .map_err(|e| format!("error: {e}"))?;
    bar.finish_and_clear();
    if let Some(prefix) = &args.plot {
        plots(prefix, &rows)?;
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

fn plots(prefix: &std::path::Path, rows: &[Row]) -> Result<(), String> {
    let mut cases: Vec<&str> = rows.iter().map(|r| r.case).collect();
    cases.dedup();
    for case in cases {
        let mut series: Vec<Series> = Vec::new();
        for r in rows.iter().filter(|r| r.case == case) {
            let family = r.method.split(' ').next().unwrap_or("method").to_string();
            let point = (r.seconds_per_run.log10(), r.omega_error.max(1e-17).log10());
            match series.iter_mut().find(|s| s.name == family) {
                Some(s) => s.points.push(point),
                None => series.push(Series {
                    name: family,
                    points: vec![point],
                }),
            }
        }
        let path = PathBuf::from(format!("{}-{case}.svg", prefix.display()));
        line_chart(
            &path,
            &format!("work against precision: {case} body"),
            "log10 time per run [s]",
            "log10 max |Δω|",
            &series,
        )?;
    }
    Ok(())
}
