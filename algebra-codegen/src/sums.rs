//! Sums of `coefficient x operand` terms in the three shapes the kernels use: a chain
//! ([`sum`]), chains of at most four or a kernel's measured length ([`chunked_sum`], the binary
//! products; [`crate::product_order`]) and a balanced
//! tree ([`tree_sum`], the versor actions). The shape changes only the order of the
//! floating-point additions (and so the speed and the rounding), never the exact value.
//!
//! The shapes are written once, over [`Build`]: the Rust emitter builds token streams
//! (`emit::sums::Tokens`), the other languages' emitters language-free expressions
//! ([`crate::lang::ir::Expr`]), so a C, WGSL or GLSL kernel adds in the same order as the Rust
//! kernel of the same declaration (and gives the same floating-point result).

use crate::ratio::Ratio;

/// How a sum's pieces are written: the operations [`sum`], [`chunked_sum`] and [`tree_sum`]
/// combine. `x` operands are places or values of the scalar type; the results are values.
pub(crate) trait Build {
    /// An expression.
    type E: Clone;
    /// The scalar zero.
    fn zero() -> Self::E;
    /// `x` as a value: moved when `movable`, else copied.
    fn value(x: Self::E, movable: bool) -> Self::E;
    /// `-x`.
    fn neg(x: Self::E) -> Self::E;
    /// `k · x` for a constant `k` (a chain's first term).
    fn scaled(k: Ratio, x: Self::E) -> Self::E;
    /// `k · x` as a tree leaf (parenthesised where the syntax needs it).
    fn scaled_leaf(k: Ratio, x: Self::E) -> Self::E;
    /// `acc + x` (`negative`: `acc - x`), `x` a single term.
    fn add(acc: Self::E, x: Self::E, negative: bool) -> Self::E;
    /// `acc + k · x` (`negative`: `acc - k · x`).
    fn add_scaled(acc: Self::E, k: Ratio, x: Self::E, negative: bool) -> Self::E;
    /// `acc + (e)` (`negative`: `acc - (e)`), `e` a partial sum.
    fn add_group(acc: Self::E, e: Self::E, negative: bool) -> Self::E;
    /// `(a + b)` (`negative`: `(a - b)`) inside a tree.
    fn tree_add(a: Self::E, b: Self::E, negative: bool) -> Self::E;
}

/// One summand: coefficient, operand expression, whether the operand may be moved.
pub(crate) type Term<E> = (Ratio, E, bool);

/// [`sum`] over any [`Build`].
pub(crate) fn sum_in<B: Build>(mut terms: Vec<Term<B::E>>) -> B::E {
    if terms.is_empty() {
        return B::zero();
    }
    // start with a positive term if there is one, to avoid a negation
    if let Some(p) = terms.iter().position(|(c, _, _)| c.0 > 0) {
        terms.swap(0, p);
    }
    let mut it = terms.into_iter();
    let (c, x, movable) = it.next().expect("non-empty");
    let mut acc = match c {
        (1, 1) => B::value(x, movable),
        (-1, 1) => B::neg(x),
        c => B::scaled(c, x),
    };
    for (c, x, _) in it {
        acc = match c {
            (1, 1) => B::add(acc, x, false),
            (-1, 1) => B::add(acc, x, true),
            (n, d) if n < 0 => B::add_scaled(acc, (-n, d), x, true),
            c => B::add_scaled(acc, c, x, false),
        };
    }
    acc
}

/// [`chunked_sum`] over any [`Build`]: chains of at most `chunk` terms.
pub(crate) fn chunked_sum_in<B: Build>(terms: Vec<Term<B::E>>, chunk: usize) -> B::E {
    let chunk = chunk.max(1);
    if terms.len() <= chunk {
        return sum_in::<B>(terms);
    }
    let mut chunks = Vec::new();
    let mut rest = terms;
    while !rest.is_empty() {
        let tail = rest.split_off(rest.len().min(chunk));
        chunks.push(rest);
        rest = tail;
    }
    let mut it = chunks.into_iter();
    let mut acc = sum_in::<B>(it.next().expect("more than `chunk` terms"));
    for mut chunk in it {
        if chunk.len() == 1 {
            // a lone term joins the chain (no clone of a borrowed operand)
            let ((n, d), x, _) = chunk.pop().expect("one term");
            acc = match (n.abs(), d) {
                (1, 1) => B::add(acc, x, n < 0),
                (k, d) => B::add_scaled(acc, (k, d), x, n < 0),
            };
        } else if chunk[0].0.0 > 0 {
            let e = sum_in::<B>(chunk);
            acc = B::add_group(acc, e, false);
        } else {
            let e = sum_in::<B>(chunk.into_iter().map(|((n, d), x, m)| ((-n, d), x, m)).collect());
            acc = B::add_group(acc, e, true);
        }
    }
    acc
}

/// [`tree_sum`] over any [`Build`].
pub(crate) fn tree_sum_in<B: Build>(terms: Vec<Term<B::E>>) -> B::E {
    if terms.is_empty() {
        return B::zero();
    }
    let part = tree::<B>(terms);
    match (part.neg, part.owned) {
        (true, _) => B::neg(part.e),
        (false, owned) => B::value(part.e, owned),
    }
}

/// A signed partial sum: `±e`, and whether `e` is an owned value (else a place to borrow).
struct Part<E> {
    e: E,
    neg: bool,
    owned: bool,
}

fn tree<B: Build>(mut terms: Vec<Term<B::E>>) -> Part<B::E> {
    if terms.len() == 1 {
        let (c, x, movable) = terms.pop().expect("one term");
        return match c {
            (1, 1) | (-1, 1) => Part { e: x, neg: c.0 < 0, owned: movable },
            (n, d) => Part { e: B::scaled_leaf((n.abs(), d), x), neg: n < 0, owned: true },
        };
    }
    let right = terms.split_off(terms.len() / 2);
    let (l, r) = (tree::<B>(terms), tree::<B>(right));
    // the receiver of `+`/`-` must be owned; addition commutes, and signs travel with the parts
    let (recv, arg) = match (l.owned, r.owned) {
        (true, _) => (l, r),
        (false, true) => (r, l),
        (false, false) => (Part { e: B::value(l.e, false), neg: l.neg, owned: true }, r),
    };
    let e = B::tree_add(recv.e, arg.e, recv.neg != arg.neg);
    Part { e, neg: recv.neg, owned: true }
}
