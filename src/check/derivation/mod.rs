//! A hand derivation checked line by line, with error carried forward.
//!
//! A derivation is a chain of equations, one a line. Each line is first decided against the
//! mechanics ([`check`]): `holds`, `differs` (with its slip), `undecided`. A line that differs
//! is then decided again in the student's world ([`world`]): the values the earlier lines,
//! taken as true, give the derived names. Where it holds there it `follows from` the earlier
//! lines that differ and that its names' values rest on: it is wrong only because it carries
//! their slip (the marking scheme's "error carried forward").
//!
//! Blank lines separate the parts of a file (each its own chain); `#` starts a comment.

pub mod report;
mod world;

use super::context::Context;
use super::verdict::{check_parsed, Report, Verdict};
use crate::parse::{ClaimSyntax, Diagnostic, Follows};
pub use world::Given;
use world::World;

/// A line of a derivation: its number in its file and its text.
#[derive(Debug, Clone)]
pub struct Line {
    pub number: usize,
    pub text: String,
}

/// What a line of a derivation is judged.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Judgement {
    Holds,
    Differs,
    /// Wrong against the mechanics, right from the earlier wrong lines.
    Follows,
    Undecided,
    /// The line could not be read.
    Error,
}

impl Judgement {
    /// The judgement as a word: `holds`, `differs`, `follows`, `undecided`, `error`.
    pub fn word(self) -> &'static str {
        match self {
            Judgement::Holds => "holds",
            Judgement::Differs => "differs",
            Judgement::Follows => "follows",
            Judgement::Undecided => "undecided",
            Judgement::Error => "error",
        }
    }
}

/// One line checked: against the mechanics, and (where it differs) in the student's world.
#[derive(Debug, Clone)]
pub struct LineCheck {
    pub line: Line,
    /// The check against the mechanics, or why the line could not be read.
    pub outcome: Result<Report, Box<Diagnostic>>,
    /// The earlier lines that differ whose slip this line carries (none unless it differs
    /// and holds in the world of the lines before it).
    pub follows_from: Vec<usize>,
    /// For a line that differs and writes only quantities earlier lines wrote (it relates
    /// them again: algebra, not mechanics), the lines it should have followed from.
    pub does_not_follow: Vec<usize>,
}

impl LineCheck {
    pub fn judgement(&self) -> Judgement {
        match &self.outcome {
            Err(_) => Judgement::Error,
            Ok(_) if !self.follows_from.is_empty() => Judgement::Follows,
            Ok(r) => match r.verdict {
                Verdict::Holds => Judgement::Holds,
                Verdict::Differs => Judgement::Differs,
                Verdict::Undecided => Judgement::Undecided,
            },
        }
    }
}

/// The parts of a derivation file: runs of lines between blank lines, `#` comments and
/// trailing blanks taken off (a line that is only a comment neither counts nor separates).
pub fn parts(text: &str) -> Vec<Vec<Line>> {
    let mut parts: Vec<Vec<Line>> = vec![Vec::new()];
    for (k, raw) in text.lines().enumerate() {
        let is_comment = raw.trim_start().starts_with('#');
        let content = raw.split('#').next().unwrap_or_default().trim_end();
        if content.trim().is_empty() {
            if !is_comment && parts.last().is_some_and(|p| !p.is_empty()) {
                parts.push(Vec::new());
            }
            continue;
        }
        if let Some(part) = parts.last_mut() {
            part.push(Line {
                number: k + 1,
                text: content.to_string(),
            });
        }
    }
    parts.retain(|p| !p.is_empty());
    parts
}

/// A derivation checked: each part's lines, and what the lines give each quantity asked
/// for.
#[derive(Debug, Clone)]
pub struct DerivationCheck {
    pub parts: Vec<Vec<LineCheck>>,
    /// For each name of `asked`, what the lines give it (none when no line fixed it).
    pub asked: Vec<Option<Given>>,
}

/// Checks a derivation, line by line, in `context` ([the module](self)): its parts in
/// order, a later part taking what the earlier ones gave (part (b) uses part (a)'s result);
/// and what the lines give each name of `asked`.
pub fn check_derivation(
    context: &Context,
    source_name: &str,
    parts: &[Vec<Line>],
    asked: &[String],
) -> DerivationCheck {
    let mut world = World::new(context);
    let mut checked: Vec<Vec<LineCheck>> = Vec::with_capacity(parts.len());
    for lines in parts {
        let mut part: Vec<LineCheck> = Vec::with_capacity(lines.len());
        for line in lines {
            let earlier: Vec<&LineCheck> = checked.iter().flatten().chain(&part).collect();
            // Parsed once, the line is read in the mechanics, in the world of the earlier
            // lines and for what it gives the world.
            let syntax = ClaimSyntax::parse(source_name, &line.text);
            let c = check_line(context, &world, &earlier, line, syntax.as_ref());
            if let (Ok(syntax), true) = (&syntax, c.outcome.is_ok()) {
                world.take(line.number, syntax, &c.follows_from);
            }
            part.push(c);
        }
        checked.push(part);
    }
    DerivationCheck {
        parts: checked,
        asked: asked.iter().map(|name| world.given(name)).collect(),
    }
}

/// One line against the mechanics, and where it differs, against the earlier lines.
fn check_line(
    context: &Context,
    world: &World,
    earlier: &[&LineCheck],
    line: &Line,
    syntax: Result<&ClaimSyntax, &Diagnostic>,
) -> LineCheck {
    let outcome = syntax
        .map_err(Diagnostic::clone)
        .and_then(|syntax| check_parsed(context, syntax))
        .map_err(|mut d| {
            d.line = line.number;
            Box::new(d)
        });
    let mut c = LineCheck {
        line: line.clone(),
        outcome,
        follows_from: Vec::new(),
        does_not_follow: Vec::new(),
    };
    let differs = c
        .outcome
        .as_ref()
        .is_ok_and(|r| r.verdict == Verdict::Differs);
    if let (Ok(syntax), true) = (syntax, differs) {
        let names = names_written(context, syntax);
        c.follows_from = carried(context, world, earlier, syntax, &names);
        if c.follows_from.is_empty() && !names.is_empty() && world.all_met(&names) {
            c.does_not_follow = world.lines_under(names.iter()).into_iter().collect();
        }
    }
    c
}

/// The earlier lines that differ (not themselves carrying a slip) whose values `text` rests
/// on, when it holds in the world of the earlier lines; none when it does not.
fn carried(
    context: &Context,
    world: &World,
    earlier: &[&LineCheck],
    syntax: &ClaimSyntax,
    names: &[String],
) -> Vec<usize> {
    let values = world.values();
    if values.is_empty() {
        return Vec::new();
    }
    let slips: Vec<usize> = earlier
        .iter()
        .filter(|c| c.judgement() == Judgement::Differs)
        .map(|c| c.line.number)
        .collect();
    let under: Vec<usize> = world
        .lines_under(names.iter())
        .into_iter()
        .filter(|l| slips.contains(l))
        .collect();
    if under.is_empty() {
        return Vec::new();
    }
    let in_world = context.with_names(&values);
    match check_parsed(&in_world, syntax) {
        Ok(r) if r.verdict == Verdict::Holds => under,
        _ => Vec::new(),
    }
}

/// The derived names the line writes.
fn names_written(context: &Context, syntax: &ClaimSyntax) -> Vec<String> {
    let resolve = |name: &str| context.name(name);
    let unit = |name: &str, follows: Follows| context.unit(name, follows);
    match syntax.read(&resolve, Some(&unit)) {
        Ok(claim) => claim.resolved_names().cloned().collect(),
        Err(_) => Vec::new(),
    }
}

/// The first line that differs (a slip of its own), and the lines that carry it.
pub fn first_slip(checked: &[LineCheck]) -> Option<(&LineCheck, Vec<usize>)> {
    let first = checked
        .iter()
        .find(|c| c.judgement() == Judgement::Differs)?;
    let carrying = checked
        .iter()
        .filter(|c| c.follows_from.contains(&first.line.number))
        .map(|c| c.line.number)
        .collect();
    Some((first, carrying))
}
