//! The Fortran module, the C++ wrappers, the ABI probe files and docs/api.md are generated from
//! the committed `include/demcontact.h` by `xtask` (xtask/src/); this test regenerates them in
//! memory and compares with the committed files (regenerate: `cargo run -p xtask -- bindings`).

use std::path::Path;

fn header() -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(root.join(xtask::HEADER)).expect("read include/demcontact.h")
}

#[test]
fn generated_bindings_are_fresh() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = xtask::bindings(&header()).expect("the header parses");
    let stale = xtask::stale(root, &files);
    assert!(
        stale.is_empty(),
        "stale generated bindings {stale:?}: run `cargo run -p xtask -- bindings` and commit"
    );
}

#[test]
fn every_function_has_a_fortran_interface() {
    let api = xtask::cheader::parse(&header()).expect("the header parses");
    assert!(
        api.funcs.iter().any(|f| f.name == "dc_alpha_from_e"),
        "parser found no functions"
    );
    // Long interfaces are continued with `&`: join continuation lines before searching.
    let f90 = xtask::fortran::fortran(&api)
        .replace("&\n", " ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    for f in &api.funcs {
        assert!(
            f90.contains(&format!("name='{}')", f.name)),
            "{} missing",
            f.name
        );
    }
}
