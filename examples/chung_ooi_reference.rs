//! Writes c_tests/data/chung_ooi_ref.csv: the reference outcomes of Chung & Ooi (2011) test 4
//! (oblique impact of a sphere on a rigid wall) from the independent integration in
//! tests/common/oblique.rs. Run from the repository root:
//! `cargo run --release --example chung_ooi_reference`. `cargo test --release --test chung_ooi`
//! fails when the committed file is stale.
#![allow(missing_docs)]

#[path = "../tests/common/oblique.rs"]
mod oblique;

fn main() {
    let rows = match oblique::reference_rows(1e-11) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("chung_ooi_reference: {e}");
            std::process::exit(1);
        }
    };
    let path = std::path::Path::new("c_tests/data/chung_ooi_ref.csv");
    if let Err(e) = std::fs::write(path, oblique::format_csv(&rows)) {
        eprintln!("chung_ooi_reference: writing {}: {e}", path.display());
        std::process::exit(1);
    }
    eprintln!("wrote {} ({} rows)", path.display(), rows.len());
}
