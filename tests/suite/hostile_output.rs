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

/// Powers of numbers in scientific notation, with signed and fractional exponents, and a
/// degree after a superscript (`{}^\circ`, never a second superscript).
const SCIENTIFIC_POWERS: [&str; 11] = [
    "1e5 deg",
    "1e5°",
    "x^2°",
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
                !out.replace("{}^", "").contains("}^"),
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

/// A title a hostile user might write: a tag, a right-to-left override, an ESC sequence,
/// the bell, an ampersand, mathematics with `<` and words with `<` in it, and letters of
/// scripts the page's fonts lack (Greek, accented Latin, Chinese, an emoji).
const HOSTILE_TITLE: &str = "<script>alert(1)</script> \u{202e}drawkcab \u{1b}[2J\u{1b}[31m \
     & $a<b$ $\\text{<img src=x>&amp;}$ θ é 中 😀 \u{7}";

/// The sliding box of the examples under [`HOSTILE_TITLE`], written in `dir`.
fn hostile_scene(dir: &std::path::Path) -> String {
    let example = std::fs::read_to_string(crate::common::binary::scene("sliding_box"))
        .expect("the example is there");
    let body: Vec<&str> = example
        .lines()
        .filter(|l| !l.starts_with("title"))
        .collect();
    let scene = dir.join("hostile.scene");
    std::fs::write(
        &scene,
        format!("title {HOSTILE_TITLE}\n{}\n", body.join("\n")),
    )
    .expect("the scene is written");
    scene.to_str().expect("a UTF-8 path").to_string()
}

/// Whether `text` shows a character a reader cannot see as itself.
fn hidden(text: &str) -> Option<char> {
    text.chars().find(|c| kinetics::visible::is_hidden(*c))
}

/// The standalone LaTeX of a scene under a hostile title compiles with pdflatex: `<` and
/// `>` are `\textless{}` and `\textgreater{}` (OT1 would set ¡ and ¿), the characters the
/// fonts lack and the controls are their escapes in typewriter letters.
#[test]
fn a_hostile_title_compiles_in_latex() {
    let dir = scratch("hostile-latex");
    let path = hostile_scene(&dir);
    let (code, latex, err) = kinetics(&["solve", "--format", "latex", "--standalone", &path]);
    assert_eq!(code, 0, "{err}");
    let title = latex
        .lines()
        .find(|l| l.starts_with(r"\section*"))
        .unwrap_or_default();
    for shown in [
        r"\textless{}script\textgreater{}",
        r"\texttt{\textbackslash u\{202e\}}",
        r"\texttt{\textbackslash u\{1b\}}",
        r"\texttt{\textbackslash u\{4e2d\}}",
        r"$\theta$",
        "é",
    ] {
        assert!(title.contains(shown), "{shown} in {title}");
    }
    assert_eq!(hidden(&latex), None, "{title}");
    let error = latex_error(&dir, "hostile", &latex);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(error.is_none(), "{}\n\n{title}", error.unwrap_or_default());
}

/// Markdown and HTML of the same scene hold no tag of the title (no raw `<script`, `<img`
/// anywhere, `<` and `>` not at all in Markdown), no `&` of it as itself, and the text,
/// Markdown and HTML pages show the controls and the override escaped.
#[test]
fn a_hostile_title_injects_nothing_in_markdown_html_or_text() {
    let dir = scratch("hostile-pages");
    let path = hostile_scene(&dir);
    let page = |format: &str| {
        let (code, out, err) = kinetics(&["solve", "--format", format, &path]);
        assert_eq!(code, 0, "{format}: {err}");
        out
    };
    let (markdown, html, text) = (page("markdown"), page("html"), page("text"));
    let _ = std::fs::remove_dir_all(&dir);
    let heading = markdown.lines().next().unwrap_or_default();
    assert!(
        !markdown.contains("<script") && !markdown.contains("<img"),
        "{heading}"
    );
    assert!(!markdown.contains(['<', '>']), "{heading}");
    assert!(
        !heading.contains("& ") && !heading.contains("&amp;}"),
        "{heading}"
    );
    assert!(heading.contains(r"$a \lt b$"), "{heading}");
    assert!(
        heading.contains(r"$\lt \text{img src=x}\gt \And \text{amp;}$"),
        "{heading}"
    );
    assert!(
        !html.contains("<script") && !html.contains("<img"),
        "{html}"
    );
    for (format, page) in [("markdown", &markdown), ("html", &html), ("text", &text)] {
        assert_eq!(hidden(page), None, "{format}");
        assert!(
            page.contains(r"u{202e}") && page.contains(r"u{1b}"),
            "{format}"
        );
    }
}

/// Every character the LaTeX escaper sets as itself compiles in a title, and every other
/// one is escaped: all of U+00A0 to U+017F, the common punctuation, other scripts, symbols
/// and controls, in a section title and in text.
#[test]
fn every_character_of_a_title_compiles_in_latex() {
    let dir = scratch("title-characters");
    let characters: String = ('\u{a0}'..='\u{17f}')
        .chain("–—‘’“”†‡•…‰€™←≤√∞ΣΩωאبक中あ한😀\u{0}\u{8}\u{7f}\u{85}\u{200b}\u{200f}\u{2028}\u{fffd}\u{301}".chars())
        .collect();
    let words = kinetics::print::markup::latex_words(&characters);
    let document = format!(
        "\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\usepackage{{amssymb}}\n\\begin{{document}}\n\\section*{{{words}}}\n{words}\n\\end{{document}}\n"
    );
    let error = latex_error(&dir, "characters", &document);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(error.is_none(), "{}\n\n{words}", error.unwrap_or_default());
}
