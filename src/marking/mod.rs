//! Marking a class: a scheme's questions, a CSV of the students' answers, each answer checked
//! line by line with error carried forward ([`crate::check::derivation`]) and marked by its
//! steps; then a gradebook, each student's feedback and the class's summary.
//!
//! A row that cannot be marked (an unknown question, bytes that are not UTF-8, a broken row,
//! an answer beyond the work a check may do) is named with its CSV line and student, marked 0
//! where it belongs to a question, and never stops the marking.

pub mod answer;
pub mod document;
pub mod feedback;
pub mod grades;
pub mod scheme;
pub mod submissions;
pub mod summary;

use crate::algebra::work::Budget;
use crate::check::context::Context;
use answer::{mark_answer, Marked};
use rayon::prelude::*;
use scheme::Scheme;
use submissions::{BadRow, Submission};

/// One student's answer to one question.
#[derive(Debug, Clone)]
pub enum Answer {
    /// No row gives one.
    Missing,
    /// The row could not be marked: why (its [`BadRow`] is among the class's).
    Unmarked { line: usize, why: String },
    /// The answer as written, its CSV line and its marks.
    Marked {
        line: usize,
        text: String,
        marked: Box<Marked>,
    },
}

impl Answer {
    pub fn marks(&self) -> f64 {
        match self {
            Answer::Marked { marked, .. } => marked.marks,
            _ => 0.0,
        }
    }
}

/// A class marked: the students in the order first met, each one's answers (one per
/// question, in the scheme's order), and the rows that could not be marked.
#[derive(Debug, Clone)]
pub struct Class {
    pub students: Vec<String>,
    pub answers: Vec<Vec<Answer>>,
    pub bad_rows: Vec<BadRow>,
}

impl Class {
    /// A student's total.
    pub fn total(&self, student: usize) -> f64 {
        self.answers[student].iter().map(Answer::marks).sum()
    }
}

/// The rows `answers` marked: the index of each student in the order first met.
fn students_of(answers: &[Submission], bad: &[BadRow]) -> Vec<String> {
    let mut students: Vec<String> = Vec::new();
    let named = answers.iter().map(|a| (a.line, &a.student)).chain(
        bad.iter()
            .filter_map(|b| Some((b.line, b.student.as_ref()?))),
    );
    let mut named: Vec<(usize, &String)> = named.collect();
    named.sort_by_key(|(line, _)| *line);
    for (_, s) in named {
        if !students.contains(s) {
            students.push(s.clone());
        }
    }
    students
}

/// Marks every answer of `submissions` to `scheme`'s questions, each in its context
/// (`contexts[k]` for question k) within its own work budget, reporting the fraction done
/// to `progress`. `bad_rows` (those the CSV reader found) are kept and added to.
pub fn mark_class(
    scheme: &Scheme,
    contexts: &[Context],
    submissions: &[Submission],
    mut bad_rows: Vec<BadRow>,
    progress: &mut dyn FnMut(f64),
) -> Class {
    let students = students_of(submissions, &bad_rows);
    let student_index = |name: &str| students.iter().position(|s| s == name);
    let mut answers: Vec<Vec<Answer>> =
        vec![vec![Answer::Missing; scheme.questions.len()]; students.len()];
    // Each (student, question) marks its last row; an earlier one is named.
    let mut latest: Vec<Vec<Option<&Submission>>> =
        vec![vec![None; scheme.questions.len()]; students.len()];
    for s in submissions {
        let Some(q) = scheme.question(&s.question) else {
            bad_rows.push(s.bad(format!(
                "the scheme has no question {:?} (its questions: {})",
                s.question,
                question_ids(scheme)
            )));
            continue;
        };
        let k = student_index(&s.student).expect("every student of a row is listed");
        if let Some(earlier) = latest[k][q].replace(s) {
            bad_rows.push(earlier.bad(format!(
                "answered again at line {}: the last answer is marked",
                s.line
            )));
        }
    }
    for b in &bad_rows {
        let (Some(student), Some(question)) = (&b.student, &b.question) else {
            continue;
        };
        let (Some(k), Some(q)) = (student_index(student), scheme.question(question)) else {
            continue;
        };
        if latest[k][q].is_none() {
            answers[k][q] = Answer::Unmarked {
                line: b.line,
                why: b.why.clone(),
            };
        }
    }
    let work: Vec<(usize, usize, &Submission)> = latest
        .iter()
        .enumerate()
        .flat_map(|(k, row)| {
            row.iter()
                .enumerate()
                .filter_map(move |(q, s)| Some((k, q, (*s)?)))
        })
        .collect();
    // In chunks, so that the progress is told between them.
    let chunk = (work.len() / 50).max(16);
    let total = work.len().max(1);
    let mut done = 0;
    for part in work.chunks(chunk) {
        let marked: Vec<(usize, usize, Answer)> = part
            .par_iter()
            .map(|&(k, q, s)| {
                let question = &scheme.questions[q];
                let label = format!("answer to {}", s.question);
                let budget = Budget::for_input(s.answer.len());
                let answer =
                    match budget.run(|| mark_answer(question, &contexts[q], &label, &s.answer)) {
                        Ok((marked, _)) => Answer::Marked {
                            line: s.line,
                            text: s.answer.clone(),
                            marked: Box::new(marked),
                        },
                        Err(e) => Answer::Unmarked {
                            line: s.line,
                            why: format!("the answer is beyond what a check may do: {e}"),
                        },
                    };
                (k, q, answer)
            })
            .collect();
        for (k, q, answer) in marked {
            let why = match &answer {
                Answer::Unmarked { line, why } => Some((*line, why.clone())),
                Answer::Marked { line, marked, .. } => marked.unreadable().map(|why| (*line, why)),
                Answer::Missing => None,
            };
            if let Some((line, why)) = why {
                bad_rows.push(BadRow {
                    line,
                    student: Some(students[k].clone()),
                    question: Some(scheme.questions[q].id.clone()),
                    why,
                });
            }
            answers[k][q] = answer;
        }
        done += part.len();
        progress(done as f64 / total as f64);
    }
    bad_rows.sort_by_key(|b| b.line);
    Class {
        students,
        answers,
        bad_rows,
    }
}

/// `Q1, Q2, Q3`.
fn question_ids(scheme: &Scheme) -> String {
    scheme
        .questions
        .iter()
        .map(|q| q.id.as_str())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Marks as a person writes them: `2`, `1.5`, `0.67`.
pub fn marks_text(marks: f64) -> String {
    let rounded = (marks * 100.0).round() / 100.0;
    let text = format!("{rounded:.2}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}
