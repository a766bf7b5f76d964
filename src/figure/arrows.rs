//! How one vector is drawn: as one arrow, or by components where it holds an unknown
//! magnitude; from its point or (a push, an impulse) into it; beside a line it would lie
//! along; lengthened out of the body where its point is inside or hidden behind it, dashed
//! where hidden; labelled by its name, its magnitude or its components, and with a second
//! vector a component stands for too (`ω₂ = Ω`).

use super::canvas::{Canvas, Layer};
use super::extent::Extent;
use super::view::{self, add, scaled, sub, P3};
use super::{Dashes, FigureError, Role, Stroke};
use crate::algebra::{Expr, Symbol, Vector};
use crate::print::{self, markup};

/// How far a vector at a point inside the body reaches past its outline on the page, and
/// how deep inside a point is for that.
const PAST_BODY: f64 = 0.2;
const INSIDE: f64 = 0.05;
/// The most steps of a quarter of [`PAST_BODY`] a load at a hidden point is lengthened by.
const LONGEST_STEPS: u32 = 60;
/// How far toward the mass centre, in shares of the reach, a load along a line must point
/// to be drawn into its point: a reaction at a bearing a little below the body's middle
/// (C_z in SP 18.4) is drawn out from its bearing, as a textbook draws it.
const TOWARD_BODY: f64 = 0.15;
/// How near, in shares of the reach, an arrow's head may come to another's, and the
/// lengths tried (in shares of its own) when it comes nearer.
const HEADS_APART: f64 = 0.1;
const SHORTER: f64 = 0.7;
/// The share of the way to another load's head coming the other way that a load runs.
const SHORT_OF: f64 = 0.7;
const LONGER: f64 = 1.3;
/// A component smaller than this share of its vector's largest vanishes at the figure's values.
const VANISHES: f64 = 1e-9;
/// The least share of its length a vector is drawn at, however the view foreshortens it.
const SHORTEST_DRAWN: f64 = 0.6;

/// A vector's length along the unit `d`, stretched where the view foreshortens `d` (toward
/// the reader), so that it is drawn at least [`SHORTEST_DRAWN`] of its length long.
pub(super) fn stretched(canvas: &Canvas, d: P3, length: f64) -> f64 {
    let drawn = canvas.project(d).minus(canvas.project([0.0; 3])).length();
    length * (SHORTEST_DRAWN / drawn.max(1e-9)).clamp(1.0, 2.5)
}

/// Whether a vector's components hold one of the unknowns.
pub(super) fn holds_any(v: &Vector, unknowns: &[Symbol]) -> bool {
    v.iter()
        .any(|c| c.symbols().iter().any(|s| unknowns.contains(s)))
}

/// A second vector drawn on one of a vector's components, equal to it: Ω on ω's component
/// (labelled ω₂ = Ω). `component`: the axis of that component.
pub(super) struct Also {
    pub(super) component: usize,
    pub(super) name: &'static str,
}

/// What a vector's drawing came to: whether it was drawn whole (else by components), and
/// its arrows.
pub(super) struct Drew {
    pub(super) whole: bool,
    pub(super) arrows: Vec<Arrow>,
}

/// An arrow drawn: its unit direction, the length it was drawn at, its tail and its head,
/// and whether it was drawn beside its line (else on it).
pub(super) struct Arrow {
    pub(super) direction: P3,
    pub(super) length: f64,
    pub(super) ends: [P3; 2],
    pub(super) beside: bool,
}

/// How a vector is drawn: from a point (or into it), at a length, single or double.
pub(super) struct Drawn<'b> {
    pub(super) from: P3,
    pub(super) length: f64,
    pub(super) double: bool,
    pub(super) stroke: Stroke,
    pub(super) role: Role,
    /// The head at the point (an impulse striking it), else the tail.
    pub(super) into_point: bool,
    /// A second vector one component's arrow stands for.
    pub(super) also: Option<Also>,
    /// The body: a load at a point inside it reaches out past it, and one drawn beside a
    /// line is drawn on the side away from its mass centre.
    pub(super) body: &'b Extent,
}

impl Drawn<'_> {
    /// Draws `v`: one arrow ([`whole_label`]) when no unknown is in it or it has one
    /// component, else an arrow per component that is not zero, each labelled with the
    /// component when it is one symbol (`C_y`), else by the name and the axis (`ω_x`); the
    /// arrow [`Also`] names labelled with it too. What it drew.
    pub(super) fn vector(
        &self,
        canvas: &mut Canvas,
        v: &Vector,
        name: Option<&str>,
        unknowns: &[Symbol],
        what: &str,
    ) -> Result<Drew, FigureError> {
        let value = canvas.vector(v, what)?;
        let also = |component: usize, first: Expr| match &self.also {
            Some(a) if a.component == component => label_equal(&[first, symbol(a.name)]),
            _ => label(&first),
        };
        let components = drawn_components(v, value);
        // Drawn whole too where the constraints left one component (a rolling cone's ω along
        // its line of contact): it is the whole vector, labelled as that.
        // A vector another is drawn on a component of (ω with Ω on ω₂) is drawn by them.
        if (drawn_whole(v, unknowns) && self.also.is_none()) || components.len() == 1 {
            let label = label(&whole_label(v, value, name));
            return Ok(Drew {
                whole: true,
                arrows: self.arrow(canvas, value, label, true).into_iter().collect(),
            });
        }
        let mut arrows = Vec::new();
        for k in components {
            let mut d = [0.0; 3];
            d[k] = value[k].signum();
            if d[k] == 0.0 {
                d[k] = 1.0;
            }
            let first = match (one_symbol(&v[k]), name) {
                (true, _) | (false, None) => magnitude(&v[k], value[k]),
                // A component that is not one symbol is named by the vector's name.
                (false, Some(n)) => symbol(&format!("{n}_{}", ["x", "y", "z"][k])),
            };
            arrows.extend(self.arrow(canvas, d, also(k, first), false));
        }
        Ok(Drew {
            whole: false,
            arrows,
        })
    }

    /// One arrow along `direction`, its label at its free end; its unit direction and the
    /// length it was drawn at. Not `alone` (one of a vector's components at its point), it
    /// is drawn from the point, as a textbook draws a reaction's components (their heads
    /// brought into one point would knot there), unless it runs along a line of the body
    /// toward it (a bearing's thrust along the shaft, drawn into the bearing).
    fn arrow(
        &self,
        canvas: &mut Canvas,
        direction: P3,
        label: String,
        alone: bool,
    ) -> Option<Arrow> {
        let u = view::unit(direction);
        if view::norm(u) == 0.0 {
            return None;
        }
        let load = matches!(self.role, Role::Force(_) | Role::Impulse);
        // A load pushing on a face (a floor's normal force) comes into its point from
        // outside, as a textbook draws it, not across the body.
        let pushes = load && self.body.goes_into(self.from, u, INSIDE * self.body.reach);
        let mut into_point = alone && (self.into_point || pushes);
        let mut length = self.length_from(canvas, u, into_point, load);
        // A load that would run through another's head coming the other way along its line
        // (a weight from G down through the floor's push at C) stops short of it: two loads
        // on one line, head to head, as a textbook draws them, not one beside the other.
        if load && !into_point {
            let drawn = stretched(canvas, u, length);
            if let Some(t) = canvas.head_coming(self.from, u, drawn) {
                length *= SHORT_OF * t / drawn;
            }
        }
        let (mut from, mut to, mut free) = self.ends(canvas, u, length, into_point);
        // Nothing is drawn along an axis, a rod or the shaft, but beside it; a load along
        // such a line toward the body (a bearing's thrust along the shaft, by more than
        // [`TOWARD_BODY`]) comes into its point from outside too.
        let mut side = canvas.beside(from, to, self.body.centre, load);
        let toward = view::dot(u, sub(self.body.centre, self.from));
        let toward_body = toward > TOWARD_BODY * self.body.reach;
        // At O a component lies along an axis, beside which it is drawn from its point.
        let at_origin = view::norm(self.from) < INSIDE * self.body.reach;
        let along_body_line = side.length() > 0.0 && (alone || !at_origin);
        if load && !into_point && toward_body && along_body_line {
            into_point = true;
            (from, to, free) = self.ends(canvas, u, length, into_point);
            side = canvas.beside(from, to, self.body.centre, load);
        }
        // A free head landing on another arrow's head (a weight's on a reaction's) is drawn
        // shorter, else longer, so the two are told apart.
        let apart = HEADS_APART * self.body.reach;
        if !into_point && canvas.head_near(to, apart) {
            let other = [SHORTER, LONGER]
                .map(|k| k * length)
                .into_iter()
                .find(|l| !canvas.head_near(self.ends(canvas, u, *l, false).1, apart));
            if let Some(l) = other {
                length = l;
                (from, to, free) = self.ends(canvas, u, length, false);
                side = canvas.beside(from, to, self.body.centre, load);
            }
        }
        let outward = match into_point {
            true => scaled(u, -1.0),
            false => u,
        };
        // A load at a point out of sight behind the body (a box's far corner).
        let hidden = load && self.body.hides(canvas, self.from, INSIDE * self.body.reach);
        // A motion vector from a point inside the body (ω at a box's G) goes under its faces
        // until it comes out of sight's way, as the axes do.
        let mut shown_from = from;
        let depth = INSIDE * self.body.reach;
        let drawn = view::norm(sub(to, from));
        if !load && !into_point && self.body.surrounds(self.from, u, depth) {
            let hidden = self.body.hidden_along(canvas, from, u, drawn);
            if hidden > 0.0 && hidden < drawn {
                shown_from = add(from, scaled(u, hidden));
                canvas.path_beside(Layer::Behind, &[from, shown_from], false, self.stroke, side);
            }
        }
        // A load is dashed where it is out of sight: from a hidden point, as far as it runs
        // inside the body's outline (past it, a push on a far face comes from out of the
        // body's way, in sight); from a point outside the body, where it passes behind a
        // face (R_z from O behind a wheel) or a part. From a point inside the body it is
        // drawn over it, as a textbook draws the weight at a box's G. Such a load is one
        // dashed arrow from its point, with its runs in sight drawn solid over it.
        let inside = self.body.surrounds(self.from, u, depth);
        let runs = match (load, hidden) {
            (true, true) => self
                .body
                .runs_along(from, u, drawn, |q| self.body.covers(canvas, q)),
            (true, false) if !inside => self
                .body
                .runs_along(from, u, drawn, |q| self.body.out_of_sight(canvas, q)),
            _ => Vec::new(),
        };
        let partly_hidden = runs.iter().any(|run| run.2);
        let stroke = match partly_hidden {
            true => Stroke {
                dashes: Dashes::Hidden,
                ..self.stroke
            },
            false => self.stroke,
        };
        canvas.arrow_beside(
            Layer::Front,
            shown_from,
            to,
            self.double,
            stroke,
            self.role.clone(),
            side,
        );
        let at = |t: f64| add(from, scaled(u, t));
        for &(a, b, _) in runs.iter().filter(|run| partly_hidden && !run.2) {
            canvas.path_beside(Layer::Front, &[at(a), at(b)], false, self.stroke, side);
        }
        canvas.label_beside(label, free, outward, side);
        // A later vector along this one's line is drawn beside it (a normal force under a
        // weight, v̄ the way ω points from G), not over it.
        canvas.keep_arrow_clear(from, to, side);
        Some(Arrow {
            direction: u,
            length: stretched(canvas, u, length),
            ends: [from, to],
            beside: side.length() > 0.0,
        })
    }

    /// The length of an arrow along the unit `u` from the point (into it when `into_point`):
    /// a vector at a point inside the body (the body on both sides of it, as ω at a
    /// sphere's or a box's G) or a load out of sight behind it (a box's far corner) reaches
    /// out past it, so its free end and its label stand clear of the body.
    fn length_from(&self, canvas: &Canvas, u: P3, into_point: bool, load: bool) -> f64 {
        let outward = match into_point {
            true => scaled(u, -1.0),
            false => u,
        };
        let (reach, depth) = (self.body.reach, INSIDE * self.body.reach);
        if self.body.surrounds(self.from, outward, depth) {
            // PAST_BODY of the reach past the outline on the page, however foreshortened.
            let on_page = canvas
                .project(outward)
                .minus(canvas.project([0.0; 3]))
                .length();
            let past = PAST_BODY * reach / on_page.clamp(SHORTEST_DRAWN, 1.0);
            self.length
                .max(self.body.beyond(canvas, self.from, outward) + past)
        } else if load && self.body.hides(canvas, self.from, depth) {
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
pub(super) fn whole_label(v: &Vector, value: P3, name: Option<&str>) -> Expr {
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
pub(super) fn magnitude(c: &Expr, value: f64) -> Expr {
    match value < 0.0 {
        true => -c,
        false => c.clone(),
    }
}

/// Whether a component is one symbol, or its negative (`C_y`, `-w_2`).
pub(super) fn one_symbol(c: &Expr) -> bool {
    c.as_symbol().or_else(|| (-c).as_symbol()).is_some()
}

/// The axes of a vector's components that are not zero.
pub(super) fn nonzero(v: &Vector) -> Vec<usize> {
    (0..3).filter(|k| !v[*k].is_zero()).collect()
}

/// The components a vector is drawn by: those that are not zero, nor vanish at the figure's
/// values (a cone's `ω_y = p r/l + ω₁` once rolling fixes `p`); all of them where every one
/// vanishes there.
fn drawn_components(v: &Vector, value: P3) -> Vec<usize> {
    let largest = value.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    nonzero(v)
        .into_iter()
        .filter(|k| largest == 0.0 || value[*k].abs() > VANISHES * largest)
        .collect()
}

/// Whether a vector is drawn as one arrow: no unknown in it, or one component (its line is
/// known whatever its unknown magnitude); else by components.
pub(super) fn drawn_whole(v: &Vector, unknowns: &[Symbol]) -> bool {
    !holds_any(v, unknowns) || nonzero(v).len() == 1
}

/// Whether a name is a word (`push`, `front`, `weight`): three or more lower-case letters
/// that are not a Greek letter's name.
pub(super) fn is_word(name: &str) -> bool {
    name.len() >= 3
        && name.chars().all(|c| c.is_ascii_lowercase())
        && Symbol::new(name).latex().starts_with(r"\mathit")
}

/// A label for a name as written (`C`, `P1`, `omega_x`, `weight`): the symbol of that name.
pub(super) fn named(name: &str) -> String {
    label(&symbol(name))
}

/// The symbol of a name as written.
pub(super) fn symbol(name: &str) -> Expr {
    Expr::sym(Symbol::new(name))
}

/// A label for `e`: its LaTeX as the mathematics of a label where the markup of titles
/// reads it, else its text as words (`weight`, `m g sin(θ)`).
pub(super) fn label(e: &Expr) -> String {
    label_equal(std::slice::from_ref(e))
}

/// A label for the equal vectors one arrow stands for (`ω₂ = Ω`), as [`label`] writes one.
pub(super) fn label_equal(es: &[Expr]) -> String {
    let list = |write: fn(&Expr) -> String, equals: &str| {
        es.iter().map(write).collect::<Vec<_>>().join(equals)
    };
    let maths = format!("${}$", list(print::latex, " = "));
    match markup::validate(&maths) {
        Ok(()) => maths,
        Err(_) => list(print::text, " = ").replace('$', ""),
    }
}
