//! Where generated code finds the engine. [`crate::emit`] writes every engine path as
//! `__gam_engine::...` ([`ENGINE`]), and the module imports the engine under that name once
//! ([`engine_use`]), so the emitter stays independent of how the user reaches the engine
//! and no pass over the emitted tokens is needed:
//! - the `algebra!` macro imports `::algebra_core` (its default) or the front door's
//!   `$crate::__engine` (its `crate PATH;` option) as `__gam_engine`. Rewriting every path of
//!   a 35k-line module instead took about 0.13 s of each expansion in an unoptimised proc
//!   macro;
//! - [`crate::emit::module_with`] (the module `gam codegen` prints for a crate that depends on
//!   algebra-core) writes the paths out as `::algebra_core::...` ([`with_engine_path`]);
//! - the standalone file ([`crate::standalone`]) points the paths at its own inlined items
//!   ([`map_engine_paths`]).

use proc_macro2::{Group, Ident, Punct, Spacing, TokenStream, TokenTree};
use quote::quote;

/// The name generated code reaches the engine by.
pub const ENGINE: &str = "__gam_engine";

/// The import that makes [`ENGINE`] name `engine` (a path to algebra-core or a re-export of
/// it, such as the front door's `$crate::__engine`), placed once in the generated module.
///
/// ```
/// use quote::quote;
/// let line = algebra_codegen::paths::engine_use(&quote!(::gam_ga::__engine));
/// assert_eq!(line.to_string(), quote!(#[allow(unused_imports)] use ::gam_ga::__engine as __gam_engine;).to_string());
/// ```
pub fn engine_use(engine: &TokenStream) -> TokenStream {
    let alias = Ident::new(ENGINE, proc_macro2::Span::call_site());
    quote!(#[allow(unused_imports)] use #engine as #alias;)
}

/// Replaces each path `__gam_engine::a::b::C` by `replace(["a", "b", "C"])` (segments up to
/// the first non-identifier after `::`, e.g. before `<`, `{` or `(`), in groups too.
pub fn map_engine_paths(tokens: TokenStream, replace: &dyn Fn(&[Ident]) -> TokenStream) -> TokenStream {
    let tts: Vec<TokenTree> = tokens.into_iter().collect();
    let mut out = TokenStream::new();
    let mut i = 0;
    while i < tts.len() {
        if matches!(&tts[i], TokenTree::Ident(id) if id == ENGINE) && is_path_sep(&tts, i + 1) {
            i += 1;
            let mut segments = Vec::new();
            while is_path_sep(&tts, i) {
                let Some(TokenTree::Ident(id)) = tts.get(i + 2) else { break };
                segments.push(id.clone());
                i += 3;
            }
            out.extend(replace(&segments));
            continue;
        }
        match &tts[i] {
            TokenTree::Group(g) => {
                let mut ng = Group::new(g.delimiter(), map_engine_paths(g.stream(), replace));
                ng.set_span(g.span());
                out.extend([TokenTree::Group(ng)]);
            }
            tt => out.extend([tt.clone()]),
        }
        i += 1;
    }
    out
}

/// Whether `tts[i..]` starts with `::`.
fn is_path_sep(tts: &[TokenTree], i: usize) -> bool {
    matches!((tts.get(i), tts.get(i + 1)),
        (Some(TokenTree::Punct(a)), Some(TokenTree::Punct(b)))
            if a.as_char() == ':' && a.spacing() == Spacing::Joint && b.as_char() == ':')
}

/// `prefix::segments...` as tokens.
pub(crate) fn join_path(prefix: TokenStream, segments: &[Ident]) -> TokenStream {
    let mut out = prefix;
    for s in segments {
        out.extend([
            TokenTree::Punct(Punct::new(':', Spacing::Joint)),
            TokenTree::Punct(Punct::new(':', Spacing::Alone)),
            TokenTree::Ident(s.clone()),
        ]);
    }
    out
}

/// Generated tokens with every engine path written out through `engine` instead of the
/// [`ENGINE`] alias (for code placed where the alias is not imported).
///
/// ```
/// use quote::quote;
/// let code = quote!(impl<T: __gam_engine::Ring> X<T> { fn f() -> __gam_engine::ops::Grade {} });
/// let moved = algebra_codegen::paths::with_engine_path(code, &quote!(::gam_ga::__engine));
/// assert_eq!(
///     moved.to_string(),
///     quote!(impl<T: ::gam_ga::__engine::Ring> X<T> { fn f() -> ::gam_ga::__engine::ops::Grade {} }).to_string()
/// );
/// ```
pub fn with_engine_path(tokens: TokenStream, engine: &TokenStream) -> TokenStream {
    map_engine_paths(tokens, &|segments| join_path(engine.clone(), segments))
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::quote;

    #[test]
    fn leaves_other_paths_and_groups_alone() {
        let code =
            quote!(pub use __gam_engine::ops::{A, B}; ::core::clone::Clone::clone(&x); algebra_core::X; ::__gam_engine);
        let moved = with_engine_path(code, &quote!(crate::engine));
        assert_eq!(
            moved.to_string(),
            quote!(pub use crate::engine::ops::{A, B}; ::core::clone::Clone::clone(&x); algebra_core::X; ::__gam_engine).to_string()
        );
    }
}
