//! `find I_G`, `I_O`, `principal_G`, `principal_O` (issue 18), checked against independent
//! computations: each body cut into point masses (two Gauss points an edge per cell, exact
//! for the quadratic integrands of inertia), `[I] = Σ m (|r|² 1 − r rᵀ)`, `H = Σ m r × (ω × r)`,
//! `T = ½ Σ m |ω × r|²`, and the principal moments and axes derived by hand in each test.
//! The axes are checked as eigenvectors of the point masses' tensor (`[I]e = λe`), unit,
//! orthogonal and right-handed.

use kinetics::algebra::{Expr, Symbol};
use kinetics::mechanics::principal_frame::PrincipalFrame;
use kinetics::scene::{Analysis, Scene, Value};

use crate::common::examples::{analysed_example as load, result};

type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];

/// Two-point Gauss abscissae on [0, 1], each with weight ½.
const GAUSS: [f64; 2] = [0.5 - 0.288_675_134_594_812_9, 0.5 + 0.288_675_134_594_812_9];

fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// A box of mass `m`, centred at `centre`, edges `a, b, c` along x, y, z (`c = 0`: a plate),
/// as point masses: 3 cells an edge, 2 Gauss points a cell and edge.
fn box_points(m: f64, centre: V3, edges: V3) -> Vec<(f64, V3)> {
    let n = 3;
    let layers = |edge: f64| -> Vec<f64> {
        if edge == 0.0 {
            return vec![0.0];
        }
        (0..n)
            .flat_map(|k| GAUSS.map(|g| ((k as f64 + g) / n as f64 - 0.5) * edge))
            .collect()
    };
    let (xs, ys, zs) = (layers(edges[0]), layers(edges[1]), layers(edges[2]));
    let count = (xs.len() * ys.len() * zs.len()) as f64;
    let mut points = Vec::new();
    for x in &xs {
        for y in &ys {
            for z in &zs {
                points.push((m / count, [centre[0] + x, centre[1] + y, centre[2] + z]));
            }
        }
    }
    points
}

/// `[I] = Σ m (|r|² 1 − r rᵀ)` about the origin of `r`: the chapter's matrix, whose
/// off-diagonal entries are `−Σ m x y = −I_xy`.
fn tensor(points: &[(f64, V3)]) -> M3 {
    let mut t = [[0.0; 3]; 3];
    for &(m, r) in points {
        for (i, row) in t.iter_mut().enumerate() {
            for (j, entry) in row.iter_mut().enumerate() {
                let identity = if i == j { dot(r, r) } else { 0.0 };
                *entry += m * (identity - r[i] * r[j]);
            }
        }
    }
    t
}

fn times(t: &M3, v: V3) -> V3 {
    [dot(t[0], v), dot(t[1], v), dot(t[2], v)]
}

fn angular_momentum(points: &[(f64, V3)], omega: V3) -> V3 {
    points.iter().fold([0.0; 3], |h, &(m, r)| {
        let c = cross(r, cross(omega, r));
        [h[0] + m * c[0], h[1] + m * c[1], h[2] + m * c[2]]
    })
}

fn kinetic_energy(points: &[(f64, V3)], omega: V3) -> f64 {
    points
        .iter()
        .map(|&(m, r)| 0.5 * m * dot(cross(omega, r), cross(omega, r)))
        .sum()
}

fn values(scene: &Scene) -> impl Fn(Symbol) -> Option<f64> + '_ {
    |s| scene.value(s)
}

fn eval(e: &Expr, scene: &Scene) -> f64 {
    e.eval(&values(scene)).expect("every given has a value")
}

fn vector(a: &Analysis, scene: &Scene, name: &str) -> V3 {
    match result(a, name) {
        Value::Vector(v) => [0, 1, 2].map(|k| eval(&v[k], scene)),
        _ => panic!("{name} is a vector"),
    }
}

fn matrix(a: &Analysis, scene: &Scene, name: &str) -> M3 {
    match result(a, name) {
        Value::Tensor(m) => [0, 1, 2].map(|r| [0, 1, 2].map(|c| eval(&m[(r, c)], scene))),
        _ => panic!("{name} is a tensor"),
    }
}

fn frame<'a>(a: &'a Analysis, name: &str) -> &'a PrincipalFrame {
    match result(a, name) {
        Value::Principal(p) => p,
        _ => panic!("{name} is a principal frame"),
    }
}

fn close(what: &str, derived: f64, independent: f64, scale: f64) {
    assert!(
        (derived - independent).abs() <= 1e-9 * scale,
        "{what}: derived {derived}, independent {independent}"
    );
}

fn close_matrix(what: &str, derived: &M3, independent: &M3) {
    let scale = independent
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    for r in 0..3 {
        for c in 0..3 {
            close(
                &format!("{what}[{r}][{c}]"),
                derived[r][c],
                independent[r][c],
                scale,
            );
        }
    }
}

/// The frame's moments are `moments` (by hand), ascending, and its axes eigenvectors of the
/// point masses' tensor, unit, orthogonal, right-handed.
fn check_frame(frame: &PrincipalFrame, scene: &Scene, t: &M3, moments: V3) {
    let found = frame.moments.clone().map(|m| eval(&m, scene));
    let axes = frame
        .axes
        .clone()
        .map(|e| [0, 1, 2].map(|k| eval(&e[k], scene)));
    let scale = moments[2];
    for k in 0..3 {
        close(&format!("I_{}", k + 1), found[k], moments[k], scale);
        close(&format!("|e_{}|", k + 1), norm(axes[k]), 1.0, 1.0);
        let residual = times(t, axes[k]);
        let off = [0, 1, 2].map(|i| residual[i] - found[k] * axes[k][i]);
        assert!(
            norm(off) <= 1e-9 * scale,
            "[I]e_{} − I_{} e_{} = {off:?}",
            k + 1,
            k + 1,
            k + 1
        );
    }
    assert!(
        found[0] <= found[1] && found[1] <= found[2],
        "ascending: {found:?}"
    );
    close("e_1 · e_2", dot(axes[0], axes[1]), 0.0, 1.0);
    close(
        "e_1 × e_2 · e_3",
        dot(cross(axes[0], axes[1]), axes[2]),
        1.0,
        1.0,
    );
}

#[test]
fn plate_spinning_about_its_diagonal() {
    let (scene, analysis) = load("plate_spinning_about_diagonal", "");
    let (m, a, b, w): (f64, f64, f64, f64) = (2.0, 0.4, 0.3, 10.0);
    let d = (a * a + b * b).sqrt();
    let omega = [w * a / d, w * b / d, 0.0];
    let points = box_points(m, [0.0; 3], [a, b, 0.0]);
    let t = tensor(&points);
    close_matrix("I_G", &matrix(&analysis, &scene, "I_G"), &t);

    // By hand: the plate's own axes are principal, I = (b², a², a² + b²) m/12, sorted (a > b).
    let by_hand = [
        m * b * b / 12.0,
        m * a * a / 12.0,
        m * (a * a + b * b) / 12.0,
    ];
    let principal = frame(&analysis, "principal_G");
    check_frame(principal, &scene, &t, by_hand);
    assert!(principal.remark.is_none());

    let h = angular_momentum(&points, omega);
    let h_hand = [
        m * a * b * w / (12.0 * d) * b,
        m * a * b * w / (12.0 * d) * a,
        0.0,
    ];
    let h_g = vector(&analysis, &scene, "H_G");
    for k in 0..3 {
        close("H_G (point masses)", h_g[k], h[k], norm(h));
        close("H_G (by hand)", h_g[k], h_hand[k], norm(h));
    }
    let t_hand = m * a * a * b * b * w * w / (12.0 * d * d);
    let Value::Scalar(energy) = result(&analysis, "T") else {
        panic!("T is a scalar")
    };
    close(
        "T (point masses)",
        eval(energy, &scene),
        kinetic_energy(&points, omega),
        t_hand,
    );
    close("T (by hand)", eval(energy, &scene), t_hand, t_hand);

    // The bearings' couple: Ḣ_G = ω × H_G = m a b (a² − b²) w²/(12 d²) k, constant ω.
    let hdot = vector(&analysis, &scene, "Hdot_G");
    let hdot_hand = m * a * b * (a * a - b * b) * w * w / (12.0 * d * d);
    let hdot_points = cross(omega, h);
    for k in 0..3 {
        close("Hdot_G", hdot[k], hdot_points[k], hdot_hand);
    }
    close("Hdot_G (by hand)", hdot[2], hdot_hand, hdot_hand);
}

#[test]
fn box_spinning_about_its_body_diagonal() {
    let (scene, analysis) = load("box_about_body_diagonal", "");
    let (m, a, b, c, w): (f64, f64, f64, f64, f64) = (6.0, 0.3, 0.2, 0.1, 10.0);
    let d = (a * a + b * b + c * c).sqrt();
    let omega = [w * a / d, w * b / d, w * c / d];
    let about_o = box_points(m, [a / 2.0, b / 2.0, c / 2.0], [a, b, c]);
    let about_g = box_points(m, [0.0; 3], [a, b, c]);
    let (t_o, t_g) = (tensor(&about_o), tensor(&about_g));
    close_matrix("I_O", &matrix(&analysis, &scene, "I_O"), &t_o);
    close_matrix("I_G", &matrix(&analysis, &scene, "I_G"), &t_g);
    // By hand, the entries of [I_O]: I_x = m(b² + c²)/3, I_xy = m a b/4 entered as −I_xy.
    close("I_O x", t_o[0][0], m * (b * b + c * c) / 3.0, t_o[0][0]);
    close("I_O xy", t_o[0][1], -m * a * b / 4.0, t_o[0][0]);

    // Principal about O: three products, found numerically; the moments are the roots of
    // det(λ1 − [I_O]) = λ³ − tr λ² + (sum of principal minors) λ − det: checked as roots.
    let principal_o = frame(&analysis, "principal_O");
    let moments: V3 = principal_o.moments.clone().map(|x| eval(&x, &scene));
    let tr = t_o[0][0] + t_o[1][1] + t_o[2][2];
    let minors = t_o[0][0] * t_o[1][1] - t_o[0][1] * t_o[1][0] + t_o[1][1] * t_o[2][2]
        - t_o[1][2] * t_o[2][1]
        + t_o[0][0] * t_o[2][2]
        - t_o[0][2] * t_o[2][0];
    let det = dot(t_o[0], cross(t_o[1], t_o[2]));
    for l in moments {
        let p = l * l * l - tr * l * l + minors * l - det;
        assert!(
            p.abs() < 1e-12 * tr * tr * tr,
            "det(λ1 − [I_O]) at λ = {l}: {p:e}"
        );
    }
    check_frame(principal_o, &scene, &t_o, moments);
    close("Σ I_k = tr [I_O]", moments.iter().sum(), tr, tr);

    // About G the box's edges are principal: (b² + c², c² + a², a² + b²) m/12, ascending here.
    let by_hand = [b * b + c * c, c * c + a * a, a * a + b * b].map(|s| m * s / 12.0);
    check_frame(frame(&analysis, "principal_G"), &scene, &t_g, by_hand);

    // H_G is not along ω: 21.64° between them (the comment's number), by hand and by points.
    let h_g = vector(&analysis, &scene, "H_G");
    let h_hand = [
        a * (b * b + c * c),
        b * (c * c + a * a),
        c * (a * a + b * b),
    ]
    .map(|x| m * w / (12.0 * d) * x);
    let h_points = angular_momentum(&about_g, omega);
    for k in 0..3 {
        close("H_G (by hand)", h_g[k], h_hand[k], norm(h_hand));
        close("H_G (point masses)", h_g[k], h_points[k], norm(h_hand));
    }
    let angle = (dot(h_g, omega) / (norm(h_g) * norm(omega)))
        .acos()
        .to_degrees();
    assert!(
        (angle - 21.64).abs() < 0.005,
        "angle between H_G and ω: {angle}°"
    );

    // G is on the axis (v̄ = 0): T = ½ ω·H_G = m w² (a²b² + b²c² + c²a²)/(12 d²).
    let t_hand = m * w * w * (a * a * b * b + b * b * c * c + c * c * a * a) / (12.0 * d * d);
    let Value::Scalar(energy) = result(&analysis, "T") else {
        panic!("T is a scalar")
    };
    close("T (by hand)", eval(energy, &scene), t_hand, t_hand);
    close(
        "T (point masses about O)",
        eval(energy, &scene),
        kinetic_energy(&about_o, omega),
        t_hand,
    );
}

fn analysed(text: &str) -> Result<(Scene, Analysis), String> {
    let scene = kinetics::parse_scene("test.scene", text).map_err(|d| d.render())?;
    let analysis = kinetics::analyse(&scene).map_err(|d| d.render())?;
    Ok((scene, analysis))
}

#[test]
fn several_products_without_values_are_refused_at_the_find_naming_the_givens() {
    let text = "given m : kg\ngiven a : m\ngiven b : m\ngiven c : m\n\
                body prism(a, b, c) mass m at (a/2, b/2, c/2)\nfind principal_O\n";
    let error = analysed(text).expect_err("no values: refused");
    assert!(
        error.contains("principal_O needs values for a, b, c, m"),
        "{error}"
    );
    assert!(error.contains("6:6"), "at the find: {error}");
}

#[test]
fn equal_moments_are_said_so() {
    // A cube about G: every axis is principal; a square plate: the two in its plane.
    let cube = "given m : kg\ngiven a : m\nbody prism(a, a, a) mass m\nfind principal_G\n";
    let (_, analysis) = analysed(cube).expect("a cube needs no values: its moments are equal");
    let remark = frame(&analysis, "principal_G").remark.clone();
    assert!(remark.is_some_and(|r| r.contains("I_1 = I_2 = I_3")));

    let square = "given m = 1 kg\ngiven a = 0.2 m\nbody plate(a, a) mass m\nfind principal_G\n";
    let (_, analysis) = analysed(square).expect("a square plate solves");
    let principal = frame(&analysis, "principal_G");
    assert!(principal
        .remark
        .as_deref()
        .is_some_and(|r| r.contains("$I_1 = I_2$")));
    assert_eq!(
        principal.moments[2],
        kinetics::parse_expression("", "m a^2/6").unwrap()
    );
}

#[test]
fn one_product_is_answered_exactly() {
    // A rod of length L turned 30° about z: I_x = mL²/48, I_y = mL²/16, I_xy = √3 mL²/48;
    // (I_x + I_y)/2 ∓ √(((I_x − I_y)/2)² + I_xy²) = mL²/24 ∓ mL²/24, so the moments are 0
    // (along the rod, (cos 30°, sin 30°, 0)) and mL²/12 twice.
    let rod = "given m = 2 kg\ngiven L = 1.2 m\nbody rod(L) mass m rotated 30 deg about z\nfind principal_G\n";
    let (scene, analysis) = analysed(rod).expect("the rod solves");
    let principal = frame(&analysis, "principal_G");
    assert!(principal.moments[0].is_zero(), "{:?}", principal.moments);
    let axis = [0, 1, 2].map(|k| eval(&principal.axes[0][k], &scene));
    let along = [3f64.sqrt() / 2.0, 0.5, 0.0];
    assert!((dot(axis, along).abs() - 1.0).abs() < 1e-12, "{axis:?}");
    assert!(principal
        .remark
        .as_deref()
        .is_some_and(|r| r.contains("$I_2 = I_3$")));
    let text = kinetics::render(&scene, &analysis, kinetics::Format::Text, false);
    assert!(!text.contains("found numerically"), "{text}");

    // Without values: the order is proved and e_3 = e_1 × e_2 = (sin 30°, −cos 30°, 0).
    let symbolic = rod.replace("= 2 kg", ": kg").replace("= 1.2 m", ": m");
    let (_, analysis) = analysed(&symbolic).expect("the order is proved without values");
    let e3 = &frame(&analysis, "principal_G").axes[2];
    let hand = ["1/2", "-sqrt(3)/2", "0"].map(|t| kinetics::parse_expression("", t).unwrap());
    assert_eq!([e3[0].clone(), e3[1].clone(), e3[2].clone()], hand);
}

/// The characteristic equation a page shows with three products (by cofactors, in the names
/// `I_x`, `I_xy`, …) is det(λ1 − [I_O]) = 0: with the point masses' tensor put in for the
/// names, its two sides differ by λ³ − tr λ² + (principal minors) λ − det at any λ.
#[test]
fn the_characteristic_equation_shown_is_the_determinant() {
    let (_, analysis) = load("box_about_body_diagonal", "");
    let t_o = tensor(&box_points(6.0, [0.15, 0.1, 0.05], [0.3, 0.2, 0.1]));
    let step = analysis
        .plan
        .iter()
        .find(|s| s.title.contains("characteristic equation"))
        .expect("a step gives the characteristic equation");
    let relation = &step.relations[0];
    let names = [
        ("I_x", t_o[0][0]),
        ("I_y", t_o[1][1]),
        ("I_z", t_o[2][2]),
        ("I_xy", -t_o[0][1]),
        ("I_yz", -t_o[1][2]),
        ("I_xz", -t_o[0][2]),
    ];
    let tr = t_o[0][0] + t_o[1][1] + t_o[2][2];
    let minors = t_o[0][0] * t_o[1][1] - t_o[0][1] * t_o[1][0] + t_o[1][1] * t_o[2][2]
        - t_o[1][2] * t_o[2][1]
        + t_o[0][0] * t_o[2][2]
        - t_o[0][2] * t_o[2][0];
    let det = dot(t_o[0], cross(t_o[1], t_o[2]));
    for lambda in [0.0, 0.05, 0.17, 0.3] {
        let at = |s: Symbol| match s.name() {
            "lambda" => Some(lambda),
            name => names.iter().find(|(n, _)| *n == name).map(|(_, v)| *v),
        };
        let shown =
            relation.lhs.eval(&at).expect("a number") - relation.rhs.eval(&at).expect("a number");
        let by_hand = lambda.powi(3) - tr * lambda.powi(2) + minors * lambda - det;
        close("det(λ1 − [I_O])", shown, by_hand, tr.powi(3));
    }
}
