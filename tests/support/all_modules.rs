//! The test that keeps a crate's one test binary complete: with `autotests = false`, Cargo no
//! longer finds the files of `tests/` itself, so a file not declared in `tests/all.rs` would
//! silently not run. Each `tests/all.rs` includes this module with `#[path]`.

/// Every `.rs` file and every directory with a `mod.rs` in the crate's `tests/` is declared
/// as `mod NAME;` (on a line of its own) in `tests/all.rs`.
#[test]
fn every_test_file_is_a_module() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let root = std::fs::read_to_string(dir.join("all.rs")).expect("tests/all.rs");
    let mut seen = 0;
    for entry in std::fs::read_dir(&dir).expect("the tests directory") {
        let path = entry.expect("a directory entry").path();
        let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else { continue };
        let module =
            if path.is_dir() { path.join("mod.rs").exists() } else { path.extension().is_some_and(|e| e == "rs") };
        if module && stem != "all" {
            assert!(root.lines().any(|l| l == format!("mod {stem};")), "tests/{stem} is not a module of tests/all.rs");
            seen += 1;
        }
    }
    assert!(seen > 1, "{seen} test modules in {}", dir.display());
}
