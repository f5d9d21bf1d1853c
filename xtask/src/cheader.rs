//! A parser for the subset of C that cbindgen writes into `include/demcontact.h`: value
//! `#define`s, structs, enums (plain, `typedef enum`, and the fixed-type form
//! `enum X { .. }; typedef int32_t X;` of a `#[repr(i32)]` Rust enum), type aliases and function
//! prototypes. Anything else is an error naming the statement, so that a header the generators
//! do not understand cannot produce silently incomplete bindings.

use std::collections::BTreeMap;

/// The C scalar types the ABI uses; `Named` is a struct or a plain C enum of the header.
#[derive(Clone, Debug, PartialEq)]
pub enum Base {
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
pub struct Ty {
    pub base: Base,
    pub is_const: bool,
    pub ptr: bool,
}

#[derive(Clone, Debug)]
pub struct Param {
    pub ty: Ty,
    pub name: String,
}

#[derive(Clone, Debug)]
pub struct Func {
    pub ret: Ty,
    pub name: String,
    pub params: Vec<Param>,
}

#[derive(Clone, Debug)]
pub struct Field {
    pub ty: Ty,
    pub name: String,
    pub len: Option<usize>,
}

/// Everything the generators need from the header, in header order.
#[derive(Default, Debug)]
pub struct Api {
    /// Named integer and floating constants: the `#define`s and the items of fixed-type enums
    /// (`enum dc_status { DC_OK = 0, .. }; typedef int32_t dc_status;`), which are the same
    /// constants to every consumer (same name, same value, type int32_t).
    pub consts: Vec<(String, String)>,
    pub structs: Vec<(String, Vec<Field>)>,
    /// Plain C enums (type `int`), kept as enums.
    pub enums: Vec<(String, Vec<(String, String)>)>,
    pub funcs: Vec<Func>,
}

/// Parse error: the statement that could not be understood and why.
#[derive(Debug)]
pub struct ParseError(pub String);

impl std::fmt::Display for ParseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "header parser: {}", self.0)
    }
}

impl std::error::Error for ParseError {}

fn err<T>(msg: String) -> Result<T, ParseError> {
    Err(ParseError(msg))
}

/// Removes `/* .. */` and `// ..` comments.
pub fn strip_comments(src: &str) -> String {
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

fn builtin_base(s: &str) -> Option<Base> {
    Some(match s {
        "double" => Base::F64,
        "float" => Base::F32,
        "int32_t" | "int" => Base::I32,
        "uint32_t" => Base::U32,
        "int64_t" => Base::I64,
        "uint64_t" => Base::U64,
        "size_t" | "uintptr_t" => Base::Usize,
        "bool" => Base::Bool,
        "char" => Base::Char,
        "void" => Base::Void,
        _ => return None,
    })
}

struct Types {
    /// Struct and plain-enum names.
    named: Vec<String>,
    /// `typedef <builtin> NAME;` aliases, resolved to the builtin (ABI-identical).
    aliases: BTreeMap<String, Base>,
}

impl Types {
    fn base(&self, s: &str) -> Result<Base, ParseError> {
        if let Some(b) = builtin_base(s) {
            return Ok(b);
        }
        if let Some(b) = self.aliases.get(s) {
            return Ok(b.clone());
        }
        if self.named.iter().any(|t| t == s) {
            return Ok(Base::Named(s.to_string()));
        }
        err(format!("unknown C type `{s}`"))
    }

    /// "const double *x" → (Ty, "x")
    fn decl(&self, decl: &str) -> Result<(Ty, String), ParseError> {
        let spaced = decl.replace('*', " * ");
        let toks: Vec<&str> = spaced
            .split_whitespace()
            .filter(|t| *t != "struct" && *t != "enum")
            .collect();
        let Some((name, front)) = toks.split_last() else {
            return err(format!("empty declaration `{decl}`"));
        };
        let Some(base) = front.iter().rev().find(|t| **t != "*" && **t != "const") else {
            return err(format!("declaration without a type `{decl}`"));
        };
        Ok((
            Ty {
                base: self.base(base)?,
                is_const: front.contains(&"const"),
                ptr: front.contains(&"*"),
            },
            name.to_string(),
        ))
    }
}

/// Splits `{ .. }` out of `head { body } tail`.
fn braces(s: &str) -> Result<(&str, &str, &str), ParseError> {
    match (s.find('{'), s.rfind('}')) {
        (Some(o), Some(c)) if o < c => Ok((s[..o].trim(), &s[o + 1..c], s[c + 1..].trim())),
        _ => err(format!("expected a braced body in `{s}`")),
    }
}

fn enum_items(body: &str) -> Result<Vec<(String, String)>, ParseError> {
    let mut next = 0i64;
    let mut items = Vec::new();
    for item in body.split(',').map(str::trim).filter(|f| !f.is_empty()) {
        let (n, v) = match item.split_once('=') {
            Some((n, v)) => match v.trim().parse::<i64>() {
                Ok(v) => (n.trim(), v),
                Err(_) => return err(format!("enum value `{item}` is not an integer literal")),
            },
            None => (item, next),
        };
        items.push((n.to_string(), v.to_string()));
        next = v + 1;
    }
    Ok(items)
}

/// `#ifdef NAME` as a C99 compiler sees it: only the header's own guard can be asked about.
fn defined_in_c99(name: &str) -> Result<bool, ParseError> {
    match name {
        "__cplusplus" => Ok(false),
        n if n.ends_with("_H") => Ok(false),
        other => err(format!("unknown macro `{other}` in a conditional")),
    }
}

/// `#if` expressions cbindgen writes: `||`-joined `defined(__cplusplus)` and
/// `__STDC_VERSION__ >= N` terms, evaluated for C99 (`__STDC_VERSION__` = 199901L).
fn eval_c99(expr: &str) -> Result<bool, ParseError> {
    let mut any = false;
    for term in expr.split("||").map(str::trim) {
        let v = if let Some(n) = term
            .strip_prefix("defined(")
            .and_then(|r| r.strip_suffix(')'))
        {
            defined_in_c99(n.trim())?
        } else if let Some(n) = term.strip_prefix("__STDC_VERSION__ >=") {
            match n.trim().trim_end_matches('L').parse::<i64>() {
                Ok(n) => 199_901 >= n,
                Err(_) => return err(format!("cannot evaluate `#if {expr}`")),
            }
        } else {
            return err(format!("cannot evaluate `#if {expr}`"));
        };
        any |= v;
    }
    Ok(any)
}

/// Parses the header text.
pub fn parse(header: &str) -> Result<Api, ParseError> {
    let mut api = Api::default();
    // Read the header as a C99 compiler does: the C++-only and C23-only branches (extern "C"
    // guards, an enum's `: int32_t`, `typedef enum X X`) are dropped; of the other preprocessor
    // lines only the value #defines are kept.
    let mut body = String::new();
    // One entry per open conditional: (this branch is taken, an earlier branch was taken).
    let mut conds: Vec<(bool, bool)> = Vec::new();
    for line in strip_comments(header).lines() {
        let t = line.trim();
        if let Some(d) = t.strip_prefix('#') {
            let d = d.trim_start();
            let word = d.split_whitespace().next().unwrap_or("");
            let arg = d[word.len()..].trim();
            match word {
                "ifdef" | "ifndef" | "if" => {
                    let v = match word {
                        "ifdef" => defined_in_c99(arg)?,
                        "ifndef" => !defined_in_c99(arg)?,
                        _ => eval_c99(arg)?,
                    };
                    conds.push((v, v));
                    continue;
                }
                "elif" | "else" => {
                    let Some(top) = conds.last_mut() else {
                        return err(format!("`#{word}` without `#if`"));
                    };
                    let v = !top.1 && (word == "else" || eval_c99(arg)?);
                    *top = (v, top.1 || v);
                    continue;
                }
                "endif" => {
                    if conds.pop().is_none() {
                        return err("`#endif` without `#if`".into());
                    }
                    continue;
                }
                _ => {}
            }
        }
        if !conds.iter().all(|c| c.0) {
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
    let (mut depth, mut cur) = (0i32, String::new());
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
    let stmts: Vec<String> = stmts
        .iter()
        .map(|s| s.split_whitespace().collect::<Vec<_>>().join(" "))
        .filter(|s| !s.is_empty())
        .collect();
    // Type names first, so that declarations can refer to types defined later.
    let mut types = Types {
        named: Vec::new(),
        aliases: BTreeMap::new(),
    };
    for s in &stmts {
        if s.starts_with("typedef") && !s.contains('{') {
            // typedef <type> NAME
            let toks: Vec<&str> = s.split_whitespace().collect();
            if let [_, .., ty, name] = toks.as_slice() {
                match builtin_base(ty) {
                    Some(b) => {
                        types.aliases.insert(name.to_string(), b);
                    }
                    None => types.named.push(name.to_string()),
                }
            }
        } else if s.starts_with("typedef") {
            if let Some(name) = s.rsplit(' ').next() {
                types.named.push(name.to_string());
            }
        } else if let Some(name) = s
            .strip_prefix("enum ")
            .or_else(|| s.strip_prefix("struct "))
            .and_then(|rest| rest.split([' ', '{']).next())
        {
            types.named.push(name.to_string());
        }
    }
    for s in &stmts {
        if let Some(rest) = s.strip_prefix("typedef struct ") {
            let (_, fields_src, name) = braces(rest)?;
            let mut fields = Vec::new();
            for f in fields_src
                .split(';')
                .map(str::trim)
                .filter(|f| !f.is_empty())
            {
                let (decl, len) = match f.find('[') {
                    Some(i) => match f[i + 1..f.len() - 1].trim().parse::<usize>() {
                        Ok(n) => (&f[..i], Some(n)),
                        Err(_) => return err(format!("array length in `{f}`")),
                    },
                    None => (f, None),
                };
                let (ty, fname) = types.decl(decl)?;
                fields.push(Field {
                    ty,
                    name: fname,
                    len,
                });
            }
            api.structs.push((name.to_string(), fields));
        } else if let Some(rest) = s.strip_prefix("typedef enum ") {
            let (_, items, name) = braces(rest)?;
            api.enums.push((name.to_string(), enum_items(items)?));
        } else if let Some(rest) = s.strip_prefix("enum ") {
            let (head, items, _) = braces(rest)?;
            let items = enum_items(items)?;
            if types.aliases.contains_key(head) {
                // Fixed underlying type: its items are typed constants, like the #defines.
                api.consts.extend(items);
            } else {
                api.enums.push((head.to_string(), items));
            }
        } else if s.starts_with("typedef ") {
            // A type alias, already recorded.
        } else if let Some(open) = s.find('(') {
            let Some(close) = s.rfind(')') else {
                return err(format!("unclosed parameter list in `{s}`"));
            };
            let (ret, name) = types.decl(&s[..open])?;
            let inner = s[open + 1..close].trim();
            let mut params = Vec::new();
            if inner != "void" && !inner.is_empty() {
                for p in inner.split(',') {
                    let (ty, name) = types.decl(p)?;
                    params.push(Param { ty, name });
                }
            }
            api.funcs.push(Func { ret, name, params });
        } else {
            return err(format!("cannot parse `{s}`"));
        }
    }
    if api.funcs.is_empty() {
        return err("no function prototypes found".into());
    }
    Ok(api)
}

/// C spelling of a base type (aliases already resolved).
pub fn c_base(b: &Base) -> String {
    match b {
        Base::F64 => "double".into(),
        Base::F32 => "float".into(),
        Base::I32 => "int32_t".into(),
        Base::U32 => "uint32_t".into(),
        Base::I64 => "int64_t".into(),
        Base::U64 => "uint64_t".into(),
        Base::Usize => "size_t".into(),
        Base::Bool => "bool".into(),
        Base::Char => "char".into(),
        Base::Void => "void".into(),
        Base::Named(n) => n.clone(),
    }
}

/// C spelling of a type: `const double *`.
pub fn c_type(t: &Ty) -> String {
    let c = if t.is_const { "const " } else { "" };
    let p = if t.ptr { " *" } else { "" };
    format!("{c}{}{p}", c_base(&t.base))
}

#[cfg(test)]
mod tests {
    use super::*;

    const DEFINES: &str = "#define DC_OK 0\n#define DC_ERR_NAN 6101\n#define DC_ERR_RANGE 6102\n\
        int32_t dc_f(double x, double *out);\n";

    /// The status codes as cbindgen 0.29 writes a `#[repr(i32)]` enum (with `cpp_compat`).
    const ENUM: &str = "#ifndef DEMCONTACT_H\n#define DEMCONTACT_H\nenum dc_status\n\
        #if defined(__cplusplus) || __STDC_VERSION__ >= 202311L\n  : int32_t\n\
        #endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L\n {\n\
        /** ok */\n  DC_OK = 0,\n  DC_ERR_NAN = 6101,\n  DC_ERR_RANGE = 6102,\n};\n\
        #ifndef __cplusplus\n#if __STDC_VERSION__ >= 202311L\ntypedef enum dc_status dc_status;\n\
        #else\ntypedef int32_t dc_status;\n#endif\n#endif // __cplusplus\n\
        #ifdef __cplusplus\nextern \"C\" {\n#endif\n\
        dc_status dc_f(double x, double *out);\n#ifdef __cplusplus\n}\n#endif\n#endif\n";

    #[test]
    fn enum_constants_equal_defines() {
        let a = parse(DEFINES).expect("defines parse");
        let b = parse(ENUM).expect("enum parses");
        assert_eq!(a.consts, b.consts);
        assert!(b.enums.is_empty());
        assert_eq!(c_type(&b.funcs[0].ret), "int32_t");
    }

    #[test]
    fn unknown_statement_is_an_error() {
        assert!(parse("int32_t dc_f(void);\nunion u { int a; };\n").is_err());
        assert!(parse("int32_t dc_f(mystery_t x);\n").is_err());
    }
}
