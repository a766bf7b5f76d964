//! The commands of the title markup's LaTeX subset, and the Unicode each stands for:
//! Greek letters (`\omega` → ω), operators (`\times` → ×, `\cdot` → ·, `\int` → ∫,
//! `\neq` → ≠, `\circ` → ∘), the thin space `\,`, the braces `\{ \}`, and the commands that
//! take arguments (`\mathbf`, `\boldsymbol`, `\mathrm`, `\text`, `\bar`, `\dot`, `\ddot`,
//! `\frac`, `\tfrac`), and the functions `\sin \cos \tan \arccos \arctan`.

/// An accent over its argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Accent {
    Bar,
    Dot,
    DoubleDot,
}

impl Accent {
    pub const ALL: [Accent; 3] = [Accent::Bar, Accent::Dot, Accent::DoubleDot];

    /// The command's name: `bar`, `dot`, `ddot`.
    pub fn name(self) -> &'static str {
        match self {
            Accent::Bar => "bar",
            Accent::Dot => "dot",
            Accent::DoubleDot => "ddot",
        }
    }

    /// The combining character that puts the accent on the letter before it (text).
    pub fn combining(self) -> char {
        match self {
            Accent::Bar => '\u{0304}',
            Accent::Dot => '\u{0307}',
            Accent::DoubleDot => '\u{0308}',
        }
    }

    /// The spacing character MathML sets over the base: ¯ ˙ ¨.
    pub fn spacing(self) -> char {
        match self {
            Accent::Bar => '\u{00AF}',
            Accent::Dot => '\u{02D9}',
            Accent::DoubleDot => '\u{00A8}',
        }
    }
}

/// A typeface command's face.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Face {
    /// `\mathbf`: bold upright.
    Bold,
    /// `\boldsymbol`: bold, letters keep their italic.
    BoldSymbol,
    /// `\mathrm`: upright.
    Roman,
}

impl Face {
    pub fn name(self) -> &'static str {
        match self {
            Face::Bold => "mathbf",
            Face::BoldSymbol => "boldsymbol",
            Face::Roman => "mathrm",
        }
    }
}

/// What a command is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Command {
    /// A Greek letter: an identifier.
    Letter(char),
    /// An operator or a fence.
    Operator(char),
    /// `\,`.
    ThinSpace,
    /// A face over its one argument.
    Face(Face),
    /// `\text{words}`.
    Text,
    Accent(Accent),
    /// `\frac` (false) or `\tfrac` (true), two arguments.
    Fraction {
        small: bool,
    },
    /// A function's name set upright: `\sin`, `\cos`, `\tan`, `\arccos`, `\arctan`.
    Function(&'static str),
}

/// The functions' names, as commands.
const FUNCTIONS: [&str; 5] = ["sin", "cos", "tan", "arccos", "arctan"];

/// The Greek letters, by command name (ϵ-, ϑ- and other variants are not in the subset).
const GREEK: [(&str, char); 35] = [
    ("alpha", 'α'),
    ("beta", 'β'),
    ("gamma", 'γ'),
    ("delta", 'δ'),
    ("epsilon", 'ε'),
    ("zeta", 'ζ'),
    ("eta", 'η'),
    ("theta", 'θ'),
    ("iota", 'ι'),
    ("kappa", 'κ'),
    ("lambda", 'λ'),
    ("mu", 'μ'),
    ("nu", 'ν'),
    ("xi", 'ξ'),
    ("pi", 'π'),
    ("rho", 'ρ'),
    ("sigma", 'σ'),
    ("tau", 'τ'),
    ("upsilon", 'υ'),
    ("phi", 'φ'),
    ("chi", 'χ'),
    ("psi", 'ψ'),
    ("omega", 'ω'),
    ("Gamma", 'Γ'),
    ("Delta", 'Δ'),
    ("Theta", 'Θ'),
    ("Lambda", 'Λ'),
    ("Xi", 'Ξ'),
    ("Pi", 'Π'),
    ("Sigma", 'Σ'),
    ("Upsilon", 'Υ'),
    ("Phi", 'Φ'),
    ("Psi", 'Ψ'),
    ("Omega", 'Ω'),
    ("varphi", 'ϕ'),
];

/// The operators written as commands.
const OPERATORS: [(&str, char); 5] = [
    ("times", '×'),
    ("cdot", '·'),
    ("int", '∫'),
    ("neq", '≠'),
    ("circ", '∘'),
];

/// The command of this name (the name without its backslash), if the subset has it.
pub fn command(name: &str) -> Option<Command> {
    let named = |table: &[(&str, char)]| table.iter().find(|(n, _)| *n == name).map(|p| p.1);
    if let Some(c) = named(&GREEK) {
        return Some(Command::Letter(c));
    }
    if let Some(c) = named(&OPERATORS) {
        return Some(Command::Operator(c));
    }
    Some(match name {
        "," => Command::ThinSpace,
        "{" => Command::Operator('{'),
        "}" => Command::Operator('}'),
        "mathbf" => Command::Face(Face::Bold),
        "boldsymbol" => Command::Face(Face::BoldSymbol),
        "mathrm" => Command::Face(Face::Roman),
        "text" => Command::Text,
        "bar" => Command::Accent(Accent::Bar),
        "dot" => Command::Accent(Accent::Dot),
        "ddot" => Command::Accent(Accent::DoubleDot),
        "frac" => Command::Fraction { small: false },
        "tfrac" => Command::Fraction { small: true },
        f if FUNCTIONS.contains(&f) => Command::Function(FUNCTIONS.iter().find(|n| **n == f)?),
        _ => return None,
    })
}

/// The LaTeX command (with its backslash) for a Unicode letter or operator of the subset:
/// `ω` → `\omega`, `×` → `\times`, `{` → `\{`; none for an ASCII character that is itself.
pub fn latex_of(c: char) -> Option<String> {
    let name = GREEK
        .iter()
        .chain(OPERATORS.iter())
        .find(|(_, u)| *u == c)
        .map(|p| p.0);
    match (name, c) {
        (Some(name), _) => Some(format!("\\{name}")),
        (None, '{' | '}') => Some(format!("\\{c}")),
        _ => None,
    }
}

/// Relations and binary operators, written with a space each side (unless a sign).
pub fn is_spaced(c: char) -> bool {
    "=≠<>+-×·".contains(c)
}

/// Whether `c` is an upper-case Greek letter (upright in mathematics, as TeX sets it).
pub fn is_upper_greek(c: char) -> bool {
    ('Α'..='Ω').contains(&c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_letter_and_operator_reads_back_from_its_latex() {
        for (name, c) in GREEK.iter().chain(OPERATORS.iter()) {
            assert_eq!(latex_of(*c), Some(format!("\\{name}")));
            assert!(command(name).is_some());
        }
        assert_eq!(latex_of('x'), None);
        assert_eq!(command("foo"), None);
    }
}
