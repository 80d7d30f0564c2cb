//! `gam codegen`: the emitted module is pinned by a snapshot (which the gam-algebras tests
//! compile and check against the runtime), the stats are the documented counts, and bad type
//! lists are usage errors.

use crate::common;

use common::gam;

#[test]
fn emitted_module_matches_the_snapshot() {
    let out = gam(&["codegen", "--algebra", "g3", "--types", "Vector=grade1;Rotor=even", "--module", "g3_vendored"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let expected = include_str!("../../algebras/tests/vendored/g3_vendored.rs");
    let got = String::from_utf8(out.stdout).unwrap();
    // println! adds one newline after the source
    assert_eq!(got.trim_end(), expected.trim_end(), "regenerate the snapshot with the command in its header");
}

#[test]
fn motor_product_is_48_multiplications_and_40_additions() {
    let out = gam(&[
        "codegen",
        "--algebra",
        "g123inf",
        "--types",
        "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1",
        "--emit",
        "stats",
        "--json",
    ]);
    assert!(out.status.success());
    let stats: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let gp = stats
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["op"] == "gp" && s["lhs"] == "Motor" && s["rhs"] == "Motor")
        .unwrap();
    assert_eq!(gp, &serde_json::json!({"op":"gp","lhs":"Motor","rhs":"Motor","out":"Motor","mul":48,"add":40}));
    // Vector * Vector in g123inf: 4 x 4 pairs minus einf*einf = 15 products, into the Motor type
    let vv = stats.as_array().unwrap().iter().find(|s| s["op"] == "gp" && s["lhs"] == "Vector" && s["rhs"] == "Vector");
    assert_eq!(vv.unwrap()["mul"], 15);
    assert_eq!(vv.unwrap()["out"], "Motor");
}

#[test]
fn bad_type_lists_are_usage_errors() {
    for types in ["Motor", "Motor=e9", "motor=even", "A=grade 9", "A=even;A=odd", "A=e1,e1"] {
        let out = gam(&["codegen", "--algebra", "g3", "--types", types]);
        assert_eq!(out.status.code(), Some(2), "{types}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.starts_with("error: "), "{err}");
        assert!(out.stdout.is_empty());
    }
}

#[test]
fn standalone_file_matches_the_vendored_example() {
    // examples/vendored builds this file as its own crate with no dependencies (cargo test
    // --workspace compiles and tests it); here it is regenerated and compared byte for byte.
    let out = gam(&["codegen", "--standalone", "--algebra", "g3", "--types", "Vector=grade1;Rotor=even"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let expected = include_str!("../../examples/vendored/src/kernels.rs");
    let got = String::from_utf8(out.stdout).unwrap();
    assert_eq!(got.trim_end(), expected.trim_end(), "regenerate with the command in the file's header");
    let header: Vec<&str> = got.lines().take(4).collect();
    assert!(header[3].contains("regenerate with `cargo run --release -p gam -- codegen --standalone"), "{header:?}");
    assert!(!got.contains("algebra_core") && !got.contains("pub mod "), "no dependency, no nesting");
}

#[test]
fn standalone_nests_only_when_asked() {
    let out = gam(&["codegen", "--standalone", "--algebra", "g3", "--types", "Vector=grade1", "--module", "g3k"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let got = String::from_utf8(out.stdout).unwrap();
    assert_eq!(got.matches("pub mod ").count(), 1, "one wrapper module");
    assert!(got.contains("pub mod g3k {"));
}

#[test]
fn constrained_unit_motor_on_a_point_is_a_point_with_fewer_multiplications() {
    let types = "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1";
    let args =
        ["codegen", "--basis", "product", "--types", types, "--emit", "stats", "--json", "--constrain", "Motor=unit"];
    let out = gam(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let row = rows
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["constraints"].is_array() && r["lhs"] == "Motor" && r["rhs"] == "Vector")
        .expect("a constrained row");
    // the output type is proven (the unconstrained expansion has a σ part, so it lands in the
    // automatic odd fallback type)
    assert_eq!((row["out"].as_str(), row["unconstrained"]["out"].as_str()), (Some("Vector"), Some("Odd")));
    assert_eq!((row["mul"].as_u64(), row["unconstrained"]["mul"].as_u64()), (Some(57), Some(65)));
    assert_eq!((row["terms"].as_u64(), row["unconstrained"]["terms"].as_u64()), (Some(51), Some(68)));
    // bad constraints are usage errors with one error line
    for bad in [["--constrain", "Motor=blah"], ["--constrain", "Nope=unit"]] {
        let out = gam(&["codegen", "--types", types, "--emit", "stats", bad[0], bad[1]]);
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("error: --constrain") && err.lines().count() == 1, "{err}");
    }
}

#[test]
fn fallback_full_turns_the_parity_types_off() {
    let out_of = |extra: &[&str]| {
        let mut args = vec!["codegen", "--algebra", "pga3", "--types", "Plane=grade1;Point=grade3", "--emit", "stats"];
        args.extend_from_slice(extra);
        args.push("--json");
        let out = gam(&args);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let rows: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let row =
            rows.as_array().unwrap().iter().find(|s| s["op"] == "gp" && s["lhs"] == "Plane" && s["rhs"] == "Point");
        row.unwrap()["out"].as_str().unwrap().to_string()
    };
    assert_eq!(out_of(&[]), "Even");
    assert_eq!(out_of(&["--fallback", "parity"]), "Even");
    assert_eq!(out_of(&["--fallback", "full"]), "Multivector");
    // the regeneration command in the header keeps the switch
    let out = gam(&["codegen", "--algebra", "pga3", "--types", "Point=grade3", "--fallback", "full"]);
    let source = String::from_utf8(out.stdout).unwrap();
    assert!(source.contains("--fallback full") && !source.contains("pub struct Even"));
    let bad = gam(&["codegen", "--algebra", "pga3", "--types", "Point=grade3", "--fallback", "odd"]);
    assert!(!bad.status.success());
}

/// `--table-above N` is the DSL's `table_above N;`: the 48-term g123inf motor product is
/// straight-line code under the default and a table loop when the threshold is below 48; the
/// header's regeneration command keeps the option; a bad value is a usage error.
/// The number of bytes of the byte-string literal `text` starts with (after its `b"`), as Rust
/// escapes it (`\x01`, `\0`, `\n`, `\"`, printable ASCII).
fn byte_string_len(text: &str) -> usize {
    let mut n = 0;
    let mut chars = text.chars();
    while let Some(c) = chars.next() {
        match c {
            '"' => return n,
            '\\' if chars.next() == Some('x') => {
                chars.nth(1);
            }
            _ => {}
        }
        n += 1;
    }
    panic!("an unterminated byte string: {text}")
}

#[test]
fn table_above_sets_the_size_policy() {
    let motor_product = |extra: &[&str]| {
        let mut args = vec!["codegen", "--algebra", "g123inf", "--types", "Motor=even"];
        args.extend_from_slice(extra);
        let out = gam(&args);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let source = String::from_utf8(out.stdout).unwrap();
        let start = source.find("::algebra_core::ops::GeometricProduct<Motor<T>>\n    for Motor<T> {").unwrap();
        let end = start + 1 + source[start + 1..].find("    impl<").unwrap();
        (source[..source.find("pub use").unwrap()].to_string(), source[start..end].to_string())
    };
    let (_, default) = motor_product(&[]);
    assert!(!default.contains("bilinear"), "{default}");
    let (_, at_48) = motor_product(&["--table-above", "48"]);
    assert_eq!(at_48, default);
    let (header, at_47) = motor_product(&["--table-above", "47"]);
    // the 48 terms as one packed table: three two-byte numbers per term
    assert!(at_47.contains("kernels::bilinear::<") && at_47.contains("8usize,"), "{at_47}");
    let table = &at_47[at_47.find("b\"").unwrap() + 2..];
    assert_eq!(byte_string_len(table), 48 * 6, "{at_47}");
    assert!(header.contains("--table-above 47"), "{header}");
    for bad in ["many", "-1", "1.5"] {
        let out = gam(&["codegen", "--algebra", "g3", "--types", "Vector=grade1", "--table-above", bad]);
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(err.starts_with("error: ") && err.lines().count() == 1, "{err}");
    }
}

/// `where unit` in --types declares the constraint in the module: `--emit stats` shows the
/// constrained kernels with what they save (the same as `--constrain`), `--emit rust` uses
/// them in the unit actions; an unknown constraint is a usage error.
#[test]
fn declared_constraints_in_types_show_savings_and_emit_methods() {
    let types = "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf where unit;Vector=grade1;Multivector=all";
    let out =
        gam(&["codegen", "--algebra", "cga-null", "--basis", "product", "--types", types, "--emit", "stats", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let find = |op: &str| {
        rows.as_array()
            .unwrap()
            .iter()
            .find(|r| r["constraints"].is_array() && r["op"] == op && r["rhs"] == "Vector")
            .cloned()
            .expect("a constrained row")
    };
    for op in ["sandwich", "apply"] {
        let row = find(op);
        assert_eq!(row["out"], "Vector");
        assert_eq!(row["saved"], serde_json::json!({"mul": 8, "terms": 17}), "{row}");
    }
    let text = gam(&["codegen", "--algebra", "cga-null", "--basis", "product", "--types", types, "--emit", "stats"]);
    let text = String::from_utf8(text.stdout).unwrap();
    assert!(text.contains("sandwich [Motor: rev(x) x = 1] saves 8 mul, 17 terms"), "{text}");
    let rust = gam(&["codegen", "--algebra", "cga-null", "--basis", "product", "--types", types]);
    assert!(rust.status.success());
    let rust = String::from_utf8(rust.stdout).unwrap();
    // one unit-action family: the `UnitAction` impl of the pair, the cheaper kernel (the
    // commutator form, 36 against the reduced 57), and the proof in its rustdoc
    let unit = rust.split("UnitAction<Vector<T>>\n    for Motor<T>").nth(1).expect("the pair's UnitAction impl");
    let unit = unit.split("impl<").next().unwrap();
    assert!(unit.contains("fn sandwich_unit(&self, x: &Vector<T>) -> Vector<T>"), "{unit}");
    assert!(unit.contains("36 multiplications (reduced modulo `rev(x) x = 1`: 57"), "{unit}");
    assert!(unit.contains("Proven (ideal membership): on a unit `Motor` the action on a `Vector` is a `Vector`"));
    assert!(!rust.contains("sandwich_unit_vector"));
    // the general fused action says what it drops (the σ part of a non-unit motor)
    let general = rust
        .split("Sandwich<Vector<T>> for Motor<T>")
        .nth(1)
        .expect("the fused sandwich")
        .split("impl<")
        .next()
        .unwrap();
    assert!(general.contains("component(s) outside `Vector`, dropped here"), "{general}");
    let bad = gam(&["codegen", "--algebra", "cga-null", "--types", "Motor=even where round"]);
    assert_eq!(bad.status.code(), Some(2));
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(
        err.starts_with("error: ") && err.contains("unknown constraint `round`") && err.lines().count() == 1,
        "{err}"
    );
}

/// `--lang c|wgsl|glsl`: the library's emitter, headed by the regeneration command; `--ops`
/// and `--every-type` select kernels; misuse is a usage error.
#[test]
fn other_languages_are_the_library_emitters_with_the_regeneration_command() {
    let types = "Motor=even;Point=grade3;Line=grade2";
    let out =
        gam(&["codegen", "--lang", "c", "--algebra", "pga3", "--module", "pga", "--types", types, "--ops", "gp,exp"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let c = String::from_utf8(out.stdout).unwrap();
    assert!(c.starts_with(&format!(
        "/* @generated by gam codegen --lang c --algebra pga3 --basis blade --module pga --ops gp,exp --types \"{types}\" */"
    )));
    // the library's text, after the header lines
    let alg = algebra_core::Algebra::builtin("pga3").unwrap();
    let spec = algebra_codegen::ModuleSpec::new(
        "pga",
        alg.metric().clone(),
        algebra_core::Basis::Blade,
        algebra_codegen::ModuleSpec::parse_types(types, &alg).unwrap(),
    )
    .unwrap();
    let plan = algebra_codegen::plan::Plan::new(spec).unwrap();
    let options = algebra_codegen::lang::Options {
        ops: Some(["gp".to_string(), "exp".to_string()].into()),
        ..Default::default()
    };
    let lib = algebra_codegen::lang::emit(&plan, algebra_codegen::lang::Lang::C, &options).unwrap();
    assert!(c.trim_end().ends_with(lib.trim_end()), "the CLI prints the library's header");
    assert!(c.contains("static inline pga_Motor pga_line_exp(pga_Line x)"));
    assert!(!c.contains("apply_unit") && !c.contains("pga_multivector_gp"));
    // JSON, WGSL, every type
    let out = gam(&["codegen", "--lang", "wgsl", "--algebra", "pga3", "--types", types, "--every-type", "--json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!((v["module"].as_str(), v["lang"].as_str()), (Some("pga3"), Some("wgsl")));
    assert!(v["source"].as_str().unwrap().contains("fn pga3_multivector_gp_multivector("));
    // misuse: exit 2, one error line
    for bad in [
        vec!["--lang", "c", "--ops", "gp,frobnicate"],
        vec!["--lang", "glsl", "--standalone"],
        vec!["--ops", "gp"],
        vec!["--lang", "c", "--emit", "stats", "--every-type"],
        vec!["--lang", "fortran"],
    ] {
        let mut args = vec!["codegen", "--algebra", "pga3", "--types", types];
        args.extend(bad.iter().copied());
        let out = gam(&args);
        assert_eq!(out.status.code(), Some(2), "{bad:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("error:") && err.lines().count() == 1, "{bad:?}: {err}");
    }
}

/// `--standalone --ops ...` and `--every-type`: the selected kernels only, and every selection
/// compiles on its own without warnings (rustc, no dependency).
#[test]
fn standalone_selections_compile_on_their_own() {
    let types = "Motor=even;Point=grade3;Line=grade2;Plane=grade1";
    let dir = std::env::temp_dir().join(format!("gam-standalone-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut lines = Vec::new();
    for (n, extra) in [
        vec![],
        vec!["--ops", "gp,op,regressive,apply_unit"],
        vec!["--ops", "gp", "--every-type"],
        vec!["--ops", "gp,sandwich,apply,sandwich_unit,apply_unit"],
    ]
    .iter()
    .enumerate()
    {
        let mut args = vec!["codegen", "--standalone", "--algebra", "pga3", "--types", types];
        args.extend(extra.iter().copied());
        let out = gam(&args);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let text = String::from_utf8(out.stdout).unwrap();
        // an impl of `kernel` (e.g. `GeometricProduct<Line<T>> for Motor<T>`)
        let has = |kernel: &str| text.contains(&format!("> self::{kernel}"));
        let any = |t: &str| text.contains(&format!("> self::{t}<"));
        match n {
            0 => {
                // the default: gp, and apply/apply_unit of the motor on the declared types
                assert!(has("UnitAction<Point<T>> for Motor<T>") && has("GeometricProduct<Line<T>> for Motor<T>"));
                assert!(has("Apply<Line<T>> for Motor<T>") && !any("Sandwich") && !text.contains("fn sandwich_unit"));
                assert!(!has("Apply<Point<T>> for Plane<T>") && !has("UnitAction<Point<T>> for Line<T>"));
                assert!(!any("OuterProduct") && !any("ActionMatrix") && !text.contains("struct Multivector"));
            }
            1 => {
                assert!(has("OuterProduct<Plane<T>> for Plane<T>") && has("RegressiveProduct<Point<T>> for Point<T>"));
                assert!(!has("Apply<Point<T>> for Motor<T>") && !any("LeftContraction"));
                assert!(text.lines().nth(1).unwrap().contains("--ops gp,op,regressive,apply_unit"));
            }
            2 => assert!(has("GeometricProduct<Multivector<T>> for Multivector<T>") && !any("UnitAction")),
            _ => {
                // the earlier default: both conventions, of every versor type (a plane's
                // reflection, a line's half-turn), and both unit methods
                assert!(has("Sandwich<Point<T>> for Plane<T>") && has("Apply<Motor<T>> for Line<T>"));
                assert!(
                    has("UnitAction<Point<T>> for Point<T>") && text.contains("fn sandwich_unit(&self, x: &Line<T>)")
                );
            }
        }
        let file = dir.join(format!("k{n}.rs"));
        std::fs::write(&file, &text).unwrap();
        let rustc = std::process::Command::new("rustc")
            .args(["--edition", "2024", "--crate-type", "lib", "-D", "warnings", "--out-dir"])
            .arg(&dir)
            .arg(&file)
            .output()
            .expect("rustc runs");
        assert!(rustc.status.success(), "selection {n}: {}", String::from_utf8_lossy(&rustc.stderr));
        lines.push(text.lines().count());
    }
    // the default is a fraction of every kernel of every type
    assert!(lines[0] * 2 < lines[2] + lines[0], "{lines:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The closed forms in a standalone file (Real and algebra-core's factors inlined): a program
/// using only the file turns a point by exp of a line and reads the angle back with log, against
/// the rotation by hand (cos, sin of a quarter turn and a general angle).
#[test]
fn standalone_closed_forms_run_without_dependencies() {
    let out = gam(&[
        "codegen",
        "--standalone",
        "--algebra",
        "pga3",
        "--types",
        "Motor=even;Point=e032,e013,e021,e123;Line=grade2",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let dir = std::env::temp_dir().join(format!("gam-standalone-closed-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("kernels.rs"), &out.stdout).unwrap();
    let main = r#"
mod kernels;
use kernels::{Line, Point};
fn main() {
    for angle in [std::f64::consts::FRAC_PI_2, 0.7, 1e-9] {
        // exp(-angle/2 e12) turns by `angle` about z in the apply convention
        let mut b = Line::<f64>::zero();
        b.e12 = -angle / 2.0;
        let m = b.exp();
        let p = Point::new(1.0, 2.0, 0.5, 1.0); // (x, y, z) = (1, 2, 0.5)
        let q = m.apply_unit(&p);
        let back = m.log().unwrap();
        println!("{:e} {:e} {:e} {:e} {:e}", q.e032, q.e013, q.e021, q.e123, back.e12);
    }
    println!("{}", kernels::Motor::<f64>::zero().normalize().unwrap_err());
}
"#;
    let text = compile_and_run(&dir, main, &["-O"]);
    let mut lines = text.lines();
    for angle in [std::f64::consts::FRAC_PI_2, 0.7, 1e-9] {
        let v: Vec<f64> = lines.next().unwrap().split_whitespace().map(|x| x.parse().unwrap()).collect();
        let (c, s) = (angle.cos(), angle.sin());
        let want = [c - 2.0 * s, s + 2.0 * c, 0.5, 1.0, -angle / 2.0];
        for (g, w) in v.iter().zip(want) {
            assert!((g - w).abs() <= 1e-15 * (1.0 + w.abs()), "angle {angle}: {v:?} vs {want:?}");
        }
    }
    assert!(lines.next().unwrap().contains("normalize is not defined"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The default standalone file for 3D PGA with `Motor`, `Point`, `Line`, `Plane` (issue 26 item
/// 4): at most 3,000 lines, compiles with rustc alone under `-D warnings`, and its `apply` and
/// `apply_unit` of a motor (a rotation about a general axis, then a translation) on points agree
/// with the 4x4 matrix `[[R, t], [0, 1]]` to 1e-12. The program also touches the value
/// semantics `value_type!` writes (constructors, arrays, indexing, iteration, operators by value
/// and by reference, compound assignment, `s * x`, `Display`, `Debug`) and the closed forms.
#[test]
fn standalone_pga3_default_is_lean_and_moves_points_like_a_matrix() {
    let types = "Motor=even;Point=grade3;Line=grade2;Plane=grade1";
    let out = gam(&["codegen", "--standalone", "--algebra", "pga3", "--types", types]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    let lines = text.lines().count();
    assert!(lines <= 3000, "{lines} lines");
    // one convention, of the motor only; the value semantics written once
    assert!(!text.contains("> self::Sandwich<") && !text.contains("fn sandwich_unit"));
    assert!(
        text.contains("> self::Apply<Point<T>> for Motor<T>") && !text.contains("> self::Apply<Point<T>> for Line<T>")
    );
    assert_eq!(text.matches("macro_rules! value_type").count(), 1);
    assert_eq!(text.matches("impl<T: self::Ring> ::core::ops::Neg for").count(), 0, "no per-type copies");
    let dir = std::env::temp_dir().join(format!("gam-standalone-lean-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("kernels.rs"), &text).unwrap();
    let main = r#"
mod kernels;
use kernels::{Line, Motor, Plane, Point};

/// (x, y, z) as a point of this file: x = -e023, y = e013, z = -e012, weight e123.
fn point(x: f64, y: f64, z: f64) -> Point<f64> {
    Point::new(-z, y, -x, 1.0)
}

fn main() {
    // R = exp(-θ/2 (nx e23 + ny e31 + nz e12)) turns by θ about the unit axis n; T = 1 - t e0/2
    // moves by t; M = T R turns, then moves (M x rev(M)).
    let (theta, n, t) = (0.9_f64, [2.0_f64, -1.0, 2.0].map(|c| c / 3.0), [0.5_f64, -1.25, 2.0]);
    let (s, c) = (theta / 2.0).sin_cos();
    let r = Motor::new(c, 0.0, 0.0, -s * n[2], 0.0, s * n[1], -s * n[0], 0.0);
    let tr = Motor::new(1.0, -t[0] / 2.0, -t[1] / 2.0, 0.0, -t[2] / 2.0, 0.0, 0.0, 0.0);
    let m = &tr * &r;
    for p in [[1.0, 2.0, 0.5], [0.0, 0.0, 0.0], [-3.0, 0.25, 7.0]] {
        let (a, b) = (m.apply(&point(p[0], p[1], p[2])), m.apply_unit(&point(p[0], p[1], p[2])));
        for q in [a, b] {
            println!("{:e} {:e} {:e} {:e}", -q.e023, q.e013, -q.e012, q.e123);
        }
    }
    // the same motor through exp of a line (the closed form) and back through log
    let back = m.log().unwrap().exp();
    println!("{:e}", (back - m).iter().map(|x| x.abs()).fold(0.0, f64::max));

    // value semantics (value_type!, scalar_times!, product_operators!)
    let mut l = Line::<f64>::from_array([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(Line::<f64>::LEN, 6);
    assert_eq!(Line::<f64>::ELEMENTS[3], "e03");
    assert_eq!((l[2], l.e12), (3.0, 3.0));
    l[2] = -3.0;
    *l.iter_mut().next().unwrap() += 1.0;
    assert_eq!(l.to_array(), [2.0, 2.0, -3.0, 4.0, 5.0, 6.0]);
    let arr: [f64; 6] = l.into();
    assert_eq!(Line::from(arr), l);
    assert_eq!(l.iter().sum::<f64>(), (&l).into_iter().sum::<f64>());
    assert_eq!(l.into_iter().count(), 6);
    let mut q = Plane::<f64>::e1() * 2.0 + Plane::e2() - Plane::e3() / 4.0;
    q += Plane::e0();
    q -= Plane::e2();
    q *= 2.0;
    q /= 4.0;
    assert_eq!(q, Plane::new(0.5, 1.0, 0.0, -0.125));
    assert_eq!(format!("{q}"), "0.5*e0 + e1 - 0.125*e3");
    assert_eq!(format!("{:?}", -&q), "Plane(-0.5*e0 - e1 + 0.125*e3)");
    assert_eq!(2.0 * &q, &q + &q);
    assert_eq!(&q - &q, Plane::zero());
    assert_eq!(2.0_f32 * Plane::<f32>::e1(), Plane::<f32>::e1() * 2.0_f32);
    assert_eq!(Motor::<f64>::default(), Motor::zero());
    assert_eq!(Motor::<f64>::one() * Motor::one(), Motor::one());
    assert_eq!((&m * m.reverse()).scalar.round(), 1.0);
    assert!((m.inverse().unwrap() - m.reverse()).iter().all(|x| x.abs() < 1e-12));
    assert!(std::panic::catch_unwind(|| Point::<f64>::zero()[4]).is_err());
    println!("ok");
}
"#;
    let text = compile_and_run(&dir, main, &[]);
    let mut rows = text.lines();
    // by hand: the rotation matrix of θ about n (Rodrigues), then + t
    let (theta, n, t) = (0.9_f64, [2.0_f64, -1.0, 2.0].map(|c| c / 3.0), [0.5_f64, -1.25, 2.0]);
    let (s, c) = theta.sin_cos();
    let k = 1.0 - c;
    let rot = [
        [c + n[0] * n[0] * k, n[0] * n[1] * k - n[2] * s, n[0] * n[2] * k + n[1] * s],
        [n[1] * n[0] * k + n[2] * s, c + n[1] * n[1] * k, n[1] * n[2] * k - n[0] * s],
        [n[2] * n[0] * k - n[1] * s, n[2] * n[1] * k + n[0] * s, c + n[2] * n[2] * k],
    ];
    let matrix = [
        [rot[0][0], rot[0][1], rot[0][2], t[0]],
        [rot[1][0], rot[1][1], rot[1][2], t[1]],
        [rot[2][0], rot[2][1], rot[2][2], t[2]],
        [0.0, 0.0, 0.0, 1.0],
    ];
    for p in [[1.0, 2.0, 0.5], [0.0, 0.0, 0.0], [-3.0, 0.25, 7.0]] {
        let h = [p[0], p[1], p[2], 1.0];
        let want: Vec<f64> = matrix.iter().map(|row| row.iter().zip(&h).map(|(a, b)| a * b).sum()).collect();
        for method in ["apply", "apply_unit"] {
            let got: Vec<f64> = rows.next().unwrap().split_whitespace().map(|x| x.parse().unwrap()).collect();
            for (g, w) in got.iter().zip(&want) {
                assert!((g - w).abs() <= 1e-12, "{method} of {p:?}: {got:?} vs {want:?}");
            }
        }
    }
    let roundtrip: f64 = rows.next().unwrap().parse().unwrap();
    assert!(roundtrip <= 1e-12, "exp(log(m)) - m: {roundtrip}");
    assert_eq!(rows.next(), Some("ok"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Writes `main` as `dir/main.rs`, compiles it with rustc alone (`-D warnings`, plus `flags`),
/// runs it and returns its standard output; fails the test if either step fails.
fn compile_and_run(dir: &std::path::Path, main: &str, flags: &[&str]) -> String {
    std::fs::write(dir.join("main.rs"), main).unwrap();
    let rustc = std::process::Command::new("rustc")
        .args(["--edition", "2024", "-D", "warnings"])
        .args(flags)
        .arg("-o")
        .arg(dir.join("run"))
        .arg(dir.join("main.rs"))
        .output()
        .expect("rustc runs");
    assert!(rustc.status.success(), "{}", String::from_utf8_lossy(&rustc.stderr));
    let run = std::process::Command::new(dir.join("run")).output().expect("the program runs");
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    String::from_utf8(run.stdout).unwrap()
}
