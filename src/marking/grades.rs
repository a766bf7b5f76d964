//! The gradebook: `student`, a column per question (its id) and `total`, one row per student
//! in the order first met: a CSV Moodle's and Canvas' gradebooks import (marks as plain
//! decimals, a missing or unmarked answer 0).

use super::scheme::Scheme;
use super::{marks_text, Class};

/// The gradebook of `class` as CSV text.
pub fn grades_csv(scheme: &Scheme, class: &Class) -> Result<String, csv::Error> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["student".to_string()];
    header.extend(scheme.questions.iter().map(|q| q.id.clone()));
    header.push("total".into());
    writer.write_record(&header)?;
    for (k, student) in class.students.iter().enumerate() {
        let mut row = vec![student.clone()];
        row.extend(class.answers[k].iter().map(|a| marks_text(a.marks())));
        row.push(marks_text(class.total(k)));
        writer.write_record(&row)?;
    }
    let bytes = writer.into_inner().map_err(|e| e.into_error())?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}
