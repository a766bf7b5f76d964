//! Headless Chromium for the tests that look at a page as a browser lays it out. `.ci/run`
//! installs Debian's `chromium` when it is missing, so these tests never skip.

use std::path::Path;
use std::process::Command;

/// The browser, as Debian installs it.
const CHROMIUM: &str = "chromium";

/// Runs headless Chromium on `file` with `flags` (its own profile in `dir`, so that runs in
/// parallel never share one), within a minute; its standard output.
pub fn chromium(dir: &Path, file: &Path, flags: &[&str]) -> String {
    let profile = dir.join("profile");
    let run = Command::new("timeout")
        .arg("60")
        .arg(CHROMIUM)
        .args(["--headless", "--no-sandbox", "--disable-gpu"])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(flags)
        .arg(format!("file://{}", file.display()))
        .output()
        .expect("timeout runs");
    assert!(
        run.status.success(),
        "install chromium (.ci/run does): `{CHROMIUM}` failed: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    String::from_utf8_lossy(&run.stdout).into_owned()
}
