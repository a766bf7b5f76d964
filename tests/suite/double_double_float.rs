//! `DoubleDouble` as a `num_traits::Float`: its elementary functions against exact rational
//! Taylor sums, identities, constants against published digits, the trait's limits and
//! conversions, exact evaluation of rational polynomials through `Expr::eval` and the tape,
//! and the double-double tape as an estimate of the f64 rounding error.

use kinetics::algebra::{rational_to, Expr, Func, Symbol, Q};
use kinetics::numeric::scalar::double_double::DoubleDouble;
use kinetics::numeric::{Instruction, Tape};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Float, FloatConst, Num, NumCast, One, Signed, ToPrimitive, Zero};
use proptest::prelude::*;
use std::num::FpCategory;

type Dd = DoubleDouble;

fn dd(x: f64) -> Dd {
    Dd::from_f64(x)
}

/// The exact value of a double-double.
fn exact(x: Dd) -> BigRational {
    BigRational::from_float(x.hi()).unwrap() + BigRational::from_float(x.lo()).unwrap()
}

fn exact_q(q: &Q) -> BigRational {
    let (n, d) = q.parts();
    BigRational::new(n, d)
}

/// `|a − b| / |b|` as an f64 (absolute when `b = 0`).
fn relative_error(a: &BigRational, b: &BigRational) -> f64 {
    let difference = (a - b).abs();
    let scale = if b.is_zero() {
        BigRational::one()
    } else {
        b.abs()
    };
    (difference / scale).to_f64().unwrap()
}

fn error_of(x: Dd, truth: &BigRational) -> f64 {
    relative_error(&exact(x), truth)
}

/// A decimal string as an exact rational.
fn decimal(text: &str) -> BigRational {
    exact_q(&Q::parse_decimal(text).unwrap())
}

/// Fraction bits of the fixed-point reference sums (each operation truncates by 2^-400).
const FRACTION_BITS: usize = 400;

/// `x·2^400` as an integer (every double-double in range is a multiple of 2^-400).
fn fixed(x: &BigRational) -> BigInt {
    let scaled = x * BigRational::from_integer(BigInt::from(1) << FRACTION_BITS);
    assert!(scaled.is_integer());
    scaled.to_integer()
}

fn unfixed(n: BigInt) -> BigRational {
    BigRational::new(n, BigInt::from(1) << FRACTION_BITS)
}

/// `Σ_{k<terms} ± x^(start + k·step)/(start + k·step)!` in 400-bit fixed point (error below
/// `terms·2^-398`): the Taylor sums of exp (`start 0, step 1`), sin (`1, 2`, alternating)
/// and cos (`0, 2`, alternating).
fn taylor(x: &BigRational, start: u32, step: u32, alternating: bool, terms: u32) -> BigRational {
    let x = fixed(x);
    let mut term = if start == 0 {
        BigInt::from(1) << FRACTION_BITS
    } else {
        x.clone()
    };
    let mut sum = BigInt::from(0);
    for k in 0..terms {
        sum += &term;
        let n = start + k * step;
        for j in 1..=step {
            term = ((&term * &x) >> FRACTION_BITS) / BigInt::from(n + j);
        }
        if alternating {
            term = -term;
        }
    }
    unfixed(sum)
}

/// Points in [−6.6, 6.6] that are not short binary fractions (so both parts are non-zero).
fn points() -> Vec<Dd> {
    (-40..=40)
        .filter(|&k| k != 0)
        .map(|k| dd(k as f64) / dd(6.1))
        .collect()
}

#[test]
fn exp_sin_and_cos_match_exact_taylor_sums() {
    // For |x| ≤ 6.6 the remainders after 100 terms of exp and 45 of sin, cos are below 1e-45.
    let mut worst: [f64; 3] = [0.0; 3];
    for x in points() {
        let q = exact(x);
        let (sin, cos) = x.sin_cos();
        let errors = [
            error_of(x.exp(), &taylor(&q, 0, 1, false, 100)),
            error_of(sin, &taylor(&q, 1, 2, true, 45)),
            error_of(cos, &taylor(&q, 0, 2, true, 45)),
        ];
        for (w, e) in worst.iter_mut().zip(errors) {
            *w = w.max(e);
        }
    }
    println!("largest relative errors of exp, sin, cos on [-6.6, 6.6]: {worst:?}");
    for e in worst {
        assert!(e < 1e-31, "{worst:?}");
    }
}

#[test]
fn exp_of_a_large_argument_matches_the_exact_power_of_e() {
    // e^(64x) = (e^x)^64, against the fixed-point Taylor sum of e^x raised to the 64th
    // power: 64x is exact, so this tests the range reduction k ln 2 at k = 106.
    let x = dd(7.0) / dd(6.1);
    let e_x = fixed(&taylor(&exact(x), 0, 1, false, 60));
    let power = unfixed((1..64).fold(e_x.clone(), |p, _| (&p * &e_x) >> FRACTION_BITS));
    let error = error_of(x.mul_f64(64.0).exp(), &power);
    println!("exp(64·7/6.1) relative error {error:e}");
    assert!(error < 1e-31, "{error:e}");
    // And the underflow side: e^(−64x) = 1/(e^x)^64.
    let error = relative_error(
        &exact(x.mul_f64(-64.0).exp()),
        &(BigRational::one() / power),
    );
    println!("exp(-64·7/6.1) relative error {error:e}");
    assert!(error < 1e-31, "{error:e}");
}

#[test]
fn reduction_of_large_angles_keeps_sin_and_cos_accurate() {
    // sin(x + 2πm) = sin x with 2πm formed in double-double: the only difference is the
    // rounding of x + 2πm, about |x + 2πm|·2^-106 absolute.
    for m in [1.0, 10.0, 1e3, 1e6, 1e15] {
        let x = dd(1.0) / dd(3.0);
        let shifted = x + Dd::TAU.mul_f64(m);
        let expected_error = (shifted.hi().abs() * 2f64.powi(-105)).max(1e-31);
        let (sin, cos) = shifted.sin_cos();
        let (sin0, cos0) = x.sin_cos();
        let ds = (sin - sin0).abs().to_f64();
        let dc = (cos - cos0).abs().to_f64();
        println!("m = {m:e}: |Δsin| {ds:e}, |Δcos| {dc:e}, bound {expected_error:e}");
        assert!(ds < 4.0 * expected_error && dc < 4.0 * expected_error);
    }
}

#[test]
fn atan_of_small_arguments_matches_its_exact_series() {
    // atan x = x − x³/3 + x⁵/5 − …; for |x| ≤ 1/8, 40 terms leave below 8^-80.
    for k in 1..=8 {
        let x = dd(k as f64) / dd(64.3);
        let q = exact(x);
        let mut truth = BigRational::zero();
        for n in 0..40u32 {
            let term = num_traits::pow(q.clone(), (2 * n + 1) as usize)
                / BigRational::from_integer(BigInt::from(2 * n + 1));
            truth = if n % 2 == 0 {
                truth + term
            } else {
                truth - term
            };
        }
        let error = error_of(x.atan(), &truth);
        assert!(
            error < 1e-31,
            "atan({}) relative error {error:e}",
            x.to_f64()
        );
        let error = error_of((-x).atan(), &-truth.clone());
        assert!(
            error < 1e-31,
            "atan(-{}) relative error {error:e}",
            x.to_f64()
        );
    }
}

#[test]
fn constants_match_published_digits() {
    // π and e to 40 digits (OEIS A000796, A001113); ln 2 (A002162), √2 (A002193).
    let published = [
        (Dd::PI, "3.141592653589793238462643383279502884197"),
        (Dd::E, "2.718281828459045235360287471352662497757"),
        (Dd::LN_2, "0.6931471805599453094172321214581765680755"),
        (Dd::SQRT_2, "1.414213562373095048801688724209698078570"),
        (
            <Dd as FloatConst>::PI(),
            "3.141592653589793238462643383279502884197",
        ),
    ];
    for (value, digits) in published {
        let error = error_of(value, &decimal(digits));
        assert!(
            error < 2f64.powi(-106),
            "{digits}: relative error {error:e}"
        );
    }
    // The functions reproduce them.
    let pairs = [
        (Dd::ONE.exp(), Dd::E),
        (dd(2.0).ln(), Dd::LN_2),
        (Dd::ONE.atan().mul_f64(4.0), Dd::PI),
        (dd(-1.0).acos(), Dd::PI),
        (dd(2.0).sqrt(), Dd::SQRT_2),
        (Dd::ONE.atan2(dd(0.0)), Dd::FRAC_PI_2),
        (dd(10.0).ln(), Dd::LN_10),
    ];
    for (computed, constant) in pairs {
        let error = error_of(computed, &exact(constant));
        assert!(error < 1e-31, "{computed:?} vs {constant:?}: {error:e}");
    }
}

#[test]
fn parsing_reads_32_digits() {
    let pi = Dd::from_str_radix("3.14159265358979323846264338327950288", 10).unwrap();
    assert!(error_of(pi, &decimal("3.14159265358979323846264338327950288")) < 1e-31);
    let tiny = Dd::from_str_radix("-1.25e-280", 10).unwrap();
    let error = error_of(-tiny, &decimal("1.25e-280"));
    // 10^282 by binary powering: about 2 log₂ 282 ≈ 16 roundings of 2^-106.
    println!("1.25e-280 read with relative error {error:e}");
    assert!(error < 16.0 * 2f64.powi(-106));
    assert_eq!(Dd::from_str_radix("ff.8", 16).unwrap(), dd(255.5));
    assert!(Dd::from_str_radix("inf", 10).unwrap().is_infinite());
    assert!(Dd::from_str_radix("1.2.3", 10).is_err());
    assert!(Dd::from_str_radix("", 10).is_err());
    assert!(Dd::from_str_radix("12", 1).is_err());
}

fn moderate() -> impl Strategy<Value = Dd> {
    (-1e3f64..1e3, -1.0f64..1.0).prop_map(|(a, b)| dd(a) + dd(b * a.abs() * 1e-17))
}

fn positive() -> impl Strategy<Value = Dd> {
    (-300f64..300.0, 1.0f64..2.0).prop_map(|(e, m)| dd(m).mul_f64(2f64.powf(e.round())) / dd(1.7))
}

fn close(a: Dd, b: Dd, tolerance: f64) -> bool {
    let scale = b.abs().to_f64().max(f64::MIN_POSITIVE);
    ((a - b).abs().to_f64() / scale) < tolerance
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn sine_and_cosine_are_on_the_unit_circle(x in moderate()) {
        let (s, c) = x.sin_cos();
        let defect = (s * s + c * c - Dd::ONE).abs().to_f64();
        prop_assert!(defect < 2e-31, "x = {x:?}: {defect:e}");
        prop_assert!((s.to_f64() - x.to_f64().sin()).abs() < 1e-12);
    }

    #[test]
    fn exp_inverts_ln_and_square_root_squares_back(x in positive()) {
        prop_assert!(close(x.ln().exp(), x, 2e-31 * (1.0 + x.ln().abs().to_f64())));
        let r = x.sqrt();
        prop_assert!(close(r * r, x, 1e-31));
        let c = x.cbrt();
        prop_assert!(close(c * c * c, x, 2e-31));
        prop_assert!(close(x.log2().exp2(), x, 2e-31 * (1.0 + x.log2().abs().to_f64())));
    }

    #[test]
    fn inverse_functions_invert(x in -0.99f64..0.99, y in -0.5f64..0.5) {
        let x = dd(x) / dd(1.01);
        prop_assert!(close(x.asin().sin(), x, 1e-30));
        prop_assert!(close(x.acos().cos(), x, 1e-30 / x.abs().to_f64().max(1e-3)));
        prop_assert!(close(x.atan().tan(), x, 1e-30));
        prop_assert!(close(x.atanh().tanh(), x, 1e-30));
        prop_assert!(close(x.asinh().sinh(), x, 1e-30));
        let z = dd(1.0) + dd(y).abs() * dd(7.0);
        prop_assert!(close(z.acosh().cosh(), z, 1e-30));
        // The small-argument forms agree with the direct ones.
        let small = dd(y) * dd(1e-3);
        prop_assert!(close(small.exp_m1() + Dd::ONE, small.exp(), 1e-31));
        prop_assert!(close(small.ln_1p().exp_m1(), small, 1e-30));
        // Second and third quadrants: sin of an angle near π is only absolutely accurate.
        let (px, py) = (dd(x.to_f64() - 2.0), dd(y));
        let angle = py.atan2(px);
        let rho = py.hypot(px);
        prop_assert!((angle.sin() * rho - py).abs().to_f64() < 1e-31 * rho.to_f64());
        prop_assert!((angle.cos() * rho - px).abs().to_f64() < 1e-31 * rho.to_f64());
    }

    #[test]
    fn powers_match_exact_rational_powers(x in (0.01f64..100.0).prop_map(|v| dd(v) / dd(1.7)), n in -20i32..20) {
        let q = exact(x);
        let truth = if n < 0 {
            BigRational::one() / num_traits::pow(q.clone(), n.unsigned_abs() as usize)
        } else {
            num_traits::pow(q.clone(), n as usize)
        };
        // Binary powering: a partial power's rounding is raised with it, so the relative
        // error grows like |n| roundings of about 2^-105.
        let bound_of_powi = (n.abs() as f64 + 2.0) * 2f64.powi(-105);
        prop_assert!(error_of(x.powi(n), &truth) < bound_of_powi);
        prop_assert!(error_of(x.powf(dd(n as f64)), &truth) < bound_of_powi);
        // A non-integer exponent: (x^(n/3))³ = xⁿ, through exp(y ln x).
        let third = x.powf(dd(n as f64) / dd(3.0));
        let bound = 2e-31 * (1.0 + (x.ln().to_f64() * n as f64).abs());
        prop_assert!(relative_error(&exact(third * third * third), &truth) < bound);
        prop_assert!(close(x.powf(dd(0.5)), x.sqrt(), 2e-31 * (1.0 + x.ln().abs().to_f64())));
    }

    #[test]
    fn integer_decode_rebuilds_the_value(x in moderate()) {
        let (mantissa, exponent, sign) = x.integer_decode();
        let rebuilt = BigRational::from_integer(BigInt::from(sign) * BigInt::from(mantissa))
            * num_traits::pow(BigRational::from_integer(2.into()), 1000)
            / num_traits::pow(BigRational::from_integer(2.into()), (1000 - exponent as i32) as usize);
        if !x.is_zero() {
            prop_assert!(relative_error(&rebuilt, &exact(x)) <= 2f64.powi(-64));
        }
    }
}

#[test]
fn limits_and_classification() {
    assert_eq!(Dd::epsilon().to_f64(), 2f64.powi(-104));
    let max = Dd::max_value();
    assert_eq!(max.to_f64(), f64::MAX);
    assert!(max.lo() > 0.0 && max.is_finite());
    assert!((max + max).is_infinite());
    assert_eq!(Dd::min_value(), -max);
    let min = Dd::min_positive_value();
    assert_eq!(min.classify(), FpCategory::Normal);
    assert_eq!((min / dd(2.0)).classify(), FpCategory::Subnormal);
    assert_eq!(Dd::zero().classify(), FpCategory::Zero);
    assert_eq!(Dd::nan().classify(), FpCategory::Nan);
    assert_eq!(Dd::infinity().classify(), FpCategory::Infinite);
    assert!(Dd::neg_zero().is_sign_negative() && Dd::neg_zero().is_zero());
    // Arithmetic keeps infinities and NaN as f64 does.
    assert_eq!(Dd::one() / Dd::zero(), Dd::infinity());
    assert!((Dd::zero() / Dd::zero()).is_nan());
    assert_eq!(Dd::infinity() + Dd::one(), Dd::infinity());
    assert_eq!(Dd::neg_infinity() * dd(2.0), Dd::neg_infinity());
    assert_eq!(Dd::one() / Dd::infinity(), Dd::zero());
    assert!((Dd::infinity() - Dd::infinity()).is_nan());
    assert_eq!(Dd::infinity().sqrt(), Dd::infinity());
    assert_eq!(dd(0.0).ln(), Dd::neg_infinity());
    assert!(dd(-1.0).ln().is_nan() && dd(-1.0).sqrt().is_nan() && dd(2.0).asin().is_nan());
    assert_eq!(dd(800.0).exp(), Dd::infinity());
    assert_eq!(dd(-800.0).exp(), Dd::zero());
    assert!(Dd::infinity().sin().is_nan());
    assert_eq!(Dd::ONE.atanh(), Dd::infinity());
    assert_eq!(Float::max(Dd::nan(), Dd::one()), Dd::one());
}

#[test]
fn rounding_and_remainder() {
    let just_below = dd(2.5) - dd(1e-20);
    assert_eq!(Float::round(just_below), dd(2.0));
    assert_eq!(Float::round(-just_below), dd(-2.0));
    assert_eq!(Float::round(dd(-2.5)), dd(-3.0));
    assert_eq!(Float::trunc(dd(-2.7)), dd(-2.0));
    assert_eq!(Float::ceil(just_below), dd(3.0));
    let third = dd(1.0) / dd(3.0);
    assert!(close(Float::fract(dd(7.0) + third), third, 1e-30));
    assert_eq!(dd(7.0) % dd(3.0), dd(1.0));
    assert_eq!(dd(-7.0) % dd(3.0), dd(-1.0));
    assert_eq!(dd(7.0) % dd(-3.0), dd(1.0));
    // 10 mod 2π with the quotient's rounding not spoiling the sign.
    let r = dd(10.0) % Dd::TAU;
    assert!(close(r, dd(10.0) - Dd::TAU, 1e-31));
    assert!((dd(1.0) % dd(0.0)).is_nan());
}

#[test]
fn conversions_are_exact_for_integers() {
    let big = (1i128 << 100) + 12345;
    let x: Dd = NumCast::from(big).unwrap();
    assert_eq!(x.to_i128(), Some(big));
    let u = u64::MAX;
    let y: Dd = NumCast::from(u).unwrap();
    assert_eq!(y.to_u64(), Some(u));
    assert_eq!(y.to_i64(), None);
    assert_eq!((-y).to_i128(), Some(-(u as i128)));
    assert_eq!(dd(-3.9).to_i64(), Some(-3));
    assert_eq!(Dd::nan().to_i64(), None);
    let z: Dd = NumCast::from(0.1f32).unwrap();
    assert_eq!(z.to_f64(), 0.1f32 as f64);
    assert_eq!(ToPrimitive::to_f64(&(dd(1.0) / dd(3.0))), Some(1.0 / 3.0));
}

/// Rational polynomials of three symbols with rational coefficients.
fn polynomials() -> Vec<Expr> {
    let [x, y, z] = ["x", "y", "z"].map(Expr::symbol);
    let q = |n, d| Expr::num(Q::new(n, d).unwrap());
    vec![
        q(1, 3) * x.powi(3) - q(7, 5) * &x * &y + q(2, 9) * z.powi(2) - q(5, 7),
        (&x - &y).powi(5) * q(3, 11) + (&y * &z - q(1, 7)).powi(3),
        (&x * &x + &y * &y + &z * &z) / (q(1, 1) + &x * &x) - q(13, 17) * &z,
        (&x + q(1, 2)).powi(-2) * (&y - q(4, 3)) + q(1, 13),
    ]
}

#[test]
fn rational_polynomials_evaluate_to_the_exact_rational() {
    let names = ["x", "y", "z"].map(Symbol::new);
    let mut worst: f64 = 0.0;
    for e in polynomials() {
        for (a, b, c) in [(1, 3, 5), (-2, 7, 9), (11, -13, 4), (5, 8, -1)] {
            let values = [
                Q::new(a, 7).unwrap(),
                Q::new(b, 11).unwrap(),
                Q::new(c, 3).unwrap(),
            ];
            let value_of = |s: Symbol| names.iter().position(|&n| n == s);
            let exact_value = e
                .subs(&|s| value_of(s).map(|k| Expr::num(values[k].clone())))
                .unwrap();
            let truth = exact_q(exact_value.as_num().unwrap());
            let inputs: Vec<Dd> = values.iter().map(rational_to).collect();
            let by_tree: Dd = e.eval(&|s| value_of(s).map(|k| inputs[k])).unwrap();
            let mut by_tape = [Dd::ZERO];
            Tape::compile(std::slice::from_ref(&e), &names)
                .unwrap()
                .eval(&inputs, &mut by_tape)
                .unwrap();
            // Rounding errors are relative to the terms, not to a cancelled total.
            let scale = e
                .terms()
                .iter()
                .map(|t| t.eval(&|s| value_of(s).map(|k| inputs[k])).unwrap().abs())
                .fold(Dd::ZERO, |a, b| a + b);
            for value in [by_tree, by_tape[0]] {
                let error = (exact(value) - &truth).abs().to_f64().unwrap() / scale.to_f64();
                worst = worst.max(error);
                assert!(error < 1e-30, "{e} at {values:?}: {error:e}");
            }
        }
    }
    println!(
        "largest error of the tree and the tape in DoubleDouble relative to the terms: {worst:e}"
    );
}

#[test]
fn the_tape_in_double_double_estimates_the_f64_error() {
    // H² − 2 I_y T = I_x (I_x − I_y) ω_x² + I_z (I_z − I_y) ω_z², written as the difference
    // of |H_G|² and 2 I_y T: it decides on which side of the separatrix a free body turns, and
    // cancels when I_x ≈ I_y ≈ I_z.
    let names = ["I_x", "I_y", "I_z", "w_x", "w_y", "w_z"];
    let [ix, iy, iz, wx, wy, wz] = names.map(Expr::symbol);
    let h2 = (&ix * &wx).powi(2) + (&iy * &wy).powi(2) + (&iz * &wz).powi(2);
    let t2 = &ix * wx.powi(2) + &iy * wy.powi(2) + &iz * wz.powi(2);
    let tape = Tape::compile(&[h2 - &iy * t2], &names.map(Symbol::new)).unwrap();
    let mut ratios = Vec::new();
    for k in 1..=20 {
        let k = k as f64;
        let inputs = [
            1.0 + 3e-9 * k,
            1.0 + 1.1e-9 * k,
            1.0 - 2.3e-9,
            0.7 + 0.013 * k,
            1.3 - 0.021 * k,
            0.9 + 0.017 * k,
        ];
        let truth = {
            let q: Vec<BigRational> = inputs
                .iter()
                .map(|&v| BigRational::from_float(v).unwrap())
                .collect();
            let h2 = (0..3)
                .map(|i| num_traits::pow(&q[i] * &q[i + 3], 2))
                .fold(BigRational::zero(), |a, b| a + b);
            let t2 = (0..3)
                .map(|i| &q[i] * &q[i + 3] * &q[i + 3])
                .fold(BigRational::zero(), |a, b| a + b);
            h2 - &q[1] * t2
        };
        let mut single = [0.0];
        tape.eval(&inputs, &mut single).unwrap();
        let mut double = [Dd::ZERO];
        tape.eval(&inputs.map(dd), &mut double).unwrap();
        let true_error = (BigRational::from_float(single[0]).unwrap() - &truth)
            .to_f64()
            .unwrap();
        let estimate = single[0] - double[0].to_f64();
        // Cancellation amplifies the f64 rounding far beyond 1e-16 relative.
        assert!(
            true_error.abs() > 1e-12 * truth.to_f64().unwrap().abs(),
            "{true_error:e}"
        );
        assert!(
            error_of(double[0], &truth) < 1e-20,
            "the double-double value is nearly exact"
        );
        ratios.push(estimate / true_error);
    }
    println!("estimated / true f64 error: {ratios:?}");
    for r in ratios {
        assert!((r - 1.0).abs() < 1e-6, "{r}");
    }
}

type Pair = (&'static str, fn(Dd) -> Dd, fn(f64) -> f64);

#[test]
fn special_and_extreme_arguments_behave_as_in_f64() {
    let functions: [Pair; 22] = [
        ("sqrt", Float::sqrt, f64::sqrt),
        ("cbrt", Float::cbrt, f64::cbrt),
        ("exp", Float::exp, f64::exp),
        ("exp2", Float::exp2, f64::exp2),
        ("exp_m1", Float::exp_m1, f64::exp_m1),
        ("ln", Float::ln, f64::ln),
        ("log2", Float::log2, f64::log2),
        ("log10", Float::log10, f64::log10),
        ("ln_1p", Float::ln_1p, f64::ln_1p),
        ("sin", Float::sin, f64::sin),
        ("cos", Float::cos, f64::cos),
        ("tan", Float::tan, f64::tan),
        ("asin", Float::asin, f64::asin),
        ("acos", Float::acos, f64::acos),
        ("atan", Float::atan, f64::atan),
        ("sinh", Float::sinh, f64::sinh),
        ("cosh", Float::cosh, f64::cosh),
        ("tanh", Float::tanh, f64::tanh),
        ("asinh", Float::asinh, f64::asinh),
        ("acosh", Float::acosh, f64::acosh),
        ("atanh", Float::atanh, f64::atanh),
        ("abs", Float::abs, f64::abs),
    ];
    let arguments = [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.0,
        -0.0,
        1.0,
        -1.0,
        2.0,
        -2.0,
        0.5,
        -0.7,
        1e-300,
        -1e-300,
        1e300,
        -1e300,
        800.0,
        -800.0,
    ];
    for (name, double_double, float) in functions {
        for x in arguments {
            let (d, f) = (double_double(dd(x)), float(x));
            let what = format!("{name}({x:e}) = {d:?}, f64 says {f:e}");
            assert_eq!(d.is_nan(), f.is_nan(), "{what}");
            if f.is_infinite() || f == 0.0 {
                assert_eq!(d.to_f64(), f, "{what}");
            } else if !f.is_nan() {
                assert!(((d.to_f64() - f) / f).abs() < 1e-14, "{what}");
            }
        }
    }
}

#[test]
fn the_tape_runs_its_elementary_instructions_in_double_double() {
    // Outputs that use Sin, Cos, Tan, Sqrt and Powf; identities check them to ~1e-31.
    let x = Expr::symbol("x");
    let (sin, cos, tan) = (
        Expr::func(Func::Sin, x.clone()),
        Expr::func(Func::Cos, x.clone()),
        Expr::func(Func::Tan, x.clone()),
    );
    let outputs = [
        sin.powi(2) + cos.powi(2),
        tan * &cos - &sin,
        x.checked_pow(&Expr::rational(1, 2)).unwrap(),
        x.checked_pow(&Expr::rational(1, 3)).unwrap(),
    ];
    let tape = Tape::compile(&outputs, &[Symbol::new("x")]).unwrap();
    let uses = |wanted: fn(&Instruction) -> bool| tape.instructions().iter().any(wanted);
    assert!(
        uses(|i| matches!(i, Instruction::Sin(_))) && uses(|i| matches!(i, Instruction::Tan(_)))
    );
    assert!(
        uses(|i| matches!(i, Instruction::Sqrt(_))) && uses(|i| matches!(i, Instruction::Powf(..)))
    );
    for k in 1..=30 {
        let x = dd(k as f64) / dd(3.7);
        let mut out = [Dd::ZERO; 4];
        tape.eval(&[x], &mut out).unwrap();
        assert!((out[0] - Dd::ONE).abs().to_f64() < 2e-31, "{out:?}");
        assert!(
            (out[1]).abs().to_f64() < 1e-31 * (1.0 + x.tan().abs().to_f64()),
            "{out:?}"
        );
        assert!(close(out[2] * out[2], x, 1e-31));
        assert!(close(out[3] * out[3] * out[3], x, 2e-31));
    }
}
