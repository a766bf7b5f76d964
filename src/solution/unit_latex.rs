//! A number with its unit in LaTeX, as a textbook sets it: a thin space and upright unit
//! letters (`6\,\mathrm{N\cdot m}`, `2.4\,\mathrm{m}`, `3000\,\mathrm{rad/s^2}`), an angle in
//! degrees with the degree sign and no space (`60^\circ`).
//!
//! The unit is set from its names ([`NamedUnit`]), never read from text.

use crate::scene::named_unit::{NamedUnit, UnitMarks};

/// `number` followed by `unit` (none: the number alone).
///
/// ```
/// use kinetics::scene::named_unit::NamedUnit;
/// use kinetics::solution::unit_latex::quantity;
/// let unit = |text: &str| NamedUnit::read(text).unwrap();
/// assert_eq!(quantity("6", &unit("N*m")), r"6\,\mathrm{N\cdot m}");
/// assert_eq!(quantity("0.3", &unit("kg·m²")), r"0.3\,\mathrm{kg\cdot m^2}");
/// assert_eq!(quantity("60", &unit("deg")), r"60^\circ");
/// assert_eq!(quantity("1.5e5", &unit("deg")), r"(1.5\times 10^{5})^\circ");
/// assert_eq!(quantity("9.81", &unit("m/s^2")), r"9.81\,\mathrm{m/s^2}");
/// assert_eq!(quantity("1", &unit("kg/m/s^2")), r"1\,\mathrm{kg\cdot m^{-1}\cdot s^{-2}}");
/// assert_eq!(quantity("2", &NamedUnit::default()), "2");
/// assert_eq!(quantity("-1.371e-6", &unit("m")), r"-1.371\times 10^{-6}\,\mathrm{m}");
/// ```
pub fn quantity(number: &str, unit: &NamedUnit) -> String {
    let number = powers_of_ten(number);
    if unit.is_none() {
        number
    } else if unit.is_degrees() && number.contains('^') {
        // A number in scientific notation ends in a superscript of its own: fenced, so
        // the degree's is not a second one (`(1.5\times 10^{5})^\circ`).
        format!(r"({number})^\circ")
    } else if unit.is_degrees() {
        format!(r"{number}^\circ")
    } else {
        format!(r"{number}\,\mathrm{{{}}}", unit_letters(unit))
    }
}

/// Numbers in scientific notation (`-1.371e-6`, `2e10`) as LaTeX writes them
/// (`-1.371\times 10^{-6}`); every other character as it is (a list, a matrix).
fn powers_of_ten(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut k = 0;
    while k < chars.len() {
        let after_digit = k > 0 && chars[k - 1].is_ascii_digit();
        let exponent_len = chars[k + 1..]
            .iter()
            .enumerate()
            .take_while(|(n, c)| c.is_ascii_digit() || (*n == 0 && **c == '-'))
            .count();
        let digits = chars[k + 1..k + 1 + exponent_len]
            .iter()
            .any(char::is_ascii_digit);
        if chars[k] == 'e' && after_digit && digits {
            let exponent: String = chars[k + 1..k + 1 + exponent_len].iter().collect();
            out.push_str(&format!(r"\times 10^{{{exponent}}}"));
            k += 1 + exponent_len;
        } else {
            out.push(chars[k]);
            k += 1;
        }
    }
    out
}

/// The unit inside `\mathrm{…}`: products as `\cdot`, powers as superscripts.
fn unit_letters(unit: &NamedUnit) -> String {
    unit.written_with(&UnitMarks {
        name: str::to_string,
        power: |name, e| match e {
            0..=9 => format!("{name}^{e}"),
            e => format!("{name}^{{{e}}}"),
        },
        times: r"\cdot ",
        over: "/",
    })
}
