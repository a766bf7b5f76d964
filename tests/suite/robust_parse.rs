//! Hostile input to the parsers (issue 14). Nested calls with an error inside, unclosed
//! parentheses and long runs of blanks in a scene's mathematics are read in time linear in
//! their length: no alternative of the grammar re-reads what a failed one read (22 unclosed
//! `f(` took 10 s, 24 levels of `abs(...abs()...)` 43 s). The guard below only turns a hang
//! into a failure; no test asserts on how fast the parser is. And an error of the algebra
//! met while reading points at, and quotes, the text the user wrote.

use kinetics::parse::limits::MAX_NESTING;
use kinetics::parse_expression;
use std::io::Write;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Far longer than any of these inputs needs, far shorter than the old exponential times.
const HANG_GUARD: Duration = Duration::from_secs(30);

/// `kinetics args` with `stdin`: its exit code and standard error, or a failure if it does
/// not finish within the guard.
fn kinetics(args: &[&str], stdin: &str) -> (Option<i32>, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    let mut pipe = child.stdin.take().expect("stdin is piped");
    let text = stdin.to_string();
    // The program may stop reading early; a broken pipe is expected then.
    let writer = std::thread::spawn(move || pipe.write_all(text.as_bytes()));
    let started = Instant::now();
    while child
        .try_wait()
        .expect("the child can be waited on")
        .is_none()
    {
        if started.elapsed() > HANG_GUARD {
            let _ = child.kill();
            panic!("kinetics {args:?} did not finish within {HANG_GUARD:?}: it hangs");
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    let _ = writer.join();
    let out = child.wait_with_output().expect("the output is readable");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// A clean error: exit code 1, the message first, at `place` (`name:line:column`).
fn assert_error_at(outcome: &(Option<i32>, String), place: &str, message: &str) {
    let (code, stderr) = outcome;
    assert_eq!(*code, Some(1), "exit code; stderr: {stderr}");
    let first = stderr.lines().next().unwrap_or_default();
    assert!(first.starts_with("error: "), "first line: {first}");
    assert!(stderr.contains(message), "names {message:?}: {stderr}");
    assert!(
        stderr.contains(&format!("--> {place}\n")),
        "at {place}: {stderr}"
    );
    assert!(!stderr.contains("panicked"), "no panic: {stderr}");
}

/// The depths of the reproducers: the issue's, and the deepest nesting accepted.
const DEPTHS: [usize; 3] = [22, 24, MAX_NESTING];

fn unclosed_calls(depth: usize) -> String {
    format!("{}x", "f(".repeat(depth))
}

fn empty_innermost_abs(depth: usize) -> String {
    format!("{}{}", "abs(".repeat(depth), ")".repeat(depth))
}

#[test]
fn unclosed_nested_calls_are_reported_at_the_end() {
    for depth in DEPTHS {
        let input = unclosed_calls(depth);
        let place = format!("<stdin>:1:{}", input.len() + 1);
        let outcome = kinetics(&["simplify", "-"], &input);
        assert_error_at(&outcome, &place, "found end of input");
        assert!(outcome
            .1
            .contains("every '(' needs an expression and a matching ')'"));
    }
}

#[test]
fn an_empty_call_deep_inside_calls_is_reported_where_it_is_empty() {
    for depth in DEPTHS {
        let input = empty_innermost_abs(depth);
        let place = format!("<stdin>:1:{}", 4 * depth + 1);
        let outcome = kinetics(&["latex", "-"], &input);
        assert_error_at(&outcome, &place, "expected an expression");
    }
}

/// A sphere about a fixed point whose `omega` line is `omega`; the line is the fifth.
fn scene_with_omega(omega: &str) -> String {
    format!(
        "given m = 1 kg\ngiven r = 1 m\ngiven w : rad/s\nbody sphere(r) mass m\nomega = {omega}\nfixed point\nfind T\n"
    )
}

#[test]
fn nested_calls_in_a_scene_are_reported_in_the_file() {
    for depth in DEPTHS {
        // More than one '(' never closed on a line is refused before the grammar reads it,
        // at the first.
        let omega = unclosed_calls(depth);
        let outcome = kinetics(&["solve", "-"], &scene_with_omega(&omega));
        let message = format!("{depth} '(' on this line are never closed");
        assert_error_at(&outcome, "<stdin>:5:10", &message);
        assert!(outcome
            .1
            .contains("every '(' needs a matching ')' on the same line"));

        let omega = format!("{}*i", empty_innermost_abs(depth));
        let place = format!("<stdin>:5:{}", "omega = ".len() + 4 * depth + 1);
        let outcome = kinetics(&["plan", "-"], &scene_with_omega(&omega));
        assert_error_at(&outcome, &place, "expected an expression");
    }
}

/// One '(' never closed is read by the grammar as an ordinary character (a second reading
/// of the line at most), and the expression parser reports it where the mathematics ends.
#[test]
fn one_unclosed_parenthesis_in_a_scene_is_reported_where_the_mathematics_ends() {
    // The mathematics ends before the comment, its blanks included.
    let omega = format!("({}w*i  ", "(w) + ".repeat(100_000));
    let place = format!("<stdin>:5:{}", "omega = ".len() + omega.len() + 1);
    let outcome = kinetics(
        &["solve", "-"],
        &scene_with_omega(&format!("{omega}# spin")),
    );
    assert_error_at(&outcome, &place, "found end of input");
    assert!(outcome
        .1
        .contains("every '(' needs an expression and a matching ')'"));
}

/// A title's text and a comment are not mathematics: their parentheses are not counted.
#[test]
fn unclosed_parentheses_in_a_title_or_a_comment_are_text() {
    let scene = scene_with_omega("w*i  # spin (about x (the axis")
        .replace("given m", "title Sample (a (b\n# see ((1\ngiven m");
    let (code, stderr) = kinetics(&["plan", "-"], &scene);
    assert_eq!(code, Some(0), "{stderr}");
}

/// A keyword after the mathematics is looked for once after a run of blanks, not at each
/// blank of it (which read the rest of the run each time: 20,000 blanks took 4 s).
#[test]
fn long_runs_of_blanks_in_a_scene_line_finish() {
    let blanks = " ".repeat(500_000);
    let omega = format!("w*i{blanks}x");
    let outcome = kinetics(&["solve", "-"], &scene_with_omega(&omega));
    assert_error_at(&outcome, "<stdin>:5:9", "unknown symbol x");

    // D_x unknown: a given force there would be refused, as no load acts on this motion.
    let line = format!("force D = D_x*i{blanks}\tat{blanks}(r, 0, 0)");
    let scene =
        scene_with_omega("w*i").replace("find T", &format!("unknown D_x : N\n{line}\nfind T"));
    let (code, stderr) = kinetics(&["plan", "-"], &scene);
    assert_eq!(code, Some(0), "the force reads with its point: {stderr}");
}

/// The place (line, column, length of the caret) and the message of an expression's error.
fn error_of(input: &str) -> (usize, usize, String) {
    let e = parse_expression("input", input).expect_err("the input is refused");
    assert_eq!(e.line, 1);
    (e.column, e.span.len(), e.message)
}

#[test]
fn a_zero_divisor_is_pointed_at_and_quoted_as_written() {
    let cases = [
        // The divisor, not the rest of the input after it.
        ("x/(a - a) + 5*y", 3, 7, "'(a - a)' is exactly zero"),
        ("1/0", 3, 1, "'0' is exactly zero"),
        ("x/0.0e5 + q", 3, 5, "'0.0e5' is exactly zero"),
        // The zero factor of a divisor, even where two divisions cancel.
        ("x / (2*(a-a)) * b + c", 8, 5, "'(a-a)' is exactly zero"),
        ("x/(1/0)", 6, 1, "'0' is exactly zero"),
        ("x/(a/(-(1 - 1)))", 8, 7, "'(1 - 1)' is exactly zero"),
    ];
    for (input, column, width, quoted) in cases {
        let (c, w, message) = error_of(input);
        assert_eq!((c, w), (column, width), "{input}: {message}");
        assert!(
            message.starts_with("division by zero: "),
            "{input}: {message}"
        );
        assert!(message.contains(quoted), "{input}: {message}");
    }
}

#[test]
fn zero_to_a_negative_power_is_pointed_at_and_quoted_as_written() {
    let cases = [
        ("3*0^-1 + b", 3, "'0^-1'"),
        ("(a-a)^(-2) + x", 1, "'(a-a)^(-2)'"),
        ("2 * (a - a)^-1", 5, "'(a - a)^-1'"),
        ("sqrt(0)^-1", 1, "'sqrt(0)^-1'"),
    ];
    for (input, column, quoted) in cases {
        let (c, w, message) = error_of(input);
        assert_eq!((c, w), (column, quoted.len() - 2), "{input}: {message}");
        assert_eq!(
            message,
            format!("division by zero: {quoted} is zero to a negative power"),
            "{input}"
        );
    }
}

/// A long divisor is quoted shortened, on one line.
#[test]
fn a_long_divisor_is_quoted_shortened() {
    let terms: Vec<String> = (0..30).map(|k| format!("a_{k}")).collect();
    let sum = terms.join(" + ");
    let input = format!("y + x/(\n{sum} - ({sum}))");
    let e = parse_expression("input", &input).expect_err("a zero divisor");
    assert!(e.message.ends_with("...' is exactly zero"), "{}", e.message);
    assert!(!e.message.contains('\n'), "{}", e.message);
    assert_eq!((e.line, e.column), (1, 7));
}
