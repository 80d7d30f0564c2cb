//! The Rust emitter's sums: the shapes of [`crate::sums`] built as token streams, every
//! operand a place borrowed by reference (`acc + &x`).

use crate::ratio::Ratio;
use crate::sums::{Build, Term, chunked_sum_in, sum_in, tree_sum_in};
use proc_macro2::TokenStream;
use quote::quote;

/// Rust tokens: operands are places borrowed by reference (`acc + &x`).
pub(crate) struct Tokens;

/// `T::from_ratio(n, d)`.
fn constant(c: Ratio) -> TokenStream {
    let (n, d) = (c.0, c.1);
    quote!(T::from_ratio(#n, #d))
}

impl Build for Tokens {
    type E = TokenStream;
    fn zero() -> TokenStream {
        quote!(T::zero())
    }
    fn value(x: TokenStream, movable: bool) -> TokenStream {
        if movable { x } else { quote!(::core::clone::Clone::clone(&#x)) }
    }
    fn neg(x: TokenStream) -> TokenStream {
        quote!(__gam_engine::Ring::neg_ref(&#x))
    }
    fn scaled(k: Ratio, x: TokenStream) -> TokenStream {
        let k = constant(k);
        quote!(#k * &#x)
    }
    fn scaled_leaf(k: Ratio, x: TokenStream) -> TokenStream {
        let k = constant(k);
        quote!((#k * &#x))
    }
    fn add(acc: TokenStream, x: TokenStream, negative: bool) -> TokenStream {
        if negative { quote!(#acc - &#x) } else { quote!(#acc + &#x) }
    }
    fn add_scaled(acc: TokenStream, k: Ratio, x: TokenStream, negative: bool) -> TokenStream {
        let k = constant(k);
        if negative { quote!(#acc - #k * &#x) } else { quote!(#acc + #k * &#x) }
    }
    fn add_group(acc: TokenStream, e: TokenStream, negative: bool) -> TokenStream {
        if negative { quote!(#acc - &(#e)) } else { quote!(#acc + &(#e)) }
    }
    fn tree_add(a: TokenStream, b: TokenStream, negative: bool) -> TokenStream {
        if negative { quote!((#a - &#b)) } else { quote!((#a + &#b)) }
    }
}

/// One summand of a Rust token sum.
pub(crate) type SumTerm = Term<TokenStream>;

/// A sum of `(coefficient, operand)` terms, each operand an expression of type `T` that may be
/// used by reference (`&operand`). `movable` says the operand may be moved when it comes
/// first with coefficient 1.
pub(crate) fn sum(terms: Vec<SumTerm>) -> TokenStream {
    sum_in::<Tokens>(terms)
}

/// [`sum`] as chains of at most `chunk` terms (the kernel's
/// [`crate::product_order::ProductOrder::chain`], four unless measured otherwise), added left to right:
/// `(a + b - c + d) + (e - f - g + h)`. Used by the binary product kernels. A motor product's
/// translation outputs have 8 terms, 4 from `R x T` and 4 from `T x R`; as two chains of 4
/// they have the shape of nalgebra's dual-quaternion product (two quaternion products, then
/// one addition), which halves the dependency depth and lets LLVM's SLP vectoriser pack
/// neighbouring outputs. Measured (docs/performance.md, "Motor product shape"): 8 % to 11 %
/// faster than one chain of 8 in the tables' order on `g123inf` `Motor * Motor` (AMD EPYC),
/// where a balanced tree was slower; per-kernel exceptions are measured and listed in
/// [`crate::product_order::WISDOM`].
/// A chunk whose first term is negative is negated and subtracted, so each chunk keeps its
/// term order (the same order in neighbouring outputs) and no term is negated on its own.
pub(crate) fn chunked_sum(terms: Vec<SumTerm>, chunk: usize) -> TokenStream {
    chunked_sum_in::<Tokens>(terms, chunk)
}

/// [`sum`] as a balanced tree (`(a + b) + (c - d)`) rather than a chain, so its dependency
/// depth is `log2` of the term count. Used by the two-stage versor actions, whose second stage
/// sums products of the first stage's sums: measured in the same run (docs/performance.md),
/// the tree made the conformal point action 10% faster and the pga3 point action 12% faster,
/// while the chain stays faster for the motor product (so binary kernels keep [`sum`]). Each
/// partial sum carries its sign, so no term is negated on its own and the result is negated
/// at most once.
pub(crate) fn tree_sum(terms: Vec<SumTerm>) -> TokenStream {
    tree_sum_in::<Tokens>(terms)
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::format_ident;

    /// `n` terms `p0 .. p{n-1}` with the given signs, all borrowed.
    fn terms(signs: &[i64]) -> Vec<SumTerm> {
        signs
            .iter()
            .enumerate()
            .map(|(i, &s)| {
                let p = format_ident!("p{}", i);
                ((s, 1), quote!(#p), false)
            })
            .collect()
    }

    fn text(t: TokenStream) -> String {
        t.to_string().split_whitespace().collect()
    }

    #[test]
    fn short_sums_are_one_chain() {
        let t = terms(&[1, -1, 1, 1]);
        assert_eq!(text(chunked_sum(t.clone(), 4)), text(sum(t)));
        assert_eq!(text(sum(terms(&[1, -1, 1, 1]))), "::core::clone::Clone::clone(&p0)-&p1+&p2+&p3");
    }

    /// The motor product's translation outputs: `R x T` (4 terms) then `T x R` (4 terms), as
    /// two chains in the written order, the second subtracted when it starts negative.
    #[test]
    fn eight_terms_are_two_chains_of_four_in_order() {
        let got = text(chunked_sum(terms(&[1, 1, 1, -1, 1, -1, -1, -1]), 4));
        assert_eq!(got, "::core::clone::Clone::clone(&p0)+&p1+&p2-&p3+&(::core::clone::Clone::clone(&p4)-&p5-&p6-&p7)");
        let got = text(chunked_sum(terms(&[1, -1, 1, 1, -1, 1, 1, -1, 1]), 4));
        assert_eq!(
            got,
            "::core::clone::Clone::clone(&p0)-&p1+&p2+&p3-&(::core::clone::Clone::clone(&p4)-&p5-&p6+&p7)+&p8"
        );
    }
}
