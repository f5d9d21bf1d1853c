//! `demcontact`: contact calibration for people preparing DEM input decks.
//!
//! ```text
//! demcontact builtin --code liggghts --model hertz --limit-force --e 0.5
//! demcontact contact --E1 7e10 --nu1 0.22 --rho1 2500 --R1 1e-3 --v 2 --e 0.5 [--wall]
//! demcontact fit data.csv [--tol 0.02] [--plot fit.png]
//! demcontact plan --E1 7e10 --nu1 0.22 --rho1 2500 --e 0.5 --R-min 1e-3 --R-max 2e-3 \
//!     --v-max 2 --depth 0.5 --overlap-tol 0.01 --e-tol 0.01
//! ```
//!
//! `--json` on every command prints one JSON object on stdout (errors too: `{"error": …}`).
//! Exit codes: 0 success; 1 the computation was refused (the library's status, e.g. a target the
//! builtin cannot realise); 2 bad command line (unknown option, a value that is not a number);
//! 3 bad input file (unreadable, or a CSV error reported as file:line:column); 4 the output file
//! (plot) could not be written.

mod builtin_cmd;
mod contact_cmd;
mod csv;
mod fit_cmd;
mod output;
mod plan_cmd;
mod plot;

use clap::{Parser, Subcommand};
use output::Failure;
use std::process::ExitCode;

/// Contact calibration for DEM input decks: corrected builtin inputs, one collision's
/// observables, fits to measured restitution.
#[derive(Parser, Debug)]
#[command(name = "demcontact", version, about, long_about = None)]
// A value may start with '-': `--E1 -7e10` or `--R1 -1e-3` reaches the library's range check,
// which names it, instead of clap's "unexpected argument '-7'" (clap's negative-number rule
// rejects exponents such as 1e-3, hence hyphen values; set on every subcommand below too).
#[command(allow_hyphen_values = true)]
#[command(
    after_help = "Exit codes: 0 ok, 1 refused by the library (e.g. target unreachable), \
2 bad command line, 3 bad input file (file:line:column), 4 output file not written."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// The value to type into a DEM code's builtin contact model for a target restitution.
    #[command(allow_hyphen_values = true)]
    Builtin(builtin_cmd::Args),
    /// α, δ_max, peak force, durations and a time step for one Hertz collision.
    #[command(allow_hyphen_values = true)]
    Contact(contact_cmd::Args),
    /// Fit measured restitution (CSV: v, e[, sigma]) with the viscoelastic and constant-e models.
    #[command(allow_hyphen_values = true)]
    Fit(fit_cmd::Args),
    /// The softest Young's modulus and the largest time step that meet a scene's tolerances.
    #[command(allow_hyphen_values = true)]
    Plan(plan_cmd::Args),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            // clap prints help/version with exit 0 and usage errors with exit 2.
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { 2 } else { 0 });
        }
    };
    let (json, result) = match &cli.command {
        Command::Builtin(a) => (a.json, builtin_cmd::run(a)),
        Command::Contact(a) => (a.json, contact_cmd::run(a)),
        Command::Fit(a) => (a.json, fit_cmd::run(a)),
        Command::Plan(a) => (a.json, plan_cmd::run(a)),
    };
    match result {
        Ok(out) => {
            if json {
                println!("{}", out.json);
            } else {
                print!("{}", out.text);
            }
            ExitCode::SUCCESS
        }
        Err(f) => {
            if json {
                println!("{}", f.to_json());
            }
            eprintln!("demcontact: error: {}", f.message);
            ExitCode::from(f.exit_code())
        }
    }
}

/// Shared by the subcommands: a library call's error as a [`Failure`] naming what was computed.
pub(crate) fn refused(what: &str, e: demcontact::Error) -> Failure {
    Failure::refused(format!("{what}: {}", output::describe(e)), e)
}
