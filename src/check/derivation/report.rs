//! A derivation's check as a person reads it: each line's verdict (a line that carries an
//! earlier slip says which line it follows from), then for each part the first wrong line,
//! its slip and the lines that carry it. In text and JSON.

use super::{first_slip, Judgement, LineCheck};
use crate::algebra::Domains;
use crate::check::forms::Forms;
use crate::check::report;
use crate::print::{markup, Notation};
use serde_json::{json, Value as Json};

/// `lines 3, 4 and 5`, `line 2`.
pub fn line_list(lines: &[usize]) -> String {
    let numbers: Vec<String> = lines.iter().map(ToString::to_string).collect();
    match numbers.as_slice() {
        [] => String::new(),
        [one] => format!("line {one}"),
        [init @ .., last] => format!("lines {} and {last}", init.join(", ")),
    }
}

/// The part's report in text.
pub fn text(checked: &[LineCheck], source_name: &str, domains: &Domains) -> String {
    let forms = Forms::new(domains);
    let mut out = String::new();
    for c in checked {
        let label = format!("{source_name}:{}", c.line.number);
        match (&c.outcome, c.judgement()) {
            (Err(d), _) => out.push_str(&format!(
                "error ({label}): {}\n  {}\n",
                c.line.text, d.message
            )),
            (Ok(r), Judgement::Follows) => {
                let from = line_list(&c.follows_from);
                out.push_str(&format!("follows from {from} ({label}): {}\n", c.line.text));
                out.push_str(&format!(
                    "  right from {from}, which differs: it carries that slip, and is otherwise correct\n"
                ));
                for form in report::correct_forms(r, Notation::Text, &forms) {
                    out.push_str(&format!("  {form}\n"));
                }
            }
            (Ok(r), _) => {
                let text = report::text(r, &label, &forms);
                let (head, rest) = text.split_once('\n').unwrap_or((&text, ""));
                out.push_str(head);
                out.push('\n');
                if let Some(words) = algebra_words(c) {
                    out.push_str(&format!("  {words}\n"));
                }
                out.push_str(rest);
            }
        }
    }
    out.push_str(&summary(checked));
    out.push('\n');
    out
}

/// The part's report in LaTeX: a paragraph a line (a carried line says which line it
/// follows from and gives the correct form), then the summary as a comment.
pub fn latex(checked: &[LineCheck], source_name: &str, domains: &Domains) -> String {
    let forms = Forms::new(domains);
    let mut out = String::new();
    for c in checked {
        let label = format!("{source_name}:{}", c.line.number);
        let (label_tex, text_tex) = (
            markup::latex_words(&label),
            markup::latex_words(&c.line.text),
        );
        match (&c.outcome, c.judgement()) {
            (Err(d), _) => out.push_str(&format!(
                "\\paragraph{{{label_tex} error.}} \\texttt{{{text_tex}}}: {}.\n",
                markup::latex_words(&d.message)
            )),
            (Ok(r), Judgement::Follows) => {
                let from = line_list(&c.follows_from);
                out.push_str(&format!(
                    "\\paragraph{{{label_tex} follows from {from}.}} \\texttt{{{text_tex}}}\nRight from {from}, which differs: it carries that slip, and is otherwise correct.\n"
                ));
                for form in report::correct_forms(r, Notation::Latex, &forms) {
                    out.push_str(&format!("{form}.\n"));
                }
            }
            (Ok(r), _) => {
                out.push_str(&report::latex(r, &label, &forms));
                if let Some(words) = algebra_words(c) {
                    out.push_str(&format!("{}.\n", markup::latex_words(&words)));
                }
            }
        }
    }
    out.push_str(&format!("% {}\n", summary(checked)));
    out
}

/// For a line that differs and only relates quantities earlier lines gave: `it does not
/// follow from line 1: a slip in the algebra, …`.
pub fn algebra_words(c: &LineCheck) -> Option<String> {
    if c.does_not_follow.is_empty() {
        return None;
    }
    let lines = line_list(&c.does_not_follow);
    Some(format!(
        "it does not follow from {lines}: a slip in the algebra (the quantities it relates are {lines}'s), read against the mechanics below"
    ))
}

/// `first wrong line: 2 (sign-flipped); lines 3, 4 and 5 carry it`, or `every line holds`.
pub fn summary(checked: &[LineCheck]) -> String {
    let (Some(first), Some(last)) = (checked.first(), checked.last()) else {
        return String::new();
    };
    let span = format!("lines {}-{}", first.line.number, last.line.number);
    match first_slip(checked) {
        Some((slip, carrying)) => {
            let reading = match slip.does_not_follow.is_empty() {
                false => Some(format!(
                    "does not follow from {}",
                    line_list(&slip.does_not_follow)
                )),
                true => slip
                    .outcome
                    .as_ref()
                    .ok()
                    .and_then(|r| r.reading())
                    .map(String::from),
            }
            .map(|r| format!(" ({r})"))
            .unwrap_or_default();
            let carried = match carrying.len() {
                0 => "no later line carries it".to_string(),
                1 => format!("{} carries it", line_list(&carrying)),
                _ => format!("{} carry it", line_list(&carrying)),
            };
            format!(
                "{span}: first wrong line {}{reading}; {carried}",
                slip.line.number
            )
        }
        None if checked.iter().any(|c| c.judgement() == Judgement::Follows) => {
            let carrying: Vec<usize> = checked
                .iter()
                .filter(|c| c.judgement() == Judgement::Follows)
                .map(|c| c.line.number)
                .collect();
            let mut from: Vec<usize> = checked
                .iter()
                .flat_map(|c| c.follows_from.clone())
                .collect();
            from.sort_unstable();
            from.dedup();
            format!(
                "{span}: no slip of its own; {} carrying the slip of {} before it",
                line_list(&carrying),
                line_list(&from)
            )
        }
        None if checked.iter().all(|c| c.judgement() == Judgement::Holds) => {
            format!("{span}: every line holds")
        }
        None => format!("{span}: no line differs"),
    }
}

/// The part's report as JSON: each line's check and what it follows from, and the first slip.
pub fn json(checked: &[LineCheck], domains: &Domains) -> Json {
    let forms = Forms::new(domains);
    let lines: Vec<Json> = checked
        .iter()
        .map(|c| {
            let mut j = match &c.outcome {
                Ok(r) => report::json(r, &forms),
                Err(d) => {
                    json!({"claim": c.line.text, "reading": Json::Null, "error": d.to_string()})
                }
            };
            j["line"] = c.line.number.into();
            j["verdict"] = c.judgement().word().into();
            j["follows_from"] = c.follows_from.clone().into();
            j["does_not_follow"] = c.does_not_follow.clone().into();
            j
        })
        .collect();
    let slip = first_slip(checked).map(|(first, carrying)| {
        json!({"line": first.line.number,
               "reading": first.outcome.as_ref().ok().and_then(|r| r.reading()),
               "carried_by": carrying})
    });
    json!({"lines": lines, "first_slip": slip})
}
