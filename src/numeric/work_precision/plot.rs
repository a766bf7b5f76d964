//! Line charts as SVG (plotters): time series of a simulation, the path of a top's axis seen
//! from above, and work-precision diagrams. Logarithmic quantities are plotted as their
//! base-10 logarithms on linear axes. A chart's legend stands under its axes, outside the
//! plotting area, where it covers no data.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// One named line of points `(x, y)`.
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

/// One chart: its title, axis labels and lines. With `equal_axes` both axes have one scale,
/// as many pixels per unit across as up (a path in a plane drawn undistorted).
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

/// The space around a chart, inside its panel.
const MARGIN: i32 = 12;
/// The bottom strip of the axes' labels (the x axis's numbers and name) and the left one.
const X_LABEL_AREA: u32 = 40;
const Y_LABEL_AREA: u32 = 60;

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
    let draw = |e: &dyn std::fmt::Display| e.to_string();
    let area = panel
        .margin(MARGIN, MARGIN, MARGIN, MARGIN)
        .titled(title, ("sans-serif", 22))
        .map_err(|e| draw(&e))?;
    let legend = Legend::new(&area, series)?;
    let (width, height) = area.dim_in_pixel();
    let (axes, below) = area.split_vertically(height.saturating_sub(legend.height()));
    // The plotting area in pixels: the axes' area less its label strips.
    let plot = (
        f64::from(width.saturating_sub(Y_LABEL_AREA).max(1)),
        f64::from(
            (height.saturating_sub(legend.height()))
                .saturating_sub(X_LABEL_AREA)
                .max(1),
        ),
    );
    let pad = |lo: f64, hi: f64| {
        let d = if hi > lo { (hi - lo) * 0.05 } else { 1.0 };
        (lo - d, hi + d)
    };
    let ((mut x0, mut x1), (mut y0, mut y1)) = (pad(x0, x1), pad(y0, y1));
    if equal_axes {
        // One scale on both axes, the larger one needs: each range widened about its middle
        // to its pixels at that scale, so the path is drawn undistorted.
        let scale = ((x1 - x0) / plot.0).max((y1 - y0) / plot.1);
        let (xm, ym) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
        let (xh, yh) = (0.5 * scale * plot.0, 0.5 * scale * plot.1);
        (x0, x1, y0, y1) = (xm - xh, xm + xh, ym - yh, ym + yh);
    }
    let mut chart = ChartBuilder::on(&axes)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(Y_LABEL_AREA)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| draw(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .draw()
        .map_err(|e| draw(&e))?;
    for (k, s) in series.iter().enumerate() {
        let color = colour(k);
        let points: Vec<(f64, f64)> = s
            .points
            .iter()
            .copied()
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect();
        chart
            .draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))
            .map_err(|e| draw(&e))?;
        if points.len() <= 200 {
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 2, color.filled())))
                .map_err(|e| draw(&e))?;
        }
    }
    legend.draw(&below, series)
}

/// The colour of the `k`-th series, in its line and in the legend: Okabe and Ito's palette
/// for readers with colour-vision deficiency, without its yellow (unreadable on white, where
/// `Palette99`'s third colour put the vern9 line).
fn colour(k: usize) -> RGBAColor {
    const OKABE_ITO: [(u8, u8, u8); 7] = [
        (0x00, 0x72, 0xB2), // blue
        (0xD5, 0x5E, 0x00), // vermillion
        (0x00, 0x9E, 0x73), // bluish green
        (0xCC, 0x79, 0xA7), // reddish purple
        (0xE6, 0x9F, 0x00), // orange
        (0x56, 0xB4, 0xE9), // sky blue
        (0x00, 0x00, 0x00), // black
    ];
    let (r, g, b) = OKABE_ITO[k % OKABE_ITO.len()];
    RGBColor(r, g, b).to_rgba()
}

/// The legend, under the chart's axes and outside its plotting area, so that it covers no
/// data however the lines run: an entry per series (a sample of its line, then its name),
/// in rows centred in the chart's width, a row filled before the next begins.
struct Legend {
    /// Each row's entries: the series' index and the entry's width in pixels.
    rows: Vec<Vec<(usize, i32)>>,
}

/// A legend's sample of a line, the gap after it, the gap between entries and a row's
/// height, in pixels; the size of its names.
const SAMPLE: i32 = 18;
const AFTER_SAMPLE: i32 = 6;
const BETWEEN_ENTRIES: i32 = 24;
const ROW: i32 = 20;
const LEGEND_FONT: u32 = 14;

fn legend_font() -> TextStyle<'static> {
    TextStyle::from(("sans-serif", LEGEND_FONT).into_font())
}

impl Legend {
    fn new(area: &DrawingArea<SVGBackend, Shift>, series: &[Series]) -> Result<Legend, String> {
        let width = area.dim_in_pixel().0 as i32;
        let font = legend_font();
        let mut rows: Vec<Vec<(usize, i32)>> = Vec::new();
        let mut used = 0;
        for (k, s) in series.iter().enumerate() {
            let (name, _) = area
                .estimate_text_size(&s.name, &font)
                .map_err(|e| e.to_string())?;
            let entry = SAMPLE + AFTER_SAMPLE + name as i32;
            match rows.last_mut() {
                Some(row) if used + BETWEEN_ENTRIES + entry <= width => {
                    row.push((k, entry));
                    used += BETWEEN_ENTRIES + entry;
                }
                _ => {
                    rows.push(vec![(k, entry)]);
                    used = entry;
                }
            }
        }
        Ok(Legend { rows })
    }

    /// The height of the strip the legend takes under the axes.
    fn height(&self) -> u32 {
        (ROW * self.rows.len() as i32) as u32
    }

    fn draw(
        &self,
        strip: &DrawingArea<SVGBackend, Shift>,
        series: &[Series],
    ) -> Result<(), String> {
        let draw = |e: &dyn std::fmt::Display| e.to_string();
        let width = strip.dim_in_pixel().0 as i32;
        let font = legend_font().pos(Pos::new(HPos::Left, VPos::Center));
        for (r, row) in self.rows.iter().enumerate() {
            let entries: i32 = row.iter().map(|&(_, w)| w).sum();
            let mut x = (width - entries - BETWEEN_ENTRIES * (row.len() as i32 - 1)) / 2;
            let y = ROW * r as i32 + ROW / 2;
            for &(k, entry) in row {
                let color = colour(k);
                strip
                    .draw(&PathElement::new(
                        vec![(x, y), (x + SAMPLE, y)],
                        color.stroke_width(2),
                    ))
                    .map_err(|e| draw(&e))?;
                strip
                    .draw(&Text::new(
                        series[k].name.clone(),
                        (x + SAMPLE + AFTER_SAMPLE, y),
                        font.clone(),
                    ))
                    .map_err(|e| draw(&e))?;
                x += entry + BETWEEN_ENTRIES;
            }
        }
        Ok(())
    }
}
