//! The precomputed constrained kernels (`src/constraint/precomputed.txt`, read by the GMP-free
//! `algebra!` macro) are exactly what the Gröbner reduction computes today, for every module
//! below: the predefined modules that declare constraints (`gam-algebras`) and the test
//! modules of the DSL. Regenerate with
//! `BLESS=1 cargo test -p algebra-codegen --features constraints --test constraint_table`
//! after changing a declaration here or the reduction.

use algebra_codegen::constraint::{methods, requests, table};
use algebra_codegen::{ModuleSpec, plan::Plan};
use algebra_core::{Algebra, Basis};

/// (builtin algebra, basis, types) of every module whose constrained kernels are precomputed:
/// the same declarations as in `algebras/src/generated.rs` and `algebras/tests/constrained.rs`.
const MODULES: &[(&str, Basis, &str)] = &[
    (
        "cga-null",
        Basis::Product,
        "Vector=grade1;Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf where unit;PoseBivector=e12,e13,e23,e1inf,e2inf,e3inf;Multivector=all",
    ),
    ("pga3", Basis::Blade, "Vector=grade1;Bivector=grade2;Trivector=grade3;Motor=even where unit;Multivector=all"),
    (
        "g123inf",
        Basis::Blade,
        "Vector=grade1;Bivector=grade2;Pseudoscalar=1,e123inf;Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf where unit;Multivector=all",
    ),
    ("pga3", Basis::Blade, "Scalar=grade0;Line=grade2 where simple;Multivector=all"),
    ("cga-null", Basis::Product, "Point=grade1 where null;Multivector=all"),
];

fn plan(alg: &str, basis: Basis, types: &str) -> Plan {
    let alg = Algebra::builtin(alg).unwrap();
    let types = ModuleSpec::parse_types(types, &alg).unwrap();
    Plan::new(ModuleSpec::new("m", alg.metric().clone(), basis, types).unwrap()).unwrap()
}

#[test]
fn the_precomputed_table_is_up_to_date() {
    let mut text = String::new();
    let mut seen = std::collections::BTreeSet::new();
    for &(alg, basis, types) in MODULES {
        let plan = plan(alg, basis, types);
        for r in requests(&plan.spec, plan.full) {
            let key = table::key(&plan.spec, r);
            if seen.insert(key.clone()) {
                let k = algebra_codegen::constraint::compute(&plan.spec, r).unwrap();
                text.push_str(&table::entry(&key, &k));
            }
        }
    }
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/src/constraint/precomputed.txt");
    if std::env::var_os("BLESS").is_some() {
        std::fs::write(path, &text).unwrap();
    }
    assert_eq!(std::fs::read_to_string(path).unwrap(), text, "regenerate with BLESS=1");
}

/// A kernel read back from the table is the computed one, spec-dependent fields included.
#[test]
fn table_kernels_equal_computed_kernels() {
    for &(alg, basis, types) in MODULES {
        let plan = plan(alg, basis, types);
        for r in requests(&plan.spec, plan.full) {
            let from_table = algebra_codegen::constraint::kernel(&plan.spec, r).unwrap();
            assert_eq!(from_table, algebra_codegen::constraint::compute(&plan.spec, r).unwrap(), "{r:?}");
        }
        assert!(methods(&plan).is_ok());
    }
}
