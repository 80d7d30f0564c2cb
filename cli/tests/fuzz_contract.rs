//! Fuzz and contract harness of the `gam` binary (runs in `cargo test`, a few seconds): random
//! inputs from grammar-aware generators (expressions, TOML algebras, JSON specs) and raw bytes,
//! plus a table of CLI cases with their expected exit classes. Every run must end with exit 0,
//! or exit 1/2 with empty stdout and exactly one `error:` line on stderr: never a panic, an
//! abort (a signal), or a timeout. The number of inputs per target is printed (run with
//! `--nocapture` to see it). The binary under test is built by `cargo test` in the test
//! profile, which keeps integer-overflow checks on (asserted below), so an overflow in a parser
//! would show up here as a panic.

use crate::common;

use common::{TempFile, run_contract as run};

use algebra_core::test_support::Xorshift;

fn expression(rng: &mut Xorshift, depth: usize) -> String {
    let atoms = ["e0", "e1", "e2", "e3", "einf", "e0inf", "e12", "1", "0", "2", "0.5", "3/4", "x", "e9", "1e5"];
    if depth == 0 || rng.below(3) == 0 {
        return rng.pick(&atoms).to_string();
    }
    match rng.below(7) {
        0 => format!("-{}", expression(rng, depth - 1)),
        1 => format!("~{}", expression(rng, depth - 1)),
        2 => format!("({})", expression(rng, depth - 1)),
        3 => {
            let f = rng.pick(&["rev", "inv", "exp", "log", "sqrt", "involute", "grade", "lc", "nope"]);
            format!("{f}({})", expression(rng, depth - 1))
        }
        _ => {
            let op = rng.pick(&["+", "-", "*", "^", "/", "**", ""]);
            format!("{}{op}{}", expression(rng, depth - 1), expression(rng, depth - 1))
        }
    }
}

fn raw_bytes(rng: &mut Xorshift, len: usize) -> Vec<u8> {
    (0..len).map(|_| rng.next_u64() as u8).collect()
}

#[test]
fn overflow_checks_are_on_in_this_profile() {
    let r = std::panic::catch_unwind(|| std::hint::black_box(u8::MAX) + std::hint::black_box(1u8));
    assert!(r.is_err(), "the test profile must keep overflow checks on (the fuzz job relies on it)");
}

#[test]
fn fuzz_expression_parser() {
    let mut rng = Xorshift(0x1234_5678_9abc_def1);
    let scalars = ["rational", "f64", "mpfr:64", "rational", "f64"];
    let mut counts = [0usize; 3];
    let n = 120;
    for _ in 0..n {
        let e = expression(&mut rng, 4);
        let scalar = rng.pick(&scalars);
        let alg = rng.pick(&["cga-null", "g3", "pga3"]);
        counts[run(&["eval", "--algebra", alg, "--scalar", scalar, "--", &e], b"") as usize] += 1;
    }
    let raw = 40;
    for _ in 0..raw {
        let len = rng.below(40);
        let bytes = raw_bytes(&mut rng, len);
        let text = String::from_utf8_lossy(&bytes).replace('\0', "");
        counts[run(&["eval", "--", &text], b"") as usize] += 1;
        // the same bytes through stdin (`-`), which need not be UTF-8
        counts[run(&["eval", "-"], &bytes) as usize] += 1;
    }
    eprintln!(
        "fuzz target eval: {} inputs (ok {}, math {}, usage {}), 0 panics/aborts/timeouts",
        n + 2 * raw,
        counts[0],
        counts[1],
        counts[2]
    );
    assert!(counts[0] > 0 && counts[2] > 0);
}

#[test]
fn fuzz_toml_algebras() {
    let mut rng = Xorshift(0x0ddc_0ffe_e0dd_f00d);
    let labels = ["a", "b", "c", "1", "inf", "a", "", "é"];
    let values = ["1", "-1", "0", "\"1/2\"", "\"1e2147483648\"", "2.5", "\"x\"", "\"3/0\"", "[1]"];
    let file = TempFile::empty("fuzz.toml");
    let mut counts = [0usize; 3];
    let n = 80;
    for i in 0..n {
        let gens: Vec<&str> = (0..rng.below(5)).map(|_| rng.pick(&labels)).collect();
        let quoted: Vec<String> = gens.iter().map(|g| format!("\"{g}\"")).collect();
        let mut entries = Vec::new();
        for _ in 0..rng.below(6) {
            let (a, b) = (rng.pick(&labels), rng.pick(&labels));
            entries.push(format!("\"{a},{b}\" = {}", rng.pick(&values)));
        }
        let text = if i % 5 == 4 {
            String::from_utf8_lossy(&raw_bytes(&mut rng, 30)).into_owned()
        } else {
            format!("generators = [{}]\nmetric = {{ {} }}\n", quoted.join(", "), entries.join(", "))
        };
        std::fs::write(file.path(), text).unwrap();
        counts[run(&["table", "--algebra", file.path()], b"") as usize] += 1;
    }
    eprintln!("fuzz target TOML algebra: {n} inputs (ok {}, usage {}), 0 panics/aborts/timeouts", counts[0], counts[2]);
    assert!(counts[0] > 0 && counts[2] > 0);
}

#[test]
fn fuzz_json_specs() {
    let mut rng = Xorshift(0xfeed_beef_cafe_1234);
    let good = ["0", "1", "-1", "2.5", "3", "0.25"];
    let bad = ["1e308", "1e-320", "\"x\"", "null", "1e400", "[]"];
    let num = |rng: &mut Xorshift| if rng.below(12) == 0 { rng.pick(&bad) } else { rng.pick(&good) };
    let vec3 = |rng: &mut Xorshift| format!("[{}, {}, {}]", num(rng), num(rng), num(rng));
    let file = TempFile::empty("fuzz.json");
    let mut counts = [0usize; 3];
    let n = 60;
    for i in 0..n {
        let kind = rng.pick(&["additive", "multiplicative", "additive", "multiplicative", "other"]);
        let degree = rng.pick(&["3", "4", "5", "3", "2", "10000", "1099511627776", "-1", "3.5"]);
        let end = |rng: &mut Xorshift| {
            format!(
                "{{\"position\": {}, \"axis\": {}, \"angle\": {}, \"velocity\": {}, \"angular_velocity\": {}}}",
                vec3(rng),
                vec3(rng),
                num(rng),
                vec3(rng),
                vec3(rng)
            )
        };
        let text = if i % 6 == 5 {
            String::from_utf8_lossy(&raw_bytes(&mut rng, 40)).into_owned()
        } else {
            format!(
                "{{\"kind\": \"{kind}\", \"degree\": {degree}, \"start\": {}, \"end\": {}}}",
                end(&mut rng),
                end(&mut rng)
            )
        };
        std::fs::write(file.path(), text).unwrap();
        let samples = rng.pick(&["2", "5", "1000000", "0"]);
        let args: &[&str] = match i % 3 {
            0 => &["hermite", file.path()],
            1 => &["sample", "--samples", samples, file.path()],
            _ => &["hermite", "--json", file.path()],
        };
        counts[run(args, b"") as usize] += 1;
    }
    eprintln!(
        "fuzz target JSON spec: {n} inputs (ok {}, math {}, usage {}), 0 panics/aborts/timeouts",
        counts[0], counts[1], counts[2]
    );
    assert!(counts[0] > 0 && counts[2] > 0);
}

/// The table of CLI cases with their expected exit classes (issue 16's findings).
#[test]
fn cli_contract_table() {
    let toml = TempFile::empty("contradict.toml");
    std::fs::write(toml.path(), "generators = [\"a\", \"b\"]\nmetric = { \"a,b\" = 1, \"b,a\" = 2 }\n").unwrap();
    let big_exp = TempFile::empty("bigexp.toml");
    std::fs::write(big_exp.path(), "generators = [\"a\"]\nmetric = { \"a,a\" = \"1e2147483648\" }\n").unwrap();
    let expr_file = TempFile::empty("expr.txt");
    std::fs::write(expr_file.path(), "e1*e2 + 3\n").unwrap();
    let at_file = format!("@{}", expr_file.path());
    let cases: &[(&[&str], &[u8], i32)] = &[
        (&["codegen", "--algebra", "g3", "--module", "r#type"], b"", 2),
        (&["codegen", "--algebra", "g3", "--module", "type"], b"", 2),
        (&["table", "--algebra", toml.path()], b"", 2),
        (&["table", "--algebra", big_exp.path()], b"", 2),
        (&["eval", "--algebra", "g3", &at_file], b"", 0),
        (&["eval", "--algebra", "g3", "@/nonexistent/expr"], b"", 2),
        (&["eval", "--algebra", "g3", "-"], b"e1*e1", 0),
        (&["eval", "--algebra", "g3", "-"], b"\xff\xfe", 2),
        (&["eval", "--algebra", "g3", "--scalar", "f64", "exp(1000000000000000000*e12)"], b"", 0),
        (&["eval", "--algebra", "g3", "--scalar", "f64", "log(0)"], b"", 1),
        (&["eval", "--algebra", "g3", "inv(e1 - e1)"], b"", 1),
    ];
    for (args, stdin, code) in cases {
        assert_eq!(run(args, stdin), *code, "gam {args:?}");
    }
    eprintln!("CLI contract table: {} cases, 0 panics/aborts/timeouts", cases.len());
}
