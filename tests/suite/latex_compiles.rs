//! Every example's `--standalone` LaTeX, its figure (TikZ) before Given, compiles with pdflatex
//! (amsmath and TikZ), and so does
//! `kinetics check --format latex` in a minimal document. `.ci/run` installs pdflatex from
//! Debian's packages when it is missing, so these tests never skip.

use crate::common::pdflatex::pdflatex;
use std::path::Path;
use std::process::Command;

#[test]
fn every_example_compiles_with_pdflatex() {
    let out_dir = std::env::temp_dir().join(format!("kinetics-latex-{}", std::process::id()));
    std::fs::create_dir_all(&out_dir).expect("a temporary folder");
    let scenes = crate::common::examples::example_scenes();
    assert!(scenes.len() >= 5, "the sample problems are there");
    let mut failures = Vec::new();
    for scene in &scenes {
        let stem = scene
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or("scene");
        let latex = Command::new(env!("CARGO_BIN_EXE_kinetics"))
            .args(["solve", "--format", "latex", "--standalone"])
            .arg(scene)
            .output()
            .expect("kinetics runs");
        assert!(
            latex.status.success(),
            "{stem}: {}",
            String::from_utf8_lossy(&latex.stderr)
        );
        let page = String::from_utf8_lossy(&latex.stdout);
        let figure = page.find("\\begin{tikzpicture}");
        let given = page.find("\\paragraph{Given}");
        assert!(
            figure.is_some_and(|f| given.is_some_and(|g| f < g)),
            "{stem}: the figure before Given"
        );
        let tex = out_dir.join(format!("{stem}.tex"));
        std::fs::write(&tex, &latex.stdout).expect("the .tex is written");
        if let Some(first_error) = pdflatex_error(&out_dir, &tex) {
            failures.push(format!("{stem}:\n{first_error}"));
        }
    }
    let _ = std::fs::remove_dir_all(&out_dir);
    assert!(
        failures.is_empty(),
        "LaTeX errors:\n{}",
        failures.join("\n\n")
    );
}

/// The first LaTeX error of compiling `tex` in `dir`, if any.
fn pdflatex_error(dir: &Path, tex: &Path) -> Option<String> {
    pdflatex(dir, tex).first_error()
}

/// A check's LaTeX report compiles: every verdict and reading, a vector claim, a claim of pure
/// algebra, an odd term, a power of a power, a claims file whose name has underscores, a slip
/// of the mechanics and claims in numbers.
#[test]
fn a_check_report_compiles_with_pdflatex() {
    let dir = std::env::temp_dir().join(format!("kinetics-check-latex-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let claims = dir.join("my_class_set.claims");
    std::fs::write(
        &claims,
        "T = 1/2 (I_x w_x^2 + I_x w_x^2 + I_x w_x^2) + 1/2 m v^2 # repeated term\n\
         SumM_x = I_x wdot_x - (I_z - I_y) w_y w_z\n\
         (w1 i + w2 j) × (L i - r j) = (L w2 - r w1) k\n\
         H_G = I_x w_x i + I_y w_y j + I_z w_z k\n\
         T = I_x w_x + I_y w_y\n\
         (w_x^2)^(3/2) = w_x^3\n\
         sin(t + pi) = -sin(t)\n\
         H_x & = 1 % $ # not a claim: a located error on standard error\n",
    )
    .expect("the claims are written");
    let report = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(["check", "--principal", "--format", "latex", "--claims"])
        .arg(&claims)
        .output()
        .expect("kinetics runs");
    let mut body = String::from_utf8_lossy(&report.stdout).into_owned();
    // In a scene with values: a slip read in symbols then numbers, a number with its unit
    // that differs, and one of the wrong sign.
    let scene = crate::common::binary::scene("sp18_4_shaft_reactions");
    let in_numbers = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(["check", &scene, "--format", "latex"])
        .args(["--claim", "D_z = m c alpha/4", "--claim", "D_z = 40 N"])
        .output()
        .expect("kinetics runs");
    body.push_str(&String::from_utf8_lossy(&in_numbers.stdout));
    assert!(body.contains(r"\paragraph{"), "{body}");
    assert!(body.contains("transport term missing"), "{body}");
    let tex = dir.join("check.tex");
    std::fs::write(
        &tex,
        format!(
            "\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\begin{{document}}\n{body}\n\\end{{document}}\n"
        ),
    )
    .expect("the .tex is written");
    let error = pdflatex_error(&dir, &tex);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        error.is_none(),
        "LaTeX error:\n{}\n\n{body}",
        error.unwrap_or_default()
    );
}
