//! scratch
use demcontact::viscoelastic::reference::*;
fn main() {
    for k in [20, 22, 23, 24] {
        for tol in [1e-14, 1e-16, 1e-18] {
        let b = 2f64.powi(k);
        let o = integrate(b, Event::Force, tol, 50_000_000);
        let m = integrate(b, Event::MaxCompression, tol, 50_000_000);
        println!("2^{k} tol {tol:e} {:?} \n   max {:?}", o, m);
        }
    }
}
