//! The ABI as a list of lines, one per symbol, to check that the header only ever grows:
//! `const NAME = VALUE` for every constant (a `#define` and an item of a fixed-type enum with the
//! same name and value give the same line), `struct NAME { TYPE FIELD; .. }` with every field in
//! order, and `fn NAME(TYPES) -> TYPE` with type aliases resolved to their C types (parameter
//! names are not part of the ABI and are left out).

use crate::cheader::{Api, c_type};

/// One line per constant, struct and function of `api`, in header order.
pub fn symbols(api: &Api) -> Vec<String> {
    let mut out = Vec::new();
    for (n, v) in &api.consts {
        out.push(format!("const {n} = {v}"));
    }
    for (_, items) in &api.enums {
        for (n, v) in items {
            out.push(format!("const {n} = {v}"));
        }
    }
    for (name, fields) in &api.structs {
        let fields: Vec<String> = fields
            .iter()
            .map(|f| {
                let len = f.len.map(|l| format!("[{l}]")).unwrap_or_default();
                format!("{} {}{len};", c_type(&f.ty), f.name)
            })
            .collect();
        out.push(format!("struct {name} {{ {} }}", fields.join(" ")));
    }
    for f in &api.funcs {
        let params: Vec<String> = f.params.iter().map(|p| c_type(&p.ty)).collect();
        out.push(format!(
            "fn {}({}) -> {}",
            f.name,
            params.join(", "),
            c_type(&f.ret)
        ));
    }
    out
}

/// `kind NAME` of a symbol line.
fn key(line: &str) -> String {
    let mut it = line.split([' ', '(']);
    format!("{} {}", it.next().unwrap_or(""), it.next().unwrap_or(""))
}

/// Every line of `baseline` (blank lines and `#` comments skipped) that is not in `current`,
/// each followed by what the current header has under that name, if anything.
pub fn removed_or_changed(baseline: &str, current: &[String]) -> Vec<String> {
    baseline
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .filter(|l| !current.iter().any(|c| c == l))
        .map(|l| match current.iter().find(|c| key(c) == key(l)) {
            Some(now) => format!("changed: {l}\n     now: {now}"),
            None => format!("removed: {l}"),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cheader::parse;

    const V0: &str = "#define DC_OK 0\n#define DC_ERR_NAN 6101\n\
        typedef struct dc_e { double a; double b[2]; } dc_e;\n\
        int32_t dc_f(double x, const dc_e *e, double *out);\n";

    #[test]
    fn additions_pass_and_changes_fail() {
        let base = symbols(&parse(V0).expect("v0")).join("\n");
        let grown = "enum dc_status {\n DC_OK = 0,\n DC_ERR_NAN = 6101,\n DC_ERR_NEW = 6102,\n};\n\
            typedef int32_t dc_status;\n\
            typedef struct dc_e { double a; double b[2]; } dc_e;\n\
            dc_status dc_f(double y, const dc_e *e, double *out);\nint32_t dc_g(void);\n";
        let now = symbols(&parse(grown).expect("grown"));
        assert_eq!(removed_or_changed(&base, &now), Vec::<String>::new());
        for broken in [
            V0.replace("6101", "6102"),
            V0.replace("double b[2]", "double b[3]"),
            V0.replace("double a; double b[2];", "double b[2]; double a;"),
            V0.replace("const dc_e *e", "dc_e *e"),
            V0.replace("int32_t dc_f", "int64_t dc_f"),
            V0.replace("dc_f(", "dc_h("),
        ] {
            let now = symbols(&parse(&broken).expect("broken parses"));
            assert_eq!(removed_or_changed(&base, &now).len(), 1, "{broken}");
        }
    }
}
