//! Hints for a name the scene does not know: a declared name that differs from it only in
//! case or underscores (`C_z` for `C_Z`, `wx` for `w_x`), and a unit written as a symbol
//! (`d*mm`), which is read as a unit only right after a number (`300 mm`).

use super::super::units::unit_named;

/// The name among `known` that `name` differs from only in letter case or underscores
/// (none when there is none, or when it is `name` itself).
pub(super) fn similar_name<'a>(
    name: &str,
    known: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    let folded = |s: &str| -> String {
        s.chars()
            .filter(|c| *c != '_')
            .map(|c| c.to_ascii_lowercase())
            .collect()
    };
    let wanted = folded(name);
    known
        .into_iter()
        .find(|k| *k != name && folded(k) == wanted)
}

/// The help for an undeclared `name` among the declared `known`: the similar declared
/// name, or the unit's place when `name` is a unit, or how to declare it.
pub(super) fn undeclared_help<'a>(name: &str, known: impl IntoIterator<Item = &'a str>) -> String {
    if let Some(similar) = similar_name(name, known) {
        return format!(
            "did you mean {similar}? Names differ in letter case and underscores ({similar} is declared, {name} is not)"
        );
    }
    if unit_named(name).is_some() {
        return format!(
            "{name} is a unit, read as one only right after a number: write the quantity with its unit (300 {name}); \
             a given already holds its unit (after 'given d = 300 {name}', write d, not d*{name})"
        );
    }
    format!("declare it first: 'given {name} = <value> <unit>', 'given {name} : <unit>' or 'unknown {name} : <unit>'")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_that_differ_in_case_or_underscores_are_found() {
        let known = ["C_Z", "w_x", "m"];
        assert_eq!(similar_name("C_z", known), Some("C_Z"));
        assert_eq!(similar_name("wx", known), Some("w_x"));
        assert_eq!(similar_name("W_X", known), Some("w_x"));
        assert_eq!(similar_name("m", known), None);
        assert_eq!(similar_name("C_y", known), None);
        assert!(undeclared_help("mm", known).contains("300 mm"));
        assert!(undeclared_help("q", known).starts_with("declare it first"));
    }
}
