//! The C program of docs/codegen.md ("C: a complete program"), with the header its first line
//! names, compiled and run: a quarter turn about z then 2 along x moves (1, 0, 0) to (2, 1, 0).

use algebra_codegen::lang::{Lang, Options, emit};
use algebra_core::Basis;
use gam_lang_tests::{compile_and_run, plan};

#[test]
fn the_c_example_of_the_docs_moves_the_point() {
    let doc = include_str!("../../docs/codegen.md");
    let start = doc.find("```c\n").expect("a C block") + 5;
    let program = &doc[start..start + doc[start..].find("```").expect("its end")];
    let types = "Motor=even;Point=e032,e013,e021,e123;Line=grade2";
    assert!(program.lines().next().unwrap().contains(&format!("--module pga --types \"{types}\"")));
    let header = emit(&plan("pga3", Basis::Blade, types, "pga"), Lang::C, &Options::default()).unwrap();
    let out = compile_and_run("doc-example", &[("pga.h", &header), ("main.c", program)], "main.c", "", "-O2");
    let v: Vec<f64> = out.split_whitespace().map(|x| x.parse().unwrap()).collect();
    let want = [2.0, 1.0, 0.0, 1.0];
    assert!(v.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-15) && v.len() == 4, "{out}");
}
