//! derive's HTML page: a derivation's heading (`<h2>`) is set larger than its steps'
//! (`<h3>`), as the LaTeX's `\section` is larger than its `\subsection` (the browser's own
//! `<h3>`, 1.17em, was larger than the page's `<h2>` at 1.1em).

use crate::common::binary::kinetics;

/// The `font-size` in ems the page's style gives `selector` (`h2 { font-size: 1.1em; …`).
fn font_size_em(page: &str, selector: &str) -> f64 {
    let rule = format!("\n{selector} {{ font-size: ");
    let start = page
        .find(&rule)
        .unwrap_or_else(|| panic!("no {selector} rule"))
        + rule.len();
    let size = &page[start..];
    let end = size.find("em;").expect("a size in ems");
    size[..end].parse().expect("a number of ems")
}

#[test]
fn a_step_heading_is_smaller_than_its_derivation_heading() {
    let (code, page, stderr) = kinetics(&["derive", "--general", "--steps", "--format", "html"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(page.contains("<h2>") && page.contains("<h3>"));
    let (section, step) = (font_size_em(&page, "h2"), font_size_em(&page, "h3"));
    assert!(
        step < section,
        "step headings {step}em, derivation headings {section}em"
    );
}
