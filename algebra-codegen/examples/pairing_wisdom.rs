//! Re-derives the pairing wisdom of the fused versor actions (`algebra_codegen::versor::WISDOM`,
//! docs/performance.md "Term order of the fused actions", fifth session).
//!
//! For each benched action kernel (the modules and types of `cargo bench -p gam-algebras
//! --bench products`' fused groups) it writes one Rust program holding the module's types and
//! geometric product (`standalone::file_with`) and the kernel's body as the generator emits it
//! in every candidate order ([`TermOrder`]: six summand orders per stage, trees or chains),
//! compiles it with `rustc -O` (edition 2024, baseline x86-64 as the benches), runs it pinned
//! to one core, and prints each candidate's median ratio to the motor product (interleaved
//! rounds of 1024 pairs, as the bench) and the `WISDOM` entry of the fastest, when it beats
//! the default order by more than the noise (0.01).
//!
//! ```sh
//! cargo run --release -p algebra-codegen --example pairing_wisdom -- [DIR] [ROUNDS] [CORE]
//! ```
//! (`DIR` the scratch directory, default `/tmp/gam-pairing`; `ROUNDS` default 1000; `CORE`
//! the core to pin to with `taskset`, default 1; `GAM_PAIRING_ONLY=name` one case). The best
//! eight orders of phase 2 are timed again in a third program, the check on noise. Kernels
//! are verified against the default order's result before timing (the same values up to
//! rounding).

use algebra_codegen::plan::Plan;
use algebra_codegen::standalone::{Selection, file_with};
use algebra_codegen::versor::{
    self, ActionKernel, Convention, NormOrder, RowOrder, TermOrder, apply_order, default_order, fingerprint,
};
use algebra_codegen::{ModuleSpec, emit};
use algebra_core::{Algebra, Basis, Metric};
use std::fmt::Write as _;

mod common;

/// One benched module: name, plan, versor and operand type names, the operand's generator.
struct Case {
    name: &'static str,
    plan: Plan,
    versor: &'static str,
    operand: &'static str,
    /// Rust expression of the operand from `p: [f64; 3]` (a point of the model).
    point: &'static str,
    conventions: &'static [Convention],
}

fn plan(alg: &Algebra, metric: Metric, basis: Basis, types: &str, table_above: Option<usize>) -> Plan {
    let types = ModuleSpec::parse_types(types, alg).expect("types");
    let mut spec = ModuleSpec::new("m", metric, basis, types).expect("spec");
    if let Some(t) = table_above {
        spec.table_above = t;
    }
    Plan::new(spec).expect("plan")
}

fn cases() -> Vec<Case> {
    let builtin = |n: &str| Algebra::builtin(n).expect("builtin");
    let z = "0";
    let gram: [&[&str]; 5] =
        [&["1", z, z, z, z], &[z, "1", z, z, z], &[z, z, "1", z, z], &[z, z, z, z, "-1"], &[z, z, z, "-1", z]];
    let gatl_metric = Metric::from_strs(&["1", "2", "3", "o", "inf"], &gram).expect("metric");
    let gatl = Algebra::new("gatl", gatl_metric.clone());
    let both = &[Convention::Sandwich, Convention::Apply];
    let cn = builtin("cga-null");
    let (g3, pga3, cga) = (builtin("g3"), builtin("pga3"), builtin("cga"));
    let motor = "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf";
    vec![
        Case {
            name: "cga_null",
            plan: plan(&cn, cn.metric().clone(), Basis::Product, &format!("Vector=grade1;{motor}"), None),
            versor: "Motor",
            operand: "Vector",
            point: "Vector::from_array([1.0, p[0], p[1], p[2], (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / 2.0])",
            conventions: both,
        },
        Case {
            name: "gatl",
            plan: plan(&gatl, gatl_metric, Basis::Blade, &format!("Vector=grade1;Bivector=grade2;{motor}"), None),
            versor: "Motor",
            operand: "Vector",
            point: "Vector::from_array([p[0], p[1], p[2], 1.0, (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / 2.0])",
            conventions: both,
        },
        Case {
            name: "g3",
            plan: plan(&g3, g3.metric().clone(), Basis::Blade, "Vector=grade1;Rotor=even", None),
            versor: "Rotor",
            operand: "Vector",
            point: "Vector::from_array(p)",
            conventions: both,
        },
        Case {
            name: "pga3",
            plan: plan(&pga3, pga3.metric().clone(), Basis::Blade, "Trivector=grade3;Motor=even", None),
            versor: "Motor",
            operand: "Trivector",
            point: "Trivector::from_array([p[0], p[1], p[2], 1.0])",
            conventions: both,
        },
        // a motor on a plane: not benched, timed as the evidence for the plan's rule that takes
        // the norm form without a measured order where it saves a fifth of the operations
        // (`versor::NORM_FORM_SAVING`)
        Case {
            name: "pga3_planes",
            plan: plan(&pga3, pga3.metric().clone(), Basis::Blade, "Vector=grade1;Motor=even", None),
            versor: "Motor",
            operand: "Vector",
            point: "Vector::from_array([p[0], p[1], p[2], 1.0])",
            conventions: both,
        },
        Case {
            name: "cga",
            plan: plan(&cga, cga.metric().clone(), Basis::Blade, "Vector=grade1;Motor=even", Some(256)),
            versor: "Motor",
            operand: "Vector",
            point: "Vector::from_array([p[0], p[1], p[2], p[0] * p[1] - 0.5, p[0] * p[1] + 0.5])",
            conventions: &[Convention::Sandwich],
        },
    ]
}

/// The candidate orders for a kernel with `nv` versor fields: phase 1 every flip of the
/// versor's fields (all `2^nv`) with each norm order, stage orders as the default; phase 2
/// (given the best flips and norm orders of phase 1) every stage order and shape.
fn phase1(k: &ActionKernel) -> Vec<TermOrder> {
    let nv = k
        .stage1
        .iter()
        .flatten()
        .map(|t| t.0 + 1)
        .max()
        .unwrap_or(0)
        .max(k.stage2.iter().flatten().map(|t| t.1 + 1).max().unwrap_or(0));
    let norms: &[NormOrder] = if k.norm.is_some() {
        &[NormOrder::Tables, NormOrder::Outside, NormOrder::Halves]
    } else {
        &[NormOrder::Tables]
    };
    let base = default_order(k);
    let mut out = Vec::new();
    // every flip up to eight fields (a motor); larger versors (cga's 16) keep theirs
    for flip in 0..if nv <= 8 { 1u32 << nv } else { 1 } {
        for &norm in norms {
            for (stage1, stage2) in [(base.stage1, base.stage2), (RowOrder::PositiveVersor, RowOrder::PositiveVersor)] {
                out.push(TermOrder { stage1, stage2, flip, norm, ..base });
            }
        }
    }
    out
}

fn phase2(best: &[TermOrder]) -> Vec<TermOrder> {
    use RowOrder::*;
    let rows =
        [Tables, Versor, Other, PositiveFirst, PositiveVersor, PositiveOther, PositiveHalves, PositiveHalvesVersor];
    let mut out = Vec::new();
    for b in best {
        for chains in [[false, false], [true, false], [false, true], [true, true]] {
            for stage1 in rows {
                for stage2 in rows {
                    out.push(TermOrder { stage1, stage2, chains, ..*b });
                }
            }
        }
    }
    out
}

/// Per candidate: label, fingerprint, order (`None`: the default, first of its group) and the
/// function's name.
type Kernels = Vec<(String, u64, Option<TermOrder>, String)>;

/// The kernels to order, per convention of the case: the general form and, where it is exact,
/// the scalar-norm form (`versor::norm_form`), each in the tables' order.
fn bases(case: &Case, v: usize, x: usize) -> Vec<(String, ActionKernel)> {
    let mut out = Vec::new();
    for &conv in case.conventions {
        let k = case.plan.actions.iter().find(|k| (k.versor, k.operand, k.convention) == (v, x, conv)).expect("kernel");
        let mut general = k.clone();
        if general.norm.is_some() {
            // the plan took the scalar-norm form: rebuild the general one from a plan without it
            general = general_kernel(case, v, x, conv);
        }
        apply_order(&mut general, TermOrder::TABLES);
        out.push((format!("{conv:?}"), general.clone()));
        if let Some(mut n) = versor::norm_form(&case.plan, &general).expect("norm form") {
            apply_order(&mut n, TermOrder::TABLES);
            out.push((format!("{conv:?}-norm"), n));
        }
    }
    out
}

/// The general fused kernel of a pair (the plan's may be the scalar-norm form): from a plan of
/// the same spec whose kernels are planned afresh, found by convention and types.
fn general_kernel(case: &Case, v: usize, x: usize, conv: Convention) -> ActionKernel {
    let actions = versor::plan_actions(&case.plan.spec, case.plan.full).expect("actions");
    let mut k = actions.into_iter().find(|k| (k.versor, k.operand, k.convention) == (v, x, conv)).expect("kernel");
    let signs: Vec<Vec<i64>> = case.plan.spec.types.iter().map(algebra_codegen::TypeSpec::signs).collect();
    assert!(signs.iter().flatten().all(|&s| s == 1), "the benched declarations rename no blade");
    k.chains = [false, false];
    k
}

/// Writes, compiles and runs one program timing `orders` of the kernels of `case` (per
/// convention, the default order first); returns the kernels and their ratios.
fn measure(
    case: &Case,
    orders: &dyn Fn(&ActionKernel) -> Vec<TermOrder>,
    dir: &std::path::Path,
    rounds: usize,
    core: &str,
) -> (Kernels, Vec<f64>) {
    let types: Vec<&str> = case.plan.spec.types.iter().map(|t| t.name.as_str()).collect();
    let (v, x) = (
        types.iter().position(|t| *t == case.versor).expect("versor"),
        types.iter().position(|t| *t == case.operand).expect("operand"),
    );
    let selection = Selection { ops: Some(["gp".to_string()].into()), every_type: false };
    let module = file_with(&case.plan, &[], Some("m"), &selection).expect("standalone file");
    let mut src = String::new();
    writeln!(src, "#![allow(warnings)]\n{}", quote::ToTokens::to_token_stream(&module)).unwrap();
    let mut kernels: Kernels = Vec::new();
    for (form, k) in bases(case, v, x) {
        let f = fingerprint(&k);
        let mut bodies: Vec<String> = Vec::new();
        let mut all = vec![None];
        all.extend(orders(&k).into_iter().map(Some));
        // `groups` starts a group at each `None` (the default order)
        for order in all {
            let mut kk = k.clone();
            apply_order(&mut kk, order.unwrap_or_else(|| default_order(&k)));
            // as the plan binds them (`ActionKernel::operand_constants`)
            kk.operand_constants = kk.norm.is_none();
            let body = emit::action_body(&case.plan, &kk)
                .to_string()
                .replace("self .", "s .")
                .replace("__gam_engine ::", "m ::");
            if order.is_some() && bodies.contains(&body) {
                continue;
            }
            let name = format!("k{}", kernels.len());
            bodies.push(body.clone());
            writeln!(
                src,
                "#[inline(always)] fn {name}(s: &m::{vt}<f64>, x: &m::{xt}<f64>) -> m::{xt}<f64> {{ use m::*; type T = f64; {body} }}",
                vt = case.versor,
                xt = case.operand
            )
            .unwrap();
            let label = match order {
                None => format!("{form} default"),
                Some(o) => format!("{form} {o:?}"),
            };
            kernels.push((label, f, order, name));
        }
    }
    harness(&mut src, case, &kernels, rounds);
    let ratios = common::compile_and_time(dir, case.name, &src, core, kernels.len());
    (kernels, ratios)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let dir = std::path::PathBuf::from(args.get(1).map_or("/tmp/gam-pairing", String::as_str));
    let rounds: usize = args.get(2).map_or(1000, |r| r.parse().expect("rounds"));
    let core = args.get(3).map_or("1", String::as_str);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    let only = std::env::var("GAM_PAIRING_ONLY").ok();
    for case in cases() {
        if only.as_ref().is_some_and(|o| o != case.name) {
            continue;
        }
        // phase 1: flips and norm orders; the best four of each convention go to phase 2
        let (kernels, ratios) = measure(&case, &phase1, &dir, rounds, core);
        let mut best: Vec<Vec<TermOrder>> = Vec::new();
        for (lo, hi) in groups(&kernels) {
            let mut ranked: Vec<usize> = (lo + 1..hi).collect();
            ranked.sort_by(|&a, &b| ratios[a].total_cmp(&ratios[b]));
            println!(
                "{} {} phase 1: default {:.3}, best {:?}",
                case.name,
                kernels[lo].0,
                ratios[lo],
                ranked.first().map(|&i| (ratios[i], &kernels[i].0))
            );
            let mut top: Vec<TermOrder> = Vec::new();
            for &i in &ranked {
                let o = kernels[i].2.expect("a candidate");
                if top.len() < 4 && !top.iter().any(|t| (t.flip, t.norm) == (o.flip, o.norm)) {
                    top.push(o);
                }
            }
            best.push(top);
        }
        let fps: Vec<u64> = groups(&kernels).iter().map(|&(lo, _)| kernels[lo].1).collect();
        let index = |k: &ActionKernel| fps.iter().position(|f| *f == fingerprint(k)).expect("a measured kernel");
        let (kernels, ratios) = measure(&case, &|k| phase2(&best[index(k)]), &dir, rounds, core);
        report(&case, &kernels, &ratios);
        // phase 3: the best eight orders of phase 2 timed again in a new program (the ranking
        // should hold; the ratios move with the machine's noise)
        let mut top: Vec<Vec<TermOrder>> = Vec::new();
        for (lo, hi) in groups(&kernels) {
            let mut ranked: Vec<usize> = (lo + 1..hi).collect();
            ranked.sort_by(|&a, &b| ratios[a].total_cmp(&ratios[b]));
            top.push(ranked.iter().take(8).map(|&i| kernels[i].2.expect("a candidate")).collect());
        }
        let (kernels, ratios) = measure(&case, &|k| top[index(k)].clone(), &dir, rounds, core);
        report(&case, &kernels, &ratios);
    }
}

/// The index ranges of each convention's kernels (the default first).
fn groups(kernels: &Kernels) -> Vec<(usize, usize)> {
    let starts: Vec<usize> = (0..kernels.len()).filter(|&i| kernels[i].2.is_none()).collect();
    starts.iter().enumerate().map(|(n, &s)| (s, starts.get(n + 1).copied().unwrap_or(kernels.len()))).collect()
}

/// The `main` of the generated program: data, a correctness check of every kernel against the
/// first (the default order) of its convention, and the interleaved rounds.
fn harness(src: &mut String, case: &Case, kernels: &Kernels, rounds: usize) {
    let (vt, xt) = (case.versor, case.operand);
    let n = kernels.len();
    let calls: Vec<String> = kernels.iter().map(|k| format!("run_{}", k.3)).collect();
    for k in kernels {
        writeln!(
            src,
            "#[inline(never)] fn run_{0}(s: &[m::{vt}<f64>], x: &[m::{xt}<f64>]) {{ for (a, b) in s.iter().zip(x) {{ let (a, b) = (std::hint::black_box(a), std::hint::black_box(b)); std::hint::black_box({0}(a, b)); }} }}",
            k.3
        )
        .unwrap();
    }
    writeln!(src, "#[inline(never)] fn run_product(s: &[m::{vt}<f64>], x: &[m::{vt}<f64>]) {{ for (a, b) in s.iter().zip(x) {{ let (a, b) = (std::hint::black_box(a), std::hint::black_box(b)); std::hint::black_box(m::GeometricProduct::gp(a, b)); }} }}").unwrap();
    let firsts: Vec<usize> =
        (0..n).map(|i| (0..=i).rev().find(|&j| kernels[j].2.is_none()).expect("a default first")).collect();
    write!(
        src,
        r#"
fn main() {{
    use m::*;
    {rng}
    let len = {vt}::<f64>::zero().to_array().len();
    let (mut s, mut t, mut x) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..1024 {{
        let c: Vec<f64> = (0..len).map(|_| rng()).collect();
        s.push({vt}::<f64>::from_array(c.clone().try_into().unwrap()));
        let c: Vec<f64> = (0..len).map(|_| rng()).collect();
        t.push({vt}::<f64>::from_array(c.try_into().unwrap()));
        let p = [rng(), rng(), rng()];
        x.push({point});
    }}
    let kernels: [fn(&[{vt}<f64>], &[{xt}<f64>]); {n}] = [{calls}];
    let direct: [fn(&{vt}<f64>, &{xt}<f64>) -> {xt}<f64>; {n}] = [{names}];
    let firsts = {firsts:?};
    for i in 0..{n} {{
        for (a, b) in s.iter().zip(&x) {{
            let (y, z) = (direct[i](a, b).to_array(), direct[firsts[i]](a, b).to_array());
            assert!(y.iter().zip(&z).all(|(y, z)| (y - z).abs() <= 1e-12 * (1.0 + z.abs())), "kernel {{i}} disagrees");
        }}
    }}
    let mut times = vec![Vec::new(); {n} + 1];
    for round in 0..{rounds} {{
        for j in 0..{n} + 1 {{
            let i = (j + round) % ({n} + 1);
            let start = std::time::Instant::now();
            if i == 0 {{ run_product(&s, &t) }} else {{ kernels[i - 1](&s, &x) }}
            times[i].push(start.elapsed().as_secs_f64());
        }}
    }}
    for i in 1..{n} + 1 {{
        let mut r: Vec<f64> = times[i].iter().zip(&times[0]).map(|(a, b)| a / b).collect();
        r.sort_by(f64::total_cmp);
        println!("{{}} {{:.4}}", i - 1, r[r.len() / 2]);
    }}
}}
"#,
        rng = common::RNG,
        point = case.point,
        calls = calls.join(", "),
        names = kernels.iter().map(|k| k.3.as_str()).collect::<Vec<_>>().join(", "),
    )
    .unwrap();
}

fn report(case: &Case, kernels: &Kernels, ratios: &[f64]) {
    for (i, end) in groups(kernels) {
        let default = ratios[i];
        let mut ranked: Vec<usize> = (i + 1..end).collect();
        ranked.sort_by(|&a, &b| ratios[a].total_cmp(&ratios[b]));
        println!("{} {}: {:.3}", case.name, kernels[i].0, default);
        for &j in ranked.iter().take(8) {
            println!("  {:.3}  {}", ratios[j], kernels[j].0);
        }
        if let Some(&best) = ranked.first()
            && ratios[best] < default - 0.01
        {
            let order = kernels[best].2.expect("a candidate");
            println!(
                "  wisdom: ({:#018x}, \"{} {}\", {order:?}), // {:.3} (default {default:.3})",
                kernels[i].1,
                case.name,
                kernels[i].0.split(' ').next().unwrap_or(""),
                ratios[best],
            );
        }
    }
    let _ = versor::WISDOM;
}
