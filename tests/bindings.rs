//! Keeps the Fortran module and the C++ wrapper in step with the C header, automatically.
//!
//! Parses the cbindgen-generated `include/demcontact.h` (constants, structs, enums, functions)
//! and generates:
//! * `include/demcontact_c.f90`: module `demcontact_c` with every constant as a named parameter,
//!   every struct as a `bind(c)` derived type, a `bind(c)` interface for every function, and
//!   `impure elemental` status-returning wrappers for the scalar functions (the hand-written
//!   module `demcontact` in `include/demcontact.f90` re-exports all of it);
//! * `include/demcontact_generated.hpp`: the C++17 enums and value-returning / `noexcept` wrappers,
//!   included by the hand-written `include/demcontact.hpp`;
//! * `docs/api.md`: the written contract of every function (its header doc comment), in one page;
//! * `c_tests/fortran/abi_probe.c` and `c_tests/fortran/abi_expect.f90`: a C probe reporting every
//!   constant, struct size and field offset as the C compiler sees them, and the Fortran side that
//!   compares them with the module (run by ctest as `fortran_abi`).
//!
//! The committed files must equal the generated ones; regenerate with
//! `DC_BLESS=1 cargo test --test bindings` (after regenerating the header).

use std::fmt::Write as _;
use std::path::Path;

#[derive(Clone, Debug, PartialEq)]
enum Base {
    F64,
    F32,
    I32,
    U32,
    I64,
    U64,
    Usize,
    Bool,
    Char,
    Void,
    Named(String),
}

#[derive(Clone, Debug)]
struct Ty {
    base: Base,
    is_const: bool,
    ptr: bool,
}

#[derive(Clone, Debug)]
struct Param {
    ty: Ty,
    name: String,
}

#[derive(Clone, Debug)]
struct Func {
    ret: Ty,
    name: String,
    params: Vec<Param>,
}

#[derive(Clone, Debug)]
struct Field {
    ty: Ty,
    name: String,
    len: Option<usize>,
}

#[derive(Default, Debug)]
struct Api {
    consts: Vec<(String, String)>,
    structs: Vec<(String, Vec<Field>)>,
    enums: Vec<(String, Vec<(String, String)>)>,
    funcs: Vec<Func>,
}

fn strip_comments(src: &str) -> String {
    let mut out = String::new();
    let mut rest = src;
    while let Some(i) = rest.find("/*") {
        out.push_str(&rest[..i]);
        rest = match rest[i..].find("*/") {
            Some(j) => &rest[i + j + 2..],
            None => "",
        };
    }
    out.push_str(rest);
    out.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

fn parse_base(s: &str, api_types: &[String]) -> Base {
    match s {
        "double" => Base::F64,
        "float" => Base::F32,
        "int32_t" => Base::I32,
        "uint32_t" => Base::U32,
        "int64_t" => Base::I64,
        "uint64_t" => Base::U64,
        "size_t" | "uintptr_t" => Base::Usize,
        "bool" => Base::Bool,
        "char" => Base::Char,
        "void" => Base::Void,
        other if api_types.iter().any(|t| t == other) => Base::Named(other.to_string()),
        other => panic!("bindings generator: unknown C type `{other}`"),
    }
}

/// "const double *x" → (Ty, "x")
fn parse_decl(decl: &str, api_types: &[String]) -> (Ty, String) {
    let decl = decl.replace('*', " * ");
    let toks: Vec<&str> = decl.split_whitespace().collect();
    let name = toks.last().expect("declaration has a name").to_string();
    let is_const = toks.contains(&"const");
    let ptr = toks.contains(&"*");
    let base = toks
        .iter()
        .rev()
        .skip(1)
        .find(|t| **t != "*" && **t != "const")
        .expect("type");
    (
        Ty {
            base: parse_base(base, api_types),
            is_const,
            ptr,
        },
        name,
    )
}

fn parse(header: &str) -> Api {
    let mut api = Api::default();
    // Drop the C++ extern "C" guards and every preprocessor line but the value #defines.
    let mut body = String::new();
    let mut skip = false;
    for line in strip_comments(header).lines() {
        let t = line.trim();
        if t.starts_with("#ifdef __cplusplus") {
            skip = true;
            continue;
        }
        if skip {
            if t.starts_with("#endif") {
                skip = false;
            }
            continue;
        }
        if let Some(rest) = t.strip_prefix("#define ") {
            let mut it = rest.split_whitespace();
            if let (Some(n), Some(v)) = (it.next(), it.next()) {
                api.consts.push((n.to_string(), v.to_string()));
            }
            continue;
        }
        if t.starts_with('#') {
            continue;
        }
        body.push_str(line);
        body.push('\n');
    }
    // Statements end at ';' outside braces.
    let mut stmts = Vec::new();
    let (mut depth, mut cur) = (0, String::new());
    for c in body.chars() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            _ => {}
        }
        if c == ';' && depth == 0 {
            stmts.push(std::mem::take(&mut cur));
        } else {
            cur.push(c);
        }
    }
    let norm = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    // Type names first, so that functions can refer to them.
    let mut types: Vec<String> = Vec::new();
    for s in &stmts {
        let s = norm(s);
        if s.starts_with("typedef") {
            types.push(s.rsplit(' ').next().expect("typedef name").to_string());
        }
    }
    for s in stmts {
        let s = norm(&s);
        if s.is_empty() {
            continue;
        }
        if let Some(rest) = s.strip_prefix("typedef struct ") {
            let open = rest.find('{').expect("struct body");
            let close = rest.rfind('}').expect("struct end");
            let name = rest[close + 1..].trim().to_string();
            let mut fields = Vec::new();
            for f in rest[open + 1..close]
                .split(';')
                .map(str::trim)
                .filter(|f| !f.is_empty())
            {
                let (decl, len) = match f.find('[') {
                    Some(i) => (
                        &f[..i],
                        Some(
                            f[i + 1..f.len() - 1]
                                .trim()
                                .parse::<usize>()
                                .expect("array length"),
                        ),
                    ),
                    None => (f, None),
                };
                let (ty, fname) = parse_decl(decl, &types);
                fields.push(Field {
                    ty,
                    name: fname,
                    len,
                });
            }
            api.structs.push((name, fields));
        } else if let Some(rest) = s.strip_prefix("typedef enum ") {
            let open = rest.find('{').expect("enum body");
            let close = rest.rfind('}').expect("enum end");
            let name = rest[close + 1..].trim().to_string();
            let mut next = 0i64;
            let mut items = Vec::new();
            for item in rest[open + 1..close]
                .split(',')
                .map(str::trim)
                .filter(|f| !f.is_empty())
            {
                let (n, v) = match item.split_once('=') {
                    Some((n, v)) => (n.trim(), v.trim().parse::<i64>().expect("enum value")),
                    None => (item, next),
                };
                items.push((n.to_string(), v.to_string()));
                next = v + 1;
            }
            api.enums.push((name, items));
        } else if let Some(open) = s.find('(') {
            let close = s.rfind(')').expect("function end");
            let (ret, name) = parse_decl(&s[..open], &types);
            let inner = s[open + 1..close].trim();
            let params = if inner == "void" || inner.is_empty() {
                Vec::new()
            } else {
                inner
                    .split(',')
                    .map(|p| {
                        let (ty, name) = parse_decl(p, &types);
                        Param { ty, name }
                    })
                    .collect()
            };
            api.funcs.push(Func { ret, name, params });
        } else {
            panic!("bindings generator: cannot parse `{s}`");
        }
    }
    api
}

// ------------------------------------------------------------------ Fortran

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

/// Struct pointers are single objects (arrays only when plural and counted); numeric pointers
/// are arrays in functions that take a count (size_t) or read an input array (`const double *`),
/// otherwise `*_out` pointers are scalar outputs.
fn is_array_param(f: &Func, p: &Param) -> bool {
    if !p.ty.ptr || matches!(p.ty.base, Base::Char | Base::Void) {
        return false;
    }
    let counted = f
        .params
        .iter()
        .any(|q| q.ty.base == Base::Usize && !q.ty.ptr);
    if matches!(p.ty.base, Base::Named(_)) {
        return p.name.ends_with('s') && counted;
    }
    let reads_array = f.params.iter().any(|q| {
        q.ty.ptr && q.ty.is_const && !matches!(q.ty.base, Base::Named(_) | Base::Char | Base::Void)
    });
    counted || reads_array || !p.name.ends_with("_out")
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

fn is_pure(f: &Func) -> bool {
    // Functions that return a value and write through no pointer are pure in Fortran's sense.
    f.ret.base != Base::Void && !f.ret.ptr && f.params.iter().all(|p| !p.ty.ptr || p.ty.is_const)
}

/// Scalar status functions: by-value inputs (and const struct pointers) and one trailing scalar
/// `*_out`; these get an elemental wrapper.
fn scalar_out(f: &Func) -> Option<&Param> {
    if f.ret.base != Base::I32 || f.ret.ptr {
        return None;
    }
    let (last, rest) = f.params.split_last()?;
    let named_out = last.name == "out" || last.name.ends_with("_out");
    let ok_last = last.ty.ptr && !last.ty.is_const && named_out && !is_array_param(f, last);
    let ok_rest = rest
        .iter()
        .all(|p| !p.ty.ptr || (p.ty.is_const && matches!(p.ty.base, Base::Named(_))));
    let no_count = !f.params.iter().any(|p| p.ty.base == Base::Usize);
    (ok_last && ok_rest && no_count).then_some(last)
}

fn fortran(api: &Api) -> String {
    let mut o = String::new();
    o.push_str(
        "! Generated by tests/bindings.rs from include/demcontact.h: do not edit by hand.\n",
    );
    o.push_str("! Regenerate: DC_BLESS=1 cargo test --test bindings\n");
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

// ------------------------------------------------------------------ ABI probe (C + Fortran)

fn probe_c(api: &Api) -> String {
    let mut o = String::new();
    o.push_str(
        "/* Generated by tests/bindings.rs: do not edit. What the C compiler sees of the ABI. */\n",
    );
    o.push_str("#include <demcontact.h>\n#include <stddef.h>\n#include <stdint.h>\n\n");
    let ints: Vec<&(String, String)> = api
        .consts
        .iter()
        .filter(|(_, v)| !(v.contains('.') || v.contains('e')))
        .collect();
    let _ = writeln!(
        o,
        "int32_t dc_probe_n_consts(void) {{ return {}; }}",
        ints.len()
    );
    o.push_str("int64_t dc_probe_const(int32_t i) {\n  switch (i) {\n");
    for (i, (n, _)) in ints.iter().enumerate() {
        let _ = writeln!(o, "  case {}: return (int64_t)({n});", i + 1);
    }
    o.push_str("  default: return INT64_MIN;\n  }\n}\n");
    let mut layout = Vec::new();
    for (s, fields) in &api.structs {
        layout.push(format!("sizeof({s})"));
        for f in fields {
            layout.push(format!("offsetof({s}, {})", f.name));
        }
    }
    let _ = writeln!(
        o,
        "int32_t dc_probe_n_layout(void) {{ return {}; }}",
        layout.len()
    );
    o.push_str("int64_t dc_probe_layout(int32_t i) {\n  switch (i) {\n");
    for (i, l) in layout.iter().enumerate() {
        let _ = writeln!(o, "  case {}: return (int64_t){l};", i + 1);
    }
    o.push_str("  default: return INT64_MIN;\n  }\n}\n");
    o
}

fn probe_f90(api: &Api) -> String {
    let mut o = String::new();
    o.push_str("! Generated by tests/bindings.rs: do not edit. The module's view of the ABI, in the same\n");
    o.push_str(
        "! order as c_tests/fortran/abi_probe.c; c_tests/fortran/test_fortran.f90 compares them.\n",
    );
    o.push_str("module abi_expect\n  use demcontact\n  implicit none\ncontains\n");
    o.push_str("  subroutine expected_consts(v, n)\n    integer(c_int64_t), intent(out) :: v(:)\n    integer, intent(out) :: n\n");
    let ints: Vec<&(String, String)> = api
        .consts
        .iter()
        .filter(|(_, v)| !(v.contains('.') || v.contains('e')))
        .collect();
    for (i, (n, _)) in ints.iter().enumerate() {
        let _ = writeln!(o, "    v({}) = {n}", i + 1);
    }
    let _ = writeln!(
        o,
        "    n = {}\n  end subroutine expected_consts\n",
        ints.len()
    );
    o.push_str("  subroutine expected_layout(v, n)\n    integer(c_int64_t), intent(out) :: v(:)\n    integer, intent(out) :: n\n");
    let mut i = 0;
    for (s, fields) in &api.structs {
        let var = format!("x_{s}");
        let _ = writeln!(o, "    block\n      type({s}), target :: {var}");
        i += 1;
        let _ = writeln!(o, "      v({i}) = c_sizeof({var})");
        for f in fields {
            i += 1;
            let elem = if f.len.is_some() { "(1)" } else { "" };
            let _ = writeln!(
                o,
                "      v({i}) = transfer(c_loc({var}%{}{elem}), 0_c_intptr_t) &\n          - transfer(c_loc({var}), 0_c_intptr_t)",
                f.name
            );
        }
        o.push_str("    end block\n");
    }
    let _ = writeln!(
        o,
        "    n = {i}\n  end subroutine expected_layout\nend module abi_expect"
    );
    o
}

// ------------------------------------------------------------------ C++

fn cpp_type(b: &Base) -> String {
    match b {
        Base::F64 => "double".into(),
        Base::F32 => "float".into(),
        Base::I32 => "std::int32_t".into(),
        Base::U32 => "std::uint32_t".into(),
        Base::I64 => "std::int64_t".into(),
        Base::U64 => "std::uint64_t".into(),
        Base::Usize => "std::size_t".into(),
        Base::Bool => "bool".into(),
        Base::Char => "char".into(),
        Base::Void => "void".into(),
        Base::Named(n) => format!("::{n}"),
    }
}

fn snake_from_err(name: &str) -> String {
    name.trim_start_matches("DC_ERR_")
        .trim_start_matches("DC_")
        .to_ascii_lowercase()
}

fn cpp(api: &Api) -> String {
    let mut o = String::new();
    o.push_str(
        "// Generated by tests/bindings.rs from include/demcontact.h: do not edit by hand.\n",
    );
    o.push_str("// Included by include/demcontact.hpp, which defines demcontact::error and detail::check.\n");
    o.push_str("#pragma once\n\nnamespace demcontact {\n\n");
    o.push_str("/// Every status of the C API (DC_OK and the DC_ERR_* codes).\nenum class status : std::int32_t {\n");
    for (n, _) in api
        .consts
        .iter()
        .filter(|(n, _)| n == "DC_OK" || n.starts_with("DC_ERR_"))
    {
        let _ = writeln!(o, "    {} = {n},", snake_from_err(n));
    }
    o.push_str("};\n\n/// End-of-contact criterion.\nenum class criterion : std::int32_t {\n");
    for (n, _) in api.consts.iter().filter(|(n, _)| n.starts_with("DC_END_")) {
        let _ = writeln!(
            o,
            "    {} = {n},",
            n.trim_start_matches("DC_END_").to_ascii_lowercase()
        );
    }
    o.push_str("};\n");
    let param_cpp = |p: &Param| -> (String, String) {
        // (declaration in the wrapper, expression passed to C)
        if p.name == "criterion" && p.ty.base == Base::I32 && !p.ty.ptr {
            return (
                "criterion criterion_".into(),
                "static_cast<std::int32_t>(criterion_)".into(),
            );
        }
        if p.ty.ptr && p.ty.is_const && matches!(p.ty.base, Base::Named(_)) {
            return (
                format!("const {}& {}", cpp_type(&p.ty.base), p.name),
                format!("&{}", p.name),
            );
        }
        (
            format!("{} {}", cpp_type(&p.ty.base), p.name),
            p.name.clone(),
        )
    };
    for f in &api.funcs {
        let short = f.name.trim_start_matches("dc_");
        if let Some(out) = scalar_out(f) {
            let ins = &f.params[..f.params.len() - 1];
            let decls: Vec<String> = ins.iter().map(|p| param_cpp(p).0).collect();
            let exprs: Vec<String> = ins.iter().map(|p| param_cpp(p).1).collect();
            let ot = cpp_type(&out.ty.base);
            let mut call_args = exprs.clone();
            call_args.push("&out".into());
            let _ = writeln!(
                o,
                "\n/// {}: throws demcontact::error on a non-OK status.",
                f.name
            );
            let _ = writeln!(
                o,
                "inline {ot} {short}({}) {{\n    {ot} out{{}};\n    detail::check(::{}({}));\n    return out;\n}}",
                decls.join(", "),
                f.name,
                call_args.join(", ")
            );
            let mut decls2 = decls.clone();
            decls2.push(format!("{ot}& out"));
            let _ = writeln!(
                o,
                "/// {}: returns the status; `out` is written only on status::ok.",
                f.name
            );
            let _ = writeln!(
                o,
                "inline status {short}({}) noexcept {{\n    return static_cast<status>(::{}({}));\n}}",
                decls2.join(", "),
                f.name,
                call_args.join(", ")
            );
        } else if is_pure(f) && !f.ret.ptr && f.ret.base != Base::Char {
            let decls: Vec<String> = f.params.iter().map(|p| param_cpp(p).0).collect();
            let exprs: Vec<String> = f.params.iter().map(|p| param_cpp(p).1).collect();
            let rt = cpp_type(&f.ret.base);
            let _ = writeln!(o, "\n/// {} (no status: see the C documentation).", f.name);
            let _ = writeln!(
                o,
                "inline {rt} {short}({}) noexcept {{\n    return ::{}({});\n}}",
                decls.join(", "),
                f.name,
                exprs.join(", ")
            );
        }
    }
    o.push_str("\n}  // namespace demcontact\n");
    o
}

/// docs/api.md: every constant and function of the header with its doc comment (the written
/// contract: ranges, units, statuses, precision), in header order.
fn api_doc(header: &str) -> String {
    let mut o = String::new();
    o.push_str("# C API reference\n\n");
    o.push_str(
        "Generated by `tests/bindings.rs` from the doc comments of `include/demcontact.h` (which\n",
    );
    o.push_str("cbindgen generates from the Rust sources); checked fresh by `cargo test --test bindings`.\n");
    o.push_str(
        "Conventions shared by all functions are in the header's opening comment and the README.\n",
    );
    let mut doc: Vec<String> = Vec::new();
    let mut in_doc = false;
    let mut in_plain = false;
    let mut decl = String::new();
    let mut consts = String::new();
    let mut funcs = String::new();
    let mut structs = String::new();
    for line in header.lines() {
        let t = line.trim();
        if t.starts_with("/**") {
            in_doc = true;
            doc.clear();
            continue;
        }
        if t.starts_with("/*") {
            // An ordinary comment (file header, autogen note): skipped.
            in_plain = !t.contains("*/");
            continue;
        }
        if in_plain {
            in_plain = !t.contains("*/");
            continue;
        }
        if in_doc {
            if t.starts_with("*/") {
                in_doc = false;
            } else {
                let l = t.trim_start_matches('*').trim_start();
                // Doxygen tags become list items; "# Safety" (rustdoc) must not become a heading.
                let l = if let Some(r) = l.strip_prefix("@param ") {
                    let (name, rest) = r.trim_start().split_once(' ').unwrap_or((r, ""));
                    format!("- **`{name}`**: {}", rest.trim_start())
                } else if let Some(r) = l.strip_prefix("@return ") {
                    format!("- **returns**: {r}")
                } else if l == "# Safety" {
                    "**Safety.**".to_string()
                } else {
                    l.to_string()
                };
                doc.push(l);
            }
            continue;
        }
        if let Some(rest) = t.strip_prefix("#define ") {
            let mut it = rest.split_whitespace();
            if let (Some(n), Some(v)) = (it.next(), it.next()) {
                let _ = writeln!(
                    consts,
                    "| `{n}` | `{v}` | {} |",
                    doc.join(" ").replace('|', "\\|")
                );
            }
            doc.clear();
            continue;
        }
        if t.starts_with("typedef struct") {
            let name = t
                .trim_start_matches("typedef struct")
                .trim()
                .trim_end_matches('{')
                .trim();
            let _ = writeln!(structs, "\n### `{name}`\n\n{}\n", doc.join("\n"));
            doc.clear();
            continue;
        }
        if !decl.is_empty()
            || (t.contains("dc_") && t.contains('(') && !t.starts_with('#') && !t.starts_with("//"))
        {
            decl.push_str(t);
            decl.push(' ');
            if t.ends_with(';') {
                let sig = decl
                    .split_whitespace()
                    .collect::<Vec<_>>()
                    .join(" ")
                    .replace("( ", "(");
                let name = sig
                    .split('(')
                    .next()
                    .unwrap_or("")
                    .rsplit(' ')
                    .next()
                    .unwrap_or("")
                    .trim_start_matches('*');
                let _ = writeln!(
                    funcs,
                    "\n### `{name}`\n\n```c\n{sig}\n```\n\n{}",
                    doc.join("\n")
                );
                decl.clear();
                doc.clear();
            }
        }
    }
    o.push_str("\n## Constants\n\n| name | value | meaning |\n|---|---|---|\n");
    o.push_str(&consts);
    if !structs.is_empty() {
        o.push_str("\n## Structs\n");
        o.push_str(&structs);
    }
    o.push_str("\n## Functions\n");
    o.push_str(&funcs);
    o
}

fn check_or_bless(path: &Path, fresh: &str) -> Option<String> {
    if std::env::var_os("DC_BLESS").is_some() {
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).expect("create dir");
        }
        std::fs::write(path, fresh).expect("write generated file");
        return None;
    }
    let committed = std::fs::read_to_string(path).unwrap_or_default();
    (committed != fresh).then(|| path.display().to_string())
}

#[test]
fn generated_bindings_are_fresh() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let header = std::fs::read_to_string(root.join("include/demcontact.h")).expect("header");
    let api = parse(&header);
    assert!(
        api.funcs.iter().any(|f| f.name == "dc_alpha_from_e"),
        "parser found no functions"
    );
    let stale: Vec<String> = [
        (root.join("include/demcontact_c.f90"), fortran(&api)),
        (root.join("include/demcontact_generated.hpp"), cpp(&api)),
        (root.join("c_tests/fortran/abi_probe.c"), probe_c(&api)),
        (root.join("c_tests/fortran/abi_expect.f90"), probe_f90(&api)),
        (root.join("docs/api.md"), api_doc(&header)),
    ]
    .iter()
    .filter_map(|(p, s)| check_or_bless(p, s))
    .collect();
    assert!(
        stale.is_empty(),
        "stale generated bindings {stale:?}: run `DC_BLESS=1 cargo test --test bindings` and commit"
    );
}

#[test]
fn every_function_has_a_fortran_interface() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let header = std::fs::read_to_string(root.join("include/demcontact.h")).expect("header");
    let api = parse(&header);
    // Long interfaces are continued with `&`: join continuation lines before searching.
    let f90 = fortran(&api)
        .replace("&\n", " ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    for f in &api.funcs {
        assert!(
            f90.contains(&format!("name='{}')", f.name)),
            "{} missing",
            f.name
        );
    }
}
