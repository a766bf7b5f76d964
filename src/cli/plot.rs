//! What `--plot` draws (feature `plot`): ω(t) of `kinetics simulate` (for a top, the path
//! of its axis seen from above and θ(t)), and one work-precision diagram per body of
//! `kinetics bench work-precision`.
//!
//! A simulation streams its samples; only the plot keeps points, at most [`PLOT_POINTS`] of
//! them: a longer run keeps every `stride`-th sample, `stride = ⌈samples / PLOT_POINTS⌉`.
//! The path is checked before the run ([`writable_path`], called before the scene is read), so that a plot that cannot be
//! written fails before any sample is computed, not after the whole CSV was streamed.

use kinetics::numeric::rigid_body::eulerian_angles::EulerianAngles;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::Sampling;
use kinetics::numeric::work_precision::plot::{line_chart, side_by_side, Chart, Series};
use kinetics::numeric::work_precision::study::Row;
use std::path::{Path, PathBuf};

/// Most points kept for the plot; longer runs are thinned evenly.
const PLOT_POINTS: usize = 20_000;

/// Which samples a plot keeps: every `stride`-th, so that at most about [`PLOT_POINTS`].
struct Thinning {
    stride: usize,
    seen: usize,
}

impl Thinning {
    fn new(sampling: &Sampling<f64>) -> Self {
        let count = match sampling {
            Sampling::Times(times) => times.len(),
            Sampling::Every { interval, end } if *interval > 0.0 && end.is_finite() => {
                (end / interval) as usize + 1
            }
            Sampling::Every { .. } => 1,
        };
        Thinning {
            stride: count.div_ceil(PLOT_POINTS).max(1),
            seen: 0,
        }
    }

    /// Whether the next sample is kept.
    fn keeps_next(&mut self) -> bool {
        let keep = self.seen.is_multiple_of(self.stride);
        self.seen += 1;
        keep
    }
}

/// ω(t) in body axes, gathered sample by sample for an SVG chart.
pub struct OmegaPlot {
    path: PathBuf,
    thinning: Thinning,
    lines: [Vec<(f64, f64)>; 3],
}

impl OmegaPlot {
    /// A plot into `path` (checked by [`writable_path`] before anything is simulated) of a
    /// run sampled by `sampling`.
    pub fn new(path: &Path, sampling: &Sampling<f64>) -> Self {
        OmegaPlot {
            path: path.to_path_buf(),
            thinning: Thinning::new(sampling),
            lines: Default::default(),
        }
    }

    /// Keeps the sample when it is the first of its stride.
    pub fn add(&mut self, s: &Sample<f64>) {
        if self.thinning.keeps_next() {
            for (line, w) in self.lines.iter_mut().zip(s.omega.iter()) {
                line.push((s.t, *w));
            }
        }
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

/// A top's motion: the path of the tip of its unit axis seen from above,
/// `(X, Y) = (sin θ sin φ, −sin θ cos φ)` (the nutation loops), beside θ(t) in degrees.
pub struct TopPlot {
    path: PathBuf,
    thinning: Thinning,
    tip: Vec<(f64, f64)>,
    theta: Vec<(f64, f64)>,
}

impl TopPlot {
    /// As [`OmegaPlot::new`].
    pub fn new(path: &Path, sampling: &Sampling<f64>) -> Self {
        TopPlot {
            path: path.to_path_buf(),
            thinning: Thinning::new(sampling),
            tip: Vec::new(),
            theta: Vec::new(),
        }
    }

    /// Keeps the angles at `t` when they are the first of their stride.
    pub fn add(&mut self, t: f64, angles: &EulerianAngles) {
        if self.thinning.keeps_next() {
            let (sin_theta, sin_phi, cos_phi) =
                (angles.theta.sin(), angles.phi.sin(), angles.phi.cos());
            self.tip.push((sin_theta * sin_phi, -sin_theta * cos_phi));
            self.theta.push((t, angles.theta.to_degrees()));
        }
    }

    /// Writes the SVG file: the two charts side by side.
    pub fn draw(self) -> Result<(), String> {
        let tip = [Series {
            name: "tip of the axis".into(),
            points: self.tip,
        }];
        let theta = [Series {
            name: "θ".into(),
            points: self.theta,
        }];
        side_by_side(
            &self.path,
            (1300, 620),
            &[
                Chart {
                    title: "the axis seen from above",
                    x_label: "X",
                    y_label: "Y",
                    series: &tip,
                    equal_axes: true,
                },
                Chart {
                    title: "nutation",
                    x_label: "t [s]",
                    y_label: "θ [°]",
                    series: &theta,
                    equal_axes: false,
                },
            ],
        )
    }
}

/// Refuses a plot path that would fail only after the whole run, or write where the user
/// did not mean: a directory; a missing parent directory, or one that cannot be written
/// (tried with a file created and removed at once); an existing file, or a symbolic link
/// (dangling or not: writing follows it), unless `force`, and then the link's target is
/// checked in turn.
pub fn writable_path(path: &Path, force: bool) -> Result<(), String> {
    let refuse = |reason: String| Err(format!("error: --plot {}: {reason}", path.display()));
    let mut target = path.to_path_buf();
    // A chain of links is followed as the write will follow it, to a bound of hops.
    for hop in 0..=40 {
        let Ok(meta) = std::fs::symlink_metadata(&target) else {
            break;
        };
        if hop == 40 {
            return refuse("it is a chain of more than 40 symbolic links".into());
        }
        if meta.is_dir() {
            return refuse("it is a directory; give a file name".into());
        }
        if !force {
            return if meta.file_type().is_symlink() {
                refuse(format!(
                    "it is a symbolic link (to {}); pass --force to write through it",
                    std::fs::read_link(&target).unwrap_or_default().display()
                ))
            } else {
                refuse("the file exists; pass --force to overwrite it".into())
            };
        }
        if !meta.file_type().is_symlink() {
            return match std::fs::OpenOptions::new().write(true).open(&target) {
                Ok(_) => Ok(()),
                Err(e) => refuse(format!("cannot write {}: {e}", target.display())),
            };
        }
        let link = std::fs::read_link(&target).map_err(|e| format!("error: --plot: {e}"))?;
        target = match target.parent() {
            Some(parent) => parent.join(link),
            None => link,
        };
    }
    let parent = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if !parent.is_dir() {
        return refuse(format!("the directory {} does not exist", parent.display()));
    }
    let probe = parent.join(format!(".kinetics-plot-{}.tmp", std::process::id()));
    match std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
    {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(())
        }
        Err(e) => refuse(format!("cannot write in {}: {e}", parent.display())),
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
            let family = r.family.to_string();
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
