//! The coordinate axes x, y, z, as subscripts name them (`M_x`, `w_y`, `I_z`).
//!
//! A component equation is about one axis: `ΣM_x = I_x ω̇_x - (I_y - I_z) ω_y ω_z` is the
//! x-equation. Mechanics says which axis each relation it derives is about, and the printer
//! orders inertia symbols cyclically from it (`I_x, I_y, I_z` for x, `I_y, I_z, I_x` for y).

use super::symbol::axis_of_subscript;

/// A coordinate axis; x where none is named.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Axis {
    #[default]
    X,
    Y,
    Z,
}

impl Axis {
    /// The axis as an index: x is 0, y 1, z 2 (as [`axis_of_subscript`] counts).
    pub(crate) fn index(self) -> usize {
        self as usize
    }

    /// The axis named by a subscript such as `x` in `M_x`, if it names exactly one.
    pub fn from_subscript(subscript: &str) -> Option<Axis> {
        axis_of_subscript(subscript).map(|k| [Axis::X, Axis::Y, Axis::Z][k])
    }
}
