//! Values of results: evaluation with the scene's givens (in SI) and the unit of the result.

use crate::algebra::{vector, Expr, Symbol};
use crate::parse::Diagnostic;
use crate::scene::units::{dimension_of, Dimension, Dimensions};
use crate::scene::{Analysis, Scene, Value};

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

/// The value of `e` when every symbol in it has a given value and the value is finite;
/// `None` otherwise, and the answer stays symbolic. (An answer asked for `in UNIT` must
/// have a value: [`check_numeric_requests`] refuses it when it has none.)
pub fn value(scene: &Scene, e: &Expr) -> Option<f64> {
    e.eval(&|s: Symbol| scene.value(s)).ok()
}

/// The SI unit of `e`, when its dimension is consistent.
pub fn unit(dims: &Dimensions, e: &Expr) -> Option<String> {
    dimension_of(e, dims).ok().map(Dimension::si_unit)
}

/// Checks the requests written `find X in UNIT`: the answer must be in that kind of unit,
/// every given it depends on must have a value, and with those values it must be finite.
pub fn check_numeric_requests(scene: &Scene, analysis: &Analysis) -> Result<(), Diagnostic> {
    let dims = scene_dimensions(scene);
    for (request, value) in &analysis.results {
        let Some((written, unit)) = &request.unit else {
            continue;
        };
        let fail = |message: String, help: String| scene.error_at(request.span, message, help);
        let components: Vec<&Expr> = match value {
            Value::Scalar(e) => vec![e],
            Value::Vector(v) => v.iter().collect(),
        };
        for e in components.into_iter().filter(|e| !e.is_zero()) {
            if let Ok(d) = dimension_of(e, &dims) {
                if d != unit.dimension {
                    return Err(fail(
                        format!(
                            "unit mismatch: {} is in {d}, not in {written}",
                            request.name
                        ),
                        format!("ask for it in a unit of {d}"),
                    ));
                }
            }
            let missing: Vec<&str> = e
                .symbols()
                .into_iter()
                .filter(|s| scene.value(*s).is_none())
                .map(|s| s.name())
                .collect();
            if let Some(first) = missing.first() {
                return Err(fail(
                    format!("{} in {written} needs a value for {}", request.name, missing.join(", ")),
                    format!("give it one, e.g. 'given {first} = <number> <unit>', or drop 'in {written}' for a symbolic answer"),
                ));
            }
            if self::value(scene, e).is_none() {
                return Err(fail(
                    format!("{} in {written} is not a finite number with the given values", request.name),
                    "check the givens it depends on: with these values the configuration has no finite answer".into(),
                ));
            }
        }
    }
    Ok(())
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
