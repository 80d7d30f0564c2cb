//! What a user of the front door builds: `cargo tree` of the front door and of the example
//! crate that depends on it alone. GMP/MPFR (rug, gmp-mpfr-sys: the only crates that need m4)
//! must be absent with default features; the macro's build-time crates (proc-macro2, quote,
//! syn) must be absent when the macro is not used; toml and serde never reach a kernel user.

use std::process::Command;

/// The package names in `cargo tree -e normal` for `args` (run at the workspace root).
fn tree(args: &[&str]) -> Vec<String> {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let out = Command::new(env!("CARGO"))
        .current_dir(root)
        .args(["tree", "--offline", "-e", "normal", "--prefix", "none", "--format", "{p}"])
        .args(args)
        .output()
        .expect("cargo runs");
    assert!(out.status.success(), "cargo tree {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout)
        .expect("utf-8")
        .lines()
        .filter_map(|l| l.split_whitespace().next().map(str::to_string))
        .collect()
}

fn assert_absent(packages: &[String], forbidden: &[&str], what: &str) {
    let found: Vec<&str> = forbidden.iter().copied().filter(|f| packages.iter().any(|p| p == f)).collect();
    assert!(found.is_empty(), "{what} contains {found:?}: {packages:?}");
}

#[test]
fn kernel_user_without_the_macro_builds_no_gmp_and_no_macro_crates() {
    let packages = tree(&["-p", "gam-ga", "--no-default-features"]);
    assert!(packages.iter().any(|p| p == "algebra-core"), "{packages:?}");
    assert_absent(
        &packages,
        &["rug", "gmp-mpfr-sys", "proc-macro2", "quote", "syn", "toml", "serde", "algebra-codegen"],
        "gam-ga without default features",
    );
}

#[test]
fn scratch_crate_on_the_front_door_with_default_features_needs_no_m4() {
    // examples/game-pga depends on gam-ga alone, with its default features (the macro)
    let direct = tree(&["-p", "gam-example-game-pga", "--depth", "1"]);
    assert_eq!(direct, ["gam-example-game-pga", "gam-ga"], "the example must depend on the front door only");
    let packages = tree(&["-p", "gam-example-game-pga"]);
    assert!(packages.iter().any(|p| p == "algebra-macros"), "{packages:?}");
    assert_absent(&packages, &["rug", "gmp-mpfr-sys", "toml", "serde"], "a default-features front-door user");
}

#[test]
fn mpfr_is_the_feature_that_brings_gmp() {
    let packages = tree(&["-p", "gam-ga", "--no-default-features", "--features", "mpfr"]);
    assert!(packages.iter().any(|p| p == "gmp-mpfr-sys"), "{packages:?}");
}
