//! The distances along a shaft, as a textbook dimensions its figure: where the bearings, the
//! parts fixed on the shaft and the points on it stand along the axis (the stations, O among
//! them), a chain of dimension lines below the body parallel to the shaft, each span between
//! neighbouring stations labelled with its length as the scene writes it (`L/4`, `L/4`,
//! `L/2`). Drawn only when every span is written in the scene's symbols: a span known only as
//! a number has no name to show. And each point mass's radius from the shaft (an unbalance's
//! e₁), a line from the axis out to it labelled with its length; about a fixed point with no
//! shaft, the distance from O to G along an axis (an axle's length L), by the axle where one
//! is drawn. Each label stands on its dimension line, which its halo breaks.

use super::canvas::{Canvas, Layer};
use super::extent::Extent;
use super::view::{self, add, scaled, sub, P3};
use super::{FigureError, Stroke};
use crate::algebra::{Expr, Vector};
use crate::mechanics::shapes::Shape;
use crate::scene::model::Scene;

/// The chain's distance past the body, and how far the extension lines start from the axis
/// and run past the chain, in proportion to the body's reach.
const CHAIN_GAP: f64 = 0.5;
const EXTENSION_GAP: f64 = 0.05;
const EXTENSION_PAST: f64 = 0.06;
/// The least share of `down`'s drawn length across the shaft's drawn line for the chain to
/// clear the loads on the page.
const ACROSS_THE_PAGE: f64 = 0.25;

/// The chain of spans along the shaft whose unit axis is `a` (along one of the frame's axes),
/// clear of the body and of the `loads`' arrows (their ends).
pub fn along_shaft(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    a: P3,
    loads: &[P3],
) -> Result<(), FigureError> {
    let Some(k) = (0..3).find(|k| a[*k].abs() > 1.0 - 1e-12) else {
        return Ok(());
    };
    let coordinate = |v: &Vector| match a[k] > 0.0 {
        true => v[k].clone(),
        false => -&v[k],
    };
    let reach = body.reach;
    let on_axis = |p: P3| view::on_line(p, a, 1e-9 * reach);
    let mut stations: Vec<(f64, Expr)> = vec![(0.0, Expr::zero())];
    let mut station = |p: P3, at: &Vector| stations.push((view::dot(p, a), coordinate(at)));
    for f in &scene.forces {
        let p = canvas.vector(&f.point, &f.name)?;
        if on_axis(p) {
            station(p, &f.point);
        }
    }
    for named in &scene.points {
        let p = canvas.vector(&named.position, &named.name)?;
        if on_axis(p) {
            station(p, &named.position);
        }
    }
    for (n, part) in scene.parts.iter().enumerate() {
        let what = format!("body {}", n + 1);
        let centre = canvas.vector(&part.position, &what)?;
        if on_axis(centre) || fixed_across(canvas, part, centre, a, on_axis, &what)? {
            station(centre, &part.position);
        }
    }
    chain(canvas, body, loads, (a, k), stations);
    Ok(())
}

/// About a fixed point with no shaft, G on one of the frame's axes at a distance the scene
/// writes in its symbols (SP 18.2's axle OG, L): that distance by the `link` from O where
/// one is drawn, else a dimension from O to G.
pub fn to_mass_centre(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    loads: &[P3],
    link: Option<[P3; 2]>,
) -> Result<(), FigureError> {
    let [part] = &scene.parts[..] else {
        return Ok(());
    };
    let g = canvas.vector(&part.position, "body 1")?;
    let Some(k) = (0..3).find(|k| g[*k].abs() > 1e-9 * body.reach) else {
        return Ok(());
    };
    if !scene.fixed_point || (0..3).any(|j| j != k && g[j].abs() > 1e-9 * body.reach) {
        return Ok(());
    }
    let mut a = [0.0; 3];
    a[k] = g[k].signum();
    let distance = match a[k] > 0.0 {
        true => part.position[k].clone(),
        false => -&part.position[k],
    };
    if distance.symbols().is_empty() {
        return Ok(());
    }
    if let Some(link) = link {
        let (at, side) = super::link::middle(canvas, link);
        canvas.label(super::arrows::label(&distance), at, side);
        return Ok(());
    }
    let stations = vec![(0.0, Expr::zero()), (g[k].abs(), distance)];
    chain(canvas, body, loads, (a, k), stations);
    Ok(())
}

/// A chain of dimension lines along the unit `a` (the frame's axis `k`) between `stations`
/// (each its distance along `a` and that distance as the scene writes it), below the body
/// and the `loads`' arrows (their ends), each span labelled; none unless every span is
/// written in the scene's symbols.
fn chain(
    canvas: &mut Canvas,
    body: &Extent,
    loads: &[P3],
    (a, k): (P3, usize),
    mut stations: Vec<(f64, Expr)>,
) {
    let reach = body.reach;
    stations.sort_by(|p, q| p.0.total_cmp(&q.0));
    stations.dedup_by(|p, q| (p.0 - q.0).abs() < 1e-9 * reach);
    let spans: Vec<Expr> = stations.windows(2).map(|w| &w[1].1 - &w[0].1).collect();
    if spans.is_empty() || spans.iter().any(|s| s.symbols().is_empty()) {
        return;
    }
    // Below the body: of the frame's directions square to the shaft on the side no axis is
    // drawn (−x, −y, −z, so an extension line from O never runs along one), the one drawn
    // most nearly down whose extension lines run over no arrow (a reaction into its
    // bearing, a rate drawn down from O); the lowest when each would.
    let mut downs: Vec<P3> = (0..3)
        .filter(|j| *j != k)
        .map(|j| {
            let mut e = [0.0; 3];
            e[j] = -1.0;
            e
        })
        .collect();
    downs.sort_by(|p, q| canvas.project(*p).y.total_cmp(&canvas.project(*q).y));
    let foot = |s: f64| scaled(a, s);
    let extensions = |down: P3| {
        let offset = clearance(canvas, body, loads, a, down) + CHAIN_GAP * reach;
        let lines: Vec<[P3; 2]> = stations
            .iter()
            .map(|(s, _)| {
                [
                    add(foot(*s), scaled(down, EXTENSION_GAP * reach)),
                    add(foot(*s), scaled(down, offset + EXTENSION_PAST * reach)),
                ]
            })
            .collect();
        (down, offset, lines)
    };
    let sides: Vec<(P3, f64, Vec<[P3; 2]>)> = downs.iter().map(|d| extensions(*d)).collect();
    let Some((down, offset, lines)) = sides
        .iter()
        .find(|(_, _, lines)| !lines.iter().any(|[p, q]| canvas.arrow_along(*p, *q)))
        .or(sides.first())
    else {
        return;
    };
    let (down, offset) = (*down, *offset);
    for line in lines {
        canvas.path(Layer::Behind, line, false, Stroke::DIMENSION);
    }
    let chain = |s: f64| add(foot(s), scaled(down, offset));
    let (first, last) = (stations[0].0, stations[stations.len() - 1].0);
    canvas.path(
        Layer::Behind,
        &[chain(first), chain(last)],
        false,
        Stroke::DIMENSION,
    );
    for (w, span) in stations.windows(2).zip(&spans) {
        let middle = chain((w[0].0 + w[1].0) / 2.0);
        canvas.label_dimension(super::arrows::label(span), middle, down);
    }
}

/// How far along `down` a line parallel to the shaft `a` must stand to pass, on the page,
/// beyond the body and every load's arrow (their `loads` ends): an arrow along y drawn down
/// the page ends below a chain that only cleared it along `down` in space, and its label
/// had to stand far off. With `n` the page's normal to the shaft on the chain's side,
///
/// ```text
/// offset = max over points p of (P(p) · n) / (P(down) · n),   P the projection,
/// ```
///
/// and at least how far the body goes along `down` in space.
fn clearance(canvas: &Canvas, body: &Extent, loads: &[P3], a: P3, down: P3) -> f64 {
    let shaft = canvas.project(a);
    let below = canvas.project(down);
    let normal = shaft.normal();
    let n = match normal.x * below.x + normal.y * below.y < 0.0 {
        true => normal.times(-1.0),
        false => normal,
    };
    let per_unit = n.x * below.x + n.y * below.y;
    let on_page = |p: &P3| {
        let q = canvas.project(*p);
        (q.x * n.x + q.y * n.y) / per_unit
    };
    let in_space = body.along(down);
    match per_unit > ACROSS_THE_PAGE * below.length() {
        true => body
            .samples
            .iter()
            .chain(loads)
            .map(on_page)
            .fold(in_space, f64::max),
        // `down` drawn nearly along the shaft: clearing the page would take it far away.
        false => loads
            .iter()
            .map(|p| view::dot(*p, down))
            .fold(in_space, f64::max),
    }
}

/// Whether the part is fixed across the shaft at its centre's station: a rod square to the
/// axis with an end on it, or a point mass (an unbalance at its radius).
fn fixed_across(
    canvas: &Canvas,
    part: &crate::scene::model::Part,
    centre: P3,
    a: P3,
    on_axis: impl Fn(P3) -> bool,
    what: &str,
) -> Result<bool, FigureError> {
    Ok(match &part.shape {
        Shape::PointMass => true,
        Shape::SlenderRod { length } => {
            let [along, _, _] = canvas.columns(&part.rotation, what)?;
            let half = scaled(along, canvas.value(length, what)? / 2.0);
            let square = view::dot(along, a).abs() < 1e-9;
            square && (on_axis(add(centre, half)) || on_axis(sub(centre, half)))
        }
        _ => false,
    })
}

/// Each point mass off the shaft whose unit axis is `a` (along one of the frame's axes): a
/// dimension line from the axis out to it, labelled with its radius as the scene writes it,
/// the symbol of its position whose square is the radius squared (e₁ at (e₁, 0, z₁), e₂ at
/// (−3/5 e₂, 4/5 e₂, z₂)); none where no symbol is.
pub fn radii(canvas: &mut Canvas, scene: &Scene, body: &Extent, a: P3) -> Result<(), FigureError> {
    let Some(k) = (0..3).find(|k| a[*k].abs() > 1.0 - 1e-12) else {
        return Ok(());
    };
    for (n, part) in scene.parts.iter().enumerate() {
        if part.shape != Shape::PointMass {
            continue;
        }
        let p = canvas.vector(&part.position, &format!("body {}", n + 1))?;
        let foot = scaled(a, view::dot(p, a));
        if view::norm(sub(p, foot)) < 1e-9 * body.reach {
            continue;
        }
        let at = &part.position;
        let square = (0..3)
            .filter(|j| *j != k)
            .map(|j| &at[j] * &at[j])
            .fold(Expr::zero(), |s, t| s + t);
        let radius = at
            .iter()
            .flat_map(|c| c.symbols())
            .map(Expr::sym)
            .find(|e| e * e == square);
        if let Some(radius) = radius {
            canvas.path(Layer::Behind, &[foot, p], false, Stroke::DIMENSION);
            canvas.label_dimension(super::arrows::label(&radius), scaled(add(foot, p), 0.5), a);
        }
    }
    Ok(())
}
