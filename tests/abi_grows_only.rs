//! The C ABI only grows: every constant (name and value), struct (field names, types and order)
//! and function (parameter and return types) of the pre-issue-16 header, listed in
//! `tests/data/abi_v0.txt`, must still be in `include/demcontact.h` unchanged. New symbols are
//! fine; a `#define X 6101` that became an enum constant `X = 6101` is the same symbol.

use std::path::Path;

#[test]
fn header_keeps_every_v0_symbol() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |p: &str| std::fs::read_to_string(root.join(p)).expect(p);
    let api = xtask::cheader::parse(&read(xtask::HEADER)).expect("the header parses");
    let now = xtask::abi::symbols(&api);
    let baseline = read("tests/data/abi_v0.txt");
    assert!(
        baseline.lines().filter(|l| l.starts_with("fn ")).count() >= 38,
        "abi_v0.txt lost functions"
    );
    let broken = xtask::abi::removed_or_changed(&baseline, &now);
    assert!(
        broken.is_empty(),
        "the header removed or changed {} symbol(s) of the published ABI (only additions are \
         allowed):\n{}",
        broken.len(),
        broken.join("\n")
    );
}
