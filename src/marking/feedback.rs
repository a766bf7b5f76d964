//! A student's feedback: for each question their answer, each line's verdict (a line that
//! carries an earlier slip says so), the slip in words and in the checker's mathematics, the
//! instructor's words for it, and the marks of each step.

use super::answer::Marked;
use super::document::{Block, Document, Inline};
use super::scheme::{Question, Scheme};
use super::{marks_text, Answer, Class};
use crate::check::context::Context;
use crate::check::derivation::report::line_list;
use crate::check::derivation::{Judgement, LineCheck};
use crate::check::report;

/// The feedback page of student `k`.
pub fn feedback(
    scheme: &Scheme,
    contexts: &[Context],
    class: &Class,
    k: usize,
    submissions_name: &str,
) -> Document {
    let student = &class.students[k];
    let out_of: f64 = scheme.questions.iter().map(|q| q.marks).sum();
    let mut blocks = vec![Block::Paragraph(vec![
        Inline::Text("Total: ".into()),
        Inline::Strong(format!(
            "{} / {}",
            marks_text(class.total(k)),
            marks_text(out_of)
        )),
    ])];
    for (q, question) in scheme.questions.iter().enumerate() {
        let answer = &class.answers[k][q];
        blocks.push(Block::Heading(
            1,
            format!(
                "{}: {} / {}",
                question.id,
                marks_text(answer.marks()),
                marks_text(question.marks)
            ),
        ));
        match answer {
            Answer::Missing => blocks.push(Block::Paragraph(vec![Inline::Text(format!(
                "No answer: {} has no row for {}.",
                submissions_name, question.id
            ))])),
            Answer::Unmarked { line, why } => {
                blocks.push(Block::Paragraph(vec![Inline::Text(format!(
                    "Your answer (line {line} of {submissions_name}) could not be marked: {why}."
                ))]))
            }
            Answer::Marked { line, text, marked } => {
                blocks.push(Block::Paragraph(vec![Inline::Text(format!(
                    "Your answer (line {line} of {submissions_name}):"
                ))]));
                blocks.push(Block::Preformatted(text.clone()));
                blocks.extend(marked_blocks(question, &contexts[q], marked));
            }
        }
    }
    Document {
        title: format!("Feedback: {student}"),
        blocks,
    }
}

/// A line's verdict in words for the table.
fn verdict(c: &LineCheck) -> Vec<Inline> {
    match c.judgement() {
        Judgement::Holds => vec![Inline::Text("holds".into())],
        Judgement::Follows => vec![Inline::Text(format!(
            "right from {}, which differs: it carries that slip",
            line_list(&c.follows_from)
        ))],
        Judgement::Differs => {
            let reading = c.outcome.as_ref().ok().and_then(|r| r.reading());
            let mut v = vec![Inline::Strong("differs".into())];
            if let Some(name) = reading {
                v.push(Inline::Text(format!(" ({name})")));
            }
            v
        }
        Judgement::Undecided => vec![Inline::Text(
            "undecided: the checker cannot tell; ask your instructor".into(),
        )],
        Judgement::Error => vec![Inline::Strong("could not be read".into())],
    }
}

/// The blocks of a marked answer: its lines, its steps, and each wrong line's report.
fn marked_blocks(question: &Question, context: &Context, marked: &Marked) -> Vec<Block> {
    let mut blocks = Vec::new();
    let rows = marked
        .lines
        .iter()
        .map(|c| {
            vec![
                vec![Inline::Text(c.line.number.to_string())],
                vec![Inline::Code(c.line.text.clone())],
                verdict(c),
            ]
        })
        .collect();
    blocks.push(Block::Table {
        header: vec!["line".into(), "as checked".into(), "verdict".into()],
        rows,
    });
    let step_rows = marked
        .steps
        .iter()
        .map(|s| {
            let given = match s.line {
                Some(k) => {
                    let c = &marked.lines[k];
                    let how = match c.judgement() {
                        Judgement::Follows => format!(
                            " (carries the slip of {}: {} of the marks)",
                            line_list(&c.follows_from),
                            marks_text(question.carried_forward * 100.0) + " %"
                        ),
                        j => format!(" ({})", j.word()),
                    };
                    format!("line {}{how}", c.line.number)
                }
                None => format!("no line {} = …", s.quantity),
            };
            vec![
                vec![Inline::Code(s.quantity.clone())],
                vec![Inline::Text(given)],
                vec![Inline::Text(format!(
                    "{} / {}",
                    marks_text(s.marks),
                    marks_text(s.out_of)
                ))],
            ]
        })
        .collect();
    blocks.push(Block::Table {
        header: vec!["asked for".into(), "given by".into(), "marks".into()],
        rows: step_rows,
    });
    for c in &marked.lines {
        match (&c.outcome, c.judgement()) {
            (Ok(r), Judgement::Differs | Judgement::Undecided) => {
                blocks.push(Block::Heading(2, format!("Line {}", c.line.number)));
                blocks.push(Block::Preformatted(report::text(
                    r,
                    &format!("line {}", c.line.number),
                    context.domains(),
                )));
                if let Some(words) = r.reading().and_then(|name| question.feedback.get(name)) {
                    blocks.push(Block::Quote(format!("Your instructor: {words}")));
                }
            }
            (Err(d), _) => {
                blocks.push(Block::Heading(2, format!("Line {}", c.line.number)));
                blocks.push(Block::Preformatted(d.render()));
            }
            _ => {}
        }
    }
    if let Some(missing) = marked.steps.iter().find(|s| s.line.is_none()) {
        blocks.push(Block::Paragraph(vec![
            Inline::Text("No line gives ".into()),
            Inline::Code(missing.quantity.clone()),
            Inline::Text(": end the answer with a line ".into()),
            Inline::Code(format!("{} = …", missing.quantity)),
            Inline::Text(".".into()),
        ]));
    }
    blocks
}

/// A file name for a student's feedback: letters, digits, `-`, `_` and `.` kept, others `_`;
/// never empty or hidden.
pub fn file_stem(student: &str) -> String {
    let stem: String = student
        .chars()
        .map(|c| match c.is_ascii_alphanumeric() || "-_.".contains(c) {
            true => c,
            false => '_',
        })
        .take(80)
        .collect();
    match stem.trim_start_matches('.') {
        "" => "student".into(),
        s => s.to_string(),
    }
}
