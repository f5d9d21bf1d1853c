//! The architecture rule of src/force/: no import cycle between its files, `pair.rs` imports no
//! sibling, and kernel codes are written in one place (the registry). Parses the `use super::…`
//! and `super::name::` references of every file.

use std::collections::BTreeMap;
use std::path::Path;

fn siblings(src: &str, names: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    for n in names {
        let direct = format!("super::{n}::");
        let listed = src.lines().any(|l| {
            let l = l.trim();
            l.starts_with("use super::{") && l.split(['{', '}', ',', ' ']).any(|t| t == n)
        });
        // The registry declares the law files (`#[path = "dmt.rs"] pub mod dmt;`): an edge.
        let declared = src.contains(&format!("#[path = \"{n}.rs\"]"));
        if src.contains(&direct) || listed || declared || src.contains(&format!("use super::{n};"))
        {
            out.push(n.clone());
        }
    }
    out
}

#[test]
fn src_force_has_no_import_cycle_and_one_registry() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/force");
    let mut files = BTreeMap::new();
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_stem().unwrap().to_string_lossy().to_string();
        if name != "mod" {
            files.insert(name, std::fs::read_to_string(&p).unwrap());
        }
    }
    let names: Vec<String> = files.keys().cloned().collect();
    let graph: BTreeMap<String, Vec<String>> = files
        .iter()
        .map(|(n, s)| {
            (
                n.clone(),
                siblings(s, &names).into_iter().filter(|m| m != n).collect(),
            )
        })
        .collect();
    println!("{graph:?}");
    assert!(
        graph["pair"].is_empty(),
        "pair.rs must import no sibling: {:?}",
        graph["pair"]
    );
    assert!(
        graph["registry"].contains(&"hertz".to_string()),
        "parser sees the registry's imports"
    );
    // Depth-first search for a cycle.
    fn visit(
        n: &str,
        g: &BTreeMap<String, Vec<String>>,
        stack: &mut Vec<String>,
        done: &mut Vec<String>,
    ) {
        if done.iter().any(|d| d == n) {
            return;
        }
        assert!(
            !stack.iter().any(|s| s == n),
            "import cycle: {stack:?} -> {n}"
        );
        stack.push(n.to_string());
        for m in &g[n] {
            visit(m, g, stack, done);
        }
        stack.pop();
        done.push(n.to_string());
    }
    let mut done = Vec::new();
    for n in graph.keys() {
        visit(n, &graph, &mut Vec::new(), &mut done);
    }
    // Kernel codes appear in the registry only: no other file names a code constant.
    for (n, s) in &files {
        if n != "registry" {
            assert!(
                !s.contains("code::"),
                "{n}.rs refers to kernel code constants"
            );
        }
    }
}
