//! Values of results: evaluation with the scene's givens (in its unit system) and the unit of the result.

pub use super::evaluation::value;
use crate::algebra::{vector, AlgebraError, Expr, Symbol, Q};
use crate::parse::Diagnostic;
use crate::scene::model::{exact_decimal, Quantity, Request};
use crate::scene::named_unit::NamedUnit;
use crate::scene::unit_system::UnitSystem;
use crate::scene::units::{dimension_of, Dimension, Dimensions};
use crate::scene::{Analysis, Scene, Value};
use num_bigint::BigInt;
use num_traits::Signed;

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

/// Checks that no requested number is silently left out. A request written `find X in UNIT`
/// must be in that kind of unit and every given it depends on must have a value; any request
/// whose givens all have values must have a finite value (in the unit asked for). An answer
/// that is not (or that rounds to zero but is not zero) is refused at its `find`, saying why:
/// a division by zero (naming the givens whose value is zero) or a magnitude beyond the range
/// of numbers (`T = 2e399 J`).
pub fn check_numeric_requests(scene: &Scene, analysis: &Analysis) -> Result<(), Diagnostic> {
    let dims = scene_dimensions(scene);
    for (request, value) in &analysis.results {
        let fail = |message: String, help: String| scene.error_at(request.span, message, help);
        let components: Vec<&Expr> = match value {
            Value::Scalar(e) => vec![e],
            Value::Vector(v) => v.iter().collect(),
            Value::Balance(corrections) => corrections
                .iter()
                .flat_map(|k| [&k.mass, &k.p, &k.q])
                .collect(),
            Value::Tensor(m) => m.iter().collect(),
            // The axes are unit vectors: numbers without a unit.
            Value::Principal(p) => p.moments.iter().collect(),
            Value::Precession(p) => vec![&p.tan_gamma],
        };
        for e in components.into_iter().filter(|e| !e.is_zero()) {
            let missing: Vec<&str> = e
                .symbols()
                .into_iter()
                .filter(|s| !s.is_pi() && scene.value(*s).is_none())
                .map(|s| s.name())
                .collect();
            let Some(written) = &request.unit else {
                if missing.is_empty() {
                    finite(scene, request, e, &dims)?;
                }
                continue;
            };
            let dimension = request.quantity.dimension(&dims);
            if let Some(d) = dimension.or_else(|| dimension_of(e, &dims).ok()) {
                if d != written.unit().dimension {
                    return Err(fail(
                        format!(
                            "unit mismatch: {} is in {d}, not in {written}",
                            request.name
                        ),
                        format!("ask for it in a unit of {d}"),
                    ));
                }
            }
            if let Some(first) = missing.first() {
                return Err(fail(
                    format!("{} in {written} needs a value for {}", request.name, missing.join(", ")),
                    format!("give it one, e.g. 'given {first} = <number> <unit>', or drop 'in {written}' for a symbolic answer"),
                ));
            }
            finite(scene, request, e, &dims)?;
        }
    }
    Ok(())
}

/// The unit a result is shown in: the `system`'s unit of the quantity's dimension (so a zero
/// keeps its unit), but joules (foot-pounds; not newton metres) for the kinetic energies,
/// which are work-like.
pub fn result_unit(request: &Request, dims: &Dimensions, system: UnitSystem) -> Option<NamedUnit> {
    let d = request.quantity.dimension(dims)?;
    let energy = [
        Quantity::KineticEnergy,
        Quantity::TranslationalKineticEnergy,
        Quantity::RotationalKineticEnergy,
        Quantity::KineticEnergyBefore,
        Quantity::KineticEnergyAfter,
        Quantity::EnergyLost,
    ];
    Some(system.unit(d, energy.contains(&request.quantity)))
}

/// `e`, every given of which has a value, is a finite number in the unit asked for; else
/// the error at the request says why.
fn finite(scene: &Scene, request: &Request, e: &Expr, dims: &Dimensions) -> Result<(), Diagnostic> {
    let one = request
        .unit
        .as_ref()
        .map_or(1.0, |u| scene.unit_system.of_one(u));
    let v = value(scene, e).map(|v| v / one);
    // A zero that is not zero exactly has underflowed: it is not the answer either.
    let underflow = v == Some(0.0) && exact_value(scene, e).is_ok_and(|q| !q.is_zero());
    if v.is_some_and(f64::is_finite) && !underflow {
        return Ok(());
    }
    let named = request.as_written();
    let fail = |message: String, help: String| Err(scene.error_at(request.span, message, help));
    let depends = e
        .symbols()
        .into_iter()
        .map(|s| s.name())
        .collect::<Vec<_>>()
        .join(", ");
    match exact_value(scene, e) {
        Ok(q) => {
            let unit = match &request.unit {
                Some(unit) => unit.clone(),
                // The value below is in the scene's unit system.
                None => result_unit(request, dims, scene.unit_system).unwrap_or_default(),
            };
            let q = &q * &exact_decimal(1.0 / one).unwrap_or(Q::ONE);
            let name = &request.name;
            let message = match q.to_f64() {
                0.0 => format!("{name} = {} {unit} is below the range of numbers (magnitudes down to about 2.2e-308)", scientific(&q)),
                x if x.is_finite() => format!("{name} = {} {unit} cannot be evaluated: a value on the way to it is beyond the range of numbers", format_value(x)),
                _ => format!("{name} = {} {unit} overflows the range of numbers (magnitudes up to about 1.8e308)", scientific(&q)),
            };
            fail(
                message,
                format!("check the values of the givens it depends on ({depends}): one is far too large or too small"),
            )
        }
        Err(AlgebraError::DivisionByZero) => Err(scene.division_by_zero_at(request.span, &named, e)),
        Err(_) => fail(
            format!("{named} is not a finite number with the given values"),
            "check the givens it depends on: with these values the configuration has no finite answer".into(),
        ),
    }
}

/// The exact value of `e` with each given's value as the decimal it reads as (`1e200`,
/// `0.1`): a number when `e` is built from sums, products and integer powers; an error
/// for a division by zero; a non-number left with functions of values.
fn exact_value(scene: &Scene, e: &Expr) -> Result<Q, AlgebraError> {
    let given = |s: Symbol| scene.exact_value(s).map(Expr::num);
    let exact = e.subs(&given)?;
    exact
        .as_num()
        .cloned()
        .ok_or_else(|| AlgebraError::MissingValue(exact.to_string()))
}

/// An exact rational in scientific notation with four significant figures, however large:
/// `2e399`, `-1.235e-400`.
fn scientific(q: &Q) -> String {
    let (numerator, denominator) = q.parts();
    let sign = if q.is_negative() { "-" } else { "" };
    let numerator = numerator.abs();
    let digits = |n: &BigInt| n.to_string().len() as i64;
    // |q| lies in [10^(k-1), 10^(k+1)): scaled by 10^(4-k), it has four or five digits.
    let k = digits(&numerator) - digits(&denominator);
    let ten = |n: i64| BigInt::from(10).pow(n.max(0) as u32);
    let scaled = numerator * ten(4 - k) / (denominator * ten(k - 4));
    let text = scaled.to_string();
    let exponent = k - 5 + text.len() as i64;
    let mantissa = format!("{}.{}", &text[..1], &text[1..4]);
    let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
    format!("{sign}{mantissa}e{exponent}")
}

/// The significant figures of the page being written (`solve --digits`).
pub const DEFAULT_DIGITS: usize = 4;

thread_local! {
    static DIGITS: std::cell::Cell<usize> = const { std::cell::Cell::new(DEFAULT_DIGITS) };
}

/// `write` with every number on its page in `digits` significant figures.
pub fn with_digits<R>(digits: usize, write: impl FnOnce() -> R) -> R {
    let before = DIGITS.replace(digits.max(1));
    let written = write();
    DIGITS.set(before);
    written
}

/// A value in the page's significant figures ([`crate::algebra::significant_figures`]):
/// `-129.8`, `0.01234`, `3.930`, `123.5e3`.
pub fn format_value(x: f64) -> String {
    crate::algebra::significant_figures(x, DIGITS.get())
}

#[cfg(test)]
mod tests {
    use super::{format_value, scientific, with_digits};
    use crate::algebra::Q;

    #[test]
    fn scientific_beyond_the_range_of_doubles() {
        let big = |text: &str| Q::parse_decimal(text).unwrap();
        assert_eq!(scientific(&big("2e399")), "2e399");
        assert_eq!(scientific(&-&big("12345678e400")), "-1.234e407");
        assert_eq!(scientific(&big("9.999e-400")), "9.999e-400");
        assert_eq!(
            scientific(&(&big("1e-400") * &Q::new(1, 3).unwrap())),
            "3.333e-401"
        );
    }

    #[test]
    fn four_significant_figures() {
        assert_eq!(format_value(-129.7518), "-129.8");
        assert_eq!(format_value(2700.0), "2700");
        assert_eq!(format_value(0.012345), "0.01235");
        assert_eq!(format_value(-135.0), "-135");
        // Rounded values keep their trailing zeros; exact ones show what they are.
        assert_eq!(format_value(3.929_999_7), "3.930");
        assert_eq!(format_value(3.93), "3.93");
        assert_eq!(format_value(0.000_666_67), "0.0006667");
        assert_eq!(format_value(9.999_96), "10.00");
        // Engineering notation from 10⁵ up and below 10⁻⁴.
        assert_eq!(format_value(123_456.0), "123.5e3");
        assert_eq!(format_value(99_990.0), "99990");
        assert_eq!(format_value(99_999.0), "100.0e3");
        assert_eq!(format_value(-1.5e-7), "-150e-9");
        assert_eq!(format_value(1.234_56e-5), "12.35e-6");
        assert_eq!(format_value(2e10), "20e9");
    }

    #[test]
    fn digits_of_the_page() {
        assert_eq!(with_digits(3, || format_value(-129.7518)), "-130");
        assert_eq!(with_digits(6, || format_value(1.0 / 3.0)), "0.333333");
        assert_eq!(format_value(1.0 / 3.0), "0.3333");
    }
}
