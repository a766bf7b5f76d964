//! Line charts as SVG (plotters): time series of a simulation, the path of a top's axis seen
//! from above, and work-precision diagrams. Logarithmic quantities are plotted as their
//! base-10 logarithms on linear axes.

use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// One named line of points `(x, y)`.
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

/// One chart: its title, axis labels and lines. With `equal_axes` both axes span the same
/// range (a path in a plane drawn undistorted in a square panel).
pub struct Chart<'a> {
    pub title: &'a str,
    pub x_label: &'a str,
    pub y_label: &'a str,
    pub series: &'a [Series],
    pub equal_axes: bool,
}

/// Draws the series into an SVG file at `path`.
pub fn line_chart(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
) -> Result<(), String> {
    let chart = Chart {
        title,
        x_label,
        y_label,
        series,
        equal_axes: false,
    };
    side_by_side(path, (900, 560), &[chart])
}

/// Draws the charts side by side, in panels of equal width, into an SVG file at `path` of
/// `size` pixels.
pub fn side_by_side(path: &Path, size: (u32, u32), charts: &[Chart]) -> Result<(), String> {
    let root = SVGBackend::new(path, size).into_drawing_area();
    let draw = |e: &dyn std::fmt::Display| format!("cannot draw {}: {e}", path.display());
    root.fill(&WHITE).map_err(|e| draw(&e))?;
    for (panel, chart) in root.split_evenly((1, charts.len())).iter().zip(charts) {
        draw_chart(panel, chart).map_err(|e| draw(&e))?;
    }
    root.present().map_err(|e| draw(&e))
}

fn draw_chart(panel: &DrawingArea<SVGBackend, Shift>, chart: &Chart) -> Result<(), String> {
    let Chart {
        title,
        x_label,
        y_label,
        series,
        equal_axes,
    } = *chart;
    let finite = || {
        series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter(|(x, y)| x.is_finite() && y.is_finite())
    };
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in finite() {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if !(x0.is_finite() && y0.is_finite()) {
        return Err("nothing to plot: no finite points".into());
    }
    let pad = |lo: f64, hi: f64| {
        let d = if hi > lo { (hi - lo) * 0.05 } else { 1.0 };
        (lo - d, hi + d)
    };
    if equal_axes {
        // Both ranges widened about their middles to the larger span.
        let half = 0.5 * (x1 - x0).max(y1 - y0);
        let (xm, ym) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
        (x0, x1, y0, y1) = (xm - half, xm + half, ym - half, ym + half);
    }
    let ((x0, x1), (y0, y1)) = (pad(x0, x1), pad(y0, y1));
    let draw = |e: &dyn std::fmt::Display| e.to_string();
    let mut chart = ChartBuilder::on(panel)
        .caption(title, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| draw(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .draw()
        .map_err(|e| draw(&e))?;
    for (k, s) in series.iter().enumerate() {
        let color = Palette99::pick(k).to_rgba();
        let points: Vec<(f64, f64)> = s
            .points
            .iter()
            .copied()
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect();
        chart
            .draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))
            .map_err(|e| draw(&e))?
            .label(s.name.clone())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
            });
        if points.len() <= 200 {
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 2, color.filled())))
                .map_err(|e| draw(&e))?;
        }
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|e| draw(&e))?;
    Ok(())
}
