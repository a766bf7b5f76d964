//! The corpus of malformed scenes in `tests/bad_scenes/`: each file is a mistake a student
//! would make, and `kinetics solve FILE` must refuse it with exit code 1, a first line
//! `error: ...`, the place as `file:line:column`, a caret under it, a `= help:` hint and the
//! message named in the file's first line (`# expect: <substring>`). An optional second line
//! `# at: <line>` also pins the line the error must point at. Never a panic, a hang (a
//! generous time-out turns one into a failure) or a NaN.
//!
//! Files in [`EXPECTED_TO_FAIL`] show gaps outside the scene parser; each is checked all the
//! same, and the test fails if one of them starts to pass, so the list stays honest.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;

/// Scenes whose error is still wrong, each with the reason; the fix belongs outside
/// `src/scene/parse.rs`. Remove an entry once its scene passes.
const EXPECTED_TO_FAIL: [(&str, &str); 0] = [];

struct Outcome {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

/// Runs `kinetics solve FILE`, reading its output on another thread so that a full pipe
/// never blocks the child, and killing it after a time-out.
fn solve(path: &Path) -> Result<Outcome, String> {
    let child = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .arg("solve")
        .arg(path)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("the binary does not start: {e}"))?;
    let pid = child.id();
    let (done, finished) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = done.send(child.wait_with_output());
    });
    match finished.recv_timeout(Duration::from_secs(30)) {
        Ok(Ok(out)) => Ok(Outcome {
            code: out.status.code(),
            stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
            stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        }),
        Ok(Err(e)) => Err(format!("output not readable: {e}")),
        Err(_) => {
            let _ = Command::new("kill").args(["-9", &pid.to_string()]).status();
            Err("did not finish within 30 s: it hangs".to_string())
        }
    }
}

/// A header line `# key: value` among the first lines of a scene.
fn header<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    text.lines()
        .take(2)
        .find_map(|l| l.strip_prefix(&format!("# {key}: ")))
        .map(str::trim)
}

/// Everything wrong with how the program refused `path`; empty when it did so properly.
fn problems(path: &Path, expect: &str, at_line: Option<&str>) -> Vec<String> {
    let o = match solve(path) {
        Ok(o) => o,
        Err(e) => return vec![e],
    };
    let mut found = Vec::new();
    let shown = path.display().to_string();
    if o.code != Some(1) {
        found.push(format!("exit code {:?}, not 1", o.code));
    }
    let first = o.stderr.lines().next().unwrap_or_default();
    if !first.starts_with("error: ") {
        found.push(format!(
            "first line of stderr is not 'error: ...': {first:?}"
        ));
    }
    let place = format!("{shown}:");
    let located = o.stderr.lines().any(|l| {
        l.split_once(&place)
            .and_then(|(_, rest)| rest.split_once(':'))
            .is_some_and(|(line, column)| {
                let numbers = [line, column]
                    .iter()
                    .all(|n| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()));
                numbers && at_line.is_none_or(|want| want == line)
            })
    });
    if !located {
        found.push(format!(
            "no location {place}{}:<column>",
            at_line.unwrap_or("<line>")
        ));
    }
    if !o
        .stderr
        .lines()
        .any(|l| l.trim_start_matches([' ', '|']).starts_with('^'))
    {
        found.push("no caret line".to_string());
    }
    if !o
        .stderr
        .lines()
        .any(|l| l.trim_start().starts_with("= help: "))
    {
        found.push("no '= help:' line".to_string());
    }
    if !o.stderr.contains(expect) {
        found.push(format!("the message does not contain {expect:?}"));
    }
    if o.stderr.contains("panicked") {
        found.push("it panicked".to_string());
    }
    // The scene's own text is echoed under the error, so only the message itself is searched.
    if o.stdout.contains("NaN") || first.contains("NaN") {
        found.push("the output holds a NaN".to_string());
    }
    if !found.is_empty() {
        found.push(format!("stderr was:\n{}", o.stderr));
    }
    found
}

/// Checks each scene, then compares the failures with [`EXPECTED_TO_FAIL`]: a failure not
/// on the list, or a listed scene that passes, is reported; all of them in one message.
fn check_all(scenes: &[(PathBuf, String, Option<String>)]) {
    let mut report = Vec::new();
    for (path, expect, at_line) in scenes {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let found = problems(path, expect, at_line.as_deref());
        let listed = EXPECTED_TO_FAIL.iter().any(|(n, _)| *n == name);
        match (found.is_empty(), listed) {
            (false, false) => report.push(format!("{name}:\n  {}", found.join("\n  "))),
            (true, true) => report.push(format!(
                "{name}: now passes; remove it from EXPECTED_TO_FAIL"
            )),
            _ => {}
        }
    }
    assert!(
        report.is_empty(),
        "{} scene(s) wrong:\n\n{}",
        report.len(),
        report.join("\n\n")
    );
}

#[test]
fn every_bad_scene_is_refused_with_a_located_helpful_error() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_scenes");
    let mut scenes = Vec::new();
    let mut unlabelled = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("tests/bad_scenes is readable") {
        let path = entry.expect("a directory entry").path();
        if path.extension().is_none_or(|e| e != "scene") {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("a scene is UTF-8 text");
        match header(&text, "expect") {
            Some(expect) => {
                let at_line = header(&text, "at").map(str::to_string);
                scenes.push((path, expect.to_string(), at_line));
            }
            None => unlabelled.push(path.display().to_string()),
        }
    }
    assert!(
        unlabelled.is_empty(),
        "scenes without '# expect:': {unlabelled:?}"
    );
    assert!(
        scenes.len() >= 40,
        "the corpus has only {} scenes",
        scenes.len()
    );
    scenes.sort();
    check_all(&scenes);
}

/// A scene over the input size limit is generated rather than kept in the repository.
#[test]
fn an_oversized_scene_is_refused_with_a_located_helpful_error() {
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("oversized.scene");
    let givens = (0..60_000)
        .map(|k| format!("given g{k} = 1 m\n"))
        .collect::<String>();
    std::fs::write(&path, format!("title far too long\n{givens}find T\n")).expect("writable");
    check_all(&[(path, "larger than".to_string(), None)]);
}
