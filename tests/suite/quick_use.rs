//! Issue 20: the one-line commands as people type them, through the binary. An expression
//! that begins with a minus, the user's own order kept by `latex`, units as printed, hints
//! that name the right fix, and one real example in each command's help.

use crate::common::binary::kinetics;

/// An expression or equation beginning with `-` is the expression, for every command that
/// takes one, without `--`; the real options still work before and after it, and a
/// misspelt option is still an error.
#[test]
fn a_leading_minus_is_the_expression() {
    let (code, out, err) = kinetics(&["latex", "-a^2 + b"]);
    assert_eq!((code, out.trim()), (0, "-a^2 + b"), "{err}");
    let (code, out, err) = kinetics(&["simplify", "-a - a"]);
    assert_eq!((code, out.trim()), (0, "-2*a"), "{err}");
    let (code, out, err) = kinetics(&["check", "--claim", "-a*b = -(b*a)"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.starts_with("holds"), "{out}");
    for args in [
        ["latex", "--format", "json", "-a"],
        ["latex", "-a", "--format", "json"],
    ] {
        let (code, out, err) = kinetics(&args);
        assert_eq!(code, 0, "{args:?}: {err}");
        let json: serde_json::Value = serde_json::from_str(&out).expect("JSON");
        assert_eq!(json["text"], "-a", "{args:?}");
    }
    for args in [
        ["latex", "-a", "--fromat", "json"],
        ["latex", "--fromat", "json", "-a"],
    ] {
        let (code, out, err) = kinetics(&args);
        assert_eq!((code, out.as_str()), (2, ""), "{args:?}");
        assert!(err.contains("--fromat"), "{args:?}: {err}");
    }
    let (code, out, err) = kinetics(&["simplify", "--expnad"]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("not an option"), "{err}");
}

/// The example lines of a help text: those after `Example:`, indented.
fn examples(help: &str) -> Vec<String> {
    help.lines()
        .skip_while(|l| l.trim() != "Example:")
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .map(|l| l.trim().to_string())
        .collect()
}

/// Splits a shell line into words: spaces separate, double quotes group.
fn words(line: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ' ' if !quoted => out.push(String::new()),
            c => out.last_mut().expect("a word").push(c),
        }
    }
    out.retain(|w| !w.is_empty());
    out
}

/// `kinetics --help` and each command's help show one example, and running it succeeds
/// (from the crate's folder, where the example scenes are).
#[test]
fn every_help_carries_an_example_that_runs() {
    let (_, top, _) = kinetics(&["--help"]);
    let commands: Vec<String> = top
        .lines()
        .skip_while(|l| l.trim() != "Commands:")
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next().map(str::to_string))
        .filter(|c| c != "help")
        .collect();
    assert!(commands.len() >= 8, "{top}");
    let mut helps = vec![(String::from("kinetics"), top.clone())];
    for command in &commands {
        let (code, help, err) = kinetics(&[command, "--help"]);
        assert_eq!(code, 0, "{command}: {err}");
        helps.push((command.clone(), help));
    }
    let (_, work_precision, _) = kinetics(&["bench", "work-precision", "--help"]);
    helps.push(("bench work-precision".into(), work_precision));
    let root = env!("CARGO_MANIFEST_DIR");
    for (command, help) in helps {
        let lines = examples(&help);
        assert_eq!(lines.len(), 1, "{command}: one example\n{help}");
        let words = words(&lines[0]);
        assert_eq!(words[0], "kinetics", "{command}: {}", lines[0]);
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_kinetics"))
            .args(&words[1..])
            .current_dir(root)
            .output()
            .expect("runs");
        // `check` exits 1 when its example's claim differs, a verdict like any other.
        let verdict = command == "check" && out.status.code() == Some(1);
        assert!(
            (out.status.success() || verdict) && !out.stdout.is_empty(),
            "{command}: {} failed: {}",
            lines[0],
            String::from_utf8_lossy(&out.stderr)
        );
    }
}
