//! `gam codegen --standalone`: a module source with no dependency at all. The emitted items
//! are kept except the runtime bridge (the `algebra()` instance, `BASIS`, conversions to and
//! from `Multivector`, and the inverse of types that are not subalgebras, which goes through
//! the runtime); every `::algebra_core` path is pointed at the items of
//! `standalone/support.rs` (the scalar traits for `f32`/`f64`, the product traits, a small
//! solver and the printing helpers), which are appended to the file.

use crate::paths::{join_path, map_engine_paths};
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::{ToTokens, quote};

/// The inlined support items (parsed once per call).
const SUPPORT: &str = include_str!("standalone/support.rs");

/// algebra-core modules whose items the support file provides at its top level.
const FLATTENED: [&str; 4] = ["ops", "multivector", "display", "linalg"];

/// The lints the generated code allows (the same as the `algebra!` macro's module), plus
/// `dead_code` for kernels a user does not call.
fn allow() -> TokenStream {
    quote!(clippy::all, unused_parens, unused_mut, unused_variables, non_snake_case, dead_code)
}

/// A standalone source file for `plan`: `header` lines become the file's `//!` docs; with
/// `nest = Some(name)` the items are wrapped in `pub mod name { ... }`, otherwise they sit at
/// the top level (for `mod kernels;` with the file saved as `kernels.rs`).
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, standalone};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Vector=grade1;Rotor=even", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let file = standalone::file(&plan, &["Generated.".to_string()], None).unwrap();
/// let text = quote::ToTokens::to_token_stream(&file).to_string();
/// assert!(text.contains("pub trait Ring") && text.contains("pub struct Rotor"));
/// // no engine paths and no runtime bridge left (`Multivector` here is the generated full type)
/// assert!(!text.contains("algebra_core") && !text.contains("self :: Multivector"));
/// assert!(!text.contains("fn to_multivector") && !text.contains("fn algebra"));
/// ```
pub fn file(plan: &Plan, header: &[String], nest: Option<&str>) -> syn::Result<syn::File> {
    let items = map_engine_paths(crate::emit::module_items(plan), &|segments| {
        let skip = segments.iter().take_while(|s| FLATTENED.iter().any(|m| *s == m)).count();
        join_path(quote!(self), &segments[skip..])
    });
    let mut file: syn::File = syn::parse2(items)?;
    file.items.retain_mut(keep_item);
    let support: syn::File = syn::parse_str(SUPPORT)?;
    file.items.extend(support.items);
    let allow = allow();
    let docs = header.iter().map(|d| quote!(#![doc = #d]));
    let items = &file.items;
    let tokens = match nest {
        None => quote! {
            #(#docs)*
            #![allow(#allow)]
            #(#items)*
        },
        Some(name) => {
            let name = syn::Ident::new(name, proc_macro2::Span::call_site());
            quote! {
                #(#docs)*
                #[allow(#allow)]
                pub mod #name {
                    #(#items)*
                }
            }
        }
    };
    syn::parse2(tokens)
}

/// Whether a tokenised item uses the runtime (paths now read `self :: Multivector` etc.).
fn uses_runtime(tokens: impl ToTokens) -> bool {
    let text = tokens.to_token_stream().to_string();
    ["self :: Multivector", "self :: Algebra", "self :: Metric", "self :: Basis", ". to_multivector ("]
        .iter()
        .any(|p| text.contains(p))
}

/// Drops the runtime bridge: re-exports of engine items, `BASIS`, `algebra()`, runtime
/// conversions and methods that go through the runtime multivector.
fn keep_item(item: &mut syn::Item) -> bool {
    match item {
        syn::Item::Use(_) => false,
        syn::Item::Const(c) => c.ident != "BASIS",
        syn::Item::Fn(f) => f.sig.ident != "algebra",
        syn::Item::Impl(imp) => {
            if imp.trait_.is_none() {
                imp.items.retain(|it| !uses_runtime(it));
                !imp.items.is_empty()
            } else {
                !uses_runtime(&*imp)
            }
        }
        _ => true,
    }
}
