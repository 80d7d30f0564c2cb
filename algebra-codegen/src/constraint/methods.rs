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

use super::request::{kernel, method_name, requests, worth_a_method};
use super::{ConstrainedKernel, ConstraintError, KernelOp, Request};
use crate::ModuleSpec;
use crate::emit::Names;
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

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
    for r in requests(plan) {
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
        let unit = crate::emit::unit::pair_items(spec, &names, r.left, r.right, [sandwich, apply])
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
        impl<T: __gam_engine::Ring> #vt<T> {
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
                quote!(#f: __gam_engine::Ring::neg_ref(&#o))
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
