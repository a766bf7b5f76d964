//! Impulse and momentum (§18.3): `syst momenta₁ + syst ext imp₁→₂ = syst momenta₂`, six
//! component equations:
//!
//! ```text
//! m v̄₁ + Σ F Δt = m v̄₂          (three linear components)
//! H₁ + Σ M Δt = H₂               (three angular components, about G or a fixed point O)
//! ```

use super::derivation::{Derivation, Relation, Step};
use crate::algebra::{Expr, Vector};
use crate::print::Axis;

/// The momenta and impulses of one impact or interval.
pub struct ImpulseMomentum<'a> {
    pub mass: &'a Expr,
    pub velocity_before: &'a Vector,
    pub velocity_after: &'a Vector,
    pub angular_momentum_before: &'a Vector,
    pub angular_momentum_after: &'a Vector,
    /// `Σ F Δt`.
    pub linear_impulse: &'a Vector,
    /// `Σ M Δt` about the same point as the angular momenta.
    pub angular_impulse: &'a Vector,
}

/// The six component equations.
pub fn impulse_momentum(p: &ImpulseMomentum) -> Derivation {
    let axes = [Axis::X, Axis::Y, Axis::Z];
    let linear: Vec<Relation> = (0..3)
        .map(|k| {
            Relation::new(
                p.mass * &p.velocity_before[k] + &p.linear_impulse[k],
                p.mass * &p.velocity_after[k],
                axes[k],
            )
        })
        .collect();
    let angular: Vec<Relation> = (0..3)
        .map(|k| {
            Relation::new(
                &p.angular_momentum_before[k] + &p.angular_impulse[k],
                p.angular_momentum_after[k].clone(),
                axes[k],
            )
        })
        .collect();
    let mut relations: Vec<Relation> = linear;
    relations.extend(angular);
    Derivation {
        name: "impulse".into(),
        title: "impulse and momentum".into(),
        steps: vec![Step {
            title:
                "linear components m v̄₁ + Σ F Δt = m v̄₂, then angular components H₁ + Σ M Δt = H₂"
                    .into(),
            relations,
        }],
    }
}
