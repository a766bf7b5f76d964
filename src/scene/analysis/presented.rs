//! A result as it is shown: each expression in its shortest form
//! ([`crate::mechanics::derivation::presented`]), a balance's angle and mass, a tensor's
//! components, a principal frame's moments and axes.

use super::{principal, Value};
use crate::algebra::Domains;
use crate::mechanics::derivation::presented;
use crate::mechanics::torque_free_axisymmetric::Precession;
use crate::mechanics::two_plane_balance::{Correction, CorrectionAngle};

impl Value {
    /// The value as it is shown: each component in its shortest form
    /// ([`crate::mechanics::derivation::presented`]).
    pub(super) fn presented(self, domains: &Domains) -> Value {
        match self {
            Value::Scalar(e) => Value::Scalar(presented(&e, domains)),
            Value::Vector(v) => Value::Vector(v.map(|c| presented(&c, domains))),
            Value::Balance(corrections) => Value::Balance(Box::new(corrections.map(|k| {
                let angle = match k.angle {
                    CorrectionAngle::Atan2 { q, p } => CorrectionAngle::Atan2 {
                        q: presented(&q, domains),
                        p: presented(&p, domains),
                    },
                    exact_or_undefined => exact_or_undefined,
                };
                let mass = presented(&k.mass, domains);
                Correction { mass, angle, ..k }
            }))),
            Value::Tensor(m) => Value::Tensor(m.map(|c| presented(&c, domains))),
            Value::Principal(p) => Value::Principal(principal::presented(p, domains)),
            Value::Precession(p) => Value::Precession(Box::new(Precession {
                tan_gamma: presented(&p.tan_gamma, domains),
                sense: p.sense,
            })),
        }
    }
}
