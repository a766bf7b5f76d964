//! `kinetics solve --format html` in a browser: the page of Sample Problem 18.4, and one
//! page holding every example's, loaded in headless Chromium with a test-only script
//! appended that checks each `<math>` as laid out: it is a MathML element of nonzero size,
//! every `<mfrac>` has its numerator's box above its denominator's (so the maths was laid
//! out as maths, not run together as inline text), and no `<merror>` appears. The script
//! writes its verdict into the page, and the test reads it from the DOM Chromium dumps.
//! `.ci/run` installs Debian's `chromium` when it is missing, so the test never skips.

use crate::common::binary::{kinetics, scene};
use crate::common::chromium::chromium;

/// The test's checks, run in the page once it is laid out; the verdict is `ok`, the number
/// of formulas and of fractions, or the first failure with the formula's markup.
const CHECK: &str = r#"<script>
(function () {
  const where = (m) => {
    const article = m.closest('article');
    const section = m.closest('section');
    const heading = section ? section.querySelector('h2') : null;
    return (article ? article.id + ': ' : '') + (heading ? heading.textContent : 'page');
  };
  let failure = null, formulas = 0, fractions = 0;
  const fail = (m, why) => {
    if (!failure) failure = why + ' in ' + where(m) + ': ' + m.outerHTML.slice(0, 600);
  };
  for (const m of document.querySelectorAll('math')) {
    formulas += 1;
    const box = m.getBoundingClientRect();
    if (!(m instanceof MathMLElement)) fail(m, 'not a MathML element');
    if (box.width <= 0 || box.height <= 0) fail(m, 'no size');
    for (const f of m.querySelectorAll('mfrac')) {
      fractions += 1;
      const top = f.children[0].getBoundingClientRect();
      const bottom = f.children[1].getBoundingClientRect();
      if (!(top.bottom <= bottom.top + 0.5)) fail(m, 'numerator not above denominator');
    }
    if (m.querySelector('merror')) fail(m, 'merror');
  }
  const verdict = document.createElement('pre');
  verdict.id = 'verdict';
  verdict.textContent = failure ? 'FAIL ' + failure : 'ok ' + formulas + ' ' + fractions;
  document.body.appendChild(verdict);
})();
</script>
"#;

/// The page `kinetics solve --format html` writes for a scene.
fn page(scene_path: &str) -> String {
    let (code, page, stderr) = kinetics(&["solve", "--format", "html", scene_path]);
    assert_eq!(code, 0, "{scene_path}: {stderr}");
    page
}

/// What a page's `<body>` holds.
fn body(page: &str) -> &str {
    let start = page.find("<body>").expect("the page has a body") + "<body>".len();
    let end = page.rfind("</body>").expect("the body is closed");
    &page[start..end]
}

/// `page` with the check appended, loaded in Chromium: the verdict, the number of formulas
/// and of fractions checked.
fn verdict(page: &str, name: &str) -> (usize, usize) {
    let dir = std::env::temp_dir().join(format!("kinetics-html-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let checked = page.replace("</body>", &format!("{CHECK}</body>"));
    let file = dir.join(format!("{name}.html"));
    std::fs::write(&file, checked).expect("the page is written");
    let dom = chromium(&dir, &file, &["--dump-dom"]);
    let _ = std::fs::remove_dir_all(&dir);
    let start = dom
        .find("<pre id=\"verdict\">")
        .map(|at| at + "<pre id=\"verdict\">".len())
        .unwrap_or_else(|| panic!("{name}: the check wrote no verdict; the DOM:\n{dom}"));
    let verdict = &dom[start..dom[start..].find("</pre>").map_or(dom.len(), |n| start + n)];
    // The verdict is text in the DOM: its markup is escaped there.
    let verdict = verdict
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&amp;", "&");
    let counts = verdict.strip_prefix("ok ").unwrap_or_else(|| {
        panic!("{name}: a formula did not render as maths: {verdict}");
    });
    let mut counts = counts.split(' ').map(|n| n.parse::<usize>().unwrap_or(0));
    (counts.next().unwrap_or(0), counts.next().unwrap_or(0))
}

#[test]
fn sample_problem_18_4_renders_as_maths() {
    let page = page(&scene("sp18_4_shaft_reactions"));
    let (formulas, fractions) = verdict(&page, "sp18_4");
    // The givens, eight steps and the results; fractions in most steps.
    assert!(formulas >= 14, "{formulas} formulas");
    assert!(fractions >= 30, "{fractions} fractions");
}

/// Every example's page and derive's, together on one page (one Chromium launch).
#[test]
fn every_example_renders_as_maths() {
    let scenes = crate::common::examples::example_scenes();
    assert!(scenes.len() >= 5, "the sample problems are there");
    let first = page(&scenes[0].to_string_lossy());
    let head = &first[..first.find("<body>").expect("a body")];
    let mut all = format!("{head}<body>\n");
    for path in &scenes {
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("scene");
        let page = page(&path.to_string_lossy());
        all.push_str(&format!(
            "<article id=\"{stem}\">\n{}</article>\n",
            body(&page)
        ));
    }
    // derive's page of every derivation and step, in the same launch.
    let (code, derived, stderr) = kinetics(&["derive", "--general", "--steps", "--format", "html"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(derived.contains("<h3>"), "derive's steps are headings");
    all.push_str(&format!(
        "<article id=\"derive\">\n{}</article>\n",
        body(&derived)
    ));
    all.push_str("</body>\n</html>\n");
    let (formulas, fractions) = verdict(&all, "examples");
    assert!(formulas >= 10 * scenes.len(), "{formulas} formulas");
    assert!(fractions > 0, "no fraction checked");
}

/// The page is self-contained: no script of its own, nothing fetched, UTF-8 declared.
#[test]
fn the_page_is_self_contained() {
    let page = page(&scene("sp18_4_shaft_reactions"));
    assert!(page.starts_with("<!DOCTYPE html>"), "{page}");
    assert!(page.contains("<meta charset=\"utf-8\">"));
    for outside in [
        "<script", "<link", "src=", "href=", "http:", "https:", "@import", "url(",
    ] {
        assert!(!page.contains(outside), "the page holds {outside}");
    }
    // The same content and order as the LaTeX: every step, then the results.
    let steps = page.matches("<span class=\"step\">Step ").count();
    let (_, latex, _) = kinetics(&[
        "solve",
        "--format",
        "latex",
        &scene("sp18_4_shaft_reactions"),
    ]);
    assert_eq!(steps, latex.matches("\\paragraph{Step ").count());
    assert!(page.find("<h2>Results</h2>") > page.rfind("Step "));
}
