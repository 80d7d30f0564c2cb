//! The Rust tokens of a [`ConstrainedKernel`]: shared versor monomials, then each output as
//! `Σ_c (Σ_|k| k (±m ± m ...)) · b_c`.

use super::{ConstrainedKernel, KTerm, group};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};
use std::collections::BTreeMap;

impl ConstrainedKernel {
    /// The kernel as a Rust function `name<T: Ring>(a: &[T; NA], b: &[T; NB]) -> [T; K]` over
    /// the two inputs' coefficients (in their types' element order), returning the computed
    /// outputs in [`ConstrainedKernel::outputs`] order, with [`ConstrainedKernel::doc`] as its
    /// docs. It needs `algebra_core::Ring` in scope.
    ///
    /// ```
    /// # #[cfg(feature = "constraints")] {
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::ModuleSpec;
    /// use algebra_codegen::constraint::{Constraint, ConstraintKind, constrained_product};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let types = ModuleSpec::parse_types("Rotor=even;Vector=grade1", &alg).unwrap();
    /// let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
    /// let unit = [Constraint { ty: 0, kind: ConstraintKind::Unit }];
    /// let k = constrained_product(&spec, 0, 1, &unit).unwrap();
    /// let f: syn::ItemFn = syn::parse2(k.tokens("rotor_times_vector", 4, 3)).unwrap();
    /// assert_eq!((f.sig.ident.to_string(), f.sig.inputs.len()), ("rotor_times_vector".to_string(), 2));
    /// # }
    /// ```
    pub fn tokens(&self, name: &str, left_len: usize, right_len: usize) -> TokenStream {
        let f = format_ident!("{}", name);
        let doc = self.doc();
        let body = self.body();
        let (na, nb, n_out) = (
            Literal::usize_unsuffixed(left_len),
            Literal::usize_unsuffixed(right_len),
            Literal::usize_unsuffixed(self.outputs.len()),
        );
        quote! {
            #(#[doc = #doc])*
            pub fn #f<T: Ring>(a: &[T; #na], b: &[T; #nb]) -> [T; #n_out] #body
        }
    }

    /// The kernel's block over coefficient arrays `a` and `b` (of a type `T` bound by `Ring`):
    /// the shared left monomials, then the array of the computed outputs.
    pub(crate) fn body(&self) -> TokenStream {
        let shared = self.left_monomials.iter().enumerate().map(|(i, m)| {
            let id = format_ident!("m{}", i);
            let p = owned(product("a", m));
            quote! { let #id = #p; }
        });
        let outs = self.outputs.iter().map(|(_, ts)| {
            let groups: Vec<(bool, Expr)> =
                group(ts).into_iter().map(|(right, inner)| group_expr(&right, &inner)).collect();
            owned(signed_sum(&groups))
        });
        quote! {
            {
                #(#shared)*
                [#(#outs),*]
            }
        }
    }
}

/// One operand group `(Σ_|c| c (±m ± m ...)) · b-monomial`, with its sign.
fn group_expr(right: &[(usize, u32)], inner: &[&KTerm]) -> (bool, Expr) {
    let mut by_coeff: BTreeMap<(i64, i64), Vec<&KTerm>> = BTreeMap::new();
    for t in inner {
        by_coeff.entry((t.coeff.0.abs(), t.coeff.1)).or_default().push(t);
    }
    let parts: Vec<(bool, Expr)> = by_coeff
        .into_iter()
        .map(|((n, d), ts)| {
            let signed: Vec<(bool, Expr)> = ts.iter().map(|t| (t.coeff.0 < 0, left_factor(t.left))).collect();
            let (neg, sum) = single_or_sum(&signed);
            if (n, d) == (1, 1) {
                return (neg, sum);
            }
            let (n, d, s) = (Literal::i64_unsuffixed(n), Literal::i64_unsuffixed(d), paren(&sum));
            (neg, Expr { ts: quote! { T::from_ratio(#n, #d).mul_ref(&#s) }, place: false })
        })
        .collect();
    let (neg, inner_sum) = single_or_sum(&parts);
    if right.is_empty() {
        return (neg, inner_sum);
    }
    let r = product("b", right);
    if inner_sum.ts.to_string() == "T :: one ()" {
        return (neg, r);
    }
    let (l, r) = (paren(&inner_sum), r.ts);
    (neg, Expr { ts: quote! { #l.mul_ref(&#r) }, place: false })
}

/// A single signed term keeps its sign outside; several become one sum.
fn single_or_sum(terms: &[(bool, Expr)]) -> (bool, Expr) {
    match terms {
        [(neg, e)] => (*neg, e.clone()),
        _ => (false, signed_sum(terms)),
    }
}

/// An expression of the emitted code; `place` when it names a value (`a[0]`, `m3`) that must
/// be cloned to be returned.
#[derive(Clone)]
struct Expr {
    ts: TokenStream,
    place: bool,
}

fn owned(e: Expr) -> TokenStream {
    let ts = e.ts;
    if e.place {
        quote! { #ts.clone() }
    } else {
        ts
    }
}

fn paren(e: &Expr) -> TokenStream {
    let ts = &e.ts;
    if e.place {
        ts.clone()
    } else {
        quote! { (#ts) }
    }
}

fn left_factor(left: Option<usize>) -> Expr {
    match left {
        Some(i) => {
            let id = format_ident!("m{}", i);
            Expr { ts: quote! { #id }, place: true }
        }
        None => Expr { ts: quote! { T::one() }, place: false },
    }
}

/// The product of `vars[i]^e` over a monomial.
fn product(vars: &str, m: &[(usize, u32)]) -> Expr {
    let v = format_ident!("{}", vars);
    let factors: Vec<TokenStream> = m
        .iter()
        .flat_map(|&(i, e)| std::iter::repeat_n(i, e as usize))
        .map(|i| {
            let i = Literal::usize_unsuffixed(i);
            quote! { #v[#i] }
        })
        .collect();
    match factors.split_first() {
        Some((first, [])) => Expr { ts: first.clone(), place: true },
        Some((first, rest)) => Expr { ts: quote! { #first #(.mul_ref(&#rest))* }, place: false },
        None => Expr { ts: quote! { T::one() }, place: false },
    }
}

/// `±x0 ± x1 ...` as `x0.add_ref(&x1).sub_ref(&x2)` (a leading minus as `neg_ref`).
fn signed_sum(terms: &[(bool, Expr)]) -> Expr {
    let Some(((neg, first), rest)) = terms.split_first() else {
        return Expr { ts: quote! { T::zero() }, place: false };
    };
    if rest.is_empty() && !neg {
        return first.clone();
    }
    let head = paren(first);
    let head = if *neg {
        quote! { #head.neg_ref() }
    } else {
        head
    };
    let tail = rest.iter().map(|(neg, t)| {
        let t = &t.ts;
        if *neg {
            quote! { .sub_ref(&#t) }
        } else {
            quote! { .add_ref(&#t) }
        }
    });
    Expr { ts: quote! { #head #(#tail)* }, place: false }
}
