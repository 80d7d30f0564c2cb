//! The work estimates of `GAM_WORK_BUDGET` against the time the work takes (issue 30, item 3):
//! for each case the `gam` binary is run with a budget of one unit, which refuses the work
//! and names its estimate ("needs about X units of work"), then with the budget raised to
//! each estimate named until it succeeds (timed; the last estimate is the whole work). The estimate promises `X / UNITS_PER_SECOND` seconds on one core; the report
//! prints that, the measured time and their ratio, and fails (exit 1) when a case is
//! off by more than 2x either way. Cases: multiplicative segments through `gam sample`
//! (dual numbers), `gam plot` (second-order dual numbers) and `gam interpolate` (the
//! sampler), additive ones, the other methods' samples (Wareham–Lasenby, Jüttler's rational
//! motions), the builds of Jüttler's global interpolants (`juttler-trt` is not among
//! them: its interpolant fails the key-pose check from about 20 poses, before its build
//! takes measurable time; its constant comes from a 30-pose run, 0.18 s for 0.14 s promised),
//! and exact rational products in `gam eval` (coefficients of 30,000 and 100,000 digits).
//!
//! ```text
//! cargo bench -p gam --bench work_estimate
//! ```
#![allow(missing_docs)]

use std::process::Command;
use std::time::Instant;

/// A Hermite spec of `kind` and `degree` (the contract's example end conditions).
fn hermite(kind: &str, degree: usize) -> String {
    format!(
        r#"{{"kind": "{kind}", "degree": {degree},
  "start": {{"position": [0,0,0], "axis": [0,0,1], "angle": 0, "velocity": [1,1,1], "angular_velocity": [1,2,3]}},
  "end": {{"position": [8,10,12], "axis": [1,2,3], "angle": 1.959, "velocity": [1,5,3], "angular_velocity": [2,1,1]}}}}"#
    )
}

/// A `gam interpolate` spec of `method` through `m` key poses on a helix, sampled `n` times.
fn interpolate(method: &str, m: usize, n: usize) -> String {
    let poses: Vec<String> = (0..m)
        .map(|i| {
            let a = i as f64 * 0.4;
            format!(
                r#"{{"position": [{}, {}, {}], "axis": [0, 0.3, 1], "angle": {a}}}"#,
                3.0 * a.cos(),
                3.0 * a.sin(),
                0.2 * a
            )
        })
        .collect();
    format!(r#"{{"method": "{method}", "poses": [{}], "samples": {n}}}"#, poses.join(", "))
}

/// `n` pseudo-random decimal digits (a fixed LCG), the first non-zero.
fn digits(n: usize, seed: u64) -> String {
    let mut x = seed;
    (0..n)
        .map(|i| {
            x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            let d = (x >> 33) % 10;
            char::from(b'0' + if i == 0 { 1 + d as u8 % 9 } else { d as u8 })
        })
        .collect()
}

/// A `gam eval` product of two g3 elements with `k` coefficients of `n` digits each
/// (rationals over small primes, so every product is normalised by a gcd).
fn exact_product(k: usize, n: usize) -> String {
    let names = ["1", "e1", "e2", "e12"];
    let element = |seed: u64, p: u64| {
        let terms: Vec<String> = (0..k).map(|i| format!("{}/{p}*{}", digits(n, seed + i as u64), names[i])).collect();
        format!("({})", terms.join(" + "))
    };
    format!("{}*{}", element(1, 7), element(100, 11))
}

struct Case {
    name: String,
    spec: String,
    args: Vec<String>,
}

fn case(name: &str, spec: String, args: &[&str]) -> Case {
    Case { name: name.to_string(), spec, args: args.iter().map(|s| s.to_string()).collect() }
}

fn run(args: &[String], budget: &str) -> (bool, String, f64) {
    let start = Instant::now();
    let out =
        Command::new(env!("CARGO_BIN_EXE_gam")).env("GAM_WORK_BUDGET", budget).args(args).output().expect("gam runs");
    let secs = start.elapsed().as_secs_f64();
    (out.status.success(), String::from_utf8_lossy(&out.stderr).into_owned(), secs)
}

fn main() {
    let dir = std::env::temp_dir().join(format!("gam-work-estimate-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("out.svg").to_string_lossy().into_owned();
    let cases = vec![
        case("sample, multiplicative, degree 100", hermite("multiplicative", 100), &["sample", "--samples", "1000"]),
        case("sample, multiplicative, degree 400", hermite("multiplicative", 400), &["sample", "--samples", "60"]),
        case("sample, additive, degree 400", hermite("additive", 400), &["sample", "--samples", "2000"]),
        case(
            "plot, multiplicative, degree 100",
            hermite("multiplicative", 100),
            &["plot", "--out", &svg, "--samples", "300"],
        ),
        case(
            "plot, multiplicative, degree 400",
            hermite("multiplicative", 400),
            &["plot", "--out", &svg, "--samples", "20"],
        ),
        case(
            "interpolate, ccm-multiplicative, 40 poses",
            interpolate("ccm-multiplicative", 40, 20000),
            &["interpolate", "--json"],
        ),
        case("interpolate, ccm-additive, 40 poses", interpolate("ccm-additive", 40, 20000), &["interpolate", "--json"]),
        case("interpolate text, ccm-multiplicative", interpolate("ccm-multiplicative", 40, 20000), &["interpolate"]),
        case("interpolate, wl-quadratic, 40 poses", interpolate("wl-quadratic", 40, 20000), &["interpolate", "--json"]),
        case(
            "interpolate, juttler-spline, 40 poses",
            interpolate("juttler-spline", 40, 20000),
            &["interpolate", "--json"],
        ),
        case(
            "plot, ccm-multiplicative, 40 poses",
            interpolate("ccm-multiplicative", 40, 0),
            &["plot", "--out", &svg, "--samples", "20000"],
        ),
        case(
            "interpolate, juttler-q-motion, 45 poses (build)",
            interpolate("juttler-q-motion", 45, 0),
            &["interpolate", "--json"],
        ),
        case(
            "interpolate, juttler-minimal, 40 poses (build)",
            interpolate("juttler-minimal", 40, 0),
            &["interpolate", "--json"],
        ),
        case("eval, rational product, 2 x 100,000 digits", exact_product(1, 100_000), &["eval", "--algebra", "g3"]),
        case(
            "eval, rational product, g3, 4 x 4 x 30,000 digits",
            exact_product(4, 30_000),
            &["eval", "--algebra", "g3"],
        ),
    ];
    let per_second = gam::budget::UNITS_PER_SECOND;
    println!("work estimates against measured time (UNITS_PER_SECOND = {per_second:.0e}):");
    println!("  {:<44} {:>11} {:>11} {:>11} {:>8}", "case", "estimate", "promised s", "measured s", "ratio");
    let mut bad = Vec::new();
    for (i, c) in cases.iter().enumerate() {
        let file = dir.join(format!("spec{i}.json"));
        std::fs::write(&file, &c.spec).unwrap();
        let mut args = c.args.clone();
        if args[0] == "eval" {
            // the expression from the file (one product: its estimate is the whole work)
            args.push(format!("@{}", file.to_string_lossy()));
        } else {
            args.insert(1, file.to_string_lossy().into_owned());
        }
        // raise the budget to each refusal's estimate until the run succeeds: a command may
        // check its work in steps (`gam eval`: the product tables, then every product and
        // inverse, counted together), and the last refusal names the whole; the successful
        // run is the timed one
        let (mut budget, mut units) = (1.0f64, 0.0f64);
        let secs = loop {
            let (ok, stderr, secs) = run(&args, &format!("{budget:e}"));
            if ok {
                assert!(units > 0.0, "{}: the budget of one unit did not refuse", c.name);
                break secs;
            }
            units = match stderr.split("needs about ").nth(1) {
                Some(rest) => rest.split_whitespace().next().and_then(|x| x.parse().ok()).expect("an estimate"),
                None => panic!("{}: failed without naming an estimate: {stderr}", c.name),
            };
            budget = units * 1.01;
        };
        let promised = units / per_second;
        let ratio = secs / promised;
        let mark = if (0.5..=2.0).contains(&ratio) {
            ""
        } else {
            bad.push(c.name.clone());
            "OFF"
        };
        println!("  {:<44} {units:>11.2e} {promised:>11.2} {secs:>11.2} {ratio:>7.2}x {mark}", c.name);
    }
    std::fs::remove_dir_all(&dir).ok();
    if !bad.is_empty() {
        eprintln!("estimates off by more than 2x: {}", bad.join(", "));
        std::process::exit(1);
    }
}
