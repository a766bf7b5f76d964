//! The axes, the motion and the loads, each drawn at a length in proportion to the body's
//! reach (a drawing shows where and which way, not how much):
//!
//! - the axes x, y, z from O, past the body; O and G marked (G alone where they coincide
//!   without a fixed point), and the axes Gx'y'z' dashed when the page works about G away
//!   from O;
//! - ω (and Ω where the frame does not turn with the body, α where it does) a double arrow
//!   from the fixed point (else G); a vector holding an unknown is drawn
//!   by its components (`C_y`, `C_z`), each labelled, as a textbook draws reactions;
//! - a force an arrow from its point, labelled with its name; a couple a double arrow past
//!   the body along it; an impulse an arrow into its point, its head open;
//! - with a fixed point and ω along a fixed direction: the fixed axis, and where forces
//!   holding unknowns act on it, the bearings (short tubes) and the shaft between them;
//! - named points as dots;
//! - the pivot at a fixed point nothing else holds ([`supports`](super::supports)), clear of
//!   the arrows from O.

use super::arrows::{
    drawn_whole, holds_any, is_word, label, named, nonzero, one_symbol, stretched, whole_label,
    Also, Drawn, Drew,
};
use super::body::circle;
use super::canvas::{Canvas, Layer};
use super::extent::Extent;
use super::view::{self, add, scaled, sub, P3};
use super::{FigureError, Role, Stroke};
use crate::algebra::{Expr, Symbol, Vector};
use crate::scene::model::Scene;
use crate::scene::units::Dimension;

/// Lengths in proportion to the body's reach.
const FORCE_LENGTH: f64 = 0.45;
const COUPLE_LENGTH: f64 = 0.55;
/// The gap before a vector drawn past the body along a ray from O.
const RAY_GAP: f64 = 0.1;
const OMEGA_LENGTH: f64 = 0.55;
/// How far, in shares of the reach, the body must go along a fixed axis from O for ω to be
/// drawn past it.
const INTO_BODY: f64 = 0.1;
const AXIS_BEYOND: f64 = 0.55;
/// How far along each axis from O nothing is drawn on it (past anything drawn along it).
const AXES_KEPT_CLEAR: f64 = 10.0;
/// The length of the axes Gx'y'z' drawn when the page works about G away from O.
const G_AXIS: f64 = 0.5;
const BEARING_RADIUS: f64 = 0.07;
const BEARING_LENGTH: f64 = 0.1;
/// The radius of a couple's curved arrow round the shaft.
const TURNING_RADIUS: f64 = 0.12;

/// Everything drawn besides the body: the fixed axis with its shaft and bearings (else the
/// link to a pivot the body does not reach), ω, the named points, the forces, couples and
/// impulses, the pivot at a fixed point clear of them (`floors`: the levels of the floors
/// drawn), then the axes past all of it.
pub fn draw(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    floors: &[f64],
) -> Result<(), FigureError> {
    let unknowns = magnitudes(scene);
    let shaft = fixed_axis(canvas, scene, body, &unknowns)?;
    let link = match shaft.is_empty() {
        true => super::link::draw(canvas, scene, body),
        false => None,
    };
    let mut rays = Rays {
        body,
        ends: shaft,
        claimed: Vec::new(),
        arrows: Vec::new(),
    };
    // The axes run from O past everything drawn along them.
    for e in view::UNIT {
        canvas.keep_axis_clear(scaled(e, AXES_KEPT_CLEAR * body.reach));
    }
    let omega_arc = omega(canvas, scene, body, &unknowns, &mut rays)?;
    motion_of_g(canvas, scene, body, &unknowns, &mut rays)?;
    let mut lettered = Vec::new();
    for p in &scene.points {
        let at = canvas.vector(&p.position, &p.name)?;
        lettered.push(at);
        canvas.dot(at, 2.5);
        canvas.label_on_body(named(&p.name), at, sub(at, body.centre));
    }
    let loaded = loads(canvas, scene, body, &unknowns, (&mut rays, &lettered))?;
    lettered.extend(&loaded.lettered);
    // The pivot at O where no fixed axis holds the body, clear of the arrows drawn from O.
    let at_o = |p: &P3| view::norm(*p) < 1e-9 * body.reach;
    let from_o: Vec<P3> = rays
        .arrows
        .iter()
        .filter(|(at, ..)| at_o(at))
        .map(|(_, d, ..)| *d)
        .chain(
            loaded
                .arrows
                .iter()
                .filter_map(|[a, b]| match (at_o(a), at_o(b)) {
                    (true, _) => Some(view::unit(*b)),
                    (_, true) => Some(view::unit(*a)),
                    _ => None,
                }),
        )
        .collect();
    if fixed_direction(canvas, scene, &unknowns)?.is_none() {
        super::supports::pivot(canvas, scene, body, floors, &from_o);
    }
    // A point named at O (the pin A of SP 18.3, the bearing C of SP 18.4) is lettered by its
    // name, not O.
    let origin_named = lettered.iter().any(|p| view::norm(*p) < 1e-9 * body.reach);
    // The Eulerian rates past everything drawn along their lines, each a curve round it.
    if scene.euler_angles.is_some() {
        let r = super::euler::RATE_RADIUS * body.reach;
        let k = super::euler::vertical(canvas)?;
        let high = super::euler::PRECESSION_AT * body.reach;
        // Under no force, H_G up Z below φ̇'s curve.
        let torque_free =
            scene.forces.is_empty() && scene.couples.is_empty() && scene.impulses.is_empty();
        let momentum = torque_free.then(|| {
            let length = super::euler::MOMENTUM_LENGTH * body.reach;
            rays.claim(canvas, k, 0.0, length) + length
        });
        let precession = rays.claim(canvas, k, high, 2.0 * r) + r;
        // ψ̇ past the arc of ω's angle from z too.
        let past_arc = omega_arc.map_or(0.0, |radius| radius + r);
        let spin = rays.claim(canvas, [0.0, 0.0, 1.0], past_arc, 2.0 * r) + r;
        super::euler::angles(canvas, body, (precession, spin), momentum)?;
    }
    // The dimensions after the loads, clear of their arrows, so the loads' labels are placed
    // first.
    match shaft_line(&rays.ends) {
        Some(along) => {
            super::dimensions::along_shaft(canvas, scene, body, along, &loaded.ends())?;
            super::dimensions::radii(canvas, scene, body, along)?;
        }
        None => super::dimensions::to_mass_centre(canvas, scene, body, &loaded.ends(), link)?,
    }
    axes(canvas, scene, body, (&rays, &loaded.arrows), origin_named);
    Ok(())
}

/// The rays out of O along which vectors are drawn past the body (ω along a fixed axis, a
/// couple): each claim starts past the body, the shaft and the claims before it; an arrow
/// already drawn from O along it (a force at O) is not passed but drawn beside.
struct Rays<'b> {
    body: &'b Extent,
    ends: Vec<P3>,
    claimed: Vec<(P3, f64)>,
    /// Arrows drawn from O or G themselves (ω about a fixed point, a reaction at O, ω and v̄
    /// of a free body), each its point, direction, length and whether it lies on its line
    /// (not beside it).
    arrows: Vec<(P3, P3, f64, bool)>,
}

impl Rays<'_> {
    /// How far the body (as drawn), the shaft and the claims go along the unit vector `d`.
    fn claimed(&self, canvas: &Canvas, d: P3) -> f64 {
        let shaft = self
            .ends
            .iter()
            .map(|p| view::dot(*p, d))
            .fold(0.0, f64::max);
        let claims = self
            .claimed
            .iter()
            .filter(|(c, _)| view::dot(*c, d) > 0.99)
            .map(|(_, end)| *end)
            .fold(0.0, f64::max);
        self.body.drawn_along(canvas, d).max(shaft).max(claims)
    }

    /// How far everything drawn along the unit vector `d` goes: the claims and the arrows
    /// from O.
    fn end(&self, canvas: &Canvas, d: P3) -> f64 {
        self.claimed(canvas, d).max(self.arrows_end(d, false))
    }

    /// How far the arrows drawn from O along the unit vector `d` go (only those on the line
    /// itself, a reaction on its axis, where `on_line`).
    fn arrows_end(&self, d: P3, on_line: bool) -> f64 {
        self.arrows
            .iter()
            .filter(|(at, c, _, on)| {
                *at == [0.0; 3] && view::dot(*c, d) > 0.99 && (*on || !on_line)
            })
            .map(|(_, _, end, _)| *end)
            .fold(0.0, f64::max)
    }

    /// Notes the arrows drawn from the point `at` along their lines.
    fn drawn_from(&mut self, at: P3, drew: &Drew) {
        self.arrows.extend(
            drew.arrows
                .iter()
                .map(|a| (at, a.direction, a.length, !a.beside)),
        );
    }

    /// The start, from O along `d`, of a vector `length` long drawn past the body, the shaft
    /// and the claims there, and `least` from O or more.
    fn claim(&mut self, canvas: &Canvas, d: P3, least: f64, length: f64) -> f64 {
        let start = (self.claimed(canvas, d) + RAY_GAP * self.body.reach).max(least);
        self.claimed.push((d, start + length));
        start
    }
}

/// The axes x, y, z from O past the body and whatever is drawn along them (the `loads`'
/// arrows on them too), O (unless `origin_named`: a point named by the scene or a
/// load stands there) and G.
fn axes(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    (rays, loads): (&Rays, &[[P3; 2]]),
    origin_named: bool,
) {
    for (e, name) in view::UNIT.iter().zip(["x", "y", "z"]) {
        // Past the loads' arrows drawn on it too (an impulse's component at a rod's end).
        let on_line = |p: &P3| view::on_line(*p, *e, 1e-9 * body.reach);
        let loads_on_it = loads
            .iter()
            .filter(|arrow| arrow.iter().all(on_line))
            .flatten()
            .map(|p| view::dot(*p, *e))
            .fold(0.0, f64::max);
        let end = rays.end(canvas, *e).max(loads_on_it);
        let tip = scaled(*e, end + AXIS_BEYOND * body.reach);
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
        // drawn again there, so a face does not grey it; past the arrows drawn on it (a
        // reaction at O), not over them.
        let out = body
            .along(*e)
            .max(rays.arrows_end(*e, true))
            .max(loads_on_it);
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
    if (scene.fixed_point || apart) && !origin_named {
        canvas.label("$O$".into(), [0.0; 3], away([0.0; 3]));
    }
    // A page that works about G away from O: the axes Gx'y'z' too, dashed.
    let about_g = !scene.fixed_point || scene.about_mass_centre;
    if apart && about_g {
        for (e, name) in view::UNIT.iter().zip(["x", "y", "z"]) {
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
    // G always: at a fixed point O too (a plate spinning about its fixed mass centre), both
    // letters stand there.
    canvas.dot(body.centre, 2.5);
    canvas.label_on_body("$G$".into(), body.centre, [-1.0, -1.0, -1.0]);
}

/// ω (with Eulerian angles, only where the scene states its components, §18.11's disk
/// given ω at the angle γ from its axis, then with that angle; after an impact, only where
/// it is known), and the frame's Ω where it differs: along a fixed axis past the shaft and
/// the body, so it is not lost on the shaft; else from the fixed point, or from G. The
/// radius of the angle's arc, if drawn.
fn omega(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    unknowns: &[Symbol],
    rays: &mut Rays,
) -> Result<Option<f64>, FigureError> {
    let stated = super::euler::stated_omega(scene);
    let omega = match (&scene.omega, &scene.euler_angles, &stated) {
        (Some(omega), None, _) | (_, Some(_), Some(omega)) => omega,
        _ => return Ok(None),
    };
    // Where the scene gives the motion before an impact, the figure shows that (ω₀); an
    // unknown ω after it is the answer, as an unknown v̄ is.
    if scene.omega_before.is_some() && holds_any(omega, unknowns) {
        return Ok(None);
    }
    // Ω where the frame does not turn with the body; drawn on ω's arrow where it is one of
    // ω's components (Ω = −ω₂ j), labelled with both (ω₂ = Ω). A known ω is drawn whole,
    // but by its components where the frame turns with one of them: the spin ω₁ about an
    // axle that turns at ω₂, as a textbook draws the two rotations it adds.
    let frame_rate = scene.frame_rate.as_ref().filter(|rate| *rate != omega);
    let frame_in_omega = frame_rate.and_then(|rate| match nonzero(rate)[..] {
        [k] if omega[k] == rate[k] => Some(k),
        _ => None,
    });
    // α where the frame turns with the body (ω̇ in it is α), unless zero: its own double
    // arrow, past ω's where it points the same way (a shaft speeding up), as a textbook draws
    // the two. Where the frame turns otherwise, ω̇ in it given as rates of ω's components
    // (`omegadot = alpha1*i`, the spin speeding up) is drawn too, labelled by those rates.
    let alpha = scene.omega_dot.as_ref().filter(|a| {
        let rates = nonzero(a);
        !rates.is_empty()
            && (scene.frame_rate.is_none() || rates.iter().all(|k| one_symbol(&a[*k])))
    });
    let also = frame_in_omega.map(|k| Also {
        component: k,
        name: "Omega",
    });
    let rates = [
        Some((omega, "omega", Role::AngularVelocity, also)),
        frame_rate
            .filter(|_| frame_in_omega.is_none())
            .map(|rate| (rate, "Omega", Role::FrameRate, None)),
        alpha.map(|a| (a, "alpha", Role::AngularAcceleration, None)),
    ];
    let length = OMEGA_LENGTH * body.reach;
    let about_fixed_axis = fixed_direction(canvas, scene, unknowns)?.is_some();
    for (vector, name, role, also) in rates.into_iter().flatten() {
        let d = view::unit(canvas.vector(vector, name)?);
        // Ω given as one rate about one axis (`frame rate = w1*j`) is labelled by that rate,
        // as the statement names it (ω₁); the page's Ω = ω₁ j links the two.
        let label_name = match (&role, nonzero(vector).as_slice()) {
            (Role::FrameRate, &[k]) if one_symbol(&vector[k]) => None,
            (Role::AngularAcceleration, _) if scene.frame_rate.is_some() => None,
            _ => Some(name),
        };
        // From O (else G), beside an arrow already drawn from it along the same line; drawn
        // whole along a fixed axis, past the shaft.
        let origin = match scene.fixed_point {
            true => [0.0; 3],
            false => body.centre,
        };
        // Past the shaft, or past the body where it lies along a fixed axis from O (a box
        // about its diagonal from a corner): on the axis, clear of the body.
        let into_body = about_fixed_axis && body.along(d) > INTO_BODY * body.reach;
        let past_shaft = scene.fixed_point
            && drawn_whole(vector, unknowns)
            && (!rays.ends.is_empty() || into_body);
        let from = match past_shaft {
            true => scaled(d, rays.claim(canvas, d, 0.0, stretched(canvas, d, length))),
            false => origin,
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
        let drew = drawn.vector(canvas, vector, label_name, unknowns, name)?;
        if !past_shaft {
            rays.drawn_from(origin, &drew);
        }
    }
    match &stated {
        Some(omega) => super::euler::omega_angle(canvas, scene, body, omega),
        None => Ok(None),
    }
}

/// The mass centre's velocity and acceleration where the scene gives them (v̄ and ā,
/// labelled so), and the motion just before an impact (`before vbar = v0*i`, `before omega =
/// w0*k`, labelled by its magnitude, v₀ and ω₀): a velocity or an acceleration an arrow from
/// G, an angular velocity a double arrow from G, each beside the arrows already drawn along
/// its line from G.
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
        // The acceleration ā, known or not: its direction is the statement's.
        (
            scene.abar.as_ref(),
            Some("abar"),
            false,
            Role::Acceleration,
            "abar",
        ),
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
        let length = OMEGA_LENGTH * body.reach;
        // From G, beside what is drawn from it along the same line (ω, v̄ along it).
        let drawn = Drawn {
            from: body.centre,
            length,
            double,
            stroke: Stroke::MOTION,
            role,
            into_point: false,
            also: None,
            body,
        };
        let drew = drawn.vector(canvas, v, name, unknowns, what)?;
        rays.drawn_from(body.centre, &drew);
    }
    Ok(())
}

/// What the loads' drawing came to: the forces' and impulses' arrows (tail, head), and the
/// points lettered with a load's name (the bearing C).
struct Loaded {
    arrows: Vec<[P3; 2]>,
    lettered: Vec<P3>,
}

impl Loaded {
    /// The arrows' ends.
    fn ends(&self) -> Vec<P3> {
        self.arrows.iter().flatten().copied().collect()
    }
}

/// The forces, couples and impulses.
fn loads(
    canvas: &mut Canvas,
    scene: &Scene,
    body: &Extent,
    unknowns: &[Symbol],
    (rays, points): (&mut Rays, &[P3]),
) -> Result<Loaded, FigureError> {
    let reach = body.reach;
    let (mut arrows, mut named_at) = (Vec::new(), Vec::new());
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
        arrows.extend(drew.arrows.iter().map(|a| a.ends));
        // Drawn from O, a force's arrows push what is drawn along their rays past them.
        if at == [0.0; 3] {
            rays.drawn_from(at, &drew);
        }
        // Drawn by components (C_y, C_z), a force is named at its point (the bearing C),
        // unless the name is a word (`pin`) or the point has its letter already (O, G) and
        // is not a bearing of the shaft.
        let bearing = on_shaft(at, &rays.ends, reach);
        if !drew.whole && !is_word(&f.name) && (bearing || !lettered(at, body, points)) {
            canvas.label(named(&f.name), at, sub(at, body.centre));
            named_at.push(at);
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
                // The curve is a circle square to the shaft: on the page it reaches along the
                // shaft's line as far as its ellipse does, which the claim must cover, with a
                // radius's room before it for the label of what is drawn there (α past ω).
                let half = r.max(along_page(canvas, d, r));
                let centre = scaled(d, rays.claim(canvas, d, 0.0, 2.0 * half + r) + r + half);
                let start = canvas.turning_arrow(centre, d, r, Stroke::LOAD, Role::Couple);
                let name = whole_label(&part, value, None);
                canvas.label(label(&name), start, sub(start, centre));
                continue;
            }
            let length = COUPLE_LENGTH * reach;
            let start = rays.claim(canvas, d, 0.0, stretched(canvas, d, length));
            let drawn = Drawn {
                from: scaled(d, start),
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
        arrows.extend(drew.arrows.iter().map(|a| a.ends));
        // Drawn by its components, a named impulse is named at its point (as a force is).
        if let (false, Some(name), false) = (drew.whole, &name, lettered(at, body, points)) {
            canvas.label(named(name), at, sub(at, body.centre));
            named_at.push(at);
        }
    }
    Ok(Loaded {
        arrows,
        lettered: named_at,
    })
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
    if let Some(a) = fixed_direction(canvas, scene, unknowns)? {
        let reach = body.reach;
        let on_axis = |p: P3| view::on_line(p, a, 1e-9 * reach);
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
        // A reference line: ω along it is drawn on it, as a textbook draws the axis of
        // rotation and ω.
        canvas.path(
            Layer::Behind,
            &[scaled(a, lo), scaled(a, hi)],
            false,
            Stroke::CENTRE_LINE,
        );
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
            canvas.bar(p0, p1, Stroke::SHAFT);
            canvas.keep_clear(p0, p1, Stroke::SHAFT);
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

/// How far along the unit `d`, as the page shows its line, a circle of radius `r` square to
/// `d` reaches from its centre: the half extent of its ellipse along the drawn line, in
/// lengths along `d`.
fn along_page(canvas: &Canvas, d: P3, r: f64) -> f64 {
    let o = canvas.project([0.0; 3]);
    let line = canvas.project(d).minus(o);
    let Some(e) = line.unit() else {
        return r;
    };
    let (u, v) = view::across(d);
    let reach = |w: P3| {
        let p = canvas.project(w).minus(o);
        p.x * e.x + p.y * e.y
    };
    r * reach(u).hypot(reach(v)) / line.length()
}

/// The fixed axis's direction: ω's where it is known about a fixed point and the frame turns
/// with the body.
fn fixed_direction(
    canvas: &Canvas,
    scene: &Scene,
    unknowns: &[Symbol],
) -> Result<Option<P3>, FigureError> {
    Ok(
        match (&scene.omega, scene.fixed_point, &scene.euler_angles) {
            // The frame turning otherwise than with the body (an axle turning at Ω about
            // another axis) turns ω with it: no fixed axis.
            (Some(omega), true, None)
                if !holds_any(omega, unknowns)
                    && scene.frame_rate.as_ref().is_none_or(|rate| rate == omega) =>
            {
                Some(view::unit(canvas.vector(omega, "omega")?)).filter(|a| view::norm(*a) > 0.0)
            }
            _ => None,
        },
    )
}

/// The unknowns that are magnitudes (an unknown angle only turns a vector, which is drawn
/// at the angle's size): a vector holding one is drawn by its components.
pub(super) fn magnitudes(scene: &Scene) -> Vec<Symbol> {
    scene
        .unknowns
        .iter()
        .filter(|(_, d)| *d != Dimension::NONE)
        .map(|u| u.0)
        .collect()
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
    view::to_segment(p, *a, *b) < 1e-9 * reach
}

/// Whether the point `p` has a letter in the figure already: O, G, or one of the scene's
/// named `points` (the post's A, where the blow R is drawn by its components R_x, R_y).
fn lettered(p: P3, body: &Extent, points: &[P3]) -> bool {
    let close = |q: &P3| view::norm(sub(p, *q)) < 1e-9 * body.reach;
    close(&[0.0; 3]) || close(&body.centre) || points.iter().any(close)
}
