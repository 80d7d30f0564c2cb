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
use std::collections::BTreeSet;
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
    file_with(plan, header, nest, &Selection::default())
}

/// Which kernels a standalone file keeps (`gam codegen --standalone --ops ... [--every-type]`).
/// Every type keeps its struct and value methods; the selection applies to the product and
/// action impls.
#[derive(Debug, Clone, Default)]
pub struct Selection {
    /// Only the operations named here ([`STANDALONE_OPS`]: the products `gp`, `op`, `lc`, `rc`,
    /// `sp`, `regressive`, `commutator`, `anticommutator`; `gp_into`, the output-typed
    /// geometric products; the actions `sandwich`, `apply`, `sandwich_unit`, `apply_unit` and
    /// `matrix`, their matrix form), the actions of every versor type; `None`: [`DEFAULT_OPS`]
    /// (the geometric product, `apply` and `apply_unit`), the actions of the kinematic versor
    /// types only (see [`is_kinematic`]).
    pub ops: Option<BTreeSet<String>>,
    /// Also the kernels taking the types the plan adds (automatic `Even`/`Odd`, the full
    /// multivector), the actions composed of two full products and, without `ops`, the actions
    /// of every versor type; by default only kernels among the declared types.
    pub every_type: bool,
}

/// The operations a standalone file can select.
pub const STANDALONE_OPS: [&str; 14] = [
    "gp",
    "op",
    "lc",
    "rc",
    "sp",
    "regressive",
    "commutator",
    "anticommutator",
    "gp_into",
    "sandwich",
    "apply",
    "sandwich_unit",
    "apply_unit",
    "matrix",
];

/// The operations of a standalone file without `--ops`: the geometric product and the action
/// `x ↦ V x rev(V)` in its two forms, `apply` (exact for any `V`) and `apply_unit` (the fused
/// form for unit `V`), of the kinematic versor types ([`is_kinematic`]) on every declared type.
pub const DEFAULT_OPS: [&str; 3] = ["gp", "apply", "apply_unit"];

/// Whether a type is a kinematic versor type (a motor or rotor): every basis element even, and
/// the scalar `1` among them (so it holds the identity motion). The default standalone file
/// keeps the actions of these types only; bivector types (`Line`) and odd versors
/// (reflections in planes, point reflections) act through `--ops` or `--every-type`.
pub fn is_kinematic(elements: &[u32]) -> bool {
    elements.contains(&0) && elements.iter().all(|m| m.count_ones() % 2 == 0)
}

impl Selection {
    /// Whether the actions of the versor type `versor` are kept: those of every versor type
    /// when `ops` is given or with `every_type`, else those of the `kinematic` types.
    fn acts(&self, versor: &str, kinematic: &[&str]) -> bool {
        self.ops.is_some() || self.every_type || kinematic.contains(&versor)
    }

    fn keeps(&self, op: &str) -> bool {
        let named = |o: &str| match &self.ops {
            None => DEFAULT_OPS.contains(&o),
            Some(ops) => ops.contains(o),
        };
        match op {
            "unit" => named("sandwich_unit") || named("apply_unit"),
            op => named(op),
        }
    }
}

/// [`file()`] keeping the kernels of `selection` only.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, standalone::{Selection, file_with}};
/// let alg = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Motor=even;Point=grade3", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("pga", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let text = |s: &Selection| quote::ToTokens::to_token_stream(&file_with(&plan, &[], None, s).unwrap()).to_string();
/// let only_gp = text(&Selection { ops: Some(["gp".to_string()].into()), every_type: false });
/// assert!(only_gp.contains("GeometricProduct < Point < T > > for Motor < T >"));
/// assert!(!only_gp.contains("OuterProduct < Point < T > > for Motor < T >"));
/// assert!(!only_gp.contains("GeometricProduct < Multivector < T > > for Multivector < T >"));
/// assert!(!only_gp.contains("self :: Apply < Point < T > > for Motor < T >"));
/// // the default: the geometric product, and `apply`/`apply_unit` of the motor (the
/// // kinematic versor type) on the declared types
/// let default = text(&Selection::default());
/// assert!(default.contains("self :: UnitAction < Point < T > > for Motor < T >"));
/// assert!(default.contains("self :: Apply < Point < T > > for Motor < T >"));
/// assert!(!default.contains("self :: Sandwich < Point < T > > for Motor < T >"));
/// assert!(!default.contains("self :: Apply < Motor < T > > for Point < T >"));
/// assert!(!default.contains("fn sandwich_unit"));
/// assert!(!default.contains("self :: OuterProduct < Point < T > > for Motor < T >"));
/// assert!(!default.contains("ActionMatrix < Point"));
/// ```
pub fn file_with(plan: &Plan, header: &[String], nest: Option<&str>, selection: &Selection) -> syn::Result<syn::File> {
    let items = map_engine_paths(crate::emit::module_items(plan), &|segments| {
        let skip = segments.iter().take_while(|s| FLATTENED.iter().any(|m| *s == m)).count();
        join_path(quote!(self), &segments[skip..])
    });
    let mut file: syn::File = syn::parse2(items)?;
    file.items.retain_mut(keep_item);
    // the named constructors need the engine's `Real` and error helpers: not vendored
    file.items.retain(|item| !matches!(item, syn::Item::Fn(f) if crate::named::is_named(&f.sig.ident.to_string())));
    let types: Vec<&str> = plan.spec.types.iter().map(|t| t.name.as_str()).collect();
    let declared = &types[..plan.declared];
    let kinematic: Vec<&str> =
        (0..plan.declared).filter(|&i| is_kinematic(&plan.spec.types[i].elements)).map(|i| types[i]).collect();
    file.items = select(std::mem::take(&mut file.items), &types, declared, &kinematic, selection);
    if !selection.every_type {
        file.items = prune(std::mem::take(&mut file.items), &types, declared);
    }
    drop_dead_dispatch(&mut file.items);
    let closed = file.items.iter().any(|it| it.to_token_stream().to_string().contains("self :: closed_form ::"));
    file.items.extend(shared_items(closed, selection)?);
    let support: syn::File = syn::parse_str(SUPPORT)?;
    file.items.extend(support.items);
    if closed {
        file.items.extend(real_impls());
    }
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

/// The name a type is written with (`Motor` for `Motor<T>` and `&Motor<T>`).
fn type_name(ty: &syn::Type) -> Option<String> {
    match ty {
        syn::Type::Reference(r) => type_name(&r.elem),
        syn::Type::Path(p) => p.path.segments.last().map(|s| s.ident.to_string()),
        _ => None,
    }
}

/// The operation of a kernel trait (the product traits and their operators, the actions).
fn operation(trait_name: &str) -> Option<&'static str> {
    Some(match trait_name {
        "GeometricProduct" | "Mul" => "gp",
        "GeometricProductInto" => "gp_into",
        "OuterProduct" | "BitXor" => "op",
        "LeftContraction" | "BitOr" => "lc",
        "RightContraction" => "rc",
        "ScalarProduct" => "sp",
        "RegressiveProduct" | "BitAnd" => "regressive",
        "CommutatorProduct" => "commutator",
        "AnticommutatorProduct" => "anticommutator",
        "Sandwich" => "sandwich",
        "Apply" => "apply",
        "UnitAction" => "unit",
        "ActionMatrix" => "matrix",
        _ => return None,
    })
}

/// A kernel impl: its operation and its (self, right-hand) types; `None` for other items and
/// for `Mul<T>` (scaling by a scalar).
fn kernel_impl(item: &syn::Item, types: &[&str]) -> Option<(&'static str, String, String)> {
    let syn::Item::Impl(imp) = item else { return None };
    let (_, path, _) = imp.trait_.as_ref()?;
    let last = path.segments.last()?;
    let op = operation(&last.ident.to_string())?;
    let rhs = match &last.arguments {
        syn::PathArguments::AngleBracketed(a) => a.args.iter().find_map(|g| match g {
            syn::GenericArgument::Type(t) => type_name(t),
            _ => None,
        }),
        _ => None,
    }?;
    types.contains(&rhs.as_str()).then_some((op, type_name(&imp.self_ty)?, rhs))
}

/// The items that survive the selection: every item but the kernel impls, and the kernel
/// impls of selected operations between selected types (actions: of selected versor types,
/// [`Selection::acts`]); a `UnitAction` impl keeps the selected one of its two methods. A unit
/// action above the size threshold calls the general one of its pair, which then stays too.
fn select(
    mut items: Vec<syn::Item>,
    types: &[&str],
    declared: &[&str],
    kinematic: &[&str],
    selection: &Selection,
) -> Vec<syn::Item> {
    let among = |l: &str, r: &str| selection.every_type || (declared.contains(&l) && declared.contains(&r));
    for item in &mut items {
        if let Some(("unit", _, _)) = kernel_impl(item, types)
            && let syn::Item::Impl(imp) = item
        {
            imp.items.retain(|it| !matches!(it, syn::ImplItem::Fn(f) if !selection.keeps(&f.sig.ident.to_string())));
        }
    }
    let mut needed: BTreeSet<(&'static str, String, String)> = BTreeSet::new();
    for item in &items {
        if let Some(("unit", l, r)) = kernel_impl(item, types)
            && selection.keeps("unit")
            && among(&l, &r)
            && selection.acts(&l, kinematic)
        {
            let text = item.to_token_stream().to_string();
            for (general, call) in [("apply", "Apply :: apply"), ("sandwich", "Sandwich :: sandwich")] {
                if text.contains(call) {
                    needed.insert((general, l.clone(), r.clone()));
                }
            }
        }
    }
    items
        .into_iter()
        .filter(|item| {
            let Some((op, l, r)) = kernel_impl(item, types) else { return true };
            // an action composed of two full products goes through types the plan added
            if matches!(op, "sandwich" | "apply")
                && item.to_token_stream().to_string().contains("GeometricProduct :: gp")
            {
                return selection.every_type && selection.keeps("gp") && selection.keeps(op);
            }
            let acts = !matches!(op, "sandwich" | "apply" | "unit" | "matrix") || selection.acts(&l, kinematic);
            (among(&l, &r) && acts && selection.keeps(op)) || needed.contains(&(op, l, r))
        })
        .collect()
}

/// The generated types an item names (as whole tokens).
fn mentioned<'a>(tokens: &impl ToTokens, types: &[&'a str]) -> BTreeSet<&'a str> {
    let text = tokens.to_token_stream().to_string();
    let words: BTreeSet<&str> = text.split(|c: char| !(c.is_alphanumeric() || c == '_')).collect();
    types.iter().copied().filter(|t| words.contains(t)).collect()
}

/// The type an item belongs to: a struct's name, an impl's self type.
fn owner(item: &syn::Item) -> Option<String> {
    match item {
        syn::Item::Struct(s) => Some(s.ident.to_string()),
        syn::Item::Impl(imp) => type_name(&imp.self_ty),
        _ => None,
    }
}

/// Drops the types the plan added (automatic `Even`/`Odd`, the full multivector) that no kept
/// kernel returns, with their impls and every method or conversion naming them: the kept
/// kernels among the declared types rarely reach the full multivector, whose value methods
/// are a large part of a file.
fn prune(items: Vec<syn::Item>, types: &[&str], declared: &[&str]) -> Vec<syn::Item> {
    let mut used: BTreeSet<&str> = declared.iter().copied().collect();
    // the results of the kept kernels and of the unary maps of used types, to a fixed point
    loop {
        let before = used.len();
        for item in &items {
            let Some(o) = owner(item) else { continue };
            if !used.contains(o.as_str()) {
                continue;
            }
            match item {
                syn::Item::Impl(imp) if kernel_impl(item, types).is_some() => used.extend(mentioned(imp, types)),
                syn::Item::Impl(imp) if imp.trait_.is_none() => {
                    for it in &imp.items {
                        if let syn::ImplItem::Fn(f) = it
                            && ["reverse", "grade_involution", "conjugate", "dual", "undual"]
                                .iter()
                                .any(|u| f.sig.ident == u)
                        {
                            used.extend(mentioned(&f.sig.output, types));
                        }
                    }
                }
                _ => {}
            }
        }
        if used.len() == before {
            break;
        }
    }
    let unused: Vec<&str> = types.iter().copied().filter(|t| !used.contains(t)).collect();
    let names_unused = |t: &dyn ToTokens| !mentioned(&t.to_token_stream(), &unused).is_empty();
    items
        .into_iter()
        .filter_map(|mut item| {
            if owner(&item).is_some_and(|o| unused.contains(&o.as_str())) {
                return None;
            }
            if let syn::Item::Impl(imp) = &mut item {
                if imp.trait_.is_some() {
                    return (!names_unused(&*imp)).then_some(item);
                }
                imp.items.retain(|it| !names_unused(it));
            }
            Some(item)
        })
        .collect()
}

/// The generic inherent methods that forward to a kernel trait (`m.apply(&p)` for
/// `Apply::apply(&m, &p)`): the method, its trait and the trait method it calls.
const DISPATCH: [(&str, &str, &str); 9] = [
    ("sandwich", "Sandwich", "sandwich"),
    ("apply", "Apply", "apply"),
    ("apply_unit", "UnitAction", "apply_unit"),
    ("sandwich_unit", "UnitAction", "sandwich_unit"),
    ("apply_matrix", "ActionMatrix", "apply_matrix"),
    ("sandwich_matrix", "ActionMatrix", "sandwich_matrix"),
    ("transform", "ActionMatrix", "transform"),
    ("join", "RegressiveProduct", "regressive"),
    ("gp_into", "GeometricProductInto", "gp_into"),
];

/// Drops the forwarding methods ([`DISPATCH`]) of a type that implements their trait for no
/// operand in the file: they could not be called (their `where Self: Trait<X>` holds for no
/// `X`), so no program that compiled loses anything.
fn drop_dead_dispatch(items: &mut [syn::Item]) {
    // (trait, trait method, self type) of every kept trait impl
    let mut implemented: BTreeSet<(String, String, String)> = BTreeSet::new();
    for item in items.iter() {
        let syn::Item::Impl(imp) = item else { continue };
        let (Some((_, path, _)), Some(owner)) = (&imp.trait_, type_name(&imp.self_ty)) else { continue };
        let Some(last) = path.segments.last() else { continue };
        for it in &imp.items {
            if let syn::ImplItem::Fn(f) = it {
                implemented.insert((last.ident.to_string(), f.sig.ident.to_string(), owner.clone()));
            }
        }
    }
    for item in items.iter_mut() {
        let syn::Item::Impl(imp) = item else { continue };
        if imp.trait_.is_some() {
            continue;
        }
        let Some(owner) = type_name(&imp.self_ty) else { continue };
        imp.items.retain(|it| {
            let syn::ImplItem::Fn(f) = it else { return true };
            let Some((_, tr, method)) = DISPATCH.iter().find(|(name, _, _)| f.sig.ident == name) else { return true };
            // only the generic forwarding methods (a closed form or a user-facing method of
            // another shape with one of these names is kept)
            let forwards = !f.sig.generics.params.is_empty()
                && f.sig.generics.where_clause.to_token_stream().to_string().contains(&format!("self :: {tr} <"));
            !forwards || implemented.contains(&(tr.to_string(), method.to_string(), owner.clone()))
        });
    }
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
            // a closed form with a runtime fallback (the invariant decomposition's complex
            // roots) goes as a whole: its other methods call the one that needs the runtime
            if imp.trait_.is_none()
                && imp.generics.to_token_stream().to_string().contains("self :: Real")
                && imp.items.iter().any(uses_runtime)
            {
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
/// the solver and `join_terms`, from algebra-core's sources; with `closed` also `Real` and the
/// closed-form factors (`mod closed_form`, both of algebra-core's files, for the generated
/// `exp`, `log`, `normalize`, `sqrt` and `pow`).
fn shared_items(closed: bool, selection: &Selection) -> syn::Result<Vec<syn::Item>> {
    let mut items: Vec<syn::Item> = syn::parse_str::<syn::File>(algebra_core::sources::OPS)?
        .items
        .into_iter()
        .filter(|it| matches!(it, syn::Item::Trait(_)))
        .collect();
    // `UnitAction` with the selected one of its two methods (both when neither is selected)
    for (kept, dropped, convention) in [
        ("apply_unit", "sandwich_unit", "`S x rev(S)` ([`Apply`])"),
        ("sandwich_unit", "apply_unit", "`rev(S) x S` ([`Sandwich`])"),
    ] {
        if selection.keeps(kept) && !selection.keeps(dropped) {
            for item in &mut items {
                if let syn::Item::Trait(t) = item
                    && t.ident == "UnitAction"
                {
                    t.items.retain(|m| !matches!(m, syn::TraitItem::Fn(f) if f.sig.ident == dropped));
                    let doc = format!(
                        " The versor action {convention} for *unit* versors (`S rev(S) = 1`), fused and typed \
                         but cheaper: since `x S rev(S) = x`, the commutator drops every part of `S` that \
                         commutes with `x`. Not the action for other versors. algebra-core's `UnitAction` \
                         with the one method this file selects (`--ops {dropped}` adds `{dropped}`)."
                    );
                    set_doc(&mut t.attrs, &doc);
                }
            }
        }
    }
    for item in syn::parse_str::<syn::File>(algebra_core::sources::SCALAR)?.items {
        let syn::Item::Trait(mut t) = item else { continue };
        let keep: Option<&[&str]> = match t.ident.to_string().as_str() {
            "Ring" => Some(&RING_METHODS),
            "Field" => Some(&FIELD_METHODS),
            "Real" if closed => None,
            _ => continue,
        };
        if let Some(keep) = keep {
            t.items.retain(|m| matches!(m, syn::TraitItem::Fn(f) if keep.iter().any(|k| f.sig.ident == k)));
        }
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
    if closed {
        items.push(closed_form_module()?);
    }
    Ok(items)
}

/// `Real` for `f32` and `f64` through std (the closed forms' scalar functions).
fn real_impls() -> Vec<syn::Item> {
    [quote!(f32), quote!(f64)]
        .iter()
        .map(|t| {
            parse_quote! {
                impl Real for #t {
                    fn sqrt(&self) -> Self { #t::sqrt(*self) }
                    fn exp(&self) -> Self { #t::exp(*self) }
                    fn ln(&self) -> Self { #t::ln(*self) }
                    fn sin(&self) -> Self { #t::sin(*self) }
                    fn cos(&self) -> Self { #t::cos(*self) }
                    fn sinh(&self) -> Self { #t::sinh(*self) }
                    fn cosh(&self) -> Self { #t::cosh(*self) }
                    fn atan2(&self, x: &Self) -> Self { #t::atan2(*self, *x) }
                    fn atanh(&self) -> Self { #t::atanh(*self) }
                    fn abs(&self) -> Self { #t::abs(*self) }
                    fn to_f64(&self) -> f64 { f64::from(*self) }
                    fn from_f64(x: f64) -> Self { x as #t }
                    fn pi() -> Self { ::core::#t::consts::PI }
                    fn is_finite(&self) -> bool { #t::is_finite(*self) }
                }
            }
        })
        .collect()
}

/// `mod closed_form`: algebra-core's `closed_form` and `closed_form_inv` in one module, their
/// `use` lines replaced by the file's own items and their docs by one line each (the originals'
/// examples name algebra-core).
fn closed_form_module() -> syn::Result<syn::Item> {
    let mut body: Vec<syn::Item> = Vec::new();
    for source in [algebra_core::sources::CLOSED_FORM, algebra_core::sources::CLOSED_FORM_INV] {
        for mut item in syn::parse_str::<syn::File>(source)?.items {
            match &mut item {
                syn::Item::Use(_) => continue,
                syn::Item::Fn(f) => {
                    let doc = format!(" algebra-core's `closed_form::{}`.", f.sig.ident);
                    set_doc(&mut f.attrs, &doc);
                }
                syn::Item::Const(c) => {
                    let doc = format!(" algebra-core's `closed_form::{}`.", c.ident);
                    set_doc(&mut c.attrs, &doc);
                }
                _ => {}
            }
            body.push(item);
        }
    }
    Ok(parse_quote! {
        /// The scalar factors of the closed forms (algebra-core's `closed_form`).
        pub mod closed_form {
            use super::{MvError, Real};
            #(#body)*
        }
    })
}
