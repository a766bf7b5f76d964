//! `find balance in planes z = a, z = b at radius r`: the scene's body must turn about the
//! shaft axis the planes are across (a fixed point O on it, ω along it); its unbalance is
//! its first moment `Σ mᵢ r̄ᵢ` and its products about O, and the correction masses, their
//! angles and the residual reactions come from [`two_plane_balance`]. The scene's bearings
//! are its first two forces at points on the axis, at two different places along it.

use super::super::model::{Scene, Span};
use super::{Analyser, Value};
use crate::algebra::{Expr, Symbol};
use crate::mechanics::mass_centre::first_moment;
use crate::mechanics::two_plane_balance::{two_plane_balance, Planes, Rotor};
use crate::parse::Diagnostic;

impl Analyser<'_> {
    pub(super) fn balance(&mut self, at: Span) -> Result<Value, Diagnostic> {
        let scene = self.scene;
        let Some(balance) = &scene.balance else {
            return Err(self.fail(
                at,
                "no planes for the balance",
                "write 'find balance in planes z = a, z = b at radius r'",
            ));
        };
        let a = balance.axis.index();
        let letter = ["x", "y", "z"][a];
        if !scene.fixed_point {
            return Err(self.fail(
                at,
                "balancing needs a body turning about a fixed axis",
                format!(
                    "add 'fixed point' (O on the shaft axis) and 'omega = w*{}'",
                    ["i", "j", "k"][a]
                ),
            ));
        }
        let omega = self.kinematics(at)?.omega.clone();
        let along = omega
            .iter()
            .enumerate()
            .all(|(k, c)| (k == a) != c.is_zero());
        if !along {
            return Err(self.fail(
                at,
                format!("balancing needs ω along the shaft axis {letter}, the axis the planes are across"),
                format!("write omega = w*{} for a shaft along {letter}, or planes across the axis of ω", ["i", "j", "k"][a]),
            ));
        }
        let mass = self.mass_centre(at)?.mass;
        let inertia = self.inertia_about_o(at)?;
        let parts = self.parts(at)?;
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        let moment = first_moment(&parts);
        let s_b = moment[b].expand().map_err(self.algebra(at))?;
        let s_c = moment[c].expand().map_err(self.algebra(at))?;
        let on_axis = |p: &crate::algebra::Vector| p[b].is_zero() && p[c].is_zero();
        let mut stations: Vec<&Expr> = Vec::new();
        for force in scene.forces.iter().filter(|f| on_axis(&f.point)) {
            if stations.len() < 2 && stations.iter().all(|s| **s != force.point[a]) {
                stations.push(&force.point[a]);
            }
        }
        let bearings = match stations.as_slice() {
            [first, second] => Some((*first, *second)),
            _ => None,
        };
        let (corrections, derivation) = two_plane_balance(
            &Rotor {
                mass: &mass,
                first_moment: (&s_b, &s_c),
                inertia: &inertia,
            },
            &Planes {
                axis: balance.axis,
                positions: (&balance.planes.0, &balance.planes.1),
                radius: &balance.radius,
                labels: correction_labels(scene),
            },
            bearings,
            &scene.domains(),
        )
        .map_err(self.algebra(at))?;
        self.plan.extend(derivation.steps);
        Ok(Value::Balance(Box::new(corrections)))
    }
}

/// The subscripts of the corrections' names: `1`, `2` (`m_1`, `θ_1`, `P_1`, `Q_1`), else
/// `a`, `b`, else `c1`, `c2`: the first pair the scene has no name of (unbalance masses
/// given as `m1`, `m2` are `m_1`, `m_2`: a page must not read `m_1 = …m_1…`).
fn correction_labels(scene: &Scene) -> [&'static str; 2] {
    let taken = |name: String| {
        let s = Symbol::new(&name);
        scene.givens.iter().any(|g| g.symbol == s) || scene.is_unknown(s)
    };
    let free = |labels: &[&str; 2]| {
        !labels.iter().any(|k| {
            ["m", "theta", "P", "Q"]
                .iter()
                .any(|letter| taken(format!("{letter}_{k}")))
        })
    };
    [["1", "2"], ["a", "b"]]
        .into_iter()
        .find(free)
        .unwrap_or(["c1", "c2"])
}
