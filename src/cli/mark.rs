//! `kinetics mark SCHEME SUBMISSIONS [-o DIR] [--force]`: a class marked against a scheme
//! ([`kinetics::marking`]). Writes `grades.csv`, `feedback/<student>.md` and `.html`, and
//! `summary.md` and `.html` into DIR; a row that cannot be marked is named on standard error
//! with its CSV line and student, and never stops the run. Nothing is overwritten without
//! `--force`.

use super::error::CliError;
use super::input::read_file;
use kinetics::check::context::Context;
use kinetics::check::forms::Forms;
use kinetics::check::reading_names;
use kinetics::marking::document::{html, markdown, Document};
use kinetics::marking::feedback::{feedback, file_stem};
use kinetics::marking::grades::grades_csv;
use kinetics::marking::scheme::{check_names, parse_scheme, Scheme, Setting};
use kinetics::marking::submissions::read_submissions;
use kinetics::marking::summary::summary;
use kinetics::marking::{mark_class, Class};
use kinetics::scene::parse_scene;
use kinetics::Input;
use rayon::prelude::*;
use std::collections::HashMap;
use std::io::Read;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
#[command(
    after_help = "Example:\n  kinetics mark examples/marking/scheme.toml examples/marking/submissions.csv -o marked"
)]
pub struct Args {
    /// The marking scheme (TOML): its questions, each with an id, a scene or context, what
    /// the answer gives, its marks, the credit for carried-forward lines and feedback words.
    pub scheme: String,
    /// The submissions: a CSV with the header student,question,answer (UTF-8).
    pub submissions: String,
    /// The directory the grades, feedback and summary are written into.
    #[arg(short, long, default_value = "marked")]
    pub output: PathBuf,
    /// Overwrite the outputs of an earlier run.
    #[arg(long)]
    pub force: bool,
}

/// The largest submissions file read: a class of a thousand with long derivations.
const MAX_SUBMISSIONS_BYTES: u64 = 64 << 20;

pub fn run(args: Args) -> Result<String, CliError> {
    let (scheme_name, scheme_text) = read_file(&args.scheme)?;
    let names = reading_names();
    let scheme = parse_scheme(&scheme_name, &scheme_text, &names).map_err(CliError::Located)?;
    let contexts = contexts(&scheme, &args.scheme)?;
    check_names(&scheme, &contexts, &scheme_name, &scheme_text).map_err(CliError::Located)?;
    let bytes = submissions_bytes(&args.submissions)?;
    let (answers, bad) = read_submissions(&bytes).map_err(|why| CliError::Unreadable {
        name: args.submissions.clone(),
        reason: why,
    })?;
    let outputs = Outputs::new(&args.output);
    outputs.refuse_overwriting(args.force)?;
    let class = super::progress::with_bar(|progress| {
        mark_class(&scheme, &contexts, &answers, bad, progress)
    });
    outputs.write(&scheme, &contexts, &class, &args.submissions)?;
    for b in &class.bad_rows {
        let who = b.student.as_deref().unwrap_or("(no student read)");
        let question = b
            .question
            .as_deref()
            .map(|q| format!(", {q}"))
            .unwrap_or_default();
        super::tell(&format!(
            "{}:{}: {who}{question}: {}",
            args.submissions, b.line, b.why
        ));
    }
    let marked = class
        .answers
        .iter()
        .flatten()
        .filter(|a| matches!(a, kinetics::marking::Answer::Marked { .. }))
        .count();
    if answers.is_empty() {
        super::tell(&format!(
            "warning: {} has no answer to mark",
            args.submissions
        ));
    }
    let bad = match class.bad_rows.len() {
        0 => String::new(),
        1 => ", 1 row named above".into(),
        n => format!(", {n} rows named above"),
    };
    let answers_word = if marked == 1 { "answer" } else { "answers" };
    Ok(format!(
        "{} students, {} questions: {marked} {answers_word} marked{bad}; wrote {}",
        class.students.len(),
        scheme.questions.len(),
        outputs.listing()
    ))
}

/// Each question's context: its scene (a path relative to the scheme, each scene read and
/// analysed once) or the general body it names.
fn contexts(scheme: &Scheme, scheme_path: &str) -> Result<Vec<Context>, CliError> {
    let base = Path::new(scheme_path).parent().unwrap_or(Path::new(""));
    let mut scenes: HashMap<PathBuf, Context> = HashMap::new();
    scheme
        .questions
        .iter()
        .map(|q| match &q.setting {
            Setting::Scene(path) => {
                let path = base.join(path);
                if let Some(c) = scenes.get(&path) {
                    return Ok(c.clone());
                }
                let (name, source) = read_file(&path.to_string_lossy()).map_err(|e| {
                    CliError::Usage(format!(
                        "question {} of {scheme_path}: {}",
                        q.id,
                        e.to_string().trim_start_matches("error: ")
                    ))
                })?;
                let context = Input::scene(&name, &source)
                    .within(|| Ok::<_, CliError>(Context::scene(&parse_scene(&name, &source)?)))?;
                scenes.insert(path, context.clone());
                Ok(context)
            }
            Setting::General {
                principal,
                fixed_point,
            } => Context::general(*principal, *fixed_point)
                .map_err(|source| CliError::Algebra { name: None, source }),
            Setting::FixedAxis => {
                Context::fixed_axis().map_err(|source| CliError::Algebra { name: None, source })
            }
        })
        .collect()
}

/// The submissions file's bytes (not yet UTF-8: a row with a bad byte is a bad row).
fn submissions_bytes(path: &str) -> Result<Vec<u8>, CliError> {
    let mut bytes = Vec::new();
    let reader: Box<dyn Read> = match path {
        "-" => Box::new(std::io::stdin()),
        _ => Box::new(std::fs::File::open(path).map_err(CliError::io(format!("read {path}")))?),
    };
    reader
        .take(MAX_SUBMISSIONS_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(CliError::io(format!("read {path}")))?;
    if bytes.len() as u64 > MAX_SUBMISSIONS_BYTES {
        return Err(CliError::Unreadable {
            name: path.into(),
            reason: format!("the file is larger than the limit of {MAX_SUBMISSIONS_BYTES} bytes"),
        });
    }
    Ok(bytes)
}

/// The files a run writes.
struct Outputs {
    dir: PathBuf,
}

impl Outputs {
    fn new(dir: &Path) -> Outputs {
        Outputs {
            dir: dir.to_path_buf(),
        }
    }

    fn fixed(&self) -> [PathBuf; 4] {
        ["grades.csv", "summary.md", "summary.html", "feedback"].map(|f| self.dir.join(f))
    }

    /// An error naming the first output that exists, unless `force`.
    fn refuse_overwriting(&self, force: bool) -> Result<(), CliError> {
        if force {
            return Ok(());
        }
        match self.fixed().into_iter().find(|p| p.exists()) {
            Some(p) => Err(CliError::Usage(format!(
                "{} exists: an earlier run's output is not overwritten\n  = help: give another -o DIR, or --force to overwrite",
                p.display()
            ))),
            None => Ok(()),
        }
    }

    fn write_file(path: &Path, text: &str) -> Result<(), CliError> {
        std::fs::write(path, text).map_err(CliError::io(format!("write {}", path.display())))
    }

    fn write(
        &self,
        scheme: &Scheme,
        contexts: &[Context],
        class: &Class,
        submissions_name: &str,
    ) -> Result<(), CliError> {
        let [grades, summary_md, summary_html, feedback_dir] = self.fixed();
        std::fs::create_dir_all(&feedback_dir)
            .map_err(CliError::io(format!("create {}", feedback_dir.display())))?;
        let csv = grades_csv(scheme, class)
            .map_err(|e| CliError::Usage(format!("cannot write the gradebook: {e}")))?;
        Self::write_file(&grades, &csv)?;
        let page = summary(scheme, class, submissions_name);
        Self::write_file(&summary_md, &markdown(&page))?;
        Self::write_file(&summary_html, &html(&page))?;
        // Each student's page is written in parallel, the files in turn; the forms of each
        // question's context are found once for the class.
        let forms: Vec<Forms> = contexts.iter().map(|c| Forms::new(c.domains())).collect();
        let pages: Vec<Document> = (0..class.students.len())
            .into_par_iter()
            .map(|k| feedback(scheme, &forms, class, k, submissions_name))
            .collect();
        let mut stems: HashMap<String, usize> = HashMap::new();
        for (k, page) in pages.iter().enumerate() {
            let stem = file_stem(&class.students[k]);
            // Two students whose names make one file name: the second is `name-2`.
            let seen = stems.entry(stem.clone()).or_insert(0);
            *seen += 1;
            let stem = match *seen {
                1 => stem,
                n => format!("{stem}-{n}"),
            };
            Self::write_file(&feedback_dir.join(format!("{stem}.md")), &markdown(page))?;
            Self::write_file(&feedback_dir.join(format!("{stem}.html")), &html(page))?;
        }
        Ok(())
    }

    fn listing(&self) -> String {
        let d = self.dir.display();
        format!("{d}/grades.csv, {d}/summary.md and .html, {d}/feedback/")
    }
}
