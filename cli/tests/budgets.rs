//! Budgets before work in the CLI: a dense-metric algebra whose product tables would take
//! too long and a `poly` product with too many term products are one `error:` line (exit 2)
//! naming `GAM_WORK_BUDGET`, before any of the work; raising the budget lets them run.

use crate::common;

use common::{TempFile, fails, gam, ok, one_error_line};
use std::process::Command;

fn dense_toml(n: usize) -> String {
    let labels: Vec<String> = (0..n).map(|i| format!("\"a{i}\"")).collect();
    let rows: Vec<String> = (0..n)
        .map(|i| format!("[{}]", (0..n).map(|j| if i == j { "2" } else { "1" }).collect::<Vec<_>>().join(", ")))
        .collect();
    format!("generators = [{}]\ngram = [{}]\n", labels.join(", "), rows.join(", "))
}

fn sum(prefix: &str, n: usize) -> String {
    (0..n).map(|i| format!("{prefix}{i}")).collect::<Vec<_>>().join(" + ")
}

#[test]
fn a_dense_ten_generator_metric_is_refused_before_building_tables() {
    let f = TempFile::new("dense10.toml", &dense_toml(10));
    for args in [vec!["eval", "--algebra", f.path(), "ea0"], vec!["table", "--algebra", f.path()]] {
        let line = fails(&args, 2);
        assert!(line.contains("product tables of 10 generators") && line.contains("GAM_WORK_BUDGET"), "{line}");
    }
}

#[test]
fn a_small_dense_metric_runs() {
    // a_i . a_j = 1 (i != j), a_i^2 = 2: a0 a1 = a0 . a1 + a0 ^ a1 = 1 + a0a1 (blade basis)
    let f = TempFile::new("dense3.toml", &dense_toml(3));
    assert_eq!(ok(&["eval", "--algebra", f.path(), "ea0*ea1"]), "1 + ea0a1");
    assert_eq!(ok(&["eval", "--algebra", f.path(), "ea0*ea0"]), "2");
}

#[test]
fn a_large_poly_product_is_refused_then_allowed_by_the_budget() {
    // (x0 + ... + x399)(y0 + ... + y399)(z0 + ... + z399): 1.6e5 then 6.4e7 term products
    let expr = format!("({})*({})*({})", sum("x", 400), sum("y", 400), sum("z", 400));
    let args = ["eval", "--algebra", "g3", "--scalar", "poly", expr.as_str()];
    let line = fails(&args, 2);
    assert!(line.contains("the product at column") && line.contains("GAM_WORK_BUDGET"), "{line}");
    // the first product alone (1.6e5 term products) is within the default budget
    let two = format!("({})*({})", sum("x", 400), sum("y", 400));
    let out = ok(&["eval", "--algebra", "g3", "--scalar", "poly", two.as_str()]);
    assert_eq!(out.matches(" + ").count() + 1, 160_000);
    // a budget below it refuses the first product too, and a bad budget is a usage error
    let run = |budget: &str, args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_gam")).env("GAM_WORK_BUDGET", budget).args(args).output().unwrap()
    };
    let small = ["eval", "--algebra", "g3", "--scalar", "poly", two.as_str()];
    for budget in ["1e5", "-1", "lots"] {
        let out = run(budget, &small);
        assert_eq!(out.status.code(), Some(2), "{budget}");
        assert!(out.stdout.is_empty());
        one_error_line(&small, &String::from_utf8_lossy(&out.stderr));
    }
    // a product of multivectors counts every table entry: (v)(v) in g3 with 400-term coefficients
    let v = format!("({})*e1 + ({})*e2", sum("x", 400), sum("y", 400));
    let vv = format!("({v})*({v})");
    let out = run("1e6", &["eval", "--algebra", "g3", "--scalar", "poly", vv.as_str()]);
    // 4 coefficient pairs x 1.6e5 term products x 20 units = 1.28e7 > 1e6
    assert!(String::from_utf8_lossy(&out.stderr).contains("1.28e7"), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn gam_interpolate_checks_the_sampling_work() {
    let poses = r#"[{"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 0}, {"position": [1, 2, 3], "axis": [0, 1, 0], "angle": 1}]"#;
    // 1e6 samples of a cubic x 20 body points = 3.2e8 units: over the default budget
    let points = vec!["[0, 0, 0]"; 20].join(", ");
    let spec =
        format!(r#"{{"method": "ccm-additive", "poses": {poses}, "samples": 1000000, "body_points": [{points}]}}"#);
    let f = TempFile::new("interp-budget.json", &spec);
    for json in [false, true] {
        let mut args = vec!["interpolate", f.path()];
        if json {
            args.insert(1, "--json");
        }
        let line = fails(&args, 2);
        assert!(line.contains("sampling 20 body points") && line.contains("GAM_WORK_BUDGET"), "{line}");
    }
    // one body point at 11 samples is well within the budget
    let spec = format!(r#"{{"method": "ccm-additive", "poses": {poses}, "samples": 11}}"#);
    let f = TempFile::new("interp-small.json", &spec);
    assert_eq!(ok(&["interpolate", f.path()]).lines().filter(|l| l.starts_with("t = ")).count(), 11);
}

/// `(x0 + 1)*(x1 + 1)*...*(x{n-1} + 1)`.
fn product_of_binomials(n: usize) -> String {
    (0..n).map(|i| format!("(x{i} + 1)")).collect::<Vec<_>>().join("*")
}

#[test]
fn a_product_too_large_for_memory_is_refused_before_allocating() {
    // 2^k terms after k factors: the memory estimate (terms x bytes per term) passes a
    // 1e7-byte budget near k = 14, long before any allocation could fail; the default budget
    // (1e9 bytes) refuses the 24-factor product the same way (docs/robustness.md).
    let expr = product_of_binomials(24);
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_gam")).env("GAM_MEMORY_BUDGET", "1e7").args(args).output().unwrap()
    };
    let claim = format!("{expr} = 0");
    for args in [
        vec!["eval", "--algebra", "g3", "--scalar", "poly", expr.as_str()],
        vec!["prove", "--algebra", "g3", claim.as_str()],
    ] {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty());
        let line = one_error_line(&args, &String::from_utf8_lossy(&out.stderr));
        assert!(line.contains("bytes of memory") && line.contains("GAM_MEMORY_BUDGET"), "{line}");
    }
    // 8 factors (256 terms) are well within it
    let small = product_of_binomials(8);
    let out = run(&["eval", "--algebra", "g3", "--scalar", "poly", small.as_str()]);
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&out.stdout).matches(" + ").count() + 1, 256);
    let bad = Command::new(env!("CARGO_BIN_EXE_gam"))
        .env("GAM_MEMORY_BUDGET", "lots")
        .args(["eval", "--algebra", "g3", "--scalar", "poly", "x*x"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
}

#[test]
fn prove_honours_its_timeout_in_every_phase() {
    // The witness search of a long claim without hypotheses was cubic in its length (800
    // symbols took about 12 s under --timeout 1); it is linear now, and the whole run stays
    // within a small multiple of the timeout.
    let long = format!("{} = 0", sum("x", 800));
    let start = std::time::Instant::now();
    let out = gam(&["prove", "--timeout", "1", "--json", long.as_str()]);
    assert!(start.elapsed().as_secs_f64() < 6.0, "{:?}", start.elapsed());
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v["undecided"] == true || v["witness"]["point"].as_object().is_some_and(|p| p.len() == 800), "{v}");
    // Evaluating the claim: a product whose work does not fit in the time left is undecided
    // (exit 1, the budget's JSON), before it is formed.
    let big = format!("({})*({}) = 0", sum("x", 400), sum("y", 400));
    let args = ["prove", "--timeout", "0.01", "--json", big.as_str()];
    let out = gam(&args);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["undecided"], true);
    assert!(v["reason"].as_str().unwrap().contains("time limit"), "{v}");
    let line = one_error_line(&args, &String::from_utf8_lossy(&out.stderr));
    assert!(line.contains("raise --timeout"), "{line}");
    // The basis-size budget is an option too.
    let args = ["prove", "--max-basis", "1", "--assume", "x*y = 1", "--assume", "x*x = y", "x = y"];
    let out = gam(&args);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("undecided: "), "{out:?}");
    assert!(one_error_line(&args, &String::from_utf8_lossy(&out.stderr)).contains("basis size"));
    fails(&["prove", "--max-terms", "0", "x = x"], 2);
}

/// Jüttler's global interpolants (one curve through all key poses) are estimated before they
/// are built: 400 key poses through `juttler-q-motion` ran past 600 s; now refused at once.
#[test]
fn global_juttler_builds_are_estimated_before_the_build() {
    let poses: Vec<String> = (0..400)
        .map(|i| format!(r#"{{"position": [{}, {}, 0], "axis": [0, 0, 1], "angle": {}}}"#, i % 7, i % 5, i % 3))
        .collect();
    for method in ["juttler-q-motion", "juttler-trt", "juttler-minimal"] {
        let spec = format!(r#"{{"method": "{method}", "poses": [{}]}}"#, poses.join(", "));
        let f = TempFile::new(&format!("global-{method}.json"), &spec);
        let start = std::time::Instant::now();
        let line = fails(&["interpolate", f.path()], 2);
        assert!(
            line.contains(&format!("building {method} through 400 key poses")) && line.contains("GAM_WORK_BUDGET"),
            "{line}"
        );
        assert!(start.elapsed().as_secs_f64() < 10.0, "{method}: refused only after {:?}", start.elapsed());
    }
}

/// Exact rational products are budgeted by their coefficients' sizes (a multiply and a gcd
/// quadratic in the limbs), and the budget bounds the whole expression: ten products of
/// 100,000-digit rationals, each within the budget alone, took minutes together.
#[test]
fn exact_products_of_huge_rationals_are_budgeted_in_total() {
    let run = |budget: Option<&str>, expr: &str| {
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_gam"));
        if let Some(b) = budget {
            cmd.env("GAM_WORK_BUDGET", b);
        }
        cmd.args(["eval", "--algebra", "g3", "--scalar", "rational", expr]).output().unwrap()
    };
    // (10^n + 1)(10^n - 1) = 10^2n - 1: 2n nines (exact arithmetic by hand)
    let pair = |n: usize| format!("(1E{n} + 1)*(1E{n} - 1)");
    let out = run(None, &pair(50_000));
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "9".repeat(100_000));
    // 2 x 2,600 limbs: about 9e5 units, refused under a budget of 4e5 before the work
    let args = ["eval", &pair(50_000)];
    let out = run(Some("4e5"), &pair(50_000));
    assert_eq!(out.status.code(), Some(2));
    let line = one_error_line(&args, &String::from_utf8_lossy(&out.stderr));
    assert!(
        line.starts_with("error: the product at column 14 needs about") && line.contains("GAM_WORK_BUDGET"),
        "{line}"
    );
    // 20,000 digits: the first product (1.4e5 units) and the second alone (3.2e5) are within
    // 4e5, the two together are not
    let out = run(Some("4e5"), &pair(20_000));
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "9".repeat(40_000));
    let three = format!("{}*(1E20000 + 3)", pair(20_000));
    let out = run(Some("4e5"), &three);
    assert_eq!(out.status.code(), Some(2));
    let line = one_error_line(&args, &String::from_utf8_lossy(&out.stderr));
    assert!(line.contains("the product at column 28 (with the") && line.contains("units before it)"), "{line}");
}

/// A long sum is evaluated in place: `acc = &acc + &y` copied the accumulator, so a sum of
/// `n` polynomial variables was quadratic and outside every budget (16,000 variables took
/// 35 s; the 130,000 of a 1 MiB expression, most of an hour). The value is checked term by term.
#[test]
fn long_sums_of_polynomials_are_evaluated_in_place() {
    let n = 60_000;
    let expr = TempFile::new("long-sum.txt", &format!("{} - x7 - 2*e1", sum("x", n)));
    let at = format!("@{}", expr.path());
    let out = ok(&["eval", "--algebra", "g3", "--scalar", "poly", &at]);
    let (scalar, e1) = out.trim().rsplit_once(" - ").unwrap();
    assert_eq!(e1, "2*e1");
    let mut terms: Vec<&str> = scalar.split(" + ").collect();
    terms.sort_unstable();
    let mut want: Vec<String> = (0..n).filter(|i| *i != 7).map(|i| format!("x{i}")).collect();
    want.sort_unstable();
    assert_eq!(terms, want);
}
