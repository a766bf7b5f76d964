//! The quantities of issue 18's first item that a scene asks for by name — `v_A`, `a_A` of a
//! named point, `Hdot_O`, `T_trans` and `T_rot`, and a named impulsive reaction — each
//! checked against a computation written here without the library's mechanics:
//!
//! - `disk_on_turning_axle`: the disk's motion written as a rotation `R(t)`; `v_A` and `a_A`
//!   are finite differences of A's position `R(t) r_A`, `Ḣ_O` a finite difference of
//!   `H_O(t) = Σ mᵢ rᵢ × (ω(t) × rᵢ)` over point masses that have the disk's inertia, and
//!   `T_trans`, `T_rot` sums `½ Σ mᵢ v²` over them;
//! - `plate_falls_on_corner`: the impact solved by hand in the test;
//! - small scenes for `a_A` through the mass centre and for the refusals.

use crate::common::examples::{analysed_example, result};
use kinetics::algebra::Expr;
use kinetics::parse::parse_expression;
use kinetics::scene::{analyse, parse_scene, Scene, Value};

type V3 = [f64; 3];

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

fn scaled(s: f64, a: V3) -> V3 {
    a.map(|x| s * x)
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn value(scene: &Scene, e: &Expr) -> f64 {
    e.eval(&|s| scene.value(s))
        .unwrap_or_else(|err| panic!("{e}: {err}"))
}

fn numbers(scene: &Scene, v: &Value) -> Vec<f64> {
    match v {
        Value::Scalar(e) => vec![value(scene, e)],
        Value::Vector(v) => v.iter().map(|c| value(scene, c)).collect(),
        other => panic!("{other:?} is not a scalar or a vector"),
    }
}

fn close(derived: &[f64], expected: &[f64], tolerance: f64, what: &str) {
    let scale = expected.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    for (d, e) in derived.iter().zip(expected) {
        assert!(
            (d - e).abs() <= tolerance * scale,
            "{what}: derived {derived:?}, expected {expected:?}"
        );
    }
}

/// The disk on the turning axle (`examples/scenes/disk_on_turning_axle.scene`), by hand.
struct Disk {
    m: f64,
    r: f64,
    l: f64,
    w1: f64,
    w2: f64,
    alpha1: f64,
}

const DISK: Disk = Disk {
    m: 3.0,
    r: 0.15,
    l: 0.5,
    w1: 40.0,
    w2: 5.0,
    alpha1: 10.0,
};

impl Disk {
    /// The spin angle about the axle: `θ = w1 t + ½ α1 t²`, and its rate.
    fn spin(&self, t: f64) -> (f64, f64) {
        (
            self.w1 * t + 0.5 * self.alpha1 * t * t,
            self.w1 + self.alpha1 * t,
        )
    }

    /// Where the body point at `p` (at t = 0) is at time t: turned by θ about the axle x,
    /// then by `w2 t` about the vertical y.
    fn position(&self, t: f64, p: V3) -> V3 {
        let (theta, _) = self.spin(t);
        let (c, s) = (theta.cos(), theta.sin());
        let spun = [p[0], c * p[1] - s * p[2], s * p[1] + c * p[2]];
        let (c, s) = ((self.w2 * t).cos(), (self.w2 * t).sin());
        [
            c * spun[0] + s * spun[2],
            spun[1],
            -s * spun[0] + c * spun[2],
        ]
    }

    /// The angular velocity at time t: `w2 J` and the spin rate about the turned axle.
    fn omega(&self, t: f64) -> V3 {
        let (_, rate) = self.spin(t);
        let axle = [(self.w2 * t).cos(), 0.0, -(self.w2 * t).sin()];
        add([0.0, self.w2, 0.0], scaled(rate, axle))
    }

    /// Six equal point masses on a ring of radius r/√2 in the disk's plane: their moments
    /// about the centre are m r²/2 about the axle and m r²/4 across it, the thin disk's.
    fn masses(&self) -> Vec<(f64, V3)> {
        let rho = self.r / 2f64.sqrt();
        (0..6)
            .map(|k| {
                let phi = std::f64::consts::PI * k as f64 / 3.0 + 0.3;
                (self.m / 6.0, [self.l, rho * phi.cos(), rho * phi.sin()])
            })
            .collect()
    }

    /// `H_O(t) = Σ mᵢ rᵢ × (ω × rᵢ)`.
    fn angular_momentum(&self, t: f64) -> V3 {
        let omega = self.omega(t);
        self.masses().into_iter().fold([0.0; 3], |h, (m, p)| {
            let r = self.position(t, p);
            add(h, scaled(m, cross(r, cross(omega, r))))
        })
    }
}

#[test]
fn rim_point_velocity_and_acceleration_are_finite_differences_of_its_position() {
    let (scene, analysis) = analysed_example("disk_on_turning_axle", "");
    let (d, h) = (&DISK, 1e-5);
    let a0 = [d.l, d.r, 0.0];
    let (before, now, after) = (d.position(-h, a0), a0, d.position(h, a0));
    let velocity: Vec<f64> = (0..3).map(|k| (after[k] - before[k]) / (2.0 * h)).collect();
    let acceleration: Vec<f64> = (0..3)
        .map(|k| (after[k] - 2.0 * now[k] + before[k]) / (h * h))
        .collect();
    close(
        &numbers(&scene, result(&analysis, "v_A")),
        &velocity,
        1e-6,
        "v_A",
    );
    close(
        &numbers(&scene, result(&analysis, "a_A")),
        &acceleration,
        1e-5,
        "a_A",
    );
}

#[test]
fn hdot_o_is_the_rate_of_the_angular_momentum_of_point_masses() {
    let d = &DISK;
    let h = 1e-5;
    let (before, after) = (d.angular_momentum(-h), d.angular_momentum(h));
    let rate: Vec<f64> = (0..3).map(|k| (after[k] - before[k]) / (2.0 * h)).collect();
    // About O with [I_O], and through G (`about G`: Ḣ_G + r̄ × m ā): the same rate.
    for extra in ["", "\nabout G\n"] {
        let (scene, analysis) = analysed_example("disk_on_turning_axle", extra);
        let derived = numbers(&scene, result(&analysis, "Hdot_O"));
        close(&derived, &rate, 1e-7, &format!("Hdot_O{extra}"));
    }
}

#[test]
fn kinetic_energy_parts_are_sums_over_point_masses() {
    let (scene, analysis) = analysed_example("disk_on_turning_axle", "");
    let d = &DISK;
    let omega = d.omega(0.0);
    let centre = [d.l, 0.0, 0.0];
    let half_m_v2 = |v: V3| 0.5 * dot(v, v);
    let total: f64 = d
        .masses()
        .iter()
        .map(|(m, p)| m * half_m_v2(cross(omega, *p)))
        .sum();
    let rotation: f64 = d
        .masses()
        .iter()
        .map(|(m, p)| m * half_m_v2(cross(omega, add(*p, scaled(-1.0, centre)))))
        .sum();
    let translation = d.m * half_m_v2(cross(omega, centre));
    let value_of = |name: &str| numbers(&scene, result(&analysis, name))[0];
    close(&[value_of("T_trans")], &[translation], 1e-12, "T_trans");
    close(&[value_of("T_rot")], &[rotation], 1e-12, "T_rot");
    close(&[value_of("T")], &[total], 1e-12, "T");
    close(
        &[translation + rotation],
        &[total],
        1e-12,
        "T_trans + T_rot",
    );
}

fn same(derived: &Expr, by_hand: &str) {
    let by_hand = parse_expression("by hand", by_hand).unwrap();
    assert_eq!(
        derived.expand().unwrap(),
        by_hand.expand().unwrap(),
        "derived {derived}, by hand {by_hand}"
    );
}

fn vector<'a>(analysis: &'a kinetics::Analysis, name: &str) -> &'a kinetics::Vector {
    match result(analysis, name) {
        Value::Vector(v) => v,
        _ => panic!("{name} is a vector"),
    }
}

fn scalar<'a>(analysis: &'a kinetics::Analysis, name: &str) -> &'a Expr {
    match result(analysis, name) {
        Value::Scalar(e) => e,
        _ => panic!("{name} is a scalar"),
    }
}

/// The plate a × b (x along a, z along b, y up, G the origin) falls at v₀ and its corner
/// C = (a/2, 0, b/2) stops on an obstruction, which gives the impulse R at C. By hand:
///
/// ```text
/// linear:   m v̄_y = −m v₀ + R_y,   0 = R_x,   0 = R_z
/// angular:  [Ī]{ω} = r_C × R = (−b R_y/2, b R_x/2 − a R_z/2, a R_y/2),
///           Ī_x = m b²/12, Ī_z = m a²/12:  ω_x = −6 R_y/(m b), ω_z = 6 R_y/(m a)
/// C stops:  v̄_y + (ω × r_C)_y = v̄_y − b ω_x/2 + a ω_z/2 = v̄_y + 6 R_y/m = 0
/// so        −6 R_y = −m v₀ + R_y:  R_y = m v₀/7,  v̄_y = −6 v₀/7
/// ```
#[test]
fn impulsive_reaction_of_the_obstruction_is_the_hand_derivation() {
    let (_, analysis) = analysed_example("plate_falls_on_corner", "");
    let reaction = vector(&analysis, "R");
    for (component, by_hand) in reaction.iter().zip(["0", "m v_0/7", "0"]) {
        same(component, by_hand);
    }
    let vbar = vector(&analysis, "vbar");
    for (component, by_hand) in vbar.iter().zip(["0", "-6 v_0/7", "0"]) {
        same(component, by_hand);
    }
    let omega = vector(&analysis, "omega");
    for (component, by_hand) in omega.iter().zip(["-6 v_0/(7 b)", "0", "6 v_0/(7 a)"]) {
        same(component, by_hand);
    }
    // T_trans = ½ m (6 v₀/7)², T_rot = ½ (Ī_x ω_x² + Ī_z ω_z²) = ½ (m/12)(36 v₀²/49) · 2.
    same(scalar(&analysis, "T_trans"), "18/49 m v_0^2");
    same(scalar(&analysis, "T_rot"), "3/49 m v_0^2");
    same(scalar(&analysis, "T"), "3/7 m v_0^2");
    for component in vector(&analysis, "v_C").iter() {
        same(component, "0");
    }
}

/// A free sphere with a given ā, ω = w k and ω̇ = α k; A at (r, 0, 0) from G. By hand,
/// `a_A = ā + α k × r i + w k × (w k × r i) = (a_0 − r w²) i + r α j`, and
/// `v_A = v̄ + w k × r i = (v_0, r w, 0)`.
#[test]
fn a_point_of_a_free_body_moves_with_its_mass_centre() {
    let text = "given m : kg
given r : m
given a_0 : m/s^2
given v_0 : m/s
given w : rad/s
given alpha : rad/s^2
body sphere(r) mass m
vbar = v_0*i
abar = a_0*i
omega = w*k
omegadot = alpha*k
point A at (r, 0, 0)
find v_A, a_A";
    let scene = parse_scene("free.scene", text).unwrap_or_else(|d| panic!("{}", d.render()));
    let analysis = analyse(&scene).unwrap_or_else(|d| panic!("{}", d.render()));
    for (component, by_hand) in vector(&analysis, "v_A").iter().zip(["v_0", "r w", "0"]) {
        same(component, by_hand);
    }
    let a = vector(&analysis, "a_A");
    for (component, by_hand) in a.iter().zip(["a_0 - r w^2", "r alpha", "0"]) {
        same(component, by_hand);
    }
}

fn refused(text: &str) -> kinetics::Diagnostic {
    match parse_scene("refused.scene", text) {
        Err(d) => d,
        Ok(scene) => match analyse(&scene) {
            Err(d) => d,
            Ok(_) => panic!("accepted:\n{text}"),
        },
    }
}

const SPHERE: &str = "given m : kg
given r : m
given w : rad/s
body sphere(r) mass m
vbar = 0
omega = w*k
";

#[test]
fn hdot_o_without_a_fixed_point_is_refused_with_the_reason() {
    let d = refused(&format!("{SPHERE}find Hdot_O"));
    assert!(d.message.contains("not fixed"), "{}", d.message);
    assert!(d.help.unwrap_or_default().contains("fixed point"));
}

#[test]
fn an_unnamed_point_is_refused_with_the_known_names() {
    let d = refused(&format!("{SPHERE}point A at (r, 0, 0)\nfind v_B"));
    assert!(d.message.contains("no point is named B"), "{}", d.message);
    let help = d.help.unwrap_or_default();
    assert!(help.contains("named points are A"), "{help}");
}

#[test]
fn forces_points_and_impulses_do_not_share_names() {
    for clash in [
        "force A = m*r*w^2*j at (0, 0, 0)\npoint A at (r, 0, 0)",
        "point A at (r, 0, 0)\nforce A = m*r*w^2*j at (0, 0, 0)",
        "point R at (r, 0, 0)\nimpulse R = m*r*w*j at (r, 0, 0)",
    ] {
        let d = refused(&format!("{SPHERE}{clash}\nfind T"));
        assert!(d.message.contains("already the name of"), "{}", d.message);
    }
}

/// A free rod (length L, along x) spinning at w_0 about z through its resting centre G is
/// caught at its end E = (L/2, 0, 0) by a pin, which gives the impulse R. By hand, with
/// Ī_z = m L²/12: `m v̄_y = R_y`, `Ī_z w_0 + (L/2) R_y = Ī_z w_z` and E at rest,
/// `v̄_y + w_z L/2 = 0`; so `w_z = w_0/4` (the angular momentum about the pin,
/// `m L² w_0/12 = m L² w_z/3`, is kept) and `R_y = −m L w_0/8`.
#[test]
fn a_spinning_rod_caught_at_its_end_keeps_its_angular_momentum_about_the_pin() {
    let text = "given m : kg
given L : m
given w_0 : rad/s
unknown vbar_y : m/s
unknown w_z : rad/s
unknown R_y : N*s
body rod(L) mass m
before omega = w_0*k
vbar = vbar_y*j
omega = w_z*k
impulse R = R_y*j at (L/2, 0, 0)
constraint velocity at (L/2, 0, 0) = 0
find w_z, vbar_y, R";
    let scene = parse_scene("rod.scene", text).unwrap_or_else(|d| panic!("{}", d.render()));
    let analysis = analyse(&scene).unwrap_or_else(|d| panic!("{}", d.render()));
    same(scalar(&analysis, "w_z"), "w_0/4");
    same(scalar(&analysis, "vbar_y"), "-L w_0/8");
    for (component, by_hand) in vector(&analysis, "R").iter().zip(["0", "-m L w_0/8", "0"]) {
        same(component, by_hand);
    }
}

#[test]
fn the_motion_before_an_impact_needs_an_impulse() {
    let d = refused(&format!("{SPHERE}before vbar = r*w*i\nfind T"));
    assert!(d.message.contains("no impulse"), "{}", d.message);
}

/// `kinetics check` knows a scene's named points and impulses: a claim `v_A = ...` or
/// `R = ...` is decided against the value `solve` prints (by hand, as above).
#[test]
fn check_decides_claims_about_named_points_and_impulses() {
    use crate::common::check::{check_file, judged, ClaimsFile};
    let cases = [
        (
            "examples/scenes/disk_on_turning_axle.scene",
            "v_A = (r*w1 - L*w2)*k\nv_A = (r*w1 + L*w2)*k\na_A = (2*r*w1*w2 - L*w2^2)*i - r*w1^2*j + r*alpha1*k\n",
        ),
        (
            "examples/scenes/plate_falls_on_corner.scene",
            "R = m*v_0/7*j\nR = m*v_0/6*j\nv_C = 0*i\n",
        ),
    ];
    for (scene, claims) in cases {
        let file = ClaimsFile::new("named-points", claims);
        let (judged, _) = judged(&check_file(scene, &file));
        let verdicts: Vec<&str> = judged.iter().map(|j| j.verdict.as_str()).collect();
        assert_eq!(verdicts, ["holds", "differs", "holds"], "{scene}");
    }
}
