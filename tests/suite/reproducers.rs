//! Every reproducer of issue 14 in `tests/reproducers/`, run one after another through the
//! real binary: each must end within its work budget (and a hang guard) with exit code 1 or 2 (0 only where its
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
//! - `# never: TEXT` standard output must not hold TEXT (markup injected from the input:
//!   `<script` in Markdown).
//! - `# repeat: N` (`.expr` only) the expression is the body's first line repeated N times,
//!   then its second line if it has one (`a^2*b^3*` 131072 times, then `c`: a 1 MiB input in
//!   a small file). It is given on standard input (`-`, named `<stdin>`): an argument is
//!   limited to 128 KiB.
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

/// Only turns a hang into a failure: no test asserts on wall-clock time. What bounds a
/// reproducer is its work budget, which the binary reports (`KINETICS_WORK_REPORT`) and
/// [`within_work_budget`] checks.
const HANG_GUARD: Duration = Duration::from_secs(60);
/// What is kept of an output stream; the rest is read and counted, not stored.
const KEPT_BYTES: usize = 1 << 22;

/// A reproducer file's headers and input.
struct Reproducer {
    path: PathBuf,
    args: Vec<String>,
    at: Option<usize>,
    ok: Option<String>,
    refuse: Option<String>,
    never: Option<String>,
    /// The expression (for `.expr`) or the scene's text (for `.scene`).
    text: String,
    /// The name diagnostics give the input: `input` or the scene's path.
    name: String,
    /// The last argument: the expression, the scene's path, or the claim.
    input: String,
    /// A claim for `check`: the value of `--claim`, not after `--`.
    claim: bool,
    /// The expression on standard input (the input is then `-`): a `# repeat:`.
    stdin: Option<String>,
}

fn header<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    text.lines()
        .take_while(|l| l.starts_with("# "))
        .find_map(|l| l.strip_prefix(&format!("# {key}: ")))
}

fn read(path: &Path, scratch: &Path) -> Reproducer {
    // Bytes that are not UTF-8 and a byte-order mark are written `\xHH` (`# bytes: escaped`).
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
    let repeat = header(&text, "repeat").map(|n| n.trim().parse().expect("# repeat: a count"));
    let (name, input, body, stdin) = match repeat {
        Some(n) => {
            let mut body = text.lines().filter(|l| !l.starts_with("# "));
            let expression = body.next().unwrap_or_default().repeat(n) + body.next().unwrap_or("");
            let stdin = Some(expression.clone());
            ("<stdin>".to_string(), "-".to_string(), expression, stdin)
        }
        None => (name, input, body, None),
    };
    Reproducer {
        path: path.to_path_buf(),
        args: run.split_whitespace().map(substitute).collect(),
        at: header(&text, "at").map(|l| l.trim().parse().expect("# at: a line number")),
        ok: header(&text, "ok").map(str::to_string),
        refuse: header(&text, "refuse").map(substitute),
        never: header(&text, "never").map(str::to_string),
        text: body,
        name,
        input,
        claim,
        stdin,
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
    command.args(&r.args).env("KINETICS_WORK_REPORT", "1");
    if !r.claim {
        command.arg("--");
    }
    let mut child = command
        .arg(&r.input)
        .stdin(match r.stdin {
            Some(_) => Stdio::piped(),
            None => Stdio::null(),
        })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("the binary does not start: {e}"))?;
    if let (Some(text), Some(mut stdin)) = (r.stdin.clone(), child.stdin.take()) {
        // Written by a thread, so that a binary that never reads it cannot block the test.
        std::thread::spawn(move || {
            let _ = std::io::Write::write_all(&mut stdin, text.as_bytes());
        });
    }
    let stdout = drain(child.stdout.take().expect("piped"));
    let stderr = drain(child.stderr.take().expect("piped"));
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("waits") {
            break status;
        }
        if start.elapsed() > HANG_GUARD {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("hangs: still running after {HANG_GUARD:?}, killed"));
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

/// What is wrong with the work the binary reports on standard error, each budgeted piece
/// `work: SPENT of LIMIT operations`: a piece past its limit must have been refused for it.
fn within_work_budget(stderr: &str) -> Vec<String> {
    let refused = stderr.contains("operations, the work allowed for its length");
    stderr
        .lines()
        .filter_map(|l| l.strip_prefix("work: "))
        .filter_map(|l| {
            let (spent, rest) = l.split_once(" of ")?;
            let limit = rest.strip_suffix(" operations")?;
            Some((spent.parse::<u64>().ok()?, limit.parse::<u64>().ok()?))
        })
        .filter(|(spent, limit)| spent > limit && !refused)
        .map(|(spent, limit)| format!("spent {spent} operations of {limit} and was not refused"))
        .collect()
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
        .find(|l| !l.trim().is_empty() && !l.starts_with("work: "))
        .unwrap_or_default()
        .to_string();
    if let Some(s) = signal(&o.status) {
        return vec![format!(
            "killed by signal {s} (stack overflow or abort): {first}"
        )];
    }
    let code = o.status.code().unwrap_or(-1);
    let mut found = within_work_budget(&o.stderr);
    for (stream, text) in [("stdout", &o.stdout), ("stderr", &o.stderr)] {
        if let Some(word) = non_finite(text) {
            found.push(format!("{stream} prints a non-finite number: {word}"));
        }
        if let Some(c) = text.chars().find(|c| kinetics::visible::is_hidden(*c)) {
            found.push(format!("{stream} prints {c:?} as itself, not escaped"));
        }
    }
    if let Some(never) = r.never.as_ref().filter(|n| o.stdout.contains(n.as_str())) {
        found.push(format!("stdout holds {never:?}"));
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
            if !matches!(r.name.as_str(), "input" | "<stdin>")
                && pointed.trim_start().starts_with('#')
            {
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
fn every_reproducer_is_refused_cleanly_within_its_work_budget() {
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
