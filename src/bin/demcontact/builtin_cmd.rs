//! `demcontact builtin`: the value to type into a builtin model, and the line to paste.

use crate::output::{Failure, Output, num};
use crate::refused;
use clap::ValueEnum;
use demcontact::builtin::{self, Builtin, lammps};
use serde_json::json;
use std::fmt::Write;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Code {
    Liggghts,
    Lammps,
    Yade,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Model {
    /// LIGGGHTS `model hooke`.
    Hooke,
    /// LIGGGHTS `model hertz`.
    Hertz,
    /// LAMMPS granular `damping coeff_restitution`.
    CoeffRestitution,
    /// LAMMPS granular `damping tsuji` (with --normal hertz|hooke).
    Tsuji,
    /// YADE `ViscElMat(tc, en, et)`.
    Viscel,
    /// YADE `ViscElMat(kn, cn)`: needs --kn and --mass.
    ViscelCn,
    /// YADE `Ip2_FrictMat_FrictMat_MindlinPhys(en=…)`.
    MindlinEn,
    /// YADE `Ip2_FrictMat_FrictMat_MindlinPhys(betan=…)`.
    MindlinBetan,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Normal {
    Hertz,
    Hooke,
}

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The DEM code.
    #[arg(long, value_enum)]
    code: Code,
    /// Its builtin contact model.
    #[arg(long, value_enum)]
    model: Model,
    /// Attractive normal forces clamped: LIGGGHTS `limitForce on`, LAMMPS `limit_damping`
    /// (YADE always clamps).
    #[arg(long, visible_alias = "limit-damping")]
    limit_force: bool,
    /// Target restitution, 0 < e ≤ 1.
    #[arg(long)]
    e: f64,
    /// The particle hits a wall (fixed, massless wall or facet, or a fixed body of its own mass)
    /// rather than another particle. Changes the value for YADE `viscel` only (it calibrates
    /// with the reduced mass m/2 against a wall).
    #[arg(long)]
    wall: bool,
    /// LAMMPS normal model for `tsuji`.
    #[arg(long, value_enum, default_value = "hertz")]
    normal: Normal,
    /// LAMMPS release the deck runs on (`2026-09-02`, `20260902`, `2Sep2026` or `2 Sep 2026`, as
    /// `lmp -h` prints it): `damping tsuji` multiplies Tsuji's η by √2 from 2 Sep 2026 on.
    /// Without it, `tsuji` answers for releases up to 22 Jul 2025.
    #[arg(long, visible_alias = "release", value_name = "DATE")]
    version: Option<String>,
    /// YADE `viscel-cn`: contact normal stiffness kn [N/m].
    #[arg(long)]
    kn: Option<f64>,
    /// YADE `viscel-cn`: reduced mass m1 m2/(m1 + m2) [kg] (the particle's mass against a wall).
    #[arg(long)]
    mass: Option<f64>,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

fn pick(a: &Args) -> Result<Option<Builtin>, Failure> {
    use Model::*;
    let bad = |why: &str| {
        Failure::refused(
            format!("--code {:?} --model {:?}: {why}", a.code, a.model).to_lowercase(),
            demcontact::Error::BuiltinModel,
        )
    };
    let b = match (a.code, a.model) {
        (Code::Liggghts, Hooke) => Builtin::LiggghtsHooke,
        (Code::Liggghts, Hertz) => Builtin::LiggghtsHertz,
        (Code::Lammps, CoeffRestitution) => Builtin::LammpsCoeffRestitution,
        (Code::Lammps, Tsuji) => match a.normal {
            Normal::Hertz => Builtin::LammpsTsujiHertz,
            Normal::Hooke => Builtin::LammpsTsujiHooke,
        },
        (Code::Yade, Viscel) => Builtin::YadeViscElEn,
        (Code::Yade, ViscelCn) => return Ok(None),
        (Code::Yade, MindlinEn) => Builtin::YadeMindlinEn,
        (Code::Yade, MindlinBetan) => Builtin::YadeMindlinBetan,
        _ => return Err(bad("this code has no such model")),
    };
    let Some(version) = &a.version else {
        return Ok(Some(b));
    };
    if a.code != Code::Lammps {
        return Err(Failure::refused(
            format!("--version {version}: selects a LAMMPS release; --code is not lammps"),
            demcontact::Error::BuiltinModel,
        ));
    }
    let date = lammps::parse_release(version).ok_or_else(|| {
        Failure::refused(
            format!(
                "--version {version:?}: not a release date (write 2026-09-02, 20260902, 2Sep2026 \
                 or \"2 Sep 2026\")"
            ),
            demcontact::Error::BuiltinVersion,
        )
    })?;
    b.for_lammps_release(date)
        .map(Some)
        .map_err(|e| refused(&format!("--version {version}"), e))
}

/// What the value is called in the code, and the lines to paste.
fn lines(b: Builtin, clamp: bool, v: f64) -> (&'static str, Vec<String>) {
    let lf = if clamp { " limitForce on" } else { "" };
    let ld = if clamp { " limit_damping" } else { "" };
    match b {
        Builtin::LiggghtsHooke | Builtin::LiggghtsHertz => {
            let m = if b == Builtin::LiggghtsHooke {
                "hooke"
            } else {
                "hertz"
            };
            (
                "coefficientRestitution",
                vec![
                    format!(
                        "fix m3 all property/global coefficientRestitution peratomtypepair 1 {v:.10}"
                    ),
                    format!("pair_style gran model {m} tangential history{lf}"),
                ],
            )
        }
        Builtin::LammpsCoeffRestitution => (
            "e (damping coeff_restitution)",
            vec![format!(
                "pair_coeff * * hertz/material E {v:.10} nu tangential linear_nohistory 0 0 damping coeff_restitution{ld}"
            )],
        ),
        Builtin::LammpsTsujiHertz | Builtin::LammpsTsujiHertzSqrt2 => (
            "e (damping tsuji)",
            vec![format!(
                "pair_coeff * * hertz/material E {v:.10} nu tangential linear_nohistory 0 0 damping tsuji{ld}"
            )],
        ),
        Builtin::LammpsTsujiHooke | Builtin::LammpsTsujiHookeSqrt2 => (
            "e (damping tsuji)",
            vec![format!(
                "pair_coeff * * hooke kn {v:.10} tangential linear_nohistory 0 0 damping tsuji{ld}"
            )],
        ),
        Builtin::YadeViscElEn => (
            "en",
            vec![format!(
                "O.materials.append(ViscElMat(tc=TC, en={v:.10}, et={v:.10}, density=RHO))"
            )],
        ),
        Builtin::YadeMindlinEn => (
            "en",
            vec![format!(
                "Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(matches=((1, 1, {v:.10}),)))"
            )],
        ),
        Builtin::YadeMindlinBetan => (
            "betan",
            vec![format!(
                "Ip2_FrictMat_FrictMat_MindlinPhys(betan=MatchMaker(matches=((1, 1, {v:.10}),)))"
            )],
        ),
    }
}

pub fn run(a: &Args) -> Result<Output, Failure> {
    let Some(b) = pick(a)? else {
        return viscel_cn(a);
    };
    let clamp = a.limit_force || b.always_clamps();
    let partner = if a.wall { "a wall" } else { "a particle" };
    let value = builtin::value_for_e_wall(b, clamp, a.wall, a.e).map_err(|e| {
        let mut f = refused(
            &format!(
                "{} cannot realise e = {} against {partner}",
                label(b, clamp),
                a.e
            ),
            e,
        );
        if e == demcontact::Error::BuiltinUnreachable {
            f.message += &format!(
                "; it realises {}",
                builtin::reachable_range_wall(b, clamp, a.wall)
            );
        }
        f
    })?;
    // What the uncorrected input (the target itself; for betan the textbook formula) gives.
    let naive = builtin::naive_value(b, a.e).ok();
    let uncorrected = naive.and_then(|v| builtin::realised_e_wall(b, clamp, a.wall, v).ok());
    let (name, paste) = lines(b, clamp, value);
    let mut text = String::new();
    let _ = writeln!(
        text,
        "{}, target e = {}{}",
        label(b, clamp),
        a.e,
        if a.wall { " against a wall" } else { "" }
    );
    let _ = writeln!(text, "  type {name} = {value:.10}");
    if let (Some(n), Some(u)) = (naive, uncorrected) {
        let _ = writeln!(text, "  (uncorrected, {name} = {n:.6} realises e = {u:.6})");
    }
    let _ = writeln!(text, "  paste:");
    for l in &paste {
        let _ = writeln!(text, "    {l}");
    }
    let json = json!({
        "command": "builtin",
        "code": format!("{:?}", a.code).to_lowercase(),
        "model": format!("{:?}", b),
        "model_code": b.code(),
        "clamp": clamp,
        "wall": a.wall,
        "target_e": num(a.e),
        "parameter": name,
        "value": num(value),
        "label": label(b, clamp),
        "uncorrected_value": naive.map_or(serde_json::Value::Null, num),
        "uncorrected_realised_e": uncorrected.map_or(serde_json::Value::Null, num),
        "lines": paste,
    });
    Ok(Output { text, json })
}

/// The model in the code's own words.
fn label(b: Builtin, clamp: bool) -> String {
    let (name, clamp_s) = match b {
        Builtin::LiggghtsHooke => ("LIGGGHTS model hooke", "limitForce on"),
        Builtin::LiggghtsHertz => ("LIGGGHTS model hertz", "limitForce on"),
        Builtin::LammpsCoeffRestitution => {
            ("LAMMPS granular damping coeff_restitution", "limit_damping")
        }
        Builtin::LammpsTsujiHertz => (
            "LAMMPS (up to 22 Jul 2025) granular hertz/material damping tsuji",
            "limit_damping",
        ),
        Builtin::LammpsTsujiHooke => (
            "LAMMPS (up to 22 Jul 2025) granular hooke damping tsuji",
            "limit_damping",
        ),
        Builtin::LammpsTsujiHertzSqrt2 => (
            "LAMMPS (2 Sep 2026 on) granular hertz/material damping tsuji",
            "limit_damping",
        ),
        Builtin::LammpsTsujiHookeSqrt2 => (
            "LAMMPS (2 Sep 2026 on) granular hooke damping tsuji",
            "limit_damping",
        ),
        Builtin::YadeViscElEn => ("YADE ViscElMat(tc, en, et)", "always clamped"),
        Builtin::YadeMindlinEn => ("YADE MindlinPhys(en)", "always clamped"),
        Builtin::YadeMindlinBetan => ("YADE MindlinPhys(betan)", "always clamped"),
    };
    if clamp {
        format!("{name} ({clamp_s})")
    } else {
        format!("{name} (no force clamp)")
    }
}

fn viscel_cn(a: &Args) -> Result<Output, Failure> {
    let missing = |what: &str| {
        Failure::refused(
            format!("--model viscel-cn needs --{what}"),
            demcontact::Error::NotFinite,
        )
    };
    let kn = a.kn.ok_or_else(|| missing("kn"))?;
    let m = a.mass.ok_or_else(|| missing("mass"))?;
    let cn = builtin::yade::viscel_cn(a.e, kn, m).map_err(|e| refused("builtin viscel-cn", e))?;
    let line = format!(
        "O.materials.append(ViscElMat(kn={:.10e}, cn={:.10e}, ks=0, cs=0, density=RHO))",
        2.0 * kn,
        2.0 * cn
    );
    let text = format!(
        "Yade ViscElMat(kn, cn) (always clamps attractive force), target e = {}\n  \
         contact cn = {cn:.10e} N s/m for contact kn = {kn:e} N/m, reduced mass {m:e} kg\n  \
         paste (two equal materials: YADE combines kn and cn in series, so each gets 2x):\n    {line}\n",
        a.e
    );
    let json = json!({
        "command": "builtin", "code": "yade", "model": "YadeViscElCn", "clamp": true,
        "target_e": num(a.e), "parameter": "cn", "value": num(cn), "kn": num(kn),
        "mass": num(m), "lines": [line],
    });
    Ok(Output { text, json })
}
