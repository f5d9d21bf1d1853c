//! The committed `include/demcontact.h` must be exactly what cbindgen generates from the sources
//! (regenerate with `cargo run -p xtask -- header`).

use std::path::Path;

#[test]
fn header_is_fresh() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let fresh = xtask::header::generate(root).expect("cbindgen generates the header");
    assert!(
        xtask::stale(root, &[(xtask::HEADER, fresh)]).is_empty(),
        "include/demcontact.h is stale: regenerate with `cargo run -p xtask -- header` \
         (then `cargo run -p xtask -- bindings`) and commit"
    );
}

/// The files driven by the law registries (`demcontact::laws`: the C constants
/// `src/ffi/codes.rs`, the Python enums and stubs, the inline header's generated block, the
/// plugins' law table) must be what `xtask` generates from them.
#[test]
fn law_files_are_fresh() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = xtask::law_files(root).expect("xtask generates the law files");
    let stale = xtask::stale(root, &files);
    assert!(
        stale.is_empty(),
        "stale: {stale:?}: regenerate with `cargo run -p xtask -- all` and commit"
    );
}
