//! The `algebra!` proc-macro: declares a geometric algebra and the multivector types to
//! generate for it. This crate only parses the DSL; the generator is
//! [`algebra_codegen`].
//!
//! ```ignore
//! algebra_macros::algebra! {
//!     /// The paper's conformal algebra in its product basis.
//!     pub mod cga_null {
//!         generators { e0, e1, e2, e3, einf }
//!         metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1, (e0, einf) = -1 }
//!         basis product;
//!         types {
//!             Vector = grade 1;
//!             Motor = [1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf];
//!             Multivector = all;
//!         }
//!     }
//! }
//! ```
//!
//! - `generators { ... }`: identifiers starting with `e`; the rest is the label (`einf` has
//!   label `inf`). Basis names are `e` + labels in declaration order.
//! - `metric { (a, b) = v, ... }`: the symmetric bilinear form; unlisted pairs are 0; `v` is an
//!   integer or a ratio `p/q`, optionally negative. Alternatively `metric builtin "cga-null";`.
//! - `basis blade;` (default) or `basis product;`: what the type fields' names mean.
//! - `fallback parity;` (default) or `fallback full;`: when no type is the full multivector,
//!   a result outside every declared type lands in an automatic `Even`/`Odd` type if it has one
//!   parity (`parity`), or always in the full multivector (`full`: no automatic types).
//! - `closed_forms on;` (default) or `closed_forms off;`: whether the closed-form `exp`, `log`,
//!   `log_unit`, `normalize`, `sqrt`, `pow` detected from the tables are emitted (`off` for a
//!   crate that gives the types its own methods of those names, as `motion` does for `Pose`).
//! - `table_above N;`: the size policy's threshold (default
//!   `algebra_codegen::size::TABLE_THRESHOLD`): a kernel with more than `N` terms is a loop over
//!   a constant table, one with at most `N` straight-line code (docs/codegen.md, "Size policy").
//! - `types { Name = selector; ... }` with selectors `grade K`, `even`, `odd`, `all`, or a
//!   list `[1, e12, ...]`; doc comments on types are kept. A type may declare a polynomial
//!   constraint after its selector: `Motor = even where unit;` (`rev(x) x = 1`),
//!   `Point = grade 1 where null;` (`x x = 0`), `Line = grade 2 where simple;` (`x ∧ x = 0`,
//!   the Plücker condition). The generator then uses kernels reduced modulo the constraint —
//!   in the unit actions `sandwich_unit`/`apply_unit` (`UnitAction`, where cheaper, with the
//!   output type proven in the rustdoc) and as `square_null`/`square_simple` methods — with the
//!   outputs that vanish under the constraint proven (by ideal membership) and dropped (see
//!   `algebra_codegen::constraint`). Kernels of the predefined modules are precomputed, so the
//!   macro needs no GMP; for other modules turn on this crate's `constraints` feature (it
//!   computes them with `rug`) or vendor the module with `gam codegen`.
//! - optionally, before the module, `crate PATH;`: where the generated code finds the engine
//!   (`algebra-core`). The default is `::algebra_core`, for crates that depend on algebra-core
//!   directly (the workspace's `gam-algebras`, `motion`); the front door `gam_ga::algebra!`
//!   passes `crate $crate::__engine;`, so its users need no other dependency.

mod cache;

use algebra_codegen::constraint::ConstraintKind;
use algebra_codegen::{ModuleSpec, TypeSpec, plan::Plan};
use algebra_core::rational::{Q, q};
use algebra_core::{Algebra, Basis, Metric};
use proc_macro::TokenStream;
use quote::quote;
use syn::parse::{Parse, ParseStream};
use syn::{Attribute, Ident, LitInt, LitStr, Token, Visibility, braced, bracketed, parenthesized};

/// Declares an algebra and generates its multivector types and kernels. See the crate docs.
#[proc_macro]
pub fn algebra(input: TokenStream) -> TokenStream {
    let invocation = input.to_string();
    let decl = syn::parse_macro_input!(input as Decl);
    match expand(decl, &invocation) {
        Ok(ts) => ts.into(),
        Err(e) => e.to_compile_error().into(),
    }
}

enum MetricDecl {
    Pairs(Vec<(Ident, Ident, Q)>),
    Builtin(LitStr),
}

struct TypeDecl {
    attrs: Vec<Attribute>,
    name: Ident,
    selector: Selector,
    constraint: Option<ConstraintKind>,
}

enum Selector {
    Text(String, proc_macro2::Span),
    List(Vec<(String, proc_macro2::Span)>),
}

struct Decl {
    engine: Option<proc_macro2::TokenStream>,
    attrs: Vec<Attribute>,
    vis: Visibility,
    name: Ident,
    generators: Vec<Ident>,
    metric: MetricDecl,
    metric_span: proc_macro2::Span,
    basis: Basis,
    types: Vec<TypeDecl>,
    serde: bool,
    parity_types: bool,
    closed_forms: bool,
    table_above: Option<usize>,
}

fn parse_value(input: ParseStream) -> syn::Result<Q> {
    let neg = input.parse::<Option<Token![-]>>()?.is_some();
    let n: LitInt = input.parse()?;
    let mut v = Q::from_integer(n.base10_parse::<i64>()?.into());
    if input.parse::<Option<Token![/]>>()?.is_some() {
        let lit: LitInt = input.parse()?;
        let d = lit.base10_parse::<i64>()?;
        if d == 0 {
            return Err(syn::Error::new(lit.span(), "zero denominator"));
        }
        v /= q(d);
    }
    Ok(if neg { -v } else { v })
}

impl Parse for Decl {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let engine = if input.peek(Token![crate]) {
            input.parse::<Token![crate]>()?;
            let mut path = proc_macro2::TokenStream::new();
            while !input.peek(Token![;]) {
                path.extend([input.parse::<proc_macro2::TokenTree>()?]);
            }
            input.parse::<Token![;]>()?;
            Some(path)
        } else {
            None
        };
        let attrs = input.call(Attribute::parse_outer)?;
        let vis: Visibility = input.parse()?;
        input.parse::<Token![mod]>()?;
        let name: Ident = input.parse()?;
        let body;
        braced!(body in input);
        let (mut generators, mut metric, mut basis, mut types) = (None, None, Basis::Blade, None);
        let (mut serde, mut parity_types, mut closed_forms) = (false, true, true);
        let mut table_above = None;
        let mut metric_span = proc_macro2::Span::call_site();
        while !body.is_empty() {
            let key: Ident = body.parse()?;
            match key.to_string().as_str() {
                "generators" => {
                    let g;
                    braced!(g in body);
                    let list = g.parse_terminated(Ident::parse, Token![,])?;
                    generators = Some(list.into_iter().collect::<Vec<_>>());
                }
                "metric" => {
                    metric_span = key.span();
                    if body.peek(syn::token::Brace) {
                        let m;
                        braced!(m in body);
                        let mut pairs = Vec::new();
                        while !m.is_empty() {
                            let p;
                            parenthesized!(p in m);
                            let a: Ident = p.parse()?;
                            p.parse::<Token![,]>()?;
                            let b: Ident = p.parse()?;
                            m.parse::<Token![=]>()?;
                            pairs.push((a, b, parse_value(&m)?));
                            if !m.is_empty() {
                                m.parse::<Token![,]>()?;
                            }
                        }
                        metric = Some(MetricDecl::Pairs(pairs));
                    } else {
                        let kw: Ident = body.parse()?;
                        if kw != "builtin" {
                            return Err(syn::Error::new(
                                kw.span(),
                                "expected `{ (a, b) = value, ... }` or `builtin \"name\"`",
                            ));
                        }
                        metric = Some(MetricDecl::Builtin(body.parse()?));
                        body.parse::<Token![;]>()?;
                    }
                }
                "derive" => {
                    let d: Ident = body.parse()?;
                    if d != "serde" {
                        return Err(syn::Error::new(d.span(), "expected `serde` (the only optional derive)"));
                    }
                    serde = true;
                    body.parse::<Token![;]>()?;
                }
                "fallback" => {
                    let f: Ident = body.parse()?;
                    parity_types = match f.to_string().as_str() {
                        "parity" => true,
                        "full" => false,
                        _ => return Err(syn::Error::new(f.span(), "expected `parity` or `full`")),
                    };
                    body.parse::<Token![;]>()?;
                }
                "closed_forms" => {
                    let f: Ident = body.parse()?;
                    closed_forms = match f.to_string().as_str() {
                        "on" => true,
                        "off" => false,
                        _ => return Err(syn::Error::new(f.span(), "expected `on` or `off`")),
                    };
                    body.parse::<Token![;]>()?;
                }
                "table_above" => {
                    let bad = |span| syn::Error::new(span, "expected a number of terms, e.g. `table_above 256;`");
                    if !body.peek(LitInt) {
                        return Err(bad(body.span()));
                    }
                    let n: LitInt = body.parse()?;
                    table_above = Some(n.base10_parse::<usize>().map_err(|_| bad(n.span()))?);
                    body.parse::<Token![;]>()?;
                }
                "basis" => {
                    let b: Ident = body.parse()?;
                    basis = match b.to_string().as_str() {
                        "blade" => Basis::Blade,
                        "product" => Basis::Product,
                        _ => return Err(syn::Error::new(b.span(), "expected `blade` or `product`")),
                    };
                    body.parse::<Token![;]>()?;
                }
                "types" => {
                    let t;
                    braced!(t in body);
                    let mut list = Vec::new();
                    while !t.is_empty() {
                        let attrs = t.call(Attribute::parse_outer)?;
                        let name: Ident = t.parse()?;
                        t.parse::<Token![=]>()?;
                        let selector = if t.peek(syn::token::Bracket) {
                            let l;
                            bracketed!(l in t);
                            let mut els = Vec::new();
                            while !l.is_empty() {
                                if l.peek(LitInt) {
                                    let n: LitInt = l.parse()?;
                                    els.push((n.to_string(), n.span()));
                                } else {
                                    let id: Ident = l.parse()?;
                                    els.push((id.to_string(), id.span()));
                                }
                                if !l.is_empty() {
                                    l.parse::<Token![,]>()?;
                                }
                            }
                            Selector::List(els)
                        } else {
                            let word: Ident = t.parse()?;
                            let span = word.span();
                            let text = if word == "grade" {
                                let k: LitInt = t.parse()?;
                                format!("grade {}", k.base10_digits())
                            } else {
                                word.to_string()
                            };
                            Selector::Text(text, span)
                        };
                        let constraint = if t.peek(Token![where]) {
                            t.parse::<Token![where]>()?;
                            let kind: Ident = t.parse()?;
                            Some(ConstraintKind::parse(&kind.to_string()).ok_or_else(|| {
                                syn::Error::new(kind.span(), "expected a constraint: `unit`, `null` or `simple`")
                            })?)
                        } else {
                            None
                        };
                        t.parse::<Token![;]>()?;
                        list.push(TypeDecl { attrs, name, selector, constraint });
                    }
                    types = Some(list);
                }
                other => {
                    return Err(syn::Error::new(
                        key.span(),
                        format!(
                            "unknown section `{other}` (expected generators, metric, basis, fallback, closed_forms, table_above, derive or types)"
                        ),
                    ));
                }
            }
        }
        let missing = |what: &str| syn::Error::new(name.span(), format!("missing `{what}` section"));
        let metric = match metric {
            Some(m) => m,
            None => return Err(missing("metric")),
        };
        let types = types.ok_or_else(|| missing("types"))?;
        let generators = match (&metric, generators) {
            (_, Some(g)) => g,
            (MetricDecl::Builtin(_), None) => Vec::new(),
            (MetricDecl::Pairs(_), None) => return Err(missing("generators")),
        };
        Ok(Decl {
            engine,
            attrs,
            vis,
            name,
            generators,
            metric,
            metric_span,
            basis,
            types,
            serde,
            parity_types,
            closed_forms,
            table_above,
        })
    }
}

fn doc_lines(attrs: &[Attribute]) -> Vec<String> {
    attrs
        .iter()
        .filter(|a| a.path().is_ident("doc"))
        .filter_map(|a| match &a.meta {
            syn::Meta::NameValue(nv) => match &nv.value {
                syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(s), .. }) => Some(s.value().trim().to_string()),
                _ => None,
            },
            _ => None,
        })
        .collect()
}

/// The module of a declaration; `invocation` (the macro's input as text) keys the expansion
/// cache ([`cache`]).
fn expand(decl: Decl, invocation: &str) -> syn::Result<proc_macro2::TokenStream> {
    let metric = match &decl.metric {
        MetricDecl::Builtin(name) => {
            Algebra::builtin(&name.value()).map_err(|e| syn::Error::new(name.span(), e))?.metric().clone()
        }
        MetricDecl::Pairs(pairs) => {
            let mut labels = Vec::new();
            for g in &decl.generators {
                let s = g.to_string();
                match s.strip_prefix('e') {
                    Some(l) if !l.is_empty() => labels.push(l.to_string()),
                    _ => return Err(syn::Error::new(g.span(), "generator names start with `e` followed by a label")),
                }
            }
            let n = labels.len();
            let mut gram = vec![vec![q(0); n]; n];
            let index = |id: &Ident| {
                decl.generators
                    .iter()
                    .position(|g| g == id)
                    .ok_or_else(|| syn::Error::new(id.span(), format!("`{id}` is not one of the generators")))
            };
            for (a, b, v) in pairs {
                let (i, j) = (index(a)?, index(b)?);
                gram[i][j] = v.clone();
                gram[j][i] = v.clone();
            }
            Metric::new(labels, gram).map_err(|e| syn::Error::new(decl.metric_span, e))?
        }
    };
    let algebra = Algebra::new(decl.name.to_string(), metric.clone());
    let mut types = Vec::new();
    for t in &decl.types {
        let name = t.name.to_string();
        let mut spec = match &t.selector {
            Selector::Text(text, span) => {
                TypeSpec::parse(&name, text, &algebra).map_err(|e| syn::Error::new(*span, e))?
            }
            Selector::List(els) => {
                for (el, span) in els {
                    if algebra.mask_of(el).is_err() && algebra_codegen::orient::oriented_mask(&algebra, el).is_none() {
                        return Err(syn::Error::new(
                            *span,
                            format!(
                                "`{el}` is not a basis element (generators: {})",
                                algebra.metric().labels().join(", ")
                            ),
                        ));
                    }
                }
                let text: Vec<&str> = els.iter().map(|(e, _)| e.as_str()).collect();
                TypeSpec::parse(&name, &text.join(","), &algebra).map_err(|e| syn::Error::new(t.name.span(), e))?
            }
        };
        spec.doc = doc_lines(&t.attrs);
        spec.constraint = t.constraint;
        types.push(spec);
    }
    let mut spec = ModuleSpec::new(&decl.name.to_string(), metric, decl.basis, types).map_err(|e| {
        let span = decl.types.last().map(|t| t.name.span()).unwrap_or(decl.name.span());
        syn::Error::new(span, e)
    })?;
    spec.serde = decl.serde;
    spec.parity_types = decl.parity_types;
    spec.closed_forms = decl.closed_forms;
    if let Some(n) = decl.table_above {
        spec.table_above = n;
    }
    // the generated items, read back from the cache when neither the invocation nor the
    // generator changed; the engine's import and the module's name stay tokens of this call
    let key = cache::Key::new(invocation, &decl.name.to_string());
    // (the compiler's lexer directly: proc-macro2's `parse` first re-lexes the text with its own
    // unoptimised lexer, which took longer than the expansion it replaces)
    let cached = key.as_ref().and_then(cache::Key::lookup).and_then(|text| text.parse::<TokenStream>().ok());
    let items: proc_macro2::TokenStream = match cached {
        Some(items) => items.into(),
        None => {
            let plan = Plan::new(spec).map_err(|e| syn::Error::new(decl.name.span(), e))?;
            let mut items = algebra_codegen::emit::module_items(&plan);
            items
                .extend(algebra_codegen::constraint::methods(&plan).map_err(|e| syn::Error::new(decl.name.span(), e))?);
            if let Some(key) = &key {
                key.store(&items.to_string());
            }
            items
        }
    };
    // the items reach the engine through one alias: one import, no pass over the items
    let engine = algebra_codegen::paths::engine_use(decl.engine.as_ref().unwrap_or(&quote!(::algebra_core)));
    let (attrs, vis, name) = (&decl.attrs, &decl.vis, &decl.name);
    Ok(quote! {
        #(#attrs)*
        #[allow(clippy::all, unused_parens, unused_mut, unused_variables, non_snake_case, missing_docs)]
        #vis mod #name {
            #engine
            #items
        }
    })
}
