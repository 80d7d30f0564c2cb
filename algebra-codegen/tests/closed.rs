//! Which (bivector, even) pairs `algebra_codegen::closed::detect` finds, from the tables alone,
//! and that `--standalone` output leaves the closed forms out.

use algebra_codegen::closed::{Family, Sign, detect};
use algebra_codegen::{ModuleSpec, plan::Plan, standalone};
use algebra_core::{Algebra, Basis, Metric};
use std::sync::Arc;

fn plan(alg: Arc<Algebra>, basis: Basis, types: &str) -> Plan {
    let types = ModuleSpec::parse_types(types, &alg).unwrap();
    Plan::new(ModuleSpec::new("m", alg.metric().clone(), basis, types).unwrap()).unwrap()
}

fn families(alg: Arc<Algebra>, basis: Basis, types: &str) -> Vec<(usize, usize, Family)> {
    let p = plan(alg, basis, types);
    detect(&p.spec, &p.closed).unwrap().into_iter().map(|c| (c.bivector, c.even, c.family)).collect()
}

fn diagonal(p: usize, q: usize, r: usize) -> Arc<Algebra> {
    Algebra::new("test", Metric::diagonal(p, q, r).unwrap())
}

#[test]
fn scalar_squares_by_sign() {
    // Euclidean rotors, 2D PGA (e3² = 0 here), a boost, R^{2,1}
    let f = |alg| families(alg, Basis::Blade, "B=grade2;M=even");
    assert_eq!(f(diagonal(3, 0, 0)), [(0, 1, Family::Scalar(Sign::Elliptic))]);
    assert_eq!(f(diagonal(2, 0, 1)), [(0, 1, Family::Scalar(Sign::Elliptic))]);
    assert_eq!(f(diagonal(1, 1, 0)), [(0, 1, Family::Scalar(Sign::Hyperbolic))]);
    assert_eq!(f(diagonal(2, 1, 0)), [(0, 1, Family::Scalar(Sign::Mixed))]);
    // complex numbers as a sub-pair of g3
    let g3 = Algebra::builtin("g3").unwrap();
    assert_eq!(families(g3, Basis::Blade, "I=e12;C=1,e12"), [(0, 1, Family::Scalar(Sign::Elliptic))]);
}

#[test]
fn dual_number_squares() {
    for (name, basis, types) in [
        ("pga3", Basis::Blade, "B=e01,e20,e03,e12,e31,e23;M=1,e01,e02,e30,e21,e13,e23,e0123"),
        ("g123inf", Basis::Blade, "B=grade2;M=even"),
        ("cga-null", Basis::Product, "B=e12,e13,e23,e1inf,e2inf,e3inf;M=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf"),
    ] {
        let found = families(Algebra::builtin(name).unwrap(), basis, types);
        assert_eq!(found.len(), 1, "{name}");
        let Family::Dual { i, half_c, i_times } = &found[0].2 else { panic!("{name}: {found:?}") };
        assert_eq!(i.count_ones(), 4, "{name}: I is the pseudoscalar");
        assert_eq!(half_c.len(), 3, "{name}: c/2 pairs each rotation with its translation");
        assert_eq!(i_times.iter().filter(|r| !r.is_empty()).count(), 3, "{name}: I kills translations");
    }
}

/// STA, R^4, R^{3,1}, R^{2,2} and R^{4,1} (diagonal and null basis): `B² = s + Q`, `Q²`
/// scalar, `B Q` in `B` — the invariant decomposition, with the expected `Q` and `Q²`.
#[test]
fn invariant_decomposition() {
    let inv = |alg, basis, types| {
        let found = families(alg, basis, types);
        assert_eq!(found.len(), 1, "{types}: {found:?}");
        let Family::Invariant(inv) = found.into_iter().next().unwrap().2 else { panic!("{types}") };
        inv
    };
    for (p, neg) in [(1, 3), (4, 0), (3, 1), (2, 2)] {
        let i = inv(diagonal(p, neg, 0), Basis::Blade, "B=grade2;M=even");
        assert_eq!(i.quad, [0b1111]);
        // Q = 2 (b12 b34 - b13 b24 + b14 b23) e1234 (fields in order e12 e13 e23 e14 e24 e34)
        let q: Vec<(usize, usize, String)> = i.q[0].iter().map(|(a, b, c)| (*a, *b, c.to_string())).collect();
        let two = |a, b, s: &str| (a, b, s.to_string());
        assert_eq!(q, [two(0, 5, "2"), two(1, 4, "-2"), two(2, 3, "2")], "{p},{neg}");
        // Q² = (e1234)² q² = (-1)^neg q²
        let sign = if neg % 2 == 0 { "1" } else { "-1" };
        assert_eq!(i.q4.iter().map(|(_, _, c)| c.to_string()).collect::<Vec<_>>(), [sign]);
    }
    let cga = inv(Algebra::builtin("cga").unwrap(), Basis::Blade, "B=grade2;M=even");
    assert_eq!(cga.quad, [0b01111, 0b10111, 0b11011, 0b11101, 0b11110]);
    // Q² = v² I² for Q = v I: e1234² = +1 (e5 missing), the others contain e5² = -1
    let diag: Vec<String> = cga.q4.iter().map(|(a, b, c)| format!("{a}{b}:{c}")).collect();
    assert_eq!(diag, ["00:1", "11:-1", "22:-1", "33:-1", "44:-1"]);
    let null = Algebra::new(
        "null",
        Metric::from_strs(
            &["e1", "e2", "e3", "eo", "einf"],
            &[
                &["1", "0", "0", "0", "0"],
                &["0", "1", "0", "0", "0"],
                &["0", "0", "1", "0", "0"],
                &["0", "0", "0", "0", "-1"],
                &["0", "0", "0", "-1", "0"],
            ],
        )
        .unwrap(),
    );
    assert_eq!(inv(null, Basis::Blade, "B=grade2;M=even").quad.len(), 5);
    // the earlier families keep priority where they apply
    for name in ["pga3", "g123inf"] {
        let found = families(Algebra::builtin(name).unwrap(), Basis::Blade, "B=grade2;M=even");
        assert!(matches!(found[0].2, Family::Dual { .. }), "{name}");
    }
}

#[test]
fn outside_the_families_nothing() {
    let f = |alg, types| families(alg, Basis::Blade, types);
    // a bivector type that does not hold every bivector of the even type, an even type
    // without its 4-vectors (B² leaves it), and a non-bivector "bivector" type
    assert!(f(diagonal(4, 0, 0), "B=e12,e34;M=even").is_empty());
    // (that B pairs with the automatic `Even` instead)
    assert!(f(diagonal(4, 0, 0), "B=grade2;M=1,e12,e13,e14,e23,e24,e34").iter().all(|(_, m, _)| *m != 1));
    assert!(f(diagonal(4, 0, 0), "B=e1234;M=even").is_empty());
    // an even type alone has no pair; a bivector type alone pairs with the automatic `Even`
    assert!(f(diagonal(3, 0, 0), "M=even").is_empty());
    let p = plan(diagonal(3, 0, 0), Basis::Blade, "B=grade2;V=grade1");
    let found = detect(&p.spec, &p.closed).unwrap();
    assert_eq!((found.len(), p.spec.types[found[0].even].name.as_str()), (1, "Even"));
    // the product basis of G_{0123inf}: e0inf does not reverse to -e0inf
    let cn = Algebra::builtin("cga-null").unwrap();
    assert!(families(cn, Basis::Product, "B=grade2;M=even").is_empty());
}

/// The closed forms are methods of the generated module and of the standalone file (which
/// then inlines `Real` and the factors as `mod closed_form`), except the invariant
/// decomposition in a standalone file (its complex-root fallback needs the runtime).
#[test]
fn emitted_in_modules_and_standalone_files_but_the_invariant_family() {
    let p = plan(Algebra::builtin("pga3").unwrap(), Basis::Blade, "Line=grade2;Motor=even");
    let module = algebra_codegen::emit::module(&p).to_string();
    let file = |p: &Plan| quote::ToTokens::to_token_stream(&standalone::file(p, &[], None).unwrap()).to_string();
    let text = file(&p);
    for m in ["fn exp", "fn try_exp", "fn normalize", "fn log", "fn log_unit", "fn sqrt", "fn pow"] {
        assert!(module.contains(m) && text.contains(m), "{m}");
    }
    assert!(
        text.contains("pub mod closed_form")
            && text.contains("pub trait Real")
            && text.contains("float_real ! (f32 , f64)")
    );
    assert!(!text.contains("algebra_core ::"), "no path into algebra-core");
    // CGA: the invariant decomposition in the module, not in the standalone file
    let c = plan(Algebra::builtin("cga").unwrap(), Basis::Blade, "B=grade2;M=even");
    assert!(algebra_codegen::emit::module(&c).to_string().contains("fn log_unit"));
    let text = file(&c);
    assert!(!text.contains("fn log_unit") && !text.contains("pub trait Real") && text.contains("pub struct M"));
}
