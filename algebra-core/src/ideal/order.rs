//! Monomial orders on packed monomials (lex, grevlex, the block (elimination) order) and the
//! packed layout itself: degree word, 8- or 16-bit exponent fields, word-parallel divisibility,
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
/// four (or eight) exponents per word comparison.
pub(crate) type Mono = [Word];

/// The largest total degree (and so exponent) of a monomial the engine represents, in its
/// [`Fields::Wide`] layout: exponents are 16-bit fields with a guard bit, so that
/// divisibility, lcm and coprimality are a few word operations per four variables. A
/// computation that would form a larger degree stops with [`super::Limit::Degree`].
pub(crate) const MAX_DEGREE: u64 = Fields::Wide.max_degree();

/// The width of the exponent fields of a packing. Every field is at most the layout's
/// [`Fields::max_degree`] (its top bit, the guard bit, clear), so sums of two fields never
/// carry into the next and the guard bit of `(b | HIGH) - a` tells `a <= b` field by field.
///
/// A computation runs in [`Fields::Narrow`] when its input allows (degrees up to 127: eight
/// exponents per word, fewer words to copy and compare per term, as Singular's tail rings
/// choose the fewest exponent bits that fit) and again in [`Fields::Wide`] when a degree
/// passes 127 on the way.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Fields {
    /// 8-bit fields, eight per word: total degrees up to 127.
    Narrow,
    /// 16-bit fields, four per word: total degrees up to 32767.
    Wide,
}

impl Fields {
    /// Bits per exponent field.
    #[inline]
    pub(crate) const fn bits(self) -> u32 {
        match self {
            Fields::Narrow => 8,
            Fields::Wide => 16,
        }
    }

    /// Fields per word.
    #[inline]
    pub(crate) const fn per_word(self) -> usize {
        (64 / self.bits()) as usize
    }

    /// One field's bits.
    #[inline]
    const fn field(self) -> u64 {
        (1 << self.bits()) - 1
    }

    /// The lowest bit of each field.
    #[inline]
    const fn ones(self) -> u64 {
        u64::MAX / self.field()
    }

    /// The guard bit of each field.
    #[inline]
    const fn high(self) -> u64 {
        self.ones() << (self.bits() - 1)
    }

    /// The value bits of each field.
    #[inline]
    const fn low(self) -> u64 {
        self.high() - self.ones()
    }

    /// The largest total degree (and exponent) of the layout.
    #[inline]
    pub(crate) const fn max_degree(self) -> u64 {
        (1 << (self.bits() - 1)) - 1
    }

    /// The exponent of variable `i` in `m` (0 past the ring's variables).
    #[inline]
    pub(crate) fn exponent(self, m: &Mono, i: usize) -> u32 {
        let (w, f) = (m.len(), self.per_word());
        if i / f + 1 >= w {
            return 0;
        }
        ((m[w - 1 - i / f] >> (self.bits() as usize * (i % f))) & self.field()) as u32
    }

    /// `a | b`.
    #[inline]
    pub(crate) fn divides(self, a: &Mono, b: &Mono) -> bool {
        let high = self.high();
        a[0] <= b[0] && a[1..].iter().zip(&b[1..]).all(|(x, y)| ((y | high) - x) & high == high)
    }

    /// Whether the products of a monomial of degree `q_degree` with the terms of a polynomial
    /// whose largest degree is `top` stay within [`Fields::max_degree`] (so no field
    /// overflows): the one check before every multiple `q·g` the engine forms (reduction
    /// steps, S-polynomials, division).
    #[inline]
    pub(crate) fn products_fit(self, q_degree: u64, top: u64) -> bool {
        q_degree + top <= self.max_degree()
    }

    /// The larger of each pair of fields.
    #[inline]
    fn field_max(self, x: u64, y: u64) -> u64 {
        let high = self.high();
        let ge = ((x | high) - y) & high;
        let pick = (ge >> (self.bits() - 1)) * self.field();
        (x & pick) | (y & !pick)
    }

    /// The sum of a word's fields.
    #[inline]
    fn field_sum(self, x: u64) -> u64 {
        (0..self.per_word()).map(|f| (x >> (self.bits() as usize * f)) & self.field()).sum()
    }

    /// The guard bit of each non-zero field.
    #[inline]
    fn nonzero(self, x: u64) -> u64 {
        (x + self.low()) & self.high()
    }

    /// Appends `lcm(a, b)` to `out` (a buffer of monomials side by side). The lcm of two
    /// monomials of the engine is one (its fields are the larger of two valid fields); its
    /// degree may exceed [`Fields::max_degree`], which the pair's sugar check catches.
    #[inline]
    pub(crate) fn lcm_into(self, out: &mut Vec<Word>, a: &Mono, b: &Mono) {
        let at = out.len();
        out.push(0);
        out.extend(a[1..].iter().zip(&b[1..]).map(|(x, y)| self.field_max(*x, *y)));
        out[at] = out[at + 1..].iter().map(|&x| self.field_sum(x)).sum();
    }

    /// `lcm(a, b) == l`, without building the lcm.
    #[inline]
    pub(crate) fn lcm_is(self, a: &Mono, b: &Mono, l: &Mono) -> bool {
        a[1..].iter().zip(&b[1..]).zip(&l[1..]).all(|((x, y), z)| self.field_max(*x, *y) == *z)
    }

    /// No variable occurs in both.
    pub(crate) fn coprime(self, a: &Mono, b: &Mono) -> bool {
        a[1..].iter().zip(&b[1..]).all(|(x, y)| self.nonzero(*x) & self.nonzero(*y) == 0)
    }

    /// Bit `i % 64` set when variable `i` occurs: a cheap necessary test for divisibility.
    #[inline]
    pub(crate) fn mask(self, a: &Mono) -> u64 {
        match self {
            Fields::Narrow => mask_in(Fields::Narrow, a),
            Fields::Wide => mask_in(Fields::Wide, a),
        }
    }
}

/// [`Fields::mask`] with the layout a constant of each call site (its loop over the fields
/// unrolled).
#[inline(always)]
fn mask_in(fields: Fields, a: &Mono) -> u64 {
    let (w, per, bits) = (a.len(), fields.per_word(), fields.bits() as usize);
    let mut m = 0u64;
    for (k, &x) in a.iter().enumerate().skip(1) {
        let b = fields.nonzero(x);
        let set = (0..per).fold(0, |acc, f| acc | ((b >> (bits * f + bits - 1)) & 1) << f);
        m |= set.rotate_left((per * (w - 1 - k) % 64) as u32);
    }
    m
}

/// The packed layout of a ring's monomials: word 0 the total degree, then the exponents in
/// fields of [`Fields::bits`] bits, `f` per word ([`Fields::per_word`]), variable `i` in word
/// `w - 1 - i / f` at bit `bits · (i % f)`. The last variable sits in the most significant
/// field of word 1, so that after the degree, comparing the words as integers (the smaller
/// leading) is the reverse lexicographic tie-break of grevlex; unused fields are 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Packing {
    /// Words per monomial.
    pub(crate) w: usize,
    /// The exponent fields.
    pub(crate) fields: Fields,
}

impl Packing {
    /// The layout for `n` variables in fields of `fields`.
    pub(crate) fn new(n: usize, fields: Fields) -> Self {
        Packing { w: 1 + n.div_ceil(fields.per_word()), fields }
    }

    /// Adds `k` to the exponent of variable `i` in `m` (and to its degree). Fields may carry
    /// past the layout's largest exponent here: the caller rejects the monomial by its degree
    /// afterwards.
    #[inline]
    pub(crate) fn add_exponent(&self, m: &mut [Word], i: usize, k: u32) {
        let f = self.fields.per_word();
        let at = self.w - 1 - i / f;
        m[at] = m[at].wrapping_add(u64::from(k) << (self.fields.bits() as usize * (i % f)));
        m[0] += u64::from(k);
    }
}

/// A [`MonomialOrder`] on monomials of one [`Fields`] layout: what the engine's functions
/// compare and test divisibility with (grevlex needs no layout; lex, the block orders and the
/// field tests read the fields).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Order {
    pub(crate) kind: MonomialOrder,
    pub(crate) fields: Fields,
}

impl std::ops::Deref for Order {
    type Target = Fields;

    fn deref(&self) -> &Fields {
        &self.fields
    }
}

/// Appends the monomial `m` to `out` (monomials side by side). A copy of a slice whose
/// length is known only at run time is a call to `memcpy`, per term of every merge; for the
/// usual widths the copy is of a fixed-size array, a few moves inline.
#[inline(always)]
pub(crate) fn push_mono(out: &mut Vec<Word>, m: &Mono) {
    match m.len() {
        2 => out.extend_from_slice(&[m[0], m[1]]),
        3 => out.extend_from_slice(&[m[0], m[1], m[2]]),
        4 => out.extend_from_slice(&[m[0], m[1], m[2], m[3]]),
        5 => out.extend_from_slice(&[m[0], m[1], m[2], m[3], m[4]]),
        6 => out.extend_from_slice(&[m[0], m[1], m[2], m[3], m[4], m[5]]),
        _ => out.extend_from_slice(m),
    }
}

/// `out := a * b`.
#[inline]
pub(crate) fn mul_into(out: &mut Vec<Word>, a: &Mono, b: &Mono) {
    out.clear();
    out.extend(a.iter().zip(b).map(|(x, y)| x + y));
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

impl Order {
    /// The order `kind` on monomials in fields of `fields`.
    pub(crate) fn new(kind: MonomialOrder, fields: Fields) -> Self {
        Order { kind, fields }
    }

    /// Compares two monomials (`Greater` = `a` is the larger, i.e. leads). Inlined into the
    /// merges with grevlex, the order of every proof, inline; the others are calls.
    #[inline(always)]
    pub(crate) fn cmp(&self, a: &Mono, b: &Mono) -> Ordering {
        match self.kind {
            MonomialOrder::GrevLex => grevlex_cmp(a, b),
            _ => self.cmp_other(a, b),
        }
    }

    #[inline(never)]
    fn cmp_other(&self, a: &Mono, b: &Mono) -> Ordering {
        match self.kind {
            MonomialOrder::Lex => self.lex_cmp(a, b),
            MonomialOrder::GrevLex => grevlex_cmp(a, b),
            MonomialOrder::Elimination { first } => {
                let all = self.per_word() * (a.len() - 1);
                let first = first.min(all);
                self.block_grevlex(a, b, 0..first).then_with(|| self.block_grevlex(a, b, first..all))
            }
        }
    }

    /// Lex: the larger exponent of the first variable where they differ wins (the first
    /// variable is the least significant field of the last word).
    fn lex_cmp(&self, a: &Mono, b: &Mono) -> Ordering {
        let (bits, field) = (self.bits() as usize, self.field());
        for (x, y) in a[1..].iter().zip(&b[1..]).rev() {
            if x != y {
                for s in 0..self.per_word() {
                    let (fx, fy) = ((x >> (bits * s)) & field, (y >> (bits * s)) & field);
                    if fx != fy {
                        return fx.cmp(&fy);
                    }
                }
            }
        }
        Ordering::Equal
    }

    /// Grevlex on the variables `range` alone, read field by field (the block orders).
    fn block_grevlex(&self, a: &Mono, b: &Mono, range: std::ops::Range<usize>) -> Ordering {
        let deg = |m: &Mono| range.clone().map(|i| u64::from(self.exponent(m, i))).sum::<u64>();
        deg(a).cmp(&deg(b)).then_with(|| {
            for i in range.clone().rev() {
                let (x, y) = (self.exponent(a, i), self.exponent(b, i));
                if x != y {
                    return y.cmp(&x);
                }
            }
            Ordering::Equal
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The packed monomial of the exponents `e` in fields of `f`.
    fn m_in(f: Fields, e: &[u32]) -> Vec<Word> {
        let p = Packing::new(e.len(), f);
        let mut out = vec![0; p.w];
        for (i, &k) in e.iter().enumerate() {
            p.add_exponent(&mut out, i, k);
        }
        out
    }

    /// [`m_in`] in the wide layout.
    fn m(e: &[u32]) -> Vec<Word> {
        m_in(Fields::Wide, e)
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

    /// Every packed operation against its definition on plain exponent vectors, in both
    /// layouts: random monomials in 1 to 20 variables (one to five words, padding fields
    /// included), exponents small (so that many compare equal field by field) or up to the
    /// layout's limit.
    #[test]
    fn packed_operations_match_their_definitions() {
        let mut rng = crate::test_support::Xorshift(0x5EED_0FFA_C701_2500);
        for fields in [Fields::Narrow, Fields::Wide] {
            let m = |e: &[u32]| m_in(fields, e);
            for case in 0..4000 {
                let n = 1 + (rng.next_u64() % 20) as usize;
                let top = if case % 5 == 0 { fields.max_degree() / n as u64 } else { 3 };
                let mut exps = || -> Vec<u32> { (0..n).map(|_| (rng.next_u64() % (top + 1)) as u32).collect() };
                let (a, b) = (exps(), exps());
                let (pa, pb) = (m(&a), m(&b));
                assert_eq!(pa.len(), 1 + n.div_ceil(64 / fields.bits() as usize));
                for (i, &e) in a.iter().enumerate() {
                    assert_eq!(fields.exponent(&pa, i), e);
                }
                for kind in [MonomialOrder::Lex, MonomialOrder::GrevLex, MonomialOrder::Elimination { first: n / 2 }] {
                    let order = Order::new(kind, fields);
                    assert_eq!(order.cmp(&pa, &pb), reference(kind, &a, &b), "{order:?} {a:?} {b:?}");
                }
                let divides_ref = a.iter().zip(&b).all(|(x, y)| x <= y);
                assert_eq!(fields.divides(&pa, &pb), divides_ref, "{a:?} | {b:?}");
                let l: Vec<u32> = a.iter().zip(&b).map(|(x, y)| *x.max(y)).collect();
                let mut buf = Vec::new();
                fields.lcm_into(&mut buf, &pa, &pb);
                assert_eq!(buf, m(&l));
                assert!(fields.lcm_is(&pa, &pb, &m(&l)));
                assert_eq!(fields.coprime(&pa, &pb), a.iter().zip(&b).all(|(x, y)| *x == 0 || *y == 0));
                let bits = a.iter().enumerate().filter(|(_, e)| **e > 0).fold(0u64, |k, (i, _)| k | 1 << (i % 64));
                assert_eq!(fields.mask(&pa), bits);
                let mut prod = Vec::new();
                mul_into(&mut prod, &pa, &pb);
                assert_eq!(prod, m(&a.iter().zip(&b).map(|(x, y)| x + y).collect::<Vec<_>>()));
                if divides_ref {
                    assert_eq!(quotient(&pa, &pb), m(&a.iter().zip(&b).map(|(x, y)| y - x).collect::<Vec<_>>()));
                }
            }
            // Past 64 variables the variable mask wraps: variable 70 is bit 6.
            let mut wide = vec![0; 71];
            wide[70] = 1;
            assert_eq!(fields.mask(&m(&wide)), 1 << 6);
        }
        assert_eq!((Fields::Narrow.max_degree(), Fields::Wide.max_degree()), (127, MAX_DEGREE));
    }

    #[test]
    fn textbook_comparisons() {
        // Cox, Little, O'Shea, Ch. 2 §2: x y^2 z^4 vs x^3 y^2 ... examples.
        use Ordering::*;
        for fields in [Fields::Narrow, Fields::Wide] {
            let m = |e: &[u32]| m_in(fields, e);
            let (lex, grevlex) = (Order::new(MonomialOrder::Lex, fields), Order::new(MonomialOrder::GrevLex, fields));
            assert_eq!(lex.cmp(&m(&[1, 2, 0]), &m(&[0, 3, 4])), Greater);
            assert_eq!(lex.cmp(&m(&[3, 2, 4]), &m(&[3, 2, 1])), Greater);
            assert_eq!(grevlex.cmp(&m(&[4, 7, 1]), &m(&[4, 2, 3])), Greater);
            assert_eq!(grevlex.cmp(&m(&[1, 5, 2]), &m(&[4, 1, 3])), Greater);
            // Elimination of x: any monomial with x beats any without.
            let e = Order::new(MonomialOrder::Elimination { first: 1 }, fields);
            assert_eq!(e.cmp(&m(&[1, 0, 0]), &m(&[0, 5, 5])), Greater);
            assert_eq!(e.cmp(&m(&[1, 0, 1]), &m(&[1, 1, 0])), Less);
        }
    }

    #[test]
    fn lcm_into_appends_side_by_side() {
        // lcm(x^2 z, x y^3) = x^2 y^3 z, then lcm(1, y) = y after it in the same buffer.
        let wide = Fields::Wide;
        let mut buf = vec![7];
        wide.lcm_into(&mut buf, &m(&[2, 0, 1]), &m(&[1, 3, 0]));
        wide.lcm_into(&mut buf, &m(&[0, 0, 0]), &m(&[0, 1, 0]));
        assert_eq!(buf, [7, 6, 0x0001_0003_0002, 1, 0x0001_0000]);
        assert!(wide.lcm_is(&m(&[2, 0, 1]), &m(&[1, 3, 0]), &buf[1..3]));
        // The same in 8-bit fields: z, y, x from the most significant byte down.
        let narrow = Fields::Narrow;
        let mut buf = Vec::new();
        narrow.lcm_into(&mut buf, &m_in(narrow, &[2, 0, 1]), &m_in(narrow, &[1, 3, 0]));
        assert_eq!(buf, [6, 0x01_03_02]);
    }
}
