//! The `console` blocks of the README ("Command line") and of docs/user/cli.md are real output:
//! every `$ demcontact …` line is run with the built binary from the repository root and its
//! standard output must equal the lines quoted under it, figure for figure. The one path the tool writes
//! (`--plot FILE`) is redirected to a temporary file, so the committed figure is not touched.
//! Run: `cargo test --release --test readme_console`.
#![cfg(feature = "cli")]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::indexing_slicing)]

use std::process::Command;

/// (command arguments after `demcontact`, expected output lines) for every `$ demcontact` line of
/// every console block.
fn quoted_sessions(readme: &str) -> Vec<(Vec<String>, Vec<String>)> {
    let mut sessions: Vec<(Vec<String>, Vec<String>)> = Vec::new();
    let mut in_block = false;
    for line in readme.lines() {
        if line.starts_with("```console") {
            in_block = true;
        } else if in_block && line.starts_with("```") {
            in_block = false;
        } else if in_block {
            if let Some(cmd) = line.strip_prefix("$ demcontact ") {
                sessions.push((
                    cmd.split_whitespace().map(str::to_owned).collect(),
                    Vec::new(),
                ));
            } else if line.is_empty() {
                // blank lines separate sessions
            } else {
                sessions
                    .last_mut()
                    .expect("output before any command")
                    .1
                    .push(line.to_owned());
            }
        }
    }
    sessions
}

#[test]
fn readme_console_output_is_the_tools_output() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut sessions = Vec::new();
    // (file, the fewest sessions it quotes: a block lost in an edit fails here)
    for (file, least) in [("README.md", 2), ("docs/user/cli.md", 3)] {
        let text = std::fs::read_to_string(root.join(file)).unwrap();
        let found = quoted_sessions(&text);
        assert!(
            found.len() >= least,
            "{file}: found only {} sessions",
            found.len()
        );
        sessions.extend(found);
    }
    let plot = std::env::temp_dir().join(format!("dc_readme_{}.png", std::process::id()));
    let plot = plot.to_str().unwrap().to_owned();
    for (mut args, mut expected) in sessions {
        assert!(!expected.is_empty(), "{args:?}: no output quoted");
        if let Some(i) = args.iter().position(|a| a == "--plot") {
            let quoted_path = std::mem::replace(&mut args[i + 1], plot.clone());
            for l in &mut expected {
                *l = l.replace(&quoted_path, &plot);
            }
        }
        let out = Command::new(env!("CARGO_BIN_EXE_demcontact"))
            .args(&args)
            .current_dir(root)
            .output()
            .unwrap();
        assert!(out.status.success(), "{args:?}: exit {:?}", out.status);
        let stdout = String::from_utf8(out.stdout).unwrap();
        let got: Vec<&str> = stdout.lines().filter(|l| !l.is_empty()).collect();
        for (k, (g, e)) in got.iter().zip(&expected).enumerate() {
            assert_eq!(
                g,
                e,
                "demcontact {}: line {} differs",
                args.join(" "),
                k + 1
            );
        }
        assert_eq!(
            got.len(),
            expected.len(),
            "demcontact {}: line count",
            args.join(" ")
        );
        println!(
            "demcontact {}: {} lines as quoted",
            args.join(" "),
            got.len()
        );
    }
    std::fs::remove_file(&plot).ok();
}
