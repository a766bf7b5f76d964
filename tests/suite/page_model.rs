//! Issue 30: every notation is written from one page model. No example's page holds a
//! tautology (`vbar_x = vbar_x`) or a vector written as a tuple (`(−135, 0, 0) m/s²`);
//! components of one quantity with one value share a row; a scene's `statement` lines print before its
//! givens, and its requests in a Find section, in every format.

use super::common::binary::kinetics;
use super::common::examples::{analysed_example, example_scenes};
use kinetics::{render, Format};
use serde_json::Value;

/// Whether `text` holds a parenthesised list of three numbers, `(-135, 0, 0)`.
fn holds_a_tuple(text: &str) -> bool {
    text.split('(').skip(1).any(|after| {
        let Some((inside, _)) = after.split_once(')') else {
            return false;
        };
        let items: Vec<&str> = inside.split(',').map(str::trim).collect();
        items.len() == 3 && items.iter().all(|x| x.parse::<f64>().is_ok())
    })
}

#[test]
fn the_tuple_detector_sees_a_tuple_and_nothing_else() {
    assert!(holds_a_tuple("abar = (-135, 0, 0) m/s²"));
    assert!(holds_a_tuple("e_1 = (0.8366, 0.496, 0.2326)"));
    assert!(!holds_a_tuple("abar = (-135 m/s²) i"));
    assert!(!holds_a_tuple("at (a/2, b, 0)"));
    assert!(!holds_a_tuple("f(x, y)"));
}

#[test]
fn no_example_page_holds_a_tautology_or_a_tuple() {
    let mut broken = Vec::new();
    for path in example_scenes() {
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let (code, json, err) = kinetics(&["solve", "--format", "json", path.to_str().unwrap()]);
        assert_eq!(code, 0, "{name}: {err}");
        let doc: Value = serde_json::from_str(&json).expect("JSON");
        for step in doc["steps"].as_array().expect("steps") {
            for relation in step["relations"].as_array().expect("relations") {
                let text = relation["text"].as_str().expect("text");
                let sides: Vec<&str> = text.split(" = ").collect();
                if sides.len() == 2 && sides[0] == sides[1] {
                    broken.push(format!("{name}: tautology {text}"));
                }
            }
        }
        for format in ["text", "latex", "markdown", "html"] {
            let (_, page, _) = kinetics(&["solve", "--format", format, path.to_str().unwrap()]);
            for line in page.lines().filter(|l| holds_a_tuple(l)) {
                broken.push(format!("{name} ({format}): tuple {line}"));
            }
        }
    }
    assert!(broken.is_empty(), "{}", broken.join("\n"));
}

#[test]
fn equal_components_of_a_step_share_one_row() {
    let (scene, analysis) = analysed_example("sp18_1_plate_impact", "");
    let text = render(&scene, &analysis, Format::Text, false);
    // The plate's centroidal products of inertia are zero, derived one by one; their rows
    // are one row, and no other row says the same.
    assert!(text.contains("  I_xy = I_yz = I_xz = 0\n"), "{text}");
    assert!(!text.contains("  I_xy = 0\n"), "{text}");
    let latex = render(&scene, &analysis, Format::Latex, false);
    // Aligned at its first `=`, in the column of the rows around it.
    assert!(latex.contains("I_{xy} &= I_{yz} = I_{xz} = 0"), "{latex}");
    // The velocity of the mass centre is given: only its zero component is left to say.
    assert!(!text.contains("vbar_x = vbar_x"), "{text}");
}

#[test]
fn a_statement_prints_first_and_the_requests_under_find_in_every_format() {
    let statement = "\nstatement A sphere of radius $r$ is driven by a couple about $x$.\n\
                     statement Find its angular momentum and kinetic energy.\n";
    let (scene, analysis) = analysed_example("spun_up_sphere", statement);
    assert_eq!(scene.statement.len(), 2);
    let said = "A sphere of radius";
    for (format, given, find) in [
        (Format::Text, "Given\n", "Find\n  H_G, T\n"),
        (
            Format::Latex,
            "\\paragraph{Given}",
            "\\paragraph{Find}\n$\\mathbf{H}_G$, $T$.",
        ),
        (
            Format::Markdown,
            "**Given:**",
            "**Find:** $\\mathbf{H}_G$, $T$",
        ),
        (Format::Html, "<h2>Given</h2>", "<h2>Find</h2>"),
    ] {
        let page = render(&scene, &analysis, format, false);
        let at = |what: &str| {
            page.find(what)
                .unwrap_or_else(|| panic!("{format:?}: no {what:?} in\n{page}"))
        };
        assert!(
            at(said) < at(given),
            "{format:?}: statement after Given\n{page}"
        );
        assert!(
            at(given) < at(find),
            "{format:?}: Find before Given\n{page}"
        );
        assert!(
            at("Step 1") > at(find),
            "{format:?}: a step before Find\n{page}"
        );
    }
    let json: Value =
        serde_json::from_str(&render(&scene, &analysis, Format::Json, false)).expect("JSON");
    assert_eq!(
        json["statement"],
        "A sphere of radius r is driven by a couple about x. Find its angular momentum and \
         kinetic energy."
    );
    assert_eq!(json["find"], serde_json::json!(["H_G", "T"]));
}
