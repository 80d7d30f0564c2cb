//! Buchberger's algorithm with Gebauer–Möller's installation of the product and chain
//! criteria, the sugar selection strategy, the basis tail-reduced once per sugar degree, and the
//! final reduction to the unique reduced basis; fraction-free (primitive integer polynomials,
//! S-polynomials and reductions by integer multiples, content removed) on packed
//! monomials.

use super::division::{Reducer, ReducerBuffer, recycle, reduce, s_poly};
use super::order::{self, Fields, Word};
use super::small::{self, small_coefs};
use super::{Budget, DPoly, IdealError, Meter, PolyRing};
use crate::poly::Poly;
use rug::{Integer, Rational};

/// A reduced Gröbner basis of an ideal of a [`PolyRing`]: monic, no leading monomial divides a
/// term of another element, sorted by increasing leading monomial. It is unique for the ideal
/// and the order, so two ideals are equal exactly when their bases are.
///
/// ```
/// use algebra_core::ideal::{Budget, MonomialOrder, PolyRing};
/// use algebra_core::{Poly, Ring};
/// // Cox-Little-O'Shea Ch. 2 §7 Example 1: (x^3 - 2xy, x^2 y - 2y^2 + x), grlex-type order.
/// let (x, y) = (Poly::var("x"), Poly::var("y"));
/// let f1 = x.pow_u32(3) - Poly::from_i64(2) * x.clone() * y.clone();
/// let f2 = x.clone() * x.clone() * y.clone() - Poly::from_i64(2) * y.clone() * y.clone() + x.clone();
/// let ring = PolyRing::new(["x", "y"], MonomialOrder::GrevLex);
/// let g = ring.groebner(&[f1, f2], &Budget::default()).unwrap();
/// let shown: Vec<String> = g.polys().iter().map(|p| p.to_string()).collect();
/// assert_eq!(shown, ["y**2 - 1/2*x", "x*y", "x**2"]);
/// ```
#[derive(Clone, Debug)]
pub struct GroebnerBasis {
    ring: PolyRing,
    basis: Vec<DPoly>,
    /// Each element's coefficients as machine words, when all fit (`super::small`): computed
    /// once, for every normal form after.
    small: Vec<Option<Vec<i64>>>,
}

impl PartialEq for GroebnerBasis {
    /// The same ring and the same polynomials, whichever exponent fields each was computed in.
    fn eq(&self, other: &Self) -> bool {
        self.ring == other.ring
            && if self.ring.fields() == other.ring.fields() {
                self.basis == other.basis
            } else {
                self.widened().basis == other.widened().basis
            }
    }
}

impl Eq for GroebnerBasis {}

struct Pair {
    i: usize,
    j: usize,
    lcm: Vec<Word>,
    /// `order.mask(lcm)`: most divisibility tests of the criteria fail on it.
    mask: u64,
    sugar: u64,
}

struct State<'r> {
    ring: &'r PolyRing,
    polys: Vec<DPoly>,
    sugar: Vec<u64>,
    /// The variable mask of each leading monomial (`order::mask`), computed once.
    masks: Vec<u64>,
    /// The largest degree of each element's terms (`DPoly::top`), computed once.
    tops: Vec<u64>,
    /// Each element's coefficients as machine words, when all fit (`super::small`).
    small: Vec<Option<Vec<i64>>>,
    active: Vec<bool>,
    /// The pending pairs, sorted by decreasing (sugar, lcm): the next pair is the last.
    pairs: Vec<Pair>,
    /// `clean[i]`: element `i`'s tail has no term divisible by the leading monomial of an
    /// element with index below `clean[i]` (it was reduced by all of them).
    clean: Vec<usize>,
    /// Terms of the active polynomials together (the memory budget of the basis).
    terms: usize,
    /// The update's candidate lcms and candidates, kept between updates for their capacity.
    scratch: (Vec<Word>, Vec<Cand>),
}

/// A candidate new pair `(i, k)` of the update: `i`, the offset of its lcm in the lcm buffer,
/// whether the two leading monomials are coprime, the lcm's mask.
pub(super) type Cand = (usize, usize, bool, u64);

/// Gebauer–Möller's chain criterion among an update's new pairs: drops a candidate when another
/// one's lcm divides its lcm; of equal lcms one is kept, a coprime (product-criterion) one if
/// there is one, else the one of least `i`. The kept candidates end up first, their number is
/// returned. `lcms` holds the lcms side by side, `w` words each (the degree first).
///
/// The candidates are sorted by the lcm's degree, coprime first (stable: then by `i`), not by
/// the monomial order: a proper divisor has a smaller degree and equal lcms keep their order,
/// so the kept set is the same, without comparing whole lcms (that sort was an eighth of
/// Jüttler's Prop. 4).
pub(super) fn chain_among_new(cands: &mut [Cand], lcms: &[Word], w: usize, fields: Fields) -> usize {
    let lcm_of = |at: usize| &lcms[at..at + w];
    cands.sort_by_key(|c| (lcms[c.1], !c.2));
    // Kept in place: the first `kept` candidates.
    let mut kept = 0;
    for c in 0..cands.len() {
        let (at, mask) = (cands[c].1, cands[c].3);
        if !cands[..kept].iter().any(|d| d.3 & !mask == 0 && fields.divides(lcm_of(d.1), lcm_of(at))) {
            cands[kept] = cands[c];
            kept += 1;
        }
    }
    kept
}

impl State<'_> {
    /// Every element, the inactive ones too (those whose leading monomial a newer element's
    /// divides), oldest first: the first whose leading monomial divides a term reduces it. An
    /// old element has a lower sugar than the newer one that retired it, and reducing by it
    /// (as Singular reduces by its set `T` of all elements) takes other, shorter paths: on the
    /// docs' example 110 S-pairs and 31 new elements instead of 177 and 67 (Singular: 113 and
    /// 31), on cyclic-6 356 S-pairs instead of 411 (docs/performance.md).
    fn reducers<'s>(&'s self, buffer: &mut ReducerBuffer) -> Vec<Reducer<'s>> {
        let mut list = buffer.take();
        list.extend((0..self.polys.len()).map(|i| self.reducer(i, self.sugar[i])));
        list
    }

    /// Element `i` as a reducer of the given sugar (0 for tail reductions, where nobody asks).
    fn reducer(&self, i: usize, sugar: u64) -> Reducer<'_> {
        Reducer { mask: self.masks[i], poly: &self.polys[i], sugar, top: self.tops[i], small: self.small[i].as_deref() }
    }

    /// Gebauer–Möller update: installs `h` (index k) into the basis and the pair list.
    fn update(&mut self, k: usize) {
        let lh = self.polys[k].lm().to_vec();
        let order = self.ring.ord();
        // New pairs (i, k) for active i, with the variable mask of their lcm; the lcms side by
        // side in one buffer (`w` words each), not one allocation per candidate.
        let mh = self.masks[k];
        let w = lh.len();
        let (mut lcms, mut cands) = std::mem::take(&mut self.scratch);
        lcms.clear();
        cands.clear();
        for i in (0..k).filter(|&i| self.active[i]) {
            let li = self.polys[i].lm();
            let coprime = self.masks[i] & mh == 0 || order.coprime(li, &lh);
            let at = lcms.len();
            order.lcm_into(&mut lcms, li, &lh);
            cands.push((i, at, coprime, self.masks[i] | mh));
        }
        let lcm_of = |at: usize| &lcms[at..at + w];
        let kept = chain_among_new(&mut cands, &lcms, w, order.fields);
        // Old pairs (i, j): drop when LM(h) divides lcm(i, j) and both new lcms differ from it.
        let polys = &self.polys;
        self.pairs.retain(|p| {
            mh & !p.mask != 0
                || !order.divides(&lh, &p.lcm)
                || order.lcm_is(polys[p.i].lm(), &lh, &p.lcm)
                || order.lcm_is(polys[p.j].lm(), &lh, &p.lcm)
        });
        // Product criterion: coprime leading monomials need no pair.
        let before = self.pairs.len();
        for &(i, at, coprime, mask) in &cands[..kept] {
            if !coprime {
                let lcm = lcm_of(at).to_vec();
                let si = self.sugar[i] + lcm[0] - self.polys[i].lm()[0];
                let sk = self.sugar[k] + lcm[0] - lh[0];
                self.pairs.push(Pair { i, j: k, lcm, mask, sugar: si.max(sk) });
            }
        }
        self.scratch = (lcms, cands);
        // Keep the list sorted by decreasing (sugar, lcm), the next pair last: the new pairs
        // sorted apart and merged in (older equal ones first, as a stable sort would put them).
        if self.pairs.len() > before {
            let later = |p: &Pair, q: &Pair| q.sugar.cmp(&p.sugar).then_with(|| order.cmp(&q.lcm, &p.lcm));
            let mut new = self.pairs.split_off(before);
            new.sort_by(later);
            let old = std::mem::take(&mut self.pairs);
            self.pairs.reserve(old.len() + new.len());
            let (mut old, mut new) = (old.into_iter().peekable(), new.into_iter().peekable());
            while let (Some(o), Some(n)) = (old.peek(), new.peek()) {
                let next = if later(n, o) == std::cmp::Ordering::Less { new.next() } else { old.next() };
                self.pairs.extend(next);
            }
            self.pairs.extend(old);
            self.pairs.extend(new);
        }
        for i in 0..k {
            if self.active[i] && order.divides(&lh, self.polys[i].lm()) {
                self.active[i] = false;
                self.terms -= self.polys[i].len();
            }
        }
        self.active[k] = true;
        self.terms += self.polys[k].len();
    }

    /// [`Limit::Degree`](super::Limit::Degree) when the S-polynomial of `p` would form a
    /// product of degree above the layout's largest (`deg(lcm/lm f) + top(f)`; under grevlex
    /// this is the lcm's degree).
    fn check_degree(&self, p: &Pair, meter: &Meter) -> Result<(), IdealError> {
        let fields = self.ring.fields();
        let over = |i: usize| !fields.products_fit(p.lcm[0] - self.polys[i].lm()[0], self.tops[i]);
        if over(p.i) || over(p.j) { Err(meter.degree_limit()) } else { Ok(()) }
    }

    /// The S-polynomial `(lc g/d)(lcm/lm f) f - (lc f/d)(lcm/lm g) g`, `d = gcd(lc f, lc g)`.
    fn spoly(&self, p: &Pair) -> DPoly {
        let (f, g) = (&self.polys[p.i], &self.polys[p.j]);
        let (mf, mg) = (order::quotient(f.lm(), &p.lcm), order::quotient(g.lm(), &p.lcm));
        let d = Integer::from(f.lc().gcd_ref(g.lc()));
        let (a, b) = (Integer::from(g.lc().div_exact_ref(&d)), Integer::from(f.lc().div_exact_ref(&d)));
        s_poly((&a, &mf, f), (&b, &mg, g), self.ring.ord())
    }

    /// [`Self::spoly`] in machine words when both elements have theirs and nothing overflows.
    fn small_spoly(&self, p: &Pair) -> Option<small::Work> {
        let (f, g) = (&self.polys[p.i], &self.polys[p.j]);
        let (fc, gc) = (self.small[p.i].as_deref()?, self.small[p.j].as_deref()?);
        let (mf, mg) = (order::quotient(f.lm(), &p.lcm), order::quotient(g.lm(), &p.lcm));
        let d = small::gcd(fc[0].unsigned_abs(), gc[0].unsigned_abs()) as i64;
        small::s_poly((gc[0] / d, &mf, f, fc), (fc[0] / d, &mg, g, gc), self.ring.ord())
    }

    /// Tail-reduces the elements whose tails became reducible by elements added since their
    /// last reduction; leading monomials stay, so the pairs and criteria are untouched (a
    /// standard representation of an S-polynomial in the old elements is one in the new). Run
    /// once per sugar degree: on cyclic-6 the intermediate basis otherwise carries coefficients
    /// of ten thousand bits (the reduced basis has fifty), and every later reduction pays for
    /// them; the shorter tails pay on the other ideals of the suite too. The inactive elements
    /// are kept reduced as well, since they still reduce (see [`Self::reducers`]): with their
    /// tails left as they were, the docs' example took as long with 110 S-pairs as with 177
    /// (2.3 ms, against 1.5 ms); cyclic-5 pays about 15% for it.
    fn reduce_tails(&mut self, buffer: &mut ReducerBuffer, meter: &mut Meter) -> Result<(), IdealError> {
        let order = self.ring.ord();
        for i in 0..self.polys.len() {
            let since = std::mem::replace(&mut self.clean[i], self.polys.len());
            // The added elements' leading masks and monomials, read in place (no list per
            // element: most elements are not dirty).
            let g = &self.polys[i];
            let (masks, polys, active) = (&self.masks, &self.polys, &self.active);
            // A term of degree below every added leading monomial's is divisible by none of
            // them: elements of lower degree are skipped without a look at their terms.
            let least = (since..polys.len()).filter(|&j| active[j]).map(|j| polys[j].lm()[0]).min();
            let dirty = least.is_some_and(|d| self.tops[i] >= d)
                && (1..g.len()).any(|t| {
                    let (m, mask) = (g.mono(t), order.mask(g.mono(t)));
                    (since..polys.len()).any(|j| active[j] && masks[j] & !mask == 0 && order.divides(polys[j].lm(), m))
                });
            if !dirty {
                continue;
            }
            let mut others = buffer.take();
            others.extend((0..self.polys.len()).filter(|&j| j != i && self.active[j]).map(|j| self.reducer(j, 0)));
            let h = with_tail_reduced(g, self.small[i].as_deref(), &others, order, meter)?;
            buffer.keep(others);
            if self.active[i] {
                self.terms = self.terms + h.len() - g.len();
            }
            self.small[i] = small_coefs(&h);
            self.tops[i] = h.top();
            let old = std::mem::replace(&mut self.polys[i], h);
            recycle([old.coefs]);
        }
        Ok(())
    }

    fn add(&mut self, mut h: DPoly, sugar: u64, meter: &Meter) -> Result<usize, IdealError> {
        h.make_primitive();
        meter.check_basis(self.active.iter().filter(|a| **a).count() + 1, self.terms + h.len())?;
        self.masks.push(self.ring.fields().mask(h.lm()));
        self.tops.push(h.top());
        self.small.push(small_coefs(&h));
        self.polys.push(h);
        self.sugar.push(sugar);
        self.clean.push(self.polys.len());
        self.active.push(false);
        Ok(self.polys.len() - 1)
    }
}

impl PolyRing {
    /// The reduced Gröbner basis of the ideal generated by `generators` in the ring's order.
    /// The ideal of no (or only zero) generators has the empty basis; an ideal containing a
    /// non-zero constant has the basis `[1]`.
    pub fn groebner(&self, generators: &[Poly], budget: &Budget) -> Result<GroebnerBasis, IdealError> {
        self.groebner_metered(generators, &mut Meter::new(budget))
    }

    /// [`Self::groebner`] under a running meter: in 8-bit exponent fields first
    /// ([`Fields::Narrow`]: fewer words per monomial to copy and compare), and again in the
    /// ring's 16-bit fields when a degree on the way passes 127 (the input's, or a product's:
    /// the engine checks before it forms one, so the first run stops with
    /// [`Limit::Degree`](super::Limit::Degree) and nothing wrong is computed). The basis keeps
    /// the layout it was computed in.
    pub(crate) fn groebner_metered(&self, generators: &[Poly], meter: &mut Meter) -> Result<GroebnerBasis, IdealError> {
        if self.fields() == Fields::Wide {
            match self.with_fields(Fields::Narrow).groebner_in(generators, meter) {
                Err(IdealError::Undecided { limit: super::Limit::Degree, .. }) => {}
                done => return done,
            }
        }
        self.groebner_in(generators, meter)
    }

    /// [`Self::groebner_metered`] in the ring's own layout.
    pub(crate) fn groebner_in(&self, generators: &[Poly], meter: &mut Meter) -> Result<GroebnerBasis, IdealError> {
        let order = self.ord();
        let mut buffer = ReducerBuffer::default();
        let mut st = State {
            ring: self,
            polys: Vec::new(),
            sugar: Vec::new(),
            masks: Vec::new(),
            tops: Vec::new(),
            small: Vec::new(),
            active: Vec::new(),
            pairs: Vec::new(),
            clean: Vec::new(),
            terms: 0,
            scratch: (Vec::new(), Vec::new()),
        };
        let mut input: Vec<DPoly> =
            generators.iter().map(|g| self.to_dense(g).map(|d| d.0)).collect::<Result<Vec<_>, _>>()?;
        input.retain(|p| !p.is_zero());
        input.sort_by(|a, b| order.cmp(a.lm(), b.lm()));
        for g in input {
            let sugar = (0..g.len()).map(|i| g.mono(i)[0]).max().unwrap_or(0);
            let reducers = st.reducers(&mut buffer);
            let red = reduce(g, &reducers, order, meter)?;
            buffer.keep(reducers);
            let r = red.r;
            if !r.is_zero() {
                if r.lm()[0] == 0 {
                    return Ok(GroebnerBasis::new(self.clone(), vec![unit(self)]));
                }
                let k = st.add(r, sugar.max(red.sugar), meter)?;
                st.update(k);
            }
        }
        let mut degree = 0;
        while !st.pairs.is_empty() {
            meter.check_time()?;
            // Sugar strategy: least sugar, then least lcm (the list is sorted, the least last).
            let next = st.pairs.last().expect("non-empty pair list").sugar;
            if next > degree {
                degree = next;
                st.reduce_tails(&mut buffer, meter)?;
            }
            let pair = st.pairs.pop().expect("non-empty pair list");
            st.check_degree(&pair, meter)?;
            let reducers = st.reducers(&mut buffer);
            let words = match st.small_spoly(&pair) {
                Some(s) if reducers.iter().all(|d| d.small.is_some()) => Some(s),
                _ => None,
            };
            let red = match words {
                Some(s) => small::reduce_work(s, self.width(), &reducers, order, meter)?,
                None => reduce(st.spoly(&pair), &reducers, order, meter)?,
            };
            buffer.keep(reducers);
            let r = red.r;
            if !r.is_zero() {
                if r.lm()[0] == 0 {
                    return Ok(GroebnerBasis::new(self.clone(), vec![unit(self)]));
                }
                let k = st.add(r, pair.sugar.max(red.sugar), meter)?;
                st.update(k);
            }
        }
        let gens: Vec<DPoly> = st.polys.into_iter().zip(st.active).filter(|(_, a)| *a).map(|(p, _)| p).collect();
        Ok(GroebnerBasis::new(self.clone(), interreduce(gens, self, meter)?))
    }
}

fn unit(ring: &PolyRing) -> DPoly {
    let mut one = DPoly::zero(ring.width());
    one.push(&vec![0; ring.width()], Integer::from(1));
    one
}

/// Minimal basis (no leading monomial divides another; the active set already is), then each
/// element's tail fully reduced by the others, primitive, sorted by increasing leading monomial.
fn interreduce(mut gens: Vec<DPoly>, ring: &PolyRing, meter: &mut Meter) -> Result<Vec<DPoly>, IdealError> {
    let order = ring.ord();
    gens.sort_by(|a, b| order.cmp(a.lm(), b.lm()));
    // The reduced elements by index; the clean ones are moved out of `gens` at the end (they
    // reduce the others until then), not cloned: a clone allocates every GMP coefficient anew.
    let mut reduced: Vec<Option<DPoly>> = Vec::with_capacity(gens.len());
    let small: Vec<Option<Vec<i64>>> = gens.iter().map(small_coefs).collect();
    let masks: Vec<u64> = gens.iter().map(|g| order.mask(g.lm())).collect();
    let tops: Vec<u64> = gens.iter().map(DPoly::top).collect();
    for i in 0..gens.len() {
        // Mostly the basis is reduced already (its tails are reduced once per sugar degree): an
        // element no other leading monomial divides a term of is kept as it is (primitive
        // already), without a reduction that would take no step.
        let g = &gens[i];
        let dirty = (1..g.len()).any(|t| {
            let (m, mask) = (g.mono(t), order.mask(g.mono(t)));
            (0..gens.len()).any(|j| j != i && masks[j] & !mask == 0 && order.divides(gens[j].lm(), m))
        });
        if !dirty {
            reduced.push(None);
            continue;
        }
        let others: Vec<Reducer<'_>> = (0..gens.len())
            .filter(|&j| j != i)
            .map(|j| Reducer { mask: masks[j], poly: &gens[j], sugar: 0, top: tops[j], small: small[j].as_deref() })
            .collect();
        reduced.push(Some(with_tail_reduced(g, small[i].as_deref(), &others, order, meter)?));
    }
    Ok(gens.into_iter().zip(reduced).map(|(g, r)| r.unwrap_or(g)).collect())
}

/// `g` with its tail fully reduced by `others` (which must not include `g`), primitive;
/// `words`: `g`'s coefficients as machine words, when they fit (the tail goes to the
/// machine-word reduction without a GMP copy).
fn with_tail_reduced(
    g: &DPoly,
    words: Option<&[i64]>,
    others: &[Reducer<'_>],
    order: super::order::Order,
    meter: &mut Meter,
) -> Result<DPoly, IdealError> {
    // r ≡ s·tail with s = n/d, so d·s·g ≡ n·lc·lm + d·r.
    let super::division::Reduced { r, s, .. } = match words {
        Some(c) if others.iter().all(|d| d.small.is_some()) => {
            let tail = small::Work::new(g.exps[g.w..].to_vec(), c[1..].to_vec());
            small::reduce_work(tail, g.w, others, order, meter)?
        }
        _ => reduce(g.tail(1), others, order, meter)?,
    };
    let (n, d) = s.into_numer_denom();
    let mut h = DPoly::zero(g.w);
    h.exps.reserve((r.len() + 1) * g.w);
    h.coefs.reserve(r.len() + 1);
    h.push(g.lm(), n * g.lc());
    h.exps.extend_from_slice(&r.exps);
    // The remainder's integers are moved, not copied (multiplied when `d != 1`).
    let mut rest = r.coefs;
    if d != 1 {
        for c in &mut rest {
            *c *= &d;
        }
    }
    h.coefs.append(&mut rest);
    h.make_primitive();
    Ok(h)
}

impl GroebnerBasis {
    fn new(ring: PolyRing, basis: Vec<DPoly>) -> Self {
        let small = basis.iter().map(small_coefs).collect();
        GroebnerBasis { ring, basis, small }
    }

    /// The ring (variables and order) of the basis.
    pub fn ring(&self) -> &PolyRing {
        &self.ring
    }

    /// The basis polynomials, by increasing leading monomial.
    pub fn polys(&self) -> Vec<Poly> {
        self.basis.iter().map(|p| self.ring.to_poly(p, &Rational::from(p.lc()))).collect()
    }

    /// Number of basis polynomials.
    pub fn len(&self) -> usize {
        self.basis.len()
    }

    /// `true` for the zero ideal.
    pub fn is_empty(&self) -> bool {
        self.basis.is_empty()
    }

    /// `true` when the ideal is the whole ring (the basis is `[1]`): the equations have no common
    /// complex solution.
    pub fn is_unit(&self) -> bool {
        self.basis.len() == 1 && self.basis[0].lm()[0] == 0
    }

    /// The normal form of `f`: the unique remainder of `f` modulo the ideal.
    ///
    /// ```
    /// use algebra_core::ideal::{Budget, MonomialOrder, PolyRing};
    /// use algebra_core::{Poly, Ring};
    /// let x = Poly::var("x");
    /// let ring = PolyRing::new(["x"], MonomialOrder::GrevLex);
    /// let g = ring.groebner(&[x.clone() * x.clone() + Poly::one()], &Budget::default()).unwrap();
    /// assert_eq!(g.normal_form(&x.pow_u32(3)).unwrap().to_string(), "-x");
    /// ```
    pub fn normal_form(&self, f: &Poly) -> Result<Poly, IdealError> {
        self.normal_form_within(f, &Budget::default())
    }

    /// [`GroebnerBasis::normal_form`] under an explicit budget.
    pub fn normal_form_within(&self, f: &Poly, budget: &Budget) -> Result<Poly, IdealError> {
        self.normal_form_metered(f, &mut Meter::new(budget))
    }

    /// `f = F / D`, and `r ≡ s·F`: the normal form of `f` is `r / (s·D)`.
    /// With integer coefficients that fit machine words and a basis that has its words, `f`
    /// goes to the machine-word reduction directly (no GMP integer per term on the way).
    /// A basis computed in 8-bit fields whose normal form meets a degree above 127 (in `f`, or
    /// in a product on the way, which the engine checks before forming it) starts again with
    /// the basis repacked in 16-bit fields.
    pub(crate) fn normal_form_metered(&self, f: &Poly, meter: &mut Meter) -> Result<Poly, IdealError> {
        match self.normal_form_in(f, meter) {
            Err(IdealError::Undecided { limit: super::Limit::Degree, .. }) if self.ring.fields() == Fields::Narrow => {
                self.widened().normal_form_in(f, meter)
            }
            r => r,
        }
    }

    /// The basis in the ring's 16-bit fields.
    fn widened(&self) -> GroebnerBasis {
        let ring = self.ring.with_fields(Fields::Wide);
        let (from, to) = (self.ring.packing(), ring.packing());
        let basis = self.basis.iter().map(|p| p.repacked(from, to)).collect();
        GroebnerBasis::new(ring, basis)
    }

    /// [`Self::normal_form_metered`] in the basis's own layout.
    fn normal_form_in(&self, f: &Poly, meter: &mut Meter) -> Result<Poly, IdealError> {
        let reducers: Vec<Reducer<'_>> = self
            .basis
            .iter()
            .zip(&self.small)
            .map(|(g, w)| Reducer { small: w.as_deref(), ..Reducer::new(g, self.ring.fields()) })
            .collect();
        let order = self.ring.ord();
        if reducers.iter().all(|d| d.small.is_some())
            && let Some((exps, coefs)) = self.ring.to_words(f)?
        {
            let w = self.ring.width();
            let super::division::Reduced { r, s, .. } =
                small::reduce_work_in_place(small::Work::new(exps, coefs), w, &reducers, order, meter)?;
            return Ok(self.ring.to_poly(&r, &s));
        }
        let (f, den) = self.ring.to_dense(f)?;
        let super::division::Reduced { r, s, .. } = reduce(f, &reducers, order, meter)?;
        Ok(self.ring.to_poly(&r, &(s * den)))
    }

    /// Ideal membership: `f` is in the ideal exactly when its normal form is zero.
    pub fn contains(&self, f: &Poly) -> Result<bool, IdealError> {
        Ok(self.normal_form(f)?.as_constant().is_some_and(|c| c == 0))
    }

    /// The basis elements free of the first `k` variables: for a basis in
    /// [`super::MonomialOrder::Lex`] or [`super::MonomialOrder::Elimination`] with `first >= k`,
    /// a Gröbner basis of the elimination ideal `I ∩ Q[x_k, ...]`.
    ///
    /// ```
    /// use algebra_core::ideal::{Budget, MonomialOrder, PolyRing};
    /// use algebra_core::{Poly, Ring};
    /// // Eliminate t from x = t^2, y = t^3: the cusp y^2 = x^3.
    /// let (t, x, y) = (Poly::var("t"), Poly::var("x"), Poly::var("y"));
    /// let ring = PolyRing::new(["t", "x", "y"], MonomialOrder::Elimination { first: 1 });
    /// let g = ring.groebner(&[x - t.pow_u32(2), y - t.pow_u32(3)], &Budget::default()).unwrap();
    /// let cusp: Vec<String> = g.eliminate(1).iter().map(|p| p.to_string()).collect();
    /// assert_eq!(cusp, ["x**3 - y**2"]);
    /// ```
    pub fn eliminate(&self, k: usize) -> Vec<Poly> {
        self.basis
            .iter()
            .filter(|p| (0..p.len()).all(|i| (0..k).all(|v| self.ring.fields().exponent(p.mono(i), v) == 0)))
            .map(|p| self.ring.to_poly(p, &Rational::from(p.lc())))
            .collect()
    }
}
