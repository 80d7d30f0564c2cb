//! Monomial orders on exponent vectors: lex, grevlex, and the block (elimination) order.

use std::cmp::Ordering;

/// A monomial order on the variables of a [`super::PolyRing`], in the ring's variable order
/// (`x_0 > x_1 > ...`).
///
/// ```
/// use algebra_core::ideal::{MonomialOrder, PolyRing};
/// use algebra_core::Poly;
/// let (x, y) = (Poly::var("x"), Poly::var("y"));
/// // x*y**2 vs x**2: grevlex looks at the degree first, lex at the exponent of x.
/// let f = x.clone() * y.clone() * y.clone() + x.clone() * x.clone();
/// let grevlex = PolyRing::new(["x", "y"], MonomialOrder::GrevLex);
/// let lex = PolyRing::new(["x", "y"], MonomialOrder::Lex);
/// assert_eq!(grevlex.leading_term(&f).unwrap().unwrap().to_string(), "x*y**2");
/// assert_eq!(lex.leading_term(&f).unwrap().unwrap().to_string(), "x**2");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MonomialOrder {
    /// Lexicographic: the larger exponent of the first variable where they differ wins.
    Lex,
    /// Graded reverse lexicographic: larger total degree wins; on a tie, the smaller exponent
    /// of the *last* variable where they differ wins.
    GrevLex,
    /// Block order for elimination: grevlex on the first `first` variables, ties broken by
    /// grevlex on the rest. A Gröbner basis in this order, intersected with the polynomials in
    /// the last variables only, is a basis of the elimination ideal.
    Elimination {
        /// How many leading variables are eliminated.
        first: usize,
    },
}

/// Monomials are exponent slices `[degree, e_0, ..., e_{n-1}]` (the total degree first, so
/// that graded orders decide most comparisons on one word), stored flat in each polynomial
/// (`super::DPoly`): no allocation per term.
pub(crate) type Mono = [u32];

/// `out := a * b`.
#[inline]
pub(crate) fn mul_into(out: &mut Vec<u32>, a: &Mono, b: &Mono) {
    out.clear();
    out.extend(a.iter().zip(b).map(|(x, y)| x + y));
}

/// `a | b`.
#[inline]
pub(crate) fn divides(a: &Mono, b: &Mono) -> bool {
    a.iter().zip(b).all(|(x, y)| x <= y)
}

/// `b / a`, assuming `a | b`.
pub(crate) fn quotient(a: &Mono, b: &Mono) -> Vec<u32> {
    b.iter().zip(a).map(|(x, y)| x - y).collect()
}

/// Appends `lcm(a, b)` to `out` (a buffer of monomials side by side).
#[inline]
pub(crate) fn lcm_into(out: &mut Vec<u32>, a: &Mono, b: &Mono) {
    let at = out.len();
    out.push(0);
    out.extend(a[1..].iter().zip(&b[1..]).map(|(x, y)| *x.max(y)));
    out[at] = out[at + 1..].iter().sum();
}

/// `lcm(a, b) == l`, without building the lcm.
#[inline]
pub(crate) fn lcm_is(a: &Mono, b: &Mono, l: &Mono) -> bool {
    a[1..].iter().zip(&b[1..]).zip(&l[1..]).all(|((x, y), z)| x.max(y) == z)
}

/// No variable occurs in both.
pub(crate) fn coprime(a: &Mono, b: &Mono) -> bool {
    a[1..].iter().zip(&b[1..]).all(|(x, y)| *x == 0 || *y == 0)
}

/// Bit `i % 64` set when variable `i` occurs: a cheap necessary test for divisibility.
#[inline]
pub(crate) fn mask(a: &Mono) -> u64 {
    a[1..].iter().enumerate().filter(|(_, e)| **e > 0).fold(0, |m, (i, _)| m | 1 << (i % 64))
}

/// Graded reverse lexicographic comparison of two exponent vectors (no degree word).
fn grevlex(a: &[u32], b: &[u32]) -> Ordering {
    let (da, db): (u64, u64) = (a.iter().map(|&x| u64::from(x)).sum(), b.iter().map(|&x| u64::from(x)).sum());
    da.cmp(&db).then_with(|| reverse_lex(a, b))
}

/// Grevlex on monomials with their degree word.
#[inline(always)]
fn grevlex_cmp(a: &Mono, b: &Mono) -> Ordering {
    a[0].cmp(&b[0]).then_with(|| reverse_lex(&a[1..], &b[1..]))
}

/// On equal degrees: the smaller exponent of the last variable where they differ wins.
#[inline(always)]
fn reverse_lex(a: &[u32], b: &[u32]) -> Ordering {
    for (x, y) in a.iter().zip(b).rev() {
        if x != y {
            return y.cmp(x);
        }
    }
    Ordering::Equal
}

impl MonomialOrder {
    /// Compares two monomials (`Greater` = `a` is the larger, i.e. leads). Inlined into the
    /// merges with grevlex, the order of every proof, inline; the others are calls.
    #[inline(always)]
    pub(crate) fn cmp(&self, a: &Mono, b: &Mono) -> Ordering {
        match *self {
            MonomialOrder::GrevLex => grevlex_cmp(a, b),
            _ => self.cmp_other(a, b),
        }
    }

    /// Keys that order like `self` (`w` words per monomial in `exps`, the degree first), `kw`
    /// words per monomial, for grevlex: the degree's four bytes, then `255 - e` for the
    /// exponents from the last variable to the first, packed big-endian into `u64` words, so
    /// that comparing two keys word by word compares the degrees, then finds the last variable
    /// where the exponents differ, the smaller exponent leading ([`grevlex_cmp`]). `None` for
    /// the other orders and for a degree above 255. Returns the keys and `kw`.
    pub(crate) fn sort_keys(&self, exps: &[u32], w: usize) -> Option<(Vec<u64>, usize)> {
        // an exponent is at most its monomial's degree: one test per monomial
        if *self != MonomialOrder::GrevLex || exps.chunks_exact(w).any(|m| m[0] > 255) {
            return None;
        }
        let kw = (w + 3).div_ceil(8);
        let mut keys = Vec::with_capacity(exps.len() / w * kw);
        let mut bytes = vec![0u8; kw * 8];
        for m in exps.chunks_exact(w) {
            bytes[..4].copy_from_slice(&m[0].to_be_bytes());
            for (b, &e) in bytes[4..].iter_mut().zip(m[1..].iter().rev()) {
                // `e <= degree <= 255`
                *b = 255 - e as u8;
            }
            keys.extend(bytes.chunks_exact(8).map(|c| u64::from_be_bytes(c.try_into().expect("8 bytes"))));
        }
        Some((keys, kw))
    }

    #[inline(never)]
    fn cmp_other(&self, a: &Mono, b: &Mono) -> Ordering {
        match *self {
            MonomialOrder::Lex => a[1..].cmp(&b[1..]),
            MonomialOrder::GrevLex => grevlex_cmp(a, b),
            MonomialOrder::Elimination { first } => {
                let k = (first + 1).min(a.len());
                grevlex(&a[1..k], &b[1..k]).then_with(|| grevlex(&a[k..], &b[k..]))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(e: &[u32]) -> Vec<u32> {
        std::iter::once(e.iter().sum()).chain(e.iter().copied()).collect()
    }

    #[test]
    fn textbook_comparisons() {
        // Cox, Little, O'Shea, Ch. 2 §2: x y^2 z^4 vs x^3 y^2 ... examples.
        use Ordering::*;
        assert_eq!(MonomialOrder::Lex.cmp(&m(&[1, 2, 0]), &m(&[0, 3, 4])), Greater);
        assert_eq!(MonomialOrder::Lex.cmp(&m(&[3, 2, 4]), &m(&[3, 2, 1])), Greater);
        assert_eq!(MonomialOrder::GrevLex.cmp(&m(&[4, 7, 1]), &m(&[4, 2, 3])), Greater);
        assert_eq!(MonomialOrder::GrevLex.cmp(&m(&[1, 5, 2]), &m(&[4, 1, 3])), Greater);
        // Elimination of x: any monomial with x beats any without.
        let e = MonomialOrder::Elimination { first: 1 };
        assert_eq!(e.cmp(&m(&[1, 0, 0]), &m(&[0, 5, 5])), Greater);
        assert_eq!(e.cmp(&m(&[1, 0, 1]), &m(&[1, 1, 0])), Less);
    }

    #[test]
    fn lcm_into_appends_side_by_side() {
        // lcm(x^2 z, x y^3) = x^2 y^3 z, then lcm(1, y) = y after it in the same buffer.
        let mut buf = vec![7];
        lcm_into(&mut buf, &m(&[2, 0, 1]), &m(&[1, 3, 0]));
        lcm_into(&mut buf, &m(&[0, 0, 0]), &m(&[0, 1, 0]));
        assert_eq!(buf, [7, 6, 2, 3, 1, 1, 0, 1, 0]);
        assert!(lcm_is(&m(&[2, 0, 1]), &m(&[1, 3, 0]), &buf[1..5]));
    }
}
