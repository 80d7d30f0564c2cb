//! `gam codegen --standalone`: a module source with no dependency at all. The emitted items
//! are kept except the runtime bridge (the `algebra()` instance, `BASIS`, conversions to and
//! from `Multivector`, and the inverse of types that are not subalgebras, which goes through
//! the runtime); every `::algebra_core` path is pointed at items appended to the file: the
//! product traits, `Ring`/`Field` reduced to the methods kernels call, the solver and
//! `join_terms`, all
//! parsed from algebra-core's own sources ([`algebra_core::sources`]), then
//! `standalone/support.rs` (`f32`/`f64` impls, `MvError`, `format_term`).

use crate::paths::{join_path, map_engine_paths};
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::{ToTokens, quote};
use syn::parse_quote;

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
    file.items.extend(shared_items()?);
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
    [
        "self :: Multivector",
        "self :: Algebra",
        "self :: Metric",
        "self :: Basis",
        "self :: Symbolic",
        ". to_multivector (",
    ]
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
            // the closed forms need `Real` and `algebra_core::closed_form`, not inlined
            if imp.generics.to_token_stream().to_string().contains("self :: Real") {
                return false;
            }
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

/// The `Ring` methods kept in the standalone file (what kernels, `inverse` and printing call).
const RING_METHODS: [&str; 14] = [
    "zero",
    "one",
    "from_ratio",
    "is_exact_zero",
    "magnitude",
    "relative_epsilon",
    "cmp_magnitude",
    "is_negligible",
    "add_ref",
    "sub_ref",
    "mul_ref",
    "neg_ref",
    "add_assign_ref",
    "sub_assign_ref",
];

/// The `Field` methods kept.
const FIELD_METHODS: [&str; 2] = ["try_recip", "div_ref"];

/// Replaces an item's doc comments (whose examples name algebra-core) by `doc`.
fn set_doc(attrs: &mut Vec<syn::Attribute>, doc: &str) {
    attrs.retain(|a| !a.path().is_ident("doc"));
    attrs.insert(0, parse_quote!(#[doc = #doc]));
}

/// The product traits, `Ring` and `Field` reduced to [`RING_METHODS`] and [`FIELD_METHODS`],
/// the solver and `join_terms`, from algebra-core's sources.
fn shared_items() -> syn::Result<Vec<syn::Item>> {
    let mut items: Vec<syn::Item> = syn::parse_str::<syn::File>(algebra_core::sources::OPS)?
        .items
        .into_iter()
        .filter(|it| matches!(it, syn::Item::Trait(_)))
        .collect();
    for item in syn::parse_str::<syn::File>(algebra_core::sources::SCALAR)?.items {
        let syn::Item::Trait(mut t) = item else { continue };
        let keep: &[&str] = match t.ident.to_string().as_str() {
            "Ring" => &RING_METHODS,
            "Field" => &FIELD_METHODS,
            _ => continue,
        };
        t.items.retain(|m| matches!(m, syn::TraitItem::Fn(f) if keep.iter().any(|k| f.sig.ident == k)));
        // the methods' doc examples name algebra-core: keep one line pointing at the original
        for m in &mut t.items {
            if let syn::TraitItem::Fn(f) = m {
                set_doc(&mut f.attrs, &format!(" algebra-core's `{}::{}`.", t.ident, f.sig.ident));
            }
        }
        let doc = format!(
            " algebra-core's `{}`, reduced to the methods the kernels call; implemented below for `f32` and `f64`.",
            t.ident
        );
        set_doc(&mut t.attrs, &doc);
        items.push(syn::Item::Trait(t));
    }
    let functions = [
        (
            algebra_core::sources::LINALG,
            "solve",
            " Solves `l y = rhs` (algebra-core's `linalg::solve`); `None` when singular.",
        ),
        (algebra_core::sources::DISPLAY, "join_terms", " Terms joined with ` + ` / ` - `; `0` when there are none."),
    ];
    for (source, name, doc) in functions {
        for item in syn::parse_str::<syn::File>(source)?.items {
            let syn::Item::Fn(mut f) = item else { continue };
            if f.sig.ident == name {
                set_doc(&mut f.attrs, doc);
                f.vis = syn::Visibility::Inherited;
                items.push(syn::Item::Fn(f));
            }
        }
    }
    Ok(items)
}
