//! The rows `kinetics simulate` streams: CSV (a header line, then a row per sample) or JSON
//! (one array of rows), every number in 17 significant digits, written as each sample
//! arrives. The header (or the JSON array's opening) goes out with the first row, so that a
//! problem refused before it leaves standard output empty. A failed write is kept and
//! reported once the run is over (the driver's sink cannot fail).

use super::error::CliError;
use super::simulate::Output;
use std::io::Write;

/// Rows written to standard output.
pub struct SampleRows<W: Write> {
    out: W,
    format: Output,
    header: &'static str,
    written: usize,
    failure: Option<std::io::Error>,
}

impl<W: Write> SampleRows<W> {
    /// Rows into `out` in `format` under the CSV `header` (comma-separated column names).
    pub fn new(out: W, format: Output, header: &'static str) -> Self {
        Self {
            out,
            format,
            header,
            written: 0,
            failure: None,
        }
    }

    /// Writes one row (nothing more after a write failed).
    pub fn push(&mut self, fields: &[f64]) {
        if self.failure.is_some() {
            return;
        }
        let row = fields
            .iter()
            .map(|v| format!("{v:.17e}"))
            .collect::<Vec<_>>()
            .join(",");
        let out = &mut self.out;
        let result = match (self.format, self.written) {
            (Output::Csv, 0) => writeln!(out, "{}\n{row}", self.header),
            (Output::Csv, _) => writeln!(out, "{row}"),
            (Output::Json, 0) => write!(out, "[[{row}]"),
            (Output::Json, _) => write!(out, ",[{row}]"),
        };
        if let Err(e) = result {
            self.failure = Some(e);
        }
        self.written += 1;
    }

    /// Closes the JSON array and flushes; the first write failure, if any, as the error.
    pub fn finish(mut self) -> Result<(), CliError> {
        if let Some(e) = self.failure {
            return Err(CliError::Io {
                action: "write the samples".into(),
                source: e,
            });
        }
        if self.format == Output::Json {
            writeln!(self.out, "]").map_err(CliError::io("write"))?;
        }
        self.out.flush().map_err(CliError::io("write"))
    }
}
