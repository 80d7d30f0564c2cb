//! Constrained kernels in generated code. For a type declared `where unit` that is a versor
//! type, every action on another non-full type feeds the type's one unit-action family,
//! `UnitAction::{sandwich_unit, apply_unit}` (`unit::pair_items`): the reduced kernel
//! is emitted there when it needs fewer multiplications than the structural one, and its proof
//! (which components of the full product vanish) goes into the impl's rustdoc. For a type
//! declared `where null` or `where simple`, its square `square_<kind>(&self)` = `self self` is
//! an inherent method, emitted only when the constraint changes something (fewer
//! multiplications or proven-vanishing outputs); its output type is the smallest declared type
//! holding the non-vanishing outputs, and its rustdoc states the constraint it relies on.
//!
//! The square's name carries the constraint (`square_simple`) so it never clashes with a
//! hand-designed kernel of the emitter.

use super::{ConstrainedKernel, ConstraintError, ConstraintKind, smallest_type, table};
use crate::ModuleSpec;
use crate::emit::Names;
use crate::plan::Plan;
use crate::versor::is_versor_type;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// What a constrained kernel computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KernelOp {
    /// `rev(S) x S` (the module's `sandwich`).
    Sandwich,
    /// `S x rev(S)` (the module's `apply`).
    Apply,
    /// `x x` (left and right are the same value).
    Square,
}

impl KernelOp {
    /// `sandwich`, `apply` or `square`.
    ///
    /// ```
    /// assert_eq!(algebra_codegen::constraint::KernelOp::Square.name(), "square");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            KernelOp::Sandwich => "sandwich",
            KernelOp::Apply => "apply",
            KernelOp::Square => "square",
        }
    }
}

/// One constrained kernel of a module: the operation and its two type indices (equal for
/// [`KernelOp::Square`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Request {
    /// The operation.
    pub op: KernelOp,
    /// The versor (or squared) type.
    pub left: usize,
    /// The operand type.
    pub right: usize,
}

/// The constrained kernels a module's declared constraints call for (`full`: the index of the
/// module's full type, never an operand).
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::ModuleSpec;
/// use algebra_codegen::constraint::{KernelOp, Request, requests};
/// let alg = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Motor=even where unit;Line=grade2 where simple;Full=all", &alg).unwrap();
/// let spec = ModuleSpec::new("pga3", alg.metric().clone(), Basis::Blade, types).unwrap();
/// let r = requests(&spec, 2);
/// assert!(r.contains(&Request { op: KernelOp::Sandwich, left: 0, right: 1 }));
/// assert!(r.contains(&Request { op: KernelOp::Square, left: 1, right: 1 }));
/// assert_eq!(r.len(), 5); // sandwich and apply on Motor and Line, the square of Line
/// ```
pub fn requests(spec: &ModuleSpec, full: usize) -> Vec<Request> {
    let mut out = Vec::new();
    for (v, t) in spec.types.iter().enumerate() {
        match t.constraint {
            Some(ConstraintKind::Unit) if is_versor_type(spec, full, v) => {
                for right in (0..spec.types.len()).filter(|&x| x != full) {
                    for op in [KernelOp::Sandwich, KernelOp::Apply] {
                        out.push(Request { op, left: v, right });
                    }
                }
            }
            Some(ConstraintKind::Null | ConstraintKind::Simple) if v != full => {
                out.push(Request { op: KernelOp::Square, left: v, right: v });
            }
            _ => {}
        }
    }
    out
}

/// The reduced kernel of a request: from the precomputed [`table`], else computed (with the
/// `constraints` feature), else [`ConstraintError::NotPrecomputed`].
///
/// # Errors
/// As `constrained_action` (feature `constraints`), plus the two table errors.
pub fn kernel(spec: &ModuleSpec, r: Request) -> Result<ConstrainedKernel, ConstraintError> {
    match table::lookup(table::PRECOMPUTED, &table::key(spec, r))? {
        Some(mut k) => {
            finish(spec, r, &mut k);
            Ok(k)
        }
        None => compute(spec, r),
    }
}

/// Fills in a table kernel's spec-dependent fields as the reduction does.
fn finish(spec: &ModuleSpec, r: Request, k: &mut ConstrainedKernel) {
    (k.left, k.right) = (r.left, r.right);
    let mut tys = vec![r.left, r.right];
    tys.sort_unstable();
    tys.dedup();
    k.relies_on = tys
        .iter()
        .filter_map(|&t| spec.types[t].constraint.map(|c| format!("{}: {}", spec.types[t].name, c)))
        .collect();
    let kept: Vec<u32> = k.outputs.iter().map(|o| o.0).collect();
    k.output_type = smallest_type(spec, &kept);
    k.full.output_type = smallest_type(spec, &k.full.masks);
}

/// Computes a request's kernel with the Gröbner reduction (every declared constraint used).
///
/// # Errors
/// As [`super::constrained_action`].
#[cfg(feature = "constraints")]
pub fn compute(spec: &ModuleSpec, r: Request) -> Result<ConstrainedKernel, ConstraintError> {
    use crate::versor::Convention;
    let constraints: Vec<super::Constraint> = spec
        .types
        .iter()
        .enumerate()
        .filter_map(|(ty, t)| t.constraint.map(|kind| super::Constraint { ty, kind }))
        .collect();
    match r.op {
        KernelOp::Sandwich => super::constrained_action(spec, Convention::Sandwich, r.left, r.right, &constraints),
        KernelOp::Apply => super::constrained_action(spec, Convention::Apply, r.left, r.right, &constraints),
        KernelOp::Square => super::reduce::constrained_square(spec, r.left, &constraints),
    }
}

/// Without the `constraints` feature a kernel missing from the table is an error naming it.
///
/// # Errors
/// Always [`ConstraintError::NotPrecomputed`].
#[cfg(not(feature = "constraints"))]
pub fn compute(spec: &ModuleSpec, r: Request) -> Result<ConstrainedKernel, ConstraintError> {
    let (l, x) = (&spec.types[r.left].name, &spec.types[r.right].name);
    Err(ConstraintError::NotPrecomputed(format!("`{}` of {l} on {x} (key `{}`)", r.op.name(), table::key(spec, r))))
}

/// Whether the constraint changes the kernel (and a declared type holds its output).
fn worth_a_method(k: &ConstrainedKernel) -> bool {
    !k.outputs.is_empty() && k.output_type.is_some() && (k.stats().mul < k.full.stats().mul || !k.vanishing.is_empty())
}

/// The method name of a request (`sandwich_unit` and `apply_unit` are `UnitAction`'s).
pub fn method_name(spec: &ModuleSpec, r: Request) -> String {
    match r.op {
        KernelOp::Sandwich => "sandwich_unit".to_string(),
        KernelOp::Apply => "apply_unit".to_string(),
        KernelOp::Square => {
            format!("square_{}", spec.types[r.left].constraint.map_or("constrained", |c| c.keyword()))
        }
    }
}

/// The module's items that read reduced kernels: the `UnitAction` impls of every `where unit`
/// versor type (each convention the cheaper kernel, the proof in the rustdoc) and the square
/// methods of `where null` / `where simple` types.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, constraint::methods};
/// let alg = Algebra::builtin("cga-null").unwrap();
/// let types = ModuleSpec::parse_types("Vector=grade1;Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf where unit;Multivector=all", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("cga_null", alg.metric().clone(), Basis::Product, types).unwrap()).unwrap();
/// // precomputed (the predefined module): no GMP needed
/// let code = methods(&plan).unwrap().to_string();
/// assert!(code.contains("UnitAction < Vector < T >> for Motor < T >"));
/// assert!(code.contains("fn sandwich_unit (& self , x : & Vector < T >) -> Vector < T >"));
/// assert!(code.contains("Proven (ideal membership): on a unit `Motor` the action on a `Vector` is a `Vector`"));
/// ```
///
/// # Errors
/// As [`kernel`].
pub fn methods(plan: &Plan) -> Result<TokenStream, ConstraintError> {
    let spec = &plan.spec;
    let names = Names::new(plan);
    let mut items = Vec::new();
    let mut actions: Vec<(Request, ConstrainedKernel)> = Vec::new();
    for r in requests(spec, plan.full) {
        let k = kernel(spec, r)?;
        match r.op {
            KernelOp::Square if worth_a_method(&k) => items.push(method(spec, &names, r, &k)),
            KernelOp::Square => {}
            KernelOp::Sandwich | KernelOp::Apply => actions.push((r, k)),
        }
    }
    // the unit actions of a `where unit` type: one `UnitAction` impl per pair, each
    // convention the cheaper of the structural and the reduced kernel
    for pair in actions.chunks(2) {
        let [(r, sandwich), (_, apply)] = pair else { unreachable!("requests come in sandwich/apply pairs") };
        let unit = crate::unit::pair_items(spec, &names, r.left, r.right, [sandwich, apply])
            .map_err(|e| ConstraintError::CoefficientTooLarge(e.to_string()))?;
        items.push(unit);
    }
    Ok(quote!(#(#items)*))
}

fn method(spec: &ModuleSpec, names: &Names, r: Request, k: &ConstrainedKernel) -> TokenStream {
    let out = k.output_type.expect("checked by worth_a_method");
    let (vt, ot) = (&names.types[r.left], &names.types[out]);
    let (vn, on) = (&spec.types[r.left].name, &spec.types[out].name);
    let what = format!(
        " The square `self self` of a `{vn}` declared `where {}`, proven to be a `{on}`.",
        spec.types[r.left].constraint.map_or("", |c| c.keyword())
    );
    let doc = std::iter::once(what).chain(k.doc());
    let name = format_ident!("{}", method_name(spec, r));
    let body = typed_body(names, r, k, out);
    quote! {
        impl<T: ::algebra_core::Ring> #vt<T> {
            #(#[doc = #doc])*
            pub fn #name(&self) -> #ot<T> {
                #body
            }
        }
    }
}

/// The statements of a method computing `k` (inputs `self` and, unless a square, `x`) into
/// the declared type `out`, whose elements hold every computed output of `k`.
pub(crate) fn typed_body(names: &Names, r: Request, k: &ConstrainedKernel, out: usize) -> TokenStream {
    let ot = &names.types[out];
    let load = |t: usize, var: TokenStream| -> Vec<TokenStream> {
        names.fields[t].iter().zip(&names.signs[t]).map(|(f, &s)| Names::signed(quote!(#var.#f), s)).collect()
    };
    let a = load(r.left, quote!(self));
    let outs: Vec<_> = (0..k.outputs.len()).map(|i| format_ident!("o{}", i)).collect();
    let fields = names.fields[out].iter().zip(&names.masks[out]).zip(&names.signs[out]).map(|((f, m), &s)| {
        match k.outputs.iter().position(|o| o.0 == *m) {
            Some(i) if s < 0 => {
                let o = &outs[i];
                quote!(#f: ::algebra_core::Ring::neg_ref(&#o))
            }
            Some(i) => {
                let o = &outs[i];
                quote!(#f: #o)
            }
            None => quote!(#f: T::zero()),
        }
    });
    let body = k.body();
    let load_b = match r.op {
        KernelOp::Square => quote!(),
        _ => {
            let b = load(r.right, quote!(x));
            quote!(let b = [#(#b),*];)
        }
    };
    quote! {
        let a = [#(#a),*];
        #load_b
        let [#(#outs),*] = #body;
        #ot { #(#fields),* }
    }
}
