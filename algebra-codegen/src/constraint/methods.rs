//! Constrained kernels as generated methods on the constrained type. For a type declared
//! `where unit` that is a versor type, every action on another non-full type:
//! `sandwich_unit_<operand>(&self, x)` = `rev(self) x self` and `apply_unit_<operand>(&self, x)`
//! = `self x rev(self)`; for a type declared `where null` or `where simple`, its square
//! `square_<kind>(&self)` = `self self`. A method is emitted only when the constraint changes
//! something (fewer multiplications or proven-vanishing outputs), its output type is the
//! smallest declared type holding the non-vanishing outputs, and its rustdoc states the
//! constraint it relies on.
//!
//! The names carry the constraint (`sandwich_unit_vector`) so they never clash with the
//! generic `sandwich`/`apply` or a hand-designed kernel of the emitter.

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

/// The method name of a request.
pub fn method_name(spec: &ModuleSpec, r: Request) -> String {
    let snake = crate::emit::snake(&spec.types[r.right].name);
    match r.op {
        KernelOp::Sandwich => format!("sandwich_unit_{snake}"),
        KernelOp::Apply => format!("apply_unit_{snake}"),
        KernelOp::Square => {
            format!("square_{}", spec.types[r.left].constraint.map_or("constrained", |c| c.keyword()))
        }
    }
}

/// Every constrained method of a module (an `impl` block per kernel), for the module's items.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, constraint::methods};
/// let alg = Algebra::builtin("cga-null").unwrap();
/// let types = ModuleSpec::parse_types("Vector=grade1;Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf where unit;Multivector=all", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("cga_null", alg.metric().clone(), Basis::Product, types).unwrap()).unwrap();
/// // precomputed (the predefined module): no GMP needed
/// let code = methods(&plan).unwrap().to_string();
/// assert!(code.contains("fn sandwich_unit_vector (& self , x : & Vector < T >) -> Vector < T >"));
/// ```
///
/// # Errors
/// As [`kernel`].
pub fn methods(plan: &Plan) -> Result<TokenStream, ConstraintError> {
    let spec = &plan.spec;
    let names = Names::new(plan);
    let mut items = Vec::new();
    for r in requests(spec, plan.full) {
        let k = kernel(spec, r)?;
        if worth_a_method(&k) {
            items.push(method(spec, &names, r, &k));
        }
    }
    Ok(quote!(#(#items)*))
}

fn method(spec: &ModuleSpec, names: &Names, r: Request, k: &ConstrainedKernel) -> TokenStream {
    let out = k.output_type.expect("checked by worth_a_method");
    let (vt, xt, ot) = (&names.types[r.left], &names.types[r.right], &names.types[out]);
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
    let (vn, xn, on) = (&spec.types[r.left].name, &spec.types[r.right].name, &spec.types[out].name);
    let what = match r.op {
        KernelOp::Sandwich => {
            format!(" The action `rev(self) x self` of a unit `{vn}` on a `{xn}`, proven to be a `{on}`.")
        }
        KernelOp::Apply => {
            format!(" The action `self x rev(self)` of a unit `{vn}` on a `{xn}`, proven to be a `{on}`.")
        }
        KernelOp::Square => format!(
            " The square `self self` of a `{vn}` declared `where {}`, proven to be a `{on}`.",
            spec.types[r.left].constraint.map_or("", |c| c.keyword())
        ),
    };
    let doc = std::iter::once(what).chain(k.doc());
    let name = format_ident!("{}", method_name(spec, r));
    let body = k.body();
    let (params, load_b) = match r.op {
        KernelOp::Square => (quote!(&self), quote!()),
        _ => {
            let b = load(r.right, quote!(x));
            (quote!(&self, x: &#xt<T>), quote!(let b = [#(#b),*];))
        }
    };
    quote! {
        impl<T: ::algebra_core::Ring> #vt<T> {
            #(#[doc = #doc])*
            pub fn #name(#params) -> #ot<T> {
                let a = [#(#a),*];
                #load_b
                let [#(#outs),*] = #body;
                #ot { #(#fields),* }
            }
        }
    }
}
