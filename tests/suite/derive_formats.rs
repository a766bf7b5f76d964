//! `kinetics derive` is as capable as `solve`: Markdown, standalone LaTeX, headings (never `%`
//! comments), and the reference point and axes each derivation is about.

use crate::common::binary::kinetics;

fn derive(args: &[&str]) -> String {
    let mut all = vec!["derive", "--general"];
    all.extend_from_slice(args);
    let (code, stdout, stderr) = kinetics(&all);
    assert_eq!(code, 0, "{stderr}");
    stdout
}

#[test]
fn latex_has_headings_not_comments() {
    let latex = derive(&["--only", "H_G,fixed_axis", "--steps", "--format", "latex"]);
    assert!(!latex.lines().any(|l| l.starts_with('%')), "{latex}");
    assert_eq!(latex.matches(r"\section*{").count(), 2, "{latex}");
    assert!(latex.matches(r"\subsection*{").count() >= 4, "{latex}");
}

#[test]
fn each_derivation_states_its_reference_point() {
    let text = derive(&["--only", "H_G,T_O,fixed_axis"]);
    let sections: Vec<&str> = text.split("\n# ").collect();
    assert_eq!(sections.len(), 3, "{text}");
    assert!(sections[0].contains("mass centre G"), "{}", sections[0]);
    assert!(sections[1].contains("fixed point O"), "{}", sections[1]);
    assert!(
        sections[2].contains("fixed point O") && sections[2].contains("rotation about z"),
        "{}",
        sections[2]
    );
}

#[test]
fn markdown_has_headings_and_display_maths() {
    let md = derive(&["--only", "euler", "--steps", "--format", "markdown"]);
    assert!(md.starts_with("## "), "{md}");
    assert!(md.contains("\n### "), "{md}");
    assert!(md.contains("$$\n\\begin{align*}"), "{md}");
    assert_eq!(md.matches("$$").count() % 2, 0, "{md}");
}

#[test]
fn standalone_is_a_whole_document_and_only_with_latex() {
    let doc = derive(&["--only", "T", "--format", "latex", "--standalone"]);
    assert!(doc.starts_with(r"\documentclass"), "{doc}");
    assert!(doc.trim_end().ends_with(r"\end{document}"), "{doc}");
    let (code, _, stderr) = kinetics(&["derive", "--general", "--standalone"]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("--standalone goes with --format latex"),
        "{stderr}"
    );
}

#[test]
fn json_titles_carry_text_and_latex() {
    let json: serde_json::Value =
        serde_json::from_str(&derive(&["--only", "Hdot", "--format", "json"])).unwrap();
    let d = &json[0];
    assert_eq!(d["name"], "Hdot");
    assert!(d["convention"].as_str().is_some_and(|c| c.contains('G')));
    for step in d["steps"].as_array().unwrap() {
        let text = step["title"].as_str().unwrap();
        assert!(!text.contains('$') && !text.contains('\\'), "{text}");
        assert!(step["title_latex"].as_str().is_some());
    }
}

/// A shaft along x (the chapter's Sample Problems 18.4, 18.5): with `ω = ω i`,
/// `Ḣ_O = [I]{α i} + ω i × [I]{ω i}`; by hand, `[I]{i} = (I_x, -I_xy, -I_xz)` and
/// `i × (I_x, -I_xy, -I_xz) = (0, I_xz, -I_xy)`, so `ΣM_y = -I_xy α + I_xz ω²` and
/// `ΣM_z = -I_xz α - I_xy ω²`; bearing B at `x = l`: `l i × (B_y j + B_z k) = (0, -l B_z, l B_y)`.
#[test]
fn fixed_axis_along_x_is_the_hand_derivation() {
    let text = derive(&["--only", "fixed_axis,reactions", "--axis", "x"]);
    for line in [
        "SumM_x = I_x*alpha",
        "SumM_y = -I_xy*alpha + I_xz*w^2",
        "SumM_z = -I_xz*alpha - I_xy*w^2",
        "B_y = -I_xz*alpha/l - I_xy*w^2/l",
        "B_z = I_xy*alpha/l - I_xz*w^2/l",
    ] {
        assert!(text.lines().any(|l| l.trim() == line), "{line} in\n{text}");
    }
    assert!(text.contains("rotation about x"), "{text}");
}
