//! Grammar-aware property tests of the `gam` binary with proptest (next to the deterministic
//! harness in `fuzz_contract.rs`): random `gam eval` expressions over every algebra and
//! scalar, and random `gam hermite` / `gam sample` / `gam interpolate` JSON specs. Every run
//! must keep the contract: exit 0, or exit 1/2 with empty stdout and exactly one `error:`
//! line; never a panic, a signal or a timeout (`common::run_contract`). Failing inputs are
//! shrunk by proptest to a minimal expression or spec.

use crate::common;

use common::{TempFile, run_contract};
use proptest::prelude::*;

const UNARY: &[&str] = &["rev", "inv", "dual", "undual", "involute", "conj", "brev", "exp", "log", "sqrt"];
const BINARY: &[&str] = &["lc", "rc", "sp", "comm", "acomm", "gp", "op", "rp"];

fn atom() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec!["e0", "e1", "e2", "e3", "einf", "e12", "e0inf", "e123", "1", "e7", "x", "y"])
            .prop_map(str::to_string),
        (-1000i64..1000).prop_map(|n| n.to_string()),
        prop::sample::select(vec!["0.5", "3/4", "1e5", "1e-9", "2.5E3", "1e100000", "1/0", "0.0", "1e308"])
            .prop_map(str::to_string),
        // exponent notation: mantissa, optional sign, digits (and near misses such as `2e`)
        (
            0u32..1000,
            prop::sample::select(vec!["", ".5", ".25"]),
            prop::sample::select(vec!["e", "E", "e+", "e-", "E-"])
        )
            .prop_flat_map(|(m, frac, e)| (
                Just(format!("{m}{frac}{e}")),
                prop::sample::select(vec!["", "0", "7", "17", "308", "400"])
            ))
            .prop_map(|(head, exp)| format!("{head}{exp}")),
    ]
}

fn expression() -> impl Strategy<Value = String> {
    atom().prop_recursive(5, 40, 3, |inner| {
        prop_oneof![
            (inner.clone(), prop::sample::select(vec!["+", "-", "*", "^", "/"]), inner.clone())
                .prop_map(|(a, op, b)| format!("{a} {op} {b}")),
            inner.clone().prop_map(|a| format!("({a})")),
            (prop::sample::select(vec!["-", "~"]), inner.clone()).prop_map(|(op, a)| format!("{op}{a}")),
            (prop::sample::select(UNARY.to_vec()), inner.clone()).prop_map(|(f, a)| format!("{f}({a})")),
            (prop::sample::select(BINARY.to_vec()), inner.clone(), inner.clone())
                .prop_map(|(f, a, b)| format!("{f}({a}, {b})")),
            (inner.clone(), 0usize..7).prop_map(|(a, k)| format!("grade({a}, {k})")),
            (inner, prop::sample::select(vec!["x", "y", "e1"])).prop_map(|(a, v)| format!("diff({a}, {v})")),
        ]
    })
}

fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (-100.0f64..100.0).prop_map(|x| format!("{x}")),
        1 => prop::sample::select(vec!["0", "1e308", "-1e308", "1e-320", "1e400", "\"x\"", "null", "[]"]).prop_map(str::to_string),
    ]
}

fn vec3() -> impl Strategy<Value = String> {
    prop_oneof![
        10 => [number(), number(), number()].prop_map(|[a, b, c]| format!("[{a}, {b}, {c}]")),
        1 => Just("[1, 2]".to_string()),
    ]
}

fn hermite_spec() -> impl Strategy<Value = String> {
    (
        prop::sample::select(vec!["additive", "multiplicative", "linear"]),
        prop::sample::select(vec!["3", "5", "2", "0", "10001", "-1", "3.5"]),
        [vec3(), vec3(), vec3(), vec3(), vec3(), vec3(), vec3(), vec3()],
        [number(), number(), number()],
    )
        .prop_map(|(kind, degree, v, a)| {
            format!(
                r#"{{"kind": "{kind}", "degree": {degree},
  "start": {{"position": {}, "axis": {}, "angle": {}, "velocity": {}, "angular_velocity": {}, "shape": 1, "gamma": [0, 0]}},
  "end": {{"position": {}, "axis": {}, "angle": {}, "velocity": {}, "angular_velocity": {}, "shape": {}}}}}"#,
                v[0], v[1], a[0], v[2], v[3], v[4], v[5], a[1], v[6], v[7], a[2]
            )
        })
}

fn interpolate_spec() -> impl Strategy<Value = String> {
    let pose = prop_oneof![
        (vec3(), vec3(), number()).prop_map(|(p, x, a)| format!(r#"{{"position": {p}, "axis": {x}, "angle": {a}}}"#)),
        vec3().prop_map(|p| format!(r#"{{"position": {p}}}"#)),
        [number(), number(), number(), number()].prop_map(|q| format!(
            r#"{{"position": [0, 0, 0], "quaternion": [{}, {}, {}, {}]}}"#,
            q[0], q[1], q[2], q[3]
        )),
    ];
    (
        prop::sample::select(vec!["ccm-additive", "ccm-multiplicative", "juttler-spline", "slerp", ""]),
        prop::collection::vec(pose, 0..5),
        prop::sample::select(vec!["0", "2", "7", "1", "1000001"]),
    )
        .prop_map(|(method, poses, samples)| {
            format!(r#"{{"method": "{method}", "poses": [{}], "samples": {samples}}}"#, poses.join(", "))
        })
}

/// `args` with `--json` appended when `json`.
fn with_json<'a>(args: &[&'a str], json: bool) -> Vec<&'a str> {
    let mut v = args.to_vec();
    if json {
        v.push("--json");
    }
    v
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn eval_expressions_keep_the_contract(
        e in expression(),
        alg in prop::sample::select(vec!["g3", "cga", "cga-null", "g123inf"]),
        scalar in prop::sample::select(vec!["rational", "f64", "mpfr:64", "poly"]),
    ) {
        let code = run_contract(&["eval", "--algebra", alg, "--scalar", scalar, "--", &e], b"");
        prop_assert!(code <= 2);
    }

    #[test]
    fn hermite_and_sample_specs_keep_the_contract(spec in hermite_spec(), json in any::<bool>()) {
        let f = TempFile::new("prop-hermite.json", &spec);
        prop_assert!(run_contract(&with_json(&["hermite", f.path()], json), b"") <= 2);
        prop_assert!(run_contract(&with_json(&["sample", f.path(), "--samples", "5"], json), b"") <= 2);
    }

    #[test]
    fn interpolate_specs_keep_the_contract(spec in interpolate_spec(), json in any::<bool>()) {
        let f = TempFile::new("prop-interpolate.json", &spec);
        prop_assert!(run_contract(&with_json(&["interpolate", f.path()], json), b"") <= 2);
        prop_assert!(run_contract(&["sample", f.path(), "--samples", "4", "--json"], b"") <= 2);
    }
}
