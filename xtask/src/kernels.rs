//! The stateless normal-force kernels of `include/demcontact_inline.h`, translated from the Rust
//! laws themselves: for every kernel of the registry ([`demcontact::laws::NORMAL`], its
//! `rust_type`, e.g. `hertz::HertzElastic`), the body of `impl Law for HertzElastic { fn raw }`
//! in `src/force/hertz.rs` becomes `dci_hertz_elastic`, and each function of the same file that it
//! calls becomes `dci_<file>_<fn>` (DMT's `tail` and `reach`); a law file's free
//! `critical_load` is translated too (`dci_dmt_critical_load`). Written between
//! `/* BEGIN GENERATED kernels */` and `/* END GENERATED kernels */`.
//!
//! The laws are plain arithmetic, and the translation keeps their bits: the expression tree is
//! printed as Rust evaluates it (every binary operation parenthesised, the same order), `sqrt`
//! and `abs` map to C's correctly rounded `sqrt` and exact `fabs`, `powf` to libm `pow` (Rust's
//! `powf` is libm's), `pow_dd` to its header twin `dc_pow_inline`; a product that is an operand
//! of `+` or `-` is written `DCI_M(a, b)`, which no C compiler may fuse into an FMA (Rust never
//! fuses). The C parameters are the `dc_pair` constants the body reads, in the order k, c, h,
//! then the Rust parameters it reads, in their order. Anything outside that subset (integer
//! literals, loops, other methods) is an error naming the construct, so a law that stops being
//! plain arithmetic must move to the hand-written part. The differential ctests
//! (`inline_c`, `inline_cpp`, `inline_contact_c`, …) hold the result to the library bit for bit.

use demcontact::laws::NORMAL;
use std::collections::BTreeSet;
use std::path::Path;
use syn::{BinOp, Block, Expr, FnArg, ImplItem, Item, Lit, Member, Pat, Stmt, UnOp};

/// The `dc_pair` constants a kernel may read (`Consts` fields), in C parameter order.
const CONSTS: [&str; 3] = ["k", "c", "h"];

/// One Rust function to translate.
#[derive(Clone)]
struct RustFn {
    /// Rust parameters after the `&Consts` one: names (leading `_` kept: such a one is unread).
    params: Vec<String>,
    /// Name of the `&Consts` parameter, if any.
    consts: Option<String>,
    body: Block,
}

/// One translated function: its C name, its C parameters and its body.
struct CFn {
    name: String,
    params: Vec<String>,
    body: String,
    /// Calls `pow`, `dc_pow_inline` or another kernel: `DC_INLINE_FN`, else always inlined.
    heavy: bool,
    tag: String,
}

/// The free functions and `Law` impls' `raw`/`raw_pow` of one law file.
struct LawFile {
    module: String,
    free: Vec<(String, RustFn)>,
    raws: Vec<(String, String, RustFn)>,
}

fn rust_fn(sig: &syn::Signature, block: &Block, what: &str) -> Result<RustFn, String> {
    let mut params = Vec::new();
    let mut consts = None;
    for a in &sig.inputs {
        let FnArg::Typed(pt) = a else {
            return Err(format!("{what}: a `self` parameter"));
        };
        let Pat::Ident(id) = &*pt.pat else {
            return Err(format!("{what}: a parameter that is not a name"));
        };
        let ty = quote_ty(&pt.ty);
        let name = id.ident.to_string();
        if ty == "&Consts" {
            consts = Some(name);
        } else if ty == "f64" {
            params.push(name);
        } else {
            return Err(format!(
                "{what}: parameter `{name}: {ty}` (only f64 and &Consts)"
            ));
        }
    }
    Ok(RustFn {
        params,
        consts,
        body: block.clone(),
    })
}

fn quote_ty(t: &syn::Type) -> String {
    match t {
        syn::Type::Reference(r) => format!("&{}", quote_ty(&r.elem)),
        syn::Type::Path(p) => p
            .path
            .segments
            .iter()
            .map(|s| s.ident.to_string())
            .collect::<Vec<_>>()
            .join("::"),
        _ => "?".into(),
    }
}

fn parse_file(root: &Path, module: &str) -> Result<LawFile, String> {
    let path = format!("src/force/{module}.rs");
    let text = std::fs::read_to_string(root.join(&path)).map_err(|e| format!("{path}: {e}"))?;
    parse_text(module, &text)
}

fn parse_text(module: &str, text: &str) -> Result<LawFile, String> {
    let path = format!("src/force/{module}.rs");
    let file = syn::parse_file(text).map_err(|e| format!("{path}: {e}"))?;
    let mut out = LawFile {
        module: module.to_string(),
        free: Vec::new(),
        raws: Vec::new(),
    };
    for item in &file.items {
        match item {
            Item::Fn(f) => {
                let name = f.sig.ident.to_string();
                if let Ok(r) = rust_fn(&f.sig, &f.block, &format!("{path} `{name}`")) {
                    out.free.push((name, r));
                }
            }
            Item::Impl(i) => {
                let is_law = i
                    .trait_
                    .as_ref()
                    .is_some_and(|(_, p, _)| p.segments.last().is_some_and(|s| s.ident == "Law"));
                if !is_law {
                    continue;
                }
                let ty = quote_ty(&i.self_ty);
                for it in &i.items {
                    if let ImplItem::Fn(f) = it {
                        let name = f.sig.ident.to_string();
                        if name == "raw" || name == "raw_pow" {
                            let r = rust_fn(&f.sig, &f.block, &format!("{path} `{ty}::{name}`"))?;
                            out.raws.push((ty.clone(), name, r));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    Ok(out)
}

/// The translation of one function body: C statements, and what it reads.
struct Tr<'a> {
    file: &'a LawFile,
    what: String,
    /// Name of the `&Consts` parameter in this function.
    consts: Option<String>,
    used_consts: BTreeSet<usize>,
    used_vars: BTreeSet<String>,
    heavy: bool,
    /// `Self::raw_pow` of the impl being translated (`raw` of a general-p kernel).
    raw_pow: Option<RustFn>,
}

impl Tr<'_> {
    fn err<T>(&self, msg: &str) -> Result<T, String> {
        Err(format!(
            "{}: {msg} (not plain arithmetic: write it by hand, tagged)",
            self.what
        ))
    }

    /// `e` as an operand of `+`/`-`: a product becomes `DCI_M(a, b)`.
    fn operand(&mut self, e: &Expr) -> Result<String, String> {
        let mut inner = e;
        while let Expr::Paren(p) = inner {
            inner = &p.expr;
        }
        if let Expr::Binary(b) = inner
            && matches!(b.op, BinOp::Mul(_))
        {
            let l = self.expr(&b.left)?;
            let r = self.expr(&b.right)?;
            return Ok(format!("DCI_M({}, {})", bare(l), bare(r)));
        }
        self.expr(e)
    }

    fn expr(&mut self, e: &Expr) -> Result<String, String> {
        Ok(match e {
            Expr::Paren(p) => self.expr(&p.expr)?,
            Expr::Lit(l) => match &l.lit {
                Lit::Float(f) => {
                    let s = f.base10_digits().to_string();
                    if f.suffix() != "" && f.suffix() != "f64" {
                        return self.err(&format!("literal suffix `{}`", f.suffix()));
                    }
                    if s.contains('.') || s.contains('e') {
                        s
                    } else {
                        format!("{s}.0")
                    }
                }
                _ => return self.err("a literal that is not f64"),
            },
            Expr::Path(p) => {
                let Some(id) = p.path.get_ident() else {
                    return self.err("a path that is not a local name");
                };
                let n = id.to_string();
                self.used_vars.insert(n.clone());
                n
            }
            Expr::Field(f) => {
                let base_ok = matches!(&*f.base, Expr::Path(p)
                    if p.path.get_ident().map(|i| i.to_string()) == self.consts);
                let Member::Named(m) = &f.member else {
                    return self.err("a tuple field");
                };
                let m = m.to_string();
                let Some(i) = CONSTS.iter().position(|c| *c == m) else {
                    return self.err(&format!("field `{m}`"));
                };
                if !base_ok {
                    return self.err("a field of something other than the Consts parameter");
                }
                self.used_consts.insert(i);
                m
            }
            Expr::Unary(u) => match u.op {
                UnOp::Neg(_) => format!("(-{})", self.expr(&u.expr)?),
                _ => return self.err("a unary operator other than -"),
            },
            Expr::Binary(b) => {
                let op = match b.op {
                    BinOp::Add(_) => "+",
                    BinOp::Sub(_) => "-",
                    BinOp::Mul(_) => "*",
                    BinOp::Div(_) => "/",
                    BinOp::Gt(_) => ">",
                    BinOp::Lt(_) => "<",
                    BinOp::Ge(_) => ">=",
                    BinOp::Le(_) => "<=",
                    _ => return self.err("an operator other than + - * / > < >= <="),
                };
                let (l, r) = if matches!(b.op, BinOp::Add(_) | BinOp::Sub(_)) {
                    (self.operand(&b.left)?, self.operand(&b.right)?)
                } else {
                    (self.expr(&b.left)?, self.expr(&b.right)?)
                };
                format!("({l} {op} {r})")
            }
            Expr::MethodCall(m) => {
                let recv = self.expr(&m.receiver)?;
                let args = m
                    .args
                    .iter()
                    .map(|a| self.expr(a))
                    .collect::<Result<Vec<_>, _>>()?;
                match (m.method.to_string().as_str(), args.len()) {
                    ("sqrt", 0) => format!("sqrt({})", bare(recv)),
                    ("abs", 0) => format!("fabs({})", bare(recv)),
                    ("powf", 1) => {
                        self.heavy = true;
                        format!("pow({}, {})", bare(recv), bare(args[0].clone()))
                    }
                    (other, _) => return self.err(&format!("method `{other}`")),
                }
            }
            Expr::Call(c) => {
                let Expr::Path(p) = &*c.func else {
                    return self.err("a call of something other than a function name");
                };
                let name = p
                    .path
                    .segments
                    .iter()
                    .map(|s| s.ident.to_string())
                    .collect::<Vec<_>>()
                    .join("::");
                if name == "pow_dd" && c.args.len() == 2 {
                    self.heavy = true;
                    let a = self.expr(&c.args[0])?;
                    let b = self.expr(&c.args[1])?;
                    return Ok(format!("dc_pow_inline({}, {})", bare(a), bare(b)));
                }
                let Some((_, callee)) = self.file.free.iter().find(|(n, _)| *n == name) else {
                    return self.err(&format!("a call of `{name}`"));
                };
                let callee = callee.clone();
                let sig = signature(self.file, &callee, &format!("{} -> {name}", self.what))?;
                self.heavy = true;
                // The callee's consts come from ours; its f64 parameters from the arguments.
                let mut args = Vec::new();
                let mut fargs = c.args.iter();
                if callee.consts.is_some() {
                    let a = fargs.next();
                    let ok = matches!(a, Some(Expr::Path(p))
                        if p.path.get_ident().map(|i| i.to_string()) == self.consts);
                    if !ok {
                        return self.err(&format!("`{name}` not given our Consts"));
                    }
                }
                for &i in &sig.consts {
                    self.used_consts.insert(i);
                    args.push(CONSTS[i].to_string());
                }
                for (pname, a) in callee.params.iter().zip(fargs) {
                    if sig.params.contains(pname) {
                        args.push(bare(self.expr(a)?));
                    }
                }
                format!("dci_{}_{name}({})", self.file.module, args.join(", "))
            }
            Expr::If(i) => {
                let c = self.expr(&i.cond)?;
                let t = self.block_expr(&i.then_branch)?;
                let Some((_, e)) = &i.else_branch else {
                    return self.err("an if without else");
                };
                let e = self.expr(e)?;
                format!("({c} ? {t} : {e})")
            }
            Expr::Block(b) => self.block_expr(&b.block)?,
            _ => return self.err("an expression outside + - * / sqrt abs powf if"),
        })
    }

    /// A block with no statements but its value, as an expression.
    fn block_expr(&mut self, b: &Block) -> Result<String, String> {
        match b.stmts.as_slice() {
            [Stmt::Expr(e, None)] => self.expr(e),
            _ => self.err("a block with statements inside an expression"),
        }
    }

    /// A function body as C statements ending in `return`, indented by `ind`.
    fn body(&mut self, b: &Block, ind: &str) -> Result<String, String> {
        let mut s = String::new();
        let n = b.stmts.len();
        for (k, st) in b.stmts.iter().enumerate() {
            match st {
                Stmt::Local(l) => {
                    let name = match &l.pat {
                        Pat::Ident(i) => i.ident.to_string(),
                        Pat::Type(t) => match &*t.pat {
                            Pat::Ident(i) => i.ident.to_string(),
                            _ => return self.err("a pattern in let"),
                        },
                        _ => return self.err("a pattern in let"),
                    };
                    let Some(init) = &l.init else {
                        return self.err("let without a value");
                    };
                    let v = self.expr(&init.expr)?;
                    s.push_str(&format!("{ind}const double {name} = {};\n", bare(v)));
                }
                Stmt::Expr(e, None) if k + 1 == n => s.push_str(&self.tail(e, ind)?),
                _ => return self.err("a statement other than let and the value"),
            }
        }
        Ok(s)
    }

    fn tail(&mut self, e: &Expr, ind: &str) -> Result<String, String> {
        match e {
            Expr::If(i) => {
                let Some((_, els)) = &i.else_branch else {
                    return self.err("an if without else");
                };
                let c = bare(self.expr(&i.cond)?);
                let inner = format!("{ind}    ");
                let t = self.body(&i.then_branch, &inner)?;
                let e = match &**els {
                    Expr::Block(b) => self.body(&b.block, &inner)?,
                    other => self.tail(other, &inner)?,
                };
                Ok(format!(
                    "{ind}if ({c}) {{\n{t}{ind}}} else {{\n{e}{ind}}}\n"
                ))
            }
            Expr::Call(c)
                if matches!(&*c.func, Expr::Path(p)
                    if p.path.segments.len() == 2
                        && p.path.segments[0].ident == "Self"
                        && p.path.segments[1].ident == "raw_pow") =>
            {
                // `Self::raw_pow(c, d, vn, r, m, s)`: its body, its last parameter bound once.
                let Some(rp) = self.raw_pow.clone() else {
                    return self.err("Self::raw_pow without one");
                };
                let (Some(last), Some(arg)) = (rp.params.last(), c.args.last()) else {
                    return self.err("Self::raw_pow without its power argument");
                };
                for (p, a) in rp.params.iter().zip(c.args.iter().skip(1)) {
                    let same = matches!(a, Expr::Path(q) if q.path.get_ident().is_some_and(|i| {
                        i.to_string().trim_start_matches('_') == p.trim_start_matches('_')
                    }));
                    if p != last && !same {
                        return self.err("Self::raw_pow given other arguments than ours");
                    }
                }
                let v = bare(self.expr(arg)?);
                let name = last.trim_start_matches('_');
                let mut s = format!("{ind}const double {name} = {v};\n");
                s.push_str(&self.body(&rp.body, ind)?);
                Ok(s)
            }
            other => Ok(format!("{ind}return {};\n", bare(self.expr(other)?))),
        }
    }
}

/// `s` without one pair of parentheses around all of it (an argument, a value, a condition).
fn bare(s: String) -> String {
    let b = s.as_bytes();
    if b.first() != Some(&b'(') || b.last() != Some(&b')') {
        return s;
    }
    let mut depth = 0i32;
    for (i, &c) in b.iter().enumerate() {
        match c {
            b'(' => depth += 1,
            b')' => depth -= 1,
            _ => {}
        }
        if depth == 0 && i + 1 < b.len() {
            return s;
        }
    }
    s[1..s.len() - 1].to_string()
}

/// What a translated function reads: the consts (indices into [`CONSTS`]) and its parameters.
struct Sig {
    consts: Vec<usize>,
    params: Vec<String>,
}

fn signature(file: &LawFile, f: &RustFn, what: &str) -> Result<Sig, String> {
    Ok(translate(file, f, None, what)?.1)
}

/// The C body of `f`, what it reads, and whether it is heavy (see [`CFn::heavy`]).
fn translate(
    file: &LawFile,
    f: &RustFn,
    raw_pow: Option<RustFn>,
    what: &str,
) -> Result<(String, Sig, bool), String> {
    let mut tr = Tr {
        file,
        what: what.to_string(),
        consts: f.consts.clone(),
        used_consts: BTreeSet::new(),
        used_vars: BTreeSet::new(),
        heavy: false,
        raw_pow,
    };
    let body = tr.body(&f.body, "    ")?;
    for p in &f.params {
        if p.starts_with('_') && tr.used_vars.contains(p.as_str()) {
            return tr.err(&format!("reads `{p}`, named unused"));
        }
    }
    let sig = Sig {
        consts: tr.used_consts.iter().copied().collect(),
        params: f
            .params
            .iter()
            .filter(|p| tr.used_vars.contains(p.as_str()))
            .cloned()
            .collect(),
    };
    Ok((body, sig, tr.heavy))
}

fn c_fn(
    file: &LawFile,
    f: &RustFn,
    raw_pow: Option<RustFn>,
    name: String,
    tag: String,
) -> Result<CFn, String> {
    let (body, sig, heavy) = translate(file, f, raw_pow, &tag)?;
    let mut params: Vec<String> = sig.consts.iter().map(|&i| CONSTS[i].to_string()).collect();
    params.extend(sig.params);
    Ok(CFn {
        name,
        params,
        body,
        heavy,
        tag,
    })
}

/// Every translated kernel, in registry order, each after the functions it calls.
fn all(root: &Path) -> Result<Vec<CFn>, String> {
    let mut out: Vec<CFn> = Vec::new();
    let mut files: Vec<LawFile> = Vec::new();
    for law in NORMAL {
        for k in law.kernels {
            let ty: String = k.rust_type.chars().filter(|c| !c.is_whitespace()).collect();
            let Some((module, tyname)) = ty.split_once("::") else {
                return Err(format!("kernel {}: type `{ty}` is not `law::Type`", k.name));
            };
            if !files.iter().any(|f| f.module == module) {
                files.push(parse_file(root, module)?);
            }
            let file = files.iter().find(|f| f.module == module).ok_or("parsed")?;
            let path = format!("src/force/{module}.rs");
            let find = |n: &str| {
                file.raws
                    .iter()
                    .find(|(t, f, _)| t == tyname && f == n)
                    .map(|(_, _, r)| r.clone())
            };
            let Some(raw) = find("raw") else {
                return Err(format!("{path}: no `impl Law for {tyname}` with `raw`"));
            };
            // The free functions it calls first (each once).
            let mut called = Vec::new();
            collect_calls(&raw.body, file, &mut called);
            if let Some(rp) = find("raw_pow") {
                collect_calls(&rp.body, file, &mut called);
            }
            for name in called {
                let c_name = format!("dci_{module}_{name}");
                if out.iter().any(|f| f.name == c_name) {
                    continue;
                }
                let (_, f) = file.free.iter().find(|(n, _)| *n == name).ok_or("called")?;
                out.push(c_fn(file, f, None, c_name, format!("{path} `{name}`"))?);
            }
            let c_name = format!("dci_{}", k.name.to_ascii_lowercase());
            out.push(c_fn(
                file,
                &raw,
                find("raw_pow"),
                c_name,
                format!("{path} `{tyname}::raw`"),
            )?);
        }
    }
    // A law file's own critical load of the Coulomb limits.
    for file in &files {
        if let Some((_, f)) = file.free.iter().find(|(n, _)| n == "critical_load") {
            let path = format!("src/force/{}.rs", file.module);
            let c_name = format!("dci_{}_critical_load", file.module);
            out.push(c_fn(
                file,
                f,
                None,
                c_name,
                format!("{path} `critical_load`"),
            )?);
        }
    }
    Ok(out)
}

/// The names of the file's free functions that `b` calls, callees first.
fn collect_calls(b: &Block, file: &LawFile, out: &mut Vec<String>) {
    struct V<'a> {
        file: &'a LawFile,
        out: &'a mut Vec<String>,
    }
    impl<'ast> syn::visit::Visit<'ast> for V<'_> {
        fn visit_expr_call(&mut self, c: &'ast syn::ExprCall) {
            if let Expr::Path(p) = &*c.func
                && let Some(id) = p.path.get_ident()
            {
                let name = id.to_string();
                if let Some((_, f)) = self.file.free.iter().find(|(n, _)| *n == name)
                    && !self.out.contains(&name)
                {
                    collect_calls(&f.body, self.file, self.out);
                    if !self.out.contains(&name) {
                        self.out.push(name);
                    }
                }
            }
            syn::visit::visit_expr_call(self, c);
        }
    }
    syn::visit::Visit::visit_block(&mut V { file, out }, b);
}

/// The generated block.
pub fn block(root: &Path) -> Result<String, String> {
    let mut s = String::from(
        "/* Generated by `cargo run -p xtask -- all` from the stateless kernels of the registry of\n \
         * normal laws (src/force/registry.rs), each translated from the Rust function its comment\n \
         * names (xtask/src/kernels.rs): do not edit by hand. */\n",
    );
    for f in all(root)? {
        let q = if f.heavy {
            "DC_INLINE_FN"
        } else {
            "DCI_ALWAYS_INLINE_FN"
        };
        let params = f
            .params
            .iter()
            .map(|p| format!("double {p}"))
            .collect::<Vec<_>>()
            .join(", ");
        let mut head = format!("{q} double {}({params}) {{", f.name);
        if head.len() > 100 {
            // One parameter list over two lines, aligned after the parenthesis.
            let open = head.find('(').unwrap_or(0) + 1;
            let cut = head[..100].rfind(", ").unwrap_or(open);
            head = format!(
                "{}\n{}{}",
                &head[..cut + 1],
                " ".repeat(open),
                &head[cut + 2..]
            );
        }
        s.push_str(&format!(
            "/* {} */\n{head}\n    DCI_NO_CONTRACT\n{}}}\n",
            f.tag, f.body
        ));
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The C function translated from `impl Law for T { fn raw }` of a law file `text`.
    fn raw_of(text: &str) -> Result<CFn, String> {
        let file = parse_text("x", text)?;
        let (_, _, raw) = file
            .raws
            .iter()
            .find(|(_, f, _)| f == "raw")
            .ok_or("no raw")?;
        c_fn(&file, raw, None, "dci_t".into(), "t".into())
    }

    fn law(body: &str) -> String {
        format!(
            "impl Law for T {{ fn raw(c: &Consts, d: f64, vn: f64, _r: f64, m: f64) -> f64 {{ {body} }} }}"
        )
    }

    #[test]
    fn a_product_added_is_never_fused_and_the_parameters_are_what_is_read() {
        let f = raw_of(&law("c.k * d + c.c * (m * d).sqrt() * vn")).unwrap();
        assert_eq!(f.params, ["k", "c", "d", "vn", "m"]);
        assert_eq!(
            f.body,
            "    return DCI_M(k, d) + DCI_M(c * sqrt(m * d), vn);\n"
        );
        // A product of products stays plain; order and grouping are Rust's.
        let f = raw_of(&law("c.k * (d * d) - (c.h - d) / vn")).unwrap();
        assert_eq!(f.params, ["k", "h", "d", "vn"]);
        assert_eq!(f.body, "    return DCI_M(k, d * d) - ((h - d) / vn);\n");
    }

    #[test]
    fn what_is_not_plain_arithmetic_is_refused_by_name() {
        for (body, word) in [
            ("c.k * d * 2", "not f64"),
            ("c.k.mul_add(d, vn)", "method `mul_add`"),
            ("let mut x = 0.0; for _ in 0..3 { x += d; } x", "statement"),
            ("c.q * d", "field `q`"),
            ("other(d)", "call of `other`"),
            ("if d > 0.0 { d }", "without else"),
            ("c.k * _r", "named unused"),
        ] {
            let e = raw_of(&law(body)).map(|f| f.body).unwrap_err();
            assert!(e.contains(word), "{body}: {e}");
            assert!(e.contains("write it by hand"), "{body}: {e}");
        }
    }

    #[test]
    fn a_called_law_function_passes_the_constants_it_reads() {
        let text = format!(
            "fn tail(c: &Consts, d: f64, r: f64) -> f64 {{ let s = 1.0 + d / c.h; if s > 0.0 {{ -c.k * s * r }} else {{ 0.0 }} }}\n{}",
            law("if d > 0.0 { c.c * d } else { tail(c, d, m) }")
        );
        let f = raw_of(&text).unwrap();
        assert_eq!(f.params, ["k", "c", "h", "d", "m"]);
        assert!(
            f.body.contains("return dci_x_tail(k, h, d, m);"),
            "{}",
            f.body
        );
    }
}
