//! A result's value as the page shows it, with its unit: a number `−129.8 N`, a tensor's
//! matrix of numbers `[[…], […], […]] kg·m²`, and a vector as the textbook writes it, each
//! component that is not zero (in four significant figures) times its unit vector, the unit
//! with each number, a minus between terms or before the first,
//!
//! ```text
//! H_G = (3.565 kg·m²/s) i + (0.3095 kg·m²/s) j        ā = −(135 m/s²) i
//! ```
//!
//! a zero vector `0` with its unit, and without a unit (a principal axis) the numbers alone,
//! `e_1 = 0.8366 i + 0.496 j + 0.2326 k`. In text, LaTeX and MathML.

use super::mathml_value::{decimal, spaced_unit, value as mathml_quantity};
use super::numbers::format_value;
use super::unit_latex::quantity;
use crate::print::{self, matrix::bracketed, Notation};
use crate::scene::named_unit::NamedUnit;

/// A value and its unit (empty for none): one number, a vector's three components, or a
/// tensor's nine entries row by row.
#[derive(Clone, Copy)]
pub(super) struct ShownValue<'a> {
    pub numbers: &'a [f64],
    pub unit: &'a NamedUnit,
}

impl ShownValue<'_> {
    /// The value in `notation`.
    pub(super) fn render(&self, notation: Notation) -> String {
        let ShownValue { numbers, unit } = *self;
        match (numbers, notation) {
            ([x], Notation::Text) if unit.is_none() => format_value(*x),
            ([x], Notation::Text) => format!("{} {unit}", format_value(*x)),
            ([x], Notation::Latex) => quantity(&format_value(*x), unit),
            ([x], Notation::MathMl) => mathml_quantity(&format_value(*x), unit),
            ([_, _, _], Notation::Text) => text(numbers, unit),
            ([_, _, _], Notation::Latex) => latex(numbers, unit),
            ([_, _, _], Notation::MathMl) => mathml(numbers, unit),
            (_, _) => {
                let entry = |r: usize, c: usize| {
                    let number = format_value(numbers[3 * r + c]);
                    match notation {
                        Notation::MathMl => decimal(&number),
                        Notation::Text | Notation::Latex => number,
                    }
                };
                let matrix = bracketed(entry, notation);
                match notation {
                    Notation::Text if unit.is_none() => matrix,
                    Notation::Text => format!("{matrix} {unit}"),
                    Notation::Latex => quantity(&matrix, unit),
                    Notation::MathMl => matrix + &spaced_unit(unit),
                }
            }
        }
    }

    /// The width in ems of the value in LaTeX, roughly: digits and signs at 0.55 em, a unit
    /// as a symbol of its letters (a vector's: [`latex_em`]).
    pub(super) fn latex_em(&self) -> f64 {
        match self.numbers {
            [x] => 0.55 * format_value(*x).len() as f64 + unit_em(self.unit),
            components => latex_em(components, self.unit),
        }
    }
}

/// A component shown: its magnitude's digits, its sign, the index of its unit vector.
struct Term {
    negative: bool,
    magnitude: String,
    axis: usize,
}

/// The components that do not show as zero.
fn terms(components: &[f64]) -> Vec<Term> {
    components
        .iter()
        .enumerate()
        .filter_map(|(axis, &x)| {
            let shown = format_value(x);
            let negative = shown.starts_with('-');
            let magnitude = shown.trim_start_matches('-').to_string();
            (magnitude != "0").then_some(Term {
                negative,
                magnitude,
                axis,
            })
        })
        .collect()
}

/// The terms joined by their signs: `[before the first, plus, minus]`.
fn joined(terms: &[Term], signs: [&str; 3], term: impl Fn(&Term) -> String) -> String {
    let mut out = String::new();
    for (k, t) in terms.iter().enumerate() {
        out.push_str(match (k, t.negative) {
            (0, false) => "",
            (0, true) => signs[0],
            (_, false) => signs[1],
            (_, true) => signs[2],
        });
        out.push_str(&term(t));
    }
    out
}

const UNIT_VECTORS: [&str; 3] = ["i", "j", "k"];

/// A vector's value in text: `-(135 m/s²) i + (2 m/s²) k`.
fn text(components: &[f64], unit: &NamedUnit) -> String {
    let terms = terms(components);
    if terms.is_empty() {
        return format!("0 {unit}").trim_end().to_string();
    }
    joined(&terms, ["-", " + ", " - "], |t| {
        let i = UNIT_VECTORS[t.axis];
        match unit.is_none() {
            true => format!("{} {i}", t.magnitude),
            false => format!("({} {unit}) {i}", t.magnitude),
        }
    })
}

/// A vector's value in LaTeX: `-(135\,\mathrm{m/s^2})\,\mathbf{i}`.
fn latex(components: &[f64], unit: &NamedUnit) -> String {
    let terms = terms(components);
    if terms.is_empty() {
        return quantity("0", unit);
    }
    joined(&terms, ["-", " + ", " - "], |t| {
        let i = UNIT_VECTORS[t.axis];
        match unit.is_none() {
            true => format!(r"{}\,\mathbf{{{i}}}", quantity(&t.magnitude, unit)),
            false => format!(r"({})\,\mathbf{{{i}}}", quantity(&t.magnitude, unit)),
        }
    })
}

/// A vector's value in MathML.
fn mathml(components: &[f64], unit: &NamedUnit) -> String {
    let terms = terms(components);
    if terms.is_empty() {
        return mathml_quantity("0", unit);
    }
    let row = joined(
        &terms,
        ["<mo>\u{2212}</mo>", "<mo>+</mo>", "<mo>\u{2212}</mo>"],
        |t| {
            let mut i = String::new();
            print::mathml::latex_name(&mut i, &format!(r"\mathbf{{{}}}", UNIT_VECTORS[t.axis]));
            match unit.is_none() {
                true => format!("{}{i}", decimal(&t.magnitude)),
                false => format!(
                    "<mrow><mo>(</mo>{}<mo>)</mo></mrow>{i}",
                    mathml_quantity(&t.magnitude, unit)
                ),
            }
        },
    );
    format!("<mrow>{row}</mrow>")
}

/// The width in ems of the LaTeX value, roughly: digits and signs at 0.55 em, each unit as
/// a symbol of its letters, a unit vector and parentheses an em.
fn latex_em(components: &[f64], unit: &NamedUnit) -> f64 {
    let terms = terms(components);
    let unit_em = unit_em(unit);
    terms
        .iter()
        .map(|t| 0.55 * (t.magnitude.len() + 1) as f64 + unit_em + 1.0)
        .sum::<f64>()
        .max(0.55 + unit_em)
}

/// The width in ems of a unit, as a symbol of its letters (upright, narrower than that).
fn unit_em(unit: &NamedUnit) -> f64 {
    print::width::symbol_em(&unit.to_string())
}

#[cfg(test)]
mod tests {
    use super::{latex, text};
    use crate::scene::named_unit::NamedUnit;

    fn unit(text: &str) -> NamedUnit {
        match text {
            "" => NamedUnit::default(),
            text => NamedUnit::read(text).unwrap(),
        }
    }

    #[test]
    fn components_with_their_units() {
        assert_eq!(text(&[-135.0, 0.0, 0.0], &unit("m/s²")), "-(135 m/s²) i");
        assert_eq!(
            text(&[3.5651, -0.30951, 0.0], &unit("kg·m²/s")),
            "(3.565 kg·m²/s) i - (0.3095 kg·m²/s) j"
        );
        assert_eq!(text(&[0.0, 0.0, 0.0], &unit("m/s")), "0 m/s");
        assert_eq!(
            text(&[0.8366, 0.496, -0.2326], &unit("")),
            "0.8366 i + 0.496 j - 0.2326 k"
        );
        // Only a component that shows as zero is left out: a tiny one stays.
        assert_eq!(
            text(&[1.0, 1e-20, 0.0], &unit("N")),
            "(1 N) i + (10e-21 N) j"
        );
        assert_eq!(
            latex(&[-135.0, 0.0, 2.0], &unit("m/s^2")),
            r"-(135\,\mathrm{m/s^2})\,\mathbf{i} + (2\,\mathrm{m/s^2})\,\mathbf{k}"
        );
    }
}
