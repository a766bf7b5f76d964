//! A body's orientation, the rotation R that takes its own axes to the frame's
//! (`mechanics/rotation.rs`), from the words after its position:
//!
//! - `along x|y|z`: the shape's own x' axis (a rod's length, a disk's or a cylinder's axis, a
//!   plate's side a, a prism's edge a) along the named axis, y' and z' cyclically after it;
//! - `rotated 30 deg about z, then 20 deg about x`: each rotation about the frame's fixed
//!   axis, in the order written, after `along`: R = R_x(20°) R_z(30°) R_along;
//! - `rotated 2 deg about (0, 1, 1)`: about a direction (normalised; a zero one refused);
//! - `axes (l1, m1, n1), (l2, m2, n2), (l3, m3, n3)`: direction cosines, each triple one of
//!   the body's axes x', y', z' in the frame, refused unless orthonormal and right-handed.

use super::super::units::Dimension;
use super::{span, Reader, Rule};
use crate::algebra::vector_products::dot;
use crate::algebra::{Axis, Expr, Matrix, Vector};
use crate::mechanics::rotation::{about_axis, about_direction, along, from_direction_cosines};
use crate::parse::Diagnostic;
use crate::scene::model::Turn;
use pest::iterators::Pair;

impl Reader<'_> {
    /// `rotation` turned by the orientation `p` says (`along`, a rotation, direction cosines),
    /// a rotation's turn added to `turns`.
    pub(super) fn turned(
        &self,
        p: &Pair<Rule>,
        rotation: Matrix,
        turns: &mut Vec<Turn>,
    ) -> Result<Matrix, Diagnostic> {
        Ok(match p.as_rule() {
            Rule::axis => along(frame_axis(p)),
            Rule::rotation => {
                let (turn, angle, axis) = self.rotation(p)?;
                turns.push(Turn {
                    angle,
                    axis,
                    from: rotation.clone(),
                });
                turn * rotation
            }
            Rule::axes => self.direction_cosines(p)?,
            _ => rotation,
        })
    }

    /// `ANGLE about x|y|z` or `ANGLE about (a, b, c)`: the rotation, the angle and the axis.
    fn rotation(&self, p: &Pair<Rule>) -> Result<(Matrix, Expr, Vector), Diagnostic> {
        let mut inner = p.clone().into_inner();
        let (Some(angle), Some(about)) = (inner.next(), inner.next()) else {
            return Err(self.error(span(p), "expected an angle and an axis"));
        };
        let angle = self.quantity(&angle, Dimension::NONE)?;
        if about.as_rule() == Rule::axis {
            let axis = frame_axis(&about);
            let mut direction = Vector::from_element(Expr::zero());
            direction[axis.index()] = Expr::one();
            return Ok((about_axis(axis, &angle), angle, direction));
        }
        let direction = self.direction(&about)?;
        let zero = || {
            self.error(
                span(&about),
                "a rotation about a zero direction has no axis",
            )
            .with_help("give the axis as a direction that is not zero, such as (0, 1, 1)")
        };
        let value = |s| self.scene.value(s);
        let length = dot(&direction, &direction);
        if length.eval(&value).is_ok_and(|l: f64| l == 0.0) {
            return Err(zero());
        }
        let turn = about_direction(&direction, &angle).ok_or_else(zero)?;
        Ok((turn, angle, direction))
    }

    /// `(a, b, c)`: a direction, its three components in one unit (or none).
    fn direction(&self, p: &Pair<Rule>) -> Result<Vector, Diagnostic> {
        let mut components = Vec::with_capacity(3);
        let mut unit = None;
        for c in p.clone().into_inner() {
            let e = self.math(&c)?;
            let d = self.dimension(&e, span(&c))?;
            if !e.is_zero() {
                let first = *unit.get_or_insert(d);
                self.expect_dimension(&e, first, span(&c))?;
            }
            components.push(self.in_units(&e, span(&c))?);
        }
        Ok(Vector::from_iterator(components))
    }

    /// `axes (…), (…), (…)`: the rotation whose columns are the three triples.
    fn direction_cosines(&self, p: &Pair<Rule>) -> Result<Matrix, Diagnostic> {
        let triples: Vec<Pair<Rule>> = p.clone().into_inner().collect();
        let mut axes = Vec::with_capacity(3);
        for t in &triples {
            let mut components = Vec::with_capacity(3);
            for c in t.clone().into_inner() {
                components.push(self.quantity(&c, Dimension::NONE)?);
            }
            axes.push(Vector::from_iterator(components));
        }
        let axes: [Vector; 3] = axes
            .try_into()
            .map_err(|_| self.error(span(p), "expected three triples"))?;
        let value = |s| self.scene.value(s);
        from_direction_cosines(axes, &value).map_err(|problems| {
            let at = problems[0]
                .first_axis()
                .and_then(|k| triples.get(k))
                .map_or(span(p), span);
            let reasons: Vec<String> = problems.iter().map(ToString::to_string).collect();
            self.error(
                at,
                format!(
                    "these direction cosines are not a rotation: {}",
                    reasons.join("; ")
                ),
            )
            .with_help(
                "each triple is one of the body's axes x', y', z' written in the frame: unit \
                 vectors, each perpendicular to the others, with z' = x' × y'",
            )
        })
    }
}

pub(super) fn frame_axis(p: &Pair<Rule>) -> Axis {
    match p.as_str() {
        "y" => Axis::Y,
        "z" => Axis::Z,
        _ => Axis::X,
    }
}
