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
    // Before the expression clap takes `--fromat` for it and stops at `json`.
    for (args, named) in [
        (["latex", "-a", "--fromat", "json"], "'--fromat'"),
        (["latex", "--fromat", "json", "-a"], "'json'"),
    ] {
        let (code, out, err) = kinetics(&args);
        assert_eq!((code, out.as_str()), (2, ""), "{args:?}");
        assert!(err.contains(named), "{args:?}: {err}");
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
        // `mark` writes its outputs into `marked/` and never over an earlier run's.
        let marked = std::path::Path::new(root).join("marked");
        let _ = std::fs::remove_dir_all(&marked);
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_kinetics"))
            .args(&words[1..])
            .current_dir(root)
            .output()
            .expect("runs");
        let _ = std::fs::remove_dir_all(&marked);
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

/// What people type, the LaTeX `kinetics latex` writes of it, as written: order and
/// parentheses kept, only the notation changed.
const AS_WRITTEN: [(&str, &str); 12] = [
    ("-a^2 + b", "-a^2 + b"),
    ("1/2 m v^2", r"\frac{1}{2} m v^2"),
    (
        "b*a/(2*c) + w1*wdot_x",
        r"\frac{b a}{2 c} + \omega_1 \dot{\omega}_x",
    ),
    ("I_x*w_x - I_xy*w_y", r"I_x \omega_x - I_{xy} \omega_y"),
    (
        "F_2*Dt*b/(2*(-1/12*m*b^2 - 1/12*m*c^2))",
        r"\frac{F_2\,\Delta t\,b}{2 \left(-\frac{1}{12} m b^2 - \frac{1}{12} m c^2\right)}",
    ),
    ("sqrt(4*a^2*b) + sin(t)^2", r"\sqrt{4 a^2 b} + \sin^2 t"),
    ("(a + b)^2 - (a + b) + c", "(a + b)^2 - (a + b) + c"),
    (
        "H_x = I_x w_x - I_xy w_y",
        r"H_x = I_x \omega_x - I_{xy} \omega_y",
    ),
    ("a*-b - -b", "a (-b) - (-b)"),
    ("2*3*a^(1/2) + x^-2", r"2 \cdot 3 a^{1/2} + x^{-2}"),
    (
        "sin(beta) L + cos(30 deg)",
        r"\sin\beta\,L + \cos(30^\circ)",
    ),
    ("-a/b + c/d*e/f", r"-\frac{a}{b} + \frac{c}{d} \frac{e}{f}"),
];

/// `kinetics latex` keeps the user's order (`-a^2 + b`, with or without `--`); `--textbook`
/// gives `derive`'s order, `b - a^2`, and `simplify` its canonical form.
#[test]
fn latex_keeps_the_order_written() {
    for args in [&["latex", "-a^2 + b"][..], &["latex", "--", "-a^2 + b"]] {
        let (code, out, err) = kinetics(args);
        assert_eq!((code, out.trim()), (0, "-a^2 + b"), "{args:?}: {err}");
    }
    let (code, out, _) = kinetics(&["latex", "--textbook", "-a^2 + b"]);
    assert_eq!((code, out.trim()), (0, "b - a^2"));
    let (code, out, _) = kinetics(&["simplify", "-a^2 + b"]);
    assert_eq!((code, out.trim()), (0, "b - a^2"));
    for (input, latex) in AS_WRITTEN {
        let (code, out, err) = kinetics(&["latex", input]);
        assert_eq!((code, out.trim()), (0, latex), "{input}: {err}");
    }
    // What the algebra refuses is refused as before.
    let (code, _, err) = kinetics(&["latex", "a/(b - b)"]);
    assert_eq!(code, 1);
    assert!(err.contains("division by zero"), "{err}");
}

/// The text as written reads back to the same expression as the input (an independent
/// check of the order and parentheses kept: the canonical forms agree), and the terms are
/// in the order written.
#[test]
fn the_text_as_written_reads_back_to_the_input() {
    use kinetics::parse::as_written::statement_as_written;
    use kinetics::parse::parse_statement;
    for (input, _) in AS_WRITTEN {
        let (statement, written) = statement_as_written("t", input).expect("parses");
        assert_eq!(statement, parse_statement("t", input).expect("parses"));
        assert_eq!(
            parse_statement("t", &written.text).expect("reads back"),
            statement,
            "{input} -> {}",
            written.text
        );
    }
    let (_, written) = statement_as_written("t", "z + y - x").expect("parses");
    assert_eq!(written.text, "z + y - x");
}

/// Every LaTeX of the table compiles with pdflatex.
#[test]
fn latex_as_written_compiles() {
    let dir = std::env::temp_dir().join(format!("kinetics-as-written-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let body: String = AS_WRITTEN
        .iter()
        .map(|(_, latex)| format!("\\[ {latex} \\]\n"))
        .collect();
    let tex = dir.join("as_written.tex");
    std::fs::write(
        &tex,
        format!("\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\begin{{document}}\n{body}\\end{{document}}\n"),
    )
    .expect("writable");
    let compiled = crate::common::pdflatex::pdflatex(&dir, &tex);
    assert_eq!(compiled.first_error(), None);
}

/// A scene with one more given, `q = <quantity>`, its body and request around it.
fn scene_with_given(quantity: &str) -> String {
    format!(
        "given m = 2 kg\ngiven r = 0.1 m\ngiven q = {quantity}\nbody disk(r) mass m\nfixed point\nomega = 3 rad/s*k\nfind T\n"
    )
}

/// Every unit the program prints reads back as the same unit: the units of results are
/// `Dimension::si_unit`'s, so each dimension's (exponents of kg, m, s from -3 to 3: the
/// named ones such as N·m, kg·m²/s and rad/s², and the others as kg²·m or kg·m⁻¹·s⁻²) is
/// written as a given's unit, read, and printed again; its factor to SI is 1, exactly.
#[test]
fn every_printed_unit_reads_back() {
    use kinetics::scene::parse_scene;
    use kinetics::scene::units::Dimension;
    let mut read = 0;
    for mass in -3..=3 {
        for length in -3..=3 {
            for time in -3..=3 {
                let dimension = Dimension::new(mass, length, time);
                let printed = dimension.si_unit();
                if printed.is_empty() {
                    continue;
                }
                let text = scene_with_given(&format!("2 {printed}"));
                let scene = parse_scene("t.scene", &text)
                    .unwrap_or_else(|e| panic!("{printed}: {}", e.render()));
                let q = scene
                    .givens
                    .iter()
                    .find(|g| g.symbol.name() == "q")
                    .expect("q");
                assert_eq!(q.dimension, dimension, "{printed}");
                assert_eq!(q.dimension.si_unit(), printed);
                assert_eq!(
                    scene.exact_given(q.symbol),
                    Some(kinetics::algebra::Expr::int(2)),
                    "{printed}"
                );
                read += 1;
            }
        }
    }
    assert_eq!(read, 7 * 7 * 7 - 1);
}

/// Units as people write them: N·m, N*m, N m, kg·m^2, kg m², m/s^2, rad/s and ° in a given,
/// through the binary: the engineer's page shows the value read, in SI.
#[test]
fn units_as_people_write_them() {
    let dir = std::env::temp_dir().join(format!("kinetics-units-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    for (quantity, si) in [
        ("6 N·m", "6 N·m"),
        ("6 N*m", "6 N·m"),
        ("6 N m", "6 N·m"),
        ("6 kg·m^2", "6 kg·m²"),
        ("6 kg m²", "6 kg·m²"),
        ("6 m/s^2", "6 m/s²"),
        ("6 rad/s", "6 rad/s"),
        ("6 mm", "0.006 m"),
    ] {
        let path = dir.join("units.scene");
        std::fs::write(&path, scene_with_given(quantity)).expect("writable");
        let json = numbers_json(&path, quantity);
        let given = json["givens"]
            .as_array()
            .and_then(|g| g.iter().find(|g| g["name"] == "q"))
            .unwrap_or_else(|| panic!("{quantity}: {json}"));
        let (number, unit) = si.split_once(' ').expect("a number and a unit");
        assert_eq!(given["unit"], unit, "{quantity}");
        assert_eq!(
            given["si_value"].as_f64(),
            number.parse().ok(),
            "{quantity}: {given}"
        );
    }
    // The degree sign: 30° is π/6, whose sine is exactly 1/2 in a claim.
    let path = dir.join("degrees.scene");
    std::fs::write(&path, scene_with_given("30°")).expect("writable");
    let (code, out, err) = kinetics(&["check", path.to_str().unwrap(), "--claim", "sin(q) = 1/2"]);
    assert_eq!(code, 0, "{out}{err}");
}

/// Runs `solve` on a scene written to a temporary file: exit code and standard error.
fn solve_scene(name: &str, text: &str) -> (i32, String) {
    let dir = std::env::temp_dir().join(format!("kinetics-hints-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("writable");
    let (code, _, err) = kinetics(&["solve", path.to_str().unwrap()]);
    (code, err)
}

/// A unit used as a symbol (`d*mm`, `F*N`, `2*m_0*kg`) gets the hint to write the quantity
/// with its unit, not to declare the unit; a name that differs from a declared one only in
/// case or underscores gets that name.
#[test]
fn hints_name_the_right_fix() {
    let base =
        "given m = 2 kg\ngiven r = 0.1 m\nbody disk(r) mass m\nfixed point\nomega = 3 rad/s*k\n";
    let (code, err) = solve_scene(
        "mm.scene",
        &format!("{base}given d = 300 mm\npoint A at (d*mm, 0, 0)\nfind v_A\n"),
    );
    assert_eq!(code, 1);
    assert!(err.contains("unknown symbol mm"), "{err}");
    assert!(
        err.contains("write the quantity with its unit (300 mm)"),
        "{err}"
    );
    assert!(
        !err.contains("given mm ="),
        "the wrong fix is not offered: {err}"
    );
    for unit in ["kg", "N"] {
        let (code, err) = solve_scene(
            "unit.scene",
            &format!("{base}given F = 2 N\ncouple F*r*{unit}*k\nfind T\n"),
        );
        assert_eq!(code, 1, "{unit}");
        assert!(
            err.contains(&format!("write the quantity with its unit (300 {unit})")),
            "{err}"
        );
    }
    let (code, err) = solve_scene(
        "case.scene",
        &format!("{base}unknown C_Z : N\nforce C = C_Z*k at (r, 0, 0)\nfind C_z\n"),
    );
    assert_eq!(code, 1);
    assert!(err.contains("cannot find 'C_z'"), "{err}");
    assert!(err.contains("did you mean 'C_Z'?"), "{err}");
    let (code, err) = solve_scene(
        "underscore.scene",
        &format!("{base}given W1 = 2 rad/s\ncouple m*r^2*w_1^2*k\nfind T\n"),
    );
    assert_eq!(code, 1);
    assert!(err.contains("unknown symbol w_1"), "{err}");
    // W1 is the symbol W_1 (trailing digits are a subscript), which differs in case only.
    assert!(err.contains("did you mean W_1?"), "{err}");
}

/// `find … in UNIT` takes the units as printed and as people write them: the answer is in
/// the unit asked for (T = ½ I ω² = ½ (½ m r²) ω² = 0.045 J for m = 2 kg, r = 0.1 m,
/// ω = 3 rad/s about the disk's axis z, here along x' turned by `along z`).
#[test]
fn find_in_takes_units_as_written() {
    let scene = "given m = 2 kg\ngiven r = 0.1 m\nbody disk(r) mass m along z\nfixed point\nomega = 3 rad/s*k\n";
    let dir = std::env::temp_dir().join(format!("kinetics-find-in-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let path = dir.join("find_in.scene");
    let expected = 0.5 * (0.5 * 2.0 * 0.1 * 0.1) * 3.0 * 3.0;
    // Each as written, and as the page prints it.
    for (unit, printed) in [
        ("N·m", "N·m"),
        ("N m", "N·m"),
        ("N*m", "N·m"),
        ("J", "J"),
        ("kg·m²/s^2", "kg·m²/s²"),
        ("kg m^2 s⁻²", "kg·m²/s²"),
    ] {
        std::fs::write(&path, format!("{scene}find T in {unit}\n")).expect("writable");
        let json = numbers_json(&path, unit);
        let result = &json["results"][0];
        assert_eq!(result["unit"], printed, "{unit}");
        let value = result["value"].as_f64().expect("a number");
        assert!((value - expected).abs() < 1e-15, "{unit}: {value}");
    }
}

/// The README's quick-use lines of `kinetics latex` print what their comments say, the
/// leading-minus example among them.
#[test]
fn the_readme_latex_examples_hold() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("README.md");
    let mut checked = 0;
    for line in readme.lines().filter(|l| l.starts_with("kinetics latex ")) {
        let (command, comment) = line.split_once(" # ").expect("a comment");
        let expected = comment.split("   (").next().expect("the output").trim();
        let args = words(command);
        let (code, out, err) = kinetics(&args[1..].iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!((code, out.trim()), (0, expected), "{line}: {err}");
        checked += 1;
    }
    assert!(checked >= 3, "the README shows the latex examples");
    assert!(
        readme.contains("kinetics latex \"-a^2"),
        "a leading-minus example"
    );
}

/// The degree sign in a scene's mathematics and in an expression is the degree: a body
/// `rotated 30° about z` is the body `rotated 30 deg about z`, and `cos(60°)` is 1/2.
#[test]
fn the_degree_sign_is_the_degree() {
    let scene = |angle: &str| {
        format!("given m = 2 kg\ngiven r = 0.1 m\nbody disk(r) mass m rotated {angle} about z\nfixed point\nomega = 3 rad/s*k\nfind T, H_O\n")
    };
    let (code, with_sign) = solve_scene("sign.scene", &scene("30°"));
    assert_eq!(code, 0, "{with_sign}");
    let dir = std::env::temp_dir().join(format!("kinetics-hints-{}", std::process::id()));
    let solved = |name: &str| kinetics(&["solve", dir.join(name).to_str().unwrap()]).1;
    let sign = solved("sign.scene");
    solve_scene("word.scene", &scene("30 deg"));
    assert_eq!(sign, solved("word.scene"));
    assert!(sign.contains("T = "), "{sign}");
    let (code, out, err) = kinetics(&["simplify", "cos(60°)"]);
    assert_eq!((code, out.trim()), (0, "1/2"), "{err}");
}

/// `kinetics solve --numbers --format json` of the scene at `path`, which must succeed
/// (`case` names the input in the failure).
fn numbers_json(path: &std::path::Path, case: &str) -> serde_json::Value {
    let (code, out, err) = kinetics(&[
        "solve",
        "--numbers",
        "--format",
        "json",
        path.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{case}: {err}");
    serde_json::from_str(&out).expect("JSON")
}
