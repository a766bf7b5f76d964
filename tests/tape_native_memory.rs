//! Dropping a [`NativeTape`] frees its machine code: a counting global allocator (the JIT
//! takes its code pages from the global allocator) sees the live heap return to the same
//! size after each compile–evaluate–drop cycle. Alone in its test binary so that no other
//! test allocates meanwhile.

use kinetics::algebra::{Expr, Func, Symbol};
use kinetics::numeric::Tape;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The system allocator, counting the bytes currently allocated.
struct Counting;

static LIVE_BYTES: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is forwarded unchanged to the system allocator; the counter only
// observes sizes.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        LIVE_BYTES.fetch_add(layout.size(), Ordering::SeqCst);
        // SAFETY: forwarded with the caller's guarantees.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE_BYTES.fetch_sub(layout.size(), Ordering::SeqCst);
        // SAFETY: forwarded with the caller's guarantees.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

#[test]
fn dropping_a_native_tape_frees_its_code() {
    let x = Symbol::new("x");
    let e = Expr::sym(x).powi(40) + Expr::func(Func::Sin, Expr::sym(x));
    let tape = Tape::compile(&[e], &[x]).unwrap();
    let mut out = [0.0];
    // The first compilation sets up the process-wide code generator; count after it.
    drop(tape.compile_native().unwrap());
    let before = LIVE_BYTES.load(Ordering::SeqCst);
    for _ in 0..100 {
        let compiled = tape.compile_native().unwrap();
        compiled.eval(&[1.01], &mut out).unwrap();
    }
    let after = LIVE_BYTES.load(Ordering::SeqCst);
    assert_eq!(
        after, before,
        "bytes still allocated after 100 tapes were dropped"
    );
    let mut interpreted = [0.0];
    tape.eval(&[1.01], &mut interpreted).unwrap();
    assert_eq!(out, interpreted);

    // The counter does see the JIT's memory: a live tape holds at least a page of code.
    let held = tape.compile_native().unwrap();
    let holding = LIVE_BYTES.load(Ordering::SeqCst) - after;
    assert!(holding >= 4096, "a live tape holds {holding} bytes");
    drop(held);
    assert_eq!(LIVE_BYTES.load(Ordering::SeqCst), after);
}
