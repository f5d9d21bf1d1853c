//! The C header claims only the `dc_` / `DC_` namespace: a host that includes it next to its own
//! headers (LAMMPS, LIGGGHTS, a Fortran binding) must not see macros such as `NONE` or `HERTZ`.
//! Every macro, enum constant, type and function the header declares must carry the prefix.

#[test]
fn header_declares_only_prefixed_names() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let header = std::fs::read_to_string(root.join("include/demcontact.h")).expect("header");
    let mut bad = Vec::new();
    for (i, line) in header.lines().enumerate() {
        let t = line.trim();
        if t.starts_with('*') || t.starts_with("/*") || t.starts_with("//") {
            continue; // comments
        }
        let name = if let Some(rest) = t.strip_prefix("#define ") {
            rest.split_whitespace().next()
        } else if let Some(rest) = t.strip_prefix("typedef struct ") {
            rest.split_whitespace().next()
        } else if t.starts_with("} ") && t.ends_with(';') {
            Some(t.trim_start_matches("} ").trim_end_matches(';'))
        } else if let Some(rest) = t.strip_prefix("enum ") {
            rest.split_whitespace().next()
        } else if let Some((n, _)) = t.split_once(" = ").filter(|_| t.ends_with(',')) {
            Some(n) // enum constant
        } else if t.contains('(') && !t.starts_with('#') {
            // A function declaration: the identifier before '('.
            t.split('(').next().and_then(|head| {
                head.split(|c: char| c == ' ' || c == '*')
                    .filter(|s| !s.is_empty())
                    .last()
            })
        } else {
            None
        };
        if let Some(n) = name {
            let ok = n == "DEMCONTACT_H" || n.starts_with("DC_") || n.starts_with("dc_");
            if !ok {
                bad.push(format!("line {}: `{n}` in `{t}`", i + 1));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "unprefixed names in include/demcontact.h:\n{}",
        bad.join("\n")
    );
}
