//! A class's submissions: a CSV with the header `student,question,answer` (in any order,
//! any case), UTF-8, as a learning system or a form exports it; an answer may span lines in
//! a quoted field. A row that cannot be read is a [`BadRow`] naming its line and student,
//! and the reading goes on.

use crate::visible::escaped as visible;

/// One answer of one student, and the line of the CSV its row starts on.
#[derive(Debug, Clone, PartialEq)]
pub struct Submission {
    pub line: usize,
    pub student: String,
    pub question: String,
    pub answer: String,
}

/// A row that is not an answer to mark: its line, its student and question where they
/// could be read, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct BadRow {
    pub line: usize,
    pub student: Option<String>,
    pub question: Option<String>,
    pub why: String,
}

/// The columns a submissions file must have.
const COLUMNS: [&str; 3] = ["student", "question", "answer"];

/// Reads the submissions in `bytes`: the answers, and the rows that are not answers. A file
/// whose header lacks a column is an error saying which.
pub fn read_submissions(bytes: &[u8]) -> Result<(Vec<Submission>, Vec<BadRow>), String> {
    let bytes = bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes);
    let mut reader = csv::ReaderBuilder::new().flexible(true).from_reader(bytes);
    let header = reader
        .byte_headers()
        .map_err(|e| format!("the header cannot be read: {e}"))?
        .clone();
    let column = |name: &str| {
        header
            .iter()
            .position(|h| String::from_utf8_lossy(h).trim().eq_ignore_ascii_case(name))
    };
    let found: Vec<Option<usize>> = COLUMNS.iter().map(|c| column(c)).collect();
    let [Some(student), Some(question), Some(answer)] = found[..] else {
        let missing: Vec<&str> = COLUMNS
            .iter()
            .zip(&found)
            .filter(|(_, f)| f.is_none())
            .map(|(c, _)| *c)
            .collect();
        return Err(format!(
            "the header (line 1) has no column {}: it must name student, question and answer",
            missing.join(", ")
        ));
    };
    let mut answers = Vec::new();
    let mut bad = Vec::new();
    for record in reader.byte_records() {
        let record = match record {
            Ok(r) => r,
            Err(e) => {
                let line = e.position().map_or(0, |p| p.line() as usize);
                bad.push(BadRow {
                    line,
                    student: None,
                    question: None,
                    why: format!("the row cannot be read: {e}"),
                });
                continue;
            }
        };
        let line = record.position().map_or(0, |p| p.line() as usize);
        // A field as read, when it is UTF-8 and not blank (a name to attach the row to).
        let exact = |k: usize| {
            record
                .get(k)
                .and_then(|f| std::str::from_utf8(f).ok())
                .map(|f| f.trim().to_string())
                .filter(|f| !f.is_empty())
        };
        let row_error = |why: String| BadRow {
            line,
            student: exact(student),
            question: exact(question),
            why,
        };
        if record.iter().all(|f| f.iter().all(u8::is_ascii_whitespace)) {
            continue;
        }
        if record.len() != header.len() {
            bad.push(row_error(format!(
                "the row has {} fields where the header has {}",
                record.len(),
                header.len()
            )));
            continue;
        }
        let text = |k: usize, name: &str| -> Result<String, String> {
            let field = record.get(k).unwrap_or_default();
            std::str::from_utf8(field).map(str::to_string).map_err(|e| {
                let at = e.valid_up_to();
                format!(
                    "its {name} is not UTF-8: the byte 0x{:02x} after {:?}",
                    field[at],
                    visible(&String::from_utf8_lossy(&field[..at]))
                )
            })
        };
        let fields = (
            text(student, "student"),
            text(question, "question"),
            text(answer, "answer"),
        );
        match fields {
            (Ok(s), Ok(q), Ok(a)) if !s.trim().is_empty() && !q.trim().is_empty() => {
                answers.push(Submission {
                    line,
                    student: s.trim().to_string(),
                    question: q.trim().to_string(),
                    answer: a,
                })
            }
            (Ok(s), Ok(_), Ok(_)) => bad.push(row_error(match s.trim().is_empty() {
                true => "the row names no student".into(),
                false => "the row names no question".into(),
            })),
            (Err(why), _, _) | (_, Err(why), _) | (_, _, Err(why)) => bad.push(row_error(why)),
        }
    }
    Ok((answers, bad))
}
