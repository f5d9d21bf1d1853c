//! Build script: SONAME for the shared library.
// Gives the shared library a proper SONAME (libdemcontact.so.<major>) so that installed copies
// version like any system library. Only affects the cdylib link.
fn main() {
    let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_else(|_| "0".into());
    let target_os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if target_os == "linux" {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libdemcontact.so.{major}");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
