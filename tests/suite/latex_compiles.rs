//! Every example's `--standalone` LaTeX compiles with pdflatex (amsmath only). `.ci/run`
//! installs pdflatex from Debian's packages when it is missing, so this test never skips.

use std::path::Path;
use std::process::Command;

#[test]
fn every_example_compiles_with_pdflatex() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes");
    let out_dir = std::env::temp_dir().join(format!("kinetics-latex-{}", std::process::id()));
    std::fs::create_dir_all(&out_dir).expect("a temporary folder");
    let mut scenes: Vec<_> = std::fs::read_dir(&examples)
        .expect("examples/scenes exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "scene"))
        .collect();
    scenes.sort();
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
        let tex = out_dir.join(format!("{stem}.tex"));
        std::fs::write(&tex, &latex.stdout).expect("the .tex is written");
        let run = Command::new("pdflatex")
            .args([
                "-interaction=nonstopmode",
                "-halt-on-error",
                "-output-directory",
            ])
            .arg(&out_dir)
            .arg(&tex)
            .output()
            .expect("pdflatex is installed (.ci/run installs it)");
        let log = String::from_utf8_lossy(&run.stdout);
        if !run.status.success() || log.contains("! ") {
            let first_error = log
                .lines()
                .skip_while(|l| !l.starts_with('!'))
                .take(6)
                .collect::<Vec<_>>()
                .join("\n");
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
