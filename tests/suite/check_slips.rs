//! Each slip of the mechanics (`mechanics/slip.rs`) planted in a claim, the slipped value
//! derived here by hand: the checker reads the claim as that slip, and says what it changed
//! (correct − claimed) in the givens' names.

use kinetics::algebra::Expr;
use kinetics::check::context::Context;
use kinetics::check::verdict::{check, Report, Verdict};
use kinetics::parse_expression;
use kinetics::scene::parse_scene;

fn expr(text: &str) -> Expr {
    parse_expression("by hand", text).unwrap_or_else(|d| panic!("{}", d.render()))
}

fn scene_context(name: &str) -> Context {
    let path = crate::common::binary::scene(name);
    let text = std::fs::read_to_string(&path).expect("the example exists");
    let scene = parse_scene(&path, &text).unwrap_or_else(|d| panic!("{}", d.render()));
    Context::scene(&scene)
}

/// The report of a claim that differs, read as `slip`.
fn read_as(context: &Context, claim: &str, slip: &str) -> Report {
    let report = check(context, "test", claim).unwrap_or_else(|d| panic!("{}", d.render()));
    assert_eq!(report.verdict, Verdict::Differs, "{claim}");
    assert_eq!(report.reading(), Some(slip), "{claim}: {report:?}");
    report
}

/// The slip's piece in the one component that differs: correct − claimed.
fn piece(report: &Report) -> Expr {
    let slip = report.slip.as_ref().expect("a slip");
    assert_eq!(slip.pieces.len(), 1, "{:?}", slip.pieces);
    slip.pieces[0].in_symbols.clone()
}

fn assert_same(a: &Expr, b: &Expr) {
    assert!((a - b).expand().unwrap().is_zero(), "{a} is not {b}");
}

/// Euler's x equation with principal axes is ΣM_x = I_x ω̇_x − (I_y − I_z) ω_y ω_z; the
/// transport term ω × H_G gives the second term. Left out: ΣM_x = I_x ω̇_x; written H × ω,
/// the gyroscopic term changes sign.
#[test]
fn the_transport_term_left_out_or_reversed() {
    let principal = Context::general(true, false).unwrap();
    let report = read_as(&principal, "SumM_x = I_x wdot_x", "transport-term-missing");
    assert_same(&piece(&report), &expr("-(I_y - I_z) w_y w_z"));
    let report = read_as(
        &principal,
        "SumM_x = I_x wdot_x + (I_y - I_z) w_y w_z",
        "cross-product-reversed",
    );
    assert_same(&piece(&report), &expr("-2 (I_y - I_z) w_y w_z"));
}

/// SP 18.5: the axle turns at Ω = −ω₂ j while the disk turns at ω = ω₁ i − ω₂ j, with
/// H_G = ½ m r² ω₁ i − ¼ m r² ω₂ j. Ḣ_G = Ω × H_G = ½ m r² ω₁ω₂ k (i × j = k); with ω for
/// Ω, ω × H_G = (−¼ + ½) m r² ω₁ω₂ k = ¼ m r² ω₁ω₂ k.
#[test]
fn the_body_rate_for_the_frame_rate() {
    let sp18_5 = scene_context("sp18_5_disk_reactions");
    let report = read_as(&sp18_5, "Hdot_G = 1/4 m r^2 w1 w2 k", "omega-for-Omega");
    // w2 = r w1 / L, the rolling constraint.
    assert_same(&piece(&report), &expr("1/4 m r^3 w1^2 / L"));
}

/// Rotation about the fixed axis z: ΣM_z = I_z α. With ω² for ω̇ in [I]{ω̇} (ω = ω k):
/// I_z ω².
#[test]
fn the_square_for_the_rate() {
    let fixed_axis = Context::fixed_axis().unwrap();
    let report = read_as(
        &fixed_axis,
        "SumM_z = I_z w^2",
        "omega-squared-for-omegadot",
    );
    assert_same(&piece(&report), &expr("I_z (alpha - w^2)"));
}

/// SP 18.3: the rod AB about A. Its centroidal moment about the horizontal x axis is
/// 1/12 m L² sin²β; about A the parallel-axis term m ȳ² = m (½ L sin β)² adds ¼ m L² sin²β,
/// so I_x = ⅓ m L² sin²β. Without it, 1/12 m L² sin²β.
#[test]
fn the_parallel_axis_term_left_out() {
    let sp18_3 = scene_context("sp18_3_rotating_rod");
    let report = read_as(
        &sp18_3,
        "I_x = 1/12 m L^2 sin(beta)^2",
        "parallel-axis-missing",
    );
    assert_same(&piece(&report), &expr("1/4 m L^2 sin(beta)^2"));
}

/// T = ½ m v̄² + ½ (I_x ω_x² + I_y ω_y² + I_z ω_z²) with principal axes; the rotational ½
/// left out.
#[test]
fn the_half_left_out() {
    let principal = Context::general(true, false).unwrap();
    let report = read_as(
        &principal,
        "T = 1/2 m (vbar_x^2 + vbar_y^2 + vbar_z^2) + I_x w_x^2 + I_y w_y^2 + I_z w_z^2",
        "half-missing",
    );
    assert_same(
        &piece(&report),
        &expr("-1/2 (I_x w_x^2 + I_y w_y^2 + I_z w_z^2)"),
    );
}

/// SP 18.2: the disk's H_G = ½ m r² ω₁ i − ¼ m r² ω₂ j with ω₂ = r ω₁/L. With the disk's
/// moments about its axis and about a diameter exchanged: ¼ m r² ω₁ i − ½ m r² ω₂ j.
#[test]
fn a_shapes_moments_exchanged() {
    let sp18_2 = scene_context("sp18_2_rolling_disk");
    let report = check(&sp18_2, "test", "H_G = 1/4 m r^2 w1 i - 1/2 m r^3 w1 / L j").unwrap();
    assert_eq!(
        report.reading(),
        Some("wrong-moment-of-inertia"),
        "{report:?}"
    );
    let pieces = &report.slip.as_ref().unwrap().pieces;
    assert_same(&pieces[0].in_symbols, &expr("1/4 m r^2 w1"));
    assert_same(&pieces[1].in_symbols, &expr("1/4 m r^3 w1 / L"));
}

/// A claim in numbers in a scene with values is read in the givens' names: SP 18.4's
/// D_z without the ω² term of Ω × H_O, D_z = m c α/4 (α = M/I_x), is the transport term
/// left out, and its piece −⅛ m c ω² has the value −⅛ · 0.3 · 0.1 · 125.7² = −59.25 N.
#[test]
fn a_slip_in_a_numeric_scene_is_read_in_symbols_then_numbers() {
    let sp18_4 = scene_context("sp18_4_shaft_reactions");
    let report = read_as(&sp18_4, "D_z = m c alpha/4", "transport-term-missing");
    let slip = report.slip.as_ref().unwrap();
    assert_same(&slip.pieces[0].in_symbols, &expr("-1/8 m c w^2"));
    let value = slip.pieces[0]
        .value
        .expect("a value: the claim is in numbers");
    let by_hand = -0.3 * 0.1 * 125.7_f64.powi(2) / 8.0;
    assert!((value - by_hand).abs() < 1e-9 * by_hand.abs(), "{value}");
}

/// SP 18.3 again: the rod's moment about its end, ⅓ m L², taken for its centroidal one and
/// then moved to A: (⅓ + ¼) m L² sin²β = 7/12 m L² sin²β.
#[test]
fn a_rods_moment_about_its_end_for_its_centre() {
    let sp18_3 = scene_context("sp18_3_rotating_rod");
    let report = read_as(
        &sp18_3,
        "I_x = 7/12 m L^2 sin(beta)^2",
        "wrong-moment-of-inertia",
    );
    assert_same(&piece(&report), &expr("-1/4 m L^2 sin(beta)^2"));
}
