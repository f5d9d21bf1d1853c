//! Regenerates the full-range table with the committed generator and compares it with the
//! committed `src/viscoelastic/table.rs` (through the crate's own constants).
//! Run: `cargo test --release --test viscoelastic_table_regen -- --nocapture` (about a second).
#![allow(clippy::unwrap_used, clippy::indexing_slicing, dead_code)]

#[path = "../examples/gen_viscoelastic_table.rs"]
mod generator;

use demcontact::EndCriterion;
use demcontact::viscoelastic::full_range::{asymptotic_constants, table_pieces};

#[test]
fn committed_table_matches_regeneration() {
    let mut worst: f64 = 0.0;
    let mut n = 0;
    for c in [EndCriterion::Force, EndCriterion::Overlap] {
        let (w, bin) = table_pieces(c);
        let gw = generator::w_pieces(c);
        let nb = if c == EndCriterion::Force {
            generator::FORCE_BINADES
        } else {
            generator::OVERLAP_BINADES
        };
        let gb = generator::binade_pieces(c, nb);
        assert_eq!(w.len(), gw.len());
        assert_eq!(bin.len(), gb.len());
        for (a, g) in w.iter().chain(bin.iter()).zip(gw.iter().chain(gb.iter())) {
            assert_eq!(a.len(), g.len());
            // Coefficients relative to the piece's scale |c0| (the function's size there).
            let scale = g[0].abs();
            for (x, y) in a.iter().zip(g.iter()) {
                worst = worst.max((x - y).abs() / scale);
                n += 1;
            }
        }
    }
    let (co, cf, p, d) = asymptotic_constants();
    let (gcf, gp, gd) = generator::c_force();
    let gco = generator::c_overlap();
    println!(
        "regenerated {n} coefficients: worst difference {worst:.1e} (relative to piece scale)"
    );
    println!("C_O {co} vs {gco}; C_F {cf} vs {gcf}; P {p} vs {gp}; D {d} vs {gd}");
    // Same code on the same platform gives identical bits; another libm may move the last bits.
    assert!(
        worst < 1e-13,
        "table is stale: regenerate with cargo run --release --example gen_viscoelastic_table"
    );
    assert!(((co - gco) / co).abs() < 1e-14 && ((cf - gcf) / cf).abs() < 1e-12);
    assert!(((p - gp) / p).abs() < 1e-8 && ((d - gd) / d).abs() < 1e-6);
}
