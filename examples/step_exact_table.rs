//! The realised-e table of docs/timestep.md ("The step-aware model in the library"): sphere–wall
//! collisions through `contact_force`, plain and step-aware (`set_step`), Hertz, p = 1 and p = 2,
//! e_n 0.1–0.95, both criteria, impact speeds 0.01, 1 and 10 m/s, dt = t_H/10, /20, /50, /100,
//! 64 onset phases, velocity Verlet (LAMMPS order) and symplectic Euler. Each cell: the mean
//! over phases (signed, the largest magnitude over speeds and integrators) / the worst single
//! phase, both in % of e_n. The claims are asserted by tests/step_exact.rs.
//!
//!     cargo run --profile ci --example step_exact_table

#[path = "step_exact/harness.rs"]
mod harness;

use demcontact::contact::contact_model;
use demcontact::contact::step_exact::set_step;
use harness::{Law, spec, stat, t_h};

fn main() {
    let steps = [10.0, 20.0, 50.0, 100.0];
    print!("| law | criterion | e_n |");
    for n in steps {
        print!(" t_H/{n} plain | t_H/{n} step-aware |");
    }
    println!();
    println!("|---|---|---|{}", "---|---|".repeat(steps.len()));
    let mut worst_vv_se: f64 = 0.0;
    for law in [Law::Hertz, Law::Linear, Law::P2] {
        for crit in [0, 1] {
            for e in [0.1, 0.3, 0.5, 0.7, 0.9, 0.95] {
                let plain = contact_model(&spec(law, e, crit)).expect("model");
                let name = match law {
                    Law::Hertz => "Hertz",
                    Law::Linear => "p = 1",
                    Law::P2 => "p = 2",
                };
                let c = if crit == 0 { "overlap" } else { "force" };
                print!("| {name} | {c} | {e} |");
                for n in steps {
                    let (mut pm, mut pw, mut sm, mut sw) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
                    for v0 in [0.01, 1.0, 10.0] {
                        let dt = t_h(law, v0) / n;
                        let stepped = set_step(&plain, dt, 0).expect("set_step");
                        let mut means = [0.0; 2];
                        for (i, verlet) in [true, false].into_iter().enumerate() {
                            let p = stat(&plain, law, e, v0, n, verlet);
                            let s = stat(&stepped, law, e, v0, n, verlet);
                            if p.mean.abs() > pm.abs() {
                                pm = p.mean;
                            }
                            if s.mean.abs() > sm.abs() {
                                sm = s.mean;
                            }
                            pw = pw.max(p.worst);
                            sw = sw.max(s.worst);
                            means[i] = s.mean;
                        }
                        worst_vv_se = worst_vv_se.max((means[0] - means[1]).abs() * e);
                    }
                    print!(
                        " {:+.3} / {:.3} | {:+.3} / {:.3} |",
                        pm * 100.0,
                        pw * 100.0,
                        sm * 100.0,
                        sw * 100.0
                    );
                }
                println!();
            }
        }
    }
    println!();
    println!(
        "largest |mean e (velocity Verlet) - mean e (symplectic Euler)|, step-aware: {worst_vv_se:.1e}"
    );
}
