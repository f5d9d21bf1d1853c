//! `include/demcontact_c.f90`: module `demcontact_c` with every constant as a named parameter,
//! every struct as a `bind(c)` derived type, a `bind(c)` interface for every function, and
//! `impure elemental` status-returning wrappers for the scalar functions (the hand-written
//! module `demcontact` in `include/demcontact.f90` re-exports all of it).

use std::fmt::Write as _;

use crate::cheader::{Api, Base, Func, Param};
use crate::shape::{is_array_param, is_pure, scalar_out};

fn f_kind(b: &Base) -> String {
    match b {
        Base::F64 => "real(c_double)".into(),
        Base::F32 => "real(c_float)".into(),
        Base::I32 | Base::U32 => "integer(c_int32_t)".into(),
        Base::I64 | Base::U64 => "integer(c_int64_t)".into(),
        Base::Usize => "integer(c_size_t)".into(),
        Base::Bool => "logical(c_bool)".into(),
        Base::Char | Base::Void => "type(c_ptr)".into(),
        Base::Named(n) => n.clone(),
    }
}

fn is_enum(api: &Api, b: &Base) -> bool {
    matches!(b, Base::Named(n) if api.enums.iter().any(|(e, _)| e == n))
}

fn f_type(api: &Api, b: &Base) -> String {
    match b {
        Base::Named(n) if is_enum(api, b) => {
            let _ = n;
            "integer(c_int)".into()
        }
        Base::Named(n) => format!("type({n})"),
        other => f_kind(other),
    }
}

fn f_dummy(api: &Api, f: &Func, p: &Param) -> String {
    let t = f_type(api, &p.ty.base);
    if !p.ty.ptr {
        return format!("{t}, value, intent(in) :: {}", p.name);
    }
    if matches!(p.ty.base, Base::Char | Base::Void) {
        return format!("type(c_ptr), value :: {}", p.name);
    }
    let intent = if p.ty.is_const {
        "in"
    } else if p.name.ends_with("out") {
        "out"
    } else {
        "inout"
    };
    let dims = if is_array_param(f, p) { "(*)" } else { "" };
    format!("{t}, intent({intent}) :: {}{dims}", p.name)
}

/// Fortran is case-insensitive: E1 and e1 would collide; rename later duplicates.
fn f_names(f: &Func) -> Vec<String> {
    let mut seen: Vec<String> = Vec::new();
    f.params
        .iter()
        .map(|p| {
            let mut n = p.name.clone();
            while seen.iter().any(|s| s.eq_ignore_ascii_case(&n)) || n.eq_ignore_ascii_case(&f.name)
            {
                n.push('_');
            }
            seen.push(n.clone());
            n
        })
        .collect()
}

fn wrap_args(names: &[String]) -> String {
    names.join(", ")
}

/// Writes `head(args)` broken into Fortran continuation lines.
fn f_line(out: &mut String, indent: &str, text: &str) {
    let mut line = String::from(indent);
    for (i, word) in text.split(' ').enumerate() {
        if line.len() + word.len() > 100 && i > 0 {
            out.push_str(&line);
            out.push_str(" &\n");
            line = format!("{indent}    ");
        } else if i > 0 {
            line.push(' ');
        }
        line.push_str(word);
    }
    out.push_str(&line);
    out.push('\n');
}
pub fn fortran(api: &Api) -> String {
    let mut o = String::new();
    o.push_str(
        "! Generated from include/demcontact.h by xtask (xtask/src/fortran.rs): do not edit by hand.\n",
    );
    o.push_str("! Regenerate: cargo run -p xtask -- bindings\n");
    o.push_str("!\n! bind(c) interfaces to every demcontact function, the constants as named parameters, the\n");
    o.push_str("! structs as bind(c) derived types, and impure elemental wrappers (status in `stat`) for\n");
    o.push_str("! the scalar functions. Use module `demcontact` (include/demcontact.f90), which re-exports it.\n");
    o.push_str("module demcontact_c\n  use, intrinsic :: iso_c_binding\n  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan\n  implicit none\n  private :: ieee_value, ieee_quiet_nan\n\n");
    for (n, v) in &api.consts {
        if v.contains('.') || v.contains('e') {
            let _ = writeln!(o, "  real(c_double), parameter :: {n} = {v}_c_double");
        } else {
            let _ = writeln!(o, "  integer(c_int32_t), parameter :: {n} = {v}");
        }
    }
    for (name, items) in &api.enums {
        let _ = writeln!(o, "\n  ! enum {name}");
        for (n, v) in items {
            let _ = writeln!(o, "  integer(c_int), parameter :: {n} = {v}");
        }
    }
    for (name, fields) in &api.structs {
        let _ = writeln!(o, "\n  type, bind(c) :: {name}");
        for f in fields {
            let dims = f.len.map(|l| format!("({l})")).unwrap_or_default();
            let t = if f.ty.ptr {
                "type(c_ptr)".to_string()
            } else {
                f_type(api, &f.ty.base)
            };
            let _ = writeln!(o, "    {t} :: {}{dims}", f.name);
        }
        let _ = writeln!(o, "  end type {name}");
    }
    o.push_str("\n  interface\n");
    for f in &api.funcs {
        let names = f_names(f);
        let pure = if is_pure(f) { "pure " } else { "" };
        let is_fn = f.ret.base != Base::Void || f.ret.ptr;
        let kind = if is_fn { "function" } else { "subroutine" };
        f_line(
            &mut o,
            "    ",
            &format!(
                "{pure}{kind} {}({}) bind(c, name='{}')",
                f.name,
                wrap_args(&names),
                f.name
            ),
        );
        o.push_str("      import\n");
        for (p, n) in f.params.iter().zip(&names) {
            let renamed = Param {
                ty: p.ty.clone(),
                name: n.clone(),
            };
            let _ = writeln!(o, "      {}", f_dummy(api, f, &renamed));
        }
        if is_fn {
            let rt = if f.ret.ptr {
                "type(c_ptr)".to_string()
            } else {
                f_type(api, &f.ret.base)
            };
            let _ = writeln!(o, "      {rt} :: {}", f.name);
        }
        let _ = writeln!(o, "    end {kind} {}", f.name);
    }
    o.push_str("  end interface\n\ncontains\n");
    for f in &api.funcs {
        let Some(out) = scalar_out(f) else { continue };
        let names = f_names(f);
        let short = f.name.trim_start_matches("dc_");
        let args: Vec<String> = names
            .iter()
            .cloned()
            .chain(std::iter::once("stat".to_string()))
            .collect();
        let _ = writeln!(
            o,
            "\n  !> Elemental form of {}: on error `{}` is NaN (numeric) and `stat` the status.",
            f.name, out.name
        );
        f_line(
            &mut o,
            "  ",
            &format!("impure elemental subroutine {short}({})", wrap_args(&args)),
        );
        let (last_name, in_names) = names.split_last().expect("has out");
        for (p, n) in f.params.iter().zip(&names) {
            let t = f_type(api, &p.ty.base);
            if n == last_name {
                let _ = writeln!(o, "    {t}, intent(out) :: {n}");
            } else {
                let _ = writeln!(o, "    {t}, intent(in) :: {n}");
            }
        }
        o.push_str(
            "    integer(c_int32_t), intent(out), optional :: stat\n    integer(c_int32_t) :: s\n",
        );
        f_line(
            &mut o,
            "    ",
            &format!("s = {}({}, {last_name})", f.name, wrap_args(in_names)),
        );
        o.push_str("    if (present(stat)) stat = s\n");
        if matches!(out.ty.base, Base::F64) {
            let _ = writeln!(
                o,
                "    if (s /= DC_OK) {last_name} = ieee_value({last_name}, ieee_quiet_nan)"
            );
        }
        let _ = writeln!(o, "  end subroutine {short}");
    }
    for f in &api.funcs {
        if !is_pure(f) || f.ret.base != Base::F64 || f.ret.ptr {
            continue;
        }
        let names = f_names(f);
        let short = f.name.trim_start_matches("dc_");
        let _ = writeln!(
            o,
            "\n  !> Elemental form of {} (pure: arrays of contacts in one call).",
            f.name
        );
        f_line(
            &mut o,
            "  ",
            &format!(
                "elemental function {short}({}) result(r)",
                wrap_args(&names)
            ),
        );
        for (p, n) in f.params.iter().zip(&names) {
            let _ = writeln!(o, "    {}, intent(in) :: {n}", f_type(api, &p.ty.base));
        }
        o.push_str("    real(c_double) :: r\n");
        f_line(
            &mut o,
            "    ",
            &format!("r = {}({})", f.name, wrap_args(&names)),
        );
        let _ = writeln!(o, "  end function {short}");
    }
    o.push_str("end module demcontact_c\n");
    o
}
