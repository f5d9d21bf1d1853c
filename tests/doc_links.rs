//! Every relative link in README.md, python/README.md and docs/**/*.md resolves: the file (or
//! folder) exists, and a `#fragment` into a markdown file names one of its headings (GitHub's
//! anchors: lower case, punctuation dropped, spaces as hyphens). Links in fenced code blocks and
//! to web addresses are not checked. Run: `cargo test --test doc_links`.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

fn markdown_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            markdown_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "md") {
            out.push(p);
        }
    }
}

/// The lines of `text` outside fenced code blocks.
fn prose_lines(text: &str) -> Vec<&str> {
    let mut fenced = false;
    let mut out = Vec::new();
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        } else if !fenced {
            out.push(line);
        }
    }
    out
}

/// GitHub's anchor of a heading.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || *c == ' ' || *c == '-' || *c == '_')
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

fn anchors(text: &str) -> HashSet<String> {
    let mut seen = HashSet::new();
    let mut out = HashSet::new();
    for line in prose_lines(text) {
        let hashes = line.chars().take_while(|&c| c == '#').count();
        if (1..=6).contains(&hashes) && line[hashes..].starts_with(' ') {
            let base = slug(&line[hashes..]);
            let mut s = base.clone();
            let mut k = 0;
            while !seen.insert(s.clone()) {
                k += 1;
                s = format!("{base}-{k}");
            }
            out.insert(s);
        }
    }
    out
}

/// The targets of the inline links `[text](target)` in `line`.
fn link_targets(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find("](") {
        let after = &rest[i + 2..];
        let Some(j) = after.find(')') else { break };
        out.push(after[..j].trim().to_owned());
        rest = &after[j..];
    }
    out
}

/// Every broken relative link of `files`, as "file: target (why)".
fn broken_links(root: &Path, files: &[PathBuf]) -> (usize, Vec<String>) {
    let mut checked = 0;
    let mut broken = Vec::new();
    for file in files {
        let text = std::fs::read_to_string(file).unwrap_or_default();
        let name = file
            .strip_prefix(root)
            .unwrap_or(file)
            .display()
            .to_string();
        for line in prose_lines(&text) {
            for target in link_targets(line) {
                let target = target.split_whitespace().next().unwrap_or_default();
                if target.is_empty() || target.contains("://") || target.starts_with("mailto:") {
                    continue;
                }
                checked += 1;
                let (path, fragment) = match target.split_once('#') {
                    Some((p, f)) => (p, Some(f)),
                    None => (target, None),
                };
                let resolved = if path.is_empty() {
                    file.clone()
                } else {
                    file.parent().unwrap_or(root).join(path)
                };
                if !resolved.exists() {
                    broken.push(format!("{name}: {target} (no such file)"));
                    continue;
                }
                if let Some(f) = fragment {
                    if resolved.extension().is_some_and(|x| x == "md") {
                        let t = std::fs::read_to_string(&resolved).unwrap_or_default();
                        if !anchors(&t).contains(f) {
                            broken.push(format!("{name}: {target} (no heading #{f})"));
                        }
                    }
                }
            }
        }
    }
    (checked, broken)
}

#[test]
fn every_relative_link_resolves() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = vec![root.join("README.md"), root.join("python/README.md")];
    markdown_files(&root.join("docs"), &mut files);
    let (checked, broken) = broken_links(root, &files);
    assert!(
        checked >= 50,
        "only {checked} relative links found: is the link parser broken?"
    );
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
    println!(
        "{} files, {checked} relative links, all resolve",
        files.len()
    );
}

#[test]
fn the_checker_sees_a_broken_link() {
    let dir = std::env::temp_dir().join(format!("dc_doc_links_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap_or_default();
    let page = dir.join("page.md");
    let text = "# Title\n\n## A section\n\n[ok](page.md#a-section) [file](missing.md) \
                [frag](page.md#no-such) [web](https://example.org)\n```\n[code](nope.md)\n```\n";
    std::fs::write(&page, text).unwrap_or_default();
    let (checked, broken) = broken_links(&dir, &[page]);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(checked, 3);
    assert_eq!(broken.len(), 2, "{broken:?}");
    assert_eq!(slug(" The `x`-y (z), 2 "), "the-x-y-z-2");
}
