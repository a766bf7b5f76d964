//! Impulse and momentum (§18.3): `syst momenta₁ + syst ext imp₁→₂ = syst momenta₂`, six
//! component equations:
//!
//! ```text
//! m v̄₁ + Σ F Δt = m v̄₂          (three linear components)
//! H₁ + Σ M Δt = H₂               (three angular components, about G or a fixed point O)
//! ```

use super::derivation::{Derivation, Relation, Step};
use crate::algebra::vector::expand_each;
use crate::algebra::{AlgebraError, Expr, Vector};

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

/// The six component equations; components that read `0 = 0` are left out.
///
/// A body at rest struck by the impulse `F Δt i` at `b j` from G: its moment about G is
/// `b j × F Δt i = -b F Δt k`, so `F Δt = m v` and `-b F Δt = I_z w` (the other four read
/// `0 = 0`).
///
/// ```
/// use kinetics::mechanics::impulse_momentum::{impulse_momentum, ImpulseMomentum};
/// use kinetics::{parse_expression, Expr, Vector};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap();
/// let vector = |x: &str, y: &str, z: &str| Vector::new(hand(x), hand(y), hand(z));
/// let rest = vector("0", "0", "0");
/// let d = impulse_momentum(&ImpulseMomentum {
///     mass: &hand("m"),
///     velocity_before: &rest,
///     velocity_after: &vector("v", "0", "0"),
///     angular_momentum_before: &rest,
///     angular_momentum_after: &vector("0", "0", "I_z w"),
///     linear_impulse: &vector("F Dt", "0", "0"),
///     angular_impulse: &vector("0", "0", "-b F Dt"),
/// })?;
/// let residuals: Vec<Expr> = d.result().iter().map(|r| r.residual()).collect();
/// assert_eq!(residuals, [hand("F Dt - m v"), hand("-b F Dt - I_z w")]);
/// # Ok::<(), kinetics::AlgebraError>(())
/// ```
pub fn impulse_momentum(p: &ImpulseMomentum) -> Result<Derivation, AlgebraError> {
    let linear_before = expand_each(&(p.velocity_before.map(|v| p.mass * &v) + p.linear_impulse))?;
    let linear_after = expand_each(&p.velocity_after.map(|v| p.mass * &v))?;
    let angular_before = expand_each(&(p.angular_momentum_before + p.angular_impulse))?;
    let angular_after = expand_each(p.angular_momentum_after)?;
    Ok(Derivation {
        name: "impulse".into(),
        title: "impulse and momentum".into(),
        steps: vec![Step {
            vectors: Vec::new(),
            table: None,
            title: r"impulse and momentum: $m\bar{\mathbf{v}}_1 + \Sigma\mathbf{F}\,\Delta t = m\bar{\mathbf{v}}_2$ ($x, y, z$), then $\mathbf{H}_1 + \Sigma\mathbf{M}\,\Delta t = \mathbf{H}_2$ ($x, y, z$)".into(),
            relations: [
                Relation::nonzero_components(&linear_before, &linear_after),
                Relation::nonzero_components(&angular_before, &angular_after),
            ]
            .concat(),
        }],
    })
}
