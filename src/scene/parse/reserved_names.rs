//! Names a scene may not declare, because the mathematics already gives them a meaning:
//! the unit vectors `i`, `j`, `k`, the constant `pi` (π) and the degree `deg` (π/180).

use crate::algebra::PI_NAME;
use crate::parse::DEGREE;

/// What the name already means, when a scene may not declare it.
pub(super) fn meaning(name: &str) -> Option<&'static str> {
    match name {
        "i" | "j" | "k" => Some("i, j and k are the unit vectors"),
        PI_NAME => Some("pi is the constant π = 3.14159…"),
        DEGREE => Some("deg is the degree, the number π/180"),
        _ => None,
    }
}
