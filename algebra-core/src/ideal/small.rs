//! The merge reduction of [`super::division::reduce`] on machine-word coefficients: while the
//! work polynomial, the remainder and every divisor have coefficients that fit an `i64`, each
//! step is the same fraction-free step (`p := a·p - b·q·g`, `d = gcd(c, lc g)`, content removed
//! every 16 steps) in `i64`/`i128` arithmetic, with no GMP call and no heap integer per term
//! (Singular keeps small coefficients immediate the same way). Every product is checked: the
//! step that would overflow is instead the first step of the GMP merge reduction, continued from
//! the state before it, so the result is exact either way. A work polynomial that grows past
//! [`super::division::LONG_WORK`] terms continues in geobuckets over machine words
//! ([`super::small_bucket`]) from where it is, and those over GMP from their first overflow.

use super::division::{LONG_WORK, Reduced, Reducer, Side, merge_lifted_tails, reduce_from};
use super::order::{self, Mono};
use super::small_bucket::reduce_in_word_buckets;
use super::{DPoly, IdealError, Meter, MonomialOrder};
use rug::{Integer, Rational};
use std::cell::RefCell;
use std::cmp::Ordering;

thread_local! {
    /// Buffers of finished reductions, reused by the next ones on this thread: a reduction's
    /// work, merge buffer and remainder grow by reallocation from empty otherwise, once per
    /// reduction (about 8% of the docs' example).
    static SPARE: RefCell<Vec<Work>> = const { RefCell::new(Vec::new()) };
}

/// An empty [`Work`], with the capacity of a finished one when there is one.
fn take_work() -> Work {
    SPARE.with_borrow_mut(|s| s.pop()).unwrap_or(Work { exps: Vec::new(), coefs: Vec::new() })
}

/// Keeps `p`'s buffers for [`take_work`] (a few, at most 1 MB each).
fn give_back(mut p: Work) {
    if p.exps.capacity() <= 1 << 18 {
        p.exps.clear();
        p.coefs.clear();
        SPARE.with_borrow_mut(|s| {
            if s.len() < 8 {
                s.push(p);
            }
        });
    }
}

/// The coefficients of `p` as machine words, when all fit (`i64::MIN` excluded, so that every
/// value can be negated).
pub(crate) fn small_coefs(p: &DPoly) -> Option<Vec<i64>> {
    p.coefs.iter().map(|c| c.to_i64().filter(|&x| x != i64::MIN)).collect()
}

/// An `i128` as a coefficient, when it fits (`i64::MIN` excluded).
#[inline(always)]
pub(crate) fn fit(v: i128) -> Option<i64> {
    i64::try_from(v).ok().filter(|&x| x != i64::MIN)
}

pub(crate) fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// A polynomial with machine-word coefficients (the layout of [`DPoly`]).
pub(crate) struct Work {
    exps: Vec<u32>,
    coefs: Vec<i64>,
}

/// The S-polynomial of [`super::division::s_poly`] (`a·mf·f[1..] - b·mg·g[1..]`) in machine
/// words, from the coefficients `fc`, `gc` of `f`, `g` as words; `None` on overflow.
pub(crate) fn s_poly(
    (a, mf, f, fc): (i64, &Mono, &DPoly, &[i64]),
    (b, mg, g, gc): (i64, &Mono, &DPoly, &[i64]),
    order: MonomialOrder,
) -> Option<Work> {
    let w = f.w;
    let mut out = take_work();
    out.exps.reserve((f.len() + g.len()) * w);
    out.coefs.reserve(f.len() + g.len());
    let (a, b) = (i128::from(a), i128::from(b));
    let done = merge_lifted_tails((mf, f), (mg, g), order, |m, side| {
        let v = match side {
            Side::F(i) => a * i128::from(fc[i]),
            Side::G(j) => -b * i128::from(gc[j]),
            Side::Both(i, j) => a * i128::from(fc[i]) - b * i128::from(gc[j]),
        };
        if v == 0 && !matches!(side, Side::G(_)) {
            return true;
        }
        let Some(c) = fit(v) else { return false };
        out.coefs.push(c);
        out.exps.extend_from_slice(m);
        true
    });
    done.then_some(out)
}

impl Work {
    /// The polynomial with these monomials (`w` words each, decreasing) and coefficients.
    pub(crate) fn new(exps: Vec<u32>, coefs: Vec<i64>) -> Self {
        Work { exps, coefs }
    }

    /// The monomials and the coefficients.
    pub(crate) fn into_parts(self) -> (Vec<u32>, Vec<i64>) {
        (self.exps, self.coefs)
    }

    /// Number of terms.
    pub(crate) fn len(&self) -> usize {
        self.coefs.len()
    }

    /// Appends the term `c·m`.
    pub(crate) fn push(&mut self, m: &Mono, c: i64) {
        self.exps.extend_from_slice(m);
        self.coefs.push(c);
    }

    /// Keeps the buffers for the next reductions on this thread.
    pub(crate) fn give_back(self) {
        give_back(self);
    }

    /// The polynomial over GMP.
    pub(crate) fn to_dpoly(&self, w: usize) -> DPoly {
        DPoly { w, exps: self.exps.clone(), coefs: self.coefs.iter().map(|&c| Integer::from(c)).collect() }
    }

    /// The terms from `from` on, over GMP.
    fn into_dpoly(self, w: usize, from: usize) -> DPoly {
        DPoly {
            w,
            exps: self.exps[from * w..].to_vec(),
            coefs: self.coefs[from..].iter().map(|&c| Integer::from(c)).collect(),
        }
    }
}

/// `out := a·p[from..] - b·q·g[1..]` (see [`super::division::combine`]); `None` on overflow.
#[allow(clippy::too_many_arguments)]
fn combine(
    p: &Work,
    from: usize,
    (a, b): (i64, i64),
    (q, g, gc): (&Mono, &DPoly, &[i64]),
    w: usize,
    order: MonomialOrder,
    out: &mut Work,
    lifted: &mut Vec<u32>,
) -> Option<()> {
    out.exps.clear();
    out.coefs.clear();
    let n = p.coefs.len();
    out.exps.reserve((n - from + g.len()) * w);
    out.coefs.reserve(n - from + g.len());
    let (a, b) = (i128::from(a), i128::from(b));
    let (mut i, mut j) = (from, 1);
    // `p`'s terms from `run` to `i` are in `out.coefs` but not yet in `out.exps`: a run of
    // them is copied with one `memcpy` (one per term was an eighth of the docs' example).
    let mut run = from;
    if j < g.len() {
        order::mul_into(lifted, q, g.mono(j));
    }
    while i < n && j < g.len() {
        match order.cmp(&p.exps[i * w..(i + 1) * w], lifted) {
            Ordering::Greater => {
                out.coefs.push(fit(a * i128::from(p.coefs[i]))?);
                i += 1;
                continue;
            }
            Ordering::Less => {
                out.exps.extend_from_slice(&p.exps[run * w..i * w]);
                run = i;
                out.coefs.push(fit(-b * i128::from(gc[j]))?);
                out.exps.extend_from_slice(lifted);
            }
            Ordering::Equal => {
                out.exps.extend_from_slice(&p.exps[run * w..i * w]);
                // |a·c|, |b·g| < 2^126: the difference fits an i128.
                let v = fit(a * i128::from(p.coefs[i]) - b * i128::from(gc[j]))?;
                if v != 0 {
                    out.coefs.push(v);
                    out.exps.extend_from_slice(lifted);
                }
                i += 1;
                run = i;
            }
        }
        j += 1;
        if j < g.len() {
            order::mul_into(lifted, q, g.mono(j));
        }
    }
    out.exps.extend_from_slice(&p.exps[run * w..i * w]);
    while j < g.len() {
        out.coefs.push(fit(-b * i128::from(gc[j]))?);
        out.exps.extend_from_slice(lifted);
        j += 1;
        if j < g.len() {
            order::mul_into(lifted, q, g.mono(j));
        }
    }
    if a == 1 {
        out.coefs.extend_from_slice(&p.coefs[i..n]);
    } else {
        for &c in &p.coefs[i..n] {
            out.coefs.push(fit(a * i128::from(c))?);
        }
    }
    out.exps.extend_from_slice(&p.exps[i * w..n * w]);
    Some(())
}

/// [`super::division::reduce`]: in machine words when `f` and every divisor have small
/// coefficients (`divisors[k].small`), from the first overflow on (or from the start, when
/// they do not) over GMP.
pub(crate) fn reduce(
    f: DPoly,
    divisors: &[Reducer<'_>],
    order: MonomialOrder,
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    reduce_switching_at(f, divisors, order, meter, LONG_WORK)
}

/// [`reduce`] with the switch from merges to geobuckets at `long` terms (`0`: buckets from the
/// start; `usize::MAX`: merges only), in words and over GMP alike.
pub(crate) fn reduce_switching_at(
    f: DPoly,
    divisors: &[Reducer<'_>],
    order: MonomialOrder,
    meter: &mut Meter,
    long: usize,
) -> Result<Reduced, IdealError> {
    let w = f.w;
    let small = divisors.iter().all(|d| d.small.is_some());
    let coefs = if small { small_coefs(&f) } else { None };
    let Some(coefs) = coefs else {
        return reduce_from((f, DPoly::zero(w), Rational::from(1), 0), divisors, order, meter, long);
    };
    reduce_work_switching_at(Work { exps: f.exps, coefs }, w, divisors, order, meter, long)
}

/// [`reduce`] of a polynomial already in machine words (`w` words per monomial); every divisor
/// must have its words (`small`).
pub(crate) fn reduce_work(
    p: Work,
    w: usize,
    divisors: &[Reducer<'_>],
    order: MonomialOrder,
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    reduce_work_switching_at(p, w, divisors, order, meter, LONG_WORK)
}

/// [`reduce_work`] with the switch to the word geobuckets at `long` terms.
fn reduce_work_switching_at(
    mut p: Work,
    w: usize,
    divisors: &[Reducer<'_>],
    order: MonomialOrder,
    meter: &mut Meter,
    long: usize,
) -> Result<Reduced, IdealError> {
    if p.coefs.len() > long {
        return reduce_in_word_buckets(p, take_work(), Rational::from(1), 0, w, divisors, order, meter);
    }
    let mut buf = take_work();
    let mut rem = take_work();
    // rem + p[start..] ≡ scale·f.
    let mut scale = Rational::from(1);
    let (mut start, mut steps, mut sugar) = (0, 0u32, 0);
    let (mut q, mut lifted): (Vec<u32>, Vec<u32>) = (Vec::with_capacity(w), Vec::with_capacity(w));
    while start < p.coefs.len() {
        meter.check(p.coefs.len() - start + rem.coefs.len())?;
        let m = &p.exps[start * w..(start + 1) * w];
        let mask = order::mask(m);
        match divisors.iter().find(|d| d.mask & !mask == 0 && order::divides(d.poly.lm(), m)) {
            Some(d) => {
                let (g, gc) = (d.poly, d.small.expect("checked above"));
                let (c, lc) = (p.coefs[start], gc[0]);
                // |c|, |lc| <= 2^63 - 1, so the quotients and their negations fit.
                let e = gcd(c.unsigned_abs(), lc.unsigned_abs()) as i64;
                let (mut a, mut b) = (lc / e, c / e);
                if a < 0 {
                    (a, b) = (-a, -b);
                }
                q.clear();
                q.extend(m.iter().zip(g.lm()).map(|(x, y)| x - y));
                sugar = sugar.max(q[0] + d.sugar);
                let fits = combine(&p, start + 1, (a, b), (&q, g, gc), w, order, &mut buf, &mut lifted).is_some()
                    && rem.coefs.iter().all(|&c| fit(i128::from(c) * i128::from(a)).is_some());
                if !fits {
                    // This step overflows: the reduction continues in GMP from the state before it.
                    let state = (p.into_dpoly(w, start), rem.into_dpoly(w, 0), scale, sugar);
                    return reduce_from(state, divisors, order, meter, long);
                }
                std::mem::swap(&mut p, &mut buf);
                if a != 1 {
                    for c in &mut rem.coefs {
                        *c *= a;
                    }
                    scale *= a;
                }
                start = 0;
                steps += 1;
                if steps.is_multiple_of(16) {
                    let mut g = 0u64;
                    for c in p.coefs.iter().chain(&rem.coefs) {
                        g = gcd(g, c.unsigned_abs());
                        if g == 1 {
                            break;
                        }
                    }
                    if g > 1 {
                        let g = g as i64;
                        for c in p.coefs.iter_mut().chain(rem.coefs.iter_mut()) {
                            *c /= g;
                        }
                        scale /= g;
                    }
                }
                if p.coefs.len() > long {
                    give_back(buf);
                    return reduce_in_word_buckets(p, rem, scale, sugar, w, divisors, order, meter);
                }
            }
            None => {
                rem.exps.extend_from_slice(m);
                rem.coefs.push(p.coefs[start]);
                start += 1;
            }
        }
    }
    let r = rem.to_dpoly(w);
    for spent in [p, buf, rem] {
        give_back(spent);
    }
    Ok(Reduced { r, s: scale, sugar })
}
