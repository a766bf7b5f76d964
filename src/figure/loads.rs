//! The axes, the motion and the loads, each drawn at a length in proportion to the body's
//! reach (a drawing shows where and which way, not how much):
//!
//! - the axes x, y, z from O, past the body; O and G marked (G alone where they coincide
//!   without a fixed point), and the axes Gx'y'z' dashed when the page works about G away
//!   from O;
//! - ω (and Ω where the frame does not turn with the body) a double arrow from the fixed
//!   point (else G); a vector holding an unknown is drawn
//!   by its components (`C_y`, `C_z`), each labelled, as a textbook draws reactions;
//! - a force an arrow from its point, labelled with its name; a couple a double arrow past
//!   the body along it; an impulse an arrow into its point, its head open;
//! - with a fixed point and ω along a fixed direction: the fixed axis, and where forces
//!   holding unknowns act on it, the bearings (short tubes) and the shaft between them;
//! - named points as dots.

use super::body::{circle, Extent};
use super::canvas::{Canvas, Layer};
use super::view::{self, add, scaled, sub, P3};
use super::{Dashes, FigureError, Mark, Role, Stroke};
use crate::algebra::{Expr, Symbol, Vector};
use crate::print::{self, markup};
use crate::scene::model::Scene;
use crate::scene::units::Dimension;

/// Lengths in proportion to the body's reach.
const FORCE_LENGTH: f64 = 0.45;
/// How far a load at a point inside the body reaches past its outline, and how deep inside
/// a point is for that.
const PAST_BODY: f64 = 0.2;
const INSIDE: f64 = 0.05;
/// The most steps of a quarter of [`PAST_BODY`] a load at a hidden point is lengthened by.
const LONGEST_STEPS: u32 = 60;
const COUPLE_LENGTH: f64 = 0.4;
/// The gap before a vector drawn past the body along a ray from O.
const RAY_GAP: f64 = 0.1;
/// The least share of its length a vector is drawn at, however the view foreshortens it.
const SHORTEST_DRAWN: f64 = 0.6;
const OMEGA_LENGTH: f64 = 0.55;
const AXIS_BEYOND: f64 = 0.55;
/// How far along each axis from O nothing is drawn on it (past anything drawn along it).
const AXES_KEPT_CLEAR: f64 = 10.0;
/// The length of the axes Gx'y'z' drawn when the page works about G away from O.
const G_AXIS: f64 = 0.5;
const BEARING_RADIUS: f64 = 0.07;
/// The pieces a shaft is drawn in, each at its own depth among the parts.
const SHAFT_PIECES: usize = 12;
const BEARING_LENGTH: f64 = 0.1;
/// The radius of a couple's curved arrow round the shaft.
const TURNING_RADIUS: f64 = 0.12;

const UNIT: [P3; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// Everything drawn besides the body: the fixed axis with its shaft and bearings, ω, the
/// named points, the forces, couples and impulses, then the axes past all of it.
pub fn draw(canvas: &mut Canvas, scene: &Scene, body: &Extent) -> Result<(), FigureError> {
    let unknowns = magnitudes(scene);
    let shaft = fixed_axis(canvas, scene, body, &unknowns)?;
    let mut rays = Rays {
        body,
        ends: shaft,
        claimed: Vec::new(),
        arrows: Vec::new(),
    };
    // The axes run from O past everything drawn along them.
    for e in UNIT {
        canvas.keep_clear([0.0; 3], scaled(e, AXES_KEPT_CLEAR * body.reach));
    }
    omega(canvas, scene, body, &unknowns, &mut rays)?;
    motion_of_g(canvas, scene, body, &unknowns, &mut rays)?;
    for p in &scene.points {
        let at = canvas.vector(&p.position, &p.name)?;
        canvas.dot(at, 2.5);
        canvas.label_on_body(named(&p.name), at, sub(at, body.centre));
    }
    let loaded = loads(canvas, scene, body, &unknowns, &mut rays)?;
    // The dimensions after the loads, clear of their arrows, so the loads' labels are placed
    // first.
    match shaft_line(&rays.ends) {
        Some(along) => {
            super::dimensions::along_shaft(canvas, scene, body, along, &loaded)?;
            super::dimensions::radii(canvas, scene, body, along)?;
        }
        None => super::dimensions::to_mass_centre(canvas, scene, body, &loaded)?,
    }
    axes(canvas, scene, body, &rays);
    Ok(())
}

/// The rays out of O along which vectors are drawn past the body (ω along a fixed axis, a
/// couple): each claim starts past the body, the shaft and the claims before it.
struct Rays<'b> {
    body: &'b Extent,
    ends: Vec<P3>,
    claimed: Vec<(P3, f64)>,
    /// Arrows drawn from O or G themselves (ω about a fixed point, a reaction at O, ω and v̄
    /// of a free body), each its point, direction and length.
    arrows: Vec<(P3, P3, f64)>,
}

impl Rays<'_> {
    /// How far the body, the shaft, the claims and the arrows from O go along the unit
    /// vector `d`.
    fn end(&self, d: P3) -> f64 {
        let shaft = self
            .ends
            .iter()
            .map(|p| view::dot(*p, d))
            .fold(0.0, f64::max);
        let from_o = self
            .arrows
            .iter()
            .filter(|(at, _, _)| *at == [0.0; 3])
            .map(|(_, c, end)| (*c, *end));
        let claims = self
            .claimed
            .iter()
            .copied()
            .chain(from_o)
            .filter(|(c, _)| view::dot(*c, d) > 0.99)
            .map(|(_, end)| end)
            .fold(0.0, f64::max);
        self.body.along(d).max(shaft).max(claims)
    }

    /// Where, from the point `at` along `d`, a vector starts clear of the arrows already
    /// drawn from it along that line (at the point when there are none).
    fn past_arrows(&self, at: P3, d: P3) -> P3 {
        let start = self
            .arrows
            .iter()
            .filter(|(p, a, _)| *p == at && view::dot(*a, d) > 0.99)
            .map(|(_, _, length)| length + RAY_GAP * self.body.reach)
            .fold(0.0, f64::max);
        add(at, scaled(d, start))
    }

    /// Notes the arrows drawn along their lines out of the point `at`, starting at `from`.
    fn drawn_from(&mut self, at: P3, from: P3, drew: &Drew) {
        let offset = view::norm(sub(from, at));
        self.arrows.extend(
            drew.arrows
                .iter()
                .map(|a| (at, a.direction, offset + a.length)),
        );
    }

    /// The start, from O along `d`, of a vector `length` long drawn past everything there.
    fn claim(&mut self, d: P3, length: f64) -> f64 {
        let start = self.end(d) + RAY_GAP * self.body.reach;
        self.claimed.push((d, start + length));
        start
    }
}

/// The axes x, y, z from O past the body and whatever is drawn along them, O and G.
fn axes(canvas: &mut Canvas, scene: &Scene, body: &Extent, rays: &Rays) {
    for (e, name) in UNIT.iter().zip(["x", "y", "z"]) {
        let tip = scaled(*e, rays.end(*e) + AXIS_BEYOND * body.reach);
        canvas.arrow(
            Layer::Behind,
            [0.0; 3],
            tip,
            false,
            Stroke::AXIS,
            Role::Axis,
        );
        // Where it comes out of the body toward the eye, the rest of it is in front of every
        // face (past the body along an axis turned to the eye nothing of the body is nearer):
        // drawn again there, so a face does not grey it.
        let out = body.along(*e);
        let toward_eye = view::dot(*e, canvas.view().toward_eye()) > 0.0;
        if toward_eye && out > 0.0 && out < view::norm(tip) {
            let from = scaled(*e, out);
            canvas.arrow(Layer::Front, from, tip, false, Stroke::AXIS, Role::Axis);
        }
        canvas.label(format!("${name}$"), tip, *e);
    }
    let apart = view::norm(body.centre) > 1e-9 * body.reach;
    let away = |p: P3| match view::norm(sub(p, body.centre)) > 1e-12 {
        true => sub(p, body.centre),
        false => [-1.0, -1.0, -1.0],
    };
    if scene.fixed_point || apart {
        canvas.label("$O$".into(), [0.0; 3], away([0.0; 3]));
    }
    // A page that works about G away from O: the axes Gx'y'z' too, dashed.
    let about_g = !scene.fixed_point || scene.about_mass_centre;
    if apart && about_g {
        for (e, name) in UNIT.iter().zip(["x", "y", "z"]) {
            let tip = add(body.centre, scaled(*e, G_AXIS * body.reach));
            canvas.path(
                Layer::Behind,
                &[body.centre, tip],
                false,
                Stroke::CENTRE_LINE,
            );
            canvas.label(format!("${name}'$"), tip, *e);
        }
    }
    if apart || !scene.fixed_point {
        canvas.dot(body.centre, 2.5);
        canvas.label_on_body("$G$".into(), body.centre, [-1.0, -1.0, -1.0]);
    }
}

/// ω (unless the Eulerian angles give it), and the frame's Ω where it differs: along a fixed
/// axis past the shaft and the body, so it is not lost on the shaft; else from the fixed
/// point, or from G.
fn omega(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    unknowns: &[Symbol],
    rays: &mut Rays,
) -> Result<(), FigureError> {
    let (Some(omega), None) = (&scene.omega, &scene.euler_angles) else {
        return Ok(());
    };
    let omega_whole = drawn_whole(omega, unknowns);
    // Ω where the frame does not turn with the body; drawn on ω's arrow where it is one of
    // ω's components (Ω = −ω₂ j), labelled with both (ω₂, Ω).
    let frame_rate = scene.frame_rate.as_ref().filter(|rate| *rate != omega);
    let frame_in_omega = frame_rate.and_then(|rate| match nonzero(rate)[..] {
        [k] if !omega_whole && omega[k] == rate[k] => Some(k),
        _ => None,
    });
    // α where the frame turns with the body (ω̇ in it is α), unless zero; drawn on ω's arrow
    // where it points the same way (a shaft speeding up), labelled with both (ω, α).
    let alpha = scene
        .omega_dot
        .as_ref()
        .filter(|a| scene.frame_rate.is_none() && !nonzero(a).is_empty());
    let alpha_on_omega = match alpha {
        Some(a) if omega_whole => {
            let (a, w) = (canvas.vector(a, "alpha")?, canvas.vector(omega, "omega")?);
            view::dot(view::unit(a), view::unit(w)) > 1.0 - 1e-9
        }
        _ => false,
    };
    let also = match (frame_in_omega, alpha_on_omega) {
        (Some(k), _) => Some(Also {
            component: Some(k),
            name: "Omega",
        }),
        (None, true) => Some(Also {
            component: None,
            name: "alpha",
        }),
        (None, false) => None,
    };
    let rates = [
        Some((omega, "omega", Role::AngularVelocity, also)),
        frame_rate
            .filter(|_| frame_in_omega.is_none())
            .map(|rate| (rate, "Omega", Role::FrameRate, None)),
        alpha
            .filter(|_| !alpha_on_omega)
            .map(|a| (a, "alpha", Role::AngularAcceleration, None)),
    ];
    let length = OMEGA_LENGTH * body.reach;
    for (vector, name, role, also) in rates.into_iter().flatten() {
        let d = view::unit(canvas.vector(vector, name)?);
        // Drawn whole along a fixed axis past the shaft.
        let from = match (scene.fixed_point, drawn_whole(vector, unknowns)) {
            (true, true) if !rays.ends.is_empty() => {
                scaled(d, rays.claim(d, stretched(canvas, d, length)))
            }
            // From O (else G), past an arrow already drawn from it along the same line.
            (true, _) => rays.past_arrows([0.0; 3], d),
            (false, _) => rays.past_arrows(body.centre, d),
        };
        let drawn = Drawn {
            from,
            length,
            double: true,
            stroke: Stroke::MOTION,
            role,
            into_point: false,
            also,
            body,
        };
        let drew = drawn.vector(canvas, vector, Some(name), unknowns, name)?;
        let origin = match scene.fixed_point {
            true => [0.0; 3],
            false => body.centre,
        };
        rays.drawn_from(origin, from, &drew);
    }
    Ok(())
}

/// The mass centre's velocity where the scene gives it (v̄, labelled so), and the motion
/// just before an impact (`before vbar = v0*i`, `before omega = w0*k`, labelled by its
/// magnitude, v₀ and ω₀): a velocity an arrow from G, an angular velocity a double arrow from
/// G, each past the arrows already drawn along its line from G.
fn motion_of_g(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    unknowns: &[Symbol],
    rays: &mut Rays,
) -> Result<(), FigureError> {
    // The velocity v̄ when known (an unknown one is the answer, not the statement).
    let vbar = scene.vbar.as_ref().filter(|v| !holds_any(v, unknowns));
    let motions = [
        (vbar, Some("vbar"), false, Role::Velocity, "vbar"),
        (
            scene.vbar_before.as_ref(),
            None,
            false,
            Role::Velocity,
            "the velocity before",
        ),
        (
            scene.omega_before.as_ref(),
            None,
            true,
            Role::AngularVelocity,
            "the angular velocity before",
        ),
    ];
    for (vector, name, double, role, what) in motions {
        let Some(v) = vector.filter(|v| v.iter().any(|c| !c.is_zero())) else {
            continue;
        };
        let d = view::unit(canvas.vector(v, what)?);
        let length = OMEGA_LENGTH * body.reach;
        // From G, past what is drawn from it along the same line (ω, v̄ along it).
        let start = rays.past_arrows(body.centre, d);
        let drawn = Drawn {
            from: start,
            length,
            double,
            stroke: Stroke::MOTION,
            role,
            into_point: false,
            also: None,
            body,
        };
        let drew = drawn.vector(canvas, v, name, unknowns, what)?;
        rays.drawn_from(body.centre, start, &drew);
    }
    Ok(())
}

/// The forces, couples and impulses; the ends of the forces' and impulses' arrows.
fn loads(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    unknowns: &[Symbol],
    rays: &mut Rays,
) -> Result<Vec<P3>, FigureError> {
    let reach = body.reach;
    let mut ends = Vec::new();
    for f in &scene.forces {
        let at = canvas.vector(&f.point, &f.name)?;
        let drawn = Drawn {
            from: at,
            length: FORCE_LENGTH * reach,
            double: false,
            stroke: Stroke::LOAD,
            role: Role::Force(f.name.clone()),
            into_point: false,
            also: None,
            body,
        };
        let drew = drawn.vector(canvas, &f.value, Some(&f.name), unknowns, &f.name)?;
        ends.extend(drew.arrows.iter().flat_map(|a| a.ends));
        // Drawn from O, a force's arrows push what is drawn along their rays past them.
        if at == [0.0; 3] {
            rays.drawn_from(at, at, &drew);
        }
        // Drawn by components (C_y, C_z), a force is named at its point (the bearing C),
        // unless the name is a word (`pin`) or the point has its letter already (O, G) and
        // is not a bearing of the shaft.
        let bearing = on_shaft(at, &rays.ends, reach);
        if !drew.whole && !is_word(&f.name) && (bearing || !lettered(at, body)) {
            canvas.label(named(&f.name), at, sub(at, body.centre));
        }
    }
    for (k, c) in scene.couples.iter().enumerate() {
        let what = format!("couple {}", k + 1);
        // A couple holding unknowns is drawn by its components, each along its own axis
        // (M_x along x past the body), as a textbook draws it.
        let parts: Vec<Vector> = match holds_any(c, unknowns) {
            true => nonzero(c)
                .into_iter()
                .map(|k| {
                    let mut part = Vector::from_element(Expr::zero());
                    part[k] = c[k].clone();
                    part
                })
                .collect(),
            false => vec![c.clone()],
        };
        for part in parts {
            let value = canvas.vector(&part, &what)?;
            let d = view::unit(value);
            // About the shaft: a curved arrow round it past what is drawn along it, as a
            // textbook draws the torque that drives a shaft.
            if shaft_line(&rays.ends).is_some_and(|a| view::dot(a, d).abs() > 1.0 - 1e-9) {
                let r = TURNING_RADIUS * reach;
                let centre = scaled(d, rays.claim(d, 2.0 * r) + r);
                let start = canvas.turning_arrow(centre, d, r, Stroke::LOAD, Role::Couple);
                let name = whole_label(&part, value, None);
                canvas.label(label(&name), start, sub(start, centre));
                continue;
            }
            let length = COUPLE_LENGTH * reach;
            let drawn = Drawn {
                from: scaled(d, rays.claim(d, stretched(canvas, d, length))),
                length,
                double: true,
                stroke: Stroke::LOAD,
                role: Role::Couple,
                into_point: false,
                also: None,
                body,
            };
            drawn.vector(canvas, &part, None, unknowns, &what)?;
        }
    }
    for (k, i) in scene.impulses.iter().enumerate() {
        let what = format!("impulse {}", k + 1);
        let at = canvas.vector(&i.point, &what)?;
        let drawn = Drawn {
            from: at,
            length: FORCE_LENGTH * reach,
            double: false,
            stroke: Stroke {
                width: 2.0,
                ..Stroke::LOAD
            },
            role: Role::Impulse,
            into_point: true,
            also: None,
            body,
        };
        let name = i.name.map(|s| s.name().to_string());
        let drew = drawn.vector(canvas, &i.value, name.as_deref(), unknowns, &what)?;
        ends.extend(drew.arrows.iter().flat_map(|a| a.ends));
        // Drawn by its components, a named impulse is named at its point (as a force is).
        if let (false, Some(name), false) = (drew.whole, &name, lettered(at, body)) {
            canvas.label(named(name), at, sub(at, body.centre));
        }
    }
    Ok(ends)
}

/// A vector's length along the unit `d`, stretched where the view foreshortens `d` (toward
/// the reader), so that it is drawn at least [`SHORTEST_DRAWN`] of its length long.
fn stretched(canvas: &Canvas, d: P3, length: f64) -> f64 {
    let drawn = canvas.project(d).minus(canvas.project([0.0; 3])).length();
    length * (SHORTEST_DRAWN / drawn.max(1e-9)).clamp(1.0, 2.5)
}

/// With a fixed point and ω along a fixed direction: the axis through O as a centre line,
/// the bearings where forces holding unknowns act on it, and the shaft between the outermost
/// of them (O among them). Returns the shaft's ends (none without a shaft).
fn fixed_axis(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    unknowns: &[Symbol],
) -> Result<Vec<P3>, FigureError> {
    let mut ends: Vec<P3> = Vec::new();
    let axis = match (&scene.omega, scene.fixed_point, &scene.euler_angles) {
        (Some(omega), true, None) if !holds_any(omega, unknowns) => {
            Some(view::unit(canvas.vector(omega, "omega")?))
        }
        _ => None,
    };
    if let Some(a) = axis.filter(|a| view::norm(*a) > 0.0) {
        let reach = body.reach;
        let on_axis = |p: P3| view::norm(view::square_to(p, a)) < 1e-9 * reach;
        let mut bearings = Vec::new();
        for f in &scene.forces {
            let at = canvas.vector(&f.point, &f.name)?;
            if on_axis(at) && holds_any(&f.value, unknowns) {
                bearings.push(at);
            }
        }
        let (lo, hi) = (
            -body.along(scaled(a, -1.0)) - 0.3 * reach,
            body.along(a) + 0.3 * reach,
        );
        canvas.path(
            Layer::Behind,
            &[scaled(a, lo), scaled(a, hi)],
            false,
            Stroke::CENTRE_LINE,
        );
        canvas.keep_clear(scaled(a, lo), scaled(a, hi));
        if bearings.len() >= 2 {
            let along: Vec<f64> = bearings
                .iter()
                .map(|p| view::dot(*p, a))
                .chain([0.0])
                .collect();
            let (s0, s1) = along
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), s| {
                    (l.min(*s), h.max(*s))
                });
            let (p0, p1) = (scaled(a, s0), scaled(a, s1));
            // In pieces, each drawn by its own depth: the shaft passes behind a disk on it
            // and in front of it where it comes out.
            for k in 0..SHAFT_PIECES {
                let at = |j: usize| scaled(a, s0 + (s1 - s0) * j as f64 / SHAFT_PIECES as f64);
                let (q0, q1) = (at(k), at(k + 1));
                let piece = Mark::Path {
                    points: vec![canvas.project(q0), canvas.project(q1)],
                    closed: false,
                    filled: false,
                    stroke: Stroke::SHAFT,
                };
                canvas.part(scaled(add(q0, q1), 0.5), vec![piece]);
            }
            ends = vec![p0, p1];
        }
        for b in bearings {
            let h = BEARING_LENGTH * reach / 2.0;
            let r = BEARING_RADIUS * reach;
            let rims = [
                circle(sub(b, scaled(a, h)), a, r),
                circle(add(b, scaled(a, h)), a, r),
            ];
            let points: Vec<P3> = rims.iter().flatten().copied().collect();
            let outline = super::body::hull(canvas, &points);
            canvas.part(b, vec![outline]);
        }
    }
    Ok(ends)
}

/// The unknowns that are magnitudes (an unknown angle only turns a vector, which is drawn
/// at the angle's size): a vector holding one is drawn by its components.
fn magnitudes(scene: &Scene) -> Vec<Symbol> {
    scene
        .unknowns
        .iter()
        .filter(|(_, d)| *d != Dimension::NONE)
        .map(|u| u.0)
        .collect()
}

/// Whether a vector's components hold one of the unknowns.
fn holds_any(v: &Vector, unknowns: &[Symbol]) -> bool {
    v.iter()
        .any(|c| c.symbols().iter().any(|s| unknowns.contains(s)))
}

/// A second vector drawn on a vector's arrow, along the same line: α on ω (labelled ω, α),
/// or Ω on ω's component equal to it (labelled ω₂, Ω). `component`: the axis of that
/// component, or none for the whole arrow.
struct Also {
    component: Option<usize>,
    name: &'static str,
}

/// What a vector's drawing came to: whether it was drawn whole (else by components), and
/// its arrows.
struct Drew {
    whole: bool,
    arrows: Vec<Arrow>,
}

/// An arrow drawn: its unit direction, the length it was drawn at, its tail and its head.
struct Arrow {
    direction: P3,
    length: f64,
    ends: [P3; 2],
}

/// How a vector is drawn: from a point (or into it), at a length, single or double.
struct Drawn<'b> {
    from: P3,
    length: f64,
    double: bool,
    stroke: Stroke,
    role: Role,
    /// The head at the point (an impulse striking it), else the tail.
    into_point: bool,
    /// A second vector the arrow (or one component's arrow) stands for.
    also: Option<Also>,
    /// The body: a load at a point inside it reaches out past it, and one drawn beside a
    /// line is drawn on the side away from its mass centre.
    body: &'b Extent,
}

impl Drawn<'_> {
    /// Draws `v`: one arrow ([`whole_label`]) when no unknown is in it or it has one
    /// component, else an arrow per component that is not zero, each labelled with the
    /// component when it is one symbol (`C_y`), else by the name and the axis (`ω_x`); the
    /// arrow [`Also`] names labelled with it too. What it drew.
    fn vector(
        &self,
        canvas: &mut Canvas,
        v: &Vector,
        name: Option<&str>,
        unknowns: &[Symbol],
        what: &str,
    ) -> Result<Drew, FigureError> {
        let value = canvas.vector(v, what)?;
        let also = |component: Option<usize>, first: Expr| match &self.also {
            Some(a) if a.component == component => label_all(&[first, symbol(a.name)]),
            _ => label(&first),
        };
        if drawn_whole(v, unknowns) {
            let label = also(None, whole_label(v, value, name));
            return Ok(Drew {
                whole: true,
                arrows: self.arrow(canvas, value, label).into_iter().collect(),
            });
        }
        let mut arrows = Vec::new();
        for k in nonzero(v) {
            let mut d = [0.0; 3];
            d[k] = value[k].signum();
            if d[k] == 0.0 {
                d[k] = 1.0;
            }
            let first = match (v[k].as_symbol().or_else(|| (-&v[k]).as_symbol()), name) {
                (Some(_), _) | (None, None) => magnitude(&v[k], value[k]),
                // A component that is not one symbol is named by the vector's name.
                (None, Some(n)) => symbol(&format!("{n}_{}", ["x", "y", "z"][k])),
            };
            arrows.extend(self.arrow(canvas, d, also(Some(k), first)));
        }
        Ok(Drew {
            whole: false,
            arrows,
        })
    }

    /// One arrow along `direction`, its label at its free end; its unit direction and the
    /// length it was drawn at.
    fn arrow(&self, canvas: &mut Canvas, direction: P3, label: String) -> Option<Arrow> {
        let u = view::unit(direction);
        if view::norm(u) == 0.0 {
            return None;
        }
        let load = matches!(self.role, Role::Force(_) | Role::Impulse);
        // A load pushing on a face (a floor's normal force) comes into its point from
        // outside, as a textbook draws it, not across the body.
        let pushes = load && self.body.goes_into(self.from, u, INSIDE * self.body.reach);
        let mut into_point = self.into_point || pushes;
        let length = self.length_from(canvas, u, into_point, load);
        let (mut from, mut to, mut free) = self.ends(canvas, u, length, into_point);
        // Nothing is drawn along an axis, a rod or the shaft, but beside it; a load along
        // such a line toward the body (a bearing's thrust along the shaft) comes into its
        // point from outside too.
        let mut side = canvas.beside(from, to, self.body.centre);
        let toward_body = view::dot(u, sub(self.body.centre, self.from)) > 0.0;
        if load && !into_point && toward_body && side.length() > 0.0 {
            into_point = true;
            (from, to, free) = self.ends(canvas, u, length, into_point);
            side = canvas.beside(from, to, self.body.centre);
        }
        let outward = match into_point {
            true => scaled(u, -1.0),
            false => u,
        };
        // A load at a point out of sight behind the body, dashed, as its hidden edges are.
        let hidden = load && self.body.hides(canvas, self.from, INSIDE * self.body.reach);
        let stroke = match hidden {
            true => Stroke {
                dashes: Dashes::Hidden,
                ..self.stroke
            },
            false => self.stroke,
        };
        canvas.arrow_beside(
            Layer::Front,
            from,
            to,
            self.double,
            stroke,
            self.role.clone(),
            side,
        );
        canvas.label_beside(label, free, outward, side);
        // A later load along this one's line is drawn beside it (a normal force under a
        // weight), not over it.
        if load {
            canvas.keep_clear(from, to);
        }
        Some(Arrow {
            direction: u,
            length: stretched(canvas, u, length),
            ends: [from, to],
        })
    }

    /// The length of an arrow along the unit `u` from the point (into it when `into_point`):
    /// a load at a point inside the body (the body on both sides of it, as at G) or out of
    /// sight behind it (a box's far corner) reaches out past it, so its free end and its
    /// label stand clear of the body.
    fn length_from(&self, canvas: &Canvas, u: P3, into_point: bool, load: bool) -> f64 {
        let outward = match into_point {
            true => scaled(u, -1.0),
            false => u,
        };
        let (reach, depth) = (self.body.reach, INSIDE * self.body.reach);
        if !load {
            self.length
        } else if self.body.surrounds(self.from, outward, depth) {
            let past = self.body.beyond(canvas, self.from, outward) + PAST_BODY * reach;
            self.length.max(past)
        } else if self.body.hides(canvas, self.from, depth) {
            // Out from behind the body: as long as it takes its free end to clear it.
            let step = PAST_BODY * reach / 4.0;
            let clear = |l: &f64| {
                let free = add(self.from, scaled(outward, stretched(canvas, outward, *l)));
                !self.body.covers(canvas, free)
            };
            let mut lengths = (0..=LONGEST_STEPS).map(|k| self.length + step * f64::from(k));
            let longest = self.length + step * f64::from(LONGEST_STEPS);
            lengths.find(clear).unwrap_or(longest) + step
        } else {
            self.length
        }
    }

    /// The tail, the head and the free end (the end away from the point) of an arrow along
    /// the unit `u`, `length` long, from the point or (`into_point`) into it.
    fn ends(&self, canvas: &Canvas, u: P3, length: f64, into_point: bool) -> (P3, P3, P3) {
        let span = scaled(u, stretched(canvas, u, length));
        match into_point {
            true => (sub(self.from, span), self.from, sub(self.from, span)),
            false => (self.from, add(self.from, span), add(self.from, span)),
        }
    }
}

/// The label of a vector drawn as one arrow: its name (a name that is a word, `front`,
/// along one axis: its magnitude, N_A, as a textbook labels it), else its magnitude along an
/// axis, else the vector written.
fn whole_label(v: &Vector, value: P3, name: Option<&str>) -> Expr {
    match (name, nonzero(v).as_slice()) {
        (Some(n), &[k]) if is_word(n) => magnitude(&v[k], value[k]),
        (Some(n), _) => symbol(n),
        (None, &[k]) => magnitude(&v[k], value[k]),
        (None, _) => {
            let units = crate::algebra::vector::unit_vectors();
            (0..3)
                .map(|k| &v[k] * &units[k])
                .fold(Expr::zero(), |a, b| a + b)
        }
    }
}

/// A component without its sign where the value is negative (the arrow shows it).
fn magnitude(c: &Expr, value: f64) -> Expr {
    match value < 0.0 {
        true => -c,
        false => c.clone(),
    }
}

/// The axes of a vector's components that are not zero.
fn nonzero(v: &Vector) -> Vec<usize> {
    (0..3).filter(|k| !v[*k].is_zero()).collect()
}

/// Whether a vector is drawn as one arrow: no unknown in it, or one component (its line is
/// known whatever its unknown magnitude); else by components.
fn drawn_whole(v: &Vector, unknowns: &[Symbol]) -> bool {
    !holds_any(v, unknowns) || nonzero(v).len() == 1
}

/// The unit vector along the shaft drawn between `ends` (none without a shaft).
fn shaft_line(ends: &[P3]) -> Option<P3> {
    match ends {
        [a, b] if view::norm(sub(*b, *a)) > 0.0 => Some(view::unit(sub(*b, *a))),
        _ => None,
    }
}

/// Whether the point `p` is on the shaft drawn between `ends` (none without a shaft).
fn on_shaft(p: P3, ends: &[P3], reach: f64) -> bool {
    let [a, b] = ends else {
        return false;
    };
    let along = sub(*b, *a);
    let t = view::dot(sub(p, *a), along) / view::dot(along, along).max(1e-300);
    let foot = add(*a, scaled(along, t));
    (-1e-9..=1.0 + 1e-9).contains(&t) && view::norm(sub(p, foot)) < 1e-9 * reach
}

/// Whether the point `p` has a letter in the figure already: O, or G.
fn lettered(p: P3, body: &Extent) -> bool {
    let close = |q: P3| view::norm(sub(p, q)) < 1e-9 * body.reach;
    close([0.0; 3]) || close(body.centre)
}

/// Whether a name is a word (`push`, `front`, `weight`): three or more lower-case letters
/// that are not a Greek letter's name.
fn is_word(name: &str) -> bool {
    name.len() >= 3
        && name.chars().all(|c| c.is_ascii_lowercase())
        && Symbol::new(name).latex().starts_with(r"\mathit")
}

/// A label for a name as written (`C`, `P1`, `omega_x`, `weight`): the symbol of that name.
fn named(name: &str) -> String {
    label(&symbol(name))
}

/// The symbol of a name as written.
fn symbol(name: &str) -> Expr {
    Expr::sym(Symbol::new(name))
}

/// A label for `e`: its LaTeX as the mathematics of a label where the markup of titles
/// reads it, else its text as words (`weight`, `m g sin(θ)`).
pub(super) fn label(e: &Expr) -> String {
    label_all(std::slice::from_ref(e))
}

/// A label for the vectors one arrow stands for, in a list (`ω, α`), as [`label`] writes one.
fn label_all(es: &[Expr]) -> String {
    let list = |write: fn(&Expr) -> String, comma: &str| {
        es.iter().map(write).collect::<Vec<_>>().join(comma)
    };
    let maths = format!("${}$", list(print::latex, r",\, "));
    match markup::validate(&maths) {
        Ok(()) => maths,
        Err(_) => list(print::text, ", ").replace('$', ""),
    }
}
