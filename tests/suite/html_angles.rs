//! An angle given in degrees reads `30°` in the HTML page, as the LaTeX (and Markdown) sets
//! `30^\circ`: the degree sign close after the number, never the unit name `deg` the scene
//! spells.

use crate::common::binary::{kinetics, scene};

#[test]
fn a_given_angle_in_degrees_has_the_degree_sign() {
    let path = scene("general_body");
    let (code, page, stderr) = kinetics(&["solve", "--format", "html", &path]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        page.contains(r#"<mn>30</mn><mo lspace="0" rspace="0">°</mo>"#),
        "θ = 30° is not set with the degree sign"
    );
    assert!(
        !page.contains(r#"<mi mathvariant="normal">deg</mi>"#),
        "the unit name deg is printed"
    );
}

/// Markdown's givens are mathematics as the LaTeX's are (`$\theta = 30^\circ$`), not the
/// scene's ASCII in code spans.
#[test]
fn markdown_givens_are_mathematics() {
    let path = scene("general_body");
    let (code, page, stderr) = kinetics(&["solve", "--format", "markdown", &path]);
    assert_eq!(code, 0, "{stderr}");
    let given = page
        .lines()
        .find(|l| l.starts_with("**Given:**"))
        .expect("a Given line");
    assert!(given.contains(r"$\theta = 30^\circ$"), "{given}");
    assert!(given.contains(r"$m = 4\,\mathrm{kg}$"), "{given}");
    assert!(!given.contains('`'), "{given}");
}
