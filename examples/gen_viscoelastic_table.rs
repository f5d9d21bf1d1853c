//! Generates `src/viscoelastic/table.rs`: the piecewise Chebyshev coefficients of the full-range
//! tier, sampled from the project's reference integrator (`viscoelastic::reference`).
//!
//! Run: `cargo run --release --example gen_viscoelastic_table` (about a second). The test
//! `tests/viscoelastic_table_regen.rs` includes this file, regenerates every coefficient and
//! compares with the committed table.
//!
//! Layout (must match `src/viscoelastic/full_range.rs`):
//! * small b, 0 ≤ b < 1: `W_PIECES` pieces uniform in w = √b ∈ [0, 1) (e is analytic in √b, not
//!   in b, under the force criterion); piece i covers w ∈ [i/W, (i+1)/W).
//! * 1 ≤ b < 2^n: binades [2^j, 2^(j+1)), each cut into `sub_pieces` equal parts of the mantissa
//!   m ∈ [1, 2) of b; n = `FORCE_BINADES` (force) or `OVERLAP_BINADES` (overlap).
//! * beyond: the asymptotic laws e = C_O b^-5 (overlap, exact up to exponentially small terms)
//!   and e = C_F b^(-5/3) (force), constants computed here.
//!
//! Every piece approximates e itself (overlap binades: e·b^5) with `DEG` Chebyshev coefficients (first-kind nodes).
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    dead_code
)]

use demcontact::EndCriterion;
use demcontact::viscoelastic::reference::e_reference;
use std::fmt::Write;

/// Chebyshev coefficients per piece.
pub const DEG: usize = 20;
/// Pieces in w = √b over [0, 1).
pub const W_PIECES: usize = 4;
/// Binades [2^j, 2^(j+1)) covered by the force table (b up to 2^20 ≈ 1.05e6).
pub const FORCE_BINADES: usize = 20;
/// Binades covered by the overlap table (b up to 2^3 = 8).
pub const OVERLAP_BINADES: usize = 3;
/// Sub-pieces per binade, uniform in the mantissa: force 1, overlap 4 (e b^5 approaches C_O
/// faster than any power of 1/b, which needs short pieces).
pub fn sub_pieces(c: EndCriterion) -> usize {
    match c {
        EndCriterion::Force => 1,
        EndCriterion::Overlap => 4,
    }
}

/// Chebyshev coefficients of f on [-1, 1] from DEG first-kind nodes.
pub fn chebyshev(f: impl Fn(f64) -> f64) -> [f64; DEG] {
    let n = DEG as f64;
    let vals: Vec<f64> = (0..DEG)
        .map(|j| f((std::f64::consts::PI * (j as f64 + 0.5) / n).cos()))
        .collect();
    let mut c = [0.0; DEG];
    for (k, ck) in c.iter_mut().enumerate() {
        let s: f64 = vals
            .iter()
            .enumerate()
            .map(|(j, v)| v * (std::f64::consts::PI * k as f64 * (j as f64 + 0.5) / n).cos())
            .sum();
        *ck = 2.0 * s / n;
    }
    c[0] *= 0.5;
    c
}

fn e_ref(b: f64, c: EndCriterion) -> f64 {
    e_reference(b, c).expect("reference integrates")
}

/// The w-pieces of one criterion.
pub fn w_pieces(c: EndCriterion) -> Vec<[f64; DEG]> {
    (0..W_PIECES)
        .map(|i| {
            chebyshev(|x| {
                let w = (i as f64 + 0.5 * (x + 1.0)) / W_PIECES as f64;
                e_ref(w * w, c)
            })
        })
        .collect()
}

/// The binade pieces of one criterion.
pub fn binade_pieces(c: EndCriterion, n: usize) -> Vec<[f64; DEG]> {
    let sub = sub_pieces(c);
    (0..n * sub)
        .map(|i| {
            let (j, k) = (i / sub, i % sub);
            chebyshev(move |x| {
                // mantissa m in [1 + k/sub, 1 + (k+1)/sub)
                let m = 1.0 + (k as f64 + 0.5 * (x + 1.0)) / sub as f64;
                let b = (2f64).powi(j as i32) * m;
                // Overlap: e b^5 tends to C_O, smooth and O(1); force: e itself.
                match c {
                    EndCriterion::Overlap => e_ref(b, c) * b.powi(5),
                    EndCriterion::Force => e_ref(b, c),
                }
            })
        })
        .collect()
}

/// C_O = lim e_O b^5 (reached to 1e-16 relative from b ≈ 8 on), evaluated at b = 16.
pub fn c_overlap() -> f64 {
    e_ref(16.0, EndCriterion::Overlap) * 16f64.powi(5)
}

/// C_F = lim e_F b^(5/3) = (3/2)^(2/3) (docs/viscoelastic.md: damping-dominated loading reaches
/// X_max = (3/(2b))^(2/3), and the force vanishes on the slow manifold X' = −X/b). The correction
/// e_F b^(5/3) = C_F (1 − D b^(−P)) is fitted to the reference at b = 2^18 and 2^20.
/// Returns (C_F, P, D).
pub fn c_force() -> (f64, f64, f64) {
    let cf = 1.5f64.powf(2.0 / 3.0);
    let defect = |b: f64| 1.0 - e_ref(b, EndCriterion::Force) * b.powf(5.0 / 3.0) / cf;
    let (b1, b2) = (2f64.powi(18), 2f64.powi(20));
    let (d1, d2) = (defect(b1), defect(b2));
    let p = (d1 / d2).ln() / (b2 / b1).ln();
    (cf, p, d2 * b2.powf(p))
}

fn write_array(out: &mut String, name: &str, doc: &str, rows: &[[f64; DEG]]) {
    writeln!(out, "/// {doc}").unwrap();
    writeln!(
        out,
        "pub(crate) static {name}: [[f64; DEG]; {}] = [",
        rows.len()
    )
    .unwrap();
    for r in rows {
        write!(out, "    [").unwrap();
        for (k, v) in r.iter().enumerate() {
            if k % 4 == 0 {
                write!(out, "\n        ").unwrap();
            }
            write!(out, "{v:e}, ").unwrap();
        }
        writeln!(out, "\n    ],").unwrap();
    }
    writeln!(out, "];").unwrap();
}

/// The whole generated source file.
pub fn generate() -> String {
    let mut o = String::new();
    o += "//! GENERATED by `cargo run --release --example gen_viscoelastic_table` from the reference\n";
    o += "//! integrator; do not edit. `tests/viscoelastic_table_regen.rs` regenerates and compares.\n";
    o += "#![allow(clippy::unreadable_literal, clippy::excessive_precision)]\n\n";
    writeln!(
        o,
        "/// Chebyshev coefficients per piece.\npub(crate) const DEG: usize = {DEG};"
    )
    .unwrap();
    writeln!(o, "/// Pieces uniform in w = sqrt(b) over [0, 1).\npub(crate) const W_PIECES: usize = {W_PIECES};").unwrap();
    writeln!(o, "/// Binades [2^j, 2^(j+1)) tabulated for the force criterion.\npub(crate) const FORCE_BINADES: usize = {FORCE_BINADES};").unwrap();
    writeln!(o, "/// Binades tabulated for the overlap criterion.\npub(crate) const OVERLAP_BINADES: usize = {OVERLAP_BINADES};").unwrap();
    writeln!(
        o,
        "/// Sub-pieces per binade (force).\npub(crate) const FORCE_SUB: usize = {};",
        sub_pieces(EndCriterion::Force)
    )
    .unwrap();
    writeln!(
        o,
        "/// Sub-pieces per binade (overlap).\npub(crate) const OVERLAP_SUB: usize = {};",
        sub_pieces(EndCriterion::Overlap)
    )
    .unwrap();
    let co = c_overlap();
    writeln!(
        o,
        "/// lim e_O b^5 (overlap criterion, b >= 8).\npub(crate) const C_OVERLAP: f64 = {co:e};"
    )
    .unwrap();
    let (cf, p, d) = c_force();
    writeln!(o, "/// lim e_F b^(5/3) = (3/2)^(2/3) (force criterion).\npub(crate) const C_FORCE: f64 = {cf:e};").unwrap();
    writeln!(o, "/// Measured correction e_F b^(5/3) = C_F (1 - D b^-P) beyond the table: P.\npub(crate) const FORCE_CORR_P: f64 = {p:e};").unwrap();
    writeln!(
        o,
        "/// ... and D.\npub(crate) const FORCE_CORR_D: f64 = {d:e};"
    )
    .unwrap();
    o += "\n";
    write_array(
        &mut o,
        "FORCE_W",
        "Force criterion, w = sqrt(b) pieces.",
        &w_pieces(EndCriterion::Force),
    );
    write_array(
        &mut o,
        "OVERLAP_W",
        "Overlap criterion, w = sqrt(b) pieces.",
        &w_pieces(EndCriterion::Overlap),
    );
    write_array(
        &mut o,
        "FORCE_B",
        "Force criterion, binade pieces.",
        &binade_pieces(EndCriterion::Force, FORCE_BINADES),
    );
    write_array(
        &mut o,
        "OVERLAP_B",
        "Overlap criterion, binade pieces of e*b^5.",
        &binade_pieces(EndCriterion::Overlap, OVERLAP_BINADES),
    );
    o
}

fn main() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/viscoelastic/table.rs");
    if std::env::args().any(|a| a == "--tails") {
        for c in [EndCriterion::Force, EndCriterion::Overlap] {
            for (i, p) in w_pieces(c).iter().enumerate() {
                println!("{c:?} w{i}: tail {:.1e} {:.1e}", p[DEG - 2], p[DEG - 1]);
            }
            let n = if c == EndCriterion::Force {
                FORCE_BINADES
            } else {
                OVERLAP_BINADES
            };
            for (j, p) in binade_pieces(c, n).iter().enumerate() {
                println!(
                    "{c:?} piece {j}: tail {:.1e} {:.1e}  c0 {:.3e}",
                    p[DEG - 2],
                    p[DEG - 1],
                    p[0]
                );
            }
        }
        println!("C_O {:.17e}  C_F {:?}", c_overlap(), c_force());
        return;
    }
    std::fs::write(&path, generate()).expect("write table.rs");
    println!("wrote {}", path.display());
}
