//! The Python package (`python/`): built by maturin into a virtual environment this test
//! creates (`target/python-venv`), with the tools it needs installed by name, then its
//! tests, its docstrings' examples, the quickstart notebook and the autograder example run
//! by pytest. Never skipped: a machine without `python3` fails here and says so.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The Python packages the tests need besides kinetics itself.
const TOOLS: [&str; 8] = [
    "maturin>=1.5,<2",
    "pytest",
    "sympy",
    "numpy",
    "nbclient",
    "nbformat",
    "ipykernel",
    "matplotlib",
];

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Runs `program args` in the repository's root with the environment's `bin` first on the
/// path; panics with its output unless it succeeds. Returns its standard output.
fn run(venv: &Path, program: &Path, args: &[&str]) -> String {
    let path = std::env::join_paths(std::iter::once(venv.join("bin")).chain(
        std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()),
    ))
    .expect("a PATH");
    let done = Command::new(program)
        .args(args)
        .current_dir(root())
        .env("PATH", path)
        .env("VIRTUAL_ENV", venv)
        .env_remove("PYTHONPATH")
        .output()
        .unwrap_or_else(|e| panic!("cannot run {}: {e} (python3 is needed)", program.display()));
    let out = String::from_utf8_lossy(&done.stdout).into_owned();
    assert!(
        done.status.success(),
        "{} {args:?} failed ({}):\n{out}\n{}",
        program.display(),
        done.status,
        String::from_utf8_lossy(&done.stderr)
    );
    out
}

#[test]
fn the_python_package_builds_and_its_tests_pass() {
    let venv: PathBuf = root().join("target/python-venv");
    if !venv.join("bin/python").exists() {
        run(
            &venv,
            Path::new("python3"),
            &["-m", "venv", venv.to_str().unwrap()],
        );
    }
    let python = venv.join("bin/python");
    let mut install = vec![
        "-m",
        "pip",
        "install",
        "--quiet",
        "--disable-pip-version-check",
    ];
    install.extend(TOOLS);
    run(&venv, &python, &install);
    run(
        &venv,
        &python,
        &[
            "-m",
            "pip",
            "install",
            "--quiet",
            "--disable-pip-version-check",
            "--no-build-isolation",
            "--force-reinstall",
            "--no-deps",
            "./python",
        ],
    );
    let report = run(
        &venv,
        &python,
        &[
            "-m",
            "pytest",
            "-p",
            "no:cacheprovider",
            "-rs",
            "--doctest-modules",
            "--pyargs",
            "kinetics",
            "python/tests",
        ],
    );
    let summary = report.lines().last().unwrap_or_default();
    assert!(summary.contains(" passed"), "pytest ran no test:\n{report}");
    assert!(
        !summary.contains("skipped") && !summary.contains("failed"),
        "pytest skipped or failed a test:\n{report}"
    );
}
