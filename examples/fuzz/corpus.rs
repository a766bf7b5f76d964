//! The seed corpus: issue 14's reproducers (`tests/reproducers/`); for expressions also the
//! right sides of the shipped scenes' statements, for scenes the shipped scenes
//! (`examples/scenes/`) and the malformed ones (`tests/bad_scenes/`), for claims the claims
//! of `tests/data/check_corpus.txt`.

use crate::target::Target;
use std::path::Path;

/// The headers of a file in `tests/reproducers/` (see `tests/suite/reproducers.rs`).
const HEADERS: [&str; 5] = ["# run: ", "# at: ", "# ok: ", "# refuse: ", "# repeat: "];

/// The texts of the target's seeds: an expression, a scene or a claim each.
pub fn seeds(target: Target) -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dirs: &[&str] = match target {
        Target::Expr | Target::Check => &["tests/reproducers"],
        Target::Scene => &["tests/reproducers", "examples/scenes", "tests/bad_scenes"],
    };
    let mut seeds = Vec::new();
    for dir in dirs {
        let Ok(entries) = std::fs::read_dir(root.join(dir)) else {
            continue;
        };
        let mut paths: Vec<_> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        paths.sort();
        for path in paths {
            if path.extension().is_none_or(|e| e != target.extension()) {
                continue;
            }
            let Ok(bytes) = std::fs::read(&path) else {
                continue;
            };
            // A byte that is not UTF-8 reaches the targets as U+FFFD (they take text).
            let text = String::from_utf8_lossy(&bytes);
            let repeat = text
                .lines()
                .find_map(|l| l.strip_prefix("# repeat: "))
                .and_then(|n| n.trim().parse::<usize>().ok());
            let mut body = text.lines().filter(|l| !l.starts_with("# "));
            seeds.push(match (target, repeat) {
                // `# repeat: N`: the first line N times, then the second.
                (Target::Expr, Some(n)) => {
                    body.next().unwrap_or_default().repeat(n) + body.next().unwrap_or_default()
                }
                // The expression (or claim) is the first line that is not a header.
                (Target::Expr | Target::Check, _) => body.next().unwrap_or_default().to_string(),
                // Without the reproducer's headers, which say how the test runs it.
                (Target::Scene, _) => text
                    .lines()
                    .filter(|l| !HEADERS.iter().any(|h| l.starts_with(h)))
                    .map(|l| format!("{l}\n"))
                    .collect(),
            });
        }
    }
    match target {
        Target::Expr => seeds.extend(scene_expressions(root)),
        Target::Check => seeds.extend(corpus_claims(root)),
        Target::Scene => {}
    }
    seeds
}

/// The claims of the checker's corpus: each line's text after its third `|`
/// (`CONTEXT | VERDICT | READING | CLAIM`), comments left out.
fn corpus_claims(root: &Path) -> Vec<String> {
    let text =
        std::fs::read_to_string(root.join("tests/data/check_corpus.txt")).unwrap_or_default();
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| l.splitn(4, '|').nth(3))
        .map(|claim| claim.trim().to_string())
        .collect()
}

/// The right sides of the shipped scenes' `=` (`0.3 kg`, `w*i`, `D_y*j + D_z*k at (L, 0, 0)`):
/// expressions as people write them, to mutate besides the reproducers.
fn scene_expressions(root: &Path) -> Vec<String> {
    let Ok(entries) = std::fs::read_dir(root.join("examples/scenes")) else {
        return Vec::new();
    };
    let mut paths: Vec<_> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    paths.sort();
    paths
        .iter()
        .filter_map(|p| std::fs::read_to_string(p).ok())
        .flat_map(|text| {
            text.lines()
                .filter(|l| !l.starts_with('#'))
                .filter_map(|l| l.split_once(" = ").map(|(_, rhs)| rhs.to_string()))
                .collect::<Vec<_>>()
        })
        .collect()
}
