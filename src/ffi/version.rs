//! Library version.

use core::ffi::c_char;

const VERSION: &str = concat!(env!("CARGO_PKG_VERSION"), "\0");

/// The library version as a static NUL-terminated string, e.g. "0.1.0"; never NULL, never freed.
#[unsafe(no_mangle)]
pub extern "C" fn dc_version() -> *const c_char {
    VERSION.as_ptr().cast()
}

/// The batches' vector flavour: baseline x86-64 (SSE2; every other architecture's default).
pub const DC_DISPATCH_BASELINE: i32 = 0;
/// The batches' vector flavour: AVX2 + FMA.
pub const DC_DISPATCH_AVX2: i32 = 1;
/// The batches' vector flavour: AVX-512F.
pub const DC_DISPATCH_AVX512: i32 = 2;

/// The vector flavour the batch functions run in this process (DC_DISPATCH_*): the widest the
/// CPU has, capped by the environment variable DEMCONTACT_DISPATCH=baseline or =avx2 (read once,
/// at the first call; any other value caps nothing; to measure or test the narrower flavours).
/// Every flavour gives the same bits.
#[unsafe(no_mangle)]
pub extern "C" fn dc_dispatch_level() -> i32 {
    crate::numerics::simd::level() as i32
}
