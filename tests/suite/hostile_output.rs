//! Output that always compiles and never injects (issue 29, part 3): every notation a
//! command writes is checked the way a reader meets it, LaTeX by compiling it with pdflatex.

use crate::common::binary::kinetics;
use crate::common::pdflatex::pdflatex;
use std::path::PathBuf;

/// A scratch folder of this test process, for `.tex` files and scenes.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kinetics-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    dir
}

/// The first pdflatex error of `body` in a document with the standalone page's packages.
fn latex_error(dir: &std::path::Path, stem: &str, document: &str) -> Option<String> {
    let tex = dir.join(format!("{stem}.tex"));
    std::fs::write(&tex, document).expect("the .tex is written");
    pdflatex(dir, &tex).first_error()
}

/// Powers of numbers in scientific notation, with signed and fractional exponents.
const SCIENTIFIC_POWERS: [&str; 8] = [
    "1e5^2",
    "(1e5)^2",
    "1e-5^2",
    "2.5e10^(1/2)",
    "x^1e5",
    "(1e5)^(-2)",
    "-2.5E+3^2*x",
    "sin(1e5^2) + 1e5^2/3",
];

/// `kinetics latex` (as written and `--textbook`), its JSON's LaTeX and `simplify --format
/// latex` of every power of a number in scientific notation compile in one document: the
/// number is fenced before its exponent, never `10^{5}^2` (a double superscript) or
/// `10^{5)}` (a parenthesis inside the braces).
#[test]
fn powers_of_numbers_in_scientific_notation_compile() {
    let dir = scratch("scientific-powers");
    let mut document = String::from(
        "\\documentclass{article}\n\\usepackage{amsmath}\n\\usepackage{amssymb}\n\\begin{document}\n",
    );
    for input in SCIENTIFIC_POWERS {
        let commands: [&[&str]; 3] = [
            &["latex", "--", input],
            &["latex", "--textbook", "--", input],
            &["simplify", "--format", "latex", "--", input],
        ];
        for args in commands {
            let (code, out, err) = kinetics(args);
            assert_eq!(code, 0, "{args:?}: {err}");
            assert!(
                !out.contains("}^"),
                "{args:?} writes a double superscript: {out}"
            );
            document.push_str(&format!("${}$\n\n", out.trim()));
        }
        let (code, json, err) = kinetics(&["latex", "--format", "json", "--", input]);
        assert_eq!(code, 0, "{input}: {err}");
        let json: serde_json::Value = serde_json::from_str(&json).expect("JSON");
        document.push_str(&format!("${}$\n\n", json["latex"].as_str().expect("latex")));
    }
    document.push_str("\\end{document}\n");
    let error = latex_error(&dir, "powers", &document);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        error.is_none(),
        "{}\n\n{document}",
        error.unwrap_or_default()
    );
}

/// The text as written of those powers reads back to the same value: `1e5^2` is `(1e5)^2`
/// in the grammar, so the text keeps it as typed, and `(1e5)` loses only parentheses a
/// number never needs.
#[test]
fn powers_of_numbers_in_scientific_notation_read_back_as_text() {
    for input in SCIENTIFIC_POWERS {
        let (code, text, err) = kinetics(&["latex", "--format", "text", "--", input]);
        assert_eq!(code, 0, "{input}: {err}");
        let value = |e: &str| kinetics(&["simplify", "--", e]).1;
        assert_eq!(value(text.trim()), value(input), "{input} as text: {text}");
    }
}

/// A given angle in scientific notation: its degree sign is not a second superscript on
/// the power of ten, in LaTeX (compiled) and in MathML (fenced, `(1.5 × 10⁵)°`).
#[test]
fn an_angle_in_scientific_notation_is_fenced_before_its_degree_sign() {
    let dir = scratch("scientific-angle");
    let scene = dir.join("angle.scene");
    std::fs::write(
        &scene,
        "given m = 2 kg\ngiven beta = 1.5e5 deg\ngiven w = 3 rad/s\ngiven r = 0.1 m\nbody sphere(r) mass m\n\
         fixed point\nomega = w*k\nfind T\n",
    )
    .expect("the scene is written");
    let path = scene.to_str().expect("a UTF-8 path");
    let (code, latex, err) = kinetics(&["solve", "--format", "latex", "--standalone", path]);
    assert_eq!(code, 0, "{err}");
    assert!(latex.contains(r"(1.5\times 10^{5})^\circ"), "{latex}");
    let error = latex_error(&dir, "angle", &latex);
    let (code, html, err) = kinetics(&["solve", "--format", "html", path]);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(error.is_none(), "{}\n\n{latex}", error.unwrap_or_default());
    assert_eq!(code, 0, "{err}");
    assert!(
        html.contains("<mo>(</mo><mrow><mn>1.5</mn><mo>×</mo><msup><mn>10</mn><mn>5</mn></msup></mrow><mo>)</mo>"),
        "{html}"
    );
}
