//! `gam codegen --standalone`: a module source with no dependency at all. The emitted items
//! are kept except the runtime bridge (the `algebra()` instance, `BASIS`, conversions to and
//! from `Multivector`, and the inverse of types that are not subalgebras, which goes through
//! the runtime); every `::algebra_core` path is pointed at items appended to the file: the
//! product traits, `Ring`/`Field` reduced to the methods kernels call, the solver and
//! `join_terms`, all
//! parsed from algebra-core's own sources ([`algebra_core::sources`]), then
//! `standalone/support.rs` (`f32`/`f64` impls, `MvError`, `format_term`).
//!
//! The kernels are those of a [`Selection`] (by default the geometric product and `apply` /
//! `apply_unit` of the motor and rotor types). The value semantics every type shares and the
//! product operators are written once, as the macros of `standalone/values.rs` invoked per
//! type and per product (`compact`); [`layout`] prints those macros as written after
//! prettyplease.

use crate::paths::{join_path, map_engine_paths};
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::{ToTokens, quote};
use std::collections::BTreeSet;
use syn::parse_quote;

/// The inlined support items (parsed once per call).
const SUPPORT: &str = include_str!("standalone/support.rs");

/// The macros that write the value semantics of every type and the product operators once
/// (`value_type!`, `scalar_times!`, `product_operators!`), at the top of the file.
const VALUES: &str = include_str!("standalone/values.rs");

/// `Real` for `f32` and `f64` (files with closed forms).
const REAL: &str = include_str!("standalone/real.rs");

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

pub use crate::versor::is_kinematic;

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
    file.items = compact(std::mem::take(&mut file.items), &types)?;
    // the functions of `closed_form` the kept closed forms call
    let mut used = BTreeSet::new();
    for item in &file.items {
        let text = item.to_token_stream().to_string();
        for (i, m) in text.match_indices("self :: closed_form :: ") {
            let rest = &text[i + m.len()..];
            used.insert(rest.split(|c: char| !(c.is_alphanumeric() || c == '_')).next().unwrap_or("").to_string());
        }
    }
    let closed = !used.is_empty();
    let tables = file.items.iter().any(|item| item.to_token_stream().to_string().contains("self :: kernels :: "));
    file.items.extend(shared_items(closed, &used, selection)?);
    if tables {
        file.items.push(kernels_module()?);
    }
    let support: syn::File = syn::parse_str(SUPPORT)?;
    file.items.extend(support.items);
    if closed {
        file.items.extend(real_impls()?);
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

/// The text of a standalone file as printed by prettyplease, laid out for reading: every
/// `macro_rules!` definition as written in its source (prettyplease flows a macro's body into
/// one paragraph of tokens), and the invocations of `value_type!` and `product_operators!`
/// one part per line (the fields, the basis elements; the products of one left-hand type).
///
/// ```
/// let pretty = "macro_rules! scalar_times {\n    ($ty:ident) => { flowed };\n}\nproduct_operators!(\n    Mul::mul => GeometricProduct::gp : A * A = A, A * B = B, B\n    * A = B\n);\n";
/// let text = algebra_codegen::standalone::layout(pretty);
/// assert!(text.starts_with("macro_rules! scalar_times {\n    ($ty:ident { $($f:ident),* } $float:ident) => {\n"));
/// assert!(text.ends_with("product_operators!(Mul::mul => GeometricProduct::gp:\n    A * A = A, A * B = B,\n    B * A = B,\n);\n"));
/// ```
pub fn layout(pretty: &str) -> String {
    let mut sources: std::collections::BTreeMap<String, Vec<&str>> = std::collections::BTreeMap::new();
    for source in [VALUES, SUPPORT, REAL] {
        let lines: Vec<&str> = source.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            if let Some(name) = line.strip_prefix("macro_rules! ").and_then(|r| r.strip_suffix(" {")) {
                let end = lines[i..].iter().position(|l| *l == "}").map_or(lines.len(), |e| i + e + 1);
                sources.insert(name.to_string(), lines[i..end].to_vec());
            }
        }
    }
    let lines: Vec<&str> = pretty.lines().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        let trimmed = line.trim_start();
        let indent = &line[..line.len() - trimmed.len()];
        let name = trimmed.strip_prefix("macro_rules! ").and_then(|r| r.strip_suffix(" {"));
        let invocation = ["value_type!(", "product_operators!("].into_iter().find(|p| trimmed.starts_with(p));
        // the line closing the item that starts here (at the same indentation; this line
        // itself for an invocation printed on one line)
        let block_end = |close: &str| {
            if close == ");" && trimmed.ends_with(close) {
                return Some(i);
            }
            lines[i..].iter().position(|l| l.strip_prefix(indent) == Some(close)).map(|e| i + e)
        };
        if let Some(source) = name.and_then(|n| sources.get(n))
            && let Some(end) = block_end("}")
        {
            for l in source {
                out.push_str(if l.is_empty() { "" } else { indent });
                out.push_str(l);
                out.push('\n');
            }
            i = end + 1;
        } else if let Some(head) = invocation
            && let Some(end) = block_end(");")
        {
            let joined: Vec<&str> = lines[i..=end].iter().map(|l| l.trim()).collect();
            let joined = joined.join(" ");
            let args = joined[head.len()..joined.len() - 2].trim();
            out.push_str(&invocation_layout(indent, head, args));
            i = end + 1;
        } else {
            out.push_str(line);
            out.push('\n');
            i += 1;
        }
    }
    out
}

/// One invocation of `value_type!` or `product_operators!` (`head` with its `(`), its
/// arguments `args` on one line, laid out one part per line.
fn invocation_layout(indent: &str, head: &str, args: &str) -> String {
    let tidy = |s: &str| s.replace(" : ", ": ").replace(" ,", ",");
    let mut parts: Vec<String> = Vec::new();
    if head == "value_type!(" {
        // `X[N] { fields } basis { elements } one: scalar`
        let mut rest = args;
        while let Some(close) = rest.find('}') {
            parts.push(tidy(rest[..=close].trim()));
            rest = &rest[close + 1..];
        }
        if !rest.trim().is_empty() {
            parts.push(tidy(rest.trim()));
        }
        let body: Vec<String> = parts.iter().map(|p| format!("{indent}    {p}\n")).collect();
        return format!("{indent}{head}\n{}{indent});\n", body.concat());
    }
    // `Op::op => Product::kernel: A * B = C, ...`: one line per left-hand type
    let Some((op, list)) = args.split_once(" : ") else { return format!("{indent}{head}{args});\n") };
    let mut rows: Vec<(String, Vec<String>)> = Vec::new();
    for pair in list.split(',').map(str::trim).filter(|p| !p.is_empty()) {
        let lhs = pair.split_whitespace().next().unwrap_or("").to_string();
        match rows.last_mut() {
            Some((l, row)) if *l == lhs => row.push(pair.to_string()),
            _ => rows.push((lhs, vec![pair.to_string()])),
        }
    }
    let body: Vec<String> = rows.iter().map(|(_, row)| format!("{indent}    {},\n", row.join(", "))).collect();
    format!("{indent}{head}{op}:\n{}{indent});\n", body.concat())
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

/// The traits whose impls on a generated type `value_type!` writes (with `From` between the
/// type and its array, `Mul`/`Div` by the scalar `T` and `s * x` for `f32`/`f64`).
const VALUE_TRAITS: [&str; 13] = [
    "Default",
    "Index",
    "IndexMut",
    "IntoIterator",
    "Display",
    "Debug",
    "Add",
    "Sub",
    "Neg",
    "AddAssign",
    "SubAssign",
    "MulAssign",
    "DivAssign",
];

/// The inherent methods `value_type!` writes (besides the basis elements).
const VALUE_METHODS: [&str; 10] =
    ["new", "zero", "one", "scale", "to_array", "into_array", "from_array", "each_ref", "iter", "iter_mut"];

/// The product operators `product_operators!` writes: the operator trait, its method, its
/// symbol (for the invocation's `Lhs * Rhs = Out`), the product trait and its method.
const OPERATORS: [(&str, &str, &str, &str, &str); 4] = [
    ("Mul", "mul", "*", "GeometricProduct", "gp"),
    ("BitXor", "bitxor", "^", "OuterProduct", "op"),
    ("BitOr", "bitor", "|", "LeftContraction", "lc"),
    ("BitAnd", "bitand", "&", "RegressiveProduct", "regressive"),
];

/// The first generic type argument of a path's last segment (`Point<T>` in `Mul<&Point<T>>`).
fn first_type_arg(path: &syn::Path) -> Option<&syn::Type> {
    match &path.segments.last()?.arguments {
        syn::PathArguments::AngleBracketed(a) => a.args.iter().find_map(|g| match g {
            syn::GenericArgument::Type(t) => Some(t),
            _ => None,
        }),
        _ => None,
    }
}

/// Whether a trait impl is value semantics that `value_type!` writes for its type.
fn is_value_impl(imp: &syn::ItemImpl, types: &[&str]) -> bool {
    let Some((_, path, _)) = &imp.trait_ else { return false };
    let Some(last) = path.segments.last() else { return false };
    let name = last.ident.to_string();
    let arg = first_type_arg(path);
    let generated = |t: &syn::Type| type_name(t).is_some_and(|n| types.contains(&n.as_str()));
    let scalar = |t: &syn::Type| matches!(t, syn::Type::Path(p) if p.path.is_ident("f32") || p.path.is_ident("f64"));
    let own = generated(&imp.self_ty);
    match name.as_str() {
        n if VALUE_TRAITS.contains(&n) => own,
        // `From<[T; N]> for X` and `From<X> for [T; N]` (not the embeddings between types)
        "From" => {
            (own && matches!(arg, Some(syn::Type::Array(_))))
                || (matches!(*imp.self_ty, syn::Type::Array(_)) && arg.is_some_and(generated))
        }
        // `x * s`, `x / s` for the scalar `T`, and `s * x` for `f32`/`f64`
        "Mul" | "Div" => {
            (own && arg.and_then(type_name).is_some_and(|a| a == "T"))
                || (name == "Mul" && scalar(&imp.self_ty) && arg.is_some_and(generated))
        }
        _ => false,
    }
}

/// A product operator impl (`Mul<&Point<T>> for &Motor<T>`): the index in [`OPERATORS`] and
/// the (left, right, output) types.
fn operator_impl(imp: &syn::ItemImpl, types: &[&str]) -> Option<(usize, String, String, String)> {
    let (_, path, _) = imp.trait_.as_ref()?;
    let op = OPERATORS.iter().position(|o| path.segments.last().is_some_and(|l| l.ident == o.0))?;
    let lhs = type_name(&imp.self_ty).filter(|n| types.contains(&n.as_str()))?;
    let rhs = first_type_arg(path).and_then(type_name).filter(|n| types.contains(&n.as_str()))?;
    let out = imp.items.iter().find_map(|it| match it {
        syn::ImplItem::Type(t) if t.ident == "Output" => type_name(&t.ty),
        _ => None,
    })?;
    Some((op, lhs, rhs, out))
}

/// The per-type value semantics and the product operators as macro invocations instead of
/// copies of the same impl blocks: after each struct `value_type!(X[LEN] { fields } basis {
/// elements } one: scalar);` replaces the impls [`is_value_impl`] finds and the inherent
/// [`VALUE_METHODS`] and basis elements; `product_operators!(Mul::mul =>
/// GeometricProduct::gp: A * B = C, ...);` replaces the four operator impls of each pair. The
/// macros ([`VALUES`]) go first in the file.
fn compact(items: Vec<syn::Item>, types: &[&str]) -> syn::Result<Vec<syn::Item>> {
    // the fields of every generated struct, in order
    let mut fields: std::collections::BTreeMap<String, Vec<syn::Ident>> = std::collections::BTreeMap::new();
    for item in &items {
        if let syn::Item::Struct(st) = item
            && types.contains(&st.ident.to_string().as_str())
        {
            fields.insert(st.ident.to_string(), st.fields.iter().filter_map(|f| f.ident.clone()).collect());
        }
    }
    // the operator pairs, and how many of their four impls are present
    let mut pairs: Vec<(usize, String, String, String)> = Vec::new();
    let mut count: std::collections::BTreeMap<(usize, String, String, String), usize> = Default::default();
    for item in &items {
        if let syn::Item::Impl(imp) = item
            && let Some(key) = operator_impl(imp, types)
        {
            if !count.contains_key(&key) {
                pairs.push(key.clone());
            }
            *count.entry(key).or_default() += 1;
        }
    }
    let complete = |key: &(usize, String, String, String)| count.get(key) == Some(&4);
    let mut basis: std::collections::BTreeMap<String, Vec<syn::Ident>> = Default::default();
    let mut out: Vec<syn::Item> = Vec::new();
    let mut placed = [false; OPERATORS.len()];
    for mut item in items {
        if let syn::Item::Impl(imp) = &mut item {
            if is_value_impl(imp, types) {
                continue;
            }
            if let Some(key) = operator_impl(imp, types)
                && complete(&key)
            {
                // the invocation of this operator goes where its first impl was
                let op = key.0;
                if !placed[op] {
                    placed[op] = true;
                    let (op_trait, method, sym, product, kernel) = OPERATORS[op];
                    let [op_trait, method, product, kernel] =
                        [op_trait, method, product, kernel].map(|n| syn::Ident::new(n, proc_macro2::Span::call_site()));
                    let sym: proc_macro2::TokenStream = sym.parse().expect("an operator symbol");
                    let list = pairs.iter().filter(|k| k.0 == op && complete(k)).map(|(_, l, r, o)| {
                        let [l, r, o] = [l, r, o].map(|n| syn::Ident::new(n, proc_macro2::Span::call_site()));
                        quote!(#l #sym #r = #o)
                    });
                    out.push(parse_quote!(product_operators!(#op_trait::#method => #product::#kernel: #(#list),*);));
                }
                continue;
            }
            if imp.trait_.is_none()
                && let Some(owner) = type_name(&imp.self_ty)
                && let Some(own) = fields.get(&owner)
            {
                imp.items.retain(|it| match it {
                    syn::ImplItem::Const(c) => c.ident != "LEN",
                    syn::ImplItem::Fn(f) => {
                        let name = f.sig.ident.to_string();
                        let constant = f.sig.inputs.is_empty()
                            && name != "scalar"
                            && own.iter().any(|x| *x == name)
                            && !VALUE_METHODS.contains(&name.as_str());
                        if constant {
                            basis.entry(owner.clone()).or_default().push(f.sig.ident.clone());
                        }
                        !(constant || VALUE_METHODS.contains(&name.as_str()))
                    }
                    _ => true,
                });
                if imp.items.is_empty() {
                    continue;
                }
            }
        }
        out.push(item);
    }
    // the projections `a.project_to_b()` of a type in one impl block (where the first was)
    let mut projections: std::collections::BTreeMap<String, Vec<syn::ImplItem>> = Default::default();
    let mut merged: Vec<syn::Item> = Vec::new();
    for mut item in out {
        if let syn::Item::Impl(imp) = &mut item {
            zero_rest(imp);
            let only_projections = imp.trait_.is_none()
                && !imp.items.is_empty()
                && imp
                    .items
                    .iter()
                    .all(|it| matches!(it, syn::ImplItem::Fn(f) if f.sig.ident.to_string().starts_with("project_to_")));
            if only_projections && let Some(owner) = type_name(&imp.self_ty) {
                let first = !projections.contains_key(&owner);
                projections.entry(owner).or_default().append(&mut imp.items);
                if !first {
                    continue;
                }
            }
        }
        merged.push(item);
    }
    for item in &mut merged {
        if let syn::Item::Impl(imp) = item
            && imp.trait_.is_none()
            && imp.items.is_empty()
            && let Some(fns) = type_name(&imp.self_ty).and_then(|o| projections.remove(&o))
        {
            imp.items = fns;
        }
    }
    // `value_type!` after each struct (the basis elements are known once every impl was read)
    let mut items = Vec::new();
    for item in merged {
        let invocation = match &item {
            syn::Item::Struct(st) => fields.get(&st.ident.to_string()).map(|f| {
                let ty = &st.ident;
                let n = proc_macro2::Literal::usize_unsuffixed(f.len());
                let basis = basis.get(&ty.to_string()).cloned().unwrap_or_default();
                let one = f.iter().any(|x| x == "scalar").then(|| quote!(one: scalar));
                let tokens = quote!(value_type!(#ty[#n] { #(#f),* } basis { #(#basis),* } #one););
                syn::parse2::<syn::Item>(tokens)
            }),
            _ => None,
        };
        items.push(item);
        if let Some(invocation) = invocation {
            items.push(invocation?);
        }
    }
    let mut macros: Vec<syn::Item> = syn::parse_str::<syn::File>(VALUES)?.items;
    if !placed.iter().any(|p| *p) {
        macros.retain(
            |m| !matches!(m, syn::Item::Macro(m) if m.ident.as_ref().is_some_and(|i| i == "product_operators")),
        );
    }
    macros.extend(items);
    Ok(macros)
}

/// In the projections and embeddings between types (`project_to_b`, `From<&A> for B`), a
/// struct literal's zero fields as `..B::zero()`, and a literal with nothing but zeros as
/// `B::zero()`.
fn zero_rest(imp: &mut syn::ItemImpl) {
    let conversion = match &imp.trait_ {
        Some((_, path, _)) => path.segments.last().is_some_and(|l| l.ident == "From"),
        None => true,
    };
    if !conversion {
        return;
    }
    for it in &mut imp.items {
        let syn::ImplItem::Fn(f) = it else { continue };
        let name = f.sig.ident.to_string();
        if imp.trait_.is_none() && !name.starts_with("project_to_") {
            continue;
        }
        let Some(syn::Stmt::Expr(syn::Expr::Struct(lit), None)) = f.block.stmts.last_mut() else { continue };
        if lit.rest.is_some() {
            continue;
        }
        let zero = |e: &syn::Expr| e.to_token_stream().to_string() == "T :: zero ()";
        let before = lit.fields.len();
        let fields: syn::punctuated::Punctuated<syn::FieldValue, syn::Token![,]> =
            lit.fields.iter().filter(|fv| !zero(&fv.expr)).cloned().collect();
        if fields.len() == before {
            continue;
        }
        let ty = &lit.path;
        if fields.is_empty() {
            *f.block.stmts.last_mut().expect("checked above") = syn::Stmt::Expr(parse_quote!(#ty::zero()), None);
        } else {
            lit.fields = fields;
            if !lit.fields.trailing_punct() {
                lit.fields.push_punct(Default::default());
            }
            lit.dot2_token = Some(Default::default());
            lit.rest = Some(Box::new(parse_quote!(#ty::zero())));
        }
    }
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
fn shared_items(closed: bool, used: &BTreeSet<String>, selection: &Selection) -> syn::Result<Vec<syn::Item>> {
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
                         with the one method this file selects (name `{dropped}` in `--ops` for both)."
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
        items.push(closed_form_module(used)?);
    }
    Ok(items)
}

/// The loops of the table-driven kernels (algebra-core's `kernels`), for files holding kernels
/// above the size threshold or over the types a module adds ([`crate::size::table_driven`]).
fn kernels_module() -> syn::Result<syn::Item> {
    let mut body = Vec::new();
    for mut item in syn::parse_str::<syn::File>(algebra_core::sources::KERNELS)?.items {
        match &mut item {
            syn::Item::Use(_) => continue,
            // the doc examples name algebra-core
            syn::Item::Fn(f) => set_doc(&mut f.attrs, &format!(" algebra-core's `kernels::{}`.", f.sig.ident)),
            _ => {}
        }
        body.push(item);
    }
    Ok(parse_quote! {
        /// The loops of the table-driven kernels (algebra-core's `kernels`).
        pub mod kernels {
            use super::Ring;
            #(#body)*
        }
    })
}

/// `Real` for `f32` and `f64` through std (the closed forms' scalar functions), as the macro
/// `float_real!` of `standalone/real.rs` and its invocation.
fn real_impls() -> syn::Result<Vec<syn::Item>> {
    Ok(syn::parse_str::<syn::File>(REAL)?.items)
}

/// The items of `body` that `used` names, with those they name in turn (to a fixed point), and
/// every item that is not a function or a constant.
fn reachable(body: Vec<syn::Item>, used: &BTreeSet<String>) -> Vec<syn::Item> {
    let name = |item: &syn::Item| match item {
        syn::Item::Fn(f) => Some(f.sig.ident.to_string()),
        syn::Item::Const(c) => Some(c.ident.to_string()),
        _ => None,
    };
    let mut keep: BTreeSet<String> = used.clone();
    loop {
        let before = keep.len();
        for item in &body {
            if name(item).is_some_and(|n| keep.contains(&n)) {
                let text = item.to_token_stream().to_string();
                keep.extend(text.split(|c: char| !(c.is_alphanumeric() || c == '_')).map(str::to_string));
            }
        }
        if keep.len() == before {
            break;
        }
    }
    body.into_iter().filter(|item| name(item).is_none_or(|n| keep.contains(&n))).collect()
}

/// `mod closed_form`: algebra-core's `closed_form` and `closed_form_inv` in one module, their
/// `use` lines replaced by the file's own items and their docs by one line each (the originals'
/// examples name algebra-core).
fn closed_form_module(used: &BTreeSet<String>) -> syn::Result<syn::Item> {
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
    let body = reachable(body, used);
    Ok(parse_quote! {
        /// The scalar factors of the closed forms (algebra-core's `closed_form`), those the
        /// file's closed forms call.
        pub mod closed_form {
            use super::{MvError, Real};
            #(#body)*
        }
    })
}
