//! The versor action specialised to *unit* versors (`S rev(S) = 1`): the one unit-action
//! family, `UnitAction::{sandwich_unit, apply_unit}`, for every fused (versor, operand) pair.
//!
//! For a unit versor `x S rev(S) = x`, so
//!
//! - `S x rev(S) = x + (S x - x S) rev(S)` (`apply_unit`), and
//! - `rev(S) x S = x + (rev(S) x - x rev(S)) S` (`sandwich_unit`).
//!
//! The commutator `S x - x S` drops every term of `S` that commutes with `x` (the scalar
//! always, the pseudoscalar of an odd-dimensional algebra, ...), and output components whose
//! correction expands to the zero polynomial are copied from `x` (the weight of a PGA point).
//! This is the structural form of Rodrigues' `v + 2 w (q × v) + 2 q × (q × v)`: for the pose
//! on a PGA point it needs 22 multiplications instead of the general kernel's 48. Both forms
//! are identities over any ring once `S rev(S) = 1` holds exactly; for a non-unit versor the
//! result is not the action (use `apply`/`sandwich`).
//!
//! When the versor type is declared `where unit`, the pair also has a kernel reduced modulo
//! `rev(S) S = 1` ([`crate::constraint`]); each convention then takes whichever of the two term
//! lists needs fewer multiplications (the commutator form on a tie), and the impl's rustdoc
//! states what the reduction proved: whether the components of the full product outside the
//! operand type vanish on unit versors (then the result *is* the action, e.g. a unit
//! `cga_null::Motor` on a `Vector`) or not (then it is the projection onto the operand type).
//! Those impls are emitted by [`crate::constraint::methods`], which reads the reduced kernels;
//! every other pair's by this module's `module_items`.

use super::constraint::{ConstrainedKernel, ConstraintKind, KernelOp, Request, typed_body};
use super::emit::{Names, tree_sum as sum};
use super::plan::Ratio;
use super::versor::{ActionKernel, Convention, action_kernel};
use super::{CodegenError, ModuleSpec};
use algebra_core::rational::Q;
use num_traits::{One, Zero};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeMap;

/// One unit-versor action kernel: `out_j = x_j + scale · Σ_(k, a, c) c · t_k · s_a`, with
/// `t_k = Σ_(a, b, c) c · s_a · x_b` (the commutator divided by `scale`).
#[derive(Debug, Clone)]
pub struct UnitKernel {
    /// The two stages (stage 1 the scaled commutator; an empty stage-2 row means `out_j = x_j`).
    pub kernel: ActionKernel,
    /// The common factor taken out of stage 1 (2 for rotors and motors).
    pub scale: Ratio,
}

impl UnitKernel {
    /// Multiplications and additions, counted as [`ActionKernel::counts`] does plus one
    /// addition per corrected output and the scale (an addition when it is 2).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::{ModuleSpec, unit::plan_unit_actions, versor::Convention};
    /// let alg = Algebra::builtin("pga3").unwrap();
    /// let types = ModuleSpec::parse_types("Motor=even;Point=grade3", &alg).unwrap();
    /// let spec = ModuleSpec::new("pga", alg.metric().clone(), Basis::Blade, types).unwrap();
    /// let k = plan_unit_actions(&spec, usize::MAX).unwrap();
    /// let k = k.iter().find(|k| (k.kernel.versor, k.kernel.operand, k.kernel.convention) == (0, 1, Convention::Apply)).unwrap();
    /// // the general fused kernel needs 48 multiplications; the point's weight is copied
    /// assert_eq!(k.counts(), (22, 21));
    /// assert!(k.kernel.stage2[3].is_empty());
    /// ```
    pub fn counts(&self) -> (usize, usize) {
        let (m, a) = self.kernel.counts();
        let corrected = self.kernel.stage2.iter().filter(|r| !r.is_empty()).count();
        match self.scale {
            (1, 1) => (m, a + corrected),
            (2, 1) => (m, a + 2 * corrected),
            _ => (m + corrected, a + corrected),
        }
    }
}

/// The unit-versor kernels of every fused (versor type, operand type) pair of the module
/// (those [`super::versor::plan_actions`] plans), in both conventions.
pub fn plan_unit_actions(spec: &ModuleSpec, full: usize) -> Result<Vec<UnitKernel>, CodegenError> {
    let mut out = Vec::new();
    for v in (0..spec.types.len()).filter(|&v| super::versor::is_versor_type(spec, full, v)) {
        for x in (0..spec.types.len()).filter(|&x| x != full) {
            for convention in [Convention::Sandwich, Convention::Apply] {
                out.push(unit_kernel(spec, convention, v, x)?);
            }
        }
    }
    Ok(out)
}

fn q(c: Ratio) -> Q {
    Q::new(c.0.into(), c.1.into())
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 { a.abs() } else { gcd(b, a % b) }
}

fn unit_kernel(spec: &ModuleSpec, convention: Convention, v: usize, x: usize) -> Result<UnitKernel, CodegenError> {
    let mut k = action_kernel(spec, convention, v, x, true)?;
    // an output whose correction expands to zero is x's own component
    for row in &mut k.stage2 {
        let mut poly: BTreeMap<(usize, usize, usize), Q> = BTreeMap::new();
        for &(t, a, c) in row.iter() {
            for &(a1, b, c1) in &k.stage1[t] {
                *poly.entry((a.min(a1), a.max(a1), b)).or_insert_with(Q::zero) += q(c) * q(c1);
            }
        }
        if poly.values().all(Zero::is_zero) {
            row.clear();
        }
    }
    // the common factor of stage 1: gcd of the numerators over the lcm of the denominators
    let all = k.stage1.iter().flatten();
    let (num, den) = all.fold((0, 1), |(n, d), &(_, _, (cn, cd))| (gcd(n, cn), d / gcd(d, cd) * cd));
    let scale = if num == 0 { (1, 1) } else { (num, den) };
    let factor = Q::one() / q(scale);
    for row in &mut k.stage1 {
        for term in row.iter_mut() {
            let c = q(term.2) * &factor;
            term.2 = super::plan::to_ratio(&c)?;
        }
    }
    // the fields of renamed blades (`e31`, `e021`) hold the coefficient in their orientation
    let signs: Vec<Vec<i64>> = spec.types.iter().map(super::orient::field_signs).collect();
    super::orient::fold_action(&mut k, &signs);
    Ok(UnitKernel { kernel: k, scale })
}

/// The `UnitAction` impl of one (versor, operand) pair, from its two unit kernels; `proofs`
/// are the reduced kernels of the pair (sandwich, apply) when the versor type is declared
/// `where unit`.
fn unit_items(
    spec: &ModuleSpec,
    names: &Names,
    sandwich: &UnitKernel,
    apply: &UnitKernel,
    proofs: [Option<&ConstrainedKernel>; 2],
) -> TokenStream {
    let (v, x) = (sandwich.kernel.versor, sandwich.kernel.operand);
    let (vt, xt) = (&names.types[v], &names.types[x]);
    let large = |u: &UnitKernel| {
        super::size::is_large(names.table_above, u.kernel.stage1.iter().chain(&u.kernel.stage2).map(Vec::len))
    };
    let body = |u: &UnitKernel, proof: Option<&ConstrainedKernel>, op: KernelOp, general: TokenStream| match proof
        .filter(|k| reduced_is_cheaper(spec, u, k))
    {
        Some(k) => typed_body(names, Request { op, left: v, right: x }, k, x),
        None if large(u) => quote!(::algebra_core::ops::#general(self, x)),
        None => unrolled_body(names, u),
    };
    let s_body = body(sandwich, proofs[0], KernelOp::Sandwich, quote!(Sandwich::sandwich));
    let a_body = body(apply, proofs[1], KernelOp::Apply, quote!(Apply::apply));
    let s_doc = doc_lines(spec, "`rev(self) x self` for a unit `self`", sandwich, proofs[0]);
    let a_doc = doc_lines(spec, "`self x rev(self)` for a unit `self`", apply, proofs[1]);
    quote! {
        impl<T: ::algebra_core::Ring> ::algebra_core::ops::UnitAction<#xt<T>> for #vt<T> {
            #(#[doc = #s_doc])*
            #[inline]
            fn sandwich_unit(&self, x: &#xt<T>) -> #xt<T> {
                #s_body
            }
            #(#[doc = #a_doc])*
            #[inline]
            fn apply_unit(&self, x: &#xt<T>) -> #xt<T> {
                #a_body
            }
        }
    }
}

/// Whether the reduced kernel `k` replaces the structural one: strictly fewer multiplications,
/// and every output it computes is a component of the operand type.
fn reduced_is_cheaper(spec: &ModuleSpec, u: &UnitKernel, k: &ConstrainedKernel) -> bool {
    let xm = &spec.types[u.kernel.operand].elements;
    k.stats().mul < u.counts().0 && k.outputs.iter().all(|(m, _)| xm.contains(m))
}

/// The rustdoc of one unit action: what it computes, which kernel, and what is proven about
/// the components outside the operand type.
fn doc_lines(spec: &ModuleSpec, what: &str, u: &UnitKernel, proof: Option<&ConstrainedKernel>) -> Vec<String> {
    let (vn, xn) = (&spec.types[u.kernel.versor].name, &spec.types[u.kernel.operand].name);
    let xm = &spec.types[u.kernel.operand].elements;
    let mut lines = vec![format!(
        " {what}: assumes `self rev(self) = 1`; for any other `self` the result is not the action (use `sandwich`/`apply`)."
    )];
    let (mu, _) = u.counts();
    match proof {
        Some(k) => {
            let (mk, mf) = (k.stats().mul, k.full.stats().mul);
            let kernel = if reduced_is_cheaper(spec, u, k) {
                format!(" The kernel reduced modulo `rev(x) x = 1`: {mk} multiplications (the commutator form: {mu}).")
            } else {
                format!(
                    " The commutator form `x + (L x - x L) R`: {mu} multiplications (reduced modulo `rev(x) x = 1`: {mk}; the unconstrained product: {mf})."
                )
            };
            lines.push(kernel);
            let outside = k.outputs.iter().filter(|(m, _)| !xm.contains(m)).count();
            let vanish = k.vanishing.iter().filter(|m| !xm.contains(m)).count();
            lines.push(match (outside, vanish) {
                (0, 0) => format!(" Every component of the full product is a `{xn}` component."),
                (0, n) => format!(
                    " Proven (ideal membership): on a unit `{vn}` the action on a `{xn}` is a `{xn}`; the {n} component(s) of the full product outside `{xn}` vanish."
                ),
                (n, _) => format!(
                    " Not a `{xn}` in general: {n} component(s) outside `{xn}` do not vanish under `rev(x) x = 1`; this is the projection onto `{xn}`."
                ),
            });
        }
        None => {
            lines.push(format!(" The commutator form `x + (L x - x L) R`: {mu} multiplications."));
            let k = &u.kernel;
            let outside = action_kernel(spec, k.convention, k.versor, k.operand, false).map(|g| g.outside.len());
            lines.push(match outside {
                Ok(0) => format!(" Every component of the full product is a `{xn}` component: this is the whole action."),
                n => format!(
                    " The full product has {} component(s) outside `{xn}`, dropped here: they vanish for versors (products of invertible vectors), which is assumed; declaring `{vn}` `where unit` proves or refutes it for unit ones.",
                    n.map_or_else(|_| "some".to_string(), |n| n.to_string())
                ),
            });
        }
    }
    lines
}

/// The `UnitAction` impl of the pair (`v` a versor type declared `where unit`, `x` an operand
/// type) given the pair's two reduced kernels (sandwich, apply): each convention takes the
/// cheaper of the commutator form and the reduced kernel, and the rustdoc states what the
/// reduction proved. Emitted by [`crate::constraint::methods`], which reads the reduced kernels.
///
/// # Errors
/// A coefficient of the commutator form does not fit `i64/i64`.
pub(crate) fn pair_items(
    spec: &ModuleSpec,
    names: &Names,
    v: usize,
    x: usize,
    proofs: [&ConstrainedKernel; 2],
) -> Result<TokenStream, CodegenError> {
    let sandwich = unit_kernel(spec, Convention::Sandwich, v, x)?;
    let apply = unit_kernel(spec, Convention::Apply, v, x)?;
    Ok(unit_items(spec, names, &sandwich, &apply, proofs.map(Some)))
}

/// Straight-line code: the scaled commutator, then `x_j + scale · correction_j`.
fn unrolled_body(names: &Names, u: &UnitKernel) -> TokenStream {
    let k = &u.kernel;
    let (xt, vf, xf) = (&names.types[k.operand], &names.fields[k.versor], &names.fields[k.operand]);
    let binds = super::versor::stage1_binds(names, k);
    let outs = k.stage2.iter().zip(xf).map(|(terms, f)| {
        if terms.is_empty() {
            return quote!(::core::clone::Clone::clone(&x.#f));
        }
        let y = sum(terms
            .iter()
            .map(|&(i, a, c)| {
                let (ti, fa) = (format_ident!("t{}", i), &vf[a]);
                (c, quote!((#ti.mul_ref(&self.#fa))), true)
            })
            .collect());
        match u.scale {
            (1, 1) => quote!({ x.#f.add_ref(&(#y)) }),
            (2, 1) => quote!({ let y = #y; x.#f.add_ref(&y) + &y }),
            (n, d) => quote!({ x.#f.add_ref(&(T::from_ratio(#n, #d) * &(#y))) }),
        }
    });
    quote! {
        #(#binds)*
        #xt { #(#xf: #outs),* }
    }
}

/// Every `UnitAction` impl of the module (one per fused pair) except those of a versor type
/// declared `where unit`, which [`crate::constraint::methods`] emits with the reduced kernels.
pub(super) fn module_items(plan: &super::plan::Plan, names: &Names) -> TokenStream {
    let kernels = match plan_unit_actions(&plan.spec, plan.full) {
        Ok(k) => k,
        Err(e) => {
            let msg = e.to_string();
            return quote!(compile_error!(#msg););
        }
    };
    // a `where unit` type's impls come with its reduced kernels ([`pair_items`])
    let declared = |v: usize| plan.spec.types[v].constraint == Some(ConstraintKind::Unit);
    let items = kernels
        .chunks(2)
        .filter(|pair| !declared(pair[0].kernel.versor))
        .map(|pair| unit_items(&plan.spec, names, &pair[0], &pair[1], [None, None]));
    quote!(#(#items)*)
}
