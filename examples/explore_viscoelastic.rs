//! scratch
use demcontact::viscoelastic::reference::*;
use demcontact::viscoelastic::full_range::e_full;
use demcontact::EndCriterion;
fn main() {
    for &b in &[3.553e5, 3.0e5, 4.0e5, 1e5, 2e5] {
        let r: Vec<f64> = [1e-16, 1e-18, 1e-20].iter().map(|&t| e_reference_tol(b, EndCriterion::Force, t).unwrap()).collect();
        let f = e_full(b, EndCriterion::Force).unwrap();
        println!("b={b:e} ref(1e-16,1e-18,1e-20) rel to 1e-20: {:.1e} {:.1e}; full vs 1e-20 {:.1e}", r[0]/r[2]-1.0, r[1]/r[2]-1.0, f/r[2]-1.0);
    }
}
