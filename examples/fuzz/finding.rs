//! What the fuzzer looks for, and how a finding is kept: one file per kind of failure (its
//! class and a signature with the numbers taken out), written in the reproducer format of
//! `tests/reproducers/` (`# run: ...`, `# found: ...`, then the input), so a finding can be
//! copied there as it is.

use std::io::Write;
use std::path::{Path, PathBuf};

/// The kinds of failure (issue 14's promises, broken).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Class {
    /// A Rust panic (caught by `catch_unwind`).
    Panic,
    /// The process died: a stack overflow, an abort, the memory exhausted.
    Crash,
    /// One input ran longer than the watchdog's limit.
    Hang,
    /// `inf` or `NaN` in an output, or a non-finite sample.
    NonFinite,
    /// An error without a place in the input, or pointing at a comment.
    Unlocated,
    /// An error quoting a number the user never wrote (a long expanded constant).
    Unquoted,
    /// The worker ran out of its address space ([`crate::supervisor::MEMORY_LIMIT_KB`]): an
    /// allocation failed.
    Memory,
    /// A control character (ESC, a bidirectional override, ...) printed raw, in an output
    /// or an error message.
    Control,
    /// Markup of an output format from the input left raw: HTML in Markdown or HTML, a TeX
    /// command that reads or writes files in LaTeX.
    Injection,
}

impl Class {
    pub fn name(self) -> &'static str {
        match self {
            Class::Panic => "panic",
            Class::Crash => "crash",
            Class::Hang => "hang",
            Class::NonFinite => "non-finite",
            Class::Unlocated => "unlocated",
            Class::Unquoted => "unquoted",
            Class::Memory => "memory",
            Class::Control => "control",
            Class::Injection => "injection",
        }
    }

    pub fn from_name(name: &str) -> Option<Class> {
        [
            Class::Panic,
            Class::Crash,
            Class::Hang,
            Class::NonFinite,
            Class::Unlocated,
            Class::Unquoted,
            Class::Memory,
            Class::Control,
            Class::Injection,
        ]
        .into_iter()
        .find(|c| c.name() == name)
    }
}

/// A failure: its class and what tells it apart from others of the class.
#[derive(Clone, Debug)]
pub struct Finding {
    pub class: Class,
    pub signature: String,
}

impl Finding {
    /// `place` (a panic's source location, or empty) and `message` with every run of digits
    /// as `N`, on one line, at most 160 characters: the same failure on other numbers is the
    /// same finding.
    pub fn new(class: Class, place: &str, message: &str) -> Finding {
        let mut s = place.to_string();
        let mut in_digits = false;
        for c in message
            .chars()
            .map(|c| if c.is_whitespace() { ' ' } else { c })
        {
            match (c.is_ascii_digit(), in_digits) {
                (true, true) => {}
                (true, false) => s.push('N'),
                (false, _) => s.push(c),
            }
            in_digits = c.is_ascii_digit();
            if s.len() >= 160 {
                break;
            }
        }
        Finding {
            class,
            signature: s,
        }
    }

    /// A hang or a crash of `reproducer` (whose first line is its `# run:`): told apart by
    /// the command and the input's longest line, where the trouble usually is.
    pub fn of_input(class: Class, why: &str, reproducer: &str) -> Finding {
        let (run, input) = reproducer.split_once('\n').unwrap_or((reproducer, ""));
        let longest = input.lines().max_by_key(|l| l.len()).unwrap_or_default();
        Finding::new(class, "", &format!("{why}: {run}: {longest}"))
    }

    /// The file this finding is kept in, under `dir`.
    pub fn path(&self, dir: &Path, extension: &str) -> PathBuf {
        // FNV-1a of the signature: a stable name for the same failure.
        let hash = self
            .signature
            .bytes()
            .fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
                (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
            });
        dir.join(format!("{}-{hash:016x}.{extension}", self.class.name()))
    }

    /// Keeps `reproducer` (an input in the reproducer format) for this finding unless one is
    /// kept already, and reports it on standard output for the supervisor:
    /// `finding<TAB>class<TAB>signature<TAB>path`.
    pub fn report(&self, dir: &Path, extension: &str, reproducer: &str) {
        let path = self.path(dir, extension);
        if let Ok(mut file) = std::fs::File::create_new(&path) {
            let found = format!("# found: {}: {}\n", self.class.name(), self.signature);
            let (run, input) = reproducer.split_once('\n').unwrap_or((reproducer, ""));
            let _ = write!(file, "{run}\n{found}{input}");
        }
        println!(
            "finding\t{}\t{}\t{}",
            self.class.name(),
            self.signature,
            path.display()
        );
    }
}

/// The words of `text` that are printed non-finite numbers (`inf`, `NaN`, any case).
fn non_finite_words(text: &str) -> impl Iterator<Item = &str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.'))
        .map(|w| w.trim_start_matches(|c: char| c.is_ascii_digit() || c == '.'))
        .filter(|w| ["inf", "infinity", "nan"].contains(&w.to_ascii_lowercase().as_str()))
}

/// The first printed non-finite number in `output` that `input` does not hold itself (a
/// title typed as "tumbling inf(...)" is printed as written; that is no finding).
pub fn non_finite_word<'a>(output: &'a str, input: &str) -> Option<&'a str> {
    let written: Vec<String> = non_finite_words(input)
        .map(str::to_ascii_lowercase)
        .collect();
    non_finite_words(output).find(|w| !written.contains(&w.to_ascii_lowercase()))
}

/// The length of the longest run of digits in `text`.
pub fn longest_digit_run(text: &str) -> usize {
    text.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

/// The first character of `output` that should have been shown as its escape: one a
/// terminal, a bidirectional renderer or pdflatex would take for a command
/// ([`kinetics::visible::is_hidden`], the library's one rule).
pub fn raw_control(output: &str) -> Option<char> {
    output.chars().find(|&c| kinetics::visible::is_hidden(c))
}

/// A control character's name for a signature (which takes digits out): `ESC`, `U+202E`
/// as `RLO`, ...
pub fn control_name(c: char) -> &'static str {
    match c {
        '\u{0}' => "NUL",
        '\u{7}' => "BEL",
        '\u{8}' => "BS",
        '\r' => "CR",
        '\u{1b}' => "ESC",
        '\u{7f}' => "DEL",
        '\u{85}' => "NEL",
        '\u{202e}' => "RLO",
        '\u{feff}' => "BOM",
        '\u{202a}'..='\u{2069}' => "a bidirectional control",
        _ => "a control character",
    }
}

/// The output formats whose markup a title or a name could inject.
#[derive(Clone, Copy)]
pub enum Markup {
    Latex,
    Markdown,
    Html,
}

/// Markup in `output` that only the input can have put there: an HTML tag in Markdown
/// (where `$…$` is not maths to every renderer), an active HTML element or a `javascript:`
/// link in HTML, a TeX command that reads or writes a file in LaTeX.
pub fn injected(output: &str, markup: Markup) -> Option<&'static str> {
    const HTML: [&str; 5] = ["<script", "<img", "<iframe", "<object", "<embed"];
    const TEX: [&str; 7] = [
        "\\input",
        "\\include",
        "\\write",
        "\\openin",
        "\\openout",
        "\\immediate",
        "\\catcode",
    ];
    let lower = output.to_ascii_lowercase();
    match markup {
        Markup::Markdown => {
            let tag = lower.as_bytes().windows(2).any(|w| {
                w[0] == b'<' && (w[1].is_ascii_alphabetic() || w[1] == b'/' || w[1] == b'!')
            });
            // After an odd number of backslashes `](` is an escaped bracket, not the end of
            // a link's text.
            let escaped = |at: usize| {
                lower[..at]
                    .bytes()
                    .rev()
                    .take_while(|&b| b == b'\\')
                    .count()
                    % 2
                    == 1
            };
            let link = lower
                .match_indices("](javascript:")
                .any(|(at, _)| !escaped(at));
            (tag || link).then_some("raw HTML or a javascript: link in Markdown")
        }
        Markup::Html => HTML
            .iter()
            .copied()
            .find(|t| lower.contains(t))
            .or_else(|| (lower.contains("href=\"javascript:")).then_some("href=\"javascript:")),
        Markup::Latex => TEX.iter().copied().find(|t| output.contains(t)),
    }
}
