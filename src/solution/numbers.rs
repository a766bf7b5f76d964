//! Values of results: evaluation with the scene's givens (in SI) and the unit of the result.

use crate::algebra::{vector, Expr, Symbol};
use crate::scene::units::{dimension_of, Dimension, Dimensions};
use crate::scene::Scene;

/// The dimensions of every symbol the scene declares, and of the unit vectors.
pub fn scene_dimensions(scene: &Scene) -> Dimensions {
    let mut dims: Dimensions = scene
        .givens
        .iter()
        .map(|g| (g.symbol, g.dimension))
        .collect();
    dims.extend(scene.unknowns.iter().copied());
    for u in vector::unit_vectors() {
        if let Some(s) = u.as_symbol() {
            dims.insert(s, Dimension::NONE);
        }
    }
    dims
}

/// The value of `e` when every symbol in it has a given value; `None` otherwise.
pub fn value(scene: &Scene, e: &Expr) -> Option<f64> {
    e.eval(&|s: Symbol| scene.value(s)).ok()
}

/// The SI unit of `e`, when its dimension is consistent.
pub fn unit(dims: &Dimensions, e: &Expr) -> Option<String> {
    dimension_of(e, dims).ok().map(Dimension::si_unit)
}

/// Four significant figures, without trailing noise: `-129.8`, `0.01234`, `1.235e-7`.
pub fn format_value(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let magnitude = x.abs().log10().floor() as i32;
    if !(-4..6).contains(&magnitude) {
        return format!("{x:.3e}");
    }
    let decimals = (3 - magnitude).max(0) as usize;
    let text = format!("{x:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::format_value;

    #[test]
    fn four_significant_figures() {
        assert_eq!(format_value(-129.7518), "-129.8");
        assert_eq!(format_value(2700.0), "2700");
        assert_eq!(format_value(0.012345), "0.01235");
        assert_eq!(format_value(1.5e-7), "1.500e-7");
        assert_eq!(format_value(-135.0), "-135");
    }
}
