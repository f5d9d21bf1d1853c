//! The README's quick starts are the programs and decks that the tests build and run:
//! * the C program, the Fortran program and the Python script are quoted verbatim from the files
//!   that ctest `installed_package`, ctest `fortran_minimal` and `python/tests/test_examples.py`
//!   run, and the C++ program in docs/user/c_cpp.md is the one ctest `example_minimal` runs;
//! * every line of the README's CMake block is a line of the consumer project ctest builds;
//! * the LAMMPS and LIGGGHTS blocks run the decks that ctest `lammps_quickstart` and
//!   `liggghts_quickstart` run, loaded the way those tests load them.

use std::path::Path;

fn read(root: &Path, file: &str) -> String {
    let text = std::fs::read_to_string(root.join(file)).unwrap_or_default();
    assert!(!text.is_empty(), "{file} missing or empty");
    text
}

/// The fenced blocks of `text` whose info string is `lang`, in order.
fn blocks<'a>(text: &'a str, lang: &str) -> Vec<Vec<&'a str>> {
    let mut out = Vec::new();
    let mut cur: Option<Vec<&str>> = None;
    for line in text.lines() {
        match cur.as_mut() {
            None if line.trim_end() == format!("```{lang}") => cur = Some(Vec::new()),
            Some(_) if line.starts_with("```") => out.extend(cur.take()),
            Some(b) => b.push(line),
            None => {}
        }
    }
    out
}

#[test]
fn quick_starts_quote_the_tested_programs() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = read(root, "README.md");
    for (doc, file) in [
        ("README.md", "c_tests/consumer/main.c"),
        ("README.md", "c_tests/fortran/minimal.f90"),
        ("README.md", "python/examples/quickstart.py"),
        ("docs/user/c_cpp.md", "examples_cpp/minimal.cpp"),
    ] {
        let text = if doc == "README.md" {
            readme.clone()
        } else {
            read(root, doc)
        };
        let src = read(root, file);
        assert!(text.contains(&src), "{doc} does not quote {file} verbatim");
    }
}

#[test]
fn readme_cmake_block_is_the_consumer_project() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = read(root, "README.md");
    let project = read(root, "c_tests/consumer/CMakeLists.txt");
    // Code only, comments aside on both sides.
    let code = |l: &str| l.split(" #").next().unwrap_or("").trim().to_string();
    let lines: Vec<String> = project.lines().map(code).collect();
    let cmake = blocks(&readme, "cmake");
    assert_eq!(cmake.len(), 1, "README.md: expected one cmake block");
    for line in &cmake[0] {
        let l = code(line);
        assert!(
            l.is_empty() || lines.contains(&l),
            "README.md cmake line {l:?} is not in c_tests/consumer/CMakeLists.txt"
        );
    }
}

#[test]
fn readme_plugin_blocks_run_the_tested_decks() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = read(root, "README.md");
    let sh = blocks(&readme, "sh");
    // (deck, how the README must load the plugin, the ctest script that does the same)
    for (deck, load, script) in [
        (
            "plugins/lammps/examples/in.demcontact",
            "LAMMPS_PLUGIN_PATH=\"$HOME/.local/lib/demcontact\" lmp -in ",
            "tests/simulators/lammps_quickstart.sh",
        ),
        (
            "plugins/liggghts/examples/in.demcontact",
            "LD_PRELOAD=\"$HOME/.local/lib/demcontact/libdemcontact_liggghts.so\" liggghts -in ",
            "tests/simulators/liggghts_quickstart.sh",
        ),
    ] {
        read(root, deck);
        let want = format!("{load}{deck}");
        assert!(
            sh.iter().flatten().any(|l| l.trim() == want),
            "README.md has no sh line {want:?}"
        );
        let test = read(root, script);
        let var = load.split('=').next().unwrap_or_default();
        assert!(
            test.contains(&format!("{var}=")) && test.contains("cmake --install"),
            "{script} does not install and load through {var}"
        );
    }
    // The install commands the plugin blocks rely on.
    assert!(
        sh.iter()
            .flatten()
            .any(|l| l.contains("cmake --install build-plugins --prefix \"$HOME/.local\"")),
        "README.md: the plugin install line is missing"
    );
}
