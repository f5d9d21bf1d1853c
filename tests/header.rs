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
