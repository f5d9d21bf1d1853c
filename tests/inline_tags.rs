//! The hand-written part of `include/demcontact_inline.h` mirrors Rust functions; each such
//! function carries a tag naming the one it mirrors, in the form ``src/<path>.rs `name` `` (or
//! `` `Type::name` `` where a file has several). Checked here:
//! * every tag names an existing file that defines `fn name` (and `Type`, if given);
//! * every law of the registry ([`demcontact::laws::NORMAL`]) has its hand-written functions
//!   (`dci_spec_<keyword>`, and `dci_<keyword>_force` for a law with state: the names the
//!   generated dispatch calls), each defined once and tagged with the Rust function it mirrors
//!   (`build`, `force`) in the comment just above it.

use std::path::Path;

/// Every tag of `text`: (byte offset, file, Type or "", fn).
fn tags(text: &str) -> Vec<(usize, String, String, String)> {
    let mut out = Vec::new();
    let mut at = 0;
    while let Some(i) = text[at..].find("src/") {
        let start = at + i;
        at = start + 4;
        let rest = &text[start..];
        let Some(end) = rest.find(".rs") else { break };
        let path = &rest[..end + 3];
        if !path
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '/' || c == '.')
        {
            continue;
        }
        let after = &rest[end + 3..];
        let Some(name) = after.strip_prefix(" `") else {
            continue;
        };
        let Some(close) = name.find('`') else {
            continue;
        };
        let name = &name[..close];
        let (ty, f) = match name.rsplit_once("::") {
            Some((t, f)) => (t.to_string(), f.to_string()),
            None => (String::new(), name.to_string()),
        };
        if f.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') && !f.is_empty() {
            out.push((start, path.to_string(), ty, f));
        }
    }
    out
}

/// Whether `src` defines `fn name` (followed by `(` or `<`).
fn defines_fn(src: &str, name: &str) -> bool {
    ["(", "<"]
        .iter()
        .any(|c| src.contains(&format!("fn {name}{c}")))
}

fn header() -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(root.join("include/demcontact_inline.h")).unwrap()
}

#[test]
fn every_tag_names_an_existing_rust_function() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = header();
    let found = tags(&text);
    assert!(
        found.len() >= 10,
        "the parser finds the tags: {}",
        found.len()
    );
    for (_, path, ty, f) in &found {
        let src = std::fs::read_to_string(root.join(path))
            .unwrap_or_else(|e| panic!("tag names {path}: {e}"));
        assert!(
            defines_fn(&src, f),
            "{path} defines no `fn {f}` (tag `{ty}::{f}`)"
        );
        if !ty.is_empty() {
            assert!(
                src.contains(&format!("struct {ty}")) || src.contains(&format!("for {ty} ")),
                "{path} has no type {ty} (tag `{ty}::{f}`)"
            );
        }
    }
}

#[test]
fn every_law_has_its_tagged_header_functions() {
    let text = header();
    let found = tags(&text);
    for (law, cfn, rust_fn) in xtask::inline::required_functions() {
        let defs: Vec<usize> = text
            .match_indices(&format!(" {cfn}("))
            .map(|(i, _)| i)
            .filter(|&i| {
                let line_start = text[..i].rfind('\n').map_or(0, |j| j + 1);
                text[line_start..i].contains("_FN ")
            })
            .collect();
        assert_eq!(
            defs.len(),
            1,
            "law {law}: include/demcontact_inline.h must define `{cfn}` once (found {})",
            defs.len()
        );
        let def = defs[0];
        // The comment just above the definition: from the last "/*" before it.
        let line_start = text[..def].rfind('\n').map_or(0, |j| j + 1);
        let comment_start = text[..line_start].rfind("/*").expect("a comment above");
        let between = &text[comment_start..line_start];
        assert!(
            between.trim_end().ends_with("*/"),
            "law {law}: `{cfn}` needs its tag comment right above it"
        );
        let tagged = found.iter().any(|(at, path, _, f)| {
            *at >= comment_start
                && *at < line_start
                && f == rust_fn
                && path.starts_with("src/force/")
        });
        assert!(
            tagged,
            "law {law}: the comment above `{cfn}` must name the Rust function it mirrors, \
             src/force/<file>.rs `{rust_fn}`"
        );
    }
}
