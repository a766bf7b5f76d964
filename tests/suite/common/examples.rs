//! The shipped example scenes, for tests that go through all of them.

use std::path::PathBuf;

/// Every `examples/scenes/*.scene`, sorted by name.
pub fn example_scenes() -> Vec<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/scenes");
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("examples/scenes exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "scene"))
        .collect();
    scenes.sort();
    scenes
}
