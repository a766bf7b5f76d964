//! The numbers a figure is drawn with: each given's value; a symbolic length a default, the
//! same wherever the symbol stands (the first symbolic length four times the largest length
//! given, or 1 without one, the next ones in other proportions, so `a × b` is no square; a
//! round shape's radius smaller, so a disk on an axle of length L is no wheel of radius L); a
//! rate, a velocity or an angular velocity, in other proportions again, so that ω and v̄ given
//! by their components point different ways, as a textbook draws them; any other symbol (a
//! mass, a force's magnitude, an unknown, the time t) 1, and an angle without a value 30°,
//! or another where an angle is given at about 30° (so θ and the γ given are told apart).
//! An unknown the scene's kinematic constraints fix alone (a cone's spin rate from rolling)
//! takes the value they give it, so ω is drawn the way it turns out, not the way its stated
//! form would point with the unknown at 1.
//! Only directions and sizes matter to a drawing: a force is drawn at one length whatever its
//! magnitude.

use super::view::P3;
use crate::algebra::{AlgebraError, Expr, Symbol, Vector};
use crate::mechanics::eulerian_angles::EulerianAngles;
use crate::scene::kinematic_constraints::solve_constraints;
use crate::scene::model::{Scene, Span};
use crate::scene::units::Dimension;
use std::collections::HashMap;

/// The proportions of the symbolic lengths, in the order they are given: the radii of the
/// round shapes among them, and the others (a rod's length, a side, a position).
const RADII: [f64; 3] = [0.4, 0.25, 0.3];
const LENGTHS: [f64; 5] = [1.0, 0.6, 0.8, 1.3, 0.45];
/// The proportions of the symbolic rates, in the order they are given: in the textbook's
/// view `v_x, v_y, v_z` and `w_x, w_y, w_z` are drawn over 20° apart and from every axis, and
/// two thirds of their length (a vector of equal components points nearly at the eye).
const RATES: [f64; 6] = [0.2, 1.2, 0.5, 0.3, 0.8, 1.2];
/// The angles, in degrees, an angle without a value is drawn at: the first further than
/// [`ANGLES_APART_DEG`] from every angle given.
const ANGLES_DEG: [f64; 4] = [30.0, 20.0, 40.0, 15.0];
const ANGLES_APART_DEG: f64 = 5.0;

/// The value of every symbol a scene's figure evaluates.
pub struct Sizes {
    values: HashMap<Symbol, f64>,
    /// The length the first symbolic length is drawn at: a body given by its inertia alone
    /// is drawn a quarter of it across.
    pub base: f64,
}

impl Sizes {
    pub fn of(scene: &Scene) -> Sizes {
        let largest_given = scene
            .givens
            .iter()
            .filter(|g| g.dimension == Dimension::LENGTH)
            .filter_map(|g| g.value)
            .map(f64::abs)
            .fold(0.0, f64::max);
        let base = if largest_given > 0.0 {
            4.0 * largest_given
        } else {
            1.0
        };
        let theta = EulerianAngles::chapter().nutation;
        let mut values = HashMap::new();
        let radii: Vec<Symbol> = scene
            .parts
            .iter()
            .filter_map(|p| p.shape.radius())
            .filter_map(Expr::as_symbol)
            .collect();
        let (mut radius_count, mut length_count, mut rate_count) = (0, 0, 0);
        let given_angles: Vec<f64> = scene
            .givens
            .iter()
            .filter(|g| g.dimension == Dimension::NONE)
            .filter_map(|g| g.value)
            .collect();
        let apart = |a: &f64| {
            given_angles
                .iter()
                .all(|g| (g - a.to_radians()).abs() > ANGLES_APART_DEG.to_radians())
        };
        let angle = ANGLES_DEG
            .iter()
            .copied()
            .find(apart)
            .unwrap_or(ANGLES_DEG[0])
            .to_radians();
        let declared = scene
            .givens
            .iter()
            .map(|g| (g.symbol, g.dimension, g.value))
            .chain(scene.unknowns.iter().map(|(s, d)| (*s, *d, None)));
        for (symbol, dimension, value) in declared {
            let value = value.unwrap_or_else(|| {
                if dimension == Dimension::LENGTH {
                    let (count, proportions) = match radii.contains(&symbol) {
                        true => (&mut radius_count, &RADII[..]),
                        false => (&mut length_count, &LENGTHS[..]),
                    };
                    *count += 1;
                    base * proportions[(*count - 1) % proportions.len()]
                } else if dimension == Dimension::VELOCITY
                    || dimension == Dimension::ANGULAR_VELOCITY
                {
                    rate_count += 1;
                    RATES[(rate_count - 1) % RATES.len()]
                } else if dimension == Dimension::NONE || symbol == theta {
                    angle
                } else {
                    1.0
                }
            });
            values.insert(symbol, value);
        }
        // The unknowns the constraints fix, at the values the constraints give them.
        if let Ok((kinematics, _)) = solve_constraints(scene, None, Span::default()) {
            for (symbol, solution) in &kinematics.solved {
                if let Ok(value) = solution.eval::<f64>(&|s| values.get(&s).copied()) {
                    values.insert(*symbol, value);
                }
            }
        }
        // A load that varies with the time t is drawn as it is at t = 1 (at t = 0 a sine
        // would leave nothing to draw).
        values
            .entry(Symbol::new(crate::scene::parse::TIME))
            .or_insert(1.0);
        Sizes { values, base }
    }

    /// The value of `e` with the scene's symbols at their sizes.
    pub fn of_expr(&self, e: &Expr) -> Result<f64, AlgebraError> {
        e.eval::<f64>(&|s| self.values.get(&s).copied())
    }

    /// A vector's components at the sizes.
    pub fn of_vector(&self, v: &Vector) -> Result<P3, AlgebraError> {
        Ok([
            self.of_expr(&v[0])?,
            self.of_expr(&v[1])?,
            self.of_expr(&v[2])?,
        ])
    }
}
