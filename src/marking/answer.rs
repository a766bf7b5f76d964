//! One answer marked: its lines checked as a derivation ([`check_derivation`]), and each
//! quantity the question asks for (a step) marked by what the answer gives it: the value
//! its lines, taken as true, fix for the quantity, stated by its last line `D_y = …`.
//!
//! - full marks where that value is the mechanics' own, in the givens (and the names the
//!   scheme lets an answer leave, `may_use`);
//! - the scheme's carried-forward fraction where the value is wrong only because it rests
//!   on an earlier wrong line (the last line holds as a relation, or follows from it);
//! - none where the last line has a slip of its own, where no line states the quantity, or
//!   where its value is left in another quantity (`T_BC = T_BC`, `M_x = Hdot_x - m g c`).

use super::scheme::Question;
use crate::check::context::Context;
use crate::check::derivation::{check_derivation, first_slip, Given, Judgement, Line, LineCheck};

/// How a step stands in an answer.
#[derive(Debug, Clone, PartialEq)]
pub enum Standing {
    /// The value is the mechanics' own.
    Right,
    /// Wrong only because it carries the slip of these earlier lines.
    Carried(Vec<usize>),
    /// The line stating it has a slip of its own (or cannot be read, or is undecided).
    Wrong,
    /// No line states it (`NAME = …`), or none fixes its value.
    Missing,
    /// Its value is left in these derived quantities.
    LeftIn(Vec<String>),
}

/// A step of a question as one answer gives it.
#[derive(Debug, Clone)]
pub struct Step {
    /// The quantity the step gives.
    pub quantity: String,
    /// The answer's last line stating it (an index into [`Marked::lines`]), if any does.
    pub line: Option<usize>,
    pub standing: Standing,
    pub marks: f64,
    pub out_of: f64,
}

/// An answer and its marks.
#[derive(Debug, Clone)]
pub struct Marked {
    /// Each line of the answer checked (numbered from 1 within the answer).
    pub lines: Vec<LineCheck>,
    pub steps: Vec<Step>,
    pub marks: f64,
}

/// What an answer's first slip is, for the class summary.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Slip {
    /// A named slip (`sign-flipped`, `omega-for-Omega`, …).
    Named(&'static str),
    /// A line that relates quantities earlier lines gave, and does not follow from them.
    Algebra,
    /// A line differs and no reading fits.
    Unnamed,
    /// No line gives a quantity the question asks for.
    StepMissing,
    /// A quantity left in another quantity, not in the givens.
    LeftIn,
    /// A line could not be read.
    Unreadable,
    /// A line the checker could not decide (to look at by hand).
    Undecided,
    /// No answer, or a row that could not be marked.
    NoAnswer,
}

impl Slip {
    /// The slip in words, for a summary's table.
    pub fn words(&self) -> String {
        match self {
            Slip::Named(name) => (*name).to_string(),
            Slip::Algebra => "algebra: a line does not follow from the lines before it".into(),
            Slip::Unnamed => "differs (no reading fits)".into(),
            Slip::StepMissing => "a quantity asked for is not given".into(),
            Slip::LeftIn => "a quantity left in another, not in the givens".into(),
            Slip::Unreadable => "a line could not be read".into(),
            Slip::Undecided => "undecided (look by hand)".into(),
            Slip::NoAnswer => "no answer marked".into(),
        }
    }
}

impl Marked {
    /// Why a line of the answer could not be read (the first such line), if one could not:
    /// the row is named with the class's bad rows, its readable lines still marked.
    pub fn unreadable(&self) -> Option<String> {
        self.lines.iter().find_map(|c| {
            let d = c.outcome.as_ref().err()?;
            Some(format!(
                "line {} of the answer cannot be read: {}",
                c.line.number, d.message
            ))
        })
    }

    /// The answer's first slip, if it lost marks or holds a wrong line.
    pub fn slip(&self) -> Option<Slip> {
        if let Some((first, _)) = first_slip(&self.lines) {
            if !first.does_not_follow.is_empty() {
                return Some(Slip::Algebra);
            }
            return Some(
                match first.outcome.as_ref().ok().and_then(|r| r.reading()) {
                    Some(name) => Slip::Named(name),
                    None => Slip::Unnamed,
                },
            );
        }
        let any = |j: Judgement| self.lines.iter().any(|l| l.judgement() == j);
        let standing = |f: &dyn Fn(&Standing) -> bool| self.steps.iter().any(|s| f(&s.standing));
        if any(Judgement::Error) {
            Some(Slip::Unreadable)
        } else if standing(&|s| matches!(s, Standing::Missing)) {
            Some(Slip::StepMissing)
        } else if standing(&|s| matches!(s, Standing::LeftIn(_))) {
            Some(Slip::LeftIn)
        } else if any(Judgement::Undecided) {
            Some(Slip::Undecided)
        } else {
            None
        }
    }
}

/// Marks `answer` to `question` in `context`. A last line without `=` is the value of the
/// question's last quantity (`-129.8 N` for `D_y = -129.8 N`).
pub fn mark_answer(
    question: &Question,
    context: &Context,
    source_name: &str,
    answer: &str,
) -> Marked {
    let mut lines: Vec<Line> = answer
        .lines()
        .enumerate()
        .map(|(k, text)| (k, text.split('#').next().unwrap_or_default().trim()))
        .filter(|(_, text)| !text.is_empty())
        .map(|(k, text)| Line {
            number: k + 1,
            text: text.to_string(),
        })
        .collect();
    if let (Some(last), Some(quantity)) = (lines.last_mut(), question.gives.last()) {
        if !last.text.contains('=') {
            last.text = format!("{quantity} = {}", last.text);
        }
    }
    let mut checked = check_derivation(context, source_name, &[lines], &question.gives);
    let checked_lines = checked.parts.pop().unwrap_or_default();
    let out_of = question.marks / question.gives.len() as f64;
    let may_use: Vec<String> = question
        .may_use
        .iter()
        .map(|n| context.canonical(n))
        .collect();
    let steps: Vec<Step> = question
        .gives
        .iter()
        .zip(&checked.asked)
        .map(|(quantity, given)| {
            let line = checked_lines.iter().rposition(|c| {
                c.judgement() != Judgement::Error && states(context, &c.line.text, quantity)
            });
            let standing = standing(
                line.map(|k| &checked_lines[k]),
                given.as_ref(),
                &checked_lines,
                &may_use,
            );
            let credit = match &standing {
                Standing::Right => 1.0,
                Standing::Carried(_) => question.carried_forward,
                _ => 0.0,
            };
            Step {
                quantity: quantity.clone(),
                line,
                standing,
                marks: credit * out_of,
                out_of,
            }
        })
        .collect();
    Marked {
        marks: steps.iter().map(|s| s.marks).sum(),
        lines: checked_lines,
        steps,
    }
}

/// How a step stands: `line` the last line stating it, `given` what the lines give it.
fn standing(
    line: Option<&LineCheck>,
    given: Option<&Given>,
    lines: &[LineCheck],
    may_use: &[String],
) -> Standing {
    let (Some(line), Some(given)) = (line, given) else {
        return Standing::Missing;
    };
    if !matches!(line.judgement(), Judgement::Holds | Judgement::Follows) {
        return Standing::Wrong;
    }
    let left_in: Vec<String> = given
        .left_in
        .iter()
        .filter(|n| !may_use.contains(n))
        .cloned()
        .collect();
    if !left_in.is_empty() {
        return Standing::LeftIn(left_in);
    }
    if given.agrees {
        return Standing::Right;
    }
    let slips: Vec<usize> = lines
        .iter()
        .filter(|c| c.judgement() == Judgement::Differs && given.lines.contains(&c.line.number))
        .map(|c| c.line.number)
        .collect();
    match slips.is_empty() {
        true => Standing::Wrong,
        false => Standing::Carried(slips),
    }
}

/// Whether `line` states `quantity`: one side is the name alone or a number times it, in any
/// spelling of the quantity (`D_y = …`, `M_x = …` for `SumM_x`, `2 T = …`), and the other
/// names no derived quantity (`1857 N = T_BC` states T_BC; in `D_y L = Hdot_z` Ḣ_z is used,
/// not stated).
fn states(context: &Context, line: &str, quantity: &str) -> bool {
    let Some((left, right)) = line.split_once('=') else {
        return false;
    };
    let is_quantity = |side: &str| {
        // A number in front is a multiple of the equation (`2 T = …`), which states T too.
        let side = side
            .trim()
            .trim_start_matches(|c: char| c.is_ascii_digit() || "./ ".contains(c))
            .trim_start_matches('*')
            .trim();
        side.starts_with(|c: char| c.is_ascii_alphabetic())
            && side
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "_'".contains(c))
            && context.canonical(side) == context.canonical(quantity)
    };
    let names_derived = |side: &str| {
        side.split(|c: char| !(c.is_ascii_alphanumeric() || "_'".contains(c)))
            .filter(|w| w.starts_with(|c: char| c.is_ascii_alphabetic()))
            .any(|w| context.derived_scalar(w).is_some())
    };
    is_quantity(left) || is_quantity(right) && !names_derived(left)
}
