//! The series tier (paper's coefficients as printed) against the reference: where it stays
//! within 1e-3 and 1e-6, and how its error grows.
//! Run: `cargo test --release --test viscoelastic_series -- --nocapture`.
#![allow(clippy::unwrap_used)]

use demcontact::EndCriterion::{Force, Overlap};
use demcontact::viscoelastic::reference::e_reference;
use demcontact::viscoelastic::series::e_series;

#[test]
fn series_validity_range() {
    for c in [Force, Overlap] {
        // Scan b upward; the validity limit is the first b where the error exceeds the level.
        let (mut lim6, mut lim3) = (None, None);
        let mut table = Vec::new();
        let mut b: f64 = 1e-3;
        while b < 2.0 {
            let r = e_reference(b, c).unwrap();
            let s = e_series(b, c).unwrap();
            let err = (s - r).abs();
            if err > 1e-6 && lim6.is_none() {
                lim6 = Some(b);
            }
            if err > 1e-3 && lim3.is_none() {
                lim3 = Some(b);
            }
            for &p in &[0.01, 0.03, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5] {
                if (b / p - 1.0).abs() < 0.0051 {
                    table.push((b, r, s, err));
                }
            }
            b *= 1.01;
        }
        println!(
            "{c:?}: |series − reference| exceeds 1e-6 from b = {:.3}, 1e-3 from b = {:.3}",
            lim6.unwrap(),
            lim3.unwrap()
        );
        for (b, r, s, err) in table {
            println!("   b = {b:.3}: reference {r:.12}, series {s:.12}, error {err:.1e}");
        }
        // Small b: the series (and its 8-digit coefficients) agree to the coefficients' precision.
        let err_small = (e_series(0.01, c).unwrap() - e_reference(0.01, c).unwrap()).abs();
        assert!(err_small < 1e-10, "{err_small}");
        let (l6, l3) = (lim6.unwrap(), lim3.unwrap());
        match c {
            Force => assert!(l6 > 0.4 && l6 < 0.6 && l3 > 0.65 && l3 < 0.9, "{l6} {l3}"),
            Overlap => assert!(l6 > 0.35 && l6 < 0.5 && l3 > 0.7 && l3 < 0.9, "{l6} {l3}"),
        }
    }
}
