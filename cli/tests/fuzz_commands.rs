//! Fuzzing that checks values, on the commands the other harnesses leave out (issue 30,
//! item 5): `gam eval` (exact runs against f64 runs), `gam hermite`/`gam sample` (end
//! conditions met), `gam trajectory` (the curves start and end at the key poses' images of
//! the point), `gam surface`, `gam plot --out` (a complete SVG, finite speeds), `gam figures`,
//! `gam prove` (its verdict against the expansion of `lhs - rhs`, its witness a real
//! counterexample), `gam codegen` with random options (the Rust it prints parses), `gam table`,
//! `gam algebras` and `gam verify`. Good and bad inputs are mixed; every run goes through
//! `common::run_capped` (4 GB `ulimit -v`, a timeout, one `error:` line with exit 1/2, no
//! `inf`/`NaN` printed). The number of runs per command is printed (`--nocapture`) and in
//! docs/robustness.md.

use crate::common;

use algebra_core::rational::{Q, parse_rational, rational_to_f64};
use algebra_core::test_support::Xorshift;
use common::{TempFile, rodrigues, run_capped};
use serde_json::Value;

fn json(text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not JSON ({e}): {}", &text[..text.len().min(300)]))
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| v.as_str().and_then(|s| s.parse().ok()).unwrap_or_else(|| panic!("not a number: {v}")))
}

/// A random expression over small rationals and basis elements of g3, pga3 or cga.
fn expression(rng: &mut Xorshift, atoms: &[&str], depth: usize) -> String {
    if depth == 0 || rng.below(3) == 0 {
        return rng.pick(atoms).to_string();
    }
    let (a, b) = (expression(rng, atoms, depth - 1), expression(rng, atoms, depth - 1));
    match rng.below(12) {
        0 => format!("~({a})"),
        1 => format!("({a})/{}", rng.pick(&["2", "3", "7/5"])),
        2 => format!("inv({a})"),
        3 => format!("({a}) ^ ({b})"),
        4 | 5 => format!("({a}) - ({b})"),
        6 | 7 => format!("({a}) + ({b})"),
        8 => format!("({a})**{}", 1 + rng.below(3)),
        _ => format!("({a})*({b})"),
    }
}

/// `gam eval` exactly (`--scalar rational`) and in f64: where the exact run succeeds, the f64
/// run gives the same coefficients to 1e-9 of their size (or, for an element that is exactly
/// singular, refuses as well or gives a huge value: not compared).
#[test]
fn eval_exact_runs_agree_with_f64_runs() {
    let mut rng = Xorshift(0x0e7a_1c0d_e5ee_d001);
    let algebras: [(&str, &[&str]); 3] = [
        ("g3", &["e1", "e2", "e3", "e12", "e123", "1", "2", "1/3", "-5/7", "0.25"]),
        ("pga3", &["e0", "e1", "e2", "e12", "e03", "e0123", "1", "3/2", "-2"]),
        ("cga-null", &["e1", "e2", "e3", "e0", "einf", "e1inf", "1", "1/2", "-3"]),
    ];
    let (mut runs, mut compared, mut coefficients) = (0, 0, 0);
    for _ in 0..100 {
        let (alg, atoms) = algebras[rng.below(3)];
        let e = expression(&mut rng, atoms, 5);
        let (code, exact) =
            run_capped(&["eval", "--json", "--algebra", alg, "--scalar", "rational", "--", &e], b"", false);
        let (code64, float) =
            run_capped(&["eval", "--json", "--algebra", alg, "--scalar", "f64", "--", &e], b"", false);
        runs += 2;
        if code != 0 {
            assert_eq!(code, 1, "{alg}: {e}: only `not invertible` may fail");
            continue;
        }
        assert_eq!(code64, 0, "{alg}: {e}: f64 refused what the exact run computed");
        let (exact, float) = (json(&exact), json(&float));
        let q: Vec<(String, f64)> = exact
            .as_object()
            .unwrap()
            .iter()
            .map(|(k, v)| (k.clone(), rational_to_f64(&parse_rational(v.as_str().unwrap()).unwrap())))
            .collect();
        let size = q.iter().fold(1.0f64, |m, (_, x)| m.max(x.abs()));
        for (k, x) in &q {
            let y = float.get(k).map_or(0.0, num);
            assert!((x - y).abs() <= 1e-9 * size, "{alg}: {e}: {k} exact {x} vs f64 {y}");
            coefficients += 1;
        }
        for (k, y) in float.as_object().unwrap() {
            if !q.iter().any(|(name, _)| name == k) {
                assert!(num(y).abs() <= 1e-9 * size, "{alg}: {e}: {k} is exactly 0, f64 {y}");
            }
        }
        compared += 1;
    }
    assert!(compared >= 50, "only {compared} of 100 expressions evaluated exactly");
    eprintln!(
        "value fuzz gam eval: {runs} runs, {compared} exact/f64 pairs, {coefficients} coefficients, 0 mismatches"
    );
}

fn vec3(rng: &mut Xorshift, r: f64) -> [f64; 3] {
    [r * rng.symmetric(), r * rng.symmetric(), r * rng.symmetric()]
}

fn length(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// `gam sample` of random Hermite specs: the motion starts and ends at the given positions
/// with the given linear and angular speeds (the end conditions), at every degree and kind;
/// `gam hermite` prints the same segment without failing.
#[test]
fn hermite_samples_meet_their_end_conditions() {
    let mut rng = Xorshift(0x4e12_3170_5eed_0002);
    let spec = TempFile::empty("fuzz-commands-hermite.json");
    let (mut runs, mut checked) = (0, 0);
    for i in 0..24 {
        let kind = if i % 2 == 0 { "additive" } else { "multiplicative" };
        let degree = 3 + rng.below(4);
        let ends: Vec<([f64; 3], [f64; 3], [f64; 3])> =
            (0..2).map(|_| (vec3(&mut rng, 5.0), vec3(&mut rng, 2.0), vec3(&mut rng, 2.0))).collect();
        let end = |(p, v, w): &([f64; 3], [f64; 3], [f64; 3]), rng: &mut Xorshift| {
            format!(
                r#"{{"position": {p:?}, "axis": {:?}, "angle": {}, "velocity": {v:?}, "angular_velocity": {w:?}}}"#,
                [rng.symmetric(), rng.symmetric(), 1.0],
                3.0 * rng.unit()
            )
        };
        let (start, stop) = (end(&ends[0], &mut rng), end(&ends[1], &mut rng));
        std::fs::write(
            spec.path(),
            format!(r#"{{"kind": "{kind}", "degree": {degree}, "start": {start}, "end": {stop}}}"#),
        )
        .unwrap();
        let (code, _) = run_capped(&["hermite", "--json", spec.path()], b"", false);
        assert_eq!(code, 0);
        let (code, out) = run_capped(&["sample", spec.path(), "--samples", "7", "--json"], b"", false);
        assert_eq!(code, 0);
        runs += 2;
        let v = json(&out);
        let samples = v["samples"].as_array().unwrap();
        for (s, (p, vel, w)) in [&samples[0], &samples[samples.len() - 1]].into_iter().zip(&ends) {
            let pos: Vec<f64> = s["position"].as_array().unwrap().iter().map(num).collect();
            for k in 0..3 {
                assert!((pos[k] - p[k]).abs() < 1e-9, "{kind} {degree}: position {pos:?} vs {p:?}");
            }
            let (lin, ang) = (num(&s["linear_speed"]), num(&s["angular_speed"]));
            assert!((lin - length(*vel)).abs() < 1e-9, "{kind} {degree}: linear speed {lin} vs {vel:?}");
            assert!((ang - length(*w)).abs() < 1e-9, "{kind} {degree}: angular speed {ang} vs {w:?}");
            checked += 1;
        }
    }
    eprintln!("value fuzz gam hermite/sample: {runs} runs, {checked} end conditions met, 0 mismatches");
}

/// Random key poses (axis, angle, position).
fn key_poses(rng: &mut Xorshift, m: usize) -> Vec<([f64; 3], f64, [f64; 3])> {
    (0..m).map(|_| ([rng.symmetric(), rng.symmetric(), 1.0], 2.5 * rng.unit(), vec3(rng, 4.0))).collect()
}

fn poses_json(keys: &[([f64; 3], f64, [f64; 3])]) -> String {
    let p: Vec<String> =
        keys.iter().map(|(a, phi, t)| format!(r#"{{"position": {t:?}, "axis": {a:?}, "angle": {phi:?}}}"#)).collect();
    format!("[{}]", p.join(", "))
}

/// `gam trajectory` through random key poses with every rational method: the first curve
/// starts at the first key pose's image of the point and the last ends at the last one's
/// (Rodrigues' formula, computed here); `gam surface` of a random curve keeps the contract.
#[test]
fn trajectories_start_and_end_at_the_key_poses() {
    let methods = ["ccm-additive", "juttler-q-motion", "juttler-minimal", "juttler-spline", "juttler-minimal-spline"];
    let mut rng = Xorshift(0x7a1e_c7e1_5eed_0003);
    let spec = TempFile::empty("fuzz-commands-trajectory.json");
    let curve = TempFile::empty("fuzz-commands-curve.json");
    let (mut runs, mut hits, mut surfaces) = (0, 0, 0);
    for round in 0..3 {
        for method in methods {
            let keys = key_poses(&mut rng, 3 + round % 2);
            std::fs::write(spec.path(), format!(r#"{{"method": "{method}", "poses": {}}}"#, poses_json(&keys)))
                .unwrap();
            let x = vec3(&mut rng, 1.0);
            let point = format!("{},{},{}", x[0], x[1], x[2]);
            let (code, out) = run_capped(&["trajectory", "--json", spec.path(), "--point", &point], b"", false);
            runs += 1;
            assert_eq!(code, 0, "{method}");
            let segs = json(&out)["segments"].as_array().unwrap().clone();
            let ends = [(&segs[0], 0usize, &keys[0]), (&segs[segs.len() - 1], usize::MAX, &keys[keys.len() - 1])];
            for (seg, j, (a, phi, t)) in ends {
                let pts = seg["points"].as_array().unwrap();
                let p = &pts[j.min(pts.len() - 1)];
                let m = rodrigues(*a, *phi, *t);
                for r in 0..3 {
                    let want = (0..3).map(|c| m[r][c] * x[c]).sum::<f64>() + m[r][3];
                    assert!((num(&p[r]) - want).abs() < 1e-9, "{method}: {p} vs row {r} = {want}");
                }
                hits += 1;
            }
            // a random body curve (now and then one weight too many: exit 2)
            let n = 1 + rng.below(3);
            let pts: Vec<String> = (0..n).map(|_| format!("{:?}", vec3(&mut rng, 1.0))).collect();
            let bad = rng.below(4) == 0;
            let weights = match (bad, rng.below(2)) {
                (true, _) => format!(r#", "weights": [{}]"#, vec!["1"; n + 1].join(", ")),
                (false, 0) => format!(r#", "weights": [{}]"#, vec!["2"; n].join(", ")),
                _ => String::new(),
            };
            std::fs::write(curve.path(), format!(r#"{{"points": [{}]{weights}}}"#, pts.join(", "))).unwrap();
            let (code, _) = run_capped(&["surface", "--json", spec.path(), "--curve", curve.path()], b"", false);
            assert_eq!(code, if bad { 2 } else { 0 }, "{method}: surface with {n} points{weights}");
            runs += 1;
            surfaces += 1;
        }
    }
    // the methods whose motions are not rational are refused (exit 2)
    for method in ["ccm-multiplicative", "wl-linear", "hexanion-linear"] {
        std::fs::write(
            spec.path(),
            format!(r#"{{"method": "{method}", "poses": {}}}"#, poses_json(&key_poses(&mut rng, 3))),
        )
        .unwrap();
        assert_eq!(run_capped(&["trajectory", spec.path(), "--point", "1,0,0"], b"", false).0, 2, "{method}");
        runs += 1;
    }
    eprintln!(
        "value fuzz gam trajectory/surface: {runs} runs, {hits} key-pose images hit, {surfaces} surfaces, 0 mismatches"
    );
}

/// `gam plot --out` of random specs, views, sample counts and flags: the SVG written is
/// complete, every speed finite and non-negative; bad arguments are one error line.
#[test]
fn plots_write_complete_svgs() {
    let mut rng = Xorshift(0x0910_7000_5eed_0004);
    let spec = TempFile::empty("fuzz-commands-plot.json");
    let svg = TempFile::empty("fuzz-commands-plot.svg");
    let methods = motion::method::Method::ALL.map(|m| m.name());
    let (mut runs, mut svgs) = (0, 0);
    for _ in 0..14 {
        let method = rng.pick(&methods);
        let m = if method == "juttler-projective" { 5 } else { 3 + rng.below(2) };
        std::fs::write(
            spec.path(),
            format!(r#"{{"method": "{method}", "poses": {}}}"#, poses_json(&key_poses(&mut rng, m))),
        )
        .unwrap();
        let view = rng.pick(&["3d", "xy", "xz", "yz", "sideways"]);
        let samples = rng.pick(&["2", "17", "40", "1"]);
        let mut args = vec!["plot", spec.path(), "--out", svg.path(), "--view", view, "--samples", samples, "--json"];
        if rng.below(3) == 0 {
            args.push("--acceleration");
        }
        let _ = std::fs::remove_file(svg.path());
        let (code, out) = run_capped(&args, b"", false);
        runs += 1;
        if code != 0 {
            continue;
        }
        let text = std::fs::read_to_string(svg.path()).expect("the SVG was written");
        assert!(text.contains("<svg") && text.trim_end().ends_with("</svg>"), "{method} {view}: a truncated SVG");
        let v = json(&out);
        for s in v["series"].as_array().unwrap() {
            for speeds in s["speeds"].as_array().into_iter().flatten() {
                for x in speeds.as_array().unwrap() {
                    assert!(num(x) >= 0.0, "{method} {view}: speed {x}");
                }
            }
        }
        svgs += 1;
    }
    assert!(svgs >= 5, "only {svgs} of 14 plots succeeded");
    // figures: every file written, each a complete SVG
    let dir = std::env::temp_dir().join(format!("gam-fuzz-figures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (code, out) = run_capped(&["figures", "--out", dir.to_str().unwrap()], b"", false);
    assert_eq!(code, 0);
    let written = out.lines().filter(|l| l.starts_with("wrote ")).count();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let text = std::fs::read_to_string(entry.unwrap().path()).unwrap();
        assert!(text.trim_end().ends_with("</svg>"));
    }
    std::fs::remove_dir_all(&dir).unwrap();
    eprintln!("value fuzz gam plot/figures: {} runs, {svgs} complete SVGs, {written} figures", runs + 1);
}

/// A random polynomial expression in `x, y, z` (and basis elements in g3).
fn polynomial(rng: &mut Xorshift, atoms: &[&str], depth: usize) -> String {
    if depth == 0 || rng.below(3) == 0 {
        return rng.pick(atoms).to_string();
    }
    let (a, b) = (polynomial(rng, atoms, depth - 1), polynomial(rng, atoms, depth - 1));
    match rng.below(3) {
        0 => format!("({a}) + ({b})"),
        1 => format!("({a}) - ({b})"),
        _ => format!("({a})*({b})"),
    }
}

/// `text` with every variable `x`, `y`, `z` replaced by its value at `point` (0 for a variable
/// the point leaves free).
fn substitute(text: &str, point: &serde_json::Map<String, Value>) -> String {
    let mut out = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        let prev_ident = out.chars().last().is_some_and(|p: char| p.is_ascii_alphanumeric());
        let next_ident = chars.peek().is_some_and(char::is_ascii_alphanumeric);
        if !prev_ident && !next_ident && "xyz".contains(c) {
            let v = point.get(&c.to_string()).map_or_else(
                || "0".to_string(),
                |v| v.as_i64().map_or_else(|| v.as_str().unwrap().to_string(), |n| n.to_string()),
            );
            out.push_str(&format!("({v})"));
        } else {
            out.push(c);
        }
    }
    out
}

/// `gam prove` of random claims `A = B` without hypotheses: it says "holds" exactly when
/// `gam eval --scalar poly "(A) - (B)"` is 0 (an expansion, a second algorithm), and every
/// witness it gives is a counterexample: `A - B` at the witness point (by `gam eval --scalar
/// rational`, the variables replaced by their values) is non-zero in its component.
#[test]
fn prove_verdicts_match_the_expansion_and_witnesses_refute() {
    let mut rng = Xorshift(0x9107_e000_5eed_0005);
    let atoms = ["x", "y", "z", "1", "2", "-1", "e1", "e2", "e12"];
    let (mut runs, mut held, mut refuted) = (0, 0, 0);
    for i in 0..30 {
        let a = polynomial(&mut rng, &atoms, 3);
        // a claim that holds now and then: B the expansion of A (printed by gam eval)
        let b = if i % 3 == 0 {
            let (code, out) = run_capped(&["eval", "--algebra", "g3", "--scalar", "poly", "--", &a], b"", false);
            assert_eq!(code, 0);
            runs += 1;
            out.trim().to_string()
        } else {
            polynomial(&mut rng, &atoms, 3)
        };
        let claim = format!("{a} = {b}");
        let (code, out) = run_capped(&["prove", "--algebra", "g3", "--json", "--", &claim], b"", true);
        let diff = format!("({a}) - ({b})");
        let (c2, expanded) = run_capped(&["eval", "--algebra", "g3", "--scalar", "poly", "--", &diff], b"", false);
        runs += 2;
        assert_eq!(c2, 0);
        let v = json(&out);
        assert_ne!(v["undecided"], true, "{claim}: undecided");
        let holds = expanded.trim() == "0";
        assert_eq!(v["holds"].as_bool(), Some(holds), "{claim}: prove {v} vs expansion {expanded}");
        assert_eq!(code, if holds { 0 } else { 1 }, "{claim}");
        if holds {
            held += 1;
            continue;
        }
        let w = &v["witness"];
        let point = w["point"].as_object().unwrap();
        let at = substitute(&diff, point);
        let (c3, value) =
            run_capped(&["eval", "--algebra", "g3", "--scalar", "rational", "--json", "--", &at], b"", false);
        runs += 1;
        assert_eq!(c3, 0, "{at}");
        let component = w["component"].as_str().unwrap();
        let value = json(&value);
        let c =
            value.get(component).map_or(Q::from_integer(0.into()), |x| parse_rational(x.as_str().unwrap()).unwrap());
        assert_ne!(c, Q::from_integer(0.into()), "{claim}: the witness {point:?} gives 0 in {component} ({value})");
        refuted += 1;
    }
    assert!(held >= 5 && refuted >= 5, "{held} held, {refuted} refuted");
    eprintln!(
        "value fuzz gam prove: {runs} runs, {held} claims held, {refuted} refuted by a checked witness, 0 mismatches"
    );
}

/// `gam codegen` with random options (good and bad): the contract, and the Rust module of
/// every good run parses (`syn`); `--emit stats --json` is rows of non-negative counts.
/// `gam table`, `gam algebras` and `gam verify` with random arguments keep the contract.
#[test]
fn codegen_options_and_the_small_commands() {
    let mut rng = Xorshift(0xc0de_9e00_5eed_0006);
    let toml = TempFile::new(
        "fuzz-commands.toml",
        "generators = [\"a\", \"b\", \"fn\"]\nmetric = { \"a,a\" = 1, \"b,b\" = -1, \"fn,fn\" = 0 }\n",
    );
    // every other run takes only valid values (and must succeed), the rest any value
    let good: [(&str, &[&str]); 9] = [
        ("--algebra", &["g3", "pga3", "cga", toml.path()]),
        ("--types", &["V=grade1", "V=grade 1;Even=even", "Motor=even where unit", "V=grade1;R=grades 0,2"]),
        ("--emit", &["rust", "stats"]),
        ("--lang", &["rust", "rust", "c", "wgsl", "glsl"]),
        ("--basis", &["blade", "product"]),
        ("--fallback", &["parity", "full"]),
        ("--table-above", &["0", "8", "1000"]),
        ("--module", &["m", "my_mod"]),
        ("--ops", &["gp", "gp,op", "reverse"]),
    ];
    let bad: [&[&str]; 9] = [
        &["nope", "g2"],
        &["Self=grade1", "V=grade9", "V=", "=grade1", "V=grade1 where wobbly", "P=1,e12"],
        &["words"],
        &["cobol"],
        &["neither"],
        &["half"],
        &["-1", "x"],
        &["type", "9x"],
        &["nope"],
    ];
    let (mut runs, mut parsed, mut stats) = (0, 0, 0);
    for i in 0..50 {
        let valid = i % 2 == 0;
        let mut args = vec!["codegen"];
        for (k, (flag, values)) in good.iter().enumerate() {
            // --algebra, --types, --emit, --lang always; the rest now and then
            if k < 4 || rng.below(3) == 0 {
                let value = if valid || rng.below(4) != 0 { rng.pick(values) } else { rng.pick(bad[k]) };
                args.extend([*flag, value]);
            }
        }
        for flag in ["--every-type", "--standalone", "--json"] {
            if rng.below(3) == 0 {
                args.push(flag);
            }
        }
        let (code, out) = run_capped(&args, b"", false);
        runs += 1;
        let (emit, lang) = (args[6], args[8]);
        // (--ops, --every-type and --standalone combine only in some ways: contract only)
        let plain = !["--ops", "--every-type", "--standalone"].iter().any(|f| args.contains(f));
        if valid && plain && !(emit == "stats" && lang != "rust") {
            assert_eq!(code, 0, "{args:?}");
        }
        if code != 0 {
            continue;
        }
        let json_out = args.contains(&"--json");
        if emit == "stats" {
            if json_out {
                for row in json(&out).as_array().unwrap() {
                    assert!(row["mul"].as_u64().is_some() && row["add"].as_u64().is_some(), "{args:?}: {row}");
                }
            }
            stats += 1;
        } else if lang == "rust" {
            let source = if json_out { json(&out)["source"].as_str().unwrap().to_string() } else { out };
            syn::parse_file(&source).unwrap_or_else(|e| panic!("{args:?}: the module does not parse: {e}"));
            parsed += 1;
        }
    }
    assert!(parsed >= 3 && stats >= 3, "{parsed} modules parsed, {stats} stats");
    for args in [
        &["table", "--algebra", "g3", "--product", "lc"][..],
        &["table", "--algebra", toml.path(), "--json"],
        &["table", "--algebra", "pga3", "--basis", "product"],
        &["table", "--product", "sideways"],
        &["algebras"],
        &["algebras", "--json", "cga", "g3"],
        &["algebras", "nope"],
        &["verify", "--filter", "lemma 2.1"],
        &["verify", "--filter", "no statement has this in its name"],
    ] {
        run_capped(args, b"", true);
        runs += 1;
    }
    eprintln!("fuzz gam codegen/table/algebras/verify: {runs} runs, {parsed} modules parsed, {stats} stats tables");
}
