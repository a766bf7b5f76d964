//! `kinetics check --derivation`: a hand derivation line by line, a wrong line's slip named
//! and the later lines that are right from it `follows from` it (error carried forward).
//! Each expected verdict is derived by hand in the comment above it.

use crate::common::check::{context_args, kinetics_with_input, Run};
use serde_json::Value;

/// `kinetics check CONTEXT --derivation - --format json` on `text`.
fn derivation(context: &str, text: &str) -> (Run, Value) {
    let mut args = vec!["check".to_owned()];
    args.extend(context_args(context));
    args.extend(["--derivation", "-", "--format", "json"].map(String::from));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let run = kinetics_with_input(&args, text);
    let json = serde_json::from_str(&run.stdout)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {}\n{}", run.stdout, run.stderr));
    (run, json)
}

/// Each line of part `k`: (its line, its verdict, its reading, what it follows from).
fn lines(json: &Value, k: usize) -> Vec<(u64, String, Option<String>, Vec<u64>)> {
    json["parts"][k]["lines"]
        .as_array()
        .expect("a part has lines")
        .iter()
        .map(|l| {
            (
                l["line"].as_u64().expect("a line number"),
                l["verdict"].as_str().expect("a verdict").to_owned(),
                l["reading"].as_str().map(str::to_owned),
                l["follows_from"]
                    .as_array()
                    .expect("follows_from")
                    .iter()
                    .map(|n| n.as_u64().expect("a line"))
                    .collect(),
            )
        })
        .collect()
}

/// Each line of part `k`: its verdict and what it follows from.
fn verdicts(json: &Value, k: usize) -> Vec<(String, Vec<u64>)> {
    lines(json, k)
        .into_iter()
        .map(|(_, v, _, from)| (v, from))
        .collect()
}

/// The verdicts derived by hand, as [`verdicts`] gives them.
fn by_hand(expected: &[(&str, &[u64])]) -> Vec<(String, Vec<u64>)> {
    expected
        .iter()
        .map(|(v, from)| (v.to_string(), from.to_vec()))
        .collect()
}

const SP18_4: &str = "examples/scenes/sp18_4_shaft_reactions.scene";

/// SP 18.4's D_y. Moments about C: the reaction D_y j at L i has the moment
/// L i × D_y j = +L D_y k, and Ḣ_z = −I_xz α − I_xy ω² = −⅛ m L c α − ¼ m L c ω², so the
/// truth is L D_y = −⅛ m L c α − ¼ m L c ω², D_y = −3M/(16c) − ¼ m c ω² (α = 3M/(2 m c²))
/// = −11.25 − 118.50 = −129.75 N. Line 2 writes −L D_y (the moment's sign flipped): the
/// whole side is −1 times the correct one. From it, D_y = +⅛ m c α + ¼ m c ω² (line 3,
/// divided by −L), = 3M/(16c) + ¼ m c ω² (line 4, α put in) = +129.8 N (line 5): each is
/// wrong, and each follows from line 2.
#[test]
fn a_sign_slip_in_line_2_is_carried_by_lines_3_to_5() {
    let text = "\
Hdot_z = -I_xz alpha - I_xy w^2
-D_y L = -1/8 m L c alpha - 1/4 m L c w^2
D_y = 1/8 m c alpha + 1/4 m c w^2
D_y = 3 M/(16 c) + 1/4 m c w^2
D_y = 129.8 N
";
    let (run, json) = derivation(SP18_4, text);
    let got = lines(&json, 0);
    let verdicts: Vec<(&str, Vec<u64>)> = got
        .iter()
        .map(|(_, v, _, from)| (v.as_str(), from.clone()))
        .collect();
    assert_eq!(
        verdicts,
        [
            ("holds", vec![]),
            ("differs", vec![]),
            ("follows", vec![2]),
            ("follows", vec![2]),
            ("follows", vec![2]),
        ],
        "{}",
        run.stdout
    );
    assert_eq!(
        got[1].2.as_deref(),
        Some("scaled"),
        "the slip of line 2 is named"
    );
    assert_eq!(json["parts"][0]["first_slip"]["line"], 2);
    assert_eq!(
        json["parts"][0]["first_slip"]["carried_by"],
        serde_json::json!([3, 4, 5])
    );
    assert_eq!(run.code, 1, "a derivation with a wrong line fails");
}

/// A slip carried through a line that holds: line 1 (L D_y = Ḣ_z) is true; line 2 flips the
/// sign of I_xz α in Ḣ_z; line 3 puts line 2 into line 1; line 4 puts in I_xz = ⅛ m L c and
/// I_xy = ¼ m L c: D_y = ⅛ m c α − ¼ m c ω², wrong, from line 2. Line 5 is ΣF_y = m ā_y,
/// true (C_y + D_y = −½ m c (α + ω²)); line 6 solves it for C_y with line 4's D_y, so it
/// follows from line 2 as well. Line 7 writes C_y = −½ m c (α + ω²) − D_y with the truth's
/// D_y = −⅛ m c α − ¼ m c ω² but ¼ m c ω² given the wrong sign: −⅜ m c α − ¾ m c ω² against
/// the correct −⅜ m c α − ¼ m c ω², and against line 4's D_y (−⅝ m c α − ¼ m c ω²) too: a
/// slip of its own, which follows from nothing.
#[test]
fn a_slip_is_carried_through_a_line_that_holds() {
    let text = "\
D_y L = Hdot_z
Hdot_z = I_xz alpha - I_xy w^2
D_y = (I_xz alpha - I_xy w^2)/L
D_y = 1/8 m c alpha - 1/4 m c w^2
C_y + D_y = -1/2 m c alpha - 1/2 m c w^2
C_y = -1/2 m c alpha - 1/2 m c w^2 - 1/8 m c alpha + 1/4 m c w^2
C_y = -1/2 m c alpha - 1/2 m c w^2 + 1/8 m c alpha - 1/4 m c w^2
";
    let (run, json) = derivation(SP18_4, text);
    let verdicts = verdicts(&json, 0);
    let expected = by_hand(&[
        ("holds", &[]),
        ("differs", &[]),
        ("follows", &[2]),
        ("follows", &[2]),
        ("holds", &[]),
        ("follows", &[2]),
        ("differs", &[]),
    ]);
    assert_eq!(verdicts, expected, "{}", run.stdout);
    assert_eq!(lines(&json, 0)[1].2.as_deref(), Some("sign-flipped"));
}

/// Euler's first equation for principal axes, ΣM_x = I_x ω̇_x − (I_y − I_z) ω_y ω_z: line 3
/// writes ΣM_x again with the gyroscopic term reversed. It meets no new quantity, so the slip
/// is in the algebra: it does not follow from line 2. Line 4 solves line 3 for ω̇_x, right
/// from it.
#[test]
fn a_line_relating_quantities_already_given_does_not_follow_from_them() {
    let text = "\
# Euler's equation about x
SumM_x = I_x wdot_x - (I_y - I_z) w_y w_z
SumM_x = I_x wdot_x + (I_y - I_z) w_y w_z
wdot_x = (SumM_x - (I_y - I_z) w_y w_z)/I_x
";
    let (run, json) = derivation("principal", text);
    let first: Vec<(u64, String, Vec<u64>)> = lines(&json, 0)
        .into_iter()
        .map(|(l, v, _, from)| (l, v, from))
        .collect();
    assert_eq!(
        first,
        [
            (2, "holds".to_owned(), vec![]),
            (3, "differs".to_owned(), vec![]),
            (4, "follows".to_owned(), vec![3]),
        ],
        "{}",
        run.stdout
    );
    assert_eq!(
        json["parts"][0]["lines"][1]["does_not_follow"],
        serde_json::json!([2])
    );
}

/// A blank line starts a part, and a later part takes what the earlier ones gave: part (b)
/// states D_y from part (a)'s wrong moment, −L D_y for L D_y, so D_y = +129.8 N follows.
#[test]
fn a_later_part_carries_an_earlier_parts_slip() {
    let text = "# (a)\n-D_y L = -1/8 m L c alpha - 1/4 m L c w^2\n\n# (b)\nD_y = 129.8 N\n";
    let (run, json) = derivation(SP18_4, text);
    assert_eq!(lines(&json, 0)[0].1, "differs", "{}", run.stdout);
    assert_eq!(lines(&json, 1)[0].1, "follows", "{}", run.stdout);
    assert_eq!(lines(&json, 1)[0].3, vec![2]);
}

/// Numbers carry a slip too. Line 1 is L D_y = Ḣ_z, true; line 2 divides by L but turns the
/// sign of I_xy ω²/L (an algebra slip: it meets no new quantity); line 3 puts the numbers in
/// (I_xz α/L = ⅛ m c α = 11.25, I_xy ω²/L = ¼ m c ω² = 118.5037), rounded; line 4 adds them.
/// Both follow from line 2, within the tolerance of line 2's own value, 107.2537.
#[test]
fn rounded_numbers_carry_the_slip() {
    let text = "\
L D_y = -I_xz alpha - I_xy w^2
D_y = -I_xz alpha/L + I_xy w^2/L
D_y = -11.25 + 118.5
D_y = 107.25
";
    let (run, json) = derivation(SP18_4, text);
    let got = verdicts(&json, 0);
    let expected = by_hand(&[
        ("holds", &[]),
        ("differs", &[]),
        ("follows", &[2]),
        ("follows", &[2]),
    ]);
    assert_eq!(got, expected, "{}", run.stdout);
    assert_eq!(
        json["parts"][0]["lines"][1]["does_not_follow"],
        serde_json::json!([1])
    );
}

/// A line that cannot be read is an error at its line, and the others are still checked.
#[test]
fn a_line_that_cannot_be_read_is_named_and_the_rest_checked() {
    let (run, json) = derivation(SP18_4, "alpha = 3 M/(2 m c^2)\nD_y = = 2\nalpha = 3000\n");
    let got = lines(&json, 0);
    assert_eq!(got[1].1, "error");
    assert_eq!((got[0].1.as_str(), got[2].1.as_str()), ("holds", "holds"));
    assert!(
        run.stderr.contains(":2:"),
        "the error names line 2: {}",
        run.stderr
    );
    assert_eq!(run.code, 2);
}

/// The text report says which line a carried line follows from, and sums up the part.
#[test]
fn the_text_report_names_the_first_slip_and_the_lines_carrying_it() {
    let text = "Hdot_z = -I_xz alpha - I_xy w^2\n-D_y L = -1/8 m L c alpha - 1/4 m L c w^2\nD_y = 129.8 N\n";
    let run = kinetics_with_input(
        &["check", &context_args(SP18_4)[0], "--derivation", "-"],
        text,
    );
    assert!(
        run.stdout
            .contains("follows from line 2 (<stdin>:3): D_y = 129.8 N"),
        "{}",
        run.stdout
    );
    assert!(
        run.stdout
            .contains("D_y, correct: -3*M/(16*c) - 1/4*m*c*w^2 = -129.8 N"),
        "{}",
        run.stdout
    );
    assert!(
        run.stdout
            .contains("lines 1-3: first wrong line 2 (scaled); line 3 carries it"),
        "{}",
        run.stdout
    );
}

/// In LaTeX, a carried line is a paragraph saying which line it follows from, with the
/// correct form in mathematics; the part's summary is a comment.
#[test]
fn the_latex_report_says_which_line_a_carried_line_follows_from() {
    let text = "Hdot_z = -I_xz alpha - I_xy w^2\n-D_y L = Hdot_z\nD_y = 129.8 N\n";
    let run = kinetics_with_input(
        &[
            "check",
            &context_args(SP18_4)[0],
            "--derivation",
            "-",
            "--format",
            "latex",
        ],
        text,
    );
    assert!(
        run.stdout
            .contains(r"stdin\textgreater{}:2 differs (scaled).}"),
        "{}",
        run.stdout
    );
    assert!(
        run.stdout
            .contains(r"stdin\textgreater{}:3 follows from line 2.}"),
        "{}",
        run.stdout
    );
    assert!(
        run.stdout.contains(
            r"D\_y, correct: $-\frac{3 M}{16 c} - \frac{1}{4} m c \omega^2$ = $-$129.8 N."
        ),
        "{}",
        run.stdout
    );
    assert!(run
        .stdout
        .contains("% lines 1-3: first wrong line 2 (scaled); line 3 carries it"));
}
