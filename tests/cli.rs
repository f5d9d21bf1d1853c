//! The `demcontact` command-line tool, run as a user runs it (the built binary): every
//! subcommand, text and `--json` (parsed back and compared with the library), the bad-input paths
//! with their exit codes (1 refused, 2 bad command line, 3 bad input file, 4 output not written)
//! and the file:line:column of CSV errors.
#![cfg(feature = "cli")]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::indexing_slicing)]

use demcontact::builtin::{Builtin, value_for_e};
use demcontact::viscoelastic::full_range::e_full;
use demcontact::{EndCriterion, powerlaw};
use serde_json::Value;
use std::path::PathBuf;
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_demcontact"))
        .args(args)
        .output()
        .expect("runs")
}

fn json_of(o: &Output) -> Value {
    serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(&o.stdout)))
}

fn tmp(name: &str, content: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("dc_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, content).unwrap();
    p
}

#[test]
fn builtin_text_and_json() {
    let o = run(&[
        "builtin",
        "--code",
        "liggghts",
        "--model",
        "hertz",
        "--limit-force",
        "--e",
        "0.5",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.contains("coefficientRestitution peratomtypepair 1 0.43628"),
        "{text}"
    );
    assert!(text.contains("limitForce on"), "{text}");
    let o = run(&[
        "builtin",
        "--code",
        "liggghts",
        "--model",
        "hertz",
        "--limit-force",
        "--e",
        "0.5",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let j = json_of(&o);
    let want = value_for_e(Builtin::LiggghtsHertz, true, 0.5).unwrap();
    assert_eq!(j["value"].as_f64().unwrap(), want);
    assert!((j["uncorrected_realised_e"].as_f64().unwrap() - 0.5503).abs() < 5e-4);
    // every model of every code answers
    for (code, model, extra) in [
        ("liggghts", "hooke", ""),
        ("lammps", "coeff-restitution", "--limit-damping"),
        ("lammps", "tsuji", ""),
        ("yade", "viscel", ""),
        ("yade", "mindlin-en", ""),
        ("yade", "mindlin-betan", ""),
    ] {
        let mut a = vec![
            "builtin", "--code", code, "--model", model, "--e", "0.6", "--json",
        ];
        if !extra.is_empty() {
            a.push(extra);
        }
        let o = run(&a);
        assert_eq!(o.status.code(), Some(0), "{code} {model}");
        assert!(json_of(&o)["value"].as_f64().unwrap() > 0.0);
    }
    let o = run(&[
        "builtin",
        "--code",
        "yade",
        "--model",
        "viscel-cn",
        "--e",
        "0.5",
        "--kn",
        "1e5",
        "--mass",
        "2e-3",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let cn = json_of(&o)["value"].as_f64().unwrap();
    assert_eq!(
        cn,
        demcontact::builtin::yade::viscel_cn(0.5, 1e5, 2e-3).unwrap()
    );
}

#[test]
fn builtin_wall() {
    // YADE viscel against a wall: another value, the library's, and the uncorrected en's
    // realised e against the wall (0.3 typed realises 0.4025 there, see tests/builtin_vs_ode.rs).
    let args = |e: &'static str, wall: bool| {
        let mut a = vec![
            "builtin", "--code", "yade", "--model", "viscel", "--e", e, "--json",
        ];
        if wall {
            a.push("--wall");
        }
        a
    };
    let o = run(&args("0.3", true));
    assert_eq!(o.status.code(), Some(0));
    let j = json_of(&o);
    assert_eq!(j["wall"].as_bool(), Some(true));
    let want =
        demcontact::builtin::value_for_e_wall(Builtin::YadeViscElEn, true, true, 0.3).unwrap();
    // serde_json's default float parser may be 1 ulp off the printed shortest representation
    assert!((j["value"].as_f64().unwrap() - want).abs() <= 2.0 * f64::EPSILON * want);
    let pair = json_of(&run(&args("0.3", false)))["value"]
        .as_f64()
        .unwrap();
    assert!(want < pair - 0.05, "wall {want} particle {pair}");
    let o = run(&[
        "builtin", "--code", "yade", "--model", "viscel", "--e", "0.3", "--wall",
    ]);
    assert!(String::from_utf8_lossy(&o.stdout).contains("against a wall"));
    // below exp(-π/2) against a wall: refused, exit 1, naming the range
    let o = run(&args("0.2", true));
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json_of(&o)["error"]["status"].as_i64(), Some(6131));
    assert!(String::from_utf8_lossy(&o.stderr).contains("0.2079"));
    // reachable between particles
    assert_eq!(run(&args("0.2", false)).status.code(), Some(0));
    // the wall does not change Mindlin's value
    let m = |wall: bool| {
        let mut a = vec![
            "builtin",
            "--code",
            "yade",
            "--model",
            "mindlin-en",
            "--e",
            "0.5",
            "--json",
        ];
        if wall {
            a.push("--wall");
        }
        json_of(&run(&a))["value"].as_f64().unwrap()
    };
    assert_eq!(m(true), m(false));
}

#[test]
fn builtin_lammps_release() {
    // The release decides damping tsuji's eta: the value realises the target in that release's
    // formula (checked against an independent integration in tests/builtin_vs_ode.rs), and the
    // two releases' values differ.
    // The corrected value and model code for `extra` arguments (a --version, or none).
    let value_of = |extra: &[&str]| {
        let mut args = vec![
            "builtin",
            "--code",
            "lammps",
            "--model",
            "tsuji",
            "--limit-damping",
            "--e",
            "0.5",
            "--json",
        ];
        args.extend_from_slice(extra);
        let o = run(&args);
        assert_eq!(o.status.code(), Some(0), "{extra:?}");
        let j = json_of(&o);
        (j["model_code"].as_i64(), j["value"].as_f64().unwrap())
    };
    let new = value_for_e(Builtin::LammpsTsujiHertzSqrt2, true, 0.5).unwrap();
    let old = value_for_e(Builtin::LammpsTsujiHertz, true, 0.5).unwrap();
    for v in [
        "2026-09-02",
        "20260902",
        "2Sep2026",
        "2 Sep 2026",
        "11Feb2027",
    ] {
        assert_eq!(value_of(&["--version", v]), (Some(9), new), "{v}");
    }
    for v in ["2025-07-22", "22Jul2025", "23Jun2022"] {
        assert_eq!(value_of(&["--release", v]), (Some(4), old), "{v}");
    }
    // Without --version: the releases up to 22 Jul 2025, as before.
    assert_eq!(value_of(&[]), (Some(4), old));
    // Ambiguous, impossible and unparsable releases, and a release for another code: exit 1,
    // naming the value.
    for (v, code) in [
        ("2026-02-11", "lammps"),
        ("2026-02-30", "lammps"),
        ("yesterday", "lammps"),
        ("2026-09-02", "liggghts"),
    ] {
        let model = if code == "lammps" { "tsuji" } else { "hertz" };
        let o = run(&[
            "builtin",
            "--code",
            code,
            "--model",
            model,
            "--e",
            "0.5",
            "--version",
            v,
            "--json",
        ]);
        assert_eq!(o.status.code(), Some(1), "{v} {code}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(v), "{err}");
        let status = json_of(&o)["error"]["status"].as_i64();
        let want = if code == "lammps" { 6134 } else { 6130 };
        assert_eq!(status, Some(want), "{v} {code}: {err}");
    }
}

#[test]
fn builtin_bad_input() {
    // unreachable target: exit 1, status 6131 in the JSON error
    let o = run(&[
        "builtin",
        "--code",
        "lammps",
        "--model",
        "tsuji",
        "--limit-damping",
        "--e",
        "0.1",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let j = json_of(&o);
    assert_eq!(j["error"]["status"].as_i64(), Some(6131));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("0.2628"),
        "names the reachable range"
    );
    // not a number: clap, exit 2, naming the value
    let o = run(&[
        "builtin", "--code", "liggghts", "--model", "hertz", "--e", "0.5x",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("0.5x"));
    // NaN parses as a float; the library refuses it
    let o = run(&[
        "builtin", "--code", "liggghts", "--model", "hertz", "--e", "NaN", "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json_of(&o)["error"]["status"].as_i64(), Some(6102));
    let o = run(&[
        "builtin", "--code", "liggghts", "--model", "hertz", "--e", "1.5",
    ]);
    assert_eq!(o.status.code(), Some(1));
    // a model the code does not have
    let o = run(&[
        "builtin", "--code", "lammps", "--model", "hertz", "--e", "0.5", "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json_of(&o)["error"]["status"].as_i64(), Some(6130));
    // unknown code: clap, exit 2
    assert_eq!(
        run(&["builtin", "--code", "pfc", "--model", "hertz", "--e", "0.5"])
            .status
            .code(),
        Some(2)
    );
    // viscel-cn without --kn
    assert_eq!(
        run(&[
            "builtin",
            "--code",
            "yade",
            "--model",
            "viscel-cn",
            "--e",
            "0.5"
        ])
        .status
        .code(),
        Some(1)
    );
    assert_eq!(run(&["--help"]).status.code(), Some(0));
}

#[test]
fn contact_json_matches_the_library() {
    let base = [
        "contact", "--E1", "7e10", "--nu1", "0.22", "--rho1", "2500", "--R1", "1e-3", "--v", "2",
        "--e", "0.5",
    ];
    let o = run(&base);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8(o.stdout).unwrap();
    for w in [
        "alpha",
        "max overlap",
        "peak force",
        "overlap end",
        "force end",
        "dt for",
    ] {
        assert!(text.contains(w), "{w}: {text}");
    }
    let mut a = base.to_vec();
    a.push("--json");
    let j = json_of(&run(&a));
    let alpha = powerlaw::alpha_from_e(0.5, 1.5, EndCriterion::Force).unwrap();
    assert_eq!(j["alpha"].as_f64().unwrap(), alpha);
    // independent: E* = E/(2(1-ν²)), R* = R/2, m* = m/2, k = 4/3 E* √R*, ω0 = √(k/m*)
    let (e_star, r_star): (f64, f64) = (7e10 / (2.0 * (1.0 - 0.22f64 * 0.22)), 0.5e-3);
    let m_star = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-9 / 2.0;
    let k = 4.0 / 3.0 * e_star * r_star.sqrt();
    assert!((j["k"].as_f64().unwrap() / k - 1.0).abs() < 1e-14);
    let c = powerlaw::Contact::new(1.5, alpha, 2.0, (k / m_star).sqrt()).unwrap();
    let d = powerlaw::max_overlap(&c).unwrap();
    assert!((j["max_overlap"].as_f64().unwrap() / d - 1.0).abs() < 1e-12);
    // peak force below the elastic Hertz peak k δ_el^{3/2} (damping lowers it), above k δ_max^{3/2}
    let fp = j["peak_force"].as_f64().unwrap();
    assert!(fp > k * d.powf(1.5) && fp.is_finite(), "{fp}");
    let (to, tf) = (
        j["duration_overlap_end"].as_f64().unwrap(),
        j["duration_force_end"].as_f64().unwrap(),
    );
    assert!(tf < to && j["dt"].as_f64().unwrap() < tf / 50.0);
    // wall: R* = R1, m* = m1
    let mut w = a.clone();
    w.push("--wall");
    let jw = json_of(&run(&w));
    assert_eq!(jw["r_star"].as_f64().unwrap(), 1e-3);
    assert!((jw["m_star"].as_f64().unwrap() / (2.0 * m_star) - 1.0).abs() < 1e-15);
    // overdamped under the overlap end: no overlap-end duration, null in JSON
    let mut od = base.to_vec();
    let last = od.len() - 1;
    od[last] = "0.01";
    od.push("--json");
    let j = json_of(&run(&od));
    assert!(j["duration_overlap_end"].is_null());
}

#[test]
fn contact_bad_input() {
    let o = run(&[
        "contact", "--E1", "7e10", "--nu1", "0.7", "--rho1", "2500", "--R1", "1e-3", "--v", "2",
        "--e", "0.5", "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json_of(&o)["error"]["status"].as_i64(), Some(6114));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("--nu1 0.7") && err.contains("Poisson ratio must be in (-1, 0.5]"),
        "{err}"
    );
    // Body 2's ratio is named as body 2's.
    let o = run(&[
        "contact", "--E1", "7e10", "--nu1", "0.2", "--nu2", "-1", "--rho1", "2500", "--R1", "1e-3",
        "--v", "2", "--e", "0.5",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--nu2 -1:"));
    // A negative value is a value (not a flag): the library's range check answers, naming it.
    let o = run(&[
        "contact", "--E1", "-7e10", "--nu1", "0.2", "--rho1", "2500", "--R1", "1e-3", "--v", "2",
        "--e", "0.5", "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert_eq!(json_of(&o)["error"]["status"].as_i64(), Some(6105));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--E1 -70000000000"));
    let o = run(&[
        "contact", "--E1", "7e10", "--nu1", "0.2", "--rho1", "2500", "--R1", "-1e-3", "--v", "2",
        "--e", "0.5",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let o = run(&[
        "builtin", "--code", "liggghts", "--model", "hertz", "--e", "-0.5", "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json_of(&o)["error"]["status"].as_i64(), Some(6103));
    let o = run(&[
        "contact", "--E1", "7e10", "--nu1", "0.2", "--rho1", "2500", "--R1", "1e-3", "--v=-2",
        "--e", "0.5",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let o = run(&[
        "contact", "--E1", "7e10", "--nu1", "0.2", "--rho1", "2500", "--R1", "1e-3", "--e", "0.5",
    ]);
    assert_eq!(o.status.code(), Some(2)); // --v missing
}

#[test]
fn fit_exact_data_json_and_plot() {
    let beta = 0.3;
    let mut csv = String::from("# synthetic\nv, e, sigma\n");
    for i in 0..8 {
        let v = 0.1 * 100f64.powf(i as f64 / 7.0);
        let e = e_full(beta * v.powf(0.2), EndCriterion::Force).unwrap();
        csv += &format!("{v:.17e}, {e:.17e}, 0.01\n");
    }
    let f = tmp("exact.csv", &csv);
    let png = f.with_extension("png");
    let _ = std::fs::remove_file(&png);
    let o = run(&[
        "fit",
        f.to_str().unwrap(),
        "--json",
        "--plot",
        png.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let j = json_of(&o);
    assert!((j["beta"].as_f64().unwrap() / beta - 1.0).abs() < 1e-10);
    assert_eq!(j["model"], "viscoelastic");
    assert_eq!(j["points"].as_array().unwrap().len(), 8);
    // σ given: the normal quantile; the interval is β ± q·SE
    let q = j["quantile95"].as_f64().unwrap();
    assert!((q - 1.959963984540054).abs() < 1e-12, "{q}");
    let (b, se) = (j["beta"].as_f64().unwrap(), j["beta_se"].as_f64().unwrap());
    assert!((j["beta_lo95"].as_f64().unwrap() - (b - q * se)).abs() < 1e-15);
    assert!((j["beta_hi95"].as_f64().unwrap() - (b + q * se)).abs() < 1e-15);
    // without σ (two columns): Student t with n − 1 = 7 degrees of freedom, 2.364624251592785
    // (mpmath, 30 digits)
    let two: String = csv
        .lines()
        .map(|l| match l.rfind(',') {
            Some(k) if !l.starts_with('#') => format!("{}\n", &l[..k]),
            _ => format!("{l}\n"),
        })
        .collect();
    let f2 = tmp("exact2.csv", &two);
    let j2 = json_of(&run(&["fit", f2.to_str().unwrap(), "--json"]));
    assert_eq!(j2["se_from_scatter"].as_bool(), Some(true), "{j2}");
    let q2 = j2["quantile95"].as_f64().unwrap();
    assert!((q2 - 2.364624251592785).abs() < 1e-12, "{q2}");
    let text = String::from_utf8(run(&["fit", f2.to_str().unwrap()]).stdout).unwrap();
    assert!(text.contains("Student t, 7 degrees of freedom"), "{text}");
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    // text: the table and the model choice
    let o = run(&["fit", f.to_str().unwrap(), "--tol", "0.5"]);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.contains("model required at tol 0.5: constant e"),
        "{text}"
    );
}

#[test]
fn fit_bad_input() {
    let f = tmp("bad.csv", "v,e\n1.0, 0.5\n2.0, abc\n");
    let o = run(&["fit", f.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(3));
    let j = json_of(&o);
    assert_eq!(j["error"]["line"].as_u64(), Some(3));
    assert_eq!(j["error"]["column"].as_u64(), Some(6));
    assert!(String::from_utf8_lossy(&o.stderr).contains("bad.csv:3:6: 'abc' is not a number"));
    let f = tmp("range.csv", "0.5 0.7\n1.0 1.2\n");
    let o = run(&["fit", f.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(3));
    assert!(
        String::from_utf8_lossy(&o.stderr)
            .contains("range.csv:2:5: 1.2: restitution must be in (0, 1]")
    );
    let f = tmp("fields.csv", "0.5,0.7\n1.0,0.6,0.01,9\n");
    let o = run(&["fit", f.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&o.stderr).contains("fields.csv:2:"));
    let f = tmp("one.csv", "1.0,0.6\n");
    let o = run(&["fit", f.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json_of(&o)["error"]["status"].as_i64(), Some(6132));
    let f = tmp("same.csv", "1.0,0.6\n1.0,0.62\n");
    let o = run(&["fit", f.to_str().unwrap(), "--json"]);
    assert_eq!(json_of(&o)["error"]["status"].as_i64(), Some(6133));
    let o = run(&["fit", "/nonexistent/data.csv", "--json"]);
    assert_eq!(o.status.code(), Some(3));
    let f = tmp("ok.csv", "0.5,0.7\n1.0,0.6\n");
    let o = run(&[
        "fit",
        f.to_str().unwrap(),
        "--plot",
        "/nonexistent/dir/fit.png",
    ]);
    assert_eq!(o.status.code(), Some(4));
}

const PLAN: [&str; 25] = [
    "plan",
    "--E1",
    "7e10",
    "--nu1",
    "0.22",
    "--rho1",
    "2500",
    "--e",
    "0.5",
    "--R-min",
    "1e-3",
    "--R-max",
    "2e-3",
    "--v-max",
    "2",
    "--depth",
    "0.5",
    "--overlap-tol",
    "0.01",
    "--e-tol",
    "0.01",
    "--mu",
    "0.5",
    "--mu-r",
    "0.1",
];

/// The plan command line with `flag` set to `value` (added when absent), or removed (None).
fn plan_with(flag: &str, value: Option<&str>) -> Vec<String> {
    let mut a: Vec<String> = PLAN.iter().map(|s| s.to_string()).collect();
    match a.iter().position(|s| s == flag) {
        Some(i) => match value {
            Some(v) => a[i + 1] = v.into(),
            None => {
                a.remove(i + 1);
                a.remove(i);
            }
        },
        None => {
            if let Some(v) = value {
                a.push(flag.into());
                a.push(v.into());
            }
        }
    }
    a
}

#[test]
fn plan_json_matches_the_library() {
    let args: Vec<&str> = PLAN.iter().copied().chain(["--json"]).collect();
    let o = run(&args);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let j = json_of(&o);
    let inp = demcontact::plan::PlanInput {
        youngs: 7e10,
        poisson: 0.22,
        density: 2500.0,
        restitution: 0.5,
        radius_min: 1e-3,
        radius_max: 2e-3,
        v_max: 2.0,
        depth: 0.5,
        friction: 0.5,
        rolling_friction: 0.1,
        overlap_tol: 0.01,
        e_tol: 0.01,
        static_tol: 0.01,
        ..demcontact::plan::PlanInput::new()
    };
    let p = demcontact::plan::plan(&inp).unwrap();
    for (key, want) in [
        ("youngs_soft", p.youngs_soft),
        ("dt", p.dt),
        ("speedup", p.speedup),
        ("max_overlap_ratio", p.max_overlap_ratio),
        ("static_overlap_ratio", p.static_overlap_ratio),
        ("duration", p.duration),
        ("e_plain_at_dt", p.e_plain_at_dt),
        ("steps_per_contact", p.steps_per_contact),
    ] {
        // serde_json's parser may round the last bit (no float_roundtrip feature).
        let got = j[key].as_f64().unwrap();
        assert!(
            (got - want).abs() <= 4e-16 * want.abs(),
            "{key}: {got} vs {want}"
        );
    }
    assert_eq!(j["binding"], "overlap-tol");
    assert_eq!(j["binding_dt"], "e-tol");
    assert_eq!(j["mu"].as_f64(), Some(0.5));
    assert_eq!(j["tolerances"]["duration_tol"], Value::Null); // no bound
    // The text table names the same figures.
    let o = run(&PLAN);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains(&format!("{:.6e}", p.youngs_soft)), "{text}");
    assert!(text.contains("binding: overlap-tol"), "{text}");
    assert!(text.contains(&format!("{:.4}", p.speedup)), "{text}");
    // --help lists the contract flags.
    let o = run(&["plan", "--help"]);
    assert_eq!(o.status.code(), Some(0));
    let help = String::from_utf8(o.stdout).unwrap();
    for flag in [
        "--E1",
        "--nu1",
        "--rho1",
        "--e ",
        "--R-min",
        "--R-max",
        "--v-max",
        "--depth",
        "--g ",
        "--mu ",
        "--mu-r",
        "--overlap-tol",
        "--e-tol",
        "--json",
    ] {
        assert!(help.contains(flag), "--help lacks {flag}: {help}");
    }
}

/// `plan --step-aware`: the step-aware step is reported without the flag and chosen with it;
/// both match the library (`plan::step_aware`), the plain figures stay, and an e tolerance no
/// step-aware step meets is refused with the flag (status, flag and value named) and reported as
/// null without it.
#[test]
fn plan_step_aware() {
    let inp = demcontact::plan::PlanInput {
        youngs: 7e10,
        poisson: 0.22,
        density: 2500.0,
        restitution: 0.5,
        radius_min: 1e-3,
        radius_max: 2e-3,
        v_max: 2.0,
        depth: 0.5,
        overlap_tol: 0.01,
        e_tol: 0.01,
        static_tol: 0.01,
        ..demcontact::plan::PlanInput::new()
    };
    let p = demcontact::plan::plan(&inp).unwrap();
    let sa = demcontact::plan::step_aware(&inp, &p).unwrap();
    let close = |got: &Value, want: f64, key: &str| {
        let got = got.as_f64().unwrap();
        assert!(
            (got - want).abs() <= 4e-16 * want.abs(),
            "{key}: {got} vs {want}"
        );
    };
    let plain_args: Vec<&str> = PLAN.iter().copied().chain(["--json"]).collect();
    let j = json_of(&run(&plain_args));
    assert_eq!(j["step_aware_chosen"], false);
    close(&j["dt"], p.dt, "dt (plain)");
    close(&j["step_aware"]["dt"], sa.dt, "step_aware.dt");
    close(
        &j["step_aware"]["speedup"],
        sa.speedup,
        "step_aware.speedup",
    );
    assert_eq!(j["step_aware"]["binding_dt"], "e-tol");
    let aware_args: Vec<&str> = PLAN
        .iter()
        .copied()
        .chain(["--step-aware", "--json"])
        .collect();
    let o = run(&aware_args);
    assert_eq!(o.status.code(), Some(0));
    let j = json_of(&o);
    assert_eq!(j["step_aware_chosen"], true);
    close(&j["dt"], sa.dt, "dt (step-aware)");
    close(&j["speedup"], sa.speedup, "speedup");
    close(&j["dt_plain"], p.dt, "dt_plain");
    close(&j["dt_over_t_hertz"], sa.dt_over_t_hertz, "dt_over_t_hertz");
    close(&j["e_plain_at_dt"], p.e_plain_at_dt, "e_plain_at_dt");
    assert_eq!(j["binding_dt"], "e-tol (step-aware)");
    // The step-aware step is the larger: about t_H/10 here against t_H/42 plain.
    assert!(sa.dt > 3.0 * p.dt, "{} vs {}", sa.dt, p.dt);
    let o = run(&aware_args[..aware_args.len() - 1]);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.contains("step-aware step") && text.contains("chosen"),
        "{text}"
    );
    // An e tolerance no step a scene can run meets (the plain plan, computed first, refuses it),
    // refused with the flag.
    let tight = plan_with("--e-tol", Some("1e-7"));
    let mut a: Vec<&str> = tight.iter().map(String::as_str).collect();
    a.push("--step-aware");
    let o = run(&a);
    assert_eq!(o.status.code(), Some(1));
    assert!(o.stdout.is_empty());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("--e-tol 0.0000001"), "{err}");
    a.push("--json");
    let j = json_of(&run(&a));
    assert_eq!(j["error"]["status"].as_i64(), Some(6141), "{j}");
    // A loose e tolerance the plain dashpot meets beyond t_H/10, where the step-aware calibration
    // stops: --step-aware keeps the larger plain step and says so.
    let loose = [
        "plan",
        "--E1",
        "6.9e8",
        "--nu1",
        "0.3",
        "--rho1",
        "3533",
        "--e",
        "0.54",
        "--R-min",
        "0.0047",
        "--R-max",
        "0.036",
        "--v-max",
        "0.032",
        "--depth",
        "0",
        "--overlap-tol",
        "0.016",
        "--e-tol",
        "0.072",
        "--step-aware",
    ];
    let j = json_of(&run(&[&loose[..], &["--json"]].concat()));
    assert_eq!(j["step_aware_chosen"], false, "{j}");
    assert_eq!(j["dt"], j["dt_plain"], "{j}");
    let sa_dt = j["step_aware"]["dt"].as_f64().unwrap();
    assert!(sa_dt < j["dt_plain"].as_f64().unwrap(), "{j}");
    let text = String::from_utf8(run(&loose).stdout).unwrap();
    assert!(
        text.contains("not chosen: the plain step is larger"),
        "{text}"
    );
}

#[test]
fn plan_bad_input() {
    // (flag, value, status, what the message must contain)
    let cases: [(&str, &str, i64, &str); 11] = [
        ("--E1", "-7e10", 6105, "--E1 -70000000000"),
        ("--E1", "NaN", 6102, "--E1 NaN"),
        ("--e", "1.5", 6103, "--e 1.5"),
        ("--R-max", "5e-4", 6140, "--R-min 0.001 --R-max 0.0005"),
        ("--overlap-tol", "0", 6105, "--overlap-tol 0"),
        ("--e-tol", "-0.01", 6105, "--e-tol -0.01"),
        ("--e-tol", "inf", 6102, "--e-tol inf"),
        ("--nu1", "0.7", 6114, "--nu1 0.7"),
        ("--v-max", "0", 6105, "--v-max 0"),
        ("--depth", "-1", 6106, "--depth -1"),
        // The real glass already overlaps more than 1e-4 of R at 2 m/s.
        ("--overlap-tol", "1e-4", 6141, "--overlap-tol 0.0001"),
    ];
    for (flag, value, status, says) in cases {
        let args = plan_with(flag, Some(value));
        let mut a: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = run(&a);
        assert_eq!(o.status.code(), Some(1), "{flag} {value}");
        assert!(o.stdout.is_empty(), "{flag} {value}: stdout written");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(says), "{flag} {value}: {err}");
        a.push("--json");
        let o = run(&a);
        assert_eq!(o.status.code(), Some(1), "{flag} {value}");
        let j = json_of(&o);
        assert_eq!(
            j["error"]["status"].as_i64(),
            Some(status),
            "{flag} {value}: {j}"
        );
        assert!(j.get("youngs_soft").is_none() && j.as_object().unwrap().len() == 1);
    }
    let o = run(&plan_with("--overlap-tol", Some("1e-4"))
        .iter()
        .map(String::as_str)
        .collect::<Vec<_>>());
    assert!(String::from_utf8_lossy(&o.stderr).contains("the real modulus gives delta_max/R"));
    // A missing required flag or a value that is not a number: clap, exit 2, nothing on stdout.
    for args in [plan_with("--depth", None), plan_with("--E1", Some("seven"))] {
        let a: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = run(&a);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(o.stdout.is_empty());
    }
}

/// Elastic Hertz contact duration at impact speed v for F = k δ^{3/2}, mass m: RK4 on
/// m δ'' = −k δ^{3/2} from δ = 0, δ' = v, the return through δ = 0 interpolated (independent of
/// the library's closed forms).
fn t_hertz_rk4(k: f64, m: f64, v: f64) -> f64 {
    let dmax = (5.0 * m * v * v / (4.0 * k)).powf(0.4);
    let h = 4.0 * dmax / v / 20000.0;
    let acc = |d: f64| -k * d.max(0.0).powf(1.5) / m;
    let (mut d, mut u, mut t) = (0.0f64, v, 0.0);
    loop {
        let (k1d, k1u) = (u, acc(d));
        let (k2d, k2u) = (u + 0.5 * h * k1u, acc(d + 0.5 * h * k1d));
        let (k3d, k3u) = (u + 0.5 * h * k2u, acc(d + 0.5 * h * k2d));
        let (k4d, k4u) = (u + h * k3u, acc(d + h * k3d));
        let dn = d + h / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
        let un = u + h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
        if t > 0.0 && dn <= 0.0 {
            return t + h * d / (d - dn);
        }
        (d, u, t) = (dn, un, t + h);
    }
}

/// Realised e of a sphere–wall collision, velocity Verlet in the LAMMPS order, with this test's
/// own force m δ'' = −k δ^{3/2} − α √(m k) δ^{1/4} δ' (clamped at 0 for the force end), the
/// first step at a gap of j/64 of one step's travel.
fn own_verlet_e(k: f64, m: f64, alpha: f64, clamp: bool, v0: f64, dt: f64, j: usize) -> f64 {
    let mut d = -(j as f64) / 64.0 * v0 * dt;
    let (mut v, mut acc, mut touched) = (-v0, 0.0, false);
    for _ in 0..1_000_000 {
        let vh = v + 0.5 * dt * acc;
        d -= dt * vh;
        touched |= d > 0.0;
        let f = if d > 0.0 {
            let f = k * d.powf(1.5) + alpha * (m * k).sqrt() * d.powf(0.25) * (-vh);
            if clamp { f.max(0.0) } else { f }
        } else {
            0.0
        };
        acc = f / m;
        v = vh + 0.5 * dt * acc;
        if touched && d <= 0.0 {
            return v / v0;
        }
    }
    panic!("no separation");
}

#[test]
fn contact_at_step_plain_and_step_aware() {
    // A soft sphere on a wall of the same material, e = 0.1: k = 4/3 E* √R1 with
    // E* = E/(2(1 − ν²)), m = ρ 4/3 π R1³.
    let (e_mod, nu, rho, r1, v0, e): (f64, f64, f64, f64, f64, f64) =
        (1e8, 0.3, 2500.0, 2e-3, 1.0, 0.1);
    let k = 4.0 / 3.0 * e_mod / (2.0 * (1.0 - nu * nu)) * r1.sqrt();
    let m = rho * 4.0 / 3.0 * std::f64::consts::PI * r1 * r1 * r1;
    let t_h = t_hertz_rk4(k, m, v0);
    for (crit, clamp) in [("force", true), ("overlap", false)] {
        for div in [20.0, 10.5] {
            let dt = format!("{:e}", t_h / div);
            let args = [
                "contact",
                "--E1",
                "1e8",
                "--nu1",
                "0.3",
                "--rho1",
                "2500",
                "--R1",
                "2e-3",
                "--v",
                "1",
                "--e",
                "0.1",
                "--wall",
                "--criterion",
                crit,
                "--dt",
                &dt,
                "--step-aware",
            ];
            let o = run(&args);
            assert_eq!(
                o.status.code(),
                Some(0),
                "{}",
                String::from_utf8_lossy(&o.stderr)
            );
            let text = String::from_utf8(o.stdout).unwrap();
            assert!(
                text.contains("e realised at dt")
                    && text.contains("plain")
                    && text.contains("step-aware"),
                "{text}"
            );
            assert!(!text.contains("note: dt >"), "{text}");
            let mut a = args.to_vec();
            a.push("--json");
            let j = json_of(&run(&a));
            let s = &j["at_step"];
            let dt: f64 = dt.parse().unwrap();
            assert_eq!(s["dt"].as_f64().unwrap(), dt);
            assert_eq!(s["integrator"], "verlet");
            assert_eq!(s["within_calibration"], true);
            // The CLI's elastic duration against this test's RK4.
            let th = s["t_hertz"].as_f64().unwrap();
            assert!((th / t_h - 1.0).abs() < 1e-6, "{th} vs {t_h}");
            // Plain: each onset phase against this test's own Verlet loop.
            let alpha = j["alpha"].as_f64().unwrap();
            let phases = s["plain"]["phases"].as_array().unwrap();
            assert_eq!(phases.len(), 64);
            for (jj, p) in phases.iter().enumerate() {
                let mine = own_verlet_e(k, m, alpha, clamp, v0, dt, jj);
                let cli = p.as_f64().unwrap();
                assert!(
                    (cli / mine - 1.0).abs() < 1e-9,
                    "{crit} t_H/{div} phase {jj}: {cli} vs {mine}"
                );
            }
            // docs/timestep.md: plain ~10-30 % low at these steps; step-aware mean within 0.2 %.
            let plain = s["plain"]["mean"].as_f64().unwrap();
            let aware = s["step_aware"]["mean"].as_f64().unwrap();
            assert!(plain / e - 1.0 < -0.05, "{crit} t_H/{div}: plain {plain}");
            assert!(
                (aware / e - 1.0).abs() < 2e-3,
                "{crit} t_H/{div}: step-aware {aware}"
            );
        }
    }
    // Symplectic Euler between two spheres: step-aware again within 0.2 % at t_H/20 (two equal
    // spheres: k = 4/3 E* √(R/2), m* = m/2).
    let k2 = 4.0 / 3.0 * e_mod / (2.0 * (1.0 - nu * nu)) * (r1 / 2.0).sqrt();
    let dt = format!("{:e}", t_hertz_rk4(k2, m / 2.0, v0) / 20.0);
    let j = json_of(&run(&[
        "contact",
        "--E1",
        "1e8",
        "--nu1",
        "0.3",
        "--rho1",
        "2500",
        "--R1",
        "2e-3",
        "--v",
        "1",
        "--e",
        "0.1",
        "--dt",
        &dt,
        "--step-aware",
        "--integrator",
        "euler",
        "--json",
    ]));
    assert_eq!(j["at_step"]["integrator"], "euler");
    let aware = j["at_step"]["step_aware"]["mean"].as_f64().unwrap();
    assert!((aware / e - 1.0).abs() < 2e-3, "euler step-aware {aware}");
    assert!(j["at_step"]["plain"]["mean"].as_f64().unwrap() / e - 1.0 < -0.05);
}

#[test]
fn contact_at_step_options_and_bad_input() {
    let base = [
        "contact", "--E1", "1e8", "--nu1", "0.3", "--rho1", "2500", "--R1", "2e-3", "--v", "1",
        "--e", "0.5", "--wall",
    ];
    let with = |extra: &[&str]| {
        let mut a = base.to_vec();
        a.extend_from_slice(extra);
        run(&a)
    };
    // Without --dt: no step figures (null in JSON); without --step-aware: plain only.
    assert!(json_of(&with(&["--json"]))["at_step"].is_null());
    let j = json_of(&with(&["--dt", "1e-5", "--json"]));
    assert!(j["at_step"]["step_aware"].is_null() && j["at_step"]["plain"]["mean"].is_f64());
    let text = String::from_utf8(with(&["--dt", "1e-5"]).stdout).unwrap();
    assert!(
        text.contains("plain") && !text.contains("step-aware"),
        "{text}"
    );
    // A step beyond the calibrated range is run, with a note.
    let text = String::from_utf8(with(&["--dt", "1e-4", "--step-aware"]).stdout).unwrap();
    assert!(text.contains("note: dt > t_Hertz/10"), "{text}");
    // --step-aware and --integrator need --dt; unknown integrator: clap (exit 2).
    assert_eq!(with(&["--step-aware"]).status.code(), Some(2));
    assert_eq!(with(&["--integrator", "euler"]).status.code(), Some(2));
    assert_eq!(
        with(&["--dt", "1e-5", "--integrator", "rk4"]).status.code(),
        Some(2)
    );
    // Bad --dt values: the library's statuses, naming the flag and value (exit 1).
    for (dt, status) in [("-1e-5", 6105), ("0", 6105), ("nan", 6102), ("inf", 6102)] {
        let o = with(&["--dt", dt, "--json"]);
        assert_eq!(o.status.code(), Some(1), "{dt}");
        assert_eq!(
            json_of(&o)["error"]["status"].as_i64(),
            Some(status),
            "{dt}"
        );
        assert!(String::from_utf8_lossy(&o.stderr).contains("--dt "), "{dt}");
    }
    // A step so small that the simulation would take long: refused as a usage error.
    let o = with(&["--dt", "1e-12", "--json"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(json_of(&o)["error"]["kind"], "usage");
    assert!(String::from_utf8_lossy(&o.stderr).contains("--dt 1e-12"));
    // The step-aware form is refused where the library refuses it: strong damping under the
    // force end (DC_ERR_STEP_UNREACHABLE), named with the flags; nothing on stdout but the error.
    let o = run(&[
        "contact",
        "--E1",
        "1e8",
        "--nu1",
        "0.3",
        "--rho1",
        "2500",
        "--R1",
        "2e-3",
        "--v",
        "1",
        "--e",
        "0.005",
        "--wall",
        "--dt",
        "1e-5",
        "--step-aware",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json_of(&o)["error"]["status"].as_i64(), Some(6137));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--dt 1e-5 --step-aware"));
}

/// e → 0 with the overlap criterion needs more than MAX_STEPS_PER_CONTACT steps per contact for
/// the e tolerance: refused at once, naming --e-tol and why; the force criterion plans it.
#[test]
fn plan_vanishing_restitution() {
    let mut a = plan_with("--e", Some("1e-8"));
    a.extend(["--criterion".to_string(), "overlap".to_string()]);
    let args: Vec<&str> = a.iter().map(String::as_str).collect();
    let o = run(&args);
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("--e-tol 0.01") && err.contains("steps in a contact"),
        "{err}"
    );
    let mut j: Vec<&str> = args.clone();
    j.push("--json");
    assert_eq!(json_of(&run(&j))["error"]["status"].as_i64(), Some(6141));
    let force: Vec<&str> = args
        .iter()
        .map(|s| if *s == "overlap" { "force" } else { s })
        .collect();
    assert_eq!(run(&force).status.code(), Some(0));
    // A stability fraction that leaves too fine a step: refused naming it.
    let tiny = plan_with("--stability-fraction", Some("1e-7"));
    let a: Vec<&str> = tiny.iter().map(String::as_str).collect();
    let o = run(&a);
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("--stability-fraction") && err.contains("steps in a contact"),
        "{err}"
    );
}
