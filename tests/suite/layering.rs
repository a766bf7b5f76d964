//! The layering of `src/` (ARCHITECTURE.md, "Layers"): each folder uses only the folders
//! below it. The check reads every source file's `crate::` paths (comments and `#[cfg(test)]`
//! modules aside: tests may parse what they print) and fails on a path to a folder the layer
//! may not use.

use std::path::Path;

/// Each folder of `src/` and the folders it may use, lowest first.
const LAYERS: [(&str, &[&str]); 11] = [
    ("algebra", &[]),
    ("parse", &["algebra"]),
    ("print", &["algebra"]),
    ("mechanics", &["algebra"]),
    ("numeric", &["algebra", "mechanics"]),
    ("scene", &["algebra", "parse", "mechanics", "numeric"]),
    (
        "figure",
        &["algebra", "parse", "print", "mechanics", "numeric", "scene"],
    ),
    (
        "solution",
        &[
            "algebra",
            "parse",
            "print",
            "mechanics",
            "numeric",
            "scene",
            "figure",
        ],
    ),
    (
        "check",
        &["algebra", "parse", "print", "mechanics", "numeric", "scene"],
    ),
    (
        "marking",
        &[
            "algebra",
            "parse",
            "print",
            "mechanics",
            "numeric",
            "scene",
            "check",
        ],
    ),
    (
        "cli",
        &[
            "algebra",
            "parse",
            "print",
            "mechanics",
            "numeric",
            "scene",
            "figure",
            "solution",
            "check",
            "marking",
        ],
    ),
];

/// The folders of the crate named by `crate::` (or, in the binary, `kinetics::`) paths in
/// `source` that `layer` may not use, with the line each is on.
fn forbidden_uses(layer: &str, source: &str) -> Vec<(usize, String)> {
    let allowed = LAYERS
        .iter()
        .find(|(name, _)| *name == layer)
        .map_or(&[][..], |(_, below)| *below);
    let mut found = Vec::new();
    for (number, line) in source.lines().enumerate() {
        let code = line.trim_start();
        if code.starts_with("#[cfg(test)]") {
            break;
        }
        if code.starts_with("//") {
            continue;
        }
        for root in ["crate::", "kinetics::"] {
            for (at, _) in code.match_indices(root) {
                let folder: String = code[at + root.len()..]
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                let is_layer = LAYERS.iter().any(|(name, _)| *name == folder);
                if is_layer && folder != layer && !allowed.contains(&folder.as_str()) {
                    found.push((number + 1, folder));
                }
            }
        }
    }
    found
}

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("src/ is readable") {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn every_folder_uses_only_the_folders_below_it() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut violations = Vec::new();
    let mut checked = 0;
    for (layer, _) in LAYERS {
        let mut files = Vec::new();
        rust_files(&src.join(layer), &mut files);
        assert!(!files.is_empty(), "src/{layer} has no source files");
        for file in files {
            let source = std::fs::read_to_string(&file).expect("a readable source file");
            checked += 1;
            for (line, folder) in forbidden_uses(layer, &source) {
                let shown = file.strip_prefix(&src).unwrap_or(&file).display();
                violations.push(format!("src/{shown}:{line}: {layer} uses {folder}"));
            }
        }
    }
    assert!(checked > 50, "only {checked} files read");
    assert!(
        violations.is_empty(),
        "layering broken (see ARCHITECTURE.md):\n{}",
        violations.join("\n")
    );
}

#[test]
fn the_check_names_an_upward_use_and_passes_what_is_allowed() {
    let mechanics_using_print = "use crate::algebra::Expr;\nuse crate::print::Axis;\n";
    assert_eq!(
        forbidden_uses("mechanics", mechanics_using_print),
        vec![(2, "print".to_string())]
    );
    let in_comment_or_test = "// crate::scene\n#[cfg(test)]\nuse crate::parse::parse_expression;\n";
    assert!(forbidden_uses("algebra", in_comment_or_test).is_empty());
    assert!(forbidden_uses("solution", "use crate::scene::Scene;").is_empty());
    assert_eq!(
        forbidden_uses("print", "f(&crate::scene::x, crate::mechanics::y)"),
        vec![(1, "scene".to_string()), (1, "mechanics".to_string())]
    );
}

/// The paths into a module of the crate (`kinetics::scene::…`, past the root's
/// re-exports) in `source`, comments aside, with their lines.
fn paths_past_the_root(source: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (number, line) in source.lines().enumerate() {
        if line.trim_start().starts_with("//") {
            continue;
        }
        for (at, _) in line.match_indices("kinetics::") {
            let rest = &line[at + "kinetics::".len()..];
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if rest[name.len()..].starts_with("::") {
                found.push((number + 1, name));
            }
        }
    }
    found
}

#[test]
fn the_python_binding_uses_only_the_crates_root() {
    let binding = Path::new(env!("CARGO_MANIFEST_DIR")).join("python/src");
    let mut read = 0;
    let mut past = Vec::new();
    for entry in std::fs::read_dir(&binding).expect("python/src") {
        let file = entry.expect("an entry").path();
        let source = std::fs::read_to_string(&file).expect("readable");
        read += 1;
        for (line, module) in paths_past_the_root(&source) {
            past.push(format!("{}:{line}: kinetics::{module}::", file.display()));
        }
    }
    assert!(read >= 5, "only {read} files read");
    assert!(
        past.is_empty(),
        "the binding reaches past lib.rs's re-exports:\n{}",
        past.join("\n")
    );
    assert_eq!(
        paths_past_the_root("use kinetics::{Expr, View};\nuse kinetics::scene::Scene;"),
        vec![(2, "scene".to_string())]
    );
}
