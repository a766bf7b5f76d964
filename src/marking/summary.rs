//! The class's summary, the instructor's view of what to teach again: for each question the
//! distribution of marks and the slips ranked by how many students made them, each with an
//! anonymised example (the wrong line as written, no name) and how many carried it into
//! later lines; then the rows that could not be marked.

use super::answer::Slip;
use super::document::{words_and_code, Block, Document, Inline};
use super::scheme::Scheme;
use super::{marks_text, Answer, Class};
use crate::check::derivation::first_slip;
use std::collections::BTreeMap;

/// One slip of a question: how many students made it, how many of them carried it into a
/// later line, and the first example met.
#[derive(Debug, Clone, PartialEq)]
pub struct SlipCount {
    pub slip: Slip,
    pub students: usize,
    pub carried: usize,
    /// The first example met: the wrong line as written, and the slip in words there.
    pub example: Option<String>,
    pub words: Option<String>,
}

/// The slips of question `q`, most frequent first (ties by name).
pub fn slips(class: &Class, q: usize) -> Vec<SlipCount> {
    let mut counts: BTreeMap<Slip, SlipCount> = BTreeMap::new();
    for answers in &class.answers {
        let (slip, first) = match &answers[q] {
            Answer::Marked { marked, .. } => match marked.slip() {
                Some(slip) => (slip, first_slip(&marked.lines)),
                None => continue,
            },
            Answer::Missing | Answer::Unmarked { .. } => (Slip::NoAnswer, None),
        };
        let entry = counts.entry(slip.clone()).or_insert(SlipCount {
            slip,
            students: 0,
            carried: 0,
            example: None,
            words: None,
        });
        entry.students += 1;
        if let Some((line, carrying)) = first {
            entry.carried += usize::from(!carrying.is_empty());
            if entry.example.is_none() {
                entry.example = Some(line.line.text.clone());
                entry.words = line.outcome.as_ref().ok().and_then(|r| r.reading_words());
            }
        }
    }
    let mut ranked: Vec<SlipCount> = counts.into_values().collect();
    ranked.sort_by(|a, b| b.students.cmp(&a.students).then(a.slip.cmp(&b.slip)));
    ranked
}

/// `6 (20 %)`: a count of students and its share of the class.
fn share(count: usize, of: usize) -> String {
    format!("{count} ({:.0} %)", 100.0 * count as f64 / of.max(1) as f64)
}

/// The slips of every question together, most answers first: what to teach again across
/// the assignment (a slip in three questions is one lesson), with the questions it was in.
fn across_the_class(scheme: &Scheme, per_question: &[Vec<SlipCount>], n: usize) -> Vec<Block> {
    let mut totals: BTreeMap<Slip, (usize, Vec<String>)> = BTreeMap::new();
    for (question, ranked) in scheme.questions.iter().zip(per_question) {
        for s in ranked.iter().filter(|s| s.slip != Slip::NoAnswer) {
            let entry = totals.entry(s.slip.clone()).or_default();
            entry.0 += s.students;
            entry.1.push(format!("{} ({})", question.id, s.students));
        }
    }
    if totals.is_empty() {
        return Vec::new();
    }
    let mut ranked: Vec<(Slip, (usize, Vec<String>))> = totals.into_iter().collect();
    ranked.sort_by(|a, b| b.1 .0.cmp(&a.1 .0).then(a.0.cmp(&b.0)));
    let answers = n * scheme.questions.len();
    vec![
        Block::Heading(1, "Across the class".into()),
        Block::Table {
            header: vec!["slip".into(), "answers".into(), "in".into()],
            rows: ranked
                .into_iter()
                .map(|(slip, (count, questions))| {
                    vec![
                        vec![Inline::Strong(slip.words())],
                        vec![Inline::Text(share(count, answers))],
                        vec![Inline::Text(questions.join(", "))],
                    ]
                })
                .collect(),
        },
    ]
}

/// The summary page.
pub fn summary(scheme: &Scheme, class: &Class, submissions_name: &str) -> Document {
    let n = class.students.len();
    let out_of: f64 = scheme.questions.iter().map(|q| q.marks).sum();
    let mean = |marks: &mut dyn Iterator<Item = f64>| marks.sum::<f64>() / n.max(1) as f64;
    let mut blocks = vec![Block::Paragraph(vec![Inline::Text(format!(
        "{n} students, {} questions, from {submissions_name}. Mean total {} of {}.",
        scheme.questions.len(),
        marks_text(mean(&mut (0..n).map(|k| class.total(k)))),
        marks_text(out_of)
    ))])];
    let per_question: Vec<Vec<SlipCount>> = (0..scheme.questions.len())
        .map(|q| slips(class, q))
        .collect();
    blocks.extend(across_the_class(scheme, &per_question, n));
    for (q, question) in scheme.questions.iter().enumerate() {
        let marks: Vec<f64> = class.answers.iter().map(|a| a[q].marks()).collect();
        blocks.push(Block::Heading(
            1,
            format!(
                "{} ({} marks): mean {}",
                question.id,
                marks_text(question.marks),
                marks_text(mean(&mut marks.iter().copied()))
            ),
        ));
        let mut distribution: BTreeMap<String, (f64, usize)> = BTreeMap::new();
        for m in &marks {
            distribution.entry(marks_text(*m)).or_insert((*m, 0)).1 += 1;
        }
        let mut distribution: Vec<(f64, usize)> = distribution.into_values().collect();
        distribution.sort_by(|a, b| b.0.total_cmp(&a.0));
        blocks.push(Block::Table {
            header: vec!["marks".into(), "students".into(), String::new()],
            rows: distribution
                .iter()
                .map(|(m, count)| {
                    vec![
                        vec![Inline::Text(marks_text(*m))],
                        vec![Inline::Text(count.to_string())],
                        vec![Inline::Text("█".repeat(*count))],
                    ]
                })
                .collect(),
        });
        let ranked = &per_question[q];
        if ranked.is_empty() {
            blocks.push(Block::Paragraph(vec![Inline::Text(
                "No slip: every answer marked holds.".into(),
            )]));
            continue;
        }
        let rows = ranked
            .iter()
            .map(|s| {
                let words = match &s.slip {
                    Slip::Named(name) => question.feedback.get(*name).cloned(),
                    _ => None,
                };
                let mut example: Vec<Inline> =
                    s.example.clone().map(Inline::Code).into_iter().collect();
                if let Some(w) = &s.words {
                    example.push(Inline::Text(": ".into()));
                    example.extend(words_and_code(w));
                }
                vec![
                    vec![Inline::Strong(s.slip.words())],
                    vec![Inline::Text(share(s.students, n))],
                    vec![Inline::Text(s.carried.to_string())],
                    example,
                    vec![Inline::Text(words.unwrap_or_default())],
                ]
            })
            .collect();
        blocks.push(Block::Table {
            header: vec![
                "slip".into(),
                "students".into(),
                "carried into later lines".into(),
                "example, and the slip in it".into(),
                "your words".into(),
            ],
            rows,
        });
    }
    if !class.bad_rows.is_empty() {
        blocks.push(Block::Heading(1, "Rows not marked".into()));
        blocks.push(Block::Table {
            header: vec![
                "line".into(),
                "student".into(),
                "question".into(),
                "why".into(),
            ],
            rows: class
                .bad_rows
                .iter()
                .map(|b| {
                    vec![
                        vec![Inline::Text(b.line.to_string())],
                        vec![Inline::Text(b.student.clone().unwrap_or_default())],
                        vec![Inline::Text(b.question.clone().unwrap_or_default())],
                        vec![Inline::Text(b.why.clone())],
                    ]
                })
                .collect(),
        });
    }
    Document {
        title: "Marking summary".into(),
        blocks,
    }
}
