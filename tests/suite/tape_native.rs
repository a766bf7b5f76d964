//! The tape compiled to machine code (`Tape::compile_native`) against the interpreter
//! (`Tape::eval`), which it must match bit for bit: every instruction kind, the general Euler
//! equations in a rotating frame at random points (also against tree-walking `Expr::eval`),
//! bad lengths, non-finite outputs, tapes without inputs or with constant outputs, a tape
//! hundreds of instructions deep, the parallel batch, sharing between threads, and many tapes compiled and dropped.
//! Needs the `jit` feature.
#![cfg(feature = "jit")]

use kinetics::algebra::{Expr, Func, Symbol, Vector, Q};
use kinetics::mechanics::euler::body_angular_velocity;
use kinetics::mechanics::inertia::InertiaTensor;
use kinetics::mechanics::rotating_frame::rate_of_angular_momentum;
use kinetics::numeric::tape::batch::SETS_PER_TASK;
use kinetics::numeric::{Instruction, NativeTape, NumericError, Tape};
use proptest::prelude::*;
use std::sync::OnceLock;

fn symbols(names: &[&str]) -> Vec<Symbol> {
    names.iter().map(|n| Symbol::new(n)).collect()
}

/// One evaluation: the outputs, or the error.
fn interpreted(tape: &Tape, inputs: &[f64]) -> Result<Vec<f64>, NumericError> {
    let mut out = vec![0.0; tape.n_outputs()];
    tape.eval(inputs, &mut out).map(|()| out)
}

fn native(tape: &NativeTape, inputs: &[f64]) -> Result<Vec<f64>, NumericError> {
    let mut out = vec![0.0; tape.n_outputs()];
    tape.eval(inputs, &mut out).map(|()| out)
}

/// The same result, comparing values by their bits (so `-0.0` differs from `0.0`).
fn assert_identical(
    got: Result<Vec<f64>, NumericError>,
    want: Result<Vec<f64>, NumericError>,
    at: &[f64],
) {
    let bits = |r: Result<Vec<f64>, NumericError>| {
        r.map(|v| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>())
    };
    assert_eq!(bits(got), bits(want), "at {at:?}");
}

/// Outputs exercising every instruction kind, of inputs x, y, z.
fn every_kind() -> Vec<Expr> {
    let s = Expr::symbol;
    let (x, y, z) = (s("x"), s("y"), s("z"));
    let f = |func: Func, a: Expr| Expr::func(func, a);
    vec![
        x.checked_pow(&Expr::rational(3, 2)).unwrap() + y.powi(-2) * &z,
        f(Func::Sin, &x * &y) - f(Func::Cos, z.clone()).powi(3) + f(Func::Tan, &y / &x),
        f(Func::Abs, &z - &x) * Expr::rational(1, 3) - x.powi(21) / Expr::int(7)
            + f(Func::Acos, &x / Expr::int(3))
            + f(Func::Atan, &y * &z),
        y.checked_pow(&x).unwrap() + z.checked_pow(&Expr::rational(-5, 7)).unwrap(),
        -(&x * &y) / (&z * &z),
        &x * &y + &z,
        &z - &x * &y,
        -(&x + &z),
    ]
}

/// A deterministic spread of points in [-3, 3)³ (a linear congruential sequence), with
/// the special values a tape must handle alike: zeros of both signs, a NaN, infinities.
fn points(count: usize) -> Vec<[f64; 3]> {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        -3.0 + 6.0 * (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut all: Vec<[f64; 3]> = (0..count).map(|_| [next(), next(), next()]).collect();
    all.extend([
        [0.0, 1.0, 2.0],
        [-0.0, 1.0, 2.0],
        [1.0, 0.0, -0.0],
        [f64::NAN, 1.0, 1.0],
        [f64::INFINITY, 1.0, 1.0],
        [0.5, f64::NEG_INFINITY, 2.0],
    ]);
    all
}

/// Whether an instruction is of a given kind.
type IsKind = fn(&Instruction) -> bool;

#[test]
fn every_instruction_kind_matches_the_interpreter_bit_for_bit() {
    let tape = Tape::compile(&every_kind(), &symbols(&["x", "y", "z"])).unwrap();
    use Instruction::*;
    let kinds: [(&str, IsKind); 17] = [
        ("Input", |i| matches!(i, Input(_))),
        ("Const", |i| matches!(i, Const(_))),
        ("Add", |i| matches!(i, Add(..))),
        ("Sub", |i| matches!(i, Sub(..))),
        ("Mul", |i| matches!(i, Mul(..))),
        ("Div", |i| matches!(i, Div(..))),
        ("Neg", |i| matches!(i, Neg(_))),
        ("Powi", |i| matches!(i, Powi(..))),
        ("Sqrt", |i| matches!(i, Sqrt(_))),
        ("Acos", |i| matches!(i, Acos(_))),
        ("Powf", |i| matches!(i, Powf(..))),
        ("MulAdd", |i| matches!(i, MulAdd(..))),
        ("MulSub", |i| matches!(i, MulSub(..))),
        ("Sin", |i| matches!(i, Sin(_))),
        ("Cos", |i| matches!(i, Cos(_))),
        ("Tan", |i| matches!(i, Tan(_))),
        ("Abs", |i| matches!(i, Abs(_))),
    ];
    for (name, is_kind) in kinds {
        assert!(
            tape.instructions().iter().any(is_kind),
            "the tape lacks {name}"
        );
    }
    let compiled = tape.compile_native().unwrap();
    let (mut finite, mut refused) = (0, 0);
    for point in points(2000) {
        let want = interpreted(&tape, &point);
        match want {
            Ok(_) => finite += 1,
            Err(_) => refused += 1,
        }
        assert_identical(native(&compiled, &point), want, &point);
    }
    // Both branches were exercised: most points are finite, the special ones are not.
    assert!(
        finite > 100 && refused >= 3,
        "{finite} finite, {refused} refused"
    );
}

/// The general Euler equations in a frame rotating at Ω: `[I]ω̇ + Ω × ([I]ω)`, 15 inputs.
fn rotating_frame_euler() -> &'static (Vec<Expr>, Vec<Symbol>, Tape, NativeTape) {
    static E: OnceLock<(Vec<Expr>, Vec<Symbol>, Tape, NativeTape)> = OnceLock::new();
    E.get_or_init(|| {
        let vector =
            |[a, b, c]: [&str; 3]| Vector::new(Expr::symbol(a), Expr::symbol(b), Expr::symbol(c));
        let derivation = rate_of_angular_momentum(
            &InertiaTensor::general(),
            &body_angular_velocity(),
            &vector(["wdot_x", "wdot_y", "wdot_z"]),
            &vector(["Omega_x", "Omega_y", "Omega_z"]),
            "G",
        )
        .unwrap();
        let outputs: Vec<Expr> = derivation.result().iter().map(|r| r.rhs.clone()).collect();
        let mut inputs: Vec<Symbol> = outputs.iter().flat_map(Expr::symbols).collect();
        inputs.sort();
        inputs.dedup();
        let tape = Tape::compile(&outputs, &inputs).unwrap();
        let compiled = tape.compile_native().unwrap();
        (outputs, inputs, tape, compiled)
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn general_euler_matches_the_interpreter_and_tree_walking(
        v in prop::collection::vec(-3.0f64..3.0, 15)
    ) {
        let (outputs, inputs, tape, compiled) = rotating_frame_euler();
        prop_assert_eq!(inputs.len(), 15);
        let got = native(compiled, &v).unwrap();
        let want = interpreted(tape, &v).unwrap();
        prop_assert_eq!(
            got.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            want.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
        let value = |s: Symbol| inputs.iter().position(|&i| i == s).map(|k| v[k]);
        for (e, g) in outputs.iter().zip(&got) {
            let exact = e.eval(&value).unwrap();
            // Rounding errors are relative to the sum of the terms' magnitudes.
            let scale: f64 = e.terms().iter().map(|t| t.eval(&value).unwrap().abs()).sum();
            prop_assert!((g - exact).abs() <= 1e-14 * scale, "{}: {} vs {}", e, g, exact);
        }
    }
}

#[test]
fn wrong_lengths_are_refused_before_the_call() {
    let tape = Tape::compile(&every_kind(), &symbols(&["x", "y", "z"])).unwrap();
    let compiled = tape.compile_native().unwrap();
    assert_eq!((compiled.n_inputs(), compiled.n_outputs()), (3, 8));
    let mut out = [7.0; 8];
    for inputs in [&[1.0, 2.0][..], &[1.0, 2.0, 3.0, 4.0], &[]] {
        let error = compiled.eval(inputs, &mut out).unwrap_err();
        assert_eq!(error, tape.eval(inputs, &mut out).unwrap_err());
        assert!(error.to_string().contains("tape inputs"), "{error}");
    }
    for len in [0, 7, 9] {
        let mut wrong = vec![7.0; len];
        let error = compiled.eval(&[1.0, 2.0, 3.0], &mut wrong).unwrap_err();
        assert!(error.to_string().contains("tape outputs"), "{error}");
        assert!(wrong.iter().all(|&x| x == 7.0), "nothing was written");
    }
    assert_eq!(out, [7.0; 8], "nothing was written");
}

#[test]
fn non_finite_outputs_are_refused_like_the_interpreter() {
    let x = Symbol::new("x");
    let tape = Tape::compile(&[Expr::int(1), Expr::sym(x).powi(-1)], &[x]).unwrap();
    let compiled = tape.compile_native().unwrap();
    for (input, what) in [(0.0, "infinite"), (f64::NAN, "NaN"), (-0.0, "infinite")] {
        let error = native(&compiled, &[input]).unwrap_err();
        assert_eq!(error, interpreted(&tape, &[input]).unwrap_err());
        let message = error.to_string();
        assert!(
            message.contains("output 1 of parameter set 0") && message.contains(what),
            "{message}"
        );
    }
    assert_eq!(native(&compiled, &[4.0]).unwrap(), [1.0, 0.25]);
}

#[test]
fn tapes_of_no_inputs_and_constant_outputs() {
    let x = Symbol::new("x");
    let y = Symbol::new("y");
    let nine = Tape::compile_with(&[Expr::sym(x).powi(2)], &[], &[(x, Q::int(3))]).unwrap();
    let compiled = nine.compile_native().unwrap();
    assert_eq!(compiled.n_inputs(), 0);
    assert_eq!(native(&compiled, &[]).unwrap(), [9.0]);
    assert!(
        compiled.eval(&[1.0], &mut [0.0]).is_err(),
        "no inputs expected"
    );

    // A constant output beside one of the inputs, and an input the tape never reads.
    let outputs = [Expr::rational(1, 3), Expr::sym(y) * Expr::int(2)];
    let tape = Tape::compile(&outputs, &[x, y]).unwrap();
    assert!(!tape.reads_input(0));
    let compiled = tape.compile_native().unwrap();
    let got = native(&compiled, &[f64::NAN, 1.5]).unwrap();
    assert_eq!(got, [1.0 / 3.0, 3.0]);
    assert_identical(Ok(got), interpreted(&tape, &[f64::NAN, 1.5]), &[]);
}

/// A polynomial in nested (Horner) form, `x(1/2 + x(1/3 + x(…)))`, which the canonical
/// form keeps nested: a tape one multiply-add deeper per level, 500 deep. (A polynomial
/// written out is not deep: the builder factors it and combines the parts shallowest
/// first. Much deeper nesting overflows a test thread's stack in the algebra's own
/// recursive comparisons before a tape exists; parsed input is kept to 200 levels.)
#[test]
fn a_deep_tape_matches_the_interpreter() {
    let x = Expr::symbol("x");
    let levels = 500;
    let polynomial = (2..=levels)
        .rev()
        .fold(Expr::one(), |inner, k| &x * (Expr::rational(1, k) + inner));
    let tape = Tape::compile(&[polynomial], &symbols(&["x"])).unwrap();
    // The longest chain of instructions each reading the one before.
    let mut depth: Vec<usize> = Vec::with_capacity(tape.instruction_count());
    for &instruction in tape.instructions() {
        use Instruction::*;
        let operands: Vec<u32> = match instruction {
            Input(_) | Const(_) => vec![],
            Neg(a)
            | Powi(a, _)
            | Sqrt(a)
            | Sin(a)
            | Cos(a)
            | Tan(a)
            | Abs(a)
            | Acos(a)
            | Atan(a) => {
                vec![a]
            }
            Add(a, b) | Sub(a, b) | Mul(a, b) | Div(a, b) | Powf(a, b) => vec![a, b],
            MulAdd(a, b, c) | MulSub(a, b, c) => vec![a, b, c],
        };
        depth.push(
            1 + operands
                .iter()
                .map(|&r| depth[r as usize])
                .max()
                .unwrap_or(0),
        );
    }
    let deepest = depth.iter().max().copied().unwrap_or(0);
    assert!(
        deepest >= levels as usize,
        "the tape is {deepest} instructions deep"
    );
    let compiled = tape.compile_native().unwrap();
    for at in [0.0, 0.5, -0.75, 0.999] {
        assert_identical(native(&compiled, &[at]), interpreted(&tape, &[at]), &[at]);
    }
}

#[test]
fn batch_matches_single_evaluations_and_the_interpreters_batch() {
    let tape = Tape::compile(&every_kind(), &symbols(&["x", "y", "z"])).unwrap();
    let compiled = tape.compile_native().unwrap();
    let stride = 4; // an extra column the tape must skip
    let sets = 2 * SETS_PER_TASK + 37;
    let table: Vec<f64> = (0..sets)
        .flat_map(|p| {
            let t = p as f64 / sets as f64;
            [0.5 + t, 1.5 - t, 0.25 + 2.0 * t, f64::NAN]
        })
        .collect();
    let batch = compiled.eval_batch(&table, stride).unwrap();
    assert_eq!(batch.len(), sets * 8);
    let interpreted_batch = tape.eval_batch(&table, stride).unwrap();
    assert_identical(Ok(batch.clone()), Ok(interpreted_batch), &[]);
    for (p, row) in table.chunks(stride).enumerate() {
        assert_identical(
            Ok(batch[p * 8..(p + 1) * 8].to_vec()),
            native(&compiled, &row[..3]),
            row,
        );
    }

    // A singular row is named; malformed tables are refused.
    let mut singular = table.clone();
    singular[(SETS_PER_TASK + 5) * stride] = f64::NAN;
    let error = compiled.eval_batch(&singular, stride).unwrap_err();
    let set = format!("parameter set {}", SETS_PER_TASK + 5);
    assert!(error.to_string().contains(&set), "{error}");
    assert!(compiled.eval_batch(&table[1..], stride).is_err(), "ragged");
    assert!(compiled.eval_batch(&table, 2).is_err(), "stride < inputs");
    assert!(compiled.eval_batch(&[], 0).is_err(), "zero stride");
    assert_eq!(compiled.eval_batch(&[], stride).unwrap(), Vec::<f64>::new());
}

#[test]
fn one_compiled_tape_serves_many_threads() {
    let (_, _, tape, compiled) = rotating_frame_euler();
    std::thread::scope(|scope| {
        for t in 0..4 {
            scope.spawn(move || {
                for k in 0..500 {
                    let v: Vec<f64> = (0..15)
                        .map(|i| ((t * 500 + k + i) % 17) as f64 - 8.0)
                        .collect();
                    assert_identical(native(compiled, &v), interpreted(tape, &v), &v);
                }
            });
        }
    });
}

#[test]
fn many_tapes_compile_evaluate_and_drop() {
    let x = Symbol::new("x");
    for n in 1..=300 {
        // A different tape each time: x^n + sin(x) (a multiplication chain, or powi above 16).
        let e = Expr::sym(x).powi(n) + Expr::func(Func::Sin, Expr::sym(x));
        let tape = Tape::compile(&[e], &[x]).unwrap();
        let compiled = tape.compile_native().unwrap();
        assert_identical(native(&compiled, &[1.01]), interpreted(&tape, &[1.01]), &[]);
    }
}
