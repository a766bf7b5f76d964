//! Every reproducer of issue 14 in `tests/reproducers/`, run one after another through the
//! real binary: each must end within [`DEADLINE`] with exit code 1 or 2 (0 only where its
//! file allows a correct result), no signal, no `inf`/`NaN` in either output, and an error
//! that says where: `--> NAME:LINE:COLUMN`, on a line of the user's statements (not a
//! comment), quoting no number longer than the input's own, and no character a reader cannot
//! see (ESC, a right-to-left override: `kinetics::visible::is_hidden`) as itself.
//!
//! A reproducer is one file, its headers first, each `# key: value`:
//! - `# run: ARGS` the command and its flags; the input is added last, after `--`: the
//!   expression (the first line of a `.expr` file that is not a header) or the `.scene` file's
//!   path; a `.claim` file's claim (its first line that is not a header) is added as the value
//!   of the `--claim` that ends ARGS, and its errors are at `claim 1`. In ARGS, `MISSING` is a path in a directory that does not exist and `DANGLING` a
//!   symbolic link to a file that does not exist.
//! - `# at: LINE` the line the error must point at.
//! - `# ok: TEXT` exit code 0 is a correct result when standard output holds TEXT (for a
//!   `.claim`, also 1 and 3: a verdict `differs` or `undecided`).
//! - `# refuse: TEXT` an error about the command line, not the input: no location, but
//!   standard error names TEXT (placeholders replaced) and nothing is written to standard
//!   output (no CSV header, no samples).
//! - `# bytes: escaped` (a `.scene`) the input is not the file itself but the lines after
//!   its headers, each `\xHH` in them the byte HH: a scene that is not UTF-8, or one that
//!   begins with a byte-order mark. It is written to a scratch file of the same name, which
//!   the command reads; `# at:` counts that input's lines.
//!
//! The fuzzer (`examples/fuzz`) takes the same files as its seed corpus.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// How long a reproducer may run: a clean refusal takes milliseconds.
const DEADLINE: Duration = Duration::from_secs(1);
/// What is kept of an output stream; the rest is read and counted, not stored.
const KEPT_BYTES: usize = 1 << 22;

/// A reproducer file's headers and input.
struct Reproducer {
    path: PathBuf,
    args: Vec<String>,
    at: Option<usize>,
    ok: Option<String>,
    refuse: Option<String>,
    /// The expression (for `.expr`) or the scene's text (for `.scene`).
    text: String,
    /// The name diagnostics give the input: `input` or the scene's path.
    name: String,
    /// The last argument: the expression, the scene's path, or the claim.
    input: String,
    /// A claim for `check`: the value of `--claim`, not after `--`.
    claim: bool,
}

fn header<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    text.lines()
        .take_while(|l| l.starts_with("# "))
        .find_map(|l| l.strip_prefix(&format!("# {key}: ")))
}

fn read(path: &Path, scratch: &Path) -> Reproducer {
    let text = std::fs::read_to_string(path).expect("a reproducer is UTF-8 text");
    let substitute = |s: &str| {
        s.replace(
            "MISSING",
            &scratch.join("missing").join("dir").display().to_string(),
        )
        .replace(
            "DANGLING",
            &scratch.join("dangling.svg").display().to_string(),
        )
    };
    let run = header(&text, "run").unwrap_or_else(|| panic!("{}: no '# run:'", path.display()));
    let scene = path.extension().is_some_and(|e| e == "scene");
    let claim = path.extension().is_some_and(|e| e == "claim");
    let bytes = header(&text, "bytes");
    let (name, input, body) = if let (true, Some(escaped)) = (scene, bytes) {
        assert_eq!(escaped, "escaped", "{}: '# bytes: escaped'", path.display());
        let body: String = text
            .lines()
            .skip_while(|l| l.starts_with("# "))
            .map(|l| format!("{l}\n"))
            .collect();
        let decoded = unescape_bytes(&body);
        let written = scratch.join(path.file_name().expect("a file name"));
        std::fs::write(&written, &decoded).expect("the input is written");
        let shown = written.display().to_string();
        let lossy = String::from_utf8_lossy(&decoded).into_owned();
        (shown.clone(), shown, lossy)
    } else if scene {
        let shown = path.display().to_string();
        (shown.clone(), shown, text.clone())
    } else {
        let expression = text
            .lines()
            .find(|l| !l.starts_with("# "))
            .unwrap_or_default()
            .to_string();
        let name = if claim { "claim 1" } else { "input" };
        (name.to_string(), expression.clone(), expression)
    };
    Reproducer {
        path: path.to_path_buf(),
        args: run.split_whitespace().map(substitute).collect(),
        at: header(&text, "at").map(|l| l.trim().parse().expect("# at: a line number")),
        ok: header(&text, "ok").map(str::to_string),
        refuse: header(&text, "refuse").map(substitute),
        text: body,
        name,
        input,
        claim,
    }
}

/// `text` as bytes, each `\xHH` (two hexadecimal digits) the byte HH.
fn unescape_bytes(text: &str) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(text.len());
    let mut rest = text.as_bytes();
    while let Some((&first, tail)) = rest.split_first() {
        let byte = tail
            .strip_prefix(b"x")
            .filter(|_| first == b'\\')
            .and_then(|t| t.get(..2))
            .and_then(|h| u8::from_str_radix(std::str::from_utf8(h).ok()?, 16).ok());
        match byte {
            Some(b) => {
                bytes.push(b);
                rest = &tail[3..];
            }
            None => {
                bytes.push(first);
                rest = tail;
            }
        }
    }
    bytes
}

/// The reproducers, sorted by name.
fn corpus() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reproducers");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("tests/reproducers exists")
        .map(|e| e.expect("readable").path())
        .filter(|p| {
            p.extension()
                .is_some_and(|e| e == "expr" || e == "scene" || e == "claim")
        })
        .collect();
    paths.sort();
    paths
}

struct Outcome {
    status: ExitStatus,
    stdout: String,
    stderr: String,
}

/// A thread that reads `stream` to its end, keeping the first [`KEPT_BYTES`].
fn drain(mut stream: impl Read + Send + 'static) -> std::thread::JoinHandle<String> {
    std::thread::spawn(move || {
        let mut kept = Vec::new();
        let mut buffer = [0u8; 1 << 16];
        while let Ok(n) = stream.read(&mut buffer) {
            if n == 0 {
                break;
            }
            let room = KEPT_BYTES.saturating_sub(kept.len()).min(n);
            kept.extend_from_slice(&buffer[..room]);
        }
        String::from_utf8_lossy(&kept).into_owned()
    })
}

/// Runs the binary on the reproducer; `Err` when it is still running at the deadline (then
/// it is killed).
fn run(r: &Reproducer) -> Result<Outcome, String> {
    let mut command = Command::new(env!("CARGO_BIN_EXE_kinetics"));
    command.args(&r.args);
    if !r.claim {
        command.arg("--");
    }
    let mut child = command
        .arg(&r.input)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("the binary does not start: {e}"))?;
    let stdout = drain(child.stdout.take().expect("piped"));
    let stderr = drain(child.stderr.take().expect("piped"));
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("waits") {
            break status;
        }
        if start.elapsed() > DEADLINE {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("hangs: still running after {DEADLINE:?}, killed"));
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    Ok(Outcome {
        status,
        stdout: stdout.join().expect("read"),
        stderr: stderr.join().expect("read"),
    })
}

/// The signal that ended the process, if one did.
fn signal(status: &ExitStatus) -> Option<i32> {
    #[cfg(unix)]
    {
        std::os::unix::process::ExitStatusExt::signal(status)
    }
    #[cfg(not(unix))]
    {
        let _ = status;
        None
    }
}

/// `inf`, `NaN` (any case) as a word of `text`: a non-finite number printed.
fn non_finite(text: &str) -> Option<String> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.'))
        .map(|w| w.trim_start_matches(|c: char| c.is_ascii_digit() || c == '.'))
        .find(|w| ["inf", "infinity", "nan"].contains(&w.to_ascii_lowercase().as_str()))
        .map(str::to_string)
}

fn longest_digit_run(text: &str) -> usize {
    text.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

/// The line of `--> NAME:LINE:COLUMN` in `stderr`.
fn located_line(stderr: &str, name: &str) -> Option<usize> {
    let place = stderr.split(&format!("--> {name}:")).nth(1)?;
    let (line, rest) = place.split_once(':')?;
    if !rest.starts_with(|c: char| c.is_ascii_digit()) {
        return None;
    }
    line.parse().ok()
}

/// Everything wrong with how the binary met the reproducer; empty when it refused it (or
/// answered it) properly.
fn problems(r: &Reproducer) -> Vec<String> {
    let o = match run(r) {
        Ok(o) => o,
        Err(e) => return vec![e],
    };
    let first = o
        .stderr
        .lines()
        .find(|l| !l.trim().is_empty())
        .unwrap_or_default()
        .to_string();
    if let Some(s) = signal(&o.status) {
        return vec![format!(
            "killed by signal {s} (stack overflow or abort): {first}"
        )];
    }
    let code = o.status.code().unwrap_or(-1);
    let mut found = Vec::new();
    for (stream, text) in [("stdout", &o.stdout), ("stderr", &o.stderr)] {
        if let Some(word) = non_finite(text) {
            found.push(format!("{stream} prints a non-finite number: {word}"));
        }
        if let Some(c) = text.chars().find(|c| kinetics::visible::is_hidden(*c)) {
            found.push(format!("{stream} prints {c:?} as itself, not escaped"));
        }
    }
    let answered = r.ok.as_ref().is_some_and(|ok| o.stdout.contains(ok));
    // A claim's verdicts `differs` and `undecided` are answers too.
    let verdict = code == 0 || (r.claim && (code == 1 || code == 3));
    match code {
        _ if answered && verdict => return found,
        0 => {
            found.push("accepted with exit code 0: no error".to_string());
            return found;
        }
        101 => found.push(format!("panics (exit code 101): {first}")),
        1 | 2 => {}
        c => found.push(format!("exit code {c}, not 1 or 2: {first}")),
    }
    if let Some(text) = &r.refuse {
        if !o.stdout.is_empty() {
            found.push(format!(
                "writes to stdout before refusing: {:?}",
                o.stdout.lines().next().unwrap_or_default()
            ));
        }
        if !o.stderr.contains(text.as_str()) {
            found.push(format!("stderr does not name {text:?}: {first}"));
        }
        return found;
    }
    match located_line(&o.stderr, &r.name) {
        None => found.push(format!("no location '--> {}:LINE:COLUMN': {first}", r.name)),
        Some(line) => {
            if r.at.is_some_and(|at| at != line) {
                found.push(format!("points at line {line}, not {}", r.at.unwrap_or(0)));
            }
            let pointed = r.text.lines().nth(line.wrapping_sub(1)).unwrap_or("#");
            if r.name != "input" && pointed.trim_start().starts_with('#') {
                found.push(format!("points at line {line}, a comment: {first}"));
            }
        }
    }
    let digits = longest_digit_run(&o.stderr);
    if digits > longest_digit_run(&r.text).max(12) {
        found.push(format!(
            "stderr quotes a {digits}-digit number the input does not hold: {first}"
        ));
    }
    found
}

/// A scratch directory with a dangling symbolic link (`DANGLING`) and no `missing/`.
fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kinetics-reproducers-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch directory");
    #[cfg(unix)]
    {
        let link = dir.join("dangling.svg");
        let _ = std::fs::remove_file(&link);
        std::os::unix::fs::symlink(dir.join("nowhere").join("target.svg"), &link)
            .expect("symbolic link");
    }
    dir
}

#[test]
fn every_reproducer_is_refused_cleanly_within_the_deadline() {
    let scratch = scratch();
    let paths = corpus();
    assert!(paths.len() >= 30, "the corpus is in tests/reproducers");
    let mut failures = Vec::new();
    for path in &paths {
        let r = read(path, &scratch);
        let found = problems(&r);
        if !found.is_empty() {
            let file = r.path.file_name().unwrap_or_default().to_string_lossy();
            failures.push(format!(
                "{file} ({}):\n    {}",
                r.args.join(" "),
                found.join("\n    ")
            ));
        }
    }
    let _ = std::fs::remove_dir_all(&scratch);
    assert!(
        failures.is_empty(),
        "{} of {} reproducers are not refused cleanly:\n{}",
        failures.len(),
        paths.len(),
        failures.join("\n")
    );
}
