//! The `body` statement: a standard shape (or an explicit inertia tensor) with its mass, the
//! position of its mass centre and its orientation (`orientation.rs`), checked for physical
//! admissibility: every length of the shape, the mass and the total mass of the bodies so
//! far are positive (`q > 0`, decided by [`ensure_positive`]: symbolically where it can be,
//! else from the givens' values), and an explicit tensor is one a real body can have.

use super::super::model::Part;
use super::super::units::Dimension;
use super::{span, Reader, Rule};
use crate::algebra::{Expr, Matrix, Symbol, Vector};
use crate::mechanics::inertia::InertiaTensor;
use crate::mechanics::shapes::Shape;
use crate::mechanics::validation::{
    ensure_positive, validate_inertia_tensor, MustBePositive, SymbolFacts,
};
use crate::parse::Diagnostic;
use pest::iterators::Pair;

/// Every shape a body may have, as written.
const SHAPES: &str = "the shapes are rod(L), plate(a, b), disk(r), cylinder(r, h), sphere(r), prism(a, b, c), cone(r, h), tube(r_o, r_i, h), shell(r), ring(r), gyration(k_x, k_y, k_z), point(), inertia(I_x, I_y, I_z, I_xy, I_yz, I_xz)";

impl Reader<'_> {
    pub(super) fn body(
        &mut self,
        inner: Vec<Pair<Rule>>,
        at: (usize, usize),
    ) -> Result<(), Diagnostic> {
        let shape_pair = &inner[0];
        let mut shape_inner = shape_pair.clone().into_inner();
        let kind = shape_inner
            .next()
            .ok_or_else(|| self.error(span(shape_pair), "expected a shape"))?;
        let args: Vec<Pair<Rule>> = shape_inner.collect();
        let explicit = kind.as_str() == "inertia";
        let want = if explicit {
            Dimension::INERTIA
        } else {
            Dimension::LENGTH
        };
        let mut lengths = Vec::new();
        for a in &args {
            lengths.push(self.quantity(a, want)?);
        }
        let shape = if explicit {
            self.explicit_inertia(lengths, span(shape_pair))?
        } else {
            self.shape(&kind, lengths, span(shape_pair))?
        };
        let body = format!("body {} ({})", self.scene.parts.len() + 1, kind.as_str());
        for ((what, length), a) in shape.lengths().into_iter().zip(&args) {
            let quantity = format!("the {what} of {body}");
            self.positive(&quantity, what, a.as_str().trim(), "m", length, span(a))?;
        }
        self.shape_admissible(&shape, &body, &args, span(shape_pair))?;
        let mass = self.quantity(&inner[1], Dimension::MASS)?;
        let written = inner[1].as_str().trim();
        self.positive(
            &format!("the mass of {body}"),
            "mass",
            written,
            "kg",
            &mass,
            at,
        )?;
        self.total_mass_positive(&mass, at)?;
        let mut position = Vector::from_element(Expr::zero());
        let mut rotation = Matrix::identity();
        let mut turns = Vec::new();
        for p in &inner[2..] {
            match p.as_rule() {
                Rule::point => position = self.point(p)?,
                _ => rotation = self.turned(p, rotation, &mut turns)?,
            }
        }
        self.scene.parts.push(Part {
            shape,
            mass,
            position,
            rotation,
            turns,
        });
        Ok(())
    }

    /// Refuses `e` (a length or a mass, written `written`) at `at` unless it is positive,
    /// naming the givens with a value that is not (and their lines) in the help.
    pub(super) fn positive(
        &self,
        quantity: &str,
        kind: &str,
        written: &str,
        unit: &str,
        e: &Expr,
        at: (usize, usize),
    ) -> Result<(), Diagnostic> {
        let scene = &self.scene;
        // Positive by its value, or by its domain: a given mass or length without a value.
        let positive = |s: Symbol| match (scene.value(s), scene.dimension(s)) {
            (Some(v), _) => v > 0.0,
            (None, Some(d)) if !scene.is_unknown(s) => {
                d == Dimension::MASS || d == Dimension::LENGTH
            }
            _ => false,
        };
        let value = |s: Symbol| scene.value(s);
        let facts = SymbolFacts {
            positive: &positive,
            value: &value,
        };
        let what = MustBePositive {
            quantity,
            kind,
            written,
            unit,
        };
        ensure_positive(what, e, &facts).map_err(|err| {
            let culprits = scene.cite_givens_in(e, |v| v <= 0.0);
            let help = if culprits.is_empty() {
                format!("a {kind} must be greater than zero: correct {written}")
            } else {
                format!(
                    "{}; a {kind} must be greater than zero",
                    culprits.join(", ")
                )
            };
            self.error(at, err.to_string()).with_help(help)
        })
    }

    /// The total mass of the bodies so far, this one's `mass` included, is positive too: when
    /// each mass is undecided alone (`x m`, `-x m`), their sum may still be decided.
    fn total_mass_positive(&self, mass: &Expr, at: (usize, usize)) -> Result<(), Diagnostic> {
        let parts = &self.scene.parts;
        if parts.is_empty() {
            return Ok(());
        }
        // Every body adds up all the masses so far: counted, so that thousands of bodies are
        // refused for work, not left to take the square of their number in time.
        crate::algebra::work::count(parts.len() as u64 + 1);
        let masses = parts.iter().map(|p| p.mass.clone()).chain([mass.clone()]);
        let total = Expr::add_all(masses.clone()).expand().map_err(|e| {
            self.error(at, e.to_string())
                .with_help("simplify the masses")
        })?;
        let written = masses
            .map(|m| format!("({m})"))
            .collect::<Vec<_>>()
            .join(" + ");
        let quantity = format!("the total mass of bodies 1 to {}", parts.len() + 1);
        self.positive(&quantity, "total mass", &written, "kg", &total, at)
    }

    /// What a shape's lengths must satisfy beyond each being positive: a tube's inner radius
    /// less than its outer, `r_o − r_i > 0`; radii of gyration whose moments `m k²` a real
    /// body can have (each at most the sum of the other two), decided when they have values.
    fn shape_admissible(
        &self,
        shape: &Shape,
        body: &str,
        args: &[Pair<Rule>],
        at: (usize, usize),
    ) -> Result<(), Diagnostic> {
        match shape {
            Shape::Tube { outer, inner, .. } => {
                let wall = outer - inner;
                let quantity = format!("the wall thickness of {body}");
                let [r_o, r_i] = [&args[0], &args[1]].map(|a| a.as_str().trim());
                let written = format!("{r_o} - {r_i}");
                self.positive(&quantity, "wall thickness", &written, "m", &wall, at)
                    .map_err(|e| {
                        e.with_help(
                            "the inner radius must be less than the outer: tube(r_o, r_i, h)",
                        )
                    })
            }
            Shape::Gyration { radii } => {
                let value = |e: &Expr| e.eval(&|s: Symbol| self.scene.value(s)).ok();
                let Some(k) = radii.iter().map(value).collect::<Option<Vec<f64>>>() else {
                    return Ok(());
                };
                let diagonal = nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(
                    k[0] * k[0],
                    k[1] * k[1],
                    k[2] * k[2],
                ));
                validate_inertia_tensor(&diagonal).map_err(|e| {
                    self.error(at, e.to_string()).with_help(
                        "no real body has these radii of gyration (the moments above are per unit mass, k²): each k² must be at most the sum of the other two",
                    )
                })
            }
            _ => Ok(()),
        }
    }

    /// `inertia(I_x, I_y, I_z, I_xy, I_yz, I_xz)`: checked for physical admissibility when
    /// every component has a value.
    fn explicit_inertia(&self, mut c: Vec<Expr>, at: (usize, usize)) -> Result<Shape, Diagnostic> {
        if c.len() != 6 {
            return Err(self
                .error(at, format!("inertia takes 6 components, found {}", c.len()))
                .with_help("write inertia(I_x, I_y, I_z, I_xy, I_yz, I_xz), products as positive integrals"));
        }
        let products: [Expr; 3] = [c.remove(3), c.remove(3), c.remove(3)];
        let moments: [Expr; 3] = [c.remove(0), c.remove(0), c.remove(0)];
        let tensor = InertiaTensor { moments, products };
        // Evaluation fails only for a missing value or a non-finite one, and each component
        // was refused when read if it was not finite: `None` means a symbol has no value.
        let value = |e: &Expr| e.eval(&|s: Symbol| self.scene.value(s)).ok();
        let numbers: Option<Vec<f64>> = tensor.matrix().iter().map(value).collect();
        if let Some(numbers) = numbers {
            let m = nalgebra::Matrix3::from_column_slice(&numbers);
            validate_inertia_tensor(&m).map_err(|e| {
                self.error(at, e.to_string()).with_help(
                    "these components cannot belong to a real body; check their values and signs",
                )
            })?;
        }
        Ok(Shape::Explicit(tensor))
    }

    fn shape(
        &self,
        kind: &Pair<Rule>,
        mut l: Vec<Expr>,
        at: (usize, usize),
    ) -> Result<Shape, Diagnostic> {
        let expected = |n: usize, usage: &str| -> Result<(), Diagnostic> {
            if l.len() == n {
                Ok(())
            } else {
                Err(self
                    .error(
                        at,
                        format!("{} takes {n} length(s), found {}", kind.as_str(), l.len()),
                    )
                    .with_help(format!("write {usage}")))
            }
        };
        Ok(match kind.as_str() {
            "rod" => {
                expected(1, "rod(L)")?;
                Shape::SlenderRod {
                    length: l.remove(0),
                }
            }
            "plate" => {
                expected(2, "plate(a, b)")?;
                let b = l.remove(1);
                Shape::ThinPlate { a: l.remove(0), b }
            }
            "disk" => {
                expected(1, "disk(r)")?;
                Shape::ThinDisk {
                    radius: l.remove(0),
                }
            }
            "cylinder" => {
                expected(2, "cylinder(r, h)")?;
                let h = l.remove(1);
                Shape::SolidCylinder {
                    radius: l.remove(0),
                    length: h,
                }
            }
            "sphere" => {
                expected(1, "sphere(r)")?;
                Shape::SolidSphere {
                    radius: l.remove(0),
                }
            }
            "prism" => {
                expected(3, "prism(a, b, c)")?;
                let c = l.remove(2);
                let b = l.remove(1);
                Shape::RectangularPrism {
                    a: l.remove(0),
                    b,
                    c,
                }
            }
            "cone" => {
                expected(2, "cone(r, h)")?;
                let height = l.remove(1);
                Shape::SolidCone {
                    radius: l.remove(0),
                    height,
                }
            }
            "tube" => {
                expected(3, "tube(r_o, r_i, h)")?;
                let length = l.remove(2);
                let inner = l.remove(1);
                Shape::Tube {
                    outer: l.remove(0),
                    inner,
                    length,
                }
            }
            "shell" => {
                expected(1, "shell(r)")?;
                Shape::SphericalShell {
                    radius: l.remove(0),
                }
            }
            "ring" => {
                expected(1, "ring(r)")?;
                Shape::ThinRing {
                    radius: l.remove(0),
                }
            }
            "gyration" => {
                expected(3, "gyration(k_x, k_y, k_z)")?;
                Shape::Gyration {
                    radii: [l.remove(0), l.remove(0), l.remove(0)],
                }
            }
            "point" => {
                expected(0, "point()")?;
                Shape::PointMass
            }
            other => {
                return Err(self
                    .error(span(kind), format!("unknown shape '{other}'"))
                    .with_help(SHAPES))
            }
        })
    }
}
