//! One answer marked: its lines checked as a derivation ([`check_derivation`]), and each
//! quantity the question asks for (a step) marked by the last line that gives it,
//! `D_y = …`: full marks where it holds, the scheme's carried-forward fraction where it is
//! wrong only because it carries an earlier slip, none otherwise.

use super::scheme::Question;
use crate::check::context::Context;
use crate::check::derivation::{check_derivation, first_slip, Judgement, Line, LineCheck};

/// A step of a question as one answer gives it.
#[derive(Debug, Clone)]
pub struct Step {
    /// The quantity the step gives.
    pub quantity: String,
    /// The answer's line that gives it (an index into [`Marked::lines`]), if any does.
    pub line: Option<usize>,
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
    /// A line differs and no reading fits.
    Unnamed,
    /// No line gives a quantity the question asks for.
    StepMissing,
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
            Slip::Unnamed => "differs (no reading fits)".into(),
            Slip::StepMissing => "a quantity asked for is not given".into(),
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
            return Some(
                match first.outcome.as_ref().ok().and_then(|r| r.reading()) {
                    Some(name) => Slip::Named(name),
                    None => Slip::Unnamed,
                },
            );
        }
        let any = |j: Judgement| self.lines.iter().any(|l| l.judgement() == j);
        if any(Judgement::Error) {
            Some(Slip::Unreadable)
        } else if self.steps.iter().any(|s| s.line.is_none()) {
            Some(Slip::StepMissing)
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
    let checked = check_derivation(context, source_name, &lines);
    let out_of = question.marks / question.gives.len() as f64;
    let steps: Vec<Step> = question
        .gives
        .iter()
        .map(|quantity| {
            let line = checked.iter().rposition(|c| gives(&c.line.text, quantity));
            let credit = match line.map(|k| checked[k].judgement()) {
                Some(Judgement::Holds) => 1.0,
                Some(Judgement::Follows) => question.carried_forward,
                _ => 0.0,
            };
            Step {
                quantity: quantity.clone(),
                line,
                marks: credit * out_of,
                out_of,
            }
        })
        .collect();
    Marked {
        marks: steps.iter().map(|s| s.marks).sum(),
        lines: checked,
        steps,
    }
}

/// Whether `line` gives `quantity`: its left side is the name alone (`D_y = …`; in
/// `D_y L = Hdot_z` Ḣ_z is used, not given).
fn gives(line: &str, quantity: &str) -> bool {
    line.split_once('=')
        .is_some_and(|(left, _)| left.trim() == quantity)
}
