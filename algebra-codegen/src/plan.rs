//! Structural analysis: which terms each generated kernel contains, and which declared type
//! receives each result. Everything here is decided from the exact tables at expansion time.

pub use crate::naming::{UNARY_OPS, unary_name};
use crate::product_order::ProductOrder;
pub use crate::ratio::Ratio;
use crate::ratio::{is_unit, to_ratio};
use crate::spec::{CodegenError, ModuleSpec, TypeSpec};
use algebra_core::basis::Basis;
use algebra_core::multivector::Multivector;
use algebra_core::rational::Q;
use algebra_core::tables::{Product, Unary};
use num_traits::Zero;
use std::collections::BTreeSet;

/// The chain length a kernel is planned with, before [`crate::product_order`] orders it.
const TABLES_CHAIN: usize = ProductOrder::TABLES.chain;

/// `c · lhs[lhs] · rhs[rhs]`: one term of a binary kernel (field indices into the types).
#[derive(Debug, Clone, PartialEq)]
pub struct Term {
    /// Field index in the left type.
    pub lhs: usize,
    /// Field index in the right type.
    pub rhs: usize,
    /// The exact coefficient.
    pub coef: Ratio,
}

/// One generated binary kernel.
#[derive(Debug, Clone)]
pub struct BinaryKernel {
    /// The product.
    pub product: Product,
    /// Left type index.
    pub lhs: usize,
    /// Right type index.
    pub rhs: usize,
    /// Output type index (the smallest declared type holding the structural support).
    pub out: usize,
    /// For each field of the output type, its terms.
    pub outputs: Vec<Vec<Term>>,
    /// The longest chain of additions an output's sum is written as
    /// ([`crate::product_order::ProductOrder::chain`]).
    pub chain: usize,
}

/// One generated linear unary kernel: each output field is `Σ c · x[field]`.
#[derive(Debug, Clone)]
pub struct UnaryKernel {
    /// The operation.
    pub op: Unary,
    /// Input type index.
    pub ty: usize,
    /// Output type index.
    pub out: usize,
    /// For each output field, `(input field, coefficient)`.
    pub outputs: Vec<Vec<(usize, Ratio)>>,
}

/// Operation counts of one kernel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KernelStats {
    /// `gp`, `op`, `lc`, `rc`, `sp`, `rp`, `comm`, `acomm`, or a unary name.
    pub op: String,
    /// Left (or only) operand type.
    pub lhs: String,
    /// Right operand type (`None` for unary kernels).
    pub rhs: Option<String>,
    /// Output type.
    pub out: String,
    /// Multiplications: one per distinct `lhs × rhs` field product, plus one per constant
    /// other than ±1.
    pub mul: usize,
    /// Additions and subtractions.
    pub add: usize,
}

/// The analysed module.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The spec, with the full multivector type appended when no declared type holds every
    /// basis element (named `Multivector`, or `FullMultivector` if that name is taken).
    pub spec: ModuleSpec,
    /// How many types the user declared: the first `declared` of `spec.types`; the others
    /// (automatic `Even`/`Odd`, the full multivector) are added by the plan as outputs.
    pub declared: usize,
    /// Index of the type holding every basis element (the fallback output type).
    pub full: usize,
    /// Every binary kernel: all ordered pairs of types, all products.
    pub binary: Vec<BinaryKernel>,
    /// Every unary kernel: reverse, grade involution, Clifford conjugate, dual, undual.
    pub unary: Vec<UnaryKernel>,
    /// For each type, the symmetric matrix of `<x rev(x)>_0` as upper-triangular terms.
    pub norm: Vec<Vec<Term>>,
    /// Per type: whether it is a subalgebra containing 1 (then `inverse` stays in the type).
    pub closed: Vec<bool>,
    /// The fused versor actions ([`super::versor`]).
    pub actions: Vec<super::versor::ActionKernel>,
    /// The output-typed geometric products (`GeometricProductInto`): for every pair of types
    /// and every type `out` other than the natural output that shares a basis element with
    /// the product's support, the kernel computing only `out`'s components.
    pub typed: Vec<BinaryKernel>,
    /// The matrix forms of the fused actions small enough ([`super::matrix`]).
    pub matrices: Vec<super::matrix::MatrixKernel>,
}

/// Counts of a kernel given its per-output terms.
fn count(outputs: &[Vec<Term>]) -> (usize, usize) {
    let pairs: BTreeSet<(usize, usize)> = outputs.iter().flatten().map(|t| (t.lhs, t.rhs)).collect();
    let consts = outputs.iter().flatten().filter(|t| !is_unit(t.coef)).count();
    let adds = outputs.iter().map(|o| o.len().saturating_sub(1)).sum();
    (pairs.len() + consts, adds)
}

impl Plan {
    /// Analyses a spec.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::{ModuleSpec, plan::Plan};
    /// let alg = Algebra::builtin("g123inf").unwrap();
    /// let types = ModuleSpec::parse_types("Motor=even", &alg).unwrap();
    /// let spec = ModuleSpec::new("g123inf", alg.metric().clone(), Basis::Blade, types).unwrap();
    /// let plan = Plan::new(spec).unwrap();
    /// let gp = plan.stats().into_iter().find(|s| s.op == "gp" && s.lhs == "Motor" && s.rhs.as_deref() == Some("Motor")).unwrap();
    /// assert_eq!((gp.out.as_str(), gp.mul, gp.add), ("Motor", 48, 40));
    /// ```
    pub fn new(mut spec: ModuleSpec) -> Result<Plan, CodegenError> {
        let alg = spec.algebra.clone();
        let declared = spec.types.len();
        // every type keeps its storage order ([`TypeSpec::elements`]): kernels index fields
        let order = alg.basis_order().to_vec();
        let full = match spec.types.iter().position(|t| t.elements.len() == alg.dim()) {
            Some(i) => i,
            None => {
                if spec.parity_types {
                    super::fallback::add_parity_types(&mut spec)?;
                }
                let name =
                    if spec.types.iter().any(|t| t.name == "Multivector") { "FullMultivector" } else { "Multivector" };
                let mut t = TypeSpec::new(name, order.clone())?;
                t.doc.push("Every basis element (the fallback output type).".into());
                spec.types.push(t);
                spec.types.len() - 1
            }
        };
        let sets: Vec<BTreeSet<u32>> = spec.types.iter().map(|t| t.elements.iter().copied().collect()).collect();
        // smallest type holding a support; ties go to the first declared
        let choose = |support: &BTreeSet<u32>| -> usize {
            (0..sets.len()).filter(|&i| support.is_subset(&sets[i])).min_by_key(|&i| (sets[i].len(), i)).unwrap_or(full)
        };
        let tables = alg.tables();
        let basis = spec.basis;
        let mut binary = Vec::new();
        let mut typed = Vec::new();
        for product in Product::ALL {
            let table = tables.product(basis, product);
            for (li, lt) in spec.types.iter().enumerate() {
                for (ri, rt) in spec.types.iter().enumerate() {
                    let mut raw: Vec<(u32, Term)> = Vec::new();
                    for (a, &ma) in lt.elements.iter().enumerate() {
                        for (b, &mb) in rt.elements.iter().enumerate() {
                            for (k, c) in table.get(ma, mb).expect("a mask of the spec's algebra") {
                                raw.push((*k, Term { lhs: a, rhs: b, coef: to_ratio(c)? }));
                            }
                        }
                    }
                    let support: BTreeSet<u32> = raw.iter().map(|(k, _)| *k).collect();
                    let out = choose(&support);
                    let restrict = |o: usize| -> Vec<Vec<Term>> {
                        spec.types[o]
                            .elements
                            .iter()
                            .map(|m| raw.iter().filter(|(k, _)| k == m).map(|(_, t)| t.clone()).collect())
                            .collect()
                    };
                    if product == Product::Geometric {
                        for o in (0..sets.len()).filter(|&o| o != out && !sets[o].is_disjoint(&support)) {
                            typed.push(BinaryKernel {
                                product,
                                lhs: li,
                                rhs: ri,
                                out: o,
                                outputs: restrict(o),
                                chain: TABLES_CHAIN,
                            });
                        }
                    }
                    binary.push(BinaryKernel {
                        product,
                        lhs: li,
                        rhs: ri,
                        out,
                        outputs: restrict(out),
                        chain: TABLES_CHAIN,
                    });
                }
            }
        }
        let mut unary = Vec::new();
        for op in UNARY_OPS {
            let map = tables.unary(basis, op);
            for (ti, t) in spec.types.iter().enumerate() {
                let mut raw: Vec<(u32, usize, Ratio)> = Vec::new();
                for (a, &ma) in t.elements.iter().enumerate() {
                    for (k, c) in map.image(ma).expect("a mask of the spec's algebra") {
                        raw.push((*k, a, to_ratio(c)?));
                    }
                }
                let support: BTreeSet<u32> = raw.iter().map(|(k, _, _)| *k).collect();
                let out = choose(&support);
                let outputs = spec.types[out]
                    .elements
                    .iter()
                    .map(|m| raw.iter().filter(|(k, _, _)| k == m).map(|(_, a, c)| (*a, *c)).collect())
                    .collect();
                unary.push(UnaryKernel { op, ty: ti, out, outputs });
            }
        }
        let norm = spec.types.iter().map(|t| norm_terms(&alg, basis, &t.elements)).collect::<Result<_, _>>()?;
        let closed = (0..spec.types.len())
            .map(|i| {
                let gp = binary.iter().find(|k| k.product == Product::Geometric && k.lhs == i && k.rhs == i);
                sets[i].contains(&0) && gp.is_some_and(|k| k.out == i || sets[k.out].is_subset(&sets[i]))
            })
            .collect();
        let actions = super::versor::plan_actions(&spec, full)?;
        let mut plan = Plan { spec, declared, full, binary, unary, norm, closed, actions, typed, matrices: Vec::new() };
        fold_signs(&mut plan);
        // each product's term order: the tables' (chains of `TABLES_CHAIN`) or a measured one
        for k in plan.binary.iter_mut().chain(plan.typed.iter_mut()) {
            super::product_order::order_for_pairing(k);
        }
        plan.matrices = super::matrix::plan_matrices(&plan.actions);
        super::versor::norm_forms(&mut plan)?;
        let (table_above, declared) = (plan.spec.table_above, plan.declared);
        for k in &mut plan.actions {
            let lens = k.stage1.iter().chain(&k.stage2).map(Vec::len);
            let table_driven = super::size::table_driven(table_above, declared, &[k.versor, k.operand], lens);
            super::versor::order_for_pairing(k, table_driven);
            if !table_driven {
                k.operand_constants = k.norm.is_none();
            }
        }
        Ok(plan)
    }

    /// The binary kernel for a product and a pair of type indices.
    pub fn kernel(&self, product: Product, lhs: usize, rhs: usize) -> &BinaryKernel {
        self.binary
            .iter()
            .find(|k| k.product == product && k.lhs == lhs && k.rhs == rhs)
            .expect("every pair and product is planned")
    }

    /// Operation counts of every kernel (binary first, then the output-typed geometric
    /// products as `gp_into`, the unary kernels and the fused actions).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::{ModuleSpec, plan::Plan};
    /// let alg = Algebra::builtin("g123inf").unwrap();
    /// let types = ModuleSpec::parse_types("Motor=even;Pseudoscalar=1,e123inf", &alg).unwrap();
    /// let plan = Plan::new(ModuleSpec::new("m", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
    /// let find = |op: &str, out: &str| {
    ///     let s = plan.stats().into_iter().find(|s| s.op == op && s.lhs == "Motor" && s.rhs.as_deref() == Some("Motor") && s.out == out).unwrap();
    ///     (s.mul, s.add)
    /// };
    /// // the pseudoscalar part of a motor product costs a quarter of the product
    /// assert_eq!(find("gp", "Motor"), (48, 40));
    /// assert_eq!(find("gp_into", "Pseudoscalar"), (12, 10));
    /// ```
    pub fn stats(&self) -> Vec<KernelStats> {
        let name = |i: usize| self.spec.types[i].name.clone();
        let mut out: Vec<KernelStats> = self
            .binary
            .iter()
            .map(|k| {
                let (mul, add) = count(&k.outputs);
                KernelStats {
                    op: k.product.cli_name().to_string(),
                    lhs: name(k.lhs),
                    rhs: Some(name(k.rhs)),
                    out: name(k.out),
                    mul,
                    add,
                }
            })
            .collect();
        for k in &self.typed {
            let (mul, add) = count(&k.outputs);
            out.push(KernelStats {
                op: "gp_into".to_string(),
                lhs: name(k.lhs),
                rhs: Some(name(k.rhs)),
                out: name(k.out),
                mul,
                add,
            });
        }
        for k in &self.unary {
            let mul = k.outputs.iter().flatten().filter(|(_, c)| !is_unit(*c)).count();
            let add = k.outputs.iter().map(|o| o.len().saturating_sub(1)).sum();
            out.push(KernelStats {
                op: unary_name(k.op).to_string(),
                lhs: name(k.ty),
                rhs: None,
                out: name(k.out),
                mul,
                add,
            });
        }
        for k in &self.actions {
            let (mul, add) = k.counts();
            let op = match k.convention {
                super::versor::Convention::Sandwich => "sandwich",
                super::versor::Convention::Apply => "apply",
            };
            out.push(KernelStats {
                op: op.to_string(),
                lhs: name(k.versor),
                rhs: Some(name(k.operand)),
                out: name(k.operand),
                mul,
                add,
            });
        }
        // the unit-versor kernels (`apply_unit`, `sandwich_unit`; [`super::unit`])
        for u in super::unit::plan_unit_actions(&self.spec, &self.actions).unwrap_or_default() {
            let (mul, add) = u.counts();
            let op = match u.kernel.convention {
                super::versor::Convention::Sandwich => "sandwich_unit",
                super::versor::Convention::Apply => "apply_unit",
            };
            let (v, x) = (u.kernel.versor, u.kernel.operand);
            out.push(KernelStats { op: op.to_string(), lhs: name(v), rhs: Some(name(x)), out: name(x), mul, add });
        }
        out
    }
}

/// `<x rev(x)>_0 = Σ_{i<=j} c_ij x_i x_j` for a type with the given elements.
fn norm_terms(
    alg: &std::sync::Arc<algebra_core::Algebra>,
    basis: Basis,
    elements: &[u32],
) -> Result<Vec<Term>, CodegenError> {
    let e = |m: u32| Multivector::<Q>::from_mask(alg, basis, m).expect("a type's masks are below 2^n");
    let mut terms = Vec::new();
    for (i, &mi) in elements.iter().enumerate() {
        for (j, &mj) in elements.iter().enumerate().skip(i) {
            let mut c = e(mi).sp(&e(mj).reverse()).scalar_part();
            if i != j {
                c += e(mj).sp(&e(mi).reverse()).scalar_part();
            }
            if !c.is_zero() {
                terms.push(Term { lhs: i, rhs: j, coef: to_ratio(&c)? });
            }
        }
    }
    Ok(terms)
}

/// Folds the orientation signs of renamed blades ([`crate::orient`]) of every type into the plan's kernels (a no-op without renames).
fn fold_signs(plan: &mut Plan) {
    let signs: Vec<Vec<i64>> = plan.spec.types.iter().map(crate::TypeSpec::signs).collect();
    if signs.iter().flatten().all(|&s| s == 1) {
        return;
    }
    for k in plan.binary.iter_mut().chain(plan.typed.iter_mut()) {
        for (o, terms) in k.outputs.iter_mut().enumerate() {
            for t in terms {
                t.coef = crate::orient::times(t.coef, signs[k.lhs][t.lhs] * signs[k.rhs][t.rhs] * signs[k.out][o]);
            }
        }
    }
    for k in &mut plan.unary {
        for (o, terms) in k.outputs.iter_mut().enumerate() {
            for (a, c) in terms {
                *c = crate::orient::times(*c, signs[k.ty][*a] * signs[k.out][o]);
            }
        }
    }
    for (i, terms) in plan.norm.iter_mut().enumerate() {
        for t in terms {
            t.coef = crate::orient::times(t.coef, signs[i][t.lhs] * signs[i][t.rhs]);
        }
    }
    for k in &mut plan.actions {
        crate::orient::fold_action(k, &signs);
    }
}
