//! A number with its unit in MathML, as the LaTeX writes `-129.8\ \mathrm{N\cdot m}`: the
//! sign a true minus, the digits one `<mn>`, a space, then the unit upright, its products
//! `·`, quotients `/` and powers (`m^2`, `s²`, `kg^-1`) as `<msup>`; an angle in degrees
//! as the LaTeX's `60^\circ`, the degree sign close after the number.

use crate::print::mathml::escaped;
use crate::scene::named_unit::{NamedUnit, UnitMarks};

/// `number` (a decimal as written or printed: `-2`, `0.3`, `1.500e-7`) and its `unit`
/// (`N*m`, `rad/s²`, `deg`; empty for none).
pub fn value(number: &str, unit: &NamedUnit) -> String {
    if unit.is_degrees() {
        // A number in scientific notation ends in a superscript of its own: fenced, so that
        // the degree sign is not read as raising its power of ten (`(1.5 × 10⁵)°`).
        let shown = match scientific(number) {
            Some(_) => format!("<mrow><mo>(</mo>{}<mo>)</mo></mrow>", decimal(number)),
            None => decimal(number),
        };
        return shown + r#"<mo lspace="0" rspace="0">°</mo>"#;
    }
    decimal(number) + &spaced_unit(unit)
}

/// A decimal, its minus a true minus sign (in a row of its own, so that after `=` it is
/// the sign of the number, not an operator spaced as one); scientific notation as the
/// LaTeX writes it (`1.5e-7` is `1.5 × 10⁻⁷`, one row).
pub fn decimal(number: &str) -> String {
    let (minus, magnitude) = match number.strip_prefix('-') {
        Some(magnitude) => ("<mo>\u{2212}</mo>", magnitude),
        None => ("", number),
    };
    match scientific(magnitude) {
        Some((mantissa, exponent)) => {
            let raised = match exponent.strip_prefix('-') {
                Some(e) => format!("<mrow><mo>\u{2212}</mo><mn>{e}</mn></mrow>"),
                None => format!("<mn>{exponent}</mn>"),
            };
            format!(
                "<mrow>{minus}<mn>{}</mn><mo>\u{d7}</mo><msup><mn>10</mn>{raised}</msup></mrow>",
                escaped(mantissa)
            )
        }
        None if minus.is_empty() => format!("<mn>{}</mn>", escaped(magnitude)),
        None => format!("<mrow>{minus}<mn>{}</mn></mrow>", escaped(magnitude)),
    }
}

/// A magnitude in scientific notation as its mantissa and its exponent (digits, a minus
/// kept, a plus dropped): `1.5e-7` is `("1.5", "-7")`; none for any other text.
fn scientific(magnitude: &str) -> Option<(&str, &str)> {
    let (mantissa, exponent) = magnitude.split_once(['e', 'E'])?;
    let exponent = exponent.strip_prefix('+').unwrap_or(exponent);
    let digits = exponent.strip_prefix('-').unwrap_or(exponent);
    let is_number = |t: &str| !t.is_empty() && t.chars().all(|c| c.is_ascii_digit() || c == '.');
    (is_number(mantissa) && !digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit()))
        .then_some((mantissa, exponent))
}

/// A unit after the space that separates it from its number; nothing for no unit.
pub fn spaced_unit(unit: &NamedUnit) -> String {
    if unit.is_none() {
        return String::new();
    }
    format!(r#"<mspace width="0.25em"/>{}"#, unit_mathml(unit))
}

/// A unit's MathML: names upright, products a centred dot, `/` close (as `\mathrm{rad/s}`
/// sets it), a power on its name.
fn unit_mathml(unit: &NamedUnit) -> String {
    let letters = unit.written_with(&UnitMarks {
        name: |name| format!(r#"<mi mathvariant="normal">{}</mi>"#, escaped(name)),
        power: |name, e| {
            let raised = match e {
                e if e < 0 => format!("<mo>\u{2212}</mo><mn>{}</mn>", -e),
                e => format!("<mn>{e}</mn>"),
            };
            format!("<msup>{name}<mrow>{raised}</mrow></msup>")
        },
        times: "<mo>\u{b7}</mo>",
        over: r#"<mo lspace="0" rspace="0">/</mo>"#,
    });
    format!("<mrow>{letters}</mrow>")
}

#[cfg(test)]
mod tests {
    use super::value;
    use crate::scene::named_unit::NamedUnit;

    fn unit(text: &str) -> NamedUnit {
        match text {
            "" => NamedUnit::default(),
            text => NamedUnit::read(text).unwrap(),
        }
    }

    #[test]
    fn numbers_and_units() {
        let normal = |name: &str| format!(r#"<mi mathvariant="normal">{name}</mi>"#);
        let space = r#"<mspace width="0.25em"/>"#;
        assert_eq!(value("0.3", &unit("")), "<mn>0.3</mn>");
        assert_eq!(
            value("-129.8", &unit("N")),
            format!(
                "<mrow><mo>\u{2212}</mo><mn>129.8</mn></mrow>{space}<mrow>{}</mrow>",
                normal("N")
            )
        );
        assert_eq!(
            value("6", &unit("N*m")),
            format!(
                "<mn>6</mn>{space}<mrow>{}<mo>·</mo>{}</mrow>",
                normal("N"),
                normal("m")
            )
        );
        assert_eq!(
            value("3000", &unit("rad/s²")),
            format!(
                "<mn>3000</mn>{space}<mrow>{}<mo lspace=\"0\" rspace=\"0\">/</mo><msup>{}<mrow><mn>2</mn></mrow></msup></mrow>",
                normal("rad"),
                normal("s")
            )
        );
        assert_eq!(
            value("1", &unit("kg^-1")),
            format!(
                "<mn>1</mn>{space}<mrow><msup>{}<mrow><mo>\u{2212}</mo><mn>1</mn></mrow></msup></mrow>",
                normal("kg")
            )
        );
        assert_eq!(
            value("30", &unit("deg")),
            "<mn>30</mn><mo lspace=\"0\" rspace=\"0\">°</mo>"
        );
    }

    /// A number in scientific notation is its mantissa times a power of ten, as the LaTeX
    /// writes it; before the degree sign it is fenced, so the sign raises nothing.
    #[test]
    fn scientific_notation_is_a_power_of_ten() {
        let ten = |raised: &str| format!("<mo>×</mo><msup><mn>10</mn>{raised}</msup>");
        assert_eq!(
            value("-1.371e-6", &unit("")),
            format!(
                "<mrow><mo>\u{2212}</mo><mn>1.371</mn>{}</mrow>",
                ten("<mrow><mo>\u{2212}</mo><mn>6</mn></mrow>")
            )
        );
        assert_eq!(
            value("1.5e5", &unit("deg")),
            format!(
                "<mrow><mo>(</mo><mrow><mn>1.5</mn>{}</mrow><mo>)</mo></mrow><mo lspace=\"0\" rspace=\"0\">°</mo>",
                ten("<mn>5</mn>")
            )
        );
        assert_eq!(value("e5", &unit("")), "<mn>e5</mn>");
    }
}
