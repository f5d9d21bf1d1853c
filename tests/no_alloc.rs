//! Proves that no exported function allocates on the heap: a counting global allocator is armed
//! around calls to every `dc_*` export, on valid and invalid inputs, and must count zero.
//! Runs without the test harness so that no other thread allocates while the counter is armed.

use demcontact::ffi::{calibration::*, status::*, timestep::*, version::*};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

struct Counting;
static ARMED: AtomicBool = AtomicBool::new(false);
static COUNT: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if ARMED.load(Ordering::SeqCst) {
            COUNT.fetch_add(1, Ordering::SeqCst);
        }
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if ARMED.load(Ordering::SeqCst) {
            COUNT.fetch_add(1, Ordering::SeqCst);
        }
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn counted<F: FnOnce()>(f: F) -> usize {
    COUNT.store(0, Ordering::SeqCst);
    ARMED.store(true, Ordering::SeqCst);
    f();
    ARMED.store(false, Ordering::SeqCst);
    COUNT.load(Ordering::SeqCst)
}

fn main() {
    // The counter must be able to fail: a Box allocates.
    let control = counted(|| {
        let b = std::hint::black_box(Box::new(42u64));
        drop(b);
    });
    assert_eq!(control, 1, "the counting allocator does not see allocations");

    let inputs = [-1.0, 0.0, 1e-300, 1e-6, 0.3, 0.5, 1.0, 1.5, 2.0, 7.0, 1e300, f64::NAN, f64::INFINITY];
    let n = counted(|| {
        let mut out = 0.0f64;
        for &a in &inputs {
            for &b in &inputs {
                for crit in [DC_END_OVERLAP, DC_END_FORCE, 7] {
                    unsafe {
                        std::hint::black_box(dc_alpha_from_e(a, b, crit, &mut out));
                        std::hint::black_box(dc_e_from_alpha(a, b, crit, &mut out));
                        std::hint::black_box(dc_alpha_from_e(a, b, crit, std::ptr::null_mut()));
                    }
                }
                for &c in &inputs {
                    unsafe {
                        std::hint::black_box(dc_dt_crit(a, b, c, &mut out));
                    }
                }
            }
        }
        for s in [DC_OK, DC_ERR_NULL_POINTER, DC_ERR_INTERNAL, -5, 123456] {
            std::hint::black_box(dc_status_str(s));
        }
        std::hint::black_box(dc_version());
    });
    assert_eq!(n, 0, "exported functions allocated {n} times");
    println!("no_alloc: 1 passed, 0 failed");
}
