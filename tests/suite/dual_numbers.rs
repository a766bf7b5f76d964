//! Evaluation is generic over the scalar: f32, f64 and dual numbers, whose derivative part
//! must equal the value of the symbolic partial derivative.

use kinetics::algebra::{Expr, Symbol};
use kinetics::numeric::Dual;
use kinetics::parse::parse_expression;

type Dual64 = Dual<f64>;

fn kinetic_energy() -> Expr {
    parse_expression(
        "T",
        "1/2 m v^2 + 1/2 (I_x w_x^2 + I_y w_y^2 - 2 I_xy w_x w_y) + sin(w_x) cos(w_y) + sqrt(I_x)",
    )
    .unwrap()
}

fn value_of(name: Symbol) -> f64 {
    match name.name() {
        "m" => 2.0,
        "v" => 1.5,
        "I_x" => 3.0,
        "I_y" => 4.0,
        "I_xy" => 0.5,
        "w_x" => 0.7,
        "w_y" => -1.2,
        other => panic!("no value for {other}"),
    }
}

#[test]
fn dual_numbers_give_the_symbolic_partial_derivatives() {
    let t = kinetic_energy();
    for wrt in ["w_x", "w_y", "I_x", "m"] {
        let x = Symbol::new(wrt);
        let dual: Dual64 = t
            .eval(&|s| {
                let v = value_of(s);
                Some(if s == x {
                    Dual64::variable(v)
                } else {
                    Dual64::constant(v)
                })
            })
            .unwrap();
        let symbolic: f64 = t.diff(x).unwrap().eval(&|s| Some(value_of(s))).unwrap();
        assert!(
            (dual.eps - symbolic).abs() < 1e-12,
            "d/d{wrt}: {} vs {symbolic}",
            dual.eps
        );
        let plain: f64 = t.eval(&|s| Some(value_of(s))).unwrap();
        assert!((dual.re - plain).abs() < 1e-12);
    }
}

#[test]
fn f32_and_f64_agree_to_single_precision() {
    let t = kinetic_energy();
    let single: f32 = t.eval(&|s| Some(value_of(s) as f32)).unwrap();
    let double: f64 = t.eval(&|s| Some(value_of(s))).unwrap();
    assert!(((single as f64) - double).abs() < 1e-5 * double.abs());
}

#[test]
fn non_finite_results_are_errors() {
    let e = parse_expression("e", "1/x").unwrap();
    assert!(e.eval(&|_| Some(0.0f64)).is_err());
    assert!(e.eval::<f64>(&|_| None).is_err());
}
