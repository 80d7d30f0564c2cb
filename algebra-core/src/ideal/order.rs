//! Monomial orders on packed monomials (lex, grevlex, the block (elimination) order) and the
//! packed layout itself: degree word, 16-bit exponent fields, word-parallel divisibility,
//! lcm and coprimality.

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

/// One word of a packed monomial.
pub(crate) type Word = u64;

/// Monomials are packed words `[degree, ...]` (see [`Packing`]), stored flat in each polynomial
/// (`super::DPoly`): no allocation per term, a few words per monomial, and grevlex compares
/// four exponents per word comparison.
pub(crate) type Mono = [Word];

/// The largest total degree (and so exponent) of a monomial the engine represents: exponents
/// are 16-bit fields with a guard bit, so that divisibility, lcm and coprimality are a few word
/// operations per four variables. A computation that would form a larger degree stops with
/// [`super::Limit::Degree`].
pub(crate) const MAX_DEGREE: u64 = (1 << (BITS - 1)) - 1;

/// Bits per exponent field.
const BITS: u32 = 16;
/// Fields per word.
const FIELDS: usize = (64 / BITS) as usize;
/// One field's bits.
const FIELD: u64 = (1 << BITS) - 1;
/// The lowest bit of each field.
const ONES: u64 = u64::MAX / FIELD;
/// The guard bit of each field.
const HIGH: u64 = ONES << (BITS - 1);
/// The value bits of each field.
const LOW: u64 = HIGH - ONES;

/// The packed layout of a ring's monomials: word 0 the total degree, then the exponents in
/// 16-bit fields, four per word, variable `i` in word `w - 1 - i / 4` at bit `16 (i % 4)`. The
/// last variable sits in the most significant field of word 1, so that after the degree,
/// comparing the words as integers (the smaller leading) is the reverse lexicographic tie-break
/// of grevlex; unused fields are 0. Every field is at most [`MAX_DEGREE`] (bit 15 clear), so
/// sums of two fields never carry into the next and the guard bit of `(b | HIGH) - a` tells
/// `a <= b` field by field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Packing {
    /// Words per monomial.
    pub(crate) w: usize,
}

impl Packing {
    /// The layout for `n` variables.
    pub(crate) fn new(n: usize) -> Self {
        Packing { w: 1 + n.div_ceil(FIELDS) }
    }

    /// Adds `k` to the exponent of variable `i` in `m` (and to its degree). Fields may carry
    /// past [`MAX_DEGREE`] here: the caller rejects the monomial by its degree afterwards.
    #[inline]
    pub(crate) fn add_exponent(&self, m: &mut [Word], i: usize, k: u32) {
        let at = self.w - 1 - i / FIELDS;
        m[at] = m[at].wrapping_add(u64::from(k) << (BITS as usize * (i % FIELDS)));
        m[0] += u64::from(k);
    }
}

/// The exponent of variable `i` in `m` (0 past the ring's variables).
#[inline]
pub(crate) fn exponent(m: &Mono, i: usize) -> u32 {
    let w = m.len();
    if i / FIELDS + 1 >= w {
        return 0;
    }
    ((m[w - 1 - i / FIELDS] >> (BITS as usize * (i % FIELDS))) & FIELD) as u32
}

/// `out := a * b`.
#[inline]
pub(crate) fn mul_into(out: &mut Vec<Word>, a: &Mono, b: &Mono) {
    out.clear();
    out.extend(a.iter().zip(b).map(|(x, y)| x + y));
}

/// `a | b`.
#[inline]
pub(crate) fn divides(a: &Mono, b: &Mono) -> bool {
    a[0] <= b[0] && a[1..].iter().zip(&b[1..]).all(|(x, y)| ((y | HIGH) - x) & HIGH == HIGH)
}

/// `b / a`, assuming `a | b`.
pub(crate) fn quotient(a: &Mono, b: &Mono) -> Vec<Word> {
    let mut q = Vec::with_capacity(b.len());
    quotient_into(&mut q, a, b);
    q
}

/// `q := b / a`, assuming `a | b`.
#[inline]
pub(crate) fn quotient_into(q: &mut Vec<Word>, a: &Mono, b: &Mono) {
    q.clear();
    q.extend(b.iter().zip(a).map(|(x, y)| x - y));
}

/// Whether the products of a monomial of degree `q_degree` with the terms of a polynomial whose
/// largest degree is `top` stay within [`MAX_DEGREE`] (so no field overflows): the one check
/// before every multiple `q·g` the engine forms (reduction steps, S-polynomials, division).
#[inline]
pub(crate) fn products_fit(q_degree: u64, top: u64) -> bool {
    q_degree + top <= MAX_DEGREE
}

/// The larger of each pair of fields.
#[inline]
fn field_max(x: u64, y: u64) -> u64 {
    let ge = ((x | HIGH) - y) & HIGH;
    let pick = (ge >> (BITS - 1)) * FIELD;
    (x & pick) | (y & !pick)
}

/// The sum of a word's fields.
#[inline]
fn field_sum(x: u64) -> u64 {
    (0..FIELDS).map(|f| (x >> (BITS as usize * f)) & FIELD).sum()
}

/// The guard bit of each non-zero field.
#[inline]
fn nonzero(x: u64) -> u64 {
    (x + LOW) & HIGH
}

/// Appends `lcm(a, b)` to `out` (a buffer of monomials side by side). The lcm of two monomials
/// of the engine is one (its fields are the larger of two valid fields); its degree may exceed
/// [`MAX_DEGREE`], which the pair's sugar check catches.
#[inline]
pub(crate) fn lcm_into(out: &mut Vec<Word>, a: &Mono, b: &Mono) {
    let at = out.len();
    out.push(0);
    out.extend(a[1..].iter().zip(&b[1..]).map(|(x, y)| field_max(*x, *y)));
    out[at] = out[at + 1..].iter().map(|&x| field_sum(x)).sum();
}

/// `lcm(a, b) == l`, without building the lcm.
#[inline]
pub(crate) fn lcm_is(a: &Mono, b: &Mono, l: &Mono) -> bool {
    a[1..].iter().zip(&b[1..]).zip(&l[1..]).all(|((x, y), z)| field_max(*x, *y) == *z)
}

/// No variable occurs in both.
pub(crate) fn coprime(a: &Mono, b: &Mono) -> bool {
    a[1..].iter().zip(&b[1..]).all(|(x, y)| nonzero(*x) & nonzero(*y) == 0)
}

/// Bit `i % 64` set when variable `i` occurs: a cheap necessary test for divisibility.
#[inline]
pub(crate) fn mask(a: &Mono) -> u64 {
    let w = a.len();
    let mut m = 0u64;
    for (k, &x) in a.iter().enumerate().skip(1) {
        let b = nonzero(x);
        let bits = (0..FIELDS).fold(0, |acc, f| acc | ((b >> (BITS as usize * f + BITS as usize - 1)) & 1) << f);
        m |= bits.rotate_left((FIELDS * (w - 1 - k) % 64) as u32);
    }
    m
}

/// Grevlex on monomials with their degree word.
#[inline(always)]
fn grevlex_cmp(a: &Mono, b: &Mono) -> Ordering {
    a[0].cmp(&b[0]).then_with(|| reverse_lex(&a[1..], &b[1..]))
}

/// On equal degrees: the smaller exponent of the last variable where they differ wins (the
/// last variable is the most significant field: the smaller word wins).
#[inline(always)]
fn reverse_lex(a: &[Word], b: &[Word]) -> Ordering {
    for (x, y) in a.iter().zip(b) {
        if x != y {
            return y.cmp(x);
        }
    }
    Ordering::Equal
}

/// Grevlex on the variables `range` alone, read field by field (the block orders).
fn block_grevlex(a: &Mono, b: &Mono, range: std::ops::Range<usize>) -> Ordering {
    let deg = |m: &Mono| range.clone().map(|i| u64::from(exponent(m, i))).sum::<u64>();
    deg(a).cmp(&deg(b)).then_with(|| {
        for i in range.clone().rev() {
            let (x, y) = (exponent(a, i), exponent(b, i));
            if x != y {
                return y.cmp(&x);
            }
        }
        Ordering::Equal
    })
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

    #[inline(never)]
    fn cmp_other(&self, a: &Mono, b: &Mono) -> Ordering {
        match *self {
            MonomialOrder::Lex => lex_cmp(a, b),
            MonomialOrder::GrevLex => grevlex_cmp(a, b),
            MonomialOrder::Elimination { first } => {
                let all = FIELDS * (a.len() - 1);
                let first = first.min(all);
                block_grevlex(a, b, 0..first).then_with(|| block_grevlex(a, b, first..all))
            }
        }
    }
}

/// Lex: the larger exponent of the first variable where they differ wins (the first variable
/// is the least significant field of the last word).
fn lex_cmp(a: &Mono, b: &Mono) -> Ordering {
    for (x, y) in a[1..].iter().zip(&b[1..]).rev() {
        if x != y {
            for s in 0..FIELDS {
                let (fx, fy) = ((x >> (BITS as usize * s)) & FIELD, (y >> (BITS as usize * s)) & FIELD);
                if fx != fy {
                    return fx.cmp(&fy);
                }
            }
        }
    }
    Ordering::Equal
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The packed monomial of the exponents `e`.
    fn m(e: &[u32]) -> Vec<Word> {
        let p = Packing::new(e.len());
        let mut out = vec![0; p.w];
        for (i, &k) in e.iter().enumerate() {
            p.add_exponent(&mut out, i, k);
        }
        out
    }

    /// The reference orders on plain exponent vectors (the textbook definitions).
    fn reference(order: MonomialOrder, a: &[u32], b: &[u32]) -> Ordering {
        let grevlex = |a: &[u32], b: &[u32]| {
            let d = |v: &[u32]| v.iter().map(|&x| u64::from(x)).sum::<u64>();
            d(a).cmp(&d(b))
                .then_with(|| a.iter().zip(b).rev().find(|(x, y)| x != y).map_or(Ordering::Equal, |(x, y)| y.cmp(x)))
        };
        match order {
            MonomialOrder::Lex => a.cmp(b),
            MonomialOrder::GrevLex => grevlex(a, b),
            MonomialOrder::Elimination { first } => {
                let k = first.min(a.len());
                grevlex(&a[..k], &b[..k]).then_with(|| grevlex(&a[k..], &b[k..]))
            }
        }
    }

    /// Every packed operation against its definition on plain exponent vectors: random
    /// monomials in 1 to 13 variables (one to four words, padding fields included), exponents
    /// small (so that many compare equal field by field) or up to the limit.
    #[test]
    fn packed_operations_match_their_definitions() {
        let mut rng = crate::test_support::Xorshift(0x5EED_0FFA_C701_2500);
        for case in 0..4000 {
            let n = 1 + (rng.next_u64() % 13) as usize;
            let top = if case % 5 == 0 { MAX_DEGREE / n as u64 } else { 3 };
            let mut exps = || -> Vec<u32> { (0..n).map(|_| (rng.next_u64() % (top + 1)) as u32).collect() };
            let (a, b) = (exps(), exps());
            let (pa, pb) = (m(&a), m(&b));
            for (i, &e) in a.iter().enumerate() {
                assert_eq!(exponent(&pa, i), e);
            }
            for order in [MonomialOrder::Lex, MonomialOrder::GrevLex, MonomialOrder::Elimination { first: n / 2 }] {
                assert_eq!(order.cmp(&pa, &pb), reference(order, &a, &b), "{order:?} {a:?} {b:?}");
            }
            let divides_ref = a.iter().zip(&b).all(|(x, y)| x <= y);
            assert_eq!(divides(&pa, &pb), divides_ref, "{a:?} | {b:?}");
            let l: Vec<u32> = a.iter().zip(&b).map(|(x, y)| *x.max(y)).collect();
            let mut buf = Vec::new();
            lcm_into(&mut buf, &pa, &pb);
            assert_eq!(buf, m(&l));
            assert!(lcm_is(&pa, &pb, &m(&l)));
            assert_eq!(coprime(&pa, &pb), a.iter().zip(&b).all(|(x, y)| *x == 0 || *y == 0));
            let bits = a.iter().enumerate().filter(|(_, e)| **e > 0).fold(0u64, |k, (i, _)| k | 1 << (i % 64));
            assert_eq!(mask(&pa), bits);
            let mut prod = Vec::new();
            mul_into(&mut prod, &pa, &pb);
            assert_eq!(prod, m(&a.iter().zip(&b).map(|(x, y)| x + y).collect::<Vec<_>>()));
            if divides_ref {
                assert_eq!(quotient(&pa, &pb), m(&a.iter().zip(&b).map(|(x, y)| y - x).collect::<Vec<_>>()));
            }
        }
        // Past 16 words the variable mask wraps: variable 70 is bit 6.
        let mut wide = vec![0; 71];
        wide[70] = 1;
        assert_eq!(mask(&m(&wide)), 1 << 6);
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
        assert_eq!(buf, [7, 6, 0x0001_0003_0002, 1, 0x0001_0000]);
        assert!(lcm_is(&m(&[2, 0, 1]), &m(&[1, 3, 0]), &buf[1..3]));
    }
}
