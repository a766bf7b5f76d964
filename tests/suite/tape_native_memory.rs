//! Dropping a [`NativeTape`] frees its machine code: the suite's counting global allocator
//! (`main.rs`; the JIT takes its code pages from the global allocator) sees the bytes the test's thread holds
//! return to the same count after each compile–evaluate–drop cycle. The count is per
//! thread because the test harness's own thread allocates at times of its choosing.
//! Needs the `jit` feature.
#![cfg(feature = "jit")]

use crate::common::counting_allocator::held_bytes;
use kinetics::algebra::{Expr, Func, Symbol};
use kinetics::numeric::Tape;

#[test]
fn dropping_a_native_tape_frees_its_code() {
    let x = Symbol::new("x");
    let e = Expr::sym(x).powi(40) + Expr::func(Func::Sin, Expr::sym(x));
    let tape = Tape::compile(&[e], &[x]).unwrap();
    let mut out = [0.0];
    // The first compilation sets up the process-wide code generator; count after it.
    drop(tape.compile_native().unwrap());
    let before = held_bytes();
    for _ in 0..100 {
        let compiled = tape.compile_native().unwrap();
        compiled.eval(&[1.01], &mut out).unwrap();
    }
    let after = held_bytes();
    assert_eq!(
        after, before,
        "bytes still allocated after 100 tapes were dropped"
    );
    let mut interpreted = [0.0];
    tape.eval(&[1.01], &mut interpreted).unwrap();
    assert_eq!(out, interpreted);

    // The counter does see the JIT's memory: a live tape holds at least a page of code.
    let held = tape.compile_native().unwrap();
    let holding = held_bytes() - after;
    assert!(holding >= 4096, "a live tape holds {holding} bytes");
    drop(held);
    assert_eq!(held_bytes(), after);
}
