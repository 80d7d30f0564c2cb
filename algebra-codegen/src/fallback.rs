//! Automatic `Even`/`Odd` output types: when a product or unary operation of declared types
//! lands outside every declared type, the generator declares the even (or odd) part of the
//! algebra instead of returning the full multivector, whenever the result has one parity.
//!
//! The geometric product and every product and unary map derived from it respect parity in
//! both bases (a product-basis element of `k` generators has parity `k`), so even × even and
//! odd × odd land in `Even`, even × odd in `Odd`: the added types are closed and the fixpoint
//! is reached after at most two rounds. Only modules that do not declare the full multivector
//! get them; a declared full type is a declared type every result lands in.

use super::spec::{CodegenError, ModuleSpec, TypeSpec};
use crate::naming::UNARY_OPS;
use algebra_core::tables::Product;
use std::collections::BTreeSet;

/// The parity of a basis element (`0` even, `1` odd).
fn parity(mask: u32) -> u32 {
    mask.count_ones() % 2
}

/// Every support of a product or unary kernel of the current types that no type holds.
fn homeless_supports(spec: &ModuleSpec) -> Vec<BTreeSet<u32>> {
    let tables = spec.algebra.tables();
    let sets: Vec<BTreeSet<u32>> = spec.types.iter().map(|t| t.elements.iter().copied().collect()).collect();
    let homeless = |s: &BTreeSet<u32>| !s.is_empty() && !sets.iter().any(|t| s.is_subset(t));
    let mut out = Vec::new();
    for product in Product::ALL {
        let table = tables.product(spec.basis, product);
        for a in &spec.types {
            for b in &spec.types {
                let support: BTreeSet<u32> = a
                    .elements
                    .iter()
                    .flat_map(|&ma| {
                        b.elements.iter().flat_map(move |&mb| {
                            table.get(ma, mb).expect("a mask of the spec's algebra").iter().map(|(k, _)| *k)
                        })
                    })
                    .collect();
                if homeless(&support) {
                    out.push(support);
                }
            }
        }
    }
    for op in UNARY_OPS {
        let map = tables.unary(spec.basis, op);
        for t in &spec.types {
            let support: BTreeSet<u32> = t
                .elements
                .iter()
                .flat_map(|&m| map.image(m).expect("a mask of the spec's algebra").iter().map(|(k, _)| *k))
                .collect();
            if homeless(&support) {
                out.push(support);
            }
        }
    }
    out
}

/// Appends `Even` and/or `Odd` (named `EvenMultivector`/`OddMultivector`, then with a number,
/// if the short name is taken) while some single-parity result lands outside every type. Call only when no
/// declared type is the full multivector.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Vector=grade1;Rotor=even", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let names: Vec<&str> = plan.spec.types.iter().map(|t| t.name.as_str()).collect();
/// // vector * rotor has grades 1 and 3: the odd part, not the full multivector
/// assert_eq!(names, ["Vector", "Rotor", "Odd", "Multivector"]);
/// let gp = plan.stats().into_iter().find(|s| s.op == "gp" && s.lhs == "Vector" && s.rhs.as_deref() == Some("Rotor")).unwrap();
/// assert_eq!(gp.out, "Odd");
/// // names already taken by other types get a longer one
/// let alg = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Even=grade1;EvenMultivector=grade3", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("p", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let names: Vec<&str> = plan.spec.types.iter().map(|t| t.name.as_str()).collect();
/// assert_eq!(names, ["Even", "EvenMultivector", "EvenMultivector2", "Odd", "Multivector"]);
/// ```
pub fn add_parity_types(spec: &mut ModuleSpec) -> Result<(), CodegenError> {
    let order = spec.algebra.basis_order().to_vec();
    loop {
        let mut wanted: Vec<u32> = Vec::new();
        for s in homeless_supports(spec) {
            let p = parity(*s.first().expect("non-empty"));
            if s.iter().all(|&m| parity(m) == p) && !wanted.contains(&p) {
                wanted.push(p);
            }
        }
        if wanted.is_empty() {
            return Ok(());
        }
        wanted.sort_unstable();
        for p in wanted {
            let (short, long, what) =
                if p == 0 { ("Even", "EvenMultivector", "even") } else { ("Odd", "OddMultivector", "odd") };
            let taken = |n: &str| spec.types.iter().any(|t| t.name == n);
            let name = [short.to_string(), long.to_string()]
                .into_iter()
                .chain((2..).map(|i| format!("{long}{i}")))
                .find(|n| !taken(n))
                .expect("an unused name");
            let elements: Vec<u32> = order.iter().copied().filter(|&m| parity(m) == p).collect();
            let mut t = TypeSpec::new(&name, elements)?;
            t.doc.push(format!(
                "The {what} part of the algebra, declared automatically: some product of the declared types lands here."
            ));
            spec.types.push(t);
        }
    }
}
