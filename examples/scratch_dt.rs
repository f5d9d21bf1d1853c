use demcontact::force::powerlaw::powerlaw;
use demcontact::timestep::*;
use demcontact::EndCriterion;
fn main() {
    let t = std::time::Instant::now();
    for crit in [EndCriterion::Overlap, EndCriterion::Force] {
        for &p in &[1.0, 1.5, 2.0, 3.0] {
            for &e in &[0.1, 0.5, 0.9] {
                for &tol in &[1e-2, 1e-3, 1e-4] {
                    let t1 = std::time::Instant::now();
                    let dt = dt_for_accuracy(p, e, crit, 1.0, 1.0, tol).unwrap();
                    let pair = powerlaw(p, 1.0, e, crit).unwrap();
                    let tau = collide(&pair, 1.0, 1.0, 1.0, 1e-3, 0.5, Scheme::VelocityVerlet, 10_000_000).unwrap().duration;
                    let el = t1.elapsed(); let a = worst_restitution_error(&pair, e, tau, dt, 211) / tol;
                    let b = worst_restitution_error(&pair, e, tau, 2.0 * dt, 211) / tol;
                    println!("{crit:?} p={p} e={e} tol={tol}: dt/tau={:.3e} E101/tol={a:.3} E(2dt)/tol={b:.3} {:?}", dt / tau, el);
                }
            }
        }
    }
    println!("total {:?}", t.elapsed());
}
