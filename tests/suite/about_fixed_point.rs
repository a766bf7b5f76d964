//! The textbook's route about a fixed point O (§18.7–18.8): `[I_O]` from the parts,
//! `H_O = [I_O]{ω}`, `T = ½{ω}ᵀ[I_O]{ω}`, `ΣM_O = Ḣ_O`, and the centroidal route kept by
//! `about G`. The answers of the two new examples are checked against an independent
//! computation: each part cut into many point masses (two Gauss points a segment or cell,
//! exact for the quadratic integrands), `H_O = Σ m r × (ω × r)`, `T = ½ Σ m |ω × r|²`,
//! `Σ m a` and `Σ r × m a` with `a = α × r + ω × (ω × r)`, and the bearing reactions solved
//! from them by hand.

use kinetics::algebra::{Expr, Symbol};
use kinetics::mechanics::angular_momentum::{angular_momentum, angular_momentum_about_point};
use kinetics::mechanics::InertiaTensor;
use kinetics::scene::{analyse, parse_scene, Analysis, Value};

use crate::common::examples::{analysed_example as load, result};

type V3 = [f64; 3];

fn eval(e: &Expr, values: &dyn Fn(Symbol) -> Option<f64>) -> f64 {
    e.eval(values).expect("every symbol has a value")
}

fn scalar(a: &Analysis, name: &str, values: &dyn Fn(Symbol) -> Option<f64>) -> f64 {
    match result(a, name) {
        Value::Scalar(e) => eval(e, values),
        _ => panic!("{name} is not a scalar"),
    }
}

fn vector(a: &Analysis, name: &str, values: &dyn Fn(Symbol) -> Option<f64>) -> V3 {
    match result(a, name) {
        Value::Vector(v) => [0, 1, 2].map(|k| eval(&v[k], values)),
        _ => panic!("{name} is not a vector"),
    }
}

/// `|derived − independent| ≤ 1e-9 · scale`, the scale being the size of the quantity.
fn close(what: &str, derived: f64, independent: f64, scale: f64) {
    assert!(
        (derived - independent).abs() <= 1e-9 * scale,
        "{what}: derived {derived}, point masses {independent}"
    );
}

fn close_vector(what: &str, derived: V3, independent: V3) {
    let scale = independent.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for k in 0..3 {
        close(&format!("{what}[{k}]"), derived[k], independent[k], scale);
    }
}

fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(s: f64, a: V3) -> V3 {
    a.map(|x| s * x)
}

/// A body as point masses `(m, r)`, r from O.
struct PointMasses(Vec<(f64, V3)>);

/// Two-point Gauss abscissae on [0, 1], each with weight ½.
const GAUSS: [f64; 2] = [0.5 - 0.288_675_134_594_812_9, 0.5 + 0.288_675_134_594_812_9];

impl PointMasses {
    /// The analysis's `H_O` and `T` equal these point masses' `Σ r × m (ω × r)` and
    /// `Σ ½ m |ω × r|²`.
    fn agrees_on_h_o_and_t(&self, a: &Analysis, values: &dyn Fn(Symbol) -> Option<f64>, omega: V3) {
        close_vector(
            "H_O",
            vector(a, "H_O", values),
            self.angular_momentum(omega),
        );
        let t = self.kinetic_energy(omega);
        close("T", scalar(a, "T", values), t, t);
    }

    /// A slender rod of mass `m` from `from` to `to`, cut into `n` segments.
    fn rod(&mut self, m: f64, from: V3, to: V3, n: usize) {
        let edge = add(to, scale(-1.0, from));
        for k in 0..n {
            for g in GAUSS {
                let t = (k as f64 + g) / n as f64;
                self.0.push((m / (2 * n) as f64, add(from, scale(t, edge))));
            }
        }
    }

    /// A thin plate of mass `m` with a corner at `corner` and edges `u`, `v`, cut into n × n
    /// cells.
    fn plate(&mut self, m: f64, corner: V3, u: V3, v: V3, n: usize) {
        for i in 0..n {
            for j in 0..n {
                for gu in GAUSS {
                    for gv in GAUSS {
                        let (s, t) = ((i as f64 + gu) / n as f64, (j as f64 + gv) / n as f64);
                        let r = add(corner, add(scale(s, u), scale(t, v)));
                        self.0.push((m / (4 * n * n) as f64, r));
                    }
                }
            }
        }
    }

    /// `H_O = Σ m r × (ω × r)`.
    fn angular_momentum(&self, omega: V3) -> V3 {
        self.0.iter().fold([0.0; 3], |h, &(m, r)| {
            add(h, scale(m, cross(r, cross(omega, r))))
        })
    }

    /// `T = ½ Σ m |ω × r|²`.
    fn kinetic_energy(&self, omega: V3) -> f64 {
        self.0
            .iter()
            .map(|&(m, r)| {
                let v = cross(omega, r);
                0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
            })
            .sum()
    }

    /// `(Σ m a, Σ r × m a)` with `a = α × r + ω × (ω × r)`.
    fn effective_force_and_moment(&self, omega: V3, alpha: V3) -> (V3, V3) {
        self.0
            .iter()
            .fold(([0.0; 3], [0.0; 3]), |(f, moment), &(m, r)| {
                let a = add(cross(alpha, r), cross(omega, cross(omega, r)));
                (add(f, scale(m, a)), add(moment, scale(m, cross(r, a))))
            })
    }
}

#[test]
fn bent_rod_on_a_vertical_shaft_agrees_with_point_masses() {
    let (scene, a) = load("bent_rod_vertical_shaft", "");
    let values = |s: Symbol| scene.value(s);
    let given = |name: &str| scene.value(Symbol::new(name)).expect("given");
    let (m_1, m_2, arm_a, arm_b) = (given("m_1"), given("m_2"), given("a"), given("b"));
    let (l, w, alpha, g) = (given("l"), given("w"), given("alpha"), given("g"));
    let mut body = PointMasses(Vec::new());
    body.rod(m_1, [0.0; 3], [arm_a, 0.0, 0.0], 500);
    body.rod(m_2, [arm_a, 0.0, 0.0], [arm_a, arm_b, 0.0], 500);
    let (omega, rate) = ([0.0, w, 0.0], [0.0, alpha, 0.0]);
    body.agrees_on_h_o_and_t(&a, &values, omega);
    // ΣF = Σ m a and ΣM_O = Σ r × m a with C at (0, -l, 0), D at (0, l, 0), the weights at
    // the arms' centres and the couple M j (worked by hand in the scene's comment):
    // x: C_x + D_x = F_x, z: l(C_x − D_x) − g a(m_1/2 + m_2) = M_z;
    // z: C_z + D_z = F_z, x: l(D_z − C_z) = M_x; y: C_y − (m_1 + m_2) g = F_y, M = M_y.
    let (f, m) = body.effective_force_and_moment(omega, rate);
    let c_x = 0.5 * (f[0] + (m[2] + g * arm_a * (m_1 / 2.0 + m_2)) / l);
    let d_z = 0.5 * (f[2] + m[0] / l);
    let expected = [
        ("M", m[1]),
        ("C_x", c_x),
        ("D_x", f[0] - c_x),
        ("C_y", f[1] + (m_1 + m_2) * g),
        ("C_z", f[2] - d_z),
        ("D_z", d_z),
    ];
    let size = expected.iter().fold(0.0f64, |s, (_, x)| s.max(x.abs()));
    for (name, independent) in expected {
        close(name, scalar(&a, name, &values), independent, size);
    }
}

#[test]
fn three_part_composite_agrees_with_point_masses() {
    let (_, a) = load("three_part_composite", "");
    let numbers = [
        ("m_1", 1.3),
        ("m_2", 2.1),
        ("m_3", 0.7),
        ("a", 0.9),
        ("b", 0.4),
        ("c", 0.6),
        ("w_x", 1.7),
        ("w_y", -2.3),
        ("w_z", 0.8),
    ];
    let values = |s: Symbol| numbers.iter().find(|(n, _)| *n == s.name()).map(|p| p.1);
    let given = |name: &str| values(Symbol::new(name)).expect("a value");
    let (arm, b, c) = (given("a"), given("b"), given("c"));
    let mut body = PointMasses(Vec::new());
    body.rod(given("m_1"), [0.0; 3], [arm, 0.0, 0.0], 500);
    body.plate(
        given("m_2"),
        [arm, 0.0, 0.0],
        [0.0, b, 0.0],
        [0.0, 0.0, c],
        100,
    );
    body.0.push((given("m_3"), [arm, b, c]));
    let omega = [given("w_x"), given("w_y"), given("w_z")];
    body.agrees_on_h_o_and_t(&a, &values, omega);
}

/// The step that shows the parts: its table's columns, added over the rows, are the sums the
/// step's relations give (checked at numbers, the cells and the sums being shown apart).
fn table_sums_are_the_relations(a: &Analysis, rows: usize, values: &dyn Fn(Symbol) -> Option<f64>) {
    let step = a
        .plan
        .iter()
        .find(|s| s.table.is_some())
        .expect("a step with the parts' table");
    let table = step.table.as_ref().expect("found by its table");
    assert_eq!(table.rows.len(), rows);
    let names: Vec<String> = table.columns.iter().map(|c| c.to_string()).collect();
    assert_eq!(
        names,
        ["m", "xbar", "ybar", "zbar", "I_x", "I_y", "I_z", "I_xy", "I_yz", "I_xz"]
    );
    let labels: Vec<&str> = table.rows.iter().map(|r| r.label.as_str()).collect();
    assert_eq!(
        labels,
        (1..=rows).map(|k| k.to_string()).collect::<Vec<_>>()
    );
    for (k, column) in table.columns.iter().enumerate().skip(4) {
        let sum: f64 = table.rows.iter().map(|r| eval(&r.cells[k], values)).sum();
        let relation = step
            .relations
            .iter()
            .find(|r| &r.lhs == column)
            .unwrap_or_else(|| panic!("a relation for {column}"));
        let total = eval(&relation.rhs, values);
        close(&column.to_string(), sum, total, total.abs().max(1.0));
    }
}

#[test]
fn a_composite_body_about_o_lays_out_its_parts() {
    let (_, a) = load("three_part_composite", "");
    let values = |s: Symbol| Some(1.0 + (s.name().len() % 5) as f64 / 7.0);
    table_sums_are_the_relations(&a, 3, &values);
    assert!(a.plan.iter().any(|s| s.title.contains("about $O$")));
}

/// No fixed point: the centroidal route. The table holds each part's mass, position and own
/// centroidal moments and products (Ī_x', …); the step's relations are their sums by the
/// parallel-axis theorem, checked here by hand: `I_x = Σ(Ī_x' + mᵢ((yᵢ − ȳ)² + (zᵢ − z̄)²))`,
/// `I_xy = Σ(Ī_x'y' + mᵢ(xᵢ − x̄)(yᵢ − ȳ))`, with `r̄ = Σ mᵢ r̄ᵢ / Σ mᵢ` from the table too.
#[test]
fn a_composite_body_about_g_lays_out_its_parts() {
    let (_, a) = load("compound_body_bent_rod", "");
    let values = |s: Symbol| Some(1.0 + (s.name().len() % 5) as f64 / 7.0);
    let step = a
        .plan
        .iter()
        .find(|s| s.table.is_some())
        .expect("a step with the parts' table");
    let table = step.table.as_ref().expect("found by its table");
    let names: Vec<String> = table.columns.iter().map(|c| c.to_string()).collect();
    assert_eq!(
        names,
        [
            "m",
            "xbar",
            "ybar",
            "zbar",
            "Ibar_x'",
            "Ibar_y'",
            "Ibar_z'",
            "Ibar_x'y'",
            "Ibar_y'z'",
            "Ibar_x'z'"
        ]
    );
    let cell = |row: usize, k: usize| eval(&table.rows[row].cells[k], &values);
    let parts = table.rows.len();
    assert_eq!(parts, 2);
    let mass: f64 = (0..parts).map(|i| cell(i, 0)).sum();
    let centre: Vec<f64> = (1..4)
        .map(|k| (0..parts).map(|i| cell(i, 0) * cell(i, k)).sum::<f64>() / mass)
        .collect();
    let offset = |i: usize, axis: usize| cell(i, 1 + axis) - centre[axis];
    let moment = |axis: usize| -> f64 {
        let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
        (0..parts)
            .map(|i| cell(i, 4 + axis) + cell(i, 0) * (offset(i, b).powi(2) + offset(i, c).powi(2)))
            .sum()
    };
    // Products in the chapter's order xy, yz, xz.
    let product = |k: usize, (p, q): (usize, usize)| -> f64 {
        (0..parts)
            .map(|i| cell(i, 7 + k) + cell(i, 0) * offset(i, p) * offset(i, q))
            .sum()
    };
    let by_hand = [
        ("I_x", moment(0)),
        ("I_y", moment(1)),
        ("I_z", moment(2)),
        ("I_xy", product(0, (0, 1))),
        ("I_yz", product(1, (1, 2))),
        ("I_xz", product(2, (0, 2))),
    ];
    for (name, expected) in by_hand {
        let relation = step
            .relations
            .iter()
            .find(|r| r.lhs == Expr::symbol(name))
            .unwrap_or_else(|| panic!("a relation for {name}"));
        let total = eval(&relation.rhs, &values);
        close(name, expected, total, total.abs().max(1.0));
    }
}

/// With a fixed point, `find H_O` is `[I_O]{ω}`: the plan holds the step of
/// `angular_momentum` about O and no `H_G + r̄ × m v̄`; `about G` brings that route back with
/// the same answer.
#[test]
fn h_o_about_a_fixed_point_is_i_o_omega_unless_about_g() {
    let zero = kinetics::Vector::zeros();
    let about_o_title = &angular_momentum(&InertiaTensor::general(), &zero, "O")
        .expect("derives")
        .steps[0]
        .title;
    let m = Expr::symbol("m");
    let through_g = angular_momentum_about_point(&zero, &zero, &m, &zero).expect("derives");
    let through_g_title = &through_g.steps.last().expect("a step").title;
    let (scene, about_o) = load("general_body", "");
    let titles = |a: &Analysis| -> Vec<String> { a.plan.iter().map(|s| s.title.clone()).collect() };
    assert!(
        titles(&about_o).contains(about_o_title),
        "{:?}",
        titles(&about_o)
    );
    assert!(!titles(&about_o).contains(through_g_title));
    let (_, about_g) = load("general_body", "about G\n");
    assert!(!titles(&about_g).contains(about_o_title));
    assert!(titles(&about_g).contains(through_g_title));
    let values = |s: Symbol| scene.value(s);
    for name in ["H_O", "H_G"] {
        close_vector(
            name,
            vector(&about_o, name, &values),
            vector(&about_g, name, &values),
        );
    }
    close(
        "T",
        scalar(&about_o, "T", &values),
        scalar(&about_g, "T", &values),
        1.0,
    );
}

/// The reactions of Sample Problem 18.4 are the same by both routes; about O the moments
/// equal `Ḣ_O`, about G `Ḣ_G + r̄ × m ā`.
#[test]
fn reactions_are_the_same_about_o_and_about_g() {
    let (scene, about_o) = load("sp18_4_shaft_reactions", "");
    let (_, about_g) = load("sp18_4_shaft_reactions", "about G\n");
    let equations = |a: &Analysis| -> String {
        a.plan
            .iter()
            .find(|s| s.title.starts_with("equations of motion"))
            .expect("the equations of motion")
            .title
            .clone()
    };
    assert!(equations(&about_o).contains(r"\Sigma\mathbf{M}_O = \dot{\mathbf{H}}_O"));
    assert!(equations(&about_g).contains(r"\dot{\mathbf{H}}_G + \bar{\mathbf{r}}"));
    let values = |s: Symbol| scene.value(s).or_else(|| (s.name() == "L").then_some(0.8));
    for name in ["alpha", "C_y", "C_z", "D_y", "D_z"] {
        let x = scalar(&about_o, name, &values);
        close(name, x, scalar(&about_g, name, &values), x.abs());
    }
}

/// Requests pull only what they need: about O, `T` needs `[I_O]` and ω, not the mass
/// centre, the inertia about G or any rate of angular momentum.
#[test]
fn t_about_o_pulls_only_the_inertia_about_o() {
    let text = "given m : kg\ngiven a : m\ngiven w : rad/s\n\
                body rod(a) mass m at (a/2, 0, 0) along x\nbody point() mass m at (a, 0, 0)\n\
                fixed point\nomega = w*k\nfind T\n";
    let scene = parse_scene("t_only.scene", text).unwrap();
    let analysis = analyse(&scene).unwrap();
    let titles: Vec<&str> = analysis.plan.iter().map(|s| s.title.as_str()).collect();
    assert_eq!(titles.len(), 3, "{titles:?}");
    assert!(titles[1].starts_with("inertia about $O$ by parallel axes"));
    assert!(!titles
        .iter()
        .any(|t| t.contains("mass centre") || t.contains("rate")));
    // T = ½ (m a²/3 + m a²) w² = 2/3 m a² w².
    let Value::Scalar(t) = &analysis.results[0].1 else {
        panic!("T is a scalar")
    };
    let by_hand = kinetics::parse_expression("by hand", "2/3 m a^2 w^2").unwrap();
    assert_eq!(t.expand().unwrap(), by_hand.expand().unwrap());
}

#[test]
fn about_g_is_a_statement_given_once() {
    let text = "given m : kg\ngiven r : m\ngiven w : rad/s\nbody sphere(r) mass m\n\
                fixed point\nabout G\nabout G\nomega = w*k\nfind T\n";
    let error = parse_scene("twice.scene", text).unwrap_err();
    assert_eq!(error.line, 7);
    assert!(
        error.message.contains("'about' is given twice"),
        "{}",
        error.message
    );
}
