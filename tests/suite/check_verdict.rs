//! The checker's contexts and verdicts through the library: the derived names stand for the
//! chapter's definitions (written here by hand, not taken from the library), and the
//! verdict is `holds` for a multiple or rearrangement, `differs` for a slip, `undecided`
//! where the algebra cannot show what evaluation finds.

use kinetics::algebra::{Expr, Symbol};
use kinetics::check::context::Context;
use kinetics::check::verdict::{check, Verdict};
use kinetics::parse::claim::Name;
use kinetics::parse_expression;
use kinetics::scene::parse_scene;

fn expr(text: &str) -> Expr {
    parse_expression("by hand", text).unwrap_or_else(|d| panic!("{}", d.render()))
}

fn derived(context: &Context, name: &str) -> Expr {
    match context.name(name) {
        Name::Derived(e) => e,
        other => panic!("{name} is derived in {}: {other:?}", context.description),
    }
}

/// Two expressions equal: their difference multiplies out to zero.
fn assert_same(a: &Expr, b: &Expr, what: &str) {
    let difference = (a - b).expand().expect("small");
    assert!(difference.is_zero(), "{what}: {a} is not {b}");
}

/// The context of the shipped scene `examples/scenes/<name>.scene`.
fn scene_context(name: &str) -> Context {
    let path = crate::common::binary::scene(name);
    let text = std::fs::read_to_string(&path).expect("the example exists");
    let scene = parse_scene(&path, &text).unwrap_or_else(|d| panic!("{}", d.render()));
    Context::scene(&scene)
}

fn verdict(context: &Context, claim: &str) -> Verdict {
    check(context, "test", claim)
        .unwrap_or_else(|d| panic!("{}", d.render()))
        .verdict
}

#[test]
fn the_general_body_names_stand_for_the_chapter_definitions() {
    let c = Context::general(false, false).expect("the general body");
    // {H_G} = [I]{ω} with the chapter's convention: products of inertia with a minus.
    let h = [
        "I_x w_x - I_xy w_y - I_xz w_z",
        "-I_xy w_x + I_y w_y - I_yz w_z",
        "-I_xz w_x - I_yz w_y + I_z w_z",
    ];
    for (axis, by_hand) in ["x", "y", "z"].iter().zip(h) {
        assert_same(&derived(&c, &format!("H_{axis}")), &expr(by_hand), "H_G");
    }
    // T = ½ m v̄·v̄ + ½ ωᵀ[I]ω, written out.
    let t = "1/2 m (vbar_x^2 + vbar_y^2 + vbar_z^2) + 1/2 (I_x w_x^2 + I_y w_y^2 + I_z w_z^2) \
             - I_xy w_x w_y - I_yz w_y w_z - I_xz w_z w_x";
    assert_same(&derived(&c, "T"), &expr(t), "T");
    // H_O = H_G + r̄ × m v̄, the cross product's x component by hand.
    let h_o = derived(&c, "H_O");
    let x_by_hand = expr(&format!("({}) + m (ybar vbar_z - zbar vbar_y)", h[0]));
    let x_of = |e: &Expr| {
        e.subs(&|s: Symbol| match s.name() {
            "i" => Some(Expr::int(1)),
            "j" | "k" => Some(Expr::int(0)),
            _ => None,
        })
        .expect("substitution")
    };
    assert_same(&x_of(&h_o), &x_by_hand, "H_O x");
    // Body-fixed axes: Ḣ_G = [I]{ω̇} + ω × H_G is Euler's right side.
    for axis in ["x", "y", "z"] {
        assert_same(
            &derived(&c, &format!("Hdot_{axis}")),
            &derived(&c, &format!("SumM_{axis}")),
            "Hdot = SumM",
        );
    }
}

#[test]
fn principal_euler_and_fixed_axis_moments_are_the_textbook_ones() {
    let p = Context::general(true, false).expect("principal");
    assert_same(
        &derived(&p, "M_x"),
        &expr("I_x wdot_x - (I_y - I_z) w_y w_z"),
        "Euler x",
    );
    assert_same(
        &derived(&p, "SumM_z"),
        &expr("I_z wdot_z - (I_x - I_y) w_x w_y"),
        "Euler z",
    );
    // §18.7: ΣM_x = −I_xz α + I_yz ω², ΣM_y = −I_yz α − I_xz ω², ΣM_z = I_z α.
    let f = Context::fixed_axis().expect("fixed axis");
    assert_same(&derived(&f, "SumM_x"), &expr("-I_xz alpha + I_yz w^2"), "x");
    assert_same(&derived(&f, "SumM_y"), &expr("-I_yz alpha - I_xz w^2"), "y");
    assert_same(&derived(&f, "SumM_z"), &expr("I_z alpha"), "z");
}

#[test]
fn multiples_and_rearrangements_hold() {
    let p = Context::general(true, false).expect("principal");
    for claim in [
        "2 T = m (vbar_x^2 + vbar_y^2 + vbar_z^2) + I_x w_x^2 + I_y w_y^2 + I_z w_z^2",
        "L M_x = L I_x wdot_x - L (I_y - I_z) w_y w_z",
        "I_x wdot_x = M_x + (I_y - I_z) w_y w_z",
        "1/2 I_x w_x^2 + 1/2 I_y w_y^2 + 1/2 I_z w_z^2 + 1/2 m (vbar_x^2 + vbar_y^2 + vbar_z^2) = T",
        "H_G = I_x w_x i + I_y w_y j + I_z w_z k",
    ] {
        assert_eq!(verdict(&p, claim), Verdict::Holds, "{claim}");
    }
}

#[test]
fn identities_the_algebra_reduces_hold_and_slips_differ() {
    let g = Context::general(false, false).expect("general");
    assert_eq!(verdict(&g, "sin(2 t) = 2 sin(t) cos(t)"), Verdict::Holds);
    assert_eq!(verdict(&g, "sin(t)^2 = 1 - cos(t)^2"), Verdict::Holds);
    // m is a mass, positive: √(m²) = m; x is a coordinate: √(x²) = |x|, not x.
    assert_eq!(verdict(&g, "sqrt(m^2) = m"), Verdict::Holds);
    assert_eq!(verdict(&g, "sqrt(x^2) = x"), Verdict::Differs);
    assert_eq!(
        verdict(&g, "H_x = I_x w_x - I_xy w_y + I_xz w_z"),
        Verdict::Differs
    );
}

#[test]
fn what_only_evaluation_sees_is_undecided_never_differs() {
    let g = Context::general(false, false).expect("general");
    // sin(t + π) = −sin(t): true, but the algebra does not shift angles by π.
    let report = check(&g, "test", "sin(t + pi) = -sin(t)").expect("reads");
    assert_eq!(report.verdict, Verdict::Undecided, "{report:?}");
    assert!(report.components[0].undecided_because.is_some());
}

#[test]
fn a_scene_claim_uses_its_givens_unknowns_and_quantities() {
    let c = scene_context("sp18_2_rolling_disk");
    // Sample Problem 18.2 by hand: ω₂ = r ω₁/L from v_C = 0, and
    // T = ½ (½ m r² ω₁² + m (L² + ¼ r²) (r ω₁/L)²) + ½ m (r ω₁)² = m r² (6 L² + r²) ω₁²/(8 L²).
    assert_eq!(verdict(&c, "w2 = r w1/L"), Verdict::Holds);
    assert_eq!(
        verdict(&c, "T = 1/8 m r^2 (6 + r^2/L^2) w1^2"),
        Verdict::Holds
    );
    assert_eq!(
        verdict(&c, "T = 1/8 m r^2 (6 + r^2/L^2) w1"),
        Verdict::Differs
    );
    // The disk's motion differentiated by hand: the axle turns at −w2 j and the disk spins
    // at w1 about it, so G = (L cos w2 t, 0, L sin w2 t) has ā = −L w2² i, and
    // Ḣ_G = Ω × H_G with H_G = ½ m r² w1 i + ¼ m r² (−w2) j, Ω = −w2 j: ½ m r² w1 w2 k.
    assert_eq!(verdict(&c, "abar = -L w2^2 i"), Verdict::Holds);
    assert_eq!(verdict(&c, "Hdot_G = 1/2 m r^2 w1 w2 k"), Verdict::Holds);
    assert_eq!(verdict(&c, "Hdot_G = 1/4 m r^2 w1 w2 k"), Verdict::Differs);
    // `w1` and `w_1` are one symbol; a name the scene does not know is refused, with the
    // near spelling it does know.
    assert_eq!(verdict(&c, "w2 = r w_1/L"), Verdict::Holds);
    let err = check(&c, "test", "T = W1^2").expect_err("W1 is not the scene's name");
    assert!(
        err.help.as_deref().is_some_and(|h| h.contains("w_1")),
        "{}",
        err.render()
    );
}

#[test]
fn a_claim_written_with_the_givens_values_is_decided_at_them() {
    let c = scene_context("sp18_3_rotating_rod");
    // beta = 60 deg: cos β = ½; ā = −½ L cos β ω² i = −¼ L ω² i; A_y = m g = 20 × 9.81 N.
    assert_eq!(verdict(&c, "cos(beta) = 1/2"), Verdict::Holds);
    assert_eq!(verdict(&c, "abar = -1/4 L w^2 i"), Verdict::Holds);
    assert_eq!(verdict(&c, "A_y = 196.2"), Verdict::Holds);
    // A number holds within the relative tolerance (0.5 % unless told): 196 is 0.1 % from
    // 196.2, 190 is 3.2 % from it; at 0.01 % 196 differs too.
    assert_eq!(verdict(&c, "A_y = 196"), Verdict::Holds);
    assert_eq!(verdict(&c, "A_y = 190"), Verdict::Differs);
    let tight = c.clone().with_relative_tolerance(1e-4);
    assert_eq!(verdict(&tight, "A_y = 196"), Verdict::Differs);
    // With its unit, converted: 0.1962 kN is 196.2 N; a unit of another dimension is the
    // odd term.
    assert_eq!(verdict(&c, "A_y = 0.1962 kN"), Verdict::Holds);
    assert_eq!(verdict(&c, "A_y = 196.2 N"), Verdict::Holds);
    assert_eq!(verdict(&c, "A_y = 196.2 kg"), Verdict::Differs);
    // Written in the givens' names, a claim is decided in their names.
    assert_eq!(verdict(&c, "A_y = m g"), Verdict::Holds);
    assert_eq!(verdict(&c, "abar = -1/2 L cos(beta) w^2 i"), Verdict::Holds);
}

#[test]
fn a_claim_in_names_missing_a_small_term_differs() {
    // A disk (I_z = ½ m r², I_x = ¼ m r²) turning at w_1 = 300 rpm about its axis and
    // w_2 = 2 rad/s across it: T = ¼ m r² w_1² + ⅛ m r² w_2², whose second term is 0.2 % of
    // T. Leaving it out is a slip, not a rounding: a claim in names is exact.
    let scene = parse_scene(
        "disk.scene",
        "given m = 4 kg\ngiven r = 250 mm\ngiven w1 = 300 rpm\ngiven w2 = 2 rad/s\n\
         body disk(r) mass m along z\nvbar = 0\nomega = w2*i + w1*k\nfind T\n",
    )
    .unwrap_or_else(|d| panic!("{}", d.render()));
    let c = Context::scene(&scene);
    assert_eq!(verdict(&c, "T = 1/4 m r^2 w1^2"), Verdict::Differs);
    assert_eq!(
        verdict(&c, "T = 1/4 m r^2 w1^2 + 1/8 m r^2 w2^2"),
        Verdict::Holds
    );
    // In numbers it holds within the tolerance: 61.8 J is 0.02 % from 61.81 J.
    assert_eq!(verdict(&c, "T = 61.8"), Verdict::Holds);
    // 61.5 J is 0.502 % from 61.810 J: said with the figures that tell it from 0.5 %.
    let near = check(&c, "test", "T = 61.5").unwrap_or_else(|d| panic!("{}", d.render()));
    assert_eq!(near.verdict, Verdict::Differs);
    let forms = kinetics::check::forms::Forms::new(c.domains());
    let report = kinetics::check::report::text(&near, "claim", &forms);
    assert!(
        report.contains("61.5 J is 0.502 % from the exact 61.81 J; the tolerance is 0.5 %"),
        "{report}"
    );
}

#[test]
fn dimensions_judge_what_the_student_wrote() {
    let p = Context::general(true, false).expect("principal");
    // |u| has the unit of u; exponents past a unit's range are not judged, never an error.
    assert_eq!(verdict(&p, "abs(v) = v"), Verdict::Holds);
    assert_eq!(verdict(&p, "w_x^129 = w_x^129"), Verdict::Holds);
    assert_eq!(verdict(&p, "m^128 = m^128"), Verdict::Holds);
    // The side naming T decides the dimension: the odd term is the student's.
    let report = check(&p, "test", "T = I_x w_x + I_y w_y").expect("reads");
    let odd = report.odd_term.expect("inhomogeneous");
    assert_eq!(odd.text, "I_x w_x");
    assert_eq!(report.verdict, Verdict::Differs);
}
