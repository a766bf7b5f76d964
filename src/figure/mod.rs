//! A figure drawn from the scene, as a textbook's solution starts: the body part by part,
//! the axes from O, ω, the forces at their points, the couples, the impulses, the bearings
//! and the fixed axis, named points, the floor a body rolls on, and for a gyroscope or top the
//! vertical, θ, φ̇ and ψ̇.
//!
//! One drawing, two writers: [`figure`] projects the scene once ([`view`], the near-isometric
//! view with the scene's up drawn up), at the sizes of [`sizes`], scales it to
//! [`MARKS_WIDTH`] units (a unit is a CSS pixel in SVG, ¾ pt in TikZ), places each label
//! where it overlaps no other label and no stroke ([`labels`]); [`svg`] and [`tikz`] write the
//! marks and labels as they are. Nothing is drawn that the scene does not state.

mod arrows;
mod body;
mod canvas;
mod dimensions;
mod euler;
mod extent;
mod ground;
mod labels;
mod link;
mod loads;
pub mod sizes;
mod supports;
pub mod svg;
pub mod tikz;
mod turns;
pub mod view;

use crate::algebra::AlgebraError;
use crate::scene::model::Scene;
pub use canvas::Canvas;
pub use view::{P2, P3};

/// The width the marks are scaled to (the labels may stand beyond), and the most height; a
/// drawing taller than it is wide (a vertical shaft) is given the area of a square
/// [`MARKS_HEIGHT`] on a side, up to [`MARKS_TALLEST`] high, so it is drawn taller, not
/// smaller.
pub const MARKS_WIDTH: f64 = 260.0;
pub const MARKS_HEIGHT: f64 = 180.0;
pub const MARKS_TALLEST: f64 = 240.0;
/// The labels' font size, in figure units.
pub const FONT_SIZE: f64 = 14.0;
/// How much a face hides what is behind it: the axes and parts behind a body show faintly.
pub const FACE_OPACITY: f64 = 0.82;
/// How far a load's arrow is drawn beside a line it would lie along (an axis, a rod, the
/// shaft), in figure units from the line's edge: a reaction along the shaft, a weight along
/// a rod, ω along an axle.
pub const BESIDE: f64 = 5.6;
/// How far apart two arrows along one line are drawn (ω and v̄ the same way from G, a weight
/// over a normal force), in figure units: their heads, [`HEAD_HALF_WIDTH`] to a side, a few
/// units clear of each other.
pub const ARROWS_APART: f64 = 10.0;
/// An arrow head's length and half width.
pub const HEAD_LENGTH: f64 = 8.0;
pub const HEAD_HALF_WIDTH: f64 = 3.0;

/// How a line is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    /// In figure units: 1.4 for an outline, 3.5 for a rod, 0.9 for an axis.
    pub width: f64,
    pub ink: Ink,
    pub dashes: Dashes,
}

/// A line's colour: black and one accent colour, and the paper's white for a gap.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ink {
    Black,
    /// The loads'.
    Accent,
    /// A band of white under a nearer rod, so that a farther line crossing behind it shows
    /// broken, as a textbook draws it.
    Paper,
}

/// A line's dashes, as a drawing tells them apart.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dashes {
    Solid,
    /// Short dashes: an edge out of sight, a body known only by its inertia.
    Hidden,
    /// Long dash, dot: an axis of symmetry or turning, a reference line.
    CentreLine,
}

impl Stroke {
    pub const OUTLINE: Stroke = Stroke::black(1.3);
    pub const ROD: Stroke = Stroke::black(4.0);
    pub const SHAFT: Stroke = Stroke::black(3.0);
    pub const AXIS: Stroke = Stroke::black(0.8);
    pub const MOTION: Stroke = Stroke::black(1.2);
    pub const LOAD: Stroke = Stroke {
        width: 1.4,
        ink: Ink::Accent,
        dashes: Dashes::Solid,
    };
    /// A dimension line and its extension lines.
    pub const DIMENSION: Stroke = Stroke::black(0.6);
    /// The outline of the floor a body rolls on.
    pub const GROUND: Stroke = Stroke::black(0.7);
    /// A wire the body hangs from.
    pub const WIRE: Stroke = Stroke::black(1.0);
    /// A hidden edge.
    pub const HIDDEN: Stroke = Stroke {
        width: 1.0,
        ink: Ink::Black,
        dashes: Dashes::Hidden,
    };
    pub const CENTRE_LINE: Stroke = Stroke {
        width: 0.7,
        ink: Ink::Black,
        dashes: Dashes::CentreLine,
    };

    /// The white band under a rod `width` wide ([`Ink::Paper`]).
    pub const fn gap(width: f64) -> Stroke {
        Stroke {
            width,
            ink: Ink::Paper,
            dashes: Dashes::Solid,
        }
    }

    const fn black(width: f64) -> Stroke {
        Stroke {
            width,
            ink: Ink::Black,
            dashes: Dashes::Solid,
        }
    }
}

/// What an arrow stands for: a writer draws an impulse's head open, the others filled.
#[derive(Debug, Clone, PartialEq)]
pub enum Role {
    Axis,
    /// A force (or one of its components) of the named force.
    Force(String),
    Impulse,
    Couple,
    AngularVelocity,
    /// The angular acceleration α (where the frame turns with the body).
    AngularAcceleration,
    /// A velocity: the mass centre's, or its just before an impact.
    Velocity,
    /// The mass centre's acceleration ā.
    Acceleration,
    /// The frame's angular velocity Ω, where it differs from ω.
    FrameRate,
    /// A rate of an Eulerian angle, drawn as a curved arrow.
    Rate,
    /// The angular momentum H_G of a body under no force, along the vertical Z.
    AngularMomentum,
}

/// A mark of the figure, in figure units, y up.
#[derive(Debug, Clone, PartialEq)]
pub enum Mark {
    /// A polyline, or with `closed` a polygon, filled with the paper's white when `filled` (so
    /// it mostly hides what was drawn before it: [`FACE_OPACITY`]).
    Path {
        points: Vec<P2>,
        closed: bool,
        filled: bool,
        stroke: Stroke,
    },
    /// An arrow from `from` to its head at `to` (along a curve through `via` when it has
    /// points); `double`: two heads, one behind the other (ω, a couple).
    Arrow {
        from: P2,
        via: Vec<P2>,
        to: P2,
        double: bool,
        stroke: Stroke,
        role: Role,
    },
    /// A filled dot (a point mass, G, a named point).
    Dot { at: P2, radius: f64 },
}

/// A label: mathematics in the markup of titles (`$C_y$`), its box centred at `centre`.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    pub markup: String,
    pub centre: P2,
    pub half_width: f64,
    pub half_height: f64,
}

/// A figure: marks drawn in order, then the labels; `min` and `max` bound everything.
#[derive(Debug, Clone)]
pub struct Figure {
    pub marks: Vec<Mark>,
    pub labels: Vec<Label>,
    pub min: P2,
    pub max: P2,
    /// Where the scene's points are drawn: the view, then `scale` about the origin.
    view: view::View,
    scale: f64,
}

impl Figure {
    /// Where the scene's point `p` (its frame, its length unit) stands in the figure.
    pub fn at(&self, p: P3) -> P2 {
        self.view.project(p).times(self.scale)
    }
}

/// Why a scene has no figure.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FigureError {
    #[error("the figure needs a number for {what}: {error}")]
    Value { what: String, error: AlgebraError },
}

/// The figure of `scene`.
///
/// ```
/// use kinetics::figure::{figure, Mark, Role};
/// let scene = kinetics::parse_scene("shaft.scene", "given m = 2 kg
/// given L = 0.6 m
/// given w = 10 rad/s
/// unknown B_y, B_z : N
/// body rod(L) mass m at (L/2, 0, 0)
/// fixed point
/// omega = w*i
/// force B = B_y*j + B_z*k at (L, 0, 0)
/// find B_y")?;
/// let drawn = figure(&scene)?;
/// let b = drawn.at([0.6, 0.0, 0.0]);
/// let starts_at_b = |m: &Mark| matches!(m, Mark::Arrow { from, role: Role::Force(n), .. }
///     if n == "B" && (from.x - b.x).hypot(from.y - b.y) < 1e-9);
/// assert_eq!(drawn.marks.iter().filter(|m| starts_at_b(m)).count(), 2, "B_y and B_z at B");
/// assert!(drawn.labels.iter().any(|l| l.markup == "$B_y$"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn figure(scene: &Scene) -> Result<Figure, FigureError> {
    let sizes = sizes::Sizes::of(scene);
    let mut canvas = Canvas::new(scene, &sizes)?;
    let body = body::draw(&mut canvas, scene)?;
    let floors = ground::draw(&mut canvas, scene, &body)?;
    supports::stated(&mut canvas, scene, &body)?;
    turns::draw(&mut canvas, scene, &body)?;
    loads::draw(&mut canvas, scene, &body, &floors)?;
    Ok(canvas.finish())
}

impl Mark {
    /// The points the mark's line runs through: a path's points, an arrow's from its tail
    /// through its curve to its tip (no heads), a dot's centre.
    pub fn line(&self) -> Vec<P2> {
        match self {
            Mark::Path { points, .. } => points.clone(),
            Mark::Arrow { from, via, to, .. } => std::iter::once(*from)
                .chain(via.iter().copied())
                .chain([*to])
                .collect(),
            Mark::Dot { at, .. } => vec![*at],
        }
    }

    /// An arrow's heads, each a triangle (tip, then the two back corners); none for the others.
    pub fn heads(&self) -> Vec<[P2; 3]> {
        match self {
            Mark::Arrow {
                from,
                via,
                to,
                double,
                ..
            } => heads(*from, via, *to, *double),
            _ => Vec::new(),
        }
    }
}

impl Role {
    /// An impulse's head is drawn open (white inside), every other arrow's filled.
    pub fn open_head(&self) -> bool {
        matches!(self, Role::Impulse)
    }
}

/// The heads of an arrow, each a triangle (tip, then the two back corners).
fn heads(from: P2, via: &[P2], to: P2, double: bool) -> Vec<[P2; 3]> {
    let before = via.last().copied().unwrap_or(from);
    let Some(along) = to.minus(before).unit() else {
        return Vec::new();
    };
    let across = along.normal();
    let head = |tip: P2| {
        let back = tip.minus(along.times(HEAD_LENGTH));
        [
            tip,
            back.plus(across.times(HEAD_HALF_WIDTH)),
            back.minus(across.times(HEAD_HALF_WIDTH)),
        ]
    };
    let mut out = vec![head(to)];
    if double {
        out.push(head(to.minus(along.times(HEAD_LENGTH * 0.8))));
    }
    out
}
