//! Located errors for encodings and a byte-order mark, and no control character of an input
//! echoed by an error (issue 29, part 4): through the binary, on standard input, arguments
//! and files.

use crate::common::binary::{kinetics, kinetics_with_input};

/// The byte-order mark some editors write first.
const MARK: &[u8] = "\u{feff}".as_bytes();

/// Input that is not UTF-8 on standard input is refused at its first invalid byte: the
/// line, the column and the byte offset, the line quoted with a caret under the byte.
#[test]
fn standard_input_that_is_not_utf8_is_refused_at_its_first_invalid_byte() {
    let input = b"a + b\nc * d\xff + e\n".to_vec();
    for args in [
        &["latex", "-"][..],
        &["simplify", "-"],
        &["check", "--claims", "-"],
    ] {
        let run = kinetics_with_input(args, input.clone());
        // `check` exits with 2 on an input error, the other commands with 1.
        assert!([1, 2].contains(&run.code), "{args:?}: {}", run.stderr);
        assert!(
            run.stderr
                .starts_with("error: not UTF-8 text: invalid byte 0xff at byte offset 11\n"),
            "{args:?}: {}",
            run.stderr
        );
        assert!(run.stderr.contains(" --> <stdin>:2:6\n"), "{}", run.stderr);
        assert!(
            run.stderr.contains("2 | c * d\u{fffd} + e\n"),
            "{}",
            run.stderr
        );
        assert!(run.stderr.contains("  |      ^ here\n"), "{}", run.stderr);
    }
}

/// A byte-order mark before the text is no part of it: on standard input, in an argument,
/// and in the files `solve`, `plan` and `check` (its scene and `--claims`) read.
#[test]
fn a_leading_byte_order_mark_is_ignored_in_every_input() {
    let marked = |text: &str| [MARK, text.as_bytes()].concat();
    let run = kinetics_with_input(&["latex", "-"], marked("a^2 + b"));
    assert_eq!(
        (run.code, run.stdout.trim()),
        (0, "a^2 + b"),
        "{}",
        run.stderr
    );
    let run = kinetics_with_input(&["simplify", "-"], marked("a + a"));
    assert_eq!((run.code, run.stdout.trim()), (0, "2*a"), "{}", run.stderr);
    let (code, out, err) = kinetics(&["latex", "--", "\u{feff}a^2"]);
    assert_eq!((code, out.trim()), (0, "a^2"), "{err}");
    let dir = std::env::temp_dir().join(format!("kinetics-mark-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let scene = dir.join("marked.scene");
    std::fs::write(
        &scene,
        marked("title Marked\ngiven m = 2 kg\ngiven w = 3 rad/s\ngiven r = 0.1 m\nbody sphere(r) mass m\nfixed point\nomega = w*k\nfind T\n"),
    )
    .expect("written");
    let claims = dir.join("marked.claims");
    std::fs::write(&claims, marked("T = 1/5*m*r^2*w^2\n")).expect("written");
    let scene = scene.to_str().expect("UTF-8");
    let claims = claims.to_str().expect("UTF-8");
    let runs = [
        kinetics(&["solve", scene]),
        kinetics(&["plan", scene]),
        kinetics(&["check", "--claims", claims, scene]),
    ];
    let _ = std::fs::remove_dir_all(&dir);
    for (code, out, err) in runs {
        assert_eq!(code, 0, "{err}\n{out}");
    }
}

/// An ESC sequence or a right-to-left override in an input never reaches the terminal from
/// an error: the message and the quoted line show it as `\u{1b}`.
#[test]
fn no_error_echoes_a_control_character() {
    let hostile = "a + \u{1b}[2J\u{1b}]0;pwned\u{7} \u{202e} $";
    let runs = [
        kinetics(&["latex", "--", hostile]),
        kinetics(&["simplify", "--", hostile]),
        kinetics(&["check", "--claim", &format!("T = {hostile}")]),
        kinetics(&["solve", "missing\u{1b}[2J.scene"]),
        kinetics(&["solve", "--format", "\u{1b}[2J", "x.scene"]),
    ];
    let piped = kinetics_with_input(&["latex", "-"], hostile);
    for (code, _, err) in runs
        .into_iter()
        .chain([(piped.code, piped.stdout, piped.stderr)])
    {
        assert_ne!(code, 0, "{err}");
        assert!(
            !err.contains(['\u{1b}', '\u{7}', '\u{202e}']),
            "a control character echoed: {err:?}"
        );
    }
    let (_, _, err) = kinetics(&["latex", "--", hostile]);
    assert!(
        err.contains(r"1 | a + \u{1b}[2J\u{1b}]0;pwned\u{7} \u{202e} $"),
        "{err}"
    );
}
