//! The term order of the binary product kernels, measured per kernel.
//!
//! A binary kernel's outputs are sums of `c · a[i] · b[j]`. Their exact values do not depend
//! on the order of the summands, but the speed does: LLVM's SLP vectoriser packs neighbouring
//! outputs only when their sums have the same shape and signs at the same places. Every kernel
//! takes the tables' order in chains of at most four ([`ProductOrder::TABLES`]) unless
//! [`WISDOM`] lists an order measured faster for it (keyed by [`fingerprint`]), as
//! [`crate::versor::WISDOM`] does for the fused versor actions. `cargo run --release -p
//! algebra-codegen --example product_wisdom` re-derives the table (docs/performance.md,
//! "Term order of the motor product").
//!
//! The order applies to the Rust kernels and, through the shared plan, to the C, WGSL and GLSL
//! kernels of the same declaration, which therefore still add in the same order.

use crate::plan::BinaryKernel;

/// How a binary kernel writes each output's sum.
///
/// ```
/// use algebra_codegen::product_order::ProductOrder;
/// assert_eq!(ProductOrder::TABLES, ProductOrder { positive_first: 0, chain: 4 });
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ProductOrder {
    /// Within each block of this many summands of the tables' order (by the left field, then
    /// the right field), those with a positive coefficient first, each group in the tables'
    /// order; 0 keeps the tables' order. A motor's translation outputs list `R x T` in their
    /// first four terms and `T x R` in the last four, so blocks of four sort each product.
    pub positive_first: usize,
    /// The longest chain of additions: a longer sum is written as chains of this many terms,
    /// added left to right (`(a + b - c + d) + (e - f - g + h)`).
    pub chain: usize,
}

impl ProductOrder {
    /// The default: the tables' order, chains of four (docs/performance.md, "Motor product
    /// shape"): a motor product's translation outputs as two quaternion products added.
    pub const TABLES: Self = Self { positive_first: 0, chain: 4 };
}

/// Orders measured faster than [`ProductOrder::TABLES`] for one kernel: its
/// [`fingerprint`], a label, the order. Each entry is the fastest of the candidates of the
/// `product_wisdom` example on the machine named in docs/performance.md.
pub const WISDOM: &[(u64, &str, ProductOrder)] = &[
    // `g123inf` `Motor * Motor` (1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf): its
    // outputs as one chain, the positive terms of each quaternion product (`R x T`, `T x R`)
    // first: 0.91x the tables' chains of four (Intel Xeon, baseline x86-64)
    (0x845e_62fe_fba4_f5ea, "g123inf Motor gp Motor", ProductOrder { positive_first: 4, chain: 8 }),
    // `cga` `Motor * Motor` (16 even fields, 16 terms per output): one chain, the positive
    // terms first within each pair of terms: 0.899x the tables' chains of four
    (0x022a_7650_fb28_894e, "cga Motor gp Motor", ProductOrder { positive_first: 2, chain: 16 }),
];

/// A kernel's structure, independent of its current term order: FNV-1a of the product and
/// each output's terms in the tables' order.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_core::tables::Product;
/// use algebra_codegen::{ModuleSpec, plan::Plan, product_order::fingerprint};
/// let alg = Algebra::builtin("g123inf").unwrap();
/// let types = ModuleSpec::parse_types("Motor=even", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("m", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let k = plan.kernel(Product::Geometric, 0, 0);
/// assert_eq!(fingerprint(k), algebra_codegen::product_order::WISDOM[0].0);
/// ```
pub fn fingerprint(k: &BinaryKernel) -> u64 {
    let mut canonical = k.clone();
    apply_order(&mut canonical, ProductOrder::TABLES);
    let text = format!("{:?} {:?}", canonical.product, canonical.outputs);
    crate::fnv1a(&text)
}

/// Puts `k`'s terms in `order` (a permutation of each output's terms) and sets its chain
/// length.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_core::tables::Product;
/// use algebra_codegen::{ModuleSpec, plan::Plan, product_order::{ProductOrder, apply_order}};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Rotor=even", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("m", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let mut k = plan.kernel(Product::Geometric, 0, 0).clone();
/// apply_order(&mut k, ProductOrder { positive_first: 4, chain: 8 });
/// // the scalar output `s s' - b12 b12' - b13 b13' - b23 b23'` starts with its positive term
/// assert!(k.outputs[0][0].coef.0 > 0 && k.outputs[0][1..].iter().all(|t| t.coef.0 < 0));
/// assert_eq!(k.chain, 8);
/// ```
pub fn apply_order(k: &mut BinaryKernel, order: ProductOrder) {
    for terms in &mut k.outputs {
        // the tables list the terms by left field, then right field
        terms.sort_by_key(|t| (t.lhs, t.rhs));
        if order.positive_first > 0 {
            for block in terms.chunks_mut(order.positive_first) {
                block.sort_by_key(|t| t.coef.0 < 0);
            }
        }
    }
    k.chain = order.chain;
}

/// Gives `k` the order [`WISDOM`] lists for it, else the tables' order.
pub(crate) fn order_for_pairing(k: &mut BinaryKernel) {
    let f = fingerprint(k);
    let order = WISDOM.iter().find(|w| w.0 == f).map_or(ProductOrder::TABLES, |w| w.2);
    apply_order(k, order);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ModuleSpec, plan::Plan};
    use algebra_core::{Algebra, Basis};

    fn plan(algebra: &str, types: &str) -> Plan {
        let alg = Algebra::builtin(algebra).unwrap();
        let types = ModuleSpec::parse_types(types, &alg).unwrap();
        Plan::new(ModuleSpec::new("m", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap()
    }

    /// Each output's terms as `(lhs, rhs, coefficient)`, sorted.
    type Terms = Vec<Vec<(usize, usize, crate::ratio::Ratio)>>;

    fn sorted(k: &BinaryKernel) -> Terms {
        k.outputs
            .iter()
            .map(|o| {
                let mut v: Vec<_> = o.iter().map(|t| (t.lhs, t.rhs, t.coef)).collect();
                v.sort_unstable();
                v
            })
            .collect()
    }

    /// Every order is a permutation of each output's terms (the same exact sum), and the
    /// fingerprint does not depend on the order a kernel is in.
    #[test]
    fn orders_permute_terms_and_keep_the_fingerprint() {
        for (algebra, types) in
            [("g123inf", "Motor=even;Vector=grade1"), ("pga3", "Motor=even"), ("cga", "Rotor=1,e12,e13,e23")]
        {
            let p = plan(algebra, types);
            for k in p.binary.iter().chain(&p.typed) {
                let f = fingerprint(k);
                for positive_first in [0, 1, 2, 4, 8] {
                    for chain in [1, 2, 4, 8] {
                        let mut o = k.clone();
                        apply_order(&mut o, ProductOrder { positive_first, chain });
                        assert_eq!(sorted(&o), sorted(k));
                        assert_eq!(fingerprint(&o), f);
                        assert_eq!(o.chain, chain);
                        if positive_first == 1 {
                            // blocks of one: the tables' order
                            let mut t = k.clone();
                            apply_order(&mut t, ProductOrder::TABLES);
                            assert_eq!(o.outputs, t.outputs);
                        }
                    }
                }
            }
        }
    }

    /// The planned `g123inf` motor product takes its measured order: each output's `R x T`
    /// and `T x R` halves with their positive terms first, one chain; other kernels the tables'.
    #[test]
    fn the_plan_applies_the_wisdom() {
        let p = plan("g123inf", "Motor=even;Vector=grade1");
        let motor = p.kernel(algebra_core::tables::Product::Geometric, 0, 0);
        assert_eq!(motor.chain, 8);
        let e1inf: Vec<i64> = motor.outputs[4].iter().map(|t| t.coef.0).collect();
        assert_eq!(e1inf, [1, 1, 1, -1, 1, -1, -1, -1]);
        let e2inf: Vec<i64> = motor.outputs[5].iter().map(|t| t.coef.0).collect();
        assert_eq!(e2inf, [1, 1, 1, -1, 1, 1, 1, -1]);
        let other = p.kernel(algebra_core::tables::Product::Geometric, 0, 1);
        assert_eq!(other.chain, ProductOrder::TABLES.chain);
        let mut tables = other.clone();
        apply_order(&mut tables, ProductOrder::TABLES);
        assert_eq!(other.outputs, tables.outputs);
        // `cga`'s 16-field motor product: one chain, signs sorted within each pair of terms
        let p = plan("cga", "Motor=even");
        let motor = p.kernel(algebra_core::tables::Product::Geometric, 0, 0);
        assert_eq!(motor.chain, 16);
        for out in &motor.outputs {
            assert_eq!(out.len(), 16);
            assert!(out.chunks(2).all(|pair| pair[0].coef.0 > 0 || pair[1].coef.0 < 0));
        }
    }
}
