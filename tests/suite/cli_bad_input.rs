//! Bad input to the quick commands: a one-line error, a caret where it helps, a non-zero
//! exit, and never a panic, a stack overflow or a hang. (A generous time-out turns a hang
//! into a failure; no test asserts on how fast the program is.)

use crate::common::binary::{kinetics_with_input, Run};

/// `kinetics` with `args` and, when given, bytes on standard input.
fn kinetics(args: &[&str], stdin: Option<Vec<u8>>) -> Run {
    kinetics_with_input(args, stdin.unwrap_or_default())
}

fn assert_clean_error(o: &Run, needle: &str) {
    assert_eq!(o.code, 1, "exit code; stderr: {}", o.stderr);
    assert!(o.stdout.is_empty(), "nothing on stdout: {}", o.stdout);
    let first = o.stderr.lines().next().unwrap_or_default();
    assert!(
        first.starts_with("error: "),
        "first line is the error: {first}"
    );
    assert!(
        o.stderr.contains(needle),
        "stderr names the problem ({needle}): {}",
        o.stderr
    );
    assert!(!o.stderr.contains("panicked"), "no panic: {}", o.stderr);
}

#[test]
fn unclosed_parentheses_point_at_the_end() {
    let o = kinetics(&["simplify", "(((((("], None);
    assert_clean_error(&o, "input:1:7");
    assert!(o.stderr.contains("^ here"));
}

#[test]
fn deep_nesting_on_stdin_is_refused_not_overflowed() {
    let mut text = "(".repeat(100_000);
    text.push('x');
    text.push_str(&")".repeat(100_000));
    let o = kinetics(&["simplify", "-"], Some(text.into_bytes()));
    assert_clean_error(&o, "nested more than 200 levels");
}

#[test]
fn ten_megabytes_are_refused() {
    let text = "a+".repeat(5_000_000) + "a";
    let o = kinetics(&["simplify", "-"], Some(text.into_bytes()));
    assert_clean_error(&o, "limit of 1048576 bytes");
}

#[test]
fn huge_expansion_is_refused_before_it_starts() {
    let o = kinetics(&["simplify", "--expand", "(a+b)^99999999"], None);
    assert_clean_error(&o, "more than the limit of 100000");
}

#[test]
fn division_by_zero_and_nan() {
    assert_clean_error(&kinetics(&["simplify", "1/0"], None), "division by zero");
    assert_clean_error(&kinetics(&["simplify", "nan"], None), "not a finite number");
    assert_clean_error(&kinetics(&["latex", "x/(a - a)"], None), "division by zero");
}

#[test]
fn long_sums_and_prefix_runs_stay_bounded() {
    let many: String = (0..50_000).map(|i| format!("x{i} + ")).collect::<String>() + "y";
    let o = kinetics(&["simplify", "-"], Some(many.into_bytes()));
    assert_eq!(o.code, 0, "a long flat sum is fine: {}", o.stderr);
    let o = kinetics(
        &["simplify", "-"],
        Some(format!("{}x", "-".repeat(10_000)).into_bytes()),
    );
    assert_clean_error(&o, "signs in a row");
    let o = kinetics(
        &["simplify", "-"],
        Some(vec!["x"; 1000].join("^").into_bytes()),
    );
    assert_clean_error(&o, "powers nested");
}

#[test]
fn the_acceptance_example_prints_textbook_latex() {
    let o = kinetics(&["latex", "I_x*w_x - I_xy*w_y - I_xz*w_z"], None);
    assert_eq!(o.code, 0);
    assert_eq!(
        o.stdout.trim(),
        r"I_x \omega_x - I_{xy} \omega_y - I_{xz} \omega_z"
    );
    let o = kinetics(
        &["latex", "--textbook", "-"],
        Some(b"M_y = I_y*wdot_y + (I_x - I_z)*w_z*w_x".to_vec()),
    );
    assert_eq!(
        o.stdout.trim(),
        r"M_y = I_y \dot{\omega}_y - (I_z - I_x) \omega_z \omega_x"
    );
    let o = kinetics(&["simplify", "--format", "json", "0.1 + x/2"], None);
    let v: serde_json::Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(v["text"], "1/2*x + 1/10");
    assert_eq!(v["latex"], r"\frac{1}{2} x + \frac{1}{10}");
}
