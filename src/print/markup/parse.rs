//! A title read into a tree: words, and mathematics between `$…$` in the subset.
//!
//! ```text
//! title   = { words | "$" list "$" }        words: any text without "$"
//! list    = { atom [scripts] | blank }
//! scripts = "_" argument ["^" argument] | "^" argument ["_" argument]
//! atom    = letter | number | operator | "{" list "}" | "\" command arguments
//! argument= one letter, digit or operator | "\" command | "{" list "}"
//! ```
//!
//! Operators are `+ - = × · ( ) [ ] , . / | : ' < >` and `\{ \}`; numbers are digits with an
//! inner decimal point. Reading is one pass, nesting at most [`MAX_DEPTH`] deep, so any input
//! is read in linear time and a malformed one gives a [`MarkupError`] at its byte offset.

use super::commands::{command, Accent, Command, Face};
use std::fmt;

/// How deeply braces and arguments may nest.
pub const MAX_DEPTH: usize = 32;

/// A piece of a title.
#[derive(Debug, Clone, PartialEq)]
pub enum Segment {
    Words(String),
    Maths(Vec<Node>),
}

/// A node of the mathematics.
#[derive(Debug, Clone, PartialEq)]
pub enum Node {
    /// An identifier's letter: ASCII, or Greek from its command.
    Letter(char),
    /// Digits, with a decimal point between digits.
    Number(String),
    Operator(char),
    /// A blank in the source: no space in LaTeX's mathematics, one in text.
    Blank,
    /// `\,`.
    ThinSpace,
    Face(Face, Vec<Node>),
    /// `\text{…}`: its words.
    Text(String),
    /// A function's name, upright (`\sin`).
    Function(&'static str),
    Accent(Accent, Vec<Node>),
    Fraction {
        small: bool,
        numerator: Vec<Node>,
        denominator: Vec<Node>,
    },
    /// A base with a subscript, a superscript or both.
    Scripts {
        base: Box<Node>,
        sub: Option<Vec<Node>>,
        sup: Option<Vec<Node>>,
    },
    /// `{…}`.
    Group(Vec<Node>),
}

/// Why a title is not well formed, and the byte offset where that shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MarkupError {
    pub offset: usize,
    pub kind: MarkupErrorKind,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub enum MarkupErrorKind {
    /// A `\name` the subset does not have.
    UnknownCommand(String),
    /// A `{` never closed (its offset) or a `}` never opened.
    UnbalancedBrace,
    /// A `$` whose mathematics is never closed.
    UnclosedMaths,
    /// A command, `_` or `^` with nothing to take.
    MissingArgument,
    /// A second subscript or superscript on one base.
    DoubleScript,
    /// A character outside the subset.
    UnexpectedCharacter(char),
    /// Braces or arguments nested beyond [`MAX_DEPTH`].
    TooDeep,
}

impl fmt::Display for MarkupError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            MarkupErrorKind::UnknownCommand(name) => write!(f, "unknown command \\{name}"),
            MarkupErrorKind::UnbalancedBrace => f.write_str("unbalanced brace"),
            MarkupErrorKind::UnclosedMaths => f.write_str("mathematics opened by $ never closed"),
            MarkupErrorKind::MissingArgument => f.write_str("missing argument"),
            MarkupErrorKind::DoubleScript => f.write_str("a second subscript or superscript"),
            MarkupErrorKind::UnexpectedCharacter(c) => {
                write!(f, "'{c}' is not in the mathematics of a title")
            }
            MarkupErrorKind::TooDeep => write!(f, "nested more than {MAX_DEPTH} deep"),
        }?;
        write!(f, " at byte {}", self.offset)
    }
}

impl std::error::Error for MarkupError {}

/// Reads a title.
pub fn parse(title: &str) -> Result<Vec<Segment>, MarkupError> {
    let mut reader = Reader {
        source: title,
        at: 0,
        depth: 0,
    };
    let mut segments = Vec::new();
    while reader.at < title.len() {
        let rest = &title[reader.at..];
        let words = rest.find('$').unwrap_or(rest.len());
        if words > 0 {
            segments.push(Segment::Words(rest[..words].to_string()));
            reader.at += words;
            continue;
        }
        let open = reader.at;
        reader.at += 1;
        let list = reader.list(Closing::Dollar(open))?;
        segments.push(Segment::Maths(list));
    }
    Ok(segments)
}

/// What ends a list.
#[derive(Clone, Copy)]
enum Closing {
    /// The `$` that closes the one at this offset.
    Dollar(usize),
    /// The `}` that closes the `{` at this offset.
    Brace(usize),
}

struct Reader<'a> {
    source: &'a str,
    at: usize,
    depth: usize,
}

fn error<T>(offset: usize, kind: MarkupErrorKind) -> Result<T, MarkupError> {
    Err(MarkupError { offset, kind })
}

fn is_operator(c: char) -> bool {
    "+-=×·()[],./|:'<>".contains(c)
}

impl Reader<'_> {
    fn peek(&self) -> Option<char> {
        self.source[self.at..].chars().next()
    }

    fn bump(&mut self) -> Option<char> {
        let c = self.peek()?;
        self.at += c.len_utf8();
        Some(c)
    }

    /// One level deeper, refused past [`MAX_DEPTH`].
    fn deeper(&mut self) -> Result<(), MarkupError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return error(self.at, MarkupErrorKind::TooDeep);
        }
        Ok(())
    }

    /// Nodes up to and including the closing `$` or `}`.
    fn list(&mut self, closing: Closing) -> Result<Vec<Node>, MarkupError> {
        let mut nodes = Vec::new();
        loop {
            let here = self.at;
            match (self.peek(), closing) {
                (None, Closing::Dollar(open)) => {
                    return error(open, MarkupErrorKind::UnclosedMaths)
                }
                (None, Closing::Brace(open)) | (Some('$'), Closing::Brace(open)) => {
                    return error(open, MarkupErrorKind::UnbalancedBrace)
                }
                (Some('$'), Closing::Dollar(_)) | (Some('}'), Closing::Brace(_)) => {
                    self.at += 1;
                    return Ok(nodes);
                }
                (Some('}'), Closing::Dollar(_)) => {
                    return error(here, MarkupErrorKind::UnbalancedBrace)
                }
                (Some(c), _) if c.is_whitespace() => {
                    self.at += c.len_utf8();
                    if !matches!(nodes.last(), None | Some(Node::Blank)) {
                        nodes.push(Node::Blank);
                    }
                }
                (Some(script @ ('_' | '^')), _) => {
                    self.at += 1;
                    if nodes.last() == Some(&Node::Blank) {
                        nodes.pop();
                    }
                    let base = nodes.pop().unwrap_or(Node::Group(Vec::new()));
                    let argument = self.argument()?;
                    nodes.push(attach(base, script == '_', argument, here)?);
                }
                _ => {
                    let atom = self.atom()?;
                    nodes.push(atom);
                }
            }
        }
    }

    /// One atom at the reader's position (not a blank, `_`, `^`, `$` or `}`).
    fn atom(&mut self) -> Result<Node, MarkupError> {
        let here = self.at;
        let Some(c) = self.bump() else {
            return error(here, MarkupErrorKind::MissingArgument);
        };
        match c {
            c if c.is_ascii_alphabetic() => Ok(Node::Letter(c)),
            c if c.is_ascii_digit() => {
                let mut digits = c.to_string();
                while let Some(d) = self.peek().filter(|d| d.is_ascii_digit() || *d == '.') {
                    let after = self.source[self.at + 1..].chars().next();
                    if d == '.' && !after.is_some_and(|a| a.is_ascii_digit()) {
                        break;
                    }
                    digits.push(d);
                    self.at += 1;
                }
                Ok(Node::Number(digits))
            }
            '{' => {
                self.deeper()?;
                let group = self.list(Closing::Brace(here))?;
                self.depth -= 1;
                Ok(Node::Group(group))
            }
            '\\' => self.command(here),
            c if is_operator(c) => Ok(Node::Operator(c)),
            c => error(here, MarkupErrorKind::UnexpectedCharacter(c)),
        }
    }

    /// A command after its backslash (at `start`), with its arguments.
    fn command(&mut self, start: usize) -> Result<Node, MarkupError> {
        let rest = &self.source[self.at..];
        let length = match rest.find(|c: char| !c.is_ascii_alphabetic()) {
            Some(0) => rest.chars().next().map_or(0, char::len_utf8),
            Some(n) => n,
            None => rest.len(),
        };
        let name = &rest[..length];
        self.at += length;
        if name.starts_with(|c: char| c.is_ascii_alphabetic()) {
            // A blank after a control word only ends its name, as in TeX.
            while self.peek().is_some_and(char::is_whitespace) {
                self.bump();
            }
        }
        let Some(found) = command(name) else {
            return error(start, MarkupErrorKind::UnknownCommand(name.to_string()));
        };
        Ok(match found {
            Command::Letter(c) => Node::Letter(c),
            Command::Operator(c) => Node::Operator(c),
            Command::ThinSpace => Node::ThinSpace,
            Command::Face(face) => Node::Face(face, self.argument()?),
            Command::Accent(accent) => Node::Accent(accent, self.argument()?),
            Command::Text => Node::Text(self.text_argument()?),
            Command::Function(name) => Node::Function(name),
            Command::Fraction { small } => Node::Fraction {
                small,
                numerator: self.argument()?,
                denominator: self.argument()?,
            },
        })
    }

    /// A command's argument or a script: one token, or a braced list.
    fn argument(&mut self) -> Result<Vec<Node>, MarkupError> {
        while self.peek().is_some_and(char::is_whitespace) {
            self.bump();
        }
        let here = self.at;
        match self.peek() {
            None | Some('$' | '}' | '_' | '^') => error(here, MarkupErrorKind::MissingArgument),
            Some('{') => {
                self.at += 1;
                self.deeper()?;
                let list = self.list(Closing::Brace(here))?;
                self.depth -= 1;
                Ok(list)
            }
            Some(c) if c.is_ascii_digit() => {
                // One digit, as TeX takes one token: `\tfrac12`.
                self.at += 1;
                Ok(vec![Node::Number(c.to_string())])
            }
            Some(_) => {
                self.deeper()?;
                let atom = self.atom()?;
                self.depth -= 1;
                Ok(vec![atom])
            }
        }
    }

    /// `\text`'s braced words: anything but `\`, `$`, `{`.
    fn text_argument(&mut self) -> Result<String, MarkupError> {
        let open = self.at;
        if self.peek() != Some('{') {
            return error(open, MarkupErrorKind::MissingArgument);
        }
        self.at += 1;
        let mut words = String::new();
        loop {
            let here = self.at;
            match self.bump() {
                None | Some('$') => return error(open, MarkupErrorKind::UnbalancedBrace),
                Some('}') => return Ok(words),
                Some(c @ ('\\' | '{')) => {
                    return error(here, MarkupErrorKind::UnexpectedCharacter(c))
                }
                Some(c) => words.push(c),
            }
        }
    }
}

/// Whether an operator after `previous` begins a term (a sign, not a binary operator): at
/// the start, or after an operator that is not a closing fence.
pub fn is_sign(previous: Option<&Node>) -> bool {
    match previous {
        None => true,
        Some(Node::Operator(c)) => !")]}|'".contains(*c),
        Some(_) => false,
    }
}

/// `base` with a subscript (`sub`) or superscript added; a second of one kind refused.
fn attach(base: Node, sub: bool, script: Vec<Node>, at: usize) -> Result<Node, MarkupError> {
    let (base, mut lower, mut upper) = match base {
        Node::Scripts { base, sub, sup } => (base, sub, sup),
        other => (Box::new(other), None, None),
    };
    let slot = if sub { &mut lower } else { &mut upper };
    if slot.is_some() {
        return error(at, MarkupErrorKind::DoubleScript);
    }
    *slot = Some(script);
    Ok(Node::Scripts {
        base,
        sub: lower,
        sup: upper,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kind(title: &str) -> (usize, MarkupErrorKind) {
        let e = parse(title).expect_err(title);
        (e.offset, e.kind)
    }

    #[test]
    fn errors_stand_where_they_show() {
        use MarkupErrorKind::*;
        assert_eq!(kind(r"a $\foo x$"), (3, UnknownCommand("foo".into())));
        assert_eq!(kind("a $x"), (2, UnclosedMaths));
        assert_eq!(kind("$x}$"), (2, UnbalancedBrace));
        assert_eq!(kind("$x_{a$"), (3, UnbalancedBrace));
        assert_eq!(kind(r"$\frac{1}$"), (9, MissingArgument));
        assert_eq!(kind("$x_1_2$"), (4, DoubleScript));
        assert_eq!(kind("$x ; y$"), (3, UnexpectedCharacter(';')));
        assert_eq!(kind(&format!("${}$", "{".repeat(100))).1, TooDeep);
        assert_eq!(kind(&format!("${}$", "^".repeat(100))).1, MissingArgument);
        assert_eq!(kind(&format!("${}x$", r"\dot".repeat(100))).1, TooDeep);
    }

    #[test]
    fn scripts_attach_to_the_atom_before() {
        let [Segment::Maths(nodes)] = &parse("$H_G^2$").unwrap()[..] else {
            panic!("one mathematics");
        };
        assert_eq!(
            nodes,
            &[Node::Scripts {
                base: Box::new(Node::Letter('H')),
                sub: Some(vec![Node::Letter('G')]),
                sup: Some(vec![Node::Number("2".into())]),
            }]
        );
    }
}
