//! The axes a step's component equations are about, `(x, y, z)` in its title, are
//! mathematics (`($x, y, z$)`, italic in the LaTeX), in the equations of motion as in
//! impulse and momentum: never upright words.

use crate::common::binary::{kinetics, scene};

#[test]
fn the_axes_in_a_step_title_are_mathematics() {
    for name in [
        "sp18_4_shaft_reactions",
        "sliding_box",
        "free_box_struck_at_corner",
    ] {
        let path = scene(name);
        let (code, latex, stderr) = kinetics(&["solve", "--format", "latex", &path]);
        assert_eq!(code, 0, "{name}: {stderr}");
        assert!(latex.contains("($x, y, z$)"), "{name}: no axes in maths");
        assert!(!latex.contains(" (x, y, z)"), "{name}: axes as words");
    }
}
