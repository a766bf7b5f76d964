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

/// The example `examples/scenes/<name>.scene` with `extra` lines added (a statement such as
/// `about G`, or nothing), parsed and analysed; a located error is a panic that shows it.
pub fn analysed_example(name: &str, extra: &str) -> (kinetics::Scene, kinetics::Analysis) {
    let path = format!(
        "{}/examples/scenes/{name}.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("the example exists") + extra;
    let scene = kinetics::parse_scene(&path, &text).unwrap_or_else(|d| panic!("{}", d.render()));
    let analysis = kinetics::analyse(&scene).unwrap_or_else(|d| panic!("{}", d.render()));
    (scene, analysis)
}

/// The number of the scalar request named `name`, with the givens' values.
pub fn scalar_value(scene: &kinetics::Scene, analysis: &kinetics::Analysis, name: &str) -> f64 {
    match result(analysis, name) {
        kinetics::Value::Scalar(e) => e.eval(&|s| scene.value(s)).expect("a number"),
        other => panic!("{name} is not a scalar: {other:?}"),
    }
}

/// The value of the request named `name` (as written in the scene's `find`).
pub fn result<'a>(analysis: &'a kinetics::Analysis, name: &str) -> &'a kinetics::Value {
    &analysis
        .results
        .iter()
        .find(|(r, _)| r.name == name)
        .unwrap_or_else(|| panic!("{name} requested"))
        .1
}

/// The example `examples/scenes/<name>.scene` with each `(from, to)` edit made, parsed; an
/// edit whose `from` is not in the text is a panic (else the test would check the example
/// unedited).
pub fn edited_example(name: &str, edits: &[(&str, &str)]) -> kinetics::Scene {
    let path = format!(
        "{}/examples/scenes/{name}.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut text = std::fs::read_to_string(&path).expect("the example exists");
    for (from, to) in edits {
        assert!(text.contains(from), "{name}.scene has no '{from}'");
        text = text.replace(from, to);
    }
    kinetics::parse_scene(&path, &text).unwrap_or_else(|d| panic!("{}", d.render()))
}
