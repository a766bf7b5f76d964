//! `find balance in planes z = a, z = b at radius r`: the planes across one shaft axis (the
//! letter names it), apart from each other, and a positive radius; each refused at its text.
//! Each length is read in its units and brought into the scene's unit system (`z = 50 mm` is 1/20 m).

use super::super::model::BalancePlanes;
use super::super::units::Dimension;
use super::{span, Reader, Rule};
use crate::algebra::{Axis, Symbol};
use crate::parse::Diagnostic;
use pest::iterators::Pair;

impl Reader<'_> {
    /// Reads the balance request into [`super::super::model::Scene::balance`].
    pub(super) fn balance(&mut self, p: Pair<Rule>) -> Result<(), Diagnostic> {
        let at = span(&p);
        if self.scene.balance.is_some() {
            return Err(self
                .error(at, "balance is asked for twice")
                .with_help("ask for one balance in 'find'"));
        }
        let inner: Vec<Pair<Rule>> = p.into_inner().collect();
        let [first, second, radius] = inner.as_slice() else {
            return Err(self.error(at, "expected two planes and a radius"));
        };
        let (axis, a) = self.plane(first)?;
        let (other, b) = self.plane(second)?;
        if axis != other {
            let letter = |x: Axis| ["x", "y", "z"][x.index()];
            return Err(self
                .error(
                    span(second),
                    format!(
                        "the planes are across two axes, {} and {}",
                        letter(axis),
                        letter(other)
                    ),
                )
                .with_help(format!(
                    "both planes are across the shaft axis: write '{0} = ..., {0} = ...'",
                    letter(axis)
                )));
        }
        let values = |s: Symbol| self.scene.value(s);
        let same_value =
            matches!((a.eval::<f64>(&values), b.eval::<f64>(&values)), (Ok(x), Ok(y)) if x == y);
        if a == b || same_value {
            return Err(self
                .error(span(second), "the two planes are one plane")
                .with_help("choose two planes apart along the shaft"));
        }
        let r = self.quantity(radius, Dimension::LENGTH)?;
        self.positive(
            "the radius of the correction masses",
            "radius",
            radius.as_str().trim(),
            "m",
            &r,
            span(radius),
        )?;
        self.scene.balance = Some(BalancePlanes {
            axis,
            planes: (a, b),
            radius: r,
        });
        Ok(())
    }

    /// `z = a`: the axis and the position along it, a length.
    fn plane(&self, p: &Pair<Rule>) -> Result<(Axis, crate::algebra::Expr), Diagnostic> {
        let inner: Vec<Pair<Rule>> = p.clone().into_inner().collect();
        let [letter, position] = inner.as_slice() else {
            return Err(self.error(span(p), "expected a plane such as 'z = a'"));
        };
        let axis = match letter.as_str() {
            "x" => Axis::X,
            "y" => Axis::Y,
            _ => Axis::Z,
        };
        Ok((axis, self.quantity(position, Dimension::LENGTH)?))
    }
}
