//! The README's "From C++" and "From Fortran" programs are the files that ctest builds and runs:
//! the README must quote them verbatim.

#[test]
fn readme_quotes_the_tested_programs() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap_or_default();
    for file in ["examples_cpp/minimal.cpp", "c_tests/fortran/minimal.f90"] {
        let src = std::fs::read_to_string(root.join(file)).unwrap_or_default();
        assert!(!src.is_empty(), "{file} missing");
        assert!(
            readme.contains(&src),
            "README.md does not quote {file} verbatim"
        );
    }
}
