//! Pages that fit (issue 17): every example's `solve --format latex --standalone`, and
//! `derive --general --steps --format latex` in the same preamble, compiled with pdflatex
//! at 11 pt on A4 and again at 12 pt: no `Overfull \hbox` wider than 1 pt in the log.
//! `examples/scenes/long_relations.scene` has results longer than a page is wide, so that
//! line breaking is exercised. And the page an instructor pastes (issue 30): each of the
//! sample problems 18.1–18.5 on at most two pages. The engineer's pages (`--numbers`) of
//! those with values compile and fit too.

use std::path::Path;
use std::process::Command;

/// The class line of the standalone output, and the larger page it is also compiled on.
const CLASS: &str = r"\documentclass[a4paper,11pt]{article}";
const LARGE: &str = r"\documentclass[12pt,a4paper]{article}";

fn kinetics(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(args)
        .output()
        .expect("kinetics runs");
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// The first error of compiling `tex` (named `name`) in `dir`, if any, and the log.
fn compiled(dir: &Path, name: &str, tex: &str) -> (Option<String>, String) {
    let path = dir.join(format!("{name}.tex"));
    std::fs::write(&path, tex).expect("the .tex is written");
    let error = crate::common::pdflatex::pdflatex(dir, &path).first_error();
    let log = std::fs::read_to_string(dir.join(format!("{name}.log"))).expect("a log");
    (error.map(|e| format!("{name}: {e}")), log)
}

/// The overfull boxes wider than 1 pt in the log of compiling `tex` (named `name`) in `dir`,
/// each with the line of material that overflows; a LaTeX error is a failure too.
fn overfull_boxes(dir: &Path, name: &str, tex: &str) -> Vec<String> {
    let (error, log) = compiled(dir, name, tex);
    let mut found: Vec<String> = error.into_iter().collect();
    let lines: Vec<&str> = log.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        let Some(rest) = line.strip_prefix(r"Overfull \hbox (") else {
            continue;
        };
        let points: f64 = rest
            .split("pt")
            .next()
            .and_then(|p| p.parse().ok())
            .unwrap_or(f64::INFINITY);
        if points > 1.0 {
            let material = lines.get(i + 1).unwrap_or(&"");
            found.push(format!("{name}: {line}\n    {material}"));
        }
    }
    found
}

#[test]
fn every_example_fits_the_page_at_10_and_12_pt() {
    let dir = std::env::temp_dir().join(format!("kinetics-pages-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let mut documents = Vec::new();
    let scenes = crate::common::examples::example_scenes();
    assert!(
        scenes.iter().any(|s| s.ends_with("long_relations.scene")),
        "the scene with long results is there"
    );
    for scene in &scenes {
        let stem = scene
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or("scene");
        let path = scene.to_str().expect("a UTF-8 path");
        let tex = kinetics(&["solve", "--format", "latex", "--standalone", path]);
        documents.push((stem.to_string(), tex));
        // The engineer's page too, where it has numbers to show.
        if stem.starts_with("sp18_") || stem == "box_about_body_diagonal" {
            let args = [
                "solve",
                "--numbers",
                "--format",
                "latex",
                "--standalone",
                path,
            ];
            documents.push((format!("{stem}_numbers"), kinetics(&args)));
        }
    }
    documents.push((
        "derive_general".to_string(),
        kinetics(&[
            "derive",
            "--general",
            "--steps",
            "--format",
            "latex",
            "--standalone",
        ]),
    ));
    let mut failures = Vec::new();
    for (name, tex) in &documents {
        assert!(tex.starts_with(CLASS), "{name}: {CLASS}");
        failures.extend(overfull_boxes(&dir, name, tex));
        let large = tex.replacen(CLASS, LARGE, 1);
        failures.extend(overfull_boxes(&dir, &format!("{name}_12pt_a4"), &large));
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        failures.is_empty(),
        "overfull lines:\n{}",
        failures.join("\n")
    );
}

#[test]
fn each_sample_problem_takes_at_most_two_pages() {
    let dir = std::env::temp_dir().join(format!("kinetics-sp-pages-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let mut long = Vec::new();
    for name in [
        "sp18_1_plate_impact",
        "sp18_2_rolling_disk",
        "sp18_3_rotating_rod",
        "sp18_4_shaft_reactions",
        "sp18_5_disk_reactions",
    ] {
        let scene = crate::common::binary::scene(name);
        let tex = kinetics(&["solve", "--format", "latex", "--standalone", &scene]);
        assert!(tex.starts_with(CLASS), "{name}: {CLASS}");
        let (error, log) = compiled(&dir, name, &tex);
        assert_eq!(error, None);
        // pdflatex ends its log with `Output written on NAME.pdf (N pages, …`.
        let pages: usize = log
            .split("Output written on")
            .nth(1)
            .and_then(|rest| rest.split('(').nth(1))
            .and_then(|rest| rest.split(' ').next())
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("{name}: no page count in the log"));
        if pages > 2 {
            long.push(format!("{name}: {pages} pages"));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(long.is_empty(), "{}", long.join("\n"));
}
