//! The system allocator, counting per thread the bytes held (allocated minus freed) and the
//! highest count reached. The suite installs it as its global allocator (`main.rs`), so every
//! test runs on it and the memory tests read the counts of their own thread.
//!
//! The counts are per thread because the test harness and the other tests, each on threads
//! of their own, allocate at times of their choosing.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

pub struct Counting;

thread_local! {
    static HELD: Cell<isize> = const { Cell::new(0) };
    static PEAK: Cell<isize> = const { Cell::new(0) };
}

fn count(bytes: isize) {
    // Fails only while the thread is being torn down, after the test.
    let _ = HELD.try_with(|held| {
        let now = held.get() + bytes;
        held.set(now);
        let _ = PEAK.try_with(|peak| peak.set(peak.get().max(now)));
    });
}

/// The bytes this thread holds now.
pub fn held_bytes() -> isize {
    HELD.with(Cell::get)
}

/// The most bytes this thread held during `run` above those it held when `run` started.
pub fn peak_during(run: impl FnOnce()) -> isize {
    let base = held_bytes();
    PEAK.with(|peak| peak.set(base));
    run();
    PEAK.with(Cell::get) - base
}

// SAFETY: every call is forwarded unchanged to the system allocator; the counters only
// observe sizes (and do not allocate).
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count(layout.size() as isize);
        // SAFETY: forwarded with the caller's guarantees.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        count(-(layout.size() as isize));
        // SAFETY: forwarded with the caller's guarantees.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count(new_size as isize - layout.size() as isize);
        // SAFETY: forwarded with the caller's guarantees.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}
