//! The figure of every worked solution (issue 33), tested as a reader sees it: drawn where
//! the scene's points project, with the loads, axes and angles the scene states labelled,
//! its labels apart from each other and inside the picture (the model's boxes, and the boxes
//! headless Chromium lays the SVG out with), the SVG well-formed XML, the TikZ in a page
//! that compiles (`latex_compiles.rs`), a Markdown page's SVG written beside it.

use crate::common::binary::{kinetics, scene};
use crate::common::chromium::chromium;
use crate::common::examples::example_scenes;
use kinetics::figure::sizes::Sizes;
use kinetics::figure::{
    figure, Dashes, Figure, Ink, Label, Mark, Role, Stroke, ARROWS_APART, BESIDE, P2,
};
use kinetics::{Expr, Scene, Symbol};

/// Every example scene, parsed, with its file stem.
fn examples() -> Vec<(String, Scene)> {
    example_scenes()
        .into_iter()
        .map(|path| {
            let name = path.file_stem().unwrap().to_string_lossy().into_owned();
            let text = std::fs::read_to_string(&path).expect("the example reads");
            let scene = kinetics::parse_scene(&name, &text).expect("the example parses");
            (name, scene)
        })
        .collect()
}

/// The example scene of that file stem.
fn example(name: &str) -> Scene {
    examples()
        .into_iter()
        .find(|(n, _)| n == name)
        .map(|(_, s)| s)
        .unwrap_or_else(|| panic!("no example {name}"))
}

/// The paths of two points drawn with `stroke` (the shaft's pieces, dimension lines).
fn two_point_paths(drawn: &Figure, stroke: Stroke) -> Vec<(P2, P2)> {
    drawn
        .marks
        .iter()
        .filter_map(|m| match m {
            Mark::Path {
                points, stroke: s, ..
            } if *s == stroke => Some((points[0], points[1])),
            _ => None,
        })
        .collect()
}

/// The closed paths of `corners` points (a floor's patch, a pedestal), with their strokes.
fn closed_paths(drawn: &Figure, corners: usize) -> Vec<(Stroke, Vec<P2>)> {
    drawn
        .marks
        .iter()
        .filter_map(|m| match m {
            Mark::Path {
                points,
                closed: true,
                stroke,
                ..
            } if points.len() == corners => Some((*stroke, points.clone())),
            _ => None,
        })
        .collect()
}

fn near(a: P2, b: P2) -> bool {
    (a.x - b.x).hypot(a.y - b.y) < 1e-6
}

/// Where the scene's point `p` (its vector of expressions) stands in the figure, its symbols
/// at the figure's sizes.
fn drawn_at(drawn: &Figure, scene: &Scene, p: &kinetics::Vector) -> P2 {
    let sizes = Sizes::of(scene);
    drawn.at(sizes.of_vector(p).expect("the point has a size"))
}

fn overlap(a: &Label, b: &Label) -> bool {
    (a.centre.x - b.centre.x).abs() < a.half_width + b.half_width
        && (a.centre.y - b.centre.y).abs() < a.half_height + b.half_height
}

#[test]
fn every_example_has_a_figure_whose_labels_are_apart_and_inside_it() {
    let mut failures = Vec::new();
    for (name, scene) in examples() {
        let drawn = figure(&scene).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(!drawn.labels.is_empty(), "{name}: labels");
        for (k, a) in drawn.labels.iter().enumerate() {
            for b in &drawn.labels[k + 1..] {
                if overlap(a, b) {
                    failures.push(format!("{name}: {} over {}", a.markup, b.markup));
                }
            }
            let inside = a.centre.x - a.half_width >= drawn.min.x
                && a.centre.x + a.half_width <= drawn.max.x
                && a.centre.y - a.half_height >= drawn.min.y
                && a.centre.y + a.half_height <= drawn.max.y;
            if !inside {
                failures.push(format!("{name}: {} outside the picture", a.markup));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The strokes of the lines an arrow is drawn beside, not along: the axes, the centre lines,
/// the rods, the shaft and an axle.
const KEPT_CLEAR: [Stroke; 4] = [
    Stroke::AXIS,
    Stroke::CENTRE_LINE,
    Stroke::ROD,
    Stroke::SHAFT,
];

/// How far an arrow beside a line drawn with `stroke` stands from the line's middle.
fn beside(stroke: Stroke) -> f64 {
    BESIDE + stroke.width / 2.0
}

/// The farthest an arrow beside a line stands from the line's middle.
fn farthest_beside() -> f64 {
    KEPT_CLEAR.map(beside).into_iter().fold(0.0, f64::max)
}

/// Whether an arrow's end `end` (its other end `other`) is at the point `at`, or beside it:
/// square to the arrow, [`BESIDE`] the edge of a line it would lie on or [`ARROWS_APART`]
/// from an arrow there (a weight beside a normal force), or beside both, on one side or
/// either side.
fn at_or_beside(end: P2, other: P2, at: P2) -> bool {
    let (off, along) = (end.minus(at), other.minus(end));
    let square = (off.x * along.x + off.y * along.y).abs() < 1e-6 * along.length();
    let lines = std::iter::once(0.0).chain(KEPT_CLEAR.map(beside));
    let places = lines.flat_map(|l| {
        (0..=2).flat_map(move |arrows| {
            let a = f64::from(arrows) * ARROWS_APART;
            [l + a, (l - a).abs()]
        })
    });
    let beside = places
        .filter(|d| *d > 0.0)
        .any(|d| (off.length() - d).abs() < 1e-6);
    near(end, at) || (beside && square)
}

/// No load's arrow lies along a rod or the shaft, where the reader could not see it: every
/// force's and impulse's line is off every such line it runs parallel to. (Along an axis a
/// load is drawn on it, in its colour over the black line: see the next test.)
#[test]
fn loads_are_drawn_beside_the_rods_and_shafts_they_run_along() {
    let mut failures = Vec::new();
    for (name, scene) in examples() {
        let drawn = figure(&scene).unwrap();
        let mut lines: Vec<(P2, P2)> = Vec::new();
        for m in &drawn.marks {
            if let Mark::Path { points, stroke, .. } = m {
                if stroke.width >= Stroke::SHAFT.width {
                    lines.extend(points.windows(2).map(|w| (w[0], w[1])));
                }
            }
        }
        for m in &drawn.marks {
            let Mark::Arrow {
                role: Role::Force(_) | Role::Impulse,
                from,
                to,
                ..
            } = m
            else {
                continue;
            };
            let length = to.minus(*from).length();
            for (a, b) in &lines {
                let Some(v) = b.minus(*a).unit() else {
                    continue;
                };
                let cross = |p: P2| (p.x - a.x) * v.y - (p.y - a.y) * v.x;
                let t = |p: P2| (p.x - a.x) * v.x + (p.y - a.y) * v.y;
                let on = cross(*from).abs() < 1.0 && cross(*to).abs() < 1.0;
                let (t0, t1) = (t(*from).min(t(*to)), t(*from).max(t(*to)));
                let shared = t1.min(b.minus(*a).length()) - t0.max(0.0);
                if on && shared > 0.2 * length {
                    failures.push(format!("{name}: a load's arrow lies along a line"));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A reaction's component along an axis at O starts at O, on the axis, as a free-body
/// diagram draws it (beside the axis it read as detached from its point): SP 18.5's R_y up
/// the y axis and R_z along z, the balanced shaft's A_y and A_z at its bearing A = O; each
/// drawn over the axis (after its marks), so its colour shows, and no stretch of an axis
/// redrawn in front runs over it.
#[test]
fn a_reaction_at_o_lies_on_its_axis_from_o() {
    for (name, force) in [
        ("sp18_5_disk_reactions", "R"),
        ("balanced_shaft", "A"),
        ("gyroscope_required_moment", "R"),
    ] {
        let drawn = figure(&example(name)).unwrap();
        let o = drawn.at([0.0; 3]);
        let axes: Vec<(usize, P2, P2)> = drawn
            .marks
            .iter()
            .enumerate()
            .filter_map(|(k, m)| match m {
                Mark::Arrow {
                    role: Role::Axis,
                    from,
                    to,
                    ..
                } => Some((k, *from, *to)),
                _ => None,
            })
            .collect();
        let on_axes = drawn.marks.iter().enumerate().filter_map(|(k, m)| match m {
            Mark::Arrow {
                role: Role::Force(n),
                from,
                to,
                ..
            } if n == force && near(*from, o) => {
                let along = |(_, a, b): &&(usize, P2, P2)| {
                    let (u, v) = (to.minus(*from), b.minus(*a));
                    (u.x * v.y - u.y * v.x).abs() < 1e-6 * u.length() * v.length()
                        && u.x * v.x + u.y * v.y > 0.0
                        && near(*a, o)
                };
                axes.iter().find(along).map(|axis| (k, *to, *axis))
            }
            _ => None,
        });
        let mut count = 0;
        for (k, head, (axis, _, _)) in on_axes {
            count += 1;
            assert!(axis < k, "{name}: {force}'s component drawn over its axis");
            // A stretch of the axis drawn in front starts past the component's head.
            let over = axes.iter().any(|(j, a, b)| {
                *j > k && !near(*a, o) && {
                    let (u, v) = (head.minus(o), a.minus(o));
                    (u.x * v.y - u.y * v.x).abs() < 1e-6 * u.length() * v.length()
                        && u.x * v.x + u.y * v.y > 0.0
                        && v.length() < u.length() - 1e-6
                        && b.minus(o).length() > v.length()
                }
            });
            assert!(!over, "{name}: the axis redrawn over {force}'s component");
        }
        assert!(
            count >= 2,
            "{name}: {force}'s components on the axes from O, {count}"
        );
    }
}

/// A force's arrows start (or end) at its point, an impulse's end at its point (the blow) or,
/// drawn by its components, start there; O is the origin of the figure and G a dot where the
/// body's mass centre projects.
#[test]
fn arrows_start_where_the_scene_puts_their_points() {
    for (name, scene) in examples() {
        let drawn = figure(&scene).unwrap();
        assert!(near(drawn.at([0.0; 3]), P2::new(0.0, 0.0)), "{name}: O");
        for f in &scene.forces {
            let at = drawn_at(&drawn, &scene, &f.point);
            let arrows: Vec<&Mark> = drawn
                .marks
                .iter()
                .filter(|m| matches!(m, Mark::Arrow { role: Role::Force(n), .. } if *n == f.name))
                .collect();
            assert!(!arrows.is_empty(), "{name}: force {} drawn", f.name);
            // From its point, or into it where it runs along a line toward the body (a
            // bearing's thrust along the shaft).
            for arrow in arrows {
                let Mark::Arrow { from, to, .. } = arrow else {
                    unreachable!()
                };
                assert!(
                    at_or_beside(*from, *to, at) || at_or_beside(*to, *from, at),
                    "{name}: force {} starts or ends at its point",
                    f.name
                );
            }
        }
        for i in &scene.impulses {
            let at = drawn_at(&drawn, &scene, &i.point);
            let components = i.value.iter().filter(|c| !c.is_zero()).count();
            let unknown = i.value.iter().any(|c| {
                c.symbols()
                    .iter()
                    .any(|s| scene.unknowns.iter().any(|(u, _)| u == s))
            });
            let impulses = drawn.marks.iter().filter_map(|m| match m {
                Mark::Arrow {
                    role: Role::Impulse,
                    from,
                    to,
                    ..
                } => Some((*from, *to)),
                _ => None,
            });
            if components > 1 && unknown {
                // By its components (R_x, R_y, R_z), each from its point: their heads
                // brought into it would knot there.
                let from_it = impulses.filter(|(f, t)| at_or_beside(*f, *t, at)).count();
                assert_eq!(
                    from_it, components,
                    "{name}: an impulse's components from its point"
                );
            } else {
                let strikes = { impulses }.any(|(f, t)| at_or_beside(t, f, at));
                assert!(strikes, "{name}: an impulse's head at its point");
            }
        }
        // G: the mass-weighted centre of the parts at the figure's sizes, by hand.
        let sizes = Sizes::of(&scene);
        let (mut m, mut moment) = (0.0, [0.0; 3]);
        for p in &scene.parts {
            let mass = sizes.of_expr(&p.mass).unwrap();
            let at = sizes.of_vector(&p.position).unwrap();
            m += mass;
            for k in 0..3 {
                moment[k] += mass * at[k];
            }
        }
        let g = drawn.at(moment.map(|c| c / m));
        let dot_at_g = drawn
            .marks
            .iter()
            .any(|mark| matches!(mark, Mark::Dot { at, .. } if near(*at, g)));
        let labelled_g = drawn.labels.iter().any(|l| l.markup == "$G$");
        assert_eq!(
            dot_at_g, labelled_g,
            "{name}: G marked and labelled together"
        );
    }
}

/// SP 18.4: the shaft CD between its bearings, the two rods, the couple M and ω.
#[test]
fn the_shaft_of_sample_problem_18_4() {
    let scene = example("sp18_4_shaft_reactions");
    let drawn = figure(&scene).unwrap();
    let point = |name: &str| {
        let f = scene.forces.iter().find(|f| f.name == name).unwrap();
        drawn_at(&drawn, &scene, &f.point)
    };
    let (c, d) = (point("C"), point("D"));
    // The shaft, drawn in pieces (each at its depth), runs from C to D along CD and no farther.
    let pieces = two_point_paths(&drawn, Stroke::SHAFT);
    let cd = d.minus(c);
    let along = |p: P2| (p.minus(c).x * cd.x + p.minus(c).y * cd.y) / (cd.x * cd.x + cd.y * cd.y);
    let on_cd = |p: P2| (p.minus(c).x * cd.y - p.minus(c).y * cd.x).abs() < 1e-6 * cd.length();
    assert!(
        pieces.iter().all(|(a, b)| on_cd(*a) && on_cd(*b)),
        "the shaft lies on CD"
    );
    let covered: f64 = pieces
        .iter()
        .map(|(a, b)| (along(*b) - along(*a)).abs())
        .sum();
    let (lo, hi) = pieces
        .iter()
        .flat_map(|(a, b)| [along(*a), along(*b)])
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), t| {
            (l.min(t), h.max(t))
        });
    assert!(
        (lo.abs() < 1e-9) && ((hi - 1.0).abs() < 1e-9) && ((covered - 1.0).abs() < 1e-9),
        "the shaft from C to D"
    );
    let rods = drawn
        .marks
        .iter()
        .filter(|m| matches!(m, Mark::Path { stroke, .. } if *stroke == Stroke::ROD))
        .count();
    assert_eq!(rods, 2, "two rods");
    // A bearing: a filled outline about the bearing's point.
    let bearing_at = |p: P2| {
        drawn.marks.iter().any(|m| match m {
            Mark::Path {
                points,
                filled: true,
                ..
            } if points.len() > 8 => {
                let n = points.len() as f64;
                let centre = points
                    .iter()
                    .fold(P2::new(0.0, 0.0), |s, q| s.plus(*q))
                    .times(1.0 / n);
                (centre.x - p.x).hypot(centre.y - p.y) < 3.0
            }
            _ => false,
        })
    };
    assert!(bearing_at(c) && bearing_at(d), "bearings at C and D");
    let roles = |r: Role| {
        drawn
            .marks
            .iter()
            .any(|m| matches!(m, Mark::Arrow { role, double: true, .. } if *role == r))
    };
    assert!(roles(Role::AngularVelocity), "ω a double arrow");
    // M drives the shaft: a curved arrow round its line CD, past D, as a textbook draws it.
    let round_the_shaft = drawn.marks.iter().any(|m| match m {
        Mark::Arrow {
            role: Role::Couple,
            from,
            via,
            to,
            double: false,
            ..
        } if via.len() > 8 => {
            let points: Vec<P2> = [*from, *to].into_iter().chain(via.clone()).collect();
            let centre = points
                .iter()
                .fold(P2::new(0.0, 0.0), |s, q| s.plus(*q))
                .times(1.0 / points.len() as f64);
            let radius = points
                .iter()
                .map(|q| q.minus(centre).length())
                .fold(0.0, f64::max);
            let off = centre.minus(c);
            let across = (off.x * cd.y - off.y * cd.x).abs() / cd.length();
            across < radius && along(centre) > 1.0
        }
        _ => false,
    });
    assert!(round_the_shaft, "M a curved arrow round x past D");
    for label in [
        "$C$", "$D$", "$M$", "$C_y$", "$C_z$", "$D_y$", "$D_z$", "$c$",
    ] {
        assert!(
            drawn.labels.iter().any(|l| l.markup == label),
            "label {label}"
        );
    }
}

/// SP 18.1: the plate a × b and the blow F Δt at its corner (−a/2, −b/2, 0).
#[test]
fn the_plate_and_the_blow_of_sample_problem_18_1() {
    let scene = example("sp18_1_plate_impact");
    let drawn = figure(&scene).unwrap();
    let sizes = Sizes::of(&scene);
    let size = |s: &str| sizes.of_expr(&Expr::sym(Symbol::new(s))).unwrap();
    let (a, b) = (size("a") / 2.0, size("b") / 2.0);
    let corners = [[-a, -b, 0.0], [a, -b, 0.0], [a, b, 0.0], [-a, b, 0.0]].map(|p| drawn.at(p));
    let plate = drawn.marks.iter().any(|m| {
        matches!(m, Mark::Path { points, filled: true, .. }
        if points.len() == 4 && corners.iter().all(|c| points.iter().any(|p| near(*p, *c))))
    });
    assert!(plate, "the plate's four corners");
    let blow = drawn
        .marks
        .iter()
        .any(|m| matches!(m, Mark::Arrow { role: Role::Impulse, to, .. } if near(*to, corners[0])));
    assert!(blow, "the blow at the corner");
    assert!(
        drawn.labels.iter().any(|l| l.markup.contains(r"\Delta t")),
        "F Δt labelled"
    );
    for label in ["$a$", "$b$", r"$\omega_x$", r"$\omega_y$"] {
        assert!(
            drawn.labels.iter().any(|l| l.markup == label),
            "label {label}"
        );
    }
}

/// The top: the vertical, θ, and the rates φ̇ and ψ̇ as curved arrows.
#[test]
fn the_eulerian_angles_of_a_top() {
    let scene = example("top_steady_tilt");
    let drawn = figure(&scene).unwrap();
    for label in [r"$\theta$", r"$\dot\phi$", r"$\dot\psi$", "$Z$", "$W$"] {
        assert!(
            drawn.labels.iter().any(|l| l.markup == label),
            "label {label}"
        );
    }
    let rates = drawn
        .marks
        .iter()
        .filter(|m| matches!(m, Mark::Arrow { role: Role::Rate, via, .. } if via.len() > 10))
        .count();
    assert_eq!(rates, 2, "φ̇ and ψ̇ curved");
    // The vertical K is drawn up: the weight, along −K, straight down.
    let down = drawn.marks.iter().any(|m| {
        matches!(m, Mark::Arrow { role: Role::Force(n), from, to, .. }
        if n == "W" && (to.x - from.x).abs() < 1e-9 && to.y < from.y)
    });
    assert!(down, "the weight straight down");
}

/// The text content of an SVG `<text>` element, its `<tspan>`s joined.
fn text_of(node: roxmltree::Node) -> String {
    node.descendants()
        .filter(|n| n.is_text())
        .map(|n| n.text().unwrap_or(""))
        .collect()
}

/// A symbol as the figure writes it: its Unicode text, its scripts on the line (`F₂` is
/// `F2`, `ω_x` is `ωx`).
fn written(s: Symbol) -> String {
    let latex = kinetics::print::latex(&Expr::sym(s));
    kinetics::print::markup::text(&format!("${latex}$"))
        .chars()
        .filter(|c| !matches!(c, '_' | '^' | ' '))
        .map(|c| match c {
            '₀'..='₉' => char::from(b'0' + (c as u32 - '₀' as u32) as u8),
            c => c,
        })
        .collect()
}

/// Each example's HTML page holds one inline `<svg>`, well-formed XML, with a `<text>` for
/// every force, couple and impulse (by name, or the symbols of its components) and each axis.
#[test]
fn each_html_page_holds_one_svg_with_the_loads_and_axes_labelled() {
    for (name, scene) in examples() {
        let path = scene_path(&name);
        let (code, html, err) = kinetics(&["solve", "--format", "html", &path]);
        assert_eq!(code, 0, "{name}: {err}");
        assert_eq!(html.matches("<svg").count(), 1, "{name}: one figure");
        let start = html.find("<svg").unwrap();
        let end = html.find("</svg>").unwrap() + "</svg>".len();
        let doc = roxmltree::Document::parse(&html[start..end])
            .unwrap_or_else(|e| panic!("{name}: the SVG is not XML: {e}"));
        let texts: Vec<String> = doc
            .descendants()
            .filter(|n| n.has_tag_name("text"))
            .map(text_of)
            .collect();
        let has = |t: &str| texts.iter().any(|x| x == t);
        for axis in ["x", "y", "z"] {
            assert!(has(axis), "{name}: axis {axis} in {texts:?}");
        }
        let all = texts.join(" ");
        let symbols_shown = |v: &kinetics::Vector| {
            v.iter()
                .flat_map(|c| c.symbols())
                .filter(|s| !s.is_pi())
                .all(|s| all.contains(&written(s)))
        };
        for f in &scene.forces {
            // A force named by a word (`front = N_A*j`) along one axis is labelled by its
            // magnitude's symbols, as a textbook labels it; else by its name.
            let word = f.name.len() >= 3 && f.name.chars().all(|c| c.is_ascii_lowercase());
            let one_axis = f.value.iter().filter(|c| !c.is_zero()).count() == 1;
            // Drawn by components at O or G (which have their letters), by its components.
            let shown = match word && one_axis {
                true => symbols_shown(&f.value),
                false => has(&written(Symbol::new(&f.name))) || symbols_shown(&f.value),
            };
            assert!(shown, "{name}: force {} in {texts:?}", f.name);
        }
        for c in &scene.couples {
            assert!(symbols_shown(c), "{name}: a couple's symbols in {texts:?}");
        }
        for i in &scene.impulses {
            // Named, by its name, or, drawn by its components at a point that has its letter
            // (the post's A), by those (R_x, R_y), as a force is.
            let shown = match i.name {
                Some(s) => has(&written(s)) || symbols_shown(&i.value),
                None => symbols_shown(&i.value),
            };
            assert!(shown, "{name}: an impulse in {texts:?}");
        }
    }
}

fn scene_path(name: &str) -> String {
    scene(name)
}

/// In headless Chromium, every label of every example's figure lies inside its picture, apart
/// from the others and inside the box it was placed by, by its ink: the box is as tall as
/// the letters with a subscript's drop or an accent (a plain `G` stands as near its anchor
/// as it looks, `B_y` has its subscript's room), and the text's baseline centres the ink
/// in it.
#[test]
fn in_a_browser_the_labels_are_inside_the_picture_and_apart() {
    let mut page = String::from("<!DOCTYPE html>\n<html><body>\n");
    for (name, scene) in examples() {
        let drawn = figure(&scene).unwrap();
        // Each label's box, as the SVG's coordinates have it (y down).
        let boxes: Vec<String> = drawn
            .labels
            .iter()
            .map(|l| {
                format!(
                    "[{},{},{},{}]",
                    l.centre.x, -l.centre.y, l.half_width, l.half_height
                )
            })
            .collect();
        page.push_str(&format!(
            "<div data-name=\"{name}\" data-boxes=\"[{}]\">{}</div>\n",
            boxes.join(","),
            kinetics::figure::svg::inline(&drawn)
        ));
    }
    page.push_str(CHECK);
    page.push_str("</body></html>\n");
    let dir = std::env::temp_dir().join(format!("kinetics-figures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("figures.html");
    std::fs::write(&file, page).unwrap();
    let dom = chromium(&dir, &file, &["--dump-dom"]);
    let _ = std::fs::remove_dir_all(&dir);
    let verdict = dom
        .split("<pre id=\"verdict\">")
        .nth(1)
        .and_then(|rest| rest.split("</pre>").next())
        .unwrap_or_else(|| panic!("no verdict in the DOM:\n{dom}"));
    assert!(verdict.starts_with("ok "), "{verdict}");
    let checked: usize = verdict["ok ".len()..].trim().parse().unwrap();
    assert!(
        checked >= 5 * example_scenes().len(),
        "labels checked: {checked}"
    );
}

/// The check run in the page: each `<text>`'s box inside its `<svg>`'s and clear of the
/// others' (a pixel's tolerance: glyphs' boxes carry their side bearings).
const CHECK: &str = r#"<script>
(function () {
  // A label's ink, in the page's pixels: across, its glyphs' advance (the box the browser
  // lays it out in); up and down, each piece's ink above and below its baseline as a canvas
  // measures it in the same face and size, a script's shifted by its baseline-shift (the
  // browser's box of a text is its font's whole line, taller than any glyph in it).
  const canvas = document.createElement('canvas').getContext('2d');
  function ink(t, svg, rect) {
    const view = svg.viewBox.baseVal;
    const baseline = rect.top + (t.y.baseVal[0].value - view.y) * rect.height / view.height;
    const scale = rect.height / view.height;
    let above = 0, below = 0;
    for (const node of t.childNodes) {
      const words = node.textContent;
      if (!words.trim()) continue;
      const style = getComputedStyle(node.nodeType === 1 ? node : t);
      const size = parseFloat(style.fontSize);
      const shift = node.nodeType === 1 && node.getAttribute('baseline-shift')
        ? parseFloat(node.getAttribute('baseline-shift')) * size : 0;
      canvas.font = style.fontStyle + ' ' + size + 'px ' + style.fontFamily;
      const m = canvas.measureText(words);
      above = Math.max(above, m.actualBoundingBoxAscent + shift);
      below = Math.max(below, m.actualBoundingBoxDescent - shift);
    }
    const across = t.getBoundingClientRect();
    return { left: across.left, right: across.right, top: baseline - above * scale, bottom: baseline + below * scale };
  }
  const problems = [];
  let labels = 0;
  for (const div of document.querySelectorAll('div[data-name]')) {
    const svg = div.querySelector('svg');
    const frame = svg.getBoundingClientRect();
    const boxes = [...div.querySelectorAll('text')].map(t => [t.textContent, ink(t, svg, frame)]);
    labels += boxes.length;
    const view = svg.viewBox.baseVal, scale = frame.height / view.height;
    JSON.parse(div.dataset.boxes).forEach(([x, y, w, h], i) => {
      const b = boxes[i][1];
      const [left, right] = [frame.left + (x - w - view.x) * scale, frame.left + (x + w - view.x) * scale];
      const [top, bottom] = [frame.top + (y - h - view.y) * scale, frame.top + (y + h - view.y) * scale];
      if (b.top < top - 0.5 || b.bottom > bottom + 0.5 || b.left < left - 0.5 || b.right > right + 0.5)
        problems.push(div.dataset.name + ': ' + boxes[i][0] + ' outside its box by ' +
          [top - b.top, b.bottom - bottom, left - b.left, b.right - right].map(d => d.toFixed(1)).join(' '));
    });
    boxes.forEach(([t, b], i) => {
      if (b.left < frame.left - 0.5 || b.right > frame.right + 0.5 || b.top < frame.top - 0.5 || b.bottom > frame.bottom + 0.5)
        problems.push(div.dataset.name + ': ' + t + ' outside');
      for (const [u, c] of boxes.slice(i + 1)) {
        const w = Math.min(b.right, c.right) - Math.max(b.left, c.left);
        const h = Math.min(b.bottom, c.bottom) - Math.max(b.top, c.top);
        if (w > -1 && h > -1) problems.push(div.dataset.name + ': ' + t + ' over ' + u);
      }
    });
  }
  const verdict = document.createElement('pre');
  verdict.id = 'verdict';
  verdict.textContent = problems.length ? problems.join('\n') : 'ok ' + labels;
  document.body.appendChild(verdict);
})();
</script>
"#;

/// `solve --format markdown -o page.md` writes the page and its figure beside it, the page
/// naming the figure; without `-o` the page says how to have it.
#[test]
fn a_markdown_page_has_its_figure_beside_it() {
    let dir = std::env::temp_dir().join(format!("kinetics-md-figure-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let page = dir.join("shaft.md");
    let path = scene("sp18_4_shaft_reactions");
    let (code, out, err) = kinetics(&[
        "solve",
        "--format",
        "markdown",
        "-o",
        page.to_str().unwrap(),
        &path,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.trim().is_empty(), "the page went to the file");
    let md = std::fs::read_to_string(&page).unwrap();
    assert!(md.contains("](shaft.svg)"), "{md}");
    let svg = std::fs::read_to_string(dir.join("shaft.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).expect("the SVG file is XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    assert_eq!(
        doc.root_element().tag_name().namespace(),
        Some("http://www.w3.org/2000/svg")
    );
    let _ = std::fs::remove_dir_all(&dir);
    let (_, md, _) = kinetics(&["solve", "--format", "markdown", &path]);
    assert!(
        md.contains("`kinetics solve -o FILE.md` writes `FILE.svg`"),
        "{md}"
    );
    let (_, text, _) = kinetics(&["solve", &path]);
    assert!(
        !text.contains("svg") && !text.contains("tikz"),
        "text has no figure"
    );
}

/// `kinetics figure` writes SVG, or TikZ with its picture's bounding box.
#[test]
fn the_figure_command_writes_svg_and_tikz() {
    let path = scene("top_steady_tilt");
    let (code, svg, err) = kinetics(&["figure", &path]);
    assert_eq!(code, 0, "{err}");
    roxmltree::Document::parse(&svg).expect("XML");
    let (code, tikz, err) = kinetics(&["figure", "--format", "tikz", &path]);
    assert_eq!(code, 0, "{err}");
    assert!(tikz.starts_with("\\begin{tikzpicture}") && tikz.contains("\\useasboundingbox"));
    assert!(tikz.contains(r"{$\dot{\psi}$}"), "{tikz}");
}

/// The frame's Ω where it differs from ω: the cone's Ω = ω₁ j (ω's component along y holds
/// p too) a double arrow of its own on the ray from the fixed point O along y, labelled ω₁
/// as the statement names that rate; SP 18.2's
/// Ω = −ω₂ j, which is ω's component along −y, on that component's arrow, labelled with both;
/// where the frame turns with the body (SP 18.4), no Ω; a known ω whose component the frame
/// turns with is drawn by its components (the disk on a turning axle).
#[test]
fn the_frame_rate_is_drawn_where_it_differs_from_omega() {
    let frame_rate_along = |drawn: &Figure, axis: [f64; 3]| {
        let o = drawn.at([0.0; 3]);
        let e = drawn.at(axis).minus(o);
        drawn.marks.iter().any(|m| match m {
            Mark::Arrow {
                role: Role::FrameRate,
                from,
                to,
                double: true,
                ..
            } => {
                let (tail, along) = (from.minus(o), to.minus(*from));
                // On the ray, or beside it where it is an axis.
                let on_the_ray = (tail.x * e.y - tail.y * e.x).abs()
                    <= (farthest_beside() + 1e-6) * e.length()
                    && tail.x * e.x + tail.y * e.y >= 0.0;
                on_the_ray
                    && (along.x * e.y - along.y * e.x).abs() < 1e-6 * along.length() * e.length()
                    && along.x * e.x + along.y * e.y > 0.0
            }
            _ => false,
        })
    };
    let written = |s: &str| kinetics::print::latex(&Expr::sym(Symbol::new(s)));
    let cone = figure(&example("cone_rolling_about_apex")).unwrap();
    assert!(
        frame_rate_along(&cone, [0.0, 1.0, 0.0]),
        "the cone's Ω along y"
    );
    assert!(cone
        .labels
        .iter()
        .any(|l| l.markup == format!("${}$", written("w1"))));
    let disk = figure(&example("sp18_2_rolling_disk")).unwrap();
    assert!(
        !frame_rate_along(&disk, [0.0, -1.0, 0.0]),
        "no second arrow"
    );
    let both = disk
        .labels
        .iter()
        .any(|l| l.markup.contains(&written("omega_2")) && l.markup.contains(&written("Omega")));
    assert!(both, "ω₂'s arrow labelled with Ω");
    let shaft = figure(&example("sp18_4_shaft_reactions")).unwrap();
    assert!(!shaft.marks.iter().any(|m| matches!(
        m,
        Mark::Arrow {
            role: Role::FrameRate,
            ..
        }
    )));
    // The disk on a turning axle, ω = ω₁ i + ω₂ j with Ω = ω₂ j: the two rotations drawn
    // apart (ω₁ along the axle, ω₂ = Ω about y), the spin's rate α₁ along the axle, and no
    // fixed axis (ω turns with the axle).
    let axle = figure(&example("disk_on_turning_axle")).unwrap();
    let o = axle.at([0.0; 3]);
    let double_along = |role: Role, axis: [f64; 3]| {
        let e = axle.at(axis).minus(o);
        axle.marks.iter().any(|m| match m {
            Mark::Arrow {
                role: r,
                from,
                to,
                double: true,
                ..
            } if *r == role => {
                let d = to.minus(*from);
                at_or_beside(*from, *to, o)
                    && (d.x * e.y - d.y * e.x).abs() < 1e-6 * d.length() * e.length()
                    && d.x * e.x + d.y * e.y > 0.0
            }
            _ => false,
        })
    };
    assert!(
        double_along(Role::AngularVelocity, [1.0, 0.0, 0.0]),
        "ω₁ along x"
    );
    assert!(
        double_along(Role::AngularVelocity, [0.0, 1.0, 0.0]),
        "ω₂ along y"
    );
    assert!(
        double_along(Role::AngularAcceleration, [1.0, 0.0, 0.0]),
        "α₁ along x"
    );
    for label in [
        format!("${}$", written("w1")),
        format!("${} = {}$", written("w2"), written("Omega")),
        format!("${}$", written("alpha1")),
    ] {
        assert!(axle.labels.iter().any(|l| l.markup == label), "{label}");
    }
    let centre_line = axle
        .marks
        .iter()
        .any(|m| matches!(m, Mark::Path { stroke, .. } if stroke.dashes == Dashes::CentreLine));
    assert!(!centre_line, "no fixed axis");
}

/// The engineer's page (`--numbers`) starts from the figure too: before Given in LaTeX (and
/// the document compiles), inline in HTML, none in text.
#[test]
fn the_numbers_page_has_the_figure_too() {
    let path = scene("sp18_4_shaft_reactions");
    let (code, tex, err) = kinetics(&[
        "solve",
        "--numbers",
        "--format",
        "latex",
        "--standalone",
        &path,
    ]);
    assert_eq!(code, 0, "{err}");
    let figure = tex.find("\\begin{tikzpicture}").expect("the figure");
    assert!(
        figure < tex.find("\\paragraph{Given}").expect("Given"),
        "before Given"
    );
    let dir = std::env::temp_dir().join(format!("kinetics-numbers-figure-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("numbers.tex");
    std::fs::write(&file, &tex).unwrap();
    let error = crate::common::pdflatex::pdflatex(&dir, &file).first_error();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(error, None);
    let (_, html, _) = kinetics(&["solve", "--numbers", "--format", "html", &path]);
    assert_eq!(html.matches("<svg").count(), 1);
    let (_, text, _) = kinetics(&["solve", "--numbers", &path]);
    assert!(!text.contains("svg") && !text.contains("tikz"));
}

/// A tilt the scene names is marked: the disk on its shaft turned β about z shows an arc from
/// the line y to the disk's diameter (−sin β, cos β, 0), both through G, labelled β (its
/// axis, along the shaft toward the reader, would be seen nearly end-on).
#[test]
fn the_tilt_of_the_disk_on_its_shaft_is_marked_with_beta() {
    let scene = example("disk_tilted_on_shaft");
    let drawn = figure(&scene).unwrap();
    let beta = Sizes::of(&scene)
        .of_expr(&Expr::sym(Symbol::new("beta")))
        .unwrap();
    let g = drawn.at([0.0; 3]);
    // A drawn point lies on the ray from G toward the scene's direction d.
    let on_ray = |p: P2, d: [f64; 3]| {
        let (u, v) = (drawn.at(d).minus(g), p.minus(g));
        (u.x * v.y - u.y * v.x).abs() < 1e-6 * u.length() * v.length()
            && u.x * v.x + u.y * v.y > 0.0
    };
    let diameter = [-beta.sin(), beta.cos(), 0.0];
    let arc = drawn.marks.iter().any(|m| {
        matches!(m, Mark::Path { points, .. } if points.len() > 10
            && on_ray(points[0], [0.0, 1.0, 0.0])
            && on_ray(*points.last().unwrap(), diameter))
    });
    assert!(arc, "an arc from y to the disk's diameter");
    let label = format!(
        "${}$",
        kinetics::print::latex(&Expr::sym(Symbol::new("beta")))
    );
    assert!(drawn.labels.iter().any(|l| l.markup == label), "β labelled");
}

/// SP 18.4's shaft is dimensioned as the textbook's figure: C (at O), the rod at L/4, the rod
/// at L/2 and D at L, the spans L/4, L/4 and L/2 labelled in the scene's symbols.
#[test]
fn the_shaft_of_sample_problem_18_4_is_dimensioned() {
    let scene = example("sp18_4_shaft_reactions");
    let drawn = figure(&scene).unwrap();
    let l = Expr::sym(Symbol::new("L"));
    let written = |e: Expr| format!("${}$", kinetics::print::latex(&e));
    let count = |e: Expr| {
        let w = written(e);
        drawn
            .labels
            .iter()
            .filter(|label| label.markup == w)
            .count()
    };
    assert_eq!(count(&l / &Expr::int(4)), 2, "two spans of L/4");
    assert_eq!(count(&l / &Expr::int(2)), 1, "one span of L/2");
}

/// The rod that strikes a post shows its motion just before the blow, as the statement gives
/// it: v̄₀ = v₀ i an arrow from G along x and ω₀ = ω₀ k, each labelled by its magnitude.
#[test]
fn the_motion_before_an_impact_is_drawn() {
    let scene = example("spinning_rod_strikes_a_post");
    let drawn = figure(&scene).unwrap();
    let g = drawn.at([0.0; 3]);
    let x = drawn.at([1.0, 0.0, 0.0]).minus(g);
    let along_x = drawn.marks.iter().any(|m| {
        matches!(m, Mark::Arrow { role: Role::Velocity, from, to, .. } if {
            let d = to.minus(*from);
            at_or_beside(*from, *to, g)
                && (d.x * x.y - d.y * x.x).abs() < 1e-6 * d.length() * x.length()
                && d.x * x.x + d.y * x.y > 0.0
        })
    });
    assert!(along_x, "v̄₀ from G along x");
    let latex = |name: &str| {
        format!(
            "${}$",
            kinetics::print::latex(&Expr::sym(Symbol::new(name)))
        )
    };
    for name in ["v0", "w0"] {
        let label = latex(name);
        assert!(
            drawn.labels.iter().any(|l| l.markup == label),
            "{label} labelled"
        );
    }
    // The unknown ω = w k after the blow is the answer, not the statement: only ω₀ is drawn.
    let rates = drawn
        .marks
        .iter()
        .filter(|m| {
            matches!(
                m,
                Mark::Arrow {
                    role: Role::AngularVelocity,
                    ..
                }
            )
        })
        .count();
    assert_eq!(rates, 1, "ω₀ alone");
    assert!(
        !drawn.labels.iter().any(|l| l.markup == latex("w")),
        "no ω after"
    );
}

/// A body pivoted at a point it does not reach hangs on a link of negligible mass, drawn
/// from O to it as SP 18.2 draws its axle OG: a bar in the shaft's stroke along OG from O to
/// G on the disk, labelled L by its middle; a top's stem from O up its axis to the disk; a
/// box's arm from O to its bottom face. A body that reaches O (the cone on its apex, the box
/// on its corner) has none.
#[test]
fn a_body_pivoted_off_itself_hangs_on_a_link_from_o() {
    for (name, length) in [
        ("sp18_2_rolling_disk", Some("L")),
        ("sp18_5_disk_reactions", Some("L")),
        ("top_steady_tilt", None),
        ("box_centre_on_axis", None),
    ] {
        let scene = example(name);
        let drawn = figure(&scene).unwrap();
        let (o, g) = (
            drawn.at([0.0; 3]),
            drawn_at(&drawn, &scene, &scene.parts[0].position),
        );
        let og = g.minus(o);
        let t = |p: P2| (p.minus(o).x * og.x + p.minus(o).y * og.y) / (og.x * og.x + og.y * og.y);
        let off = |p: P2| (p.minus(o).x * og.y - p.minus(o).y * og.x).abs() / og.length();
        let bar = two_point_paths(&drawn, Stroke::SHAFT);
        assert!(!bar.is_empty(), "{name}: a link drawn");
        for (a, b) in &bar {
            for p in [*a, *b] {
                assert!(off(p) < 1e-6, "{name}: the link on OG");
                assert!(
                    (-1e-9..=1.0 + 1e-9).contains(&t(p)),
                    "{name}: the link between O and G"
                );
            }
        }
        assert!(
            bar.iter().any(|(a, _)| near(*a, o)),
            "{name}: the link from O"
        );
        let end = bar.iter().map(|(_, b)| t(*b)).fold(0.0, f64::max);
        match name {
            // The arm meets the box at its bottom face, c/2 below G at L above O.
            "box_centre_on_axis" => assert!(end > 0.8 && end < 1.0, "{name}: to the box, {end}"),
            _ => assert!((end - 1.0).abs() < 1e-9, "{name}: on to G, {end}"),
        }
        if let Some(length) = length {
            let label = format!(
                "${}$",
                kinetics::print::latex(&Expr::sym(Symbol::new(length)))
            );
            let middle = o.plus(og.times(0.5));
            let by_the_middle = drawn
                .labels
                .iter()
                .any(|l| l.markup == label && l.centre.minus(middle).length() < 0.25 * og.length());
            assert!(by_the_middle, "{name}: {label} by the link's middle");
        }
    }
    for name in ["cone_rolling_about_apex", "box_about_body_diagonal"] {
        let drawn = figure(&example(name)).unwrap();
        assert!(
            two_point_paths(&drawn, Stroke::SHAFT).is_empty(),
            "{name}: no link"
        );
    }
}

/// ω at the mass centre inside a box goes under the box's faces until it comes out of one,
/// as the axes do, and is drawn in front from there: in the torque-free box, whose ω lies
/// nearly along y, a line in ω's stroke from G (beside the y axis), drawn before (under) the
/// box's outline, runs to the tail of ω's double arrow, within a step of the reach (a
/// twentieth) short of where ω's line leaves the face y = b/2. A flat plate hides nothing:
/// SP 18.1's ω components start at G.
#[test]
fn omega_inside_a_box_goes_under_its_faces() {
    let scene = example("free_body");
    let drawn = figure(&scene).unwrap();
    let value = |name: &str| {
        let given = scene.givens.iter().find(|g| g.symbol == Symbol::new(name));
        given
            .and_then(|g| g.value)
            .unwrap_or_else(|| panic!("no {name}"))
    };
    let (a, b, c) = (value("a"), value("b"), value("c"));
    let omega = [value("w_1"), value("w_2"), value("w_3")];
    // Where ω's line from G (the origin) leaves the face y = b/2 of the box a × b × c.
    let exit = omega.map(|w| w * (b / 2.0) / omega[1]);
    let step = 0.05 * (a * a + b * b + c * c).sqrt() / 2.0;
    let o = drawn.at([0.0; 3]);
    let unit_drawn = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
        .map(|e| drawn.at(e).minus(o).length())
        .into_iter()
        .sum::<f64>();
    let (index, tail) = drawn
        .marks
        .iter()
        .enumerate()
        .find_map(|(k, m)| match m {
            Mark::Arrow {
                role: Role::AngularVelocity,
                from,
                ..
            } => Some((k, *from)),
            _ => None,
        })
        .expect("ω drawn");
    let short = tail.minus(drawn.at(exit)).length();
    assert!(
        short <= step * unit_drawn,
        "ω's arrow from its face, {short} off"
    );
    let under = drawn.marks.iter().position(|m| {
        matches!(m, Mark::Path { points, stroke, .. }
            if *stroke == Stroke::MOTION
                && points[0].minus(o).length() <= farthest_beside() + 1e-6
                && near(points[1], tail))
    });
    let outline = drawn
        .marks
        .iter()
        .position(|m| matches!(m, Mark::Path { stroke, .. } if *stroke == Stroke::OUTLINE));
    match (under, outline) {
        (Some(u), Some(f)) => assert!(u < f && f < index, "under the faces, ω's arrow over them"),
        _ => panic!("ω's line from G under the box: {under:?}, outline {outline:?}"),
    }
    let plate = example("sp18_1_plate_impact");
    let drawn = figure(&plate).unwrap();
    let g = drawn_at(&drawn, &plate, &plate.parts[0].position);
    for m in &drawn.marks {
        if let Mark::Arrow {
            role: Role::AngularVelocity,
            from,
            to,
            ..
        } = m
        {
            assert!(at_or_beside(*from, *to, g), "the plate's ω from G");
        }
    }
}

/// A rate the constraints fix is drawn as it turns out. The cone rolls on the x axis (a
/// generator) with O fixed, so every point of that line is still: ω × (h, 0, 0) = 0 puts ω
/// along x, and its y component p r/l + ω₁ vanishes. Taking ω_y = 0 gives p = −l ω₁/r,
/// and then ω_x = p h/l = −h ω₁/r < 0. So ω is one double arrow along −x, labelled ω. With
/// p left at 1 it was drawn as ω_x along +x plus an ω_y that is zero.
#[test]
fn a_rate_the_constraints_fix_points_the_way_it_turns_out() {
    let cone = figure(&example("cone_rolling_about_apex")).unwrap();
    let o = cone.at([0.0; 3]);
    let minus_x = o.minus(cone.at([1.0, 0.0, 0.0]));
    let omegas: Vec<P2> = cone
        .marks
        .iter()
        .filter_map(|m| match m {
            Mark::Arrow {
                role: Role::AngularVelocity,
                from,
                to,
                ..
            } => Some(to.minus(*from)),
            _ => None,
        })
        .collect();
    assert_eq!(omegas.len(), 1, "ω one arrow, no zero component drawn");
    let d = omegas[0];
    assert!(
        (d.x * minus_x.y - d.y * minus_x.x).abs() < 1e-6 * d.length() * minus_x.length()
            && d.x * minus_x.x + d.y * minus_x.y > 0.0,
        "ω along −x: {d:?}"
    );
    let written = kinetics::print::latex(&Expr::sym(Symbol::new("omega")));
    assert!(cone
        .labels
        .iter()
        .any(|l| l.markup == format!("${written}$")));
}

/// The motion the statement gives is drawn: SP 18.4's α (omegadot = alpha*i, the way ω
/// turns) a double arrow of its own along the shaft x, past ω's, each labelled alone (a
/// label "ω, α" on one arrow named two quantities at once); slowing down (α = −α i) along
/// −x; and the frame of three rods' v̄ labelled at G.
#[test]
fn the_stated_alpha_and_vbar_are_drawn() {
    let find = |name: &str| figure(&example(name)).unwrap();
    let written = |s: &str| kinetics::print::latex(&Expr::sym(Symbol::new(s)));
    let double_along = |drawn: &Figure, role: Role, axis: P2| {
        drawn.marks.iter().any(|m| {
            matches!(m, Mark::Arrow { role: r, from, to, double: true, .. }
            if *r == role && {
                let d = to.minus(*from);
                (d.x * axis.y - d.y * axis.x).abs() < 1e-6 * d.length() * axis.length()
                    && d.x * axis.x + d.y * axis.y > 0.0
            })
        })
    };
    let scene = example("sp18_4_shaft_reactions");
    let shaft = figure(&scene).unwrap();
    let o = shaft.at([0.0; 3]);
    let x = shaft.at([1.0, 0.0, 0.0]).minus(o);
    assert!(double_along(&shaft, Role::AngularVelocity, x), "ω along x");
    assert!(
        double_along(&shaft, Role::AngularAcceleration, x),
        "α along x"
    );
    for name in ["omega", "alpha"] {
        assert!(
            shaft
                .labels
                .iter()
                .any(|l| l.markup == format!("${}$", written(name))),
            "{name} labelled alone"
        );
    }
    let mut slowing = scene.clone();
    slowing.omega_dot = scene.omega_dot.as_ref().map(|a| a.map(|c| -c));
    let slowing = figure(&slowing).unwrap();
    let minus_x = x.times(-1.0);
    assert!(
        double_along(&slowing, Role::AngularAcceleration, minus_x),
        "α along −x"
    );
    assert!(slowing
        .labels
        .iter()
        .any(|l| l.markup == format!("${}$", written("alpha"))));
    let frame = find("long_relations");
    let velocity = frame.marks.iter().any(|m| {
        matches!(
            m,
            Mark::Arrow {
                role: Role::Velocity,
                ..
            }
        )
    });
    assert!(velocity, "v̄ drawn");
    assert!(frame
        .labels
        .iter()
        .any(|l| l.markup == format!("${}$", written("vbar"))));
    // The car wheel's ā = −v²/R k, from G toward the curve's centre, along −z as drawn.
    let scene = example("car_wheel_on_a_curve");
    let wheel = figure(&scene).unwrap();
    let g = wheel.at([0.0; 3]);
    let minus_z = wheel.at([0.0, 0.0, -1.0]).minus(g);
    let toward_centre = wheel.marks.iter().any(|m| match m {
        Mark::Arrow {
            role: Role::Acceleration,
            from,
            to,
            double: false,
            ..
        } => {
            let d = to.minus(*from);
            near(*from, g)
                && (d.x * minus_z.y - d.y * minus_z.x).abs() < 1e-6 * d.length() * minus_z.length()
                && d.x * minus_z.x + d.y * minus_z.y > 0.0
        }
        _ => false,
    });
    assert!(toward_centre, "ā from G along −z");
    assert!(wheel
        .labels
        .iter()
        .any(|l| l.markup == format!("${}$", written("abar"))));
}

/// Where one rod crosses another as drawn, the nearer has paper under it that breaks the
/// farther: two rods square to each other, one over the other (along x at O, along y a
/// twentieth of their length above), drawn as an X; a white band under the upper rod's middle (nearer
/// the eye, seen from above) is drawn after the lower rod and covers the crossing.
#[test]
fn a_nearer_rod_breaks_a_farther_one_it_crosses() {
    let text = "given m = 1 kg\ngiven L = 1 m\nbody rod(L) mass m at (0, 0, 0) along x\nbody rod(L) mass m at (0, 0, L/20) along y\nvbar = 0\nomega = 0\nfind T";
    let scene = kinetics::parse_scene("cross.scene", text).unwrap();
    let drawn = figure(&scene).unwrap();
    let rods = two_point_paths(&drawn, Stroke::ROD);
    assert_eq!(rods.len(), 2, "two rods");
    let (lower, upper) = (rods[0], rods[1]);
    let (p, q) = lower;
    let (a, b) = upper;
    let (r, t) = (q.minus(p), b.minus(a));
    let den = r.x * t.y - r.y * t.x;
    let along_lower = ((a.x - p.x) * t.y - (a.y - p.y) * t.x) / den;
    let along_upper = ((a.x - p.x) * r.y - (a.y - p.y) * r.x) / den;
    assert!(
        (0.2..0.8).contains(&along_lower) && (0.2..0.8).contains(&along_upper),
        "the rods cross as drawn"
    );
    let crossing = p.plus(r.times(along_lower));
    let index = |target: &dyn Fn(&Mark) -> bool| drawn.marks.iter().position(target);
    let lower_at = index(&|m| {
        matches!(m, Mark::Path { points, stroke, .. }
            if *stroke == Stroke::ROD && near(points[0], p) && near(points[1], q))
    })
    .expect("the lower rod");
    let gap_at = index(&|m| match m {
        Mark::Path { points, stroke, .. } if stroke.ink == Ink::Paper => {
            let (c, d) = (points[0], points[1]);
            let on_upper = |x: P2| {
                (t.x * (x.y - a.y) - t.y * (x.x - a.x)).abs() < 1e-6 * t.length() * t.length()
            };
            let share = |x: P2| {
                let e = d.minus(c);
                ((x.x - c.x) * e.x + (x.y - c.y) * e.y) / (e.x * e.x + e.y * e.y)
            };
            on_upper(c)
                && on_upper(d)
                && (0.0..=1.0).contains(&share(crossing))
                && stroke.width > Stroke::ROD.width
        }
        _ => false,
    })
    .expect("paper under the upper rod at the crossing");
    assert!(gap_at > lower_at, "the band drawn over the farther rod");
}

/// The three-rod frame is seen from where no point that matters (O, G, a rod's end) is drawn
/// on a rod it is far from: its third rod crossed the first at G, and the frame read as a
/// closed triangle. Each rod's length is written nearer its own rod than the others.
#[test]
fn the_frame_is_seen_with_its_points_off_its_rods_and_sizes_by_their_rods() {
    let scene = example("long_relations");
    let drawn = figure(&scene).unwrap();
    let rods = two_point_paths(&drawn, Stroke::ROD);
    assert_eq!(rods.len(), 3, "three rods");
    let to_segment = |p: P2, (a, b): (P2, P2)| {
        let d = b.minus(a);
        let t = (((p.x - a.x) * d.x + (p.y - a.y) * d.y) / (d.x * d.x + d.y * d.y)).clamp(0.0, 1.0);
        a.plus(d.times(t)).minus(p).length()
    };
    // G, worked by hand: the rods' centres (L₁/2, 0, 0), (L₁, L₂/2, 0), (L₁, L₂, L₃/2)
    // weighted by their masses, at the figure's sizes.
    let sizes = Sizes::of(&scene);
    let masses: Vec<f64> = scene
        .parts
        .iter()
        .map(|p| sizes.of_expr(&p.mass).unwrap())
        .collect();
    let total: f64 = masses.iter().sum();
    let g = scene
        .parts
        .iter()
        .zip(&masses)
        .map(|(p, m)| sizes.of_vector(&p.position).unwrap().map(|c| c * m / total))
        .fold([0.0; 3], |s, c| [s[0] + c[0], s[1] + c[1], s[2] + c[2]]);
    let g = drawn.at(g);
    let shortest = rods
        .iter()
        .map(|(a, b)| b.minus(*a).length())
        .fold(f64::INFINITY, f64::min);
    for rod in &rods {
        assert!(
            to_segment(g, *rod) > 0.1 * shortest,
            "G drawn off every rod"
        );
    }
    let written = |s: &str| format!("${}$", kinetics::print::latex(&Expr::sym(Symbol::new(s))));
    for (part, name) in scene.parts.iter().zip(["L_1", "L_2", "L_3"]) {
        let label = drawn
            .labels
            .iter()
            .find(|l| l.markup == written(name))
            .unwrap_or_else(|| panic!("{name} written"));
        let centre = drawn_at(&drawn, &scene, &part.position);
        let own = rods
            .iter()
            .find(|(a, b)| near(a.plus(*b).times(0.5), centre))
            .expect("the part's rod");
        let mine = to_segment(label.centre, *own);
        for other in rods.iter().filter(|r| *r != own) {
            assert!(
                mine < to_segment(label.centre, *other),
                "{name} nearer its own rod"
            );
        }
    }
}

#[test]
fn a_box_has_its_three_sides_labelled() {
    let scene = example("sliding_box");
    let drawn = figure(&scene).unwrap();
    for side in ["b", "c", "d"] {
        let label = format!("${side}$");
        assert!(
            drawn.labels.iter().any(|l| l.markup == label),
            "side {side} labelled"
        );
    }
}

/// The points of the body's outline as drawn.
fn outline_points(drawn: &Figure) -> Vec<P2> {
    drawn
        .marks
        .iter()
        .filter_map(|m| match m {
            Mark::Path { points, stroke, .. } if *stroke == Stroke::OUTLINE => Some(points.clone()),
            _ => None,
        })
        .flatten()
        .collect()
}

/// Whether `p` lies outside the hull of `outline`: some direction takes it past them all.
fn outside_hull(p: P2, outline: &[P2]) -> bool {
    (0..360).any(|deg| {
        let (s, c) = f64::from(deg).to_radians().sin_cos();
        let reach = |q: P2| q.x * c + q.y * s;
        outline.iter().all(|q| reach(p) > reach(*q))
    })
}

/// A load pushing on a face comes into its point from outside, as a textbook draws a floor's
/// normal force (the sliding box's N_A: its head at its point, its tail below); one at a point
/// out of sight behind the body starts clear of the body as drawn (the free box's blow at its
/// far corner, not from G), dashed into its point, as the hidden edges there are, and solid
/// over the dashes until it passes behind the body's outline.
#[test]
fn pushes_come_into_their_points_and_hidden_loads_are_dashed() {
    let scene = example("sliding_box");
    let drawn = figure(&scene).unwrap();
    let front = scene.forces.iter().find(|f| f.name == "front").unwrap();
    let at = drawn_at(&drawn, &scene, &front.point);
    let into = drawn.marks.iter().any(|m| {
        matches!(m, Mark::Arrow { role: Role::Force(n), from, to, stroke, .. }
            if n == "front" && near(*to, at) && from.y < to.y && stroke.dashes == Dashes::Solid)
    });
    assert!(into, "N_A from below into its point, solid");
    let scene = example("free_box_struck_at_corner");
    let drawn = figure(&scene).unwrap();
    let corner = drawn_at(&drawn, &scene, &scene.impulses[0].point);
    let outline = outline_points(&drawn);
    let blow = drawn.marks.iter().find_map(|m| match m {
        Mark::Arrow {
            role: Role::Impulse,
            from,
            to,
            stroke,
            ..
        } => Some((*from, *to, *stroke)),
        _ => None,
    });
    let (from, to, stroke) = blow.expect("the blow drawn");
    // Into the corner, or beside it where its line is drawn along an axis.
    let off = to.minus(corner).length();
    assert!(off < farthest_beside() + 1e-6, "into the corner, {off} off");
    assert_eq!(
        stroke.dashes,
        Dashes::Hidden,
        "dashed: the corner is out of sight"
    );
    assert!(
        outside_hull(from, &outline),
        "from clear of the box as drawn"
    );
    // Its line in sight drawn solid over it, from its tail to where the box's outline
    // covers it: dashed only behind the box as drawn.
    let in_sight = drawn.marks.iter().any(|m| match m {
        Mark::Path { points, stroke, .. } if stroke.dashes == Dashes::Solid => {
            points.len() == 2
                && near(points[0], from)
                && !outside_hull(points[1], &outline)
                && points[1].minus(from).length() < to.minus(from).length()
        }
        _ => false,
    });
    assert!(in_sight, "solid from outside the box as drawn");
}

/// A load from a point beside the body that passes behind a disk's face is dashed there: the
/// horizontal wheel gyroscope's R_z, from O toward the wheel in front of it, is one dashed
/// arrow from O with its stretch in sight drawn solid over it, from O to where the wheel's
/// outline covers it; R_x and R_y, clear of the wheel, are solid.
#[test]
fn a_load_behind_a_disk_is_dashed_where_the_disk_covers_it() {
    let scene = example("wheel_gyroscope_horizontal");
    let drawn = figure(&scene).unwrap();
    let o = drawn.at([0.0; 3]);
    let outline = outline_points(&drawn);
    let reactions: Vec<(P2, P2, Stroke)> = drawn
        .marks
        .iter()
        .filter_map(|m| match m {
            Mark::Arrow {
                role: Role::Force(n),
                from,
                to,
                stroke,
                ..
            } if n == "R" => Some((*from, *to, *stroke)),
            _ => None,
        })
        .collect();
    assert_eq!(reactions.len(), 3, "R_x, R_y, R_z");
    let dashed: Vec<_> = reactions
        .iter()
        .filter(|(_, _, s)| s.dashes == Dashes::Hidden)
        .collect();
    assert_eq!(dashed.len(), 1, "only R_z passes behind the wheel");
    let (from, to, _) = *dashed[0];
    assert!(at_or_beside(from, to, o), "R_z from O");
    // Along z as drawn, toward G.
    let z = drawn.at([0.0, 0.0, 1.0]).minus(o);
    let along = to.minus(from);
    assert!((along.x * z.y - along.y * z.x).abs() < 1e-6 * along.length() * z.length());
    assert!(!outside_hull(to, &outline), "its head behind the wheel");
    let in_sight = drawn.marks.iter().any(|m| match m {
        Mark::Path { points, stroke, .. } if stroke.dashes == Dashes::Solid => {
            points.len() == 2
                && near(points[0], from)
                && !outside_hull(points[1], &outline)
                && points[1].minus(from).length() < along.length()
        }
        _ => false,
    });
    assert!(in_sight, "solid from O to the wheel's outline");
}

/// Two loads on one line come head to head, as a textbook draws them: in SP 18.5 the floor's
/// push N comes up into C and the weight W, at G straight above C, runs from G down toward C
/// and stops short of it, on the line GC, not beside it (where it read as a couple with N).
#[test]
fn a_weight_over_the_floors_push_stops_short_of_it_on_their_line() {
    let scene = example("sp18_5_disk_reactions");
    let drawn = figure(&scene).unwrap();
    let point_of = |name: &str| {
        let f = scene.forces.iter().find(|f| f.name == name).unwrap();
        drawn_at(&drawn, &scene, &f.point)
    };
    let (g, c) = (point_of("weight"), point_of("floor"));
    let arrow = |name: &str| {
        drawn.marks.iter().find_map(|m| match m {
            Mark::Arrow {
                role: Role::Force(n),
                from,
                to,
                ..
            } if n == name => Some((*from, *to)),
            _ => None,
        })
    };
    let (w_from, w_to) = arrow("weight").expect("W drawn");
    let (_, n_to) = arrow("floor").expect("N drawn");
    assert!(near(n_to, c), "N into C");
    assert!(near(w_from, g), "W from G itself, not beside");
    let (down, along) = (c.minus(g), w_to.minus(g));
    assert!(
        (down.x * along.y - down.y * along.x).abs() < 1e-6 * down.length() * along.length(),
        "W on the line GC"
    );
    let share = (along.x * down.x + along.y * down.y) / (down.x * down.x + down.y * down.y);
    assert!(share > 0.3 && share < 0.9, "W stops short of C: {share}");
}

/// A load drawn by its components at a point the scene names is not named again there: the
/// blow R at the post's A (spinning rod) and at the plate's corner C shows R_x, R_y (R_z) and
/// the point's letter, no stray R beside them.
#[test]
fn a_load_at_a_named_point_is_named_by_its_components() {
    for name in ["spinning_rod_strikes_a_post", "plate_falls_on_corner"] {
        let drawn = figure(&example(name)).unwrap();
        let written = |s: &str| format!("${}$", kinetics::print::latex(&Expr::sym(Symbol::new(s))));
        let labels: Vec<&str> = drawn.labels.iter().map(|l| l.markup.as_str()).collect();
        assert!(
            !labels.contains(&written("R").as_str()),
            "{name}: {labels:?}"
        );
        for component in ["R_x", "R_y"] {
            assert!(
                labels.contains(&written(component).as_str()),
                "{name}: {component}"
            );
        }
    }
}

/// ω about a fixed axis is drawn on the axis's centre line, as a textbook draws the axis of
/// rotation and ω: the box about its body diagonal and the plate about its diagonal each
/// have ω's double arrow on the line from O along ω as drawn, not beside it, and past the
/// body (from the box's corner O it ran over the top face).
#[test]
fn omega_about_a_fixed_axis_lies_on_it() {
    for name in ["box_about_body_diagonal", "plate_spinning_about_diagonal"] {
        let scene = example(name);
        let drawn = figure(&scene).unwrap();
        let o = drawn.at([0.0; 3]);
        let omega = scene.omega.as_ref().expect("ω given");
        let value: Vec<f64> = omega
            .iter()
            .map(|c| c.eval(&|s| scene.value(s)).unwrap())
            .collect();
        let e = drawn.at([value[0], value[1], value[2]]).minus(o);
        let on_line = |p: P2| {
            let q = p.minus(o);
            (q.x * e.y - q.y * e.x).abs() < 1e-6 * e.length() * e.length().max(q.length())
        };
        let arrow = drawn.marks.iter().find_map(|m| match m {
            Mark::Arrow {
                role: Role::AngularVelocity,
                from,
                to,
                double: true,
                ..
            } if on_line(*from) && on_line(*to) => Some(*from),
            _ => None,
        });
        let tail = arrow.unwrap_or_else(|| panic!("{name}: ω on its axis"));
        // Past the body along the axis: the box's far corner (a, b, c) from O at its corner,
        // the plate's corner (a/2, b/2, 0) from O at its centre.
        let sizes = Sizes::of(&scene);
        let size = |s: &str| sizes.of_expr(&Expr::sym(Symbol::new(s))).unwrap();
        let corner = match name {
            "box_about_body_diagonal" => [size("a"), size("b"), size("c")],
            _ => [size("a") / 2.0, size("b") / 2.0, 0.0],
        };
        let far = drawn.at(corner).minus(o);
        assert!(
            tail.minus(o).length() >= far.length() - 1e-6,
            "{name}: ω drawn past the body on its axis"
        );
    }
}

/// An unbalance's radius is dimensioned: the rotor's m₁ at (e₁, 0, z₁) and m₂ at
/// (−3/5 e₂, 4/5 e₂, z₂) each have a dimension line from the shaft's axis out to the mass,
/// labelled e₁ and e₂.
#[test]
fn the_unbalance_radii_are_dimensioned() {
    let scene = example("rotor_two_unbalance_masses");
    let drawn = figure(&scene).unwrap();
    let written = |s: &str| format!("${}$", kinetics::print::latex(&Expr::sym(Symbol::new(s))));
    for (part, radius) in scene.parts.iter().zip(["e1", "e2"]) {
        let mass = drawn_at(&drawn, &scene, &part.position);
        let mut foot = part.position.clone();
        foot[0] = Expr::zero();
        foot[1] = Expr::zero();
        let foot = drawn_at(&drawn, &scene, &foot);
        let line = drawn.marks.iter().any(|m| match m {
            Mark::Path { points, stroke, .. } if *stroke == Stroke::DIMENSION => {
                points.len() == 2
                    && (near(points[0], foot) && near(points[1], mass)
                        || near(points[1], foot) && near(points[0], mass))
            }
            _ => false,
        });
        assert!(line, "{radius}: a line from the axis to the mass");
        assert!(
            drawn.labels.iter().any(|l| l.markup == written(radius)),
            "{radius} labelled"
        );
    }
}

/// The floor a body rests or rolls on, a patch of its lowest level centred among the points
/// it holds: SP 18.2's disk at the contact (L, −r, 0); the cone between its contact point and
/// its apex O, which lies on the floor too (the line of contact is on it); the sliding box
/// between the points where the floor pushes straight up on it (N_A, N_B). A falling plate
/// held at the corner it strikes (a blow there) gets none, the scene shaping no ledge; nor
/// does a shaft whose bearing below the body takes an upward reaction (C of the bent rod).
#[test]
fn the_floor_under_a_body_resting_or_rolling_on_it() {
    let held = |scene: &Scene| -> Vec<kinetics::Vector> {
        scene
            .constraints
            .iter()
            .filter_map(|c| match &c.kind {
                kinetics::scene::model::ConstraintKind::VelocityZero(at) => Some(at.clone()),
                _ => None,
            })
            .collect()
    };
    let floors = |name: &str, points: &dyn Fn(&Scene) -> Vec<kinetics::Vector>| {
        let scene = example(name);
        let drawn = figure(&scene).unwrap();
        let points = points(&scene);
        let middle = points
            .iter()
            .map(|p| drawn_at(&drawn, &scene, p))
            .fold(P2::new(0.0, 0.0), |s, q| s.plus(q))
            .times(1.0 / points.len() as f64);
        let patches: Vec<P2> = closed_paths(&drawn, 4)
            .into_iter()
            .filter(|(stroke, _)| *stroke == Stroke::GROUND)
            .map(|(_, points)| {
                points
                    .iter()
                    .fold(P2::new(0.0, 0.0), |s, q| s.plus(*q))
                    .times(0.25)
            })
            .collect();
        (patches.len(), patches.iter().any(|c| near(*c, middle)))
    };
    assert_eq!(
        floors("sp18_2_rolling_disk", &held),
        (1, true),
        "the disk's floor"
    );
    let contact_and_apex = |scene: &Scene| {
        let mut points = held(scene);
        points.push(kinetics::Vector::zeros());
        points
    };
    assert_eq!(
        floors("cone_rolling_about_apex", &contact_and_apex),
        (1, true),
        "the cone's floor"
    );
    let pushed_up = |scene: &Scene| -> Vec<kinetics::Vector> {
        scene
            .forces
            .iter()
            .filter(|f| f.name == "front" || f.name == "back")
            .map(|f| f.point.clone())
            .collect()
    };
    assert_eq!(
        floors("sliding_box", &pushed_up),
        (1, true),
        "the box's floor"
    );
    // The car wheel's road, under its contact point C, which its rolling holds still.
    assert_eq!(
        floors("car_wheel_on_a_curve", &held),
        (1, true),
        "the wheel's road"
    );
    for name in ["plate_falls_on_corner", "bent_rod_vertical_shaft"] {
        assert_eq!(
            floors(name, &|_| vec![kinetics::Vector::zeros()]).0,
            0,
            "{name}"
        );
    }
}

/// A dimension's label stands on its own line, which its halo breaks, as a textbook sets it:
/// each of SP 18.4's spans (L/4, L/4, L/2) on the chain, and SP 18.2's axle OG (L, from O to
/// G) dimensioned too.
#[test]
fn dimension_labels_stand_on_their_lines() {
    let drawn = figure(&example("sp18_4_shaft_reactions")).unwrap();
    let lines = two_point_paths(&drawn, Stroke::DIMENSION);
    // How far the point is from the nearest dimension line.
    let from_lines = |p: P2| {
        lines
            .iter()
            .map(|(a, b)| {
                let d = b.minus(*a);
                let t = ((p.x - a.x) * d.x + (p.y - a.y) * d.y) / (d.x * d.x + d.y * d.y);
                a.plus(d.times(t.clamp(0.0, 1.0))).minus(p).length()
            })
            .fold(f64::INFINITY, f64::min)
    };
    let l = Expr::sym(Symbol::new("L"));
    let half = format!("${}$", kinetics::print::latex(&(&l / &Expr::int(2))));
    for span in [&l / &Expr::int(4), &l / &Expr::int(2)] {
        let markup = format!("${}$", kinetics::print::latex(&span));
        let labels: Vec<&Label> = drawn.labels.iter().filter(|x| x.markup == markup).collect();
        assert!(!labels.is_empty(), "{markup}");
        // On its line, or (a span too short for its figure) against it.
        for label in labels {
            let off = from_lines(label.centre);
            assert!(
                off < label.half_height + 6.0,
                "{markup} {off} from its line"
            );
            // The span with room for its figure, L/2, has it on the line.
            assert!(markup != half || off < 1e-6, "{markup} on its line");
        }
    }
    let axle = figure(&example("sp18_2_rolling_disk")).unwrap();
    assert!(axle.labels.iter().any(|x| x.markup == "$L$"), "OG = L");
}

/// An axis that comes out of the body toward the reader is drawn again, in front, from where
/// it leaves the body, so the face it passes in front of does not grey it: the free box's x
/// axis (toward the reader) has a second arrow to the same tip, starting where it leaves.
#[test]
fn axes_in_front_of_the_body_are_drawn_over_it() {
    let drawn = figure(&example("free_body")).unwrap();
    let o = drawn.at([0.0; 3]);
    let axes: Vec<(P2, P2)> = drawn
        .marks
        .iter()
        .filter_map(|m| match m {
            Mark::Arrow {
                role: Role::Axis,
                from,
                to,
                ..
            } => Some((*from, *to)),
            _ => None,
        })
        .collect();
    let whole = axes.iter().filter(|(from, _)| near(*from, o)).count();
    assert_eq!(whole, 3, "x, y, z from O");
    let x_tip = axes
        .iter()
        .filter(|(from, _)| near(*from, o))
        .map(|(_, to)| *to)
        .min_by(|a, b| {
            let x = drawn.at([1.0, 0.0, 0.0]).minus(o);
            let along = |p: &P2| -(p.minus(o).x * x.x + p.minus(o).y * x.y);
            along(a).total_cmp(&along(b))
        })
        .unwrap();
    let again = axes
        .iter()
        .any(|(from, to)| near(*to, x_tip) && !near(*from, o));
    assert!(again, "x drawn again in front from where it leaves the box");
}

/// A rate's curved arrow turns the way the rate does: the car wheel rolling forward spins at
/// ψ̇ = −v/r_w < 0, so its ψ̇ arrow about z turns opposite to a right-handed turn about z (the
/// signed area of its drawn curve against that of a circle turned right-handedly about z,
/// both as drawn); the gyroscope's ψ̇ = 3000 rpm > 0 turns right-handedly.
#[test]
fn a_negative_spin_is_drawn_turning_the_other_way() {
    // The signed area the curve sweeps about its points' mean (its circle's centre, near
    // enough for most of a turn).
    let area = |points: &[P2]| {
        let n = points.len() as f64;
        let c = points
            .iter()
            .fold(P2::new(0.0, 0.0), |a, p| a.plus(p.times(1.0 / n)));
        points
            .windows(2)
            .map(|w| {
                let (p, q) = (w[0].minus(c), w[1].minus(c));
                p.x * q.y - q.x * p.y
            })
            .sum::<f64>()
    };
    for (name, positive) in [
        ("car_wheel_on_a_curve", false),
        ("gyroscope_required_moment", true),
    ] {
        let drawn = figure(&example(name)).unwrap();
        let o = drawn.at([0.0; 3]);
        let z = drawn.at([0.0, 0.0, 1.0]).minus(o);
        let circle: Vec<P2> = (0..=12)
            .map(|k| {
                let t = std::f64::consts::TAU * 0.8 * f64::from(k) / 12.0;
                drawn.at([t.cos(), t.sin(), 0.0])
            })
            .collect();
        let right_handed = area(&circle);
        // The rate arrow whose middle lies on z's line as drawn: ψ̇'s.
        let spin = drawn.marks.iter().find_map(|m| match m {
            Mark::Arrow {
                role: Role::Rate,
                from,
                via,
                to,
                ..
            } => {
                let points: Vec<P2> = std::iter::once(*from)
                    .chain(via.iter().copied())
                    .chain([*to])
                    .collect();
                let n = points.len() as f64;
                let middle = points
                    .iter()
                    .fold(P2::new(0.0, 0.0), |a, p| a.plus(p.times(1.0 / n)));
                let off = middle.minus(o);
                let across = (off.x * z.y - off.y * z.x).abs() / z.length();
                (across < 0.2 * off.length()).then_some(points)
            }
            _ => None,
        });
        let spin = spin.unwrap_or_else(|| panic!("{name}: ψ̇ drawn about z"));
        let same = area(&spin) * right_handed > 0.0;
        assert_eq!(same, positive, "{name}: ψ̇ turns the way its sign says");
    }
}

/// Under no force the vertical Z is taken along the constant H_G (§18.11): each torque-free
/// figure draws H_G as an arrow up Z's centre line (from the body to below φ̇), labelled
/// H_G; a gyroscope under its weight and a couple has none.
#[test]
fn a_body_under_no_force_shows_h_g_along_z() {
    let written = |s: &str| format!("${}$", kinetics::print::latex(&Expr::sym(Symbol::new(s))));
    for (name, torque_free) in [
        ("torque_free_disk", true),
        ("torque_free_cylinder", true),
        ("torque_free_disk_from_omega", true),
        ("gyroscope_required_moment", false),
    ] {
        let scene = example(name);
        let drawn = figure(&scene).unwrap();
        let o = drawn.at([0.0; 3]);
        // Z, the fixed vertical: its centre line from O.
        let z_line = two_point_paths(&drawn, Stroke::CENTRE_LINE)
            .into_iter()
            .find(|(a, _)| near(*a, o));
        let up = match z_line {
            Some((_, b)) => b.minus(o),
            None => panic!("{name}: Z drawn"),
        };
        let momentum: Vec<(P2, P2)> = drawn
            .marks
            .iter()
            .filter_map(|m| match m {
                Mark::Arrow {
                    role: Role::AngularMomentum,
                    from,
                    to,
                    ..
                } => Some((*from, *to)),
                _ => None,
            })
            .collect();
        if !torque_free {
            assert!(momentum.is_empty(), "{name}: no H_G drawn");
            continue;
        }
        let [(from, to)] = momentum[..] else {
            panic!("{name}: one H_G arrow, {}", momentum.len())
        };
        for p in [from, to] {
            let off = p.minus(o);
            let across = (off.x * up.y - off.y * up.x).abs() / up.length();
            assert!(across < 1e-6, "{name}: H_G on the line of Z");
        }
        let d = to.minus(from);
        assert!(d.x * up.x + d.y * up.y > 0.0, "{name}: H_G up Z");
        assert!(
            drawn.labels.iter().any(|l| l.markup == written("H_G")),
            "{name}: H_G labelled"
        );
    }
}

/// A dimension's extension line is drawn on a side where no arrow runs along it: a rod
/// pivoted at its end O turning about x and precessing at ω₂ about −y has ω₂ drawn down from
/// O, and the span OG = L/2 below the rod would run its line from O over that arrow. Checked
/// on the drawing itself, there and in every example: no dimension stroke is parallel to an
/// arrow (within a degree) with both of the arrow's ends within a unit of its line and
/// beside it.
#[test]
fn extension_lines_run_over_no_arrow() {
    let rod = kinetics::parse_scene(
        "rod",
        "given m : kg\ngiven L : m\ngiven w1 : rad/s\nunknown w2 : rad/s\nbody rod(L) mass m at (L/2, 0, 0) along x
fixed point\nomega = w1*i - w2*j\nframe rate = -w2*j\nfind H_O",
    )
    .unwrap();
    let shaft = "sp18_4_shaft_reactions";
    let mut scenes = vec![
        ("rod".to_string(), rod, true),
        (shaft.to_string(), example(shaft), true),
    ];
    scenes.extend(
        examples()
            .into_iter()
            .map(|(name, scene)| (name, scene, false)),
    );
    for (name, scene, must) in &scenes {
        let drawn = figure(scene).unwrap();
        let dimensions = two_point_paths(&drawn, Stroke::DIMENSION);
        assert!(!*must || !dimensions.is_empty(), "{name}: dimensioned");
        for (a, b) in &dimensions {
            let d = b.minus(*a);
            let across = |p: P2| ((p.x - a.x) * d.y - (p.y - a.y) * d.x).abs() / d.length();
            let along = |p: P2| ((p.x - a.x) * d.x + (p.y - a.y) * d.y) / d.length();
            for mark in &drawn.marks {
                let Mark::Arrow { from, via, to, .. } = mark else {
                    continue;
                };
                if !via.is_empty() {
                    continue;
                }
                let (s, t) = (along(*from), along(*to));
                let beside = s.max(t) > 0.0 && s.min(t) < d.length();
                assert!(
                    !(across(*from) < 1.0 && across(*to) < 1.0 && beside),
                    "{name}: an arrow from ({:.1}, {:.1}) to ({:.1}, {:.1}) lies on an extension line",
                    from.x,
                    from.y,
                    to.x,
                    to.y
                );
            }
        }
    }
}

/// No two vectors' arrows are drawn on one line over each other or one running on from the
/// other's end (ω and v̄ the same way from G, a reaction's head at ω's tail): a reader would
/// take them for one arrow. Each pair of straight arrows that are not axes is checked: if
/// they are parallel and on one line, the gap between them along it is a real gap, or they
/// leave one tail the opposite ways (a reaction up from O, ω₂ down from it), which reads as
/// two arrows.
#[test]
fn no_two_arrows_read_as_one() {
    let mut failures = Vec::new();
    for (name, scene) in examples() {
        let drawn = figure(&scene).unwrap();
        let arrows: Vec<(P2, P2)> = drawn
            .marks
            .iter()
            .filter_map(|m| match m {
                Mark::Arrow {
                    from,
                    via,
                    to,
                    role,
                    ..
                } if via.is_empty() && *role != Role::Axis => Some((*from, *to)),
                _ => None,
            })
            .collect();
        for (i, (a0, a1)) in arrows.iter().enumerate() {
            for (b0, b1) in &arrows[i + 1..] {
                let Some(u) = a1.minus(*a0).unit() else {
                    continue;
                };
                let cross = |p: P2| (p.x - a0.x) * u.y - (p.y - a0.y) * u.x;
                let t = |p: P2| (p.x - a0.x) * u.x + (p.y - a0.y) * u.y;
                // On one line: both ends of the other within a hairline of this one's line.
                if cross(*b0).abs() > 1.0 || cross(*b1).abs() > 1.0 {
                    continue;
                }
                let from_one_tail = near(*a0, *b0) && t(*b1) < 0.0;
                if from_one_tail {
                    continue;
                }
                let (lo, hi) = (t(*b0).min(t(*b1)), t(*b0).max(t(*b1)));
                let length = a1.minus(*a0).length();
                let gap = (lo - length).max(-hi);
                if gap < 2.0 {
                    failures.push(format!("{name}: arrows {a0:?}→{a1:?} and {b0:?}→{b1:?}"));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// §18.11's disk stated by its ω (`constraint omega_y = w*sin(gamma)`, `omega_z =
/// w*cos(gamma)`): ω is drawn from G along `sin γ j + cos γ k` (γ = 30° given; θ, unknown,
/// is drawn at another angle so the two are told apart), and γ labels its angle from z.
#[test]
fn a_disk_stated_by_its_omega_shows_omega_at_gamma_from_its_axis() {
    let scene = example("torque_free_disk_from_omega");
    let drawn = figure(&scene).unwrap();
    let gamma = 30f64.to_radians();
    let along = drawn
        .at([0.0, gamma.sin(), gamma.cos()])
        .minus(drawn.at([0.0; 3]));
    let omega = drawn.marks.iter().find_map(|m| match m {
        Mark::Arrow {
            role: Role::AngularVelocity,
            from,
            to,
            ..
        } => Some((*from, *to)),
        _ => None,
    });
    let (from, to) = omega.expect("ω is drawn");
    assert!(near(from, drawn.at([0.0; 3])), "ω from G: {from:?}");
    let d = to.minus(from);
    let sine = (d.x * along.y - d.y * along.x) / (d.length() * along.length());
    assert!(
        sine.abs() < 1e-9 && d.x * along.x + d.y * along.y > 0.0,
        "ω along sin γ j + cos γ k: {d:?} against {along:?}"
    );
    let labels: Vec<&str> = drawn.labels.iter().map(|l| l.markup.as_str()).collect();
    assert!(labels.contains(&r"$\gamma$"), "γ labelled: {labels:?}");
    let theta = Sizes::of(&scene)
        .of_expr(&Expr::sym(Symbol::new("theta")))
        .unwrap();
    assert!(
        (theta - gamma).abs() > 5f64.to_radians(),
        "θ drawn at {theta}"
    );
}

/// `up y` turns the figure so that y is drawn straight up (the plate that falls along −y
/// lies flat, as its problem has it), where the scene has no weight to say so.
#[test]
fn a_scene_saying_up_y_is_drawn_with_y_up() {
    let scene = example("plate_falls_on_corner");
    assert_eq!(scene.up, Some(kinetics::Axis::Y));
    let drawn = figure(&scene).unwrap();
    let y = drawn.at([0.0, 1.0, 0.0]).minus(drawn.at([0.0; 3]));
    assert!(y.x.abs() < 1e-9 && y.y > 0.0, "y drawn {y:?}");
    let without = kinetics::parse_scene("plate", &scene.source.replace("up y\n", "")).unwrap();
    let z = figure(&without).unwrap();
    let z_up = z.at([0.0, 0.0, 1.0]).minus(z.at([0.0; 3]));
    assert!(
        z_up.x.abs() < 1e-9 && z_up.y > 0.0,
        "without it z is up: {z_up:?}"
    );
}

/// A fixed point that no shaft or floor holds stands on a pivot: the top's O on a pedestal, a
/// triangle with its apex at O and its base on the side the weight points to (under O); a
/// shaft's bearings hold SP 18.4 and the floor holds the cone's apex, so neither has one; nor
/// does SP 18.5, whose ω₂ is drawn down from O where the pedestal would stand, nor the
/// horizontal wheel gyroscope, whose disk comes up against O (a pedestal there read as part
/// of the wheel).
#[test]
fn a_fixed_point_nothing_else_holds_stands_on_a_pivot() {
    let pedestals = |drawn: &Figure| -> Vec<Vec<P2>> {
        let o = drawn.at([0.0; 3]);
        closed_paths(drawn, 3)
            .into_iter()
            .map(|(_, points)| points)
            .filter(|points| points.iter().any(|p| p.minus(o).length() < 1e-6))
            .collect()
    };
    let top = figure(&example("top_steady_tilt")).unwrap();
    let o = top.at([0.0; 3]);
    let down = top
        .marks
        .iter()
        .find_map(|m| match m {
            Mark::Arrow {
                role: Role::Force(name),
                from,
                to,
                ..
            } if name == "W" => Some(to.minus(*from)),
            _ => None,
        })
        .expect("the weight drawn");
    let found = pedestals(&top);
    assert_eq!(found.len(), 1, "one pedestal at O");
    let below = found[0]
        .iter()
        .filter(|p| {
            let d = p.minus(o);
            d.x * down.x + d.y * down.y > 0.5 * d.length() * down.length()
        })
        .count();
    assert_eq!(below, 2, "its base under O: {:?}", found[0]);
    for name in [
        "sp18_4_shaft_reactions",
        "cone_rolling_about_apex",
        "sp18_5_disk_reactions",
        "wheel_gyroscope_horizontal",
    ] {
        assert!(
            pedestals(&figure(&example(name)).unwrap()).is_empty(),
            "{name}"
        );
    }
}

/// The wires a scene hangs its body from are drawn: SP 18.1's plate from its two top corners
/// up to their anchors, each a line in the wire's stroke from the corner's place on the page
/// to the anchor's, with a hatched base across it at the anchor (a line of the ground's
/// stroke through the anchor). So are the posts it stands round: the post the spinning rod
/// strikes, a bar from its base at A (hatched) up to its top. A wire or a post from a point
/// to itself, or half written, is refused at its line.
#[test]
fn the_wires_and_posts_round_a_body_are_drawn() {
    let scene = example("sp18_1_plate_impact");
    assert_eq!(scene.supports.len(), 2);
    let drawn = figure(&scene).unwrap();
    for wire in &scene.supports {
        let (from, to) = (
            drawn_at(&drawn, &scene, &wire.from),
            drawn_at(&drawn, &scene, &wire.to),
        );
        let line = two_point_paths(&drawn, Stroke::WIRE)
            .into_iter()
            .any(|(a, b)| near(a, from) && near(b, to));
        assert!(line, "the wire from {from:?} to {to:?}");
        let base = two_point_paths(&drawn, Stroke::GROUND)
            .into_iter()
            .any(|(a, b)| {
                let middle = a.plus(b).times(0.5);
                near(middle, to)
            });
        assert!(base, "a base across the anchor {to:?}");
    }
    let scene = example("spinning_rod_strikes_a_post");
    let drawn = figure(&scene).unwrap();
    let post = &scene.supports[0];
    let (base, top) = (
        drawn_at(&drawn, &scene, &post.from),
        drawn_at(&drawn, &scene, &post.to),
    );
    let bar = two_point_paths(&drawn, Stroke::SHAFT);
    assert!(
        bar.iter().any(|(a, _)| near(*a, base)) && bar.iter().any(|(_, b)| near(*b, top)),
        "the post from {base:?} to {top:?}"
    );
    let hatched = two_point_paths(&drawn, Stroke::GROUND)
        .into_iter()
        .any(|(a, b)| near(a.plus(b).times(0.5), base));
    assert!(hatched, "its base hatched");
    let refused = |wire: &str| {
        let source = format!("given a = 1 m\nbody plate(a, a) mass 1 kg\n{wire}\nfind T\n");
        kinetics::parse_scene("w.scene", &source)
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default()
    };
    let itself = refused("wire from (a, 0, 0) to (a, 0, 0)");
    assert!(
        itself.contains("a wire from a point to itself") && itself.contains("w.scene:3:1"),
        "{itself}"
    );
    let post = refused("post from (a, 0, 0) to (a, 0, 0)");
    assert!(
        post.contains("a post from a point to itself") && post.contains("w.scene:3:1"),
        "{post}"
    );
    let half = refused("wire from (a, 0, 0)");
    assert!(
        half.contains("expected 'to'") && half.contains("w.scene:3:20"),
        "{half}"
    );
}
