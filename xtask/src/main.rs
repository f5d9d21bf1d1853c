//! `cargo run -p xtask -- <command>`:
//! * `laws`: regenerates the files driven by the law registries (`demcontact::laws`): the C
//!   constants `src/ffi/codes.rs`, the Python enums and stubs (see `codes.rs`);
//! * `header`: regenerates `include/demcontact.h` with cbindgen;
//! * `bindings`: regenerates, from the committed header, the Fortran module, the C++ wrappers,
//!   the ABI probe files and `docs/api.md`;
//! * `all`: `laws`, `header`, then `bindings`;
//! * `check`: writes nothing, exits 1 naming every stale file;
//! * `abi-list [HEADER]`: prints the ABI symbol list of a header (default: the committed one),
//!   the format of `tests/data/abi_v0.txt`.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

fn root() -> PathBuf {
    // xtask/ lives in the repository root.
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_else(|| PathBuf::from("."))
}

fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))
}

fn write(root: &Path, files: &[(&str, String)]) -> Result<(), String> {
    for (p, text) in files {
        let path = root.join(p);
        if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
            std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
            println!("wrote {p}");
        }
    }
    Ok(())
}

fn run(cmd: &str, args: &[String]) -> Result<bool, String> {
    let root = root();
    match cmd {
        "laws" => {
            write(&root, &xtask::law_files(&root)?)?;
        }
        "header" => {
            write(&root, &[(xtask::HEADER, xtask::header::generate(&root)?)])?;
        }
        "bindings" => {
            let header = read(&root.join(xtask::HEADER))?;
            write(&root, &xtask::bindings(&header).map_err(|e| e.to_string())?)?;
        }
        "all" => {
            run("laws", args)?;
            run("header", args)?;
            run("bindings", args)?;
        }
        "check" => {
            let header = xtask::header::generate(&root)?;
            let mut files = xtask::law_files(&root)?;
            files.push((xtask::HEADER, header.clone()));
            files.extend(xtask::bindings(&header).map_err(|e| e.to_string())?);
            let stale = xtask::stale(&root, &files);
            for p in &stale {
                eprintln!("stale: {p}");
            }
            if !stale.is_empty() {
                eprintln!("regenerate with `cargo run -p xtask -- all` and commit");
            }
            return Ok(stale.is_empty());
        }
        "abi-list" => {
            let path = args
                .first()
                .map(PathBuf::from)
                .unwrap_or_else(|| root.join(xtask::HEADER));
            let api = xtask::cheader::parse(&read(&path)?).map_err(|e| e.to_string())?;
            for line in xtask::abi::symbols(&api) {
                println!("{line}");
            }
        }
        other => {
            return Err(format!(
                "unknown command `{other}`; commands: laws, header, bindings, all, check, abi-list [HEADER]"
            ));
        }
    }
    Ok(true)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some((cmd, rest)) = args.split_first() else {
        eprintln!(
            "usage: cargo run -p xtask -- <laws|header|bindings|all|check|abi-list [HEADER]>"
        );
        return ExitCode::FAILURE;
    };
    match run(cmd, rest) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("xtask: {e}");
            ExitCode::FAILURE
        }
    }
}
