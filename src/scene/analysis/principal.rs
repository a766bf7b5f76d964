//! `find principal_G`, `find principal_O`: the principal moments and axes of the body's
//! inertia tensor about G (`[Ī]`, from the body about G) or about O (`[I_O]`), from
//! [`crate::mechanics::principal_frame`]; an order or a numeric solution that needs the
//! givens' values, without them, is refused at the `find`, naming the givens.

use super::{Analyser, Value};
use crate::algebra::Domains;
use crate::mechanics::derivation::presented as shown;
use crate::mechanics::principal_frame::{principal_frame, PrincipalError, PrincipalFrame};
use crate::parse::Diagnostic;
use crate::scene::model::Request;

impl Analyser<'_> {
    /// The principal frame about O (`about_o`) or about G, its steps in the plan.
    pub(super) fn principal(&mut self, r: &Request, about_o: bool) -> Result<Value, Diagnostic> {
        let at = r.span;
        let (tensor, point) = if about_o {
            (self.inertia_about_o(at)?, "O")
        } else {
            (self.body(at)?.inertia.clone(), "G")
        };
        let scene = self.scene;
        let values = |s| scene.value(s);
        match principal_frame(&tensor, point, &scene.domains(), &values) {
            Ok((frame, derivation)) => {
                self.plan.extend(derivation.steps);
                Ok(Value::Principal(frame))
            }
            Err(PrincipalError::NeedsValues(symbols)) => {
                let names: Vec<&str> = symbols.iter().map(|s| s.name()).collect();
                let first = names.first().copied().unwrap_or("m");
                Err(self.fail(
                    at,
                    format!(
                        "{} needs values for {}: the order of the principal moments about {point}, or the axes of a tensor with several products of inertia, is decided with the givens' values",
                        r.name,
                        names.join(", ")
                    ),
                    format!("give them values, e.g. 'given {first} = <number> <unit>'"),
                ))
            }
            Err(PrincipalError::Physics(e)) => Err(self.fail(
                at,
                format!("{} cannot be found: {e}", r.name),
                "check the masses and dimensions of the body",
            )),
            Err(PrincipalError::Algebra(e)) => Err(self.algebra(at)(e)),
        }
    }
}

/// The frame as it is shown: each moment and axis component in its shortest form.
pub(super) fn presented(frame: PrincipalFrame, domains: &Domains) -> PrincipalFrame {
    PrincipalFrame {
        moments: frame.moments.map(|m| shown(&m, domains)),
        axes: frame.axes.map(|e| e.map(|c| shown(&c, domains))),
        remark: frame.remark,
    }
}
