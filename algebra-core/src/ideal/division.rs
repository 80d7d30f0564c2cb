//! Division with remainder by a list of polynomials, and full reduction (normal forms).

use super::bucket::GeoBucket;
use super::order::{self, Fields, Mono, Order, Word};
use super::{DPoly, IdealError, Meter, PolyRing};
use crate::poly::Poly;
use rug::ops::NegAssign;
use rug::{Assign, Integer, Rational};
use std::cell::RefCell;
use std::cmp::Ordering;

/// The result of dividing `f` by `[g_1, ..., g_s]`: `f = sum q_i g_i + r`, where no term of `r`
/// is divisible by any leading monomial `LM(g_i)`.
///
/// ```
/// use algebra_core::ideal::{Budget, MonomialOrder, PolyRing};
/// use algebra_core::{Poly, Ring};
/// // Cox-Little-O'Shea Ch. 2 §3 Example 2: x^2 y + x y^2 + y^2 by (x y - 1, y^2 - 1), lex.
/// let (x, y) = (Poly::var("x"), Poly::var("y"));
/// let f = x.clone() * x.clone() * y.clone() + x.clone() * y.clone() * y.clone() + y.clone() * y.clone();
/// let g = [x.clone() * y.clone() - Poly::one(), y.clone() * y.clone() - Poly::one()];
/// let d = PolyRing::new(["x", "y"], MonomialOrder::Lex).divide(&f, &g, &Budget::default()).unwrap();
/// assert_eq!(d.quotients[0].to_string(), "x + y");
/// assert_eq!(d.quotients[1].to_string(), "1");
/// assert_eq!(d.remainder.to_string(), "x + y + 1");
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Division {
    /// `q_i`, one per divisor.
    pub quotients: Vec<Poly>,
    /// `r`.
    pub remainder: Poly,
}

/// A divisor ready for reduction: its variable mask, the polynomial and its sugar (Giovini et
/// al. 1991; 0 where nobody asks).
pub(crate) struct Reducer<'a> {
    pub(crate) mask: u64,
    pub(crate) poly: &'a DPoly,
    pub(crate) sugar: u64,
    /// The largest degree of a term of `poly` ([`DPoly::top`]): a step by this reducer forms
    /// products of degree at most `deg(q) + top` ([`step_sugar`]).
    pub(crate) top: u64,
    /// The coefficients as machine words when all fit (`super::small`), where the caller keeps
    /// them; `None` otherwise.
    pub(crate) small: Option<&'a [i64]>,
}

/// The buffer of a reducer list, kept from one list to the next (the engine builds one per
/// S-pair and one per tail reduction). A list borrows the basis, which changes in between, so
/// the list itself cannot be kept; its allocation can. Lists of 30-40 reducers take 1.5-2 KB,
/// which glibc serves from its large bins after merging every freed small chunk
/// (`malloc_consolidate`): docs/performance.md, "tenth session".
#[derive(Default)]
pub(crate) struct ReducerBuffer(Vec<Reducer<'static>>);

impl ReducerBuffer {
    /// An empty list in the kept buffer: collecting a `map` over an empty vector into a vector
    /// of an element of the same layout reuses its allocation (`Vec`'s in-place collection);
    /// only the lifetime changes.
    pub(crate) fn take<'a>(&mut self) -> Vec<Reducer<'a>> {
        std::mem::take(&mut self.0)
            .into_iter()
            .map(|_| -> Reducer<'a> { unreachable!("the kept list is empty") })
            .collect()
    }

    /// Keeps `list`'s buffer for the next [`Self::take`].
    pub(crate) fn keep(&mut self, mut list: Vec<Reducer<'_>>) {
        list.clear();
        self.0 = list.into_iter().map(|_| -> Reducer<'static> { unreachable!("the list was cleared") }).collect();
    }
}

impl<'a> Reducer<'a> {
    /// The reducer `poly` (monomials in fields of `fields`), sugar 0, no machine words.
    pub(crate) fn new(poly: &'a DPoly, fields: Fields) -> Self {
        Reducer { mask: fields.mask(poly.lm()), poly, sugar: 0, top: poly.top(), small: None }
    }
}

/// The first divisor whose leading monomial divides `m`: the search of every reduction step
/// (over GMP, machine words and in geobuckets alike). Not inlined: inside the word reduction's
/// large loop the compiler kept the scan's pointer on the stack, a store and a load per
/// reducer (docs/performance.md, "eleventh session").
#[inline(never)]
pub(crate) fn find_divisor<'r, 'a>(divisors: &'r [Reducer<'a>], m: &Mono, fields: Fields) -> Option<&'r Reducer<'a>> {
    let mask = fields.mask(m);
    divisors.iter().find(|d| d.mask & !mask == 0 && fields.divides(d.poly.lm(), m))
}

/// The sugar `deg(q) + sugar(g)` of the step that subtracts a multiple of `q·g` (`g` the
/// reducer `d`), after checking that the products `q·g_j` stay within
/// the largest degree of the layout ([`super::Limit::Degree`] otherwise: the packed fields would
/// overflow). One comparison per step; under grevlex it never fails (`q·LM(g)` is the work's
/// leading monomial, of the largest degree).
#[inline]
pub(crate) fn step_sugar(q: &Mono, d: &Reducer<'_>, fields: Fields, meter: &Meter) -> Result<u64, IdealError> {
    if !fields.products_fit(q[0], d.top) {
        return Err(meter.degree_limit());
    }
    Ok(q[0] + d.sugar)
}

/// The result of a full reduction: `r ≡ s·f` with no term of `r` divisible by a leading
/// monomial, and the largest sugar `deg(q) + sugar(g)` of the multiples `q·g` subtracted (the
/// sugar of `r` is the larger of this and the sugar of `f`).
pub(crate) struct Reduced {
    pub(crate) r: DPoly,
    pub(crate) s: Rational,
    pub(crate) sugar: u64,
}

/// `out := a * p[from..] - b * q * g[1..]`, terms by decreasing monomial. Both operands are
/// sorted and a monomial order is compatible with multiplication, so this is one merge.
///
/// No GMP integer is allocated or freed in the steady state: a coefficient of `p` is swapped
/// into `out`'s slot (leaving `out`'s old integer, limbs and all, in `p`, whose slots from
/// `from` on are dead), and a new coefficient `-b·c` is computed into the slot's limbs. The
/// reduction alternates `p` and `out` as its two buffers, so every slot is reused at the next
/// step; surplus slots of `out` go to `spare`, from which a longer `out` takes them. `lifted` is
/// scratch space for the lifted monomials of `g`.
pub(crate) fn combine(
    p: &mut DPoly,
    from: usize,
    (a, b): (&Integer, &Integer),
    (q, g): (&Mono, &DPoly),
    order: Order,
    out: &mut DPoly,
    (spare, lifted): (&mut Vec<Integer>, &mut Vec<Word>),
) {
    out.exps.clear();
    out.exps.reserve((p.len() - from + g.len()) * p.w);
    let scale = *a != 1;
    let (mut i, mut j) = (from, 1);
    if j < g.len() {
        order::mul_into(lifted, q, g.mono(j));
    }
    // The slot for the `k`-th output term, reused when there is one.
    let mut k = 0;
    fn slot<'o>(out: &'o mut DPoly, spare: &mut Vec<Integer>, k: usize) -> &'o mut Integer {
        if k == out.coefs.len() {
            out.coefs.push(spare.pop().unwrap_or_default());
        }
        &mut out.coefs[k]
    }
    loop {
        let ord = match (i < p.len(), j < g.len()) {
            (true, true) => order.cmp(p.mono(i), lifted),
            (true, false) => Ordering::Greater,
            (false, true) => Ordering::Less,
            (false, false) => break,
        };
        match ord {
            Ordering::Greater => {
                let c = slot(out, spare, k);
                std::mem::swap(c, &mut p.coefs[i]);
                if scale {
                    *c *= a;
                }
                order::push_mono(&mut out.exps, p.mono(i));
                k += 1;
                i += 1;
            }
            Ordering::Less => {
                let c = slot(out, spare, k);
                c.assign(b * &g.coefs[j]);
                c.neg_assign();
                order::push_mono(&mut out.exps, lifted);
                k += 1;
                j += 1;
                if j < g.len() {
                    order::mul_into(lifted, q, g.mono(j));
                }
            }
            Ordering::Equal => {
                let c = slot(out, spare, k);
                std::mem::swap(c, &mut p.coefs[i]);
                if scale {
                    *c *= a;
                }
                *c -= b * &g.coefs[j];
                if *c != 0 {
                    order::push_mono(&mut out.exps, lifted);
                    k += 1;
                }
                i += 1;
                j += 1;
                if j < g.len() {
                    order::mul_into(lifted, q, g.mono(j));
                }
            }
        }
    }
    if spare.len() < 4096 {
        spare.extend(out.coefs.drain(k..));
    } else {
        out.coefs.truncate(k);
    }
}

/// Where a term of the merge of two lifted tails comes from: `mf·f[i]` alone, `mg·g[j]` alone,
/// or both at the same monomial.
#[derive(Clone, Copy)]
pub(crate) enum Side {
    F(usize),
    G(usize),
    Both(usize, usize),
}

/// The merge of the lifted tails `mf·f[1..]` and `mg·g[1..]` by decreasing monomial, computed
/// on the fly (neither operand is copied): `visit` gets each monomial and where its terms are,
/// and stops the walk by returning `false`. Returns whether the walk ran to the end. The one
/// walk of both S-polynomials, over GMP ([`s_poly`]) and machine words
/// ([`super::small::s_poly`]).
#[inline(always)]
pub(crate) fn merge_lifted_tails(
    (mf, f): (&Mono, &DPoly),
    (mg, g): (&Mono, &DPoly),
    order: Order,
    mut visit: impl FnMut(&[Word], Side) -> bool,
) -> bool {
    let (mut lf, mut lg) = (Vec::with_capacity(f.w), Vec::with_capacity(f.w));
    let (mut i, mut j) = (1, 1);
    if i < f.len() {
        order::mul_into(&mut lf, mf, f.mono(i));
    }
    if j < g.len() {
        order::mul_into(&mut lg, mg, g.mono(j));
    }
    while i < f.len() || j < g.len() {
        let ord = match (i < f.len(), j < g.len()) {
            (true, true) => order.cmp(&lf, &lg),
            (true, false) => Ordering::Greater,
            _ => Ordering::Less,
        };
        let (go, next_f, next_g) = match ord {
            Ordering::Greater => (visit(&lf, Side::F(i)), true, false),
            Ordering::Less => (visit(&lg, Side::G(j)), false, true),
            Ordering::Equal => (visit(&lf, Side::Both(i, j)), true, true),
        };
        if !go {
            return false;
        }
        if next_f {
            i += 1;
            if i < f.len() {
                order::mul_into(&mut lf, mf, f.mono(i));
            }
        }
        if next_g {
            j += 1;
            if j < g.len() {
                order::mul_into(&mut lg, mg, g.mono(j));
            }
        }
    }
    true
}

/// `a·mf·f[1..] - b·mg·g[1..]`, terms by decreasing monomial: the S-polynomial of `f` and `g`
/// when `a·lc(f) = b·lc(g)` and `mf·LM(f) = mg·LM(g)` (the leading terms cancel). One merge
/// of the two lifted tails ([`merge_lifted_tails`]).
pub(crate) fn s_poly(
    (a, mf, f): (&Integer, &Mono, &DPoly),
    (b, mg, g): (&Integer, &Mono, &DPoly),
    order: Order,
) -> DPoly {
    let mut pool = POOL.with(|p| std::mem::take(&mut *p.borrow_mut()));
    let mut out = DPoly::zero(f.w);
    out.exps.reserve((f.len() + g.len()) * f.w);
    out.coefs.reserve(f.len() + g.len());
    merge_lifted_tails((mf, f), (mg, g), order, |m, side| {
        let mut c = pool.pop().unwrap_or_default();
        match side {
            Side::F(i) => c.assign(a * &f.coefs[i]),
            Side::G(j) => {
                c.assign(b * &g.coefs[j]);
                c.neg_assign();
            }
            Side::Both(i, j) => {
                c.assign(a * &f.coefs[i]);
                c -= b * &g.coefs[j];
                if c == 0 {
                    pool.push(c);
                    return true;
                }
            }
        }
        out.push(m, c);
        true
    });
    POOL.with(|p| *p.borrow_mut() = pool);
    out
}

thread_local! {
    /// GMP integers left over by finished merge reductions (their limbs allocated), taken by
    /// the next S-polynomials: without it every S-polynomial term is a `malloc` and every
    /// reduction ends in as many `free`s.
    static POOL: RefCell<Vec<Integer>> = const { RefCell::new(Vec::new()) };
}

/// The most integers [`POOL`] keeps (a few hundred kilobytes of small limbs at most).
const POOL_MAX: usize = 4096;

/// Gives the integers of `vs` to [`POOL`], up to [`POOL_MAX`]; the rest are freed (for the GMP
/// merges and [`integers_from`]).
pub(crate) fn recycle(vs: impl IntoIterator<Item = Vec<Integer>>) {
    POOL.with(|p| {
        let mut pool = p.borrow_mut();
        for v in vs {
            let room = POOL_MAX.saturating_sub(pool.len());
            pool.extend(v.into_iter().take(room));
        }
    });
}

/// `words` as GMP integers, taken from [`POOL`] where it has some (their limbs allocated, so
/// assigning a word allocates nothing): the word reductions' remainders become elements of
/// the basis this way, once per new element and per tail reduction.
pub(crate) fn integers_from(words: &[i64]) -> Vec<Integer> {
    POOL.with(|p| {
        let mut pool = p.borrow_mut();
        words
            .iter()
            .map(|&x| {
                let mut c = pool.pop().unwrap_or_default();
                c.assign(x);
                c
            })
            .collect()
    })
}

/// The gcd of the coefficients of `p` and `r` (0 when both are zero).
fn content(p: &DPoly, r: &DPoly) -> Integer {
    let mut g = Integer::new();
    for c in p.coefs.iter().chain(&r.coefs) {
        g.gcd_mut(c);
        if g == 1 {
            break;
        }
    }
    g
}

/// Work polynomials longer than this many terms continue in a [`GeoBucket`]. Below it one merge
/// per step is as cheap or cheaper (measured on the suite of docs/performance.md, thresholds
/// 0, 64, 128, 256 and never: the buckets' carries touch about as many terms as a merge of a
/// short work polynomial and cost more per term; 128 still lost a quarter on katsura-6, whose
/// works of 128-256 terms carry large coefficients; lemma 3.4's works grow past 256 and gain a
/// third).
pub(crate) const LONG_WORK: usize = 256;

/// Full reduction of `f` by `divisors`, fraction-free: returns `(r, s)` with `r ≡ s·f` modulo
/// the divisors (`s` a positive rational) and no term of `r` divisible by a leading monomial.
/// Each step is `p := a·p - b·q·g` with `a = lc(g)/d`, `b = c/d`, `d = gcd(c, lc(g))`, for
/// the first divisor `g` whose leading monomial divides the leading term `c·m` of the work
/// `p` (`q = m/LM(g)`). While the work is short this is one merge per step
/// ([`combine`]); when it grows past [`LONG_WORK`] terms it continues in geobuckets
/// ([`reduce_in_buckets`]). Either way the steps, and so `r/s`, are the same.
pub(crate) fn reduce(
    f: DPoly,
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    // Machine words while everything fits (`super::small`), continued in GMP integers from the
    // first step that would overflow.
    super::small::reduce(f, divisors, order, meter)
}

/// [`reduce`] with the switch to geobuckets at `long` terms (`0`: buckets from the start;
/// `usize::MAX`: merges only).
#[cfg(test)]
pub(crate) fn reduce_switching_at(
    f: DPoly,
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
    long: usize,
) -> Result<Reduced, IdealError> {
    let w = f.w;
    reduce_from((f, DPoly::zero(w), Rational::from(1), 0), divisors, order, meter, long)
}

/// The merge reduction continued from `rem + p ≡ scale·f` with the sugar so far (see
/// [`reduce`]).
pub(crate) fn reduce_from(
    (mut p, mut rem, mut scale, mut sugar): (DPoly, DPoly, Rational, u64),
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
    long: usize,
) -> Result<Reduced, IdealError> {
    let w = p.w;
    let mut buf = DPoly::zero(w);
    // rem + p[start..] ≡ scale·f.
    let mut start = 0;
    let mut steps = 0u32;
    let mut spare: Vec<Integer> = Vec::new();
    // Per-step temporaries, reused: the gcd, the multipliers, the quotient monomial and the
    // lifted monomial of the merge.
    let (mut d, mut a, mut b) = (Integer::new(), Integer::new(), Integer::new());
    let (mut q, mut lifted): (Vec<Word>, Vec<Word>) = (Vec::with_capacity(w), Vec::with_capacity(w));
    if p.len() > long {
        return reduce_in_buckets(p, rem, scale, sugar, divisors, order, meter);
    }
    while start < p.len() {
        meter.check(p.len() - start + rem.len())?;
        match find_divisor(divisors, p.mono(start), order.fields) {
            Some(r) => {
                let g = r.poly;
                let c = &p.coefs[start];
                d.assign(c.gcd_ref(g.lc()));
                a.assign(g.lc().div_exact_ref(&d));
                b.assign(c.div_exact_ref(&d));
                if a.is_negative() {
                    a.neg_assign();
                    b.neg_assign();
                }
                order::quotient_into(&mut q, g.lm(), p.mono(start));
                sugar = sugar.max(step_sugar(&q, r, order.fields, meter)?);
                combine(&mut p, start + 1, (&a, &b), (&q, g), order, &mut buf, (&mut spare, &mut lifted));
                std::mem::swap(&mut p, &mut buf);
                if a != 1 {
                    for c in &mut rem.coefs {
                        *c *= &a;
                    }
                    scale *= &a;
                }
                start = 0;
                steps += 1;
                if steps.is_multiple_of(16) {
                    let g = content(&p, &rem);
                    if g > 1 {
                        for c in p.coefs.iter_mut().chain(rem.coefs.iter_mut()) {
                            c.div_exact_mut(&g);
                        }
                        scale /= &g;
                    }
                }
                if p.len() > long {
                    return reduce_in_buckets(p, rem, scale, sugar, divisors, order, meter);
                }
            }
            None => {
                let c = std::mem::take(&mut p.coefs[start]);
                rem.push(p.mono(start), c);
                start += 1;
            }
        }
    }
    recycle([p.coefs, buf.coefs, spare]);
    Ok(Reduced { r: rem, s: scale, sugar })
}

/// The reduction continued from `rem + p ≡ scale·f` with the work `p` in a [`GeoBucket`]
/// (Yan 1998). Each step takes the work's leading term `c·m`; when `LM(g)` divides `m` it sets
/// `work := a·work - b·q·g[1..]` (the multiplier `a` is one multiplication per bucket, the
/// multiple of `g` is added without touching the rest of the work), else it moves the term to
/// the remainder. The factor `λ` with `λ·work` the exact remainder over Q is tracked apart
/// (divided by every `a`, multiplied by the content the work sheds every 16 steps), and each
/// remainder term remembers the `λ` it was taken under, so the remainder is never rescaled
/// during the reduction.
pub(crate) fn reduce_in_buckets(
    p: DPoly,
    rem: DPoly,
    scale: Rational,
    sugar: u64,
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    let mut work = GeoBucket::new(p.w, order);
    work.add(p, Integer::from(1));
    let lambda = Rational::from(scale.recip_ref());
    let segs = vec![(0, lambda.clone())];
    let run = BucketRun { rem, lambda, segs, changed: false, sugar, steps: 0 };
    continue_in_buckets(work, run, divisors, meter)
}

/// The state of a bucket reduction besides its work: `f ≡ Σ_k λ_k·(remainder terms of segment
/// k) + λ·work`, the remainder's terms from `segs[k].0` on taken under `λ_k = segs[k].1`
/// (`changed`: `λ` moved since the last segment began), the sugar so far and the steps taken
/// (the content is shed every 16th). Shared by the buckets over GMP and over machine words
/// ([`super::small_bucket`]), which hands its state over here when a step would overflow.
pub(crate) struct BucketRun<R> {
    pub(crate) rem: R,
    pub(crate) lambda: Rational,
    pub(crate) segs: Vec<(usize, Rational)>,
    pub(crate) changed: bool,
    pub(crate) sugar: u64,
    pub(crate) steps: u32,
}

impl<R> BucketRun<R> {
    /// `r = D·Σ λ_k·(terms of segment k)`, `D` the lcm of the denominators of the `λ_k`, from
    /// the remainder's coefficients as integers: `r ≡ D·f`.
    pub(crate) fn finish(&self, mut rem: DPoly) -> Reduced {
        let mut den = Integer::from(1);
        for (_, l) in &self.segs {
            den.lcm_mut(l.denom());
        }
        for (k, (from, l)) in self.segs.iter().enumerate() {
            let to = self.segs.get(k + 1).map_or(rem.len(), |s| s.0);
            let factor = Integer::from(&den / l.denom()) * l.numer();
            if factor != 1 {
                for c in &mut rem.coefs[*from..to] {
                    *c *= &factor;
                }
            }
        }
        Reduced { r: rem, s: Rational::from(den), sugar: self.sugar }
    }
}

/// [`reduce_in_buckets`] from its state: the work in `work`, the rest in `run`.
pub(crate) fn continue_in_buckets(
    mut work: GeoBucket,
    mut run: BucketRun<DPoly>,
    divisors: &[Reducer<'_>],
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    let (w, order) = (run.rem.w, work.order());
    let (mut mono, mut q) = (Vec::with_capacity(w), Vec::with_capacity(w));
    while let Some(c) = work.pop_lead(&mut mono) {
        // The work held, its leading term included (as the merges count it), and the remainder.
        meter.check(work.terms() + 1 + run.rem.len())?;
        match find_divisor(divisors, &mono, order.fields) {
            Some(r) => {
                let g = r.poly;
                let d = Integer::from(c.gcd_ref(g.lc()));
                let (mut a, mut b) = (Integer::from(g.lc().div_exact_ref(&d)), Integer::from(c.div_exact_ref(&d)));
                if a.is_negative() {
                    a = -a;
                    b = -b;
                }
                order::quotient_into(&mut q, g.lm(), &mono);
                run.sugar = run.sugar.max(step_sugar(&q, r, order.fields, meter)?);
                if a != 1 {
                    work.scale(&a);
                    run.lambda /= &a;
                    run.changed = true;
                }
                work.add_shifted(&q, g, 1, -b);
                work.give_back(c);
                run.steps += 1;
                if run.steps.is_multiple_of(16) {
                    let content = work.remove_content();
                    if content != 1 {
                        run.lambda *= content;
                        run.changed = true;
                    }
                }
            }
            None => {
                if run.changed {
                    run.segs.push((run.rem.len(), run.lambda.clone()));
                    run.changed = false;
                }
                run.rem.push(&mono, c);
            }
        }
    }
    let rem = std::mem::replace(&mut run.rem, DPoly::zero(w));
    Ok(run.finish(rem))
}

/// A polynomial with rational coefficients for the textbook division (quotients are needed
/// over Q there), terms by decreasing monomial.
type RPoly = Vec<(Vec<Word>, Rational)>;

fn rational(p: &DPoly, den: &Integer) -> RPoly {
    (0..p.len()).map(|i| (p.mono(i).to_vec(), Rational::from((p.coefs[i].clone(), den.clone())))).collect()
}

/// `p - c·q·g`, whose leading terms cancel.
fn sub_mul(p: &RPoly, c: &Rational, q: &Mono, g: &RPoly, order: Order) -> RPoly {
    let mut out = Vec::with_capacity(p.len() + g.len());
    let (mut i, mut j) = (1, 1);
    let lift = |j: usize| -> (Vec<Word>, Rational) {
        let mut m = Vec::new();
        order::mul_into(&mut m, q, &g[j].0);
        (m, Rational::from(c * &g[j].1))
    };
    while i < p.len() || j < g.len() {
        let next = if j < g.len() { Some(lift(j)) } else { None };
        match (p.get(i), next) {
            (Some(x), Some(y)) => match order.cmp(&x.0, &y.0) {
                Ordering::Greater => {
                    out.push(x.clone());
                    i += 1;
                }
                Ordering::Less => {
                    out.push((y.0, -y.1));
                    j += 1;
                }
                Ordering::Equal => {
                    let v = Rational::from(&x.1 - &y.1);
                    if v != 0 {
                        out.push((y.0, v));
                    }
                    i += 1;
                    j += 1;
                }
            },
            (Some(x), None) => {
                out.push(x.clone());
                i += 1;
            }
            (None, Some(y)) => {
                out.push((y.0, -y.1));
                j += 1;
            }
            (None, None) => break,
        }
    }
    out
}

impl PolyRing {
    /// Divides `f` by the list `divisors` in the ring's order (the first divisor whose leading
    /// monomial divides the current leading term is used). The remainder depends on the order
    /// of the list unless the list is a Gröbner basis.
    pub fn divide(&self, f: &Poly, divisors: &[Poly], budget: &super::Budget) -> Result<Division, IdealError> {
        let mut meter = Meter::new(budget);
        let order = self.ord();
        let (fd, fden) = self.to_dense(f)?;
        let mut p = rational(&fd, &fden);
        let mut gs: Vec<RPoly> = Vec::with_capacity(divisors.len());
        // the largest degree of each divisor's terms: a step's products stay within
        // the layout's largest degree (see `step_sugar`)
        let mut tops = Vec::with_capacity(divisors.len());
        for g in divisors {
            let (d, den) = self.to_dense(g)?;
            tops.push(d.top());
            gs.push(rational(&d, &den));
        }
        let mut qs: Vec<RPoly> = vec![Vec::new(); gs.len()];
        let mut rem: RPoly = Vec::new();
        while !p.is_empty() {
            meter.check(p.len())?;
            let lead = &p[0];
            match gs.iter().position(|g| !g.is_empty() && order.divides(&g[0].0, &lead.0)) {
                Some(k) => {
                    let q = order::quotient(&gs[k][0].0, &lead.0);
                    if !order.products_fit(q[0], tops[k]) {
                        return Err(meter.degree_limit());
                    }
                    let c = Rational::from(&lead.1 / &gs[k][0].1);
                    p = sub_mul(&p, &c, &q, &gs[k], order);
                    qs[k].push((q, c));
                }
                None => rem.push(p.remove(0)),
            }
        }
        let poly = |t: RPoly| {
            let mut d = DPoly::zero(self.width());
            let mut den = Integer::from(1);
            for (_, c) in &t {
                den.lcm_mut(c.denom());
            }
            for (m, c) in t {
                let (n, cd) = c.into_numer_denom();
                d.push(&m, n * Integer::from(&den / &cd));
            }
            self.to_poly(&d, &Rational::from(den))
        };
        Ok(Division { quotients: qs.into_iter().map(poly).collect(), remainder: poly(rem) })
    }
}
