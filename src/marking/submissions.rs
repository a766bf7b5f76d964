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

impl Submission {
    /// This row named as one not marked, and why.
    pub fn bad(&self, why: String) -> BadRow {
        BadRow {
            line: self.line,
            student: Some(self.student.clone()),
            question: Some(self.question.clone()),
            why,
        }
    }
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
/// whose header lacks a column is an error saying which. A quoted answer whose quote is
/// never closed is a bad row, and the rows after its line are read again without it (else
/// they would all be its answer).
pub fn read_submissions(bytes: &[u8]) -> Result<(Vec<Submission>, Vec<BadRow>), String> {
    let bytes = bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes);
    if bytes.iter().all(u8::is_ascii_whitespace) {
        return Err(
            "the file is empty: it needs the header student,question,answer and a row an answer"
                .into(),
        );
    }
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
        let semicolons = header.len() == 1 && header.iter().any(|h| h.contains(&b';'));
        let hint = match semicolons {
            true => " (its columns are separated by ';': export the file with commas)",
            false => "",
        };
        return Err(format!(
            "the header (line 1) has no column {}: it must name student, question and answer{hint}",
            missing.join(", ")
        ));
    };
    let columns = Columns {
        student,
        question,
        answer,
        width: header.len(),
    };
    let first_row = reader.position().byte() as usize;
    let mut rows = Rows::default();
    let mut from = first_row;
    while from < bytes.len() {
        from = match rows.read(bytes, from, &columns) {
            Some(unclosed) => next_line(bytes, unclosed),
            None => bytes.len(),
        };
    }
    Ok((rows.answers, rows.bad))
}

/// Where the columns are, and how many a row has.
struct Columns {
    student: usize,
    question: usize,
    answer: usize,
    width: usize,
}

/// The rows read so far.
#[derive(Default)]
struct Rows {
    answers: Vec<Submission>,
    bad: Vec<BadRow>,
}

/// The byte after the end of the line holding byte `at`.
fn next_line(bytes: &[u8], at: usize) -> usize {
    bytes[at..]
        .iter()
        .position(|b| *b == b'\n')
        .map_or(bytes.len(), |k| at + k + 1)
}

/// The line (from 1) a row starting at byte `at` is on: the reader may place a row at the
/// end of the line before it (the `\n` of a `\r\n`), so line ends there are passed over.
fn line_of(bytes: &[u8], at: usize) -> usize {
    let start = at
        + bytes[at.min(bytes.len())..]
            .iter()
            .take_while(|b| matches!(b, b'\r' | b'\n'))
            .count();
    1 + bytes[..start.min(bytes.len())]
        .iter()
        .filter(|b| **b == b'\n')
        .count()
}

impl Rows {
    /// Reads the rows from byte `from` to the end; where the last row's quote is never
    /// closed, that row is a bad row and its start is returned, to read on after its line.
    fn read(&mut self, bytes: &[u8], from: usize, columns: &Columns) -> Option<usize> {
        let rest = &bytes[from..];
        let mut reader = csv::ReaderBuilder::new()
            .flexible(true)
            .has_headers(false)
            .from_reader(rest);
        let records: Vec<Result<csv::ByteRecord, csv::Error>> = reader.byte_records().collect();
        let mut unclosed = None;
        for (k, record) in records.iter().enumerate() {
            let record = match record {
                Ok(r) => r,
                Err(e) => {
                    let at = from + e.position().map_or(0, |p| p.byte() as usize);
                    self.bad.push(BadRow {
                        line: line_of(bytes, at),
                        student: None,
                        question: None,
                        why: format!("the row cannot be read: {e}"),
                    });
                    continue;
                }
            };
            let start = from + record.position().map_or(0, |p| p.byte() as usize);
            // The last row, running to the end with an odd number of quotes: its quote was
            // never closed.
            let last = k + 1 == records.len();
            if last && bytes[start..].iter().filter(|b| **b == b'"').count() % 2 == 1 {
                unclosed = Some(start);
                let exact = |c: usize| {
                    let f = std::str::from_utf8(record.get(c)?).ok()?.trim();
                    (!f.is_empty() && !f.contains('\n')).then(|| f.to_string())
                };
                self.bad.push(BadRow {
                    line: line_of(bytes, start),
                    student: exact(columns.student),
                    question: exact(columns.question),
                    why: "a quote in the row is never closed: the rows after its line are read without it".into(),
                });
                continue;
            }
            self.row(record, line_of(bytes, start), columns);
        }
        unclosed
    }

    /// One row: an answer, or a bad row saying why not.
    fn row(&mut self, record: &csv::ByteRecord, line: usize, columns: &Columns) {
        let Columns {
            student,
            question,
            answer,
            width,
        } = *columns;
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
            return;
        }
        if record.len() > width {
            self.bad.push(row_error(format!(
                "the row has {} fields where the header has {width}",
                record.len()
            )));
            return;
        }
        if record.len() < width {
            // Too few fields to trust which is the student (a line of another row's answer,
            // after a quote never closed): named by its text alone.
            let text = String::from_utf8_lossy(record.as_slice()).into_owned();
            self.bad.push(BadRow {
                line,
                student: None,
                question: None,
                why: format!(
                    "the row {:?} has {} fields where the header has {width}",
                    visible(&text),
                    record.len()
                ),
            });
            return;
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
                self.answers.push(Submission {
                    line,
                    student: s.trim().to_string(),
                    question: q.trim().to_string(),
                    answer: a,
                })
            }
            (Ok(s), Ok(_), Ok(_)) => self.bad.push(row_error(match s.trim().is_empty() {
                true => "the row names no student".into(),
                false => "the row names no question".into(),
            })),
            (Err(why), _, _) | (_, Err(why), _) | (_, _, Err(why)) => self.bad.push(row_error(why)),
        }
    }
}
