//! Sums of `coefficient x operand` terms as token streams, in the three shapes the kernels
//! use: a chain ([`sum`]), chains of at most four ([`chunked_sum`], the binary products) and a
//! balanced tree ([`tree_sum`], the versor actions). The shape changes only the order of the
//! floating-point additions (and so the speed and the rounding), never the exact value.

use crate::plan::Ratio;
use proc_macro2::TokenStream;
use quote::quote;

/// `T::from_ratio(n, d)`.
fn constant(c: Ratio) -> TokenStream {
    let (n, d) = (c.0, c.1);
    quote!(T::from_ratio(#n, #d))
}

/// One summand: coefficient, operand expression, whether the operand may be moved.
pub(super) type SumTerm = (Ratio, TokenStream, bool);

/// A sum of `(coefficient, operand)` terms, each operand an expression of type `T` that may be
/// used by reference (`&operand`). `movable` says the operand may be moved when it comes
/// first with coefficient 1.
pub(super) fn sum(mut terms: Vec<SumTerm>) -> TokenStream {
    if terms.is_empty() {
        return quote!(T::zero());
    }
    // start with a positive term if there is one, to avoid a negation
    if let Some(p) = terms.iter().position(|(c, _, _)| c.0 > 0) {
        terms.swap(0, p);
    }
    let mut it = terms.into_iter();
    let (c, x, movable) = it.next().expect("non-empty");
    let mut acc = match c {
        (1, 1) if movable => x,
        (1, 1) => quote!(::core::clone::Clone::clone(&#x)),
        (-1, 1) => quote!(::algebra_core::Ring::neg_ref(&#x)),
        c => {
            let k = constant(c);
            quote!(#k * &#x)
        }
    };
    for (c, x, _) in it {
        acc = match c {
            (1, 1) => quote!(#acc + &#x),
            (-1, 1) => quote!(#acc - &#x),
            (n, d) if n < 0 => {
                let k = constant((-n, d));
                quote!(#acc - #k * &#x)
            }
            c => {
                let k = constant(c);
                quote!(#acc + #k * &#x)
            }
        };
    }
    acc
}

/// The longest chain [`chunked_sum`] emits before starting a new one.
const CHUNK: usize = 4;

/// [`sum`] as chains of at most [`CHUNK`] terms, added left to right:
/// `(a + b - c + d) + (e - f - g + h)`. Used by the binary product kernels. A motor product's
/// translation outputs have 8 terms, 4 from `R x T` and 4 from `T x R`; as two chains of 4
/// they have the shape of nalgebra's dual-quaternion product (two quaternion products, then
/// one addition), which halves the dependency depth and lets LLVM's SLP vectoriser pack
/// neighbouring outputs. Measured (docs/performance.md, "Motor product shape"): 8 % to 11 %
/// faster than one chain of 8 on `g123inf` `Motor * Motor`, where a balanced tree was slower.
/// A chunk whose first term is negative is negated and subtracted, so each chunk keeps its
/// term order (the same order in neighbouring outputs) and no term is negated on its own.
pub(super) fn chunked_sum(terms: Vec<SumTerm>) -> TokenStream {
    if terms.len() <= CHUNK {
        return sum(terms);
    }
    let mut chunks = Vec::new();
    let mut rest = terms;
    while !rest.is_empty() {
        let tail = rest.split_off(rest.len().min(CHUNK));
        chunks.push(rest);
        rest = tail;
    }
    let mut it = chunks.into_iter();
    let mut acc = sum(it.next().expect("more than CHUNK terms"));
    for mut chunk in it {
        if chunk.len() == 1 {
            // a lone term joins the chain (no clone of a borrowed operand)
            let ((n, d), x, _) = chunk.pop().expect("one term");
            let k = constant((n.abs(), d));
            acc = match (n.abs(), d, n < 0) {
                (1, 1, false) => quote!(#acc + &#x),
                (1, 1, true) => quote!(#acc - &#x),
                (_, _, false) => quote!(#acc + #k * &#x),
                (_, _, true) => quote!(#acc - #k * &#x),
            };
        } else if chunk[0].0.0 > 0 {
            let e = sum(chunk);
            acc = quote!(#acc + &(#e));
        } else {
            let e = sum(chunk.into_iter().map(|((n, d), x, m)| ((-n, d), x, m)).collect());
            acc = quote!(#acc - &(#e));
        }
    }
    acc
}

/// [`sum`] as a balanced tree (`(a + b) + (c - d)`) rather than a chain, so its dependency
/// depth is `log2` of the term count. Used by the two-stage versor actions, whose second stage
/// sums products of the first stage's sums: measured in the same run (docs/performance.md),
/// the tree made the conformal point action 10% faster and the pga3 point action 12% faster,
/// while the chain stays faster for the motor product (so binary kernels keep [`sum`]). Each
/// partial sum carries its sign, so no term is negated on its own and the result is negated
/// at most once.
pub(super) fn tree_sum(terms: Vec<SumTerm>) -> TokenStream {
    if terms.is_empty() {
        return quote!(T::zero());
    }
    let part = tree(terms);
    match (part.neg, part.owned) {
        (true, _) => {
            let e = part.e;
            quote!(::algebra_core::Ring::neg_ref(&#e))
        }
        (false, true) => part.e,
        (false, false) => {
            let e = part.e;
            quote!(::core::clone::Clone::clone(&#e))
        }
    }
}

/// A signed partial sum: `±e`, and whether `e` is an owned `T` (else a place to borrow).
struct Part {
    e: TokenStream,
    neg: bool,
    owned: bool,
}

fn tree(mut terms: Vec<SumTerm>) -> Part {
    if terms.len() == 1 {
        let (c, x, movable) = terms.pop().expect("one term");
        return match c {
            (1, 1) | (-1, 1) => Part { e: x, neg: c.0 < 0, owned: movable },
            (n, d) => {
                let k = constant((n.abs(), d));
                Part { e: quote!((#k * &#x)), neg: n < 0, owned: true }
            }
        };
    }
    let right = terms.split_off(terms.len() / 2);
    let (l, r) = (tree(terms), tree(right));
    // the receiver of `+`/`-` must be owned; addition commutes, and signs travel with the parts
    let (recv, arg) = match (l.owned, r.owned) {
        (true, _) => (l, r),
        (false, true) => (r, l),
        (false, false) => {
            let e = l.e;
            (Part { e: quote!(::core::clone::Clone::clone(&#e)), neg: l.neg, owned: true }, r)
        }
    };
    let (re, ae) = (recv.e, arg.e);
    let e = if recv.neg == arg.neg { quote!((#re + &#ae)) } else { quote!((#re - &#ae)) };
    Part { e, neg: recv.neg, owned: true }
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
        assert_eq!(text(chunked_sum(t.clone())), text(sum(t)));
        assert_eq!(text(sum(terms(&[1, -1, 1, 1]))), "::core::clone::Clone::clone(&p0)-&p1+&p2+&p3");
    }

    /// The motor product's translation outputs: `R x T` (4 terms) then `T x R` (4 terms), as
    /// two chains in the written order, the second subtracted when it starts negative.
    #[test]
    fn eight_terms_are_two_chains_of_four_in_order() {
        let got = text(chunked_sum(terms(&[1, 1, 1, -1, 1, -1, -1, -1])));
        assert_eq!(got, "::core::clone::Clone::clone(&p0)+&p1+&p2-&p3+&(::core::clone::Clone::clone(&p4)-&p5-&p6-&p7)");
        let got = text(chunked_sum(terms(&[1, -1, 1, 1, -1, 1, 1, -1, 1])));
        assert_eq!(
            got,
            "::core::clone::Clone::clone(&p0)-&p1+&p2+&p3-&(::core::clone::Clone::clone(&p4)-&p5-&p6+&p7)+&p8"
        );
    }
}
