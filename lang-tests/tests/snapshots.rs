//! Snapshots of the emitted C, WGSL and GLSL for 3D PGA, the dual quaternions of `g123inf`
//! and CGA: a change of the emitters shows up as a diff of `lang-tests/snapshots/`. After an
//! intended change, regenerate with `GAM_UPDATE_SNAPSHOTS=1 cargo test -p gam-lang-tests
//! --test snapshots` and review the diff.

use algebra_codegen::lang::{Lang, Options, emit};
use algebra_core::Basis;
use gam_lang_tests::plan;
use std::path::PathBuf;

fn check(file: &str, text: &str) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("snapshots").join(file);
    if std::env::var_os("GAM_UPDATE_SNAPSHOTS").is_some() {
        std::fs::write(&path, text).unwrap();
        return;
    }
    let want = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(want == text, "{file} changed: regenerate with GAM_UPDATE_SNAPSHOTS=1 and review the diff");
}

fn snapshot(stem: &str, algebra: &str, basis: Basis, types: &str, ops: &[&str]) {
    let plan = plan(algebra, basis, types, stem);
    let options = Options {
        ops: Some(ops.iter().map(|s| s.to_string()).collect()),
        header: vec![format!("{algebra}: {types}; ops {}", ops.join(","))],
        every_type: false,
    };
    for (lang, ext) in [(Lang::C, "h"), (Lang::Wgsl, "wgsl"), (Lang::Glsl, "glsl")] {
        check(&format!("{stem}.{ext}"), &emit(&plan, lang, &options).unwrap());
    }
}

#[test]
fn pga3() {
    snapshot(
        "pga3",
        "pga3",
        Basis::Blade,
        "Motor=even;Point=grade3;Line=grade2",
        &["gp", "apply", "apply_unit", "reverse", "norm_squared", "exp", "log_unit", "normalize"],
    );
}

#[test]
fn g123inf() {
    snapshot(
        "g123inf",
        "g123inf",
        Basis::Blade,
        "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Bivector=grade2",
        &["gp", "sandwich", "sandwich_unit", "reverse", "norm_squared", "exp", "log_unit", "normalize"],
    );
}

#[test]
fn cga() {
    snapshot("cga", "cga", Basis::Blade, "Motor=even;Vector=grade1", &["sandwich_unit", "reverse", "norm_squared"]);
}
