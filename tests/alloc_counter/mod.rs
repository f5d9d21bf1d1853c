//! A counting global allocator for tests that prove "no heap allocation".
//!
//! Counts per thread (a `const`-initialised thread-local, which itself never allocates), so tests
//! can run in the ordinary parallel harness: each test counts only what its own thread allocates.
//! A test file opts in with
//! ```ignore
//! mod alloc_counter;
//! #[global_allocator]
//! static ALLOC: alloc_counter::Counting = alloc_counter::Counting;
//! ```
#![allow(dead_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

thread_local! {
    static ARMED: Cell<bool> = const { Cell::new(false) };
    static COUNT: Cell<usize> = const { Cell::new(0) };
}

/// Forwards to the system allocator and counts allocations on armed threads.
pub struct Counting;

fn note() {
    // try_with: during thread teardown the locals may be gone; never panic inside the allocator.
    let armed = ARMED.try_with(|a| a.get()).unwrap_or(false);
    if armed {
        let _ = COUNT.try_with(|c| c.set(c.get() + 1));
    }
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        note();
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        note();
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        note();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

/// Runs `f` and returns how many heap allocations this thread made meanwhile.
pub fn count_allocations<F: FnOnce()>(f: F) -> usize {
    COUNT.with(|c| c.set(0));
    ARMED.with(|a| a.set(true));
    f();
    ARMED.with(|a| a.set(false));
    COUNT.with(|c| c.get())
}

/// The counter must be able to fail: a Box allocation is seen. Call from every no-alloc test file.
pub fn assert_counter_works() {
    let n = count_allocations(|| drop(std::hint::black_box(Box::new(7u64))));
    assert_eq!(n, 1, "the counting allocator does not see allocations");
}
