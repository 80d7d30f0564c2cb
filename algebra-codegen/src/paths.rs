//! Where generated code finds the engine. [`crate::emit`] writes every engine path as
//! `::algebra_core::...`; this module rewrites those paths afterwards, so the emitter stays
//! independent of how the user reaches the engine:
//! - [`with_engine_path`]: through another path, e.g. the front door's `$crate::__engine`
//!   (the `algebra!` macro's `crate PATH;` option);
//! - the standalone file ([`crate::standalone`]) points them at its own inlined items.

use proc_macro2::{Group, Ident, Punct, Spacing, TokenStream, TokenTree};

/// Replaces each path `::algebra_core::a::b::C` by `replace(["a", "b", "C"])` (segments up to
/// the first non-identifier after `::`, e.g. before `<`, `{` or `(`), in groups too.
pub fn map_engine_paths(tokens: TokenStream, replace: &dyn Fn(&[Ident]) -> TokenStream) -> TokenStream {
    let tts: Vec<TokenTree> = tokens.into_iter().collect();
    let mut out = TokenStream::new();
    let mut i = 0;
    while i < tts.len() {
        if is_path_sep(&tts, i) && matches!(&tts.get(i + 2), Some(TokenTree::Ident(id)) if id == "algebra_core") {
            i += 3;
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

/// Generated tokens with every `::algebra_core` path reached through `engine` instead (a path
/// to a re-export of algebra-core, such as the front door's `::gam_ga::__engine`).
///
/// ```
/// use quote::quote;
/// let code = quote!(impl<T: ::algebra_core::Ring> X<T> { fn f() -> ::algebra_core::ops::Grade {} });
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
        let code = quote!(pub use ::algebra_core::ops::{A, B}; ::core::clone::Clone::clone(&x); algebra_core::X);
        let moved = with_engine_path(code, &quote!(crate::engine));
        assert_eq!(
            moved.to_string(),
            quote!(pub use crate::engine::ops::{A, B}; ::core::clone::Clone::clone(&x); algebra_core::X).to_string()
        );
    }
}
