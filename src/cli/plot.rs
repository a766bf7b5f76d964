//! What `--plot` draws (feature `plot`): ω(t) of `kinetics simulate`, and one
//! work-precision diagram per body of `kinetics bench work-precision`.
//!
//! A simulation streams its samples; only the plot keeps points, at most [`PLOT_POINTS`] of
//! them: a longer run keeps every `stride`-th sample, `stride = ⌈samples / PLOT_POINTS⌉`.

use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::Sampling;
use kinetics::numeric::work_precision::plot::{line_chart, Series};
use kinetics::numeric::work_precision::study::Row;
use std::path::{Path, PathBuf};

/// Most points kept for the plot; longer runs are thinned evenly.
const PLOT_POINTS: usize = 20_000;

/// ω(t) in body axes, gathered sample by sample for an SVG chart.
pub struct OmegaPlot {
    path: PathBuf,
    stride: usize,
    seen: usize,
    lines: [Vec<(f64, f64)>; 3],
}

impl OmegaPlot {
    /// A plot into `path` of a run sampled by `sampling`. An existing file is refused unless
    /// `force`, before anything is simulated.
    pub fn new(path: &Path, force: bool, sampling: &Sampling<f64>) -> Result<Self, String> {
        if path.exists() && !force {
            return Err(format!(
                "error: {} exists; pass --force to overwrite it",
                path.display()
            ));
        }
        let count = match sampling {
            Sampling::Times(times) => times.len(),
            Sampling::Every { interval, end } if *interval > 0.0 && end.is_finite() => {
                (end / interval) as usize + 1
            }
            Sampling::Every { .. } => 1,
        };
        Ok(OmegaPlot {
            path: path.to_path_buf(),
            stride: count.div_ceil(PLOT_POINTS).max(1),
            seen: 0,
            lines: Default::default(),
        })
    }

    /// Keeps the sample when it is the first of its stride.
    pub fn add(&mut self, s: &Sample<f64>) {
        if self.seen.is_multiple_of(self.stride) {
            for (line, w) in self.lines.iter_mut().zip(s.omega.iter()) {
                line.push((s.t, *w));
            }
        }
        self.seen += 1;
    }

    /// Writes the SVG file.
    pub fn draw(self) -> Result<(), String> {
        let series: Vec<Series> = ["ω_x", "ω_y", "ω_z"]
            .iter()
            .zip(self.lines)
            .map(|(n, points)| Series {
                name: n.to_string(),
                points,
            })
            .collect();
        line_chart(
            &self.path,
            "angular velocity in body axes",
            "t [s]",
            "ω [rad/s]",
            &series,
        )
    }
}

/// One SVG per body, `PREFIX-<body>.svg`: log10 error against log10 time, a line per
/// method family.
pub fn work_precision(prefix: &Path, rows: &[Row]) -> Result<(), String> {
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
