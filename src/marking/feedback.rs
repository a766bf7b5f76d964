//! A student's feedback: for each question their answer, each line's verdict (a line that
//! carries an earlier slip says so), the slip in words and in the checker's mathematics, the
//! instructor's words for it, and the marks of each step.

use super::answer::{Marked, Standing, Step};
use super::document::{Block, Document, Inline};
use super::scheme::{Question, Scheme};
use super::{marks_text, Answer, Class};
use crate::check::derivation::report::{algebra_words, line_list};
use crate::check::derivation::{Judgement, LineCheck};
use crate::check::forms::Forms;
use crate::check::report;

/// The feedback page of student `k`; `forms` are those of each question's context, shared
/// by the whole class (its students' wrong lines meet the same correct forms).
pub fn feedback(
    scheme: &Scheme,
    forms: &[Forms],
    class: &Class,
    k: usize,
    submissions_name: &str,
) -> Document {
    let student = &class.students[k];
    // The file's name, not where the instructor keeps it.
    let submissions_name = std::path::Path::new(submissions_name)
        .file_name()
        .map_or(submissions_name.into(), |f| f.to_string_lossy());
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
                blocks.extend(marked_blocks(question, &forms[q], marked));
            }
        }
    }
    Document {
        title: format!("Feedback: {student}"),
        blocks,
    }
}

/// `right from line 2, which differs: it carries that slip`, or for several lines `…
/// which differ: it carries their slips`.
fn carries(lines: &[usize]) -> String {
    match lines.len() {
        1 => format!(
            "right from {}, which differs: it carries that slip",
            line_list(lines)
        ),
        _ => format!(
            "right from {}, which differ: it carries their slips",
            line_list(lines)
        ),
    }
}

/// A line's verdict in words for the table.
fn verdict(c: &LineCheck) -> Vec<Inline> {
    match c.judgement() {
        Judgement::Holds => vec![Inline::Text("holds".into())],
        Judgement::Follows => vec![Inline::Text(carries(&c.follows_from))],
        Judgement::Differs => {
            let mut v = vec![Inline::Strong("differs".into())];
            if !c.does_not_follow.is_empty() {
                v.push(Inline::Text(format!(
                    ": it does not follow from {} (a slip in the algebra)",
                    line_list(&c.does_not_follow)
                )));
            } else if let Some(name) = c.outcome.as_ref().ok().and_then(|r| r.reading()) {
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

/// How a step was marked, in words: the line stating it and why its marks are what they are.
fn step_words(question: &Question, marked: &Marked, step: &Step) -> String {
    let line = step.line.map(|k| marked.lines[k].line.number);
    let at = |words: &str| match line {
        Some(n) => format!("line {n}: {words}"),
        None => words.to_string(),
    };
    match &step.standing {
        Standing::Right => at("right"),
        Standing::Carried(slips) => at(&format!(
            "{} ({} % of the marks)",
            carries(slips),
            marks_text(question.carried_forward * 100.0)
        )),
        Standing::Wrong => at(
            match line.map(|_| marked.lines[step.line.unwrap_or(0)].judgement()) {
                Some(Judgement::Error) => "could not be read",
                Some(Judgement::Undecided) => "undecided",
                _ => "a slip of its own",
            },
        ),
        Standing::Missing if line.is_some() => at("does not fix its value"),
        Standing::Missing => format!("no line {} = …", step.quantity),
        Standing::LeftIn(names) => at(&format!(
            "left in {}: give it in the givens",
            names.join(", ")
        )),
    }
}

/// The blocks of a marked answer: its lines, its steps, and each wrong line's report.
fn marked_blocks(question: &Question, forms: &Forms, marked: &Marked) -> Vec<Block> {
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
            vec![
                vec![Inline::Code(s.quantity.clone())],
                vec![Inline::Text(step_words(question, marked, s))],
                vec![Inline::Text(format!(
                    "{} / {}",
                    marks_text(s.marks),
                    marks_text(s.out_of)
                ))],
            ]
        })
        .collect();
    blocks.push(Block::Table {
        header: vec![
            "asked for".into(),
            "your answer gives it".into(),
            "marks".into(),
        ],
        rows: step_rows,
    });
    for c in &marked.lines {
        match (&c.outcome, c.judgement()) {
            (Ok(r), Judgement::Differs | Judgement::Undecided) => {
                blocks.push(Block::Heading(2, format!("Line {}", c.line.number)));
                if let Some(words) = algebra_words(c) {
                    blocks.push(Block::Paragraph(vec![Inline::Text(words)]));
                }
                blocks.push(Block::Preformatted(report::text(
                    r,
                    &format!("line {}", c.line.number),
                    forms,
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
            Inline::Text(": state it on a line of its own, ".into()),
            Inline::Code(format!("{} = …", missing.quantity)),
            Inline::Text(", the last such line being your answer.".into()),
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
