//! A number with its unit in LaTeX, as a textbook sets it: a thin space and upright unit
//! letters (`6\,\mathrm{N\cdot m}`, `2.4\,\mathrm{m}`, `3000\,\mathrm{rad/s^2}`), an angle in
//! degrees with the degree sign and no space (`60^\circ`).
//!
//! A unit arrives as the user wrote it in the scene (`N*m`, `N m`, `N·m`, `kg*m^2`, `deg`)
//! or as the program prints it (`N·m`, `kg·m²`); both read the same.

/// `number` followed by `unit` (empty: the number alone).
///
/// ```
/// use kinetics::solution::unit_latex::quantity;
/// assert_eq!(quantity("6", "N*m"), r"6\,\mathrm{N\cdot m}");
/// assert_eq!(quantity("6", "N m"), r"6\,\mathrm{N\cdot m}");
/// assert_eq!(quantity("0.3", "kg·m²"), r"0.3\,\mathrm{kg\cdot m^2}");
/// assert_eq!(quantity("60", "deg"), r"60^\circ");
/// assert_eq!(quantity("1.5e5", "deg"), r"(1.5\times 10^{5})^\circ");
/// assert_eq!(quantity("9.81", "m/s^2"), r"9.81\,\mathrm{m/s^2}");
/// assert_eq!(quantity("2", ""), "2");
/// assert_eq!(quantity("-1.371e-6", "m"), r"-1.371\times 10^{-6}\,\mathrm{m}");
/// assert_eq!(quantity("(2e10, 0, 1)", ""), r"(2\times 10^{10}, 0, 1)");
/// ```
pub fn quantity(number: &str, unit: &str) -> String {
    let unit = unit.trim();
    let number = &powers_of_ten(number);
    match unit {
        "" => number.to_string(),
        // A number in scientific notation ends in a superscript of its own: fenced, so
        // the degree's is not a second one (`(1.5\times 10^{5})^\circ`).
        _ if is_degrees(unit) && number.contains('^') => format!(r"({number})^\circ"),
        _ if is_degrees(unit) => format!(r"{number}^\circ"),
        _ => format!(r"{number}\,\mathrm{{{}}}", unit_letters(unit)),
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

/// Whether `unit` is the degree of angle, which every notation sets as a sign after the
/// number (`60°`), not as a unit name.
pub fn is_degrees(unit: &str) -> bool {
    matches!(unit.trim(), "deg" | "°" | "degree" | "degrees")
}

/// The unit inside `\mathrm{…}`: products as `\cdot`, powers as superscripts.
fn unit_letters(unit: &str) -> String {
    let mut out = String::new();
    let mut chars = unit.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '*' | '·' => out.push_str(r"\cdot "),
            // `N m`: a space between two unit names is a product.
            ' ' => {
                while chars.peek() == Some(&' ') {
                    chars.next();
                }
                if !matches!(chars.peek(), Some('/' | '*' | '·' | '^') | None)
                    && !out.ends_with(' ')
                    && !out.ends_with('/')
                {
                    out.push_str(r"\cdot ");
                }
            }
            '²' => out.push_str("^2"),
            '³' => out.push_str("^3"),
            '^' => {
                out.push('^');
                let exponent: String =
                    std::iter::from_fn(|| chars.next_if(|d| d.is_ascii_digit() || *d == '-'))
                        .collect();
                if exponent.chars().count() == 1 {
                    out.push_str(&exponent);
                } else {
                    out.push_str(&format!("{{{exponent}}}"));
                }
            }
            '%' | '&' | '#' | '_' | '{' | '}' | '$' => {
                out.push('\\');
                out.push(c);
            }
            '\\' | '~' => {}
            c => out.push(c),
        }
    }
    out.trim_end().to_string()
}
