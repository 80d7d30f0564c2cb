//! Re-derives the product wisdom of the binary kernels (`algebra_codegen::product_order::WISDOM`,
//! docs/performance.md "Term order of the motor product").
//!
//! For each benched product (the motor and rotor products of `cargo bench -p gam-algebras
//! --bench products`) it writes one Rust program holding the module's types
//! (`standalone::file_with`) and the kernel's body as the generator emits it in every
//! candidate [`ProductOrder`] (the positive terms first within blocks of 0, 2, 4 or 8 terms;
//! chains of 2, 4, 8 or 16), compiles it with `rustc -O` (edition 2024, baseline x86-64 as the
//! benches), checks every candidate against the tables' order (the same values up to
//! rounding), runs it pinned to one core, and prints each candidate's median ratio to the
//! tables' order (interleaved rounds of 1024 pairs, as the bench) and the `WISDOM` entry of the
//! fastest when it beats the tables' order by more than the noise (0.01).
//!
//! ```sh
//! cargo run --release -p algebra-codegen --example product_wisdom -- [DIR] [ROUNDS] [CORE]
//! ```
//! (`DIR` the scratch directory, default `/tmp/gam-products`; `ROUNDS` default 1000; `CORE`
//! the core to pin to with `taskset`, default 1.) A kernel's fingerprint covers every module
//! whose product has the same tables: `g123inf`'s motor product is also `cga_null`'s and the
//! one of GATL's declaration of the conformal model.

use algebra_codegen::plan::Plan;
use algebra_codegen::product_order::{ProductOrder, apply_order, fingerprint};
use algebra_codegen::standalone::{Selection, file_with};
use algebra_codegen::{ModuleSpec, emit};
use algebra_core::tables::Product;
use algebra_core::{Algebra, Basis};
use std::fmt::Write as _;

mod common;

/// One benched product: a label, the module's plan, the type multiplied by itself.
struct Case {
    name: &'static str,
    plan: Plan,
    ty: &'static str,
}

fn case(name: &'static str, algebra: &str, types: &str, ty: &'static str) -> Case {
    let alg = Algebra::builtin(algebra).expect("builtin");
    let types = ModuleSpec::parse_types(types, &alg).expect("types");
    let mut spec = ModuleSpec::new("m", alg.metric().clone(), Basis::Blade, types).expect("spec");
    spec.table_above = 256;
    Case { name, plan: Plan::new(spec).expect("plan"), ty }
}

fn cases() -> Vec<Case> {
    vec![
        case("g123inf", "g123inf", "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf", "Motor"),
        case("pga3", "pga3", "Motor=even", "Motor"),
        case("g3", "g3", "Rotor=even", "Rotor"),
        case("cga", "cga", "Motor=even", "Motor"),
    ]
}

fn candidates() -> Vec<ProductOrder> {
    let mut out = vec![ProductOrder::TABLES];
    for positive_first in [0, 2, 4, 8] {
        for chain in [2, 4, 8, 16] {
            let o = ProductOrder { positive_first, chain };
            if o != ProductOrder::TABLES {
                out.push(o);
            }
        }
    }
    out
}

/// Writes, compiles and runs the program for one case; the candidates kept (distinct bodies,
/// the tables' order first) and their ratios to it.
fn measure(case: &Case, dir: &std::path::Path, rounds: usize, core: &str) -> (u64, Vec<(ProductOrder, f64)>) {
    let ti = case.plan.spec.types.iter().position(|t| t.name == case.ty).expect("type");
    let base = case.plan.kernel(Product::Geometric, ti, ti).clone();
    let selection = Selection { ops: Some(["gp".to_string()].into()), every_type: false };
    let module = file_with(&case.plan, &[], Some("m"), &selection).expect("standalone file");
    let mut src = String::new();
    writeln!(src, "#![allow(warnings)]\n{}", quote::ToTokens::to_token_stream(&module)).unwrap();
    let (mut kept, mut bodies): (Vec<ProductOrder>, Vec<String>) = (Vec::new(), Vec::new());
    for order in candidates() {
        let mut k = base.clone();
        apply_order(&mut k, order);
        let body =
            emit::product_body(&case.plan, &k).to_string().replace("self .", "s .").replace("__gam_engine ::", "m ::");
        if bodies.contains(&body) {
            continue;
        }
        let name = format!("k{}", kept.len());
        writeln!(
            src,
            "#[inline(always)] fn {name}(s: &m::{t}<f64>, rhs: &m::{t}<f64>) -> m::{t}<f64> {{ use m::*; type T = f64; {body} }}\n\
             #[inline(never)] fn run_{name}(x: &[m::{t}<f64>], y: &[m::{t}<f64>]) {{ for (a, b) in x.iter().zip(y) {{ let (a, b) = (std::hint::black_box(a), std::hint::black_box(b)); std::hint::black_box({name}(a, b)); }} }}",
            t = case.ty
        )
        .unwrap();
        bodies.push(body);
        kept.push(order);
    }
    harness(&mut src, case.ty, kept.len(), rounds);
    let ratios = common::compile_and_time(dir, case.name, &src, core, kept.len());
    (fingerprint(&base), kept.into_iter().zip(ratios).collect())
}

/// The program's `main`: data, every candidate checked against the first, interleaved rounds.
fn harness(src: &mut String, t: &str, n: usize, rounds: usize) {
    let names: Vec<String> = (0..n).map(|i| format!("k{i}")).collect();
    let runs: Vec<String> = names.iter().map(|k| format!("run_{k}")).collect();
    write!(
        src,
        r#"
fn main() {{
    use m::*;
    {rng}
    let len = {t}::<f64>::zero().to_array().len();
    let mut x = Vec::new();
    for _ in 0..2048 {{
        let c: Vec<f64> = (0..len).map(|_| rng()).collect();
        x.push({t}::<f64>::from_array(c.try_into().unwrap()));
    }}
    let (x, y) = x.split_at(1024);
    let direct: [fn(&{t}<f64>, &{t}<f64>) -> {t}<f64>; {n}] = [{names}];
    let runs: [fn(&[{t}<f64>], &[{t}<f64>]); {n}] = [{runs}];
    for i in 1..{n} {{
        for (a, b) in x.iter().zip(y) {{
            let (p, q) = (direct[i](a, b).to_array(), direct[0](a, b).to_array());
            assert!(p.iter().zip(&q).all(|(p, q)| (p - q).abs() <= 1e-12 * (1.0 + q.abs())), "kernel {{i}} disagrees");
        }}
    }}
    let mut times = vec![Vec::new(); {n}];
    for round in 0..{rounds} {{
        for j in 0..{n} {{
            let i = (j + round) % {n};
            let start = std::time::Instant::now();
            runs[i](x, y);
            times[i].push(start.elapsed().as_secs_f64());
        }}
    }}
    for i in 0..{n} {{
        let mut r: Vec<f64> = times[i].iter().zip(&times[0]).map(|(a, b)| a / b).collect();
        r.sort_by(f64::total_cmp);
        println!("{{}} {{:.4}}", i, r[r.len() / 2]);
    }}
}}
"#,
        rng = common::RNG,
        names = names.join(", "),
        runs = runs.join(", "),
    )
    .unwrap();
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let dir = std::path::PathBuf::from(args.get(1).map_or("/tmp/gam-products", String::as_str));
    let rounds: usize = args.get(2).map_or(1000, |r| r.parse().expect("rounds"));
    let core = args.get(3).map_or("1", String::as_str);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    for case in cases() {
        let (f, mut measured) = measure(&case, &dir, rounds, core);
        measured[1..].sort_by(|a, b| a.1.total_cmp(&b.1));
        println!("{} {} gp {}: tables' order 1.000", case.name, case.ty, case.ty);
        for (o, r) in measured.iter().skip(1).take(6) {
            println!("  {r:.3}  {o:?}");
        }
        if let Some((o, r)) = measured.get(1)
            && *r < 0.99
        {
            println!("  wisdom: ({f:#018x}, \"{} {} gp {}\", {o:?}), // {r:.3}", case.name, case.ty, case.ty);
        }
    }
}
