//! The compiled tape against tree-walking `Expr::eval` on the chapter's derivations (general
//! Euler equations, T, H_G): values, shared subexpressions, factoring, pruning by principal axes, f32,
//! dual-number sensitivities against `Expr::diff`, bad input, and batch against serial.

use kinetics::algebra::{Expr, Symbol, Q};
use kinetics::mechanics::angular_momentum::angular_momentum;
use kinetics::mechanics::euler::{body_angular_velocity, euler_equations};
use kinetics::mechanics::fixed_axis::bearing_reactions;
use kinetics::mechanics::inertia::InertiaTensor;
use kinetics::mechanics::kinetic_energy::kinetic_energy;
use kinetics::mechanics::Derivation;
use kinetics::numeric::tape::batch::SETS_PER_TASK;
use kinetics::numeric::{Dual, Instruction, NumericError, Tape};
use proptest::prelude::*;
use std::sync::OnceLock;

const INPUTS: [&str; 12] = [
    "w_x", "w_y", "w_z", "wdot_x", "wdot_y", "wdot_z", "I_x", "I_y", "I_z", "I_xy", "I_yz", "I_xz",
];
const PRODUCTS_OF_INERTIA: [&str; 3] = ["I_xy", "I_yz", "I_xz"];

fn symbols(names: &[&str]) -> Vec<Symbol> {
    names.iter().map(|n| Symbol::new(n)).collect()
}

fn rhs(d: &Derivation) -> Vec<Expr> {
    d.result().iter().map(|r| r.rhs.clone()).collect()
}

fn general_euler() -> &'static [Expr] {
    static E: OnceLock<Vec<Expr>> = OnceLock::new();
    E.get_or_init(|| rhs(&euler_equations(&InertiaTensor::general()).unwrap()))
}

/// The general Euler equations, T (with translation) and H_G, each with its inputs.
fn chapter() -> &'static [(Vec<Expr>, Vec<Symbol>)] {
    static C: OnceLock<Vec<(Vec<Expr>, Vec<Symbol>)>> = OnceLock::new();
    C.get_or_init(|| {
        let omega = body_angular_velocity();
        let general = InertiaTensor::general();
        let vbar = ["vbar_x", "vbar_y", "vbar_z"].map(Expr::symbol).into();
        let t = kinetic_energy(&general, &omega, Some((&Expr::symbol("m"), &vbar))).unwrap();
        let h = angular_momentum(&general, &omega, "G").unwrap();
        [general_euler().to_vec(), rhs(&t), rhs(&h)]
            .into_iter()
            .map(|outputs| {
                let mut inputs: Vec<Symbol> = outputs.iter().flat_map(Expr::symbols).collect();
                inputs.sort();
                inputs.dedup();
                (outputs, inputs)
            })
            .collect()
    })
}

fn value_of<'a>(inputs: &'a [Symbol], values: &'a [f64]) -> impl Fn(Symbol) -> Option<f64> + 'a {
    move |s| inputs.iter().position(|&i| i == s).map(|k| values[k])
}

/// The condition scale of a sum: the sum of the magnitudes of its terms. Rounding errors of
/// any evaluation order are relative to this, not to a possibly cancelled total.
fn scale(e: &Expr, value: &dyn Fn(Symbol) -> Option<f64>) -> f64 {
    e.terms()
        .iter()
        .map(|t| t.eval(value).unwrap().abs())
        .sum::<f64>()
        .max(f64::MIN_POSITIVE)
}

fn eval_f64(tape: &Tape, inputs: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; tape.n_outputs()];
    tape.eval(inputs, &mut out).unwrap();
    out
}

fn values(n: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-3.0f64..3.0, n)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn tape_agrees_with_tree_walking_on_the_chapter(v in values(16)) {
        for (outputs, inputs) in chapter() {
            let tape = Tape::compile(outputs, inputs).unwrap();
            let point = &v[..inputs.len()];
            let got = eval_f64(&tape, point);
            let value = value_of(inputs, point);
            for (e, g) in outputs.iter().zip(&got) {
                let want = e.eval(&value).unwrap();
                prop_assert!((g - want).abs() <= 1e-14 * scale(e, &value), "{e}: {g} vs {want}");
            }
        }
    }

    #[test]
    fn f32_tape_follows_f64_tape(v in values(12)) {
        let tape = Tape::compile(general_euler(), &symbols(&INPUTS)).unwrap();
        let wide = eval_f64(&tape, &v);
        let narrow_inputs: Vec<f32> = v.iter().map(|&x| x as f32).collect();
        let mut narrow = [0.0f32; 3];
        tape.eval(&narrow_inputs, &mut narrow).unwrap();
        // Against f64 at the same (rounded) inputs: only the arithmetic differs.
        let rounded: Vec<f64> = narrow_inputs.iter().map(|&x| f64::from(x)).collect();
        let reference = eval_f64(&tape, &rounded);
        let inputs = symbols(&INPUTS);
        let value = value_of(&inputs, &rounded);
        for ((e, r), n) in general_euler().iter().zip(&reference).zip(&narrow) {
            prop_assert!((f64::from(*n) - r).abs() <= 1e-6 * scale(e, &value), "{n} vs {r}");
        }
        // and the f64 tape at the unrounded inputs is within the rounding of the inputs.
        for (w, r) in wide.iter().zip(&reference) {
            prop_assert!((w - r).abs() <= 1e-5 * (1.0 + w.abs()), "{w} vs {r}");
        }
    }

    #[test]
    fn dual_numbers_give_the_symbolic_partial_derivatives(v in values(12)) {
        let inputs = symbols(&INPUTS);
        let tape = Tape::compile(general_euler(), &inputs).unwrap();
        let value = value_of(&inputs, &v);
        let mut scratch = Vec::new();
        let mut out = [Dual::constant(0.0); 3];
        for (j, &x) in inputs.iter().enumerate() {
            let seeded: Vec<Dual<f64>> = v.iter().enumerate()
                .map(|(k, &a)| if k == j { Dual::variable(a) } else { Dual::constant(a) })
                .collect();
            tape.eval_with(&seeded, &mut out, &mut scratch).unwrap();
            for (e, d) in general_euler().iter().zip(&out) {
                let partial = e.diff(x).unwrap();
                let want = partial.eval(&value).unwrap();
                prop_assert!((d.eps - want).abs() <= 1e-14 * scale(&partial, &value),
                    "d({e})/d{}: {} vs {want}", x.name(), d.eps);
                prop_assert!((d.re - e.eval(&value).unwrap()).abs() <= 1e-14 * scale(e, &value));
            }
        }
    }
}

#[test]
fn euler_equations_share_subexpressions_across_outputs() {
    let inputs = symbols(&INPUTS);
    let together = Tape::compile(general_euler(), &inputs).unwrap();
    let separate: usize = general_euler()
        .iter()
        .map(|e| {
            Tape::compile(std::slice::from_ref(e), &inputs)
                .unwrap()
                .instruction_count()
        })
        .sum();
    assert!(
        together.instruction_count() < separate,
        "{} instructions together, {separate} separately",
        together.instruction_count()
    );
    let loads = together
        .instructions()
        .iter()
        .filter(|i| matches!(i, Instruction::Input(_)))
        .count();
    assert_eq!(loads, inputs.len(), "each input is loaded exactly once");
    for (i, a) in together.instructions().iter().enumerate() {
        assert!(
            !together.instructions()[..i].contains(a),
            "instruction {i} ({a:?}) repeats an earlier one"
        );
    }
}

#[test]
fn principal_axes_drop_every_product_of_inertia() {
    let inputs = symbols(&INPUTS);
    let general = Tape::compile(general_euler(), &inputs).unwrap();
    let fixed: Vec<(Symbol, Q)> = symbols(&PRODUCTS_OF_INERTIA)
        .into_iter()
        .map(|s| (s, Q::ZERO))
        .collect();
    let principal = Tape::compile_with(general_euler(), &inputs, &fixed).unwrap();
    for (k, name) in INPUTS.iter().enumerate() {
        let is_product = PRODUCTS_OF_INERTIA.contains(name);
        assert_eq!(principal.reads_input(k), !is_product, "input {name}");
        assert!(general.reads_input(k), "general tape reads {name}");
    }
    assert!(principal.instruction_count() < general.instruction_count());
    // The pruned tape is the principal-axis form of the chapter, whatever the slots hold.
    let cyclic = rhs(&euler_equations(&InertiaTensor::principal()).unwrap());
    let point = [
        0.3, -1.2, 2.1, 0.7, -0.4, 1.9, 2.5, 1.5, 3.5, 9.0, -7.0, 5.0,
    ];
    let value = value_of(&inputs, &point);
    for (e, got) in cyclic.iter().zip(eval_f64(&principal, &point)) {
        let want = e.eval(&value).unwrap();
        assert!((got - want).abs() <= 1e-14 * scale(e, &value));
    }
}

/// Whether an instruction is of a given kind.
type IsKind = fn(&Instruction) -> bool;

#[test]
fn powers_and_functions_lower_to_the_intended_instructions() {
    let s = Expr::symbol;
    let (x, y) = (s("x"), s("y"));
    let half = Expr::rational(1, 2);
    let cases: Vec<(Expr, IsKind, IsKind)> = vec![
        (
            x.checked_pow(&half).unwrap(),
            |i| matches!(i, Instruction::Sqrt(_)),
            |i| matches!(i, Instruction::Powf(..)),
        ),
        (
            x.powi(-1) * &y,
            |i| matches!(i, Instruction::Div(..)),
            |i| matches!(i, Instruction::Powi(..) | Instruction::Powf(..)),
        ),
        (
            x.powi(6),
            |i| matches!(i, Instruction::Mul(..)),
            |i| matches!(i, Instruction::Powi(..)),
        ),
        (
            x.powi(40),
            |i| matches!(i, Instruction::Powi(_, 40)),
            |i| matches!(i, Instruction::Mul(..)),
        ),
        (
            x.checked_pow(&Expr::rational(1, 3)).unwrap(),
            |i| matches!(i, Instruction::Powf(..)),
            |i| matches!(i, Instruction::Sqrt(..)),
        ),
    ];
    let inputs = symbols(&["x", "y"]);
    for (e, wanted, unwanted) in cases {
        let tape = Tape::compile(std::slice::from_ref(&e), &inputs).unwrap();
        assert!(tape.instructions().iter().any(wanted), "{e}: {tape:?}");
        assert!(!tape.instructions().iter().any(unwanted), "{e}: {tape:?}");
    }
    // A product used once by a sum is fused into it: loads of x, y, z and one instruction.
    let z = s("z");
    let xyz = symbols(&["x", "y", "z"]);
    for (e, fused) in [
        (&x * &y + &z, Instruction::MulAdd(0, 1, 2)),
        (&z - &x * &y, Instruction::MulSub(0, 1, 2)),
    ] {
        let tape = Tape::compile(std::slice::from_ref(&e), &xyz).unwrap();
        assert_eq!(tape.instruction_count(), 4, "{e}: {tape:?}");
        assert_eq!(tape.instructions()[3], fused, "{e}");
    }
    // x^6 by squaring: x², x⁴ = (x²)², x⁶ = x⁴·x² — three multiplications.
    let sixth = Tape::compile(&[x.powi(6)], &inputs).unwrap();
    assert_eq!(sixth.instruction_count(), 4);
}

#[test]
fn powers_functions_and_rationals_agree_with_tree_walking() {
    let s = Expr::symbol;
    let (x, y, z) = (s("x"), s("y"), s("z"));
    let func = |name: &str, a: &Expr| {
        Expr::func(kinetics::algebra::Func::from_name(name).unwrap(), a.clone())
    };
    let outputs = vec![
        x.checked_pow(&Expr::rational(3, 2)).unwrap() + y.powi(-2) * &z,
        func("sin", &(&x * &y)) - func("cos", &z).powi(3) + func("tan", &(&y / &x)),
        func("abs", &(&z - &x)) * Expr::rational(1, 3) - x.powi(21) / Expr::int(7),
        y.checked_pow(&x).unwrap() + z.checked_pow(&Expr::rational(-5, 7)).unwrap(),
        -(&x * &y) / (&z * &z),
    ];
    let inputs = symbols(&["x", "y", "z"]);
    let tape = Tape::compile(&outputs, &inputs).unwrap();
    for point in [[0.3, 1.7, 2.9], [1.05, 0.4, 0.77], [0.9, 2.2, 1.3]] {
        let value = value_of(&inputs, &point);
        for (e, got) in outputs.iter().zip(eval_f64(&tape, &point)) {
            let want = e.eval(&value).unwrap();
            assert!(
                (got - want).abs() <= 1e-14 * scale(e, &value),
                "{e}: {got} vs {want}"
            );
        }
    }
}

fn reason(result: Result<Tape, NumericError>) -> String {
    result.unwrap_err().to_string()
}

#[test]
fn bad_input_is_an_error_naming_the_problem() {
    let mut inputs = symbols(&INPUTS);
    inputs.retain(|s| s.name() != "wdot_z");
    let missing = reason(Tape::compile(general_euler(), &inputs));
    assert!(missing.contains("wdot_z"), "{missing}");
    let twice = reason(Tape::compile(general_euler(), &symbols(&["w_x", "w_x"])));
    assert!(twice.contains("w_x") && twice.contains("twice"), "{twice}");
    assert!(Tape::compile(&[], &inputs).is_err());

    let x = Symbol::new("x");
    let reciprocal = Tape::compile(&[Expr::sym(x).powi(-1)], &[x]).unwrap();
    let mut out = [0.0];
    assert!(reciprocal.eval(&[0.0], &mut out).is_err(), "1/0 is refused");
    assert!(
        reciprocal.eval(&[f64::NAN], &mut out).is_err(),
        "NaN is refused"
    );
    assert!(
        reciprocal.eval(&[1.0, 2.0], &mut out).is_err(),
        "too many inputs"
    );
    assert!(
        reciprocal.eval(&[1.0], &mut []).is_err(),
        "no room for the output"
    );
    let singular = reciprocal.eval_batch(&[1.0, 2.0, 0.0, 4.0], 1).unwrap_err();
    assert!(
        singular.to_string().contains("parameter set 2"),
        "{singular}"
    );
    assert!(
        reciprocal.eval_batch(&[1.0, 2.0, 3.0], 2).is_err(),
        "ragged table"
    );
    assert!(reciprocal.eval_batch::<f64>(&[], 0).is_err(), "zero stride");

    let constant = Tape::compile_with(&[Expr::sym(x).powi(2)], &[], &[(x, Q::int(3))]).unwrap();
    constant.eval(&[], &mut out).unwrap();
    assert_eq!(out, [9.0], "a tape of no inputs");
    let fixed_zero = [(x, Q::ZERO)];
    let division = reason(Tape::compile_with(
        &[Expr::sym(x).powi(-1)],
        &[],
        &fixed_zero,
    ));
    assert!(division.contains("fixed"), "{division}");
}

#[test]
fn bearing_reaction_sweep_in_parallel_equals_serial() {
    let s = Expr::symbol;
    let d = bearing_reactions(
        &InertiaTensor::general(),
        &s("m"),
        (&s("xbar"), &s("ybar")),
        &s("l"),
        kinetics::Axis::Z,
    )
    .unwrap();
    let outputs = rhs(&d);
    let inputs = symbols(&[
        "w", "alpha", "I_xz", "I_yz", "m", "xbar", "ybar", "l", "unused",
    ]);
    let tape = Tape::compile(&outputs, &inputs).unwrap();
    let stride = inputs.len() + 1; // an extra column the tape must skip
    let sets = 2 * SETS_PER_TASK + 37;
    let table: Vec<f64> = (0..sets)
        .flat_map(|p| {
            let w = 0.1 + p as f64 * 0.01;
            [w, 0.5, 0.02, -0.03, 3.0, 0.001, -0.002, 0.4, f64::NAN, -1.0]
        })
        .collect();
    let parallel = tape.eval_batch(&table, stride).unwrap();
    let serial = tape.eval_batch_serial(&table, stride).unwrap();
    assert_eq!(parallel, serial);
    let mut scratch = Vec::new();
    let mut one = vec![0.0; tape.n_outputs()];
    for (p, row) in table.chunks(stride).enumerate() {
        tape.eval_with(&row[..inputs.len()], &mut one, &mut scratch)
            .unwrap();
        assert_eq!(&parallel[p * 4..p * 4 + 4], &one[..], "parameter set {p}");
    }
    // The sweep is physical: the ω² part of B_x grows with ω.
    assert!(parallel[4 * (sets - 1)].abs() > parallel[0].abs());
}

#[test]
fn factoring_recovers_the_structure_of_the_expanded_rate_of_angular_momentum() {
    use kinetics::algebra::Vector;
    use kinetics::mechanics::rotating_frame::rate_of_angular_momentum;
    let omega = body_angular_velocity();
    let v = |names: [&str; 3]| {
        Vector::new(
            Expr::symbol(names[0]),
            Expr::symbol(names[1]),
            Expr::symbol(names[2]),
        )
    };
    let alpha = v(["wdot_x", "wdot_y", "wdot_z"]);
    let frame = v(["Omega_x", "Omega_y", "Omega_z"]);
    let general = InertiaTensor::general();
    let expanded = rhs(&rate_of_angular_momentum(&general, &omega, &alpha, &frame, "G").unwrap());
    // The same vector as the chapter writes it, [I]ω̇ + Ω × ([I]ω), never expanded.
    let matrix = general.matrix();
    let factored: Vec<Expr> = (&matrix * &alpha + frame.cross(&(&matrix * &omega)))
        .iter()
        .cloned()
        .collect();
    let mut inputs: Vec<Symbol> = expanded.iter().flat_map(Expr::symbols).collect();
    inputs.sort();
    inputs.dedup();
    assert_eq!(inputs.len(), 15);
    let from_expanded = Tape::compile(&expanded, &inputs).unwrap();
    let from_factored = Tape::compile(&factored, &inputs).unwrap();
    assert!(
        from_expanded.instruction_count() <= from_factored.instruction_count(),
        "{} instructions from the expanded form, {} from the factored one",
        from_expanded.instruction_count(),
        from_factored.instruction_count()
    );
    let point: Vec<f64> = (0..15).map(|k| 0.25 + 0.37 * k as f64).collect();
    let value = value_of(&inputs, &point);
    for ((e, a), b) in expanded
        .iter()
        .zip(eval_f64(&from_expanded, &point))
        .zip(eval_f64(&from_factored, &point))
    {
        assert!((a - b).abs() <= 1e-14 * scale(e, &value), "{a} vs {b}");
    }
}
