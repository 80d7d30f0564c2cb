//! The C header against the Rust kernels of the same declaration: every kernel of the header
//! (products of every pair of types, unary maps, norms, fused and unit-versor actions), in
//! `double` (and `float` for 3D PGA; the other `float` kernels run on the GPU in
//! `lang-tests/gpu`), compiled by the system C compiler (C99, `-O1` for 3D PGA and `-O0` for the
//! others, no contraction of multiply-adds) and run on random inputs, equals the Rust kernel
//! bit for bit: the emitters print the same operations in the same order
//! ([`algebra_codegen::lang::ir`]). The closed forms are within 8 ulp (libm's functions).

use algebra_codegen::lang::{Lang, Options, emit, kernels};
use algebra_codegen::plan::Plan;
use algebra_core::Basis;
use gam_lang_tests::{Numbers, Registry, arguments, c_driver, compile_and_run, is_closed, plan, registry};

algebra_macros::algebra! {
    /// 3D PGA, canonical names.
    pub mod pga {
        metric builtin "pga3";
        types { Motor = even; Point = grade 3; Line = grade 2; Plane = grade 1; }
    }
}

algebra_macros::algebra! {
    /// 3D PGA in ganja's orientation (renamed blades: the signs folded into the constants).
    pub mod ganja {
        metric builtin "pga3";
        types {
            Plane = grade 1;
            Line = [e01, e02, e03, e12, e31, e23];
            Point = [e021, e013, e032, e123];
            Motor = [1, e01, e02, e03, e12, e31, e23, e0123];
        }
    }
}

algebra_macros::algebra! {
    /// Dual quaternions in the conformal subalgebra.
    pub mod g123inf {
        metric builtin "g123inf";
        types { Motor = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf]; Vector = grade 1; Bivector = grade 2; }
    }
}

algebra_macros::algebra! {
    /// Euclidean rotors (the trigonometric closed forms without a dual part).
    pub mod g3 {
        metric builtin "g3";
        types { Rotor = even; Vector = grade 1; Bivector = grade 2; }
    }
}

algebra_macros::algebra! {
    /// The main paper's conformal algebra in the product basis (the full 32-element multivector
    /// has table-driven products).
    pub mod cga_null {
        metric builtin "cga-null";
        basis product;
        types { Motor = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf]; Vector = grade 1; }
    }
}

algebra_macros::algebra! {
    /// The conformal model as GATL declares it (blade basis, `eo · einf = -1`): its point
    /// actions take the scalar-norm form, though the motor's norm is not a scalar
    /// (`algebra_codegen::versor::norm_acts_as_scalar`).
    pub mod gatl {
        generators { e1, e2, e3, eo, einf }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1, (eo, einf) = -1 }
        types { Vector = grade 1; Motor = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf]; }
    }
}

const SAMPLES: usize = 3;

/// Runs every kernel of the plan's C header in `double` (or `float`) and compares with the
/// registry; returns the number of kernels compared.
#[allow(clippy::too_many_arguments)]
fn check<S: Copy + PartialEq + Into<f64> + std::fmt::Debug + 'static>(
    plan: &Plan,
    reg: &Registry<S>,
    float: bool,
    from_f64: impl Fn(f64) -> S,
    bits: impl Fn(S) -> String,
    parse: impl Fn(&str) -> S,
    close: impl Fn(&[S], &[S]) -> bool,
) -> usize {
    // the registry declares the plan's types, fields in the same order
    for t in &plan.spec.types {
        let fields = t.element_names(&plan.spec.algebra);
        assert_eq!(reg.elements.get(&t.name), Some(&fields), "type {} of the Rust module", t.name);
    }
    let ks = kernels(plan).unwrap();
    let header = emit(plan, Lang::C, &Options { every_type: true, ..Options::default() }).unwrap();
    let driver = c_driver(plan, &ks, "gam.h", SAMPLES, float);
    let mut numbers = Numbers::new(0x5eed);
    let mut input = String::new();
    let mut expected = Vec::new();
    for k in &ks {
        let rust =
            reg.get(plan, k).unwrap_or_else(|| panic!("no Rust kernel registered for {} {:?}", k.op.name(), k.params));
        for sample in 0..SAMPLES {
            // the first sample of a closed form takes the series branch
            let args = arguments(plan, reg, k, &mut numbers, sample == 0, &from_f64);
            for a in args.iter().flatten() {
                input.push_str(&bits(*a));
                input.push(' ');
            }
            input.push('\n');
            // the closed forms call libm's `sin`, `cos` and `atan2` (Rust: a polynomial `atan2`):
            // within a few units in the last place, not bit for bit
            expected.push((algebra_codegen::lang::function_name(plan, k), is_closed(k.op.name()), rust(&args)));
        }
    }
    let name = format!("{}-{}", plan.spec.name, if float { "f32" } else { "f64" });
    // optimised for 3D PGA (the results must not depend on it), unoptimised for the others (a
    // `-O2` build of the five full headers is 30 s of the test run, `-O0` 4 s)
    let opt = if plan.spec.name == "pga" { "-O1" } else { "-O0" };
    let out = compile_and_run(&name, &[("gam.h", &header), ("main.c", &driver)], "main.c", &input, opt);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), expected.len(), "one output line per call");
    for (line, (name, approx, want)) in lines.iter().zip(&expected) {
        let got: Vec<S> = line.split_whitespace().map(&parse).collect();
        if *approx {
            assert!(close(&got, want), "{name}: C and Rust differ beyond a few ulp: {got:?} vs {want:?}");
        } else {
            assert_eq!(&got, want, "{name}: C and Rust differ");
        }
    }
    ks.len()
}

/// Equal within `ulps` units in the last place of the largest magnitude (the results are of
/// unit scale, so an absolute bound at that scale).
fn within<S: Copy + Into<f64>>(a: &[S], b: &[S], eps: f64, ulps: f64) -> bool {
    let scale = a.iter().chain(b).map(|x| (*x).into().abs()).fold(1.0, f64::max);
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| ((*x).into() - (*y).into()).abs() <= ulps * eps * scale)
}

fn check_f64(plan: &Plan, reg: &Registry<f64>) -> usize {
    check(
        plan,
        reg,
        false,
        |x| x,
        |x| format!("{:x}", x.to_bits()),
        |s| f64::from_bits(u64::from_str_radix(s, 16).unwrap()),
        |a, b| within(a, b, f64::EPSILON, 8.0),
    )
}

fn check_f32(plan: &Plan, reg: &Registry<f32>) -> usize {
    check(
        plan,
        reg,
        true,
        |x| x as f32,
        |x| format!("{:x}", x.to_bits()),
        |s| f32::from_bits(u32::from_str_radix(s, 16).unwrap()),
        |a, b| within(a, b, f32::EPSILON as f64, 8.0),
    )
}

/// 3D PGA's header, compiled once per precision: two tests, so that the test threads run the
/// two C builds at the same time.
fn pga3_plan() -> Plan {
    plan("pga3", Basis::Blade, "Motor=even;Point=grade3;Line=grade2;Plane=grade1", "pga")
}

#[test]
fn pga3_header_equals_the_rust_kernels() {
    let r64 = registry!(pga, f64; types [Motor, Point, Line, Plane, Odd, Multivector]; versors [Motor, Point, Line, Plane, Odd] on [Motor, Point, Line, Plane, Odd]; closed [Line => Motor]);
    let n = check_f64(&pga3_plan(), &r64);
    assert!(n > 400, "{n} kernels");
}

#[test]
fn pga3_float_header_equals_the_rust_kernels() {
    let r32 = registry!(pga, f32; types [Motor, Point, Line, Plane, Odd, Multivector]; versors [Motor, Point, Line, Plane, Odd] on [Motor, Point, Line, Plane, Odd]; closed [Line => Motor]);
    let n = check_f32(&pga3_plan(), &r32);
    assert!(n > 400, "{n} kernels");
}

#[test]
fn oriented_pga3_header_equals_the_rust_kernels() {
    let plan = plan(
        "pga3",
        Basis::Blade,
        "Plane=grade1;Line=e01,e02,e03,e12,e31,e23;Point=e021,e013,e032,e123;Motor=1,e01,e02,e03,e12,e31,e23,e0123",
        "ganja",
    );
    let r64 = registry!(ganja, f64; types [Plane, Line, Point, Motor, Odd, Multivector]; versors [Plane, Line, Point, Motor, Odd] on [Plane, Line, Point, Motor, Odd]; closed [Line => Motor]);
    check_f64(&plan, &r64);
}

#[test]
fn g123inf_header_equals_the_rust_kernels() {
    let plan = plan(
        "g123inf",
        Basis::Blade,
        "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Bivector=grade2",
        "g123inf",
    );
    let r64 = registry!(g123inf, f64; types [Motor, Vector, Bivector, Odd, Multivector]; versors [Motor, Vector, Bivector, Odd] on [Motor, Vector, Bivector, Odd]; closed [Bivector => Motor]);
    check_f64(&plan, &r64);
}

#[test]
fn euclidean_rotor_header_equals_the_rust_kernels() {
    let plan = plan("g3", Basis::Blade, "Rotor=even;Vector=grade1;Bivector=grade2", "g3");
    let r64 = registry!(g3, f64; types [Rotor, Vector, Bivector, Odd, Multivector]; versors [Rotor, Vector, Bivector, Odd] on [Rotor, Vector, Bivector, Odd]; closed [Bivector => Rotor]);
    check_f64(&plan, &r64);
}

#[test]
fn product_basis_cga_header_equals_the_rust_kernels() {
    let plan =
        plan("cga-null", Basis::Product, "Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1", "cga_null");
    let r64 = registry!(cga_null, f64; types [Motor, Vector, Even, Odd, Multivector]; versors [Motor, Vector, Even, Odd] on [Vector, Even, Odd]; versors [Motor] on [Motor]; closed []);
    check_f64(&plan, &r64);
}

#[test]
fn gatl_declaration_header_equals_the_rust_kernels() {
    use algebra_codegen::ModuleSpec;
    use algebra_core::{Algebra, Metric};
    let z = "0";
    let gram: [&[&str]; 5] =
        [&["1", z, z, z, z], &[z, "1", z, z, z], &[z, z, "1", z, z], &[z, z, z, z, "-1"], &[z, z, z, "-1", z]];
    let metric = Metric::from_strs(&["1", "2", "3", "o", "inf"], &gram).unwrap();
    let alg = Algebra::new("gatl", metric.clone());
    let types = ModuleSpec::parse_types("Vector=grade1;Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf", &alg).unwrap();
    let plan = Plan::new(ModuleSpec::new("gatl", metric, Basis::Blade, types).unwrap()).unwrap();
    // the motor's point actions in the norm form (`n x_j + 2 y_j`) are printed in C as in Rust
    let normed = |k: &&algebra_codegen::versor::ActionKernel| k.norm.is_some() && (k.versor, k.operand) == (1, 0);
    assert_eq!(plan.actions.iter().filter(normed).count(), 2);
    let r64 = registry!(gatl, f64; types [Vector, Motor, Even, Odd, Multivector]; versors [Motor, Vector, Even, Odd] on [Vector, Even, Odd]; versors [Motor] on [Motor]; closed []);
    check_f64(&plan, &r64);
}
