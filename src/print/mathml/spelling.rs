//! A symbol's LaTeX spelling as MathML Core: the small subset `Symbol::latex` writes and the
//! solution's quantity names use, read as TeX reads it.
//!
//! | LaTeX                          | MathML                                                   |
//! |--------------------------------|----------------------------------------------------------|
//! | `x`, `\omega`                  | `<mi>x</mi>`, `<mi>ω</mi>` (one letter: italic)          |
//! | `\Sigma`, `\Delta`, `\Omega`   | `<mi mathvariant="normal">Σ</mi>` (capital Greek upright) |
//! | `12`, `'`, `(`, `)`            | `<mn>12</mn>`, `<mo>′</mo>`, `<mo>(</mo>`, `<mo>)</mo>`  |
//! | `a_x`, `I_{xy}`, `a^2`         | `<msub>`, `<msup>`, both on one base: `<msubsup>`        |
//! | `\bar{v}`, `\dot{ω}`, `\ddot{θ}` | `<mover accent="true">` with `¯`, `˙`, `¨`             |
//! | `\overset{(3)}{θ}`             | `<mover>` with the row `(3)` over `θ`                    |
//! | `\mathbf{H}`, `\boldsymbol{ω}` | bold letters of Unicode's mathematical alphanumerics      |
//! | `\mathit{Lb}`                  | one `<mi>` of italic letters: one name, not a product     |
//! | `\text{body}`, `\mathrm{N}`    | `<mtext>body</mtext>`, `<mi mathvariant="normal">N</mi>` |
//! | `\,`                           | `<mspace width="0.1667em"/>`                             |
//!
//! An unknown command is written as its name in upright letters and an unclosed brace ends
//! at the end of the spelling: any text gives well-formed MathML. Each character is read
//! once, and groups and command arguments nest at most [`MAX_DEPTH`] deep (deeper ones are
//! left empty), so reading never recurses without bound.

use crate::visible;

/// How deep groups and command arguments may nest; deeper ones are left empty.
const MAX_DEPTH: usize = 16;

/// Lower-case Greek letters by their TeX names, in Unicode's order (final sigma is not one).
const GREEK_SMALL: [&str; 25] = [
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "omicron", "pi", "rho", "varsigma", "sigma", "tau", "upsilon",
    "phi", "chi", "psi", "omega",
];

/// The letter style of a group: TeX's default, or the one a font command sets.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Style {
    /// Letters italic, capital Greek upright.
    Math,
    /// `\mathbf`: bold upright.
    Bold,
    /// `\boldsymbol`: bold, italic where the letter would be.
    BoldSymbol,
    /// `\mathit`: one italic name.
    Italic,
    /// `\mathrm`: upright.
    Roman,
}

/// One element of a row with the scripts attached to it.
#[derive(Debug, Default)]
struct Atom {
    base: String,
    sub: Option<String>,
    sup: Option<String>,
}

impl Atom {
    fn new(base: String) -> Atom {
        Atom {
            base,
            ..Atom::default()
        }
    }

    /// Where a subscript (`below`) or a superscript goes.
    fn slot(&mut self, below: bool) -> &mut Option<String> {
        if below {
            &mut self.sub
        } else {
            &mut self.sup
        }
    }

    /// The text of an atom that is one unscripted `<mi>`.
    fn letter(&self) -> Option<&str> {
        if self.sub.is_some() || self.sup.is_some() {
            return None;
        }
        self.base.strip_prefix("<mi>")?.strip_suffix("</mi>")
    }

    fn write(&self, out: &mut String) {
        let row = |out: &mut String, inner: &str| {
            out.push_str("<mrow>");
            out.push_str(inner);
            out.push_str("</mrow>");
        };
        match (&self.sub, &self.sup) {
            (None, None) => out.push_str(&self.base),
            (Some(sub), None) => {
                out.push_str("<msub>");
                row(out, &self.base);
                row(out, sub);
                out.push_str("</msub>");
            }
            (None, Some(sup)) => {
                out.push_str("<msup>");
                row(out, &self.base);
                row(out, sup);
                out.push_str("</msup>");
            }
            (Some(sub), Some(sup)) => {
                out.push_str("<msubsup>");
                row(out, &self.base);
                row(out, sub);
                row(out, sup);
                out.push_str("</msubsup>");
            }
        }
    }
}

/// Appends the MathML of the spelling `latex`; with `exponent` (MathML already written),
/// raised on its last element as `latex^{...}` would be (`\omega_x^2` as one `<msubsup>`).
pub fn write(out: &mut String, latex: &str, exponent: Option<&str>) {
    let mut atoms = Reader::new(latex).row(Style::Math, 0);
    if let Some(exponent) = exponent {
        match atoms.last_mut() {
            Some(last) if last.sup.is_none() => last.sup = Some(exponent.to_string()),
            _ => {
                let mut inner = String::new();
                atoms.iter().for_each(|a| a.write(&mut inner));
                atoms = vec![Atom {
                    base: inner,
                    sup: Some(exponent.to_string()),
                    ..Atom::default()
                }];
            }
        }
    }
    if atoms.len() > 1 {
        out.push_str("<mrow>");
    }
    atoms.iter().for_each(|a| a.write(out));
    if atoms.len() > 1 {
        out.push_str("</mrow>");
    }
}

/// Sets `script` below (`_`) or above (`^`) the last atom, as TeX does: on an atom already
/// scripted there, it scripts the whole; with no atom before, an empty base.
fn attach(atoms: &mut Vec<Atom>, below: bool, script: String) {
    let mut atom = atoms
        .pop()
        .unwrap_or_else(|| Atom::new("<mrow></mrow>".into()));
    if atom.slot(below).is_some() {
        let mut written = String::new();
        atom.write(&mut written);
        atom = Atom::new(written);
    }
    *atom.slot(below) = Some(script);
    atoms.push(atom);
}

/// Whether the spelling reads as more than one letter (`\Delta t`, `\Sigma M_x`,
/// `\mathit{Lb}`), so that a letter after it would seem to belong to it.
pub fn is_several_letters(latex: &str) -> bool {
    let atoms = Reader::new(latex).row(Style::Math, 0);
    match atoms.as_slice() {
        [one] => one.letter().is_some_and(|l| l.chars().count() > 1),
        atoms => atoms.len() > 1,
    }
}

/// The spelling as characters and the position reading has reached.
struct Reader {
    chars: Vec<char>,
    at: usize,
}

impl Reader {
    fn new(latex: &str) -> Reader {
        Reader {
            chars: latex.chars().collect(),
            at: 0,
        }
    }

    fn peek(&self) -> Option<char> {
        self.chars.get(self.at).copied()
    }

    /// Atoms up to the end or the `}` closing this group (consumed).
    fn row(&mut self, style: Style, depth: usize) -> Vec<Atom> {
        let mut atoms: Vec<Atom> = Vec::new();
        while let Some(c) = self.peek() {
            self.at += 1;
            match c {
                '}' if depth > 0 => break,
                '_' | '^' => {
                    let script = self.argument(style, depth);
                    attach(&mut atoms, c == '_', script);
                }
                ' ' => {}
                '{' => {
                    let inner = self.group(style, depth);
                    atoms.push(Atom::new(inner));
                }
                '\\' => {
                    if let Some(atom) = self.command(style, depth) {
                        atoms.push(atom);
                    }
                }
                _ => atoms.push(Atom::new(self.character(c, style))),
            }
        }
        // An italic name is one identifier, not a product of letters.
        let letters: Option<String> = atoms.iter().map(Atom::letter).collect();
        match letters {
            Some(name) if style == Style::Italic && !name.is_empty() => {
                vec![Atom::new(format!("<mi>{name}</mi>"))]
            }
            _ => atoms,
        }
    }

    /// The MathML of a braced group after its `{`, or of an empty group at too great a depth.
    fn group(&mut self, style: Style, depth: usize) -> String {
        let mut out = String::new();
        if depth >= MAX_DEPTH {
            return out;
        }
        let atoms = self.row(style, depth + 1);
        atoms.iter().for_each(|a| a.write(&mut out));
        out
    }

    /// A command's argument: a braced group, a command, or one character (nothing past
    /// [`MAX_DEPTH`]).
    fn argument(&mut self, style: Style, depth: usize) -> String {
        if depth >= MAX_DEPTH {
            return String::new();
        }
        while self.peek() == Some(' ') {
            self.at += 1;
        }
        match self.peek() {
            Some('{') => {
                self.at += 1;
                self.group(style, depth)
            }
            Some('\\') => {
                self.at += 1;
                let mut out = String::new();
                if let Some(atom) = self.command(style, depth + 1) {
                    atom.write(&mut out);
                }
                out
            }
            Some(c) => {
                self.at += 1;
                self.character(c, style)
            }
            None => String::new(),
        }
    }

    /// A command after its backslash.
    fn command(&mut self, style: Style, depth: usize) -> Option<Atom> {
        let start = self.at;
        while self.peek().is_some_and(|c| c.is_ascii_alphabetic()) {
            self.at += 1;
        }
        if self.at == start {
            // A control symbol: `\,` is a thin space, `\{` a brace.
            let c = self.peek()?;
            self.at += 1;
            return Some(Atom::new(match c {
                ',' => r#"<mspace width="0.1667em"/>"#.into(),
                ' ' => r#"<mspace width="0.25em"/>"#.into(),
                c => operator(c),
            }));
        }
        let name: String = self.chars[start..self.at].iter().collect();
        let accent = |mark: &str, inner: String| {
            format!(r#"<mover accent="true"><mrow>{inner}</mrow><mo>{mark}</mo></mover>"#)
        };
        Some(Atom::new(match name.as_str() {
            "bar" => accent("\u{af}", self.argument(style, depth)),
            "dot" => accent("\u{2d9}", self.argument(style, depth)),
            "ddot" => accent("\u{a8}", self.argument(style, depth)),
            "overset" => {
                let over = self.argument(style, depth);
                let base = self.argument(style, depth);
                format!("<mover><mrow>{base}</mrow><mrow>{over}</mrow></mover>")
            }
            "mathbf" => self.argument(Style::Bold, depth),
            "boldsymbol" => self.argument(Style::BoldSymbol, depth),
            "mathit" => self.argument(Style::Italic, depth),
            "mathrm" => self.argument(Style::Roman, depth),
            "text" => self.text(depth),
            name => match greek(name) {
                Some(letter) => self.letter(letter, style),
                None => format!(r#"<mi mathvariant="normal">{}</mi>"#, escaped(name)),
            },
        }))
    }

    /// `\text{...}`'s argument, as written.
    fn text(&mut self, depth: usize) -> String {
        let mut words = String::new();
        if self.peek() == Some('{') && depth < MAX_DEPTH {
            self.at += 1;
            let mut open = 1usize;
            while let Some(c) = self.peek() {
                self.at += 1;
                match c {
                    '{' => open += 1,
                    '}' => open -= 1,
                    _ => {}
                }
                if open == 0 {
                    break;
                }
                words.push(c);
            }
        }
        format!("<mtext>{}</mtext>", escaped(&words))
    }

    /// A character outside a command.
    fn character(&mut self, c: char, style: Style) -> String {
        if c.is_ascii_digit() {
            let mut digits = String::from(c);
            while let Some(d) = self.peek().filter(char::is_ascii_digit) {
                digits.push(d);
                self.at += 1;
            }
            return format!("<mn>{digits}</mn>");
        }
        if c.is_alphabetic() {
            return self.letter(c, style);
        }
        if c == '\'' {
            return "<mo>\u{2032}</mo>".into();
        }
        operator(c)
    }

    /// A letter in a style.
    fn letter(&self, c: char, style: Style) -> String {
        let capital_greek = ('\u{391}'..='\u{3a9}').contains(&c);
        match style {
            Style::Math if capital_greek => format!(r#"<mi mathvariant="normal">{c}</mi>"#),
            Style::Math => format!("<mi>{c}</mi>"),
            Style::Roman => format!(r#"<mi mathvariant="normal">{c}</mi>"#),
            Style::Italic => format!("<mi>{}</mi>", alphanumeric(c, ITALIC).unwrap_or(c)),
            Style::Bold => format!("<mi>{}</mi>", alphanumeric(c, BOLD).unwrap_or(c)),
            Style::BoldSymbol if capital_greek => {
                format!("<mi>{}</mi>", alphanumeric(c, BOLD).unwrap_or(c))
            }
            Style::BoldSymbol => {
                format!("<mi>{}</mi>", alphanumeric(c, BOLD_ITALIC).unwrap_or(c))
            }
        }
    }
}

/// The letter a Greek command names: `omega` → ω, `Sigma` → Σ.
fn greek(name: &str) -> Option<char> {
    let small = |n: &str| GREEK_SMALL.iter().position(|g| *g == n);
    if let Some(k) = small(name) {
        return char::from_u32(0x3b1 + k as u32);
    }
    let mut lower = name.to_string();
    let first = lower.get(..1)?.to_ascii_lowercase();
    lower.replace_range(..1, &first);
    if name == lower || lower == "varsigma" {
        return None;
    }
    // Capital Greek has a gap where final sigma stands among the small letters.
    small(&lower).and_then(|k| char::from_u32(0x391 + k as u32))
}

/// Where a style's letters start in Unicode's mathematical alphanumerics: capital Latin,
/// small Latin, capital Greek, small Greek.
type Alphabet = [u32; 4];
const BOLD: Alphabet = [0x1d400, 0x1d41a, 0x1d6a8, 0x1d6c2];
const ITALIC: Alphabet = [0x1d434, 0x1d44e, 0x1d6e2, 0x1d6fc];
const BOLD_ITALIC: Alphabet = [0x1d468, 0x1d482, 0x1d71c, 0x1d736];

/// `c` in a mathematical alphabet, when it has a letter there (italic h is Planck's ℎ).
fn alphanumeric(c: char, alphabet: Alphabet) -> Option<char> {
    if alphabet == ITALIC && c == 'h' {
        return Some('\u{210e}');
    }
    let code = u32::from(c);
    let (start, first) = match c {
        'A'..='Z' => (alphabet[0], u32::from('A')),
        'a'..='z' => (alphabet[1], u32::from('a')),
        '\u{391}'..='\u{3a9}' => (alphabet[2], 0x391),
        '\u{3b1}'..='\u{3c9}' => (alphabet[3], 0x3b1),
        _ => return None,
    };
    char::from_u32(start + code - first)
}

/// A character that is no letter or digit, as an operator: `(` `)` `+` `,` ...
fn operator(c: char) -> String {
    format!("<mo>{}</mo>", escaped(&c.to_string()))
}

/// Text escaped for HTML and XML, the one escaper of both: `& < > " '` as references, so
/// the text is safe in an element and in an attribute's value, and a character a reader
/// cannot see (ESC, a right-to-left override: [`visible::is_hidden`]) as its escape
/// `\u{1b}`.
pub fn escaped(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c if visible::is_hidden(c) => visible::push_escape(&mut out, c),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::write;

    fn mathml(latex: &str) -> String {
        let mut out = String::new();
        write(&mut out, latex, None);
        out
    }

    #[test]
    fn letters_greek_and_subscripts() {
        assert_eq!(mathml("m"), "<mi>m</mi>");
        assert_eq!(mathml(r"\omega"), "<mi>ω</mi>");
        assert_eq!(
            mathml(r"\omega_x"),
            "<msub><mrow><mi>ω</mi></mrow><mrow><mi>x</mi></mrow></msub>"
        );
        assert_eq!(
            mathml("I_{xy}"),
            "<msub><mrow><mi>I</mi></mrow><mrow><mi>x</mi><mi>y</mi></mrow></msub>"
        );
        assert_eq!(
            mathml("I_{x'}"),
            "<msub><mrow><mi>I</mi></mrow><mrow><mi>x</mi><mo>′</mo></mrow></msub>"
        );
        assert_eq!(
            mathml(r"\omega_1"),
            "<msub><mrow><mi>ω</mi></mrow><mrow><mn>1</mn></mrow></msub>"
        );
    }

    #[test]
    fn capital_greek_is_upright() {
        assert_eq!(
            mathml(r"\Delta t"),
            r#"<mrow><mi mathvariant="normal">Δ</mi><mi>t</mi></mrow>"#
        );
        assert_eq!(
            mathml(r"\Sigma M_x"),
            concat!(
                r#"<mrow><mi mathvariant="normal">Σ</mi>"#,
                "<msub><mrow><mi>M</mi></mrow><mrow><mi>x</mi></mrow></msub></mrow>"
            )
        );
        assert_eq!(mathml(r"\Omega"), r#"<mi mathvariant="normal">Ω</mi>"#);
    }

    #[test]
    fn accents_over_the_letter() {
        assert_eq!(
            mathml(r"\bar{v}_x"),
            concat!(
                r#"<msub><mrow><mover accent="true"><mrow><mi>v</mi></mrow><mo>¯</mo></mover>"#,
                "</mrow><mrow><mi>x</mi></mrow></msub>"
            )
        );
        assert_eq!(
            mathml(r"\dot{\omega}"),
            r#"<mover accent="true"><mrow><mi>ω</mi></mrow><mo>˙</mo></mover>"#
        );
        assert_eq!(
            mathml(r"\ddot{\theta}"),
            r#"<mover accent="true"><mrow><mi>θ</mi></mrow><mo>¨</mo></mover>"#
        );
        assert_eq!(
            mathml(r"\overset{(3)}{\theta}"),
            "<mover><mrow><mi>θ</mi></mrow><mrow><mo>(</mo><mn>3</mn><mo>)</mo></mrow></mover>"
        );
    }

    #[test]
    fn fonts() {
        assert_eq!(mathml(r"\mathbf{i}"), "<mi>𝐢</mi>");
        assert_eq!(
            mathml(r"\mathbf{H}_G"),
            "<msub><mrow><mi>𝐇</mi></mrow><mrow><mi>G</mi></mrow></msub>"
        );
        assert_eq!(mathml(r"\boldsymbol{\omega}"), "<mi>𝝎</mi>");
        assert_eq!(mathml(r"\mathit{Lb}"), "<mi>𝐿𝑏</mi>");
        assert_eq!(
            mathml(r"m_{\text{body}}"),
            "<msub><mrow><mi>m</mi></mrow><mrow><mtext>body</mtext></mrow></msub>"
        );
        assert_eq!(mathml(r"\mathrm{N}"), r#"<mi mathvariant="normal">N</mi>"#);
    }

    #[test]
    fn names_of_several_letters() {
        use super::is_several_letters;
        for several in [r"\Delta t", r"\Sigma M_x", r"\mathit{Lb}"] {
            assert!(is_several_letters(several), "{several}");
        }
        for one in [
            r"\omega_x",
            "I_{xy}",
            r"\bar{v}_x",
            r"\dot{\omega}",
            "m_{\text{body}}",
        ] {
            assert!(!is_several_letters(one), "{one}");
        }
    }

    #[test]
    fn an_exponent_joins_the_subscript() {
        let mut out = String::new();
        write(&mut out, r"\omega_x", Some("<mn>2</mn>"));
        assert_eq!(
            out,
            "<msubsup><mrow><mi>ω</mi></mrow><mrow><mi>x</mi></mrow><mrow><mn>2</mn></mrow></msubsup>"
        );
    }

    /// Whether every element opened is closed, in order (attributes and text not read).
    fn balanced(mathml: &str) -> bool {
        let mut open = Vec::new();
        for tag in mathml.split('<').skip(1) {
            let Some((tag, _)) = tag.split_once('>') else {
                return false;
            };
            if let Some(name) = tag.strip_prefix('/') {
                if open.pop() != Some(name) {
                    return false;
                }
            } else if !tag.ends_with('/') {
                open.push(tag.split(' ').next().unwrap_or(tag));
            }
        }
        open.is_empty()
    }

    #[test]
    fn anything_else_is_well_formed() {
        let deep = "{".repeat(40) + "x";
        let accents = r"\bar".repeat(10_000);
        let odd = [
            r"\",
            "{",
            "}",
            "_",
            "^^",
            r"\unknown<&>",
            "a_",
            r"\bar",
            "_x^",
            &deep,
            &accents,
        ];
        for odd in odd {
            let out = mathml(odd);
            assert!(balanced(&out), "{odd}: {out}");
            assert!(!out.contains("<&") && !out.contains("&>"), "{odd}: {out}");
        }
    }
}
