//! The merge reduction of [`super::division::reduce`] on machine-word coefficients: while the
//! work polynomial, the remainder and every divisor have coefficients that fit an `i64`, each
//! step is the same fraction-free step (`p := a·p - b·q·g`, `d = gcd(c, lc g)`, content removed
//! every 16 steps) in `i64`/`i128` arithmetic, with no GMP call and no heap integer per term
//! (Singular keeps small coefficients immediate the same way). Every product is checked: the
//! step that would overflow is instead the first step of the GMP merge reduction, continued from
//! the state before it, so the result is exact either way. A work polynomial that grows past
//! [`super::division::LONG_WORK`] terms continues in geobuckets over machine words
//! ([`super::small_bucket`]) from where it is, and those over GMP from their first overflow.

use super::division::{LONG_WORK, Reduced, Reducer, Side, find_divisor, merge_lifted_tails, reduce_from, step_sugar};
use super::order::{self, Mono, Order, Word};
use super::small_bucket::reduce_in_word_buckets;
use super::{DPoly, IdealError, Meter};
use rug::Rational;
use std::cell::RefCell;
use std::cmp::Ordering;

thread_local! {
    /// Buffers of finished reductions, reused by the next ones on this thread: a reduction's
    /// work, merge buffer and remainder grow by reallocation from empty otherwise, once per
    /// reduction (about 8% of the docs' example).
    static SPARE: RefCell<Vec<Work>> = const { RefCell::new(Vec::new()) };
    /// The quotient monomial and the lifted monomial of the word reductions' steps, kept
    /// between reductions (two allocations per reduction otherwise).
    static MONOS: RefCell<(Vec<Word>, Vec<Word>)> = const { RefCell::new((Vec::new(), Vec::new())) };
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
    exps: Vec<Word>,
    coefs: Vec<i64>,
}

/// The S-polynomial of [`super::division::s_poly`] (`a·mf·f[1..] - b·mg·g[1..]`) in machine
/// words, from the coefficients `fc`, `gc` of `f`, `g` as words; `None` on overflow.
pub(crate) fn s_poly(
    (a, mf, f, fc): (i64, &Mono, &DPoly, &[i64]),
    (b, mg, g, gc): (i64, &Mono, &DPoly, &[i64]),
    order: Order,
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
        order::push_mono(&mut out.exps, m);
        true
    });
    done.then_some(out)
}

impl Work {
    /// The polynomial with these monomials (`w` words each, decreasing) and coefficients.
    pub(crate) fn new(exps: Vec<Word>, coefs: Vec<i64>) -> Self {
        Work { exps, coefs }
    }

    /// The monomials and the coefficients.
    pub(crate) fn into_parts(self) -> (Vec<Word>, Vec<i64>) {
        (self.exps, self.coefs)
    }

    /// Number of terms.
    pub(crate) fn len(&self) -> usize {
        self.coefs.len()
    }

    /// Appends the term `c·m`.
    pub(crate) fn push(&mut self, m: &Mono, c: i64) {
        order::push_mono(&mut self.exps, m);
        self.coefs.push(c);
    }

    /// Keeps the buffers for the next reductions on this thread.
    pub(crate) fn give_back(self) {
        give_back(self);
    }

    /// The polynomial over GMP.
    pub(crate) fn to_dpoly(&self, w: usize) -> DPoly {
        DPoly { w, exps: self.exps.clone(), coefs: super::division::integers_from(&self.coefs) }
    }

    /// The terms from `from` on with a non-zero coefficient, over GMP.
    fn into_dpoly(mut self, w: usize, from: usize) -> DPoly {
        self.compact(w, from);
        let coefs = super::division::integers_from(&self.coefs);
        DPoly { w, exps: self.exps, coefs }
    }

    /// Keeps the terms from `from` on with a non-zero coefficient (those left with 0 by steps
    /// done in place).
    fn compact(&mut self, w: usize, from: usize) {
        self.squeeze(w, from, 0);
    }

    /// Keeps the terms before `to` and the non-zero ones from `from` on, after them.
    fn squeeze(&mut self, w: usize, from: usize, to: usize) {
        let mut k = to;
        for i in from..self.coefs.len() {
            if self.coefs[i] != 0 {
                if k != i {
                    self.coefs[k] = self.coefs[i];
                    self.exps.copy_within(i * w..(i + 1) * w, k * w);
                }
                k += 1;
            }
        }
        self.coefs.truncate(k);
        self.exps.truncate(k * w);
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
    order: Order,
    out: &mut Work,
    lifted: &mut Vec<Word>,
) -> Option<()> {
    out.exps.clear();
    out.coefs.clear();
    let n = p.coefs.len();
    out.exps.reserve((n - from + g.len()) * w);
    out.coefs.reserve(n - from + g.len());
    if 1 < g.len() {
        order::mul_into(lifted, q, g.mono(1));
    }
    merge_from::<false>((p, (i128::from(a), i128::from(b)), (q, g, gc), (from, 1), w, order), out, lifted).map(|_| ())
}

/// [`combine`] resuming a failed [`in_place`] scan: the terms `p[from..i0]` are copied as one
/// block, scaled by `a`, the matched ones (`at`, for `g[1..j0]`) updated, and the merge goes on
/// from `p[i0]` and `g[j0]`, whose lifted monomial is in `lifted`. Terms with the coefficient 0
/// (left by this step or, `dead > 0`, by earlier steps in place) are dropped.
#[allow(clippy::too_many_arguments)]
fn combine_resume(
    p: &Work,
    from: usize,
    (a, b): (i64, i64),
    (q, g, gc): (&Mono, &DPoly, &[i64]),
    (at, i0, j0): (&[usize], usize, usize),
    dead: usize,
    w: usize,
    order: Order,
    out: &mut Work,
    lifted: &mut Vec<Word>,
) -> Option<()> {
    out.exps.clear();
    out.coefs.clear();
    let n = p.coefs.len();
    out.exps.reserve((n - from + g.len()) * w);
    out.coefs.reserve(n - from + g.len());
    let (a, b) = (i128::from(a), i128::from(b));
    out.exps.extend_from_slice(&p.exps[from * w..i0 * w]);
    if a == 1 {
        out.coefs.extend_from_slice(&p.coefs[from..i0]);
    } else {
        for &c in &p.coefs[from..i0] {
            out.coefs.push(fit(a * i128::from(c))?);
        }
    }
    let mut zeros = dead > 0;
    for (k, &i) in at.iter().enumerate() {
        let c = &mut out.coefs[i - from];
        *c = fit(i128::from(*c) - b * i128::from(gc[k + 1]))?;
        zeros |= *c == 0;
    }
    if zeros {
        out.compact(w, 0);
    }
    let tail = merge_from::<true>((p, (a, b), (q, g, gc), (i0, j0), w, order), out, lifted)?;
    if dead > 0 {
        out.squeeze(w, tail, tail);
    }
    Some(())
}

/// The merge shared by [`combine`] and [`combine_resume`]: `out` (holding the result up to
/// `p[i]`, exclusive) gets `a·p[i..] - b·q·g[j..]`, the lifted monomial `q·g[j]` being in
/// `lifted`. With `DROP_ZEROS`, terms of `p` with the coefficient 0 (left by steps done in
/// place) are dropped; compiled apart, so that [`combine`]'s loop has no such test. Returns
/// where the copied rest of `p` starts in `out.coefs` (terms with 0 may follow there when
/// `DROP_ZEROS`: the caller squeezes them out); `None` on overflow.
#[inline(always)]
fn merge_from<const DROP_ZEROS: bool>(m: Merge<'_>, out: &mut Work, lifted: &mut Vec<Word>) -> Option<usize> {
    if m.1.0 == 1 {
        merge_width::<DROP_ZEROS, true>(m, out, lifted)
    } else {
        merge_width::<DROP_ZEROS, false>(m, out, lifted)
    }
}

/// [`merge_runs`] with the usual widths as constants.
#[inline(always)]
fn merge_width<const DROP_ZEROS: bool, const UNSCALED: bool>(
    m: Merge<'_>,
    out: &mut Work,
    lifted: &mut Vec<Word>,
) -> Option<usize> {
    match m.4 {
        2 => merge_runs::<DROP_ZEROS, UNSCALED, 2>(m, out, lifted),
        3 => merge_runs::<DROP_ZEROS, UNSCALED, 3>(m, out, lifted),
        4 => merge_runs::<DROP_ZEROS, UNSCALED, 4>(m, out, lifted),
        5 => merge_runs::<DROP_ZEROS, UNSCALED, 5>(m, out, lifted),
        6 => merge_runs::<DROP_ZEROS, UNSCALED, 6>(m, out, lifted),
        _ => merge_runs::<DROP_ZEROS, UNSCALED, 0>(m, out, lifted),
    }
}

/// What a merge reads: the work `p`, the multipliers `(a, b)`, the multiple `q·g` with `g`'s
/// coefficients as words, where the merge starts in `p` and `g`, the width and the order.
type Merge<'a> = (&'a Work, (i128, i128), (&'a Mono, &'a DPoly, &'a [i64]), (usize, usize), usize, Order);

/// [`merge_from`]'s loop; `UNSCALED` (`a = 1`): `p`'s coefficients are copied by runs with its
/// monomials, not multiplied one by one.
#[inline(never)]
fn merge_runs<const DROP_ZEROS: bool, const UNSCALED: bool, const W: usize>(
    (p, (a, b), (q, g, gc), (i0, j0), w, order): Merge<'_>,
    out: &mut Work,
    lifted: &mut Vec<Word>,
) -> Option<usize> {
    let w = if W == 0 { w } else { W };
    let q = &q[..w];
    let lift = |lifted: &mut Vec<Word>, j: usize| order::mul_into(lifted, q, &g.exps[j * w..(j + 1) * w]);
    let n = p.coefs.len();
    let (mut i, mut j) = (i0, j0);
    // `p`'s terms from `run` to `i` are not yet in `out.exps` (nor, `UNSCALED`, in
    // `out.coefs`): a run of them is copied with one `memcpy` (one per term was an eighth of
    // the docs' example).
    let mut run = i0;
    let flush = |out: &mut Work, run: usize, i: usize| {
        if run < i {
            out.exps.extend_from_slice(&p.exps[run * w..i * w]);
            if UNSCALED {
                out.coefs.extend_from_slice(&p.coefs[run..i]);
            }
        }
    };
    while i < n && j < g.len() {
        match order.cmp(&p.exps[i * w..(i + 1) * w], &lifted[..w]) {
            Ordering::Greater => {
                if DROP_ZEROS && p.coefs[i] == 0 {
                    // A term left with 0 by a step done in place: dropped.
                    flush(out, run, i);
                    run = i + 1;
                } else if !UNSCALED {
                    out.coefs.push(fit(a * i128::from(p.coefs[i]))?);
                }
                i += 1;
                continue;
            }
            Ordering::Less => {
                flush(out, run, i);
                run = i;
                out.coefs.push(fit(-b * i128::from(gc[j]))?);
                order::push_mono(&mut out.exps, &lifted[..w]);
            }
            Ordering::Equal => {
                flush(out, run, i);
                // |a·c|, |b·g| < 2^126: the difference fits an i128.
                let v = fit(a * i128::from(p.coefs[i]) - b * i128::from(gc[j]))?;
                if v != 0 {
                    out.coefs.push(v);
                    order::push_mono(&mut out.exps, &lifted[..w]);
                }
                i += 1;
                run = i;
            }
        }
        j += 1;
        if j < g.len() {
            lift(lifted, j);
        }
    }
    flush(out, run, i);
    while j < g.len() {
        out.coefs.push(fit(-b * i128::from(gc[j]))?);
        order::push_mono(&mut out.exps, &lifted[..w]);
        j += 1;
        if j < g.len() {
            lift(lifted, j);
        }
    }
    let tail = out.coefs.len();
    if UNSCALED {
        out.coefs.extend_from_slice(&p.coefs[i..n]);
    } else {
        for &c in &p.coefs[i..n] {
            out.coefs.push(fit(a * i128::from(c))?);
        }
    }
    out.exps.extend_from_slice(&p.exps[i * w..n * w]);
    Some(tail)
}

#[cfg(test)]
thread_local! {
    /// Steps done in place, and merges that dropped terms left with 0 by them (tests check that
    /// both paths are taken).
    pub(crate) static IN_PLACE: std::cell::Cell<[u32; 2]> = const { std::cell::Cell::new([0; 2]) };
}

#[cfg(test)]
fn count_in_place(k: usize) {
    IN_PLACE.with(|c| {
        let mut v = c.get();
        v[k] += 1;
        c.set(v);
    });
}

/// How a step of the word reduction went: done where the work stands, or the first monomial
/// `q·g[j]` that is not a term of the work (it goes before `p[i]`), or a coefficient that
/// would overflow.
enum Scan {
    /// Not tried: a plain merge ([`combine`]).
    Merge,
    Done,
    Missing(usize, usize),
    Overflow,
}

/// The step `p := a·p - b·q·g[1..]` (the leading term `p[start]` cancelled) done where `p`
/// stands, when every monomial of `q·g[1..]` is already a term of `p[start + 1..]` (in
/// reductions to zero, mostly): the matching coefficients updated, the others scaled by `a`,
/// no exponent vector copied (a merge copies the whole work at every step; on the Study quadric
/// with three poses the claim's 192 terms cancel four at a time). A coefficient that becomes 0
/// stays as a term with the coefficient 0 (`dead` counts them). Otherwise `p` is untouched and
/// the scan so far (`at`: the positions of the monomials of `q·g[1..j]`, `lifted`: `q·g[j]`)
/// is where [`combine`] resumes.
#[allow(clippy::too_many_arguments)]
fn in_place(
    p: &mut Work,
    start: usize,
    (a, b): (i64, i64),
    (q, g, gc): (&Mono, &DPoly, &[i64]),
    w: usize,
    order: Order,
    (at, lifted): (&mut Vec<usize>, &mut Vec<Word>),
    dead: &mut usize,
) -> Scan {
    let n = p.coefs.len();
    at.clear();
    let mut i = start + 1;
    for (j, &gj) in gc.iter().enumerate().take(g.len()).skip(1) {
        order::mul_into(lifted, q, g.mono(j));
        loop {
            if i >= n {
                return Scan::Missing(i, j);
            }
            match order.cmp(&p.exps[i * w..(i + 1) * w], lifted) {
                Ordering::Greater => i += 1,
                Ordering::Equal => break,
                Ordering::Less => return Scan::Missing(i, j),
            }
        }
        // a·c - b·g_j: |a·c|, |b·g_j| < 2^126, the difference fits an i128.
        if fit(i128::from(a) * i128::from(p.coefs[i]) - i128::from(b) * i128::from(gj)).is_none() {
            return Scan::Overflow;
        }
        at.push(i);
        i += 1;
    }
    if a != 1 {
        if p.coefs[start + 1..].iter().any(|&c| fit(i128::from(a) * i128::from(c)).is_none()) {
            return Scan::Overflow;
        }
        for c in &mut p.coefs[start + 1..] {
            *c *= a;
        }
    }
    for (j, &i) in at.iter().enumerate() {
        let old = p.coefs[i];
        // Fits: checked above (`old` is a·c now).
        let new = (i128::from(old) - i128::from(b) * i128::from(gc[j + 1])) as i64;
        p.coefs[i] = new;
        if old == 0 && new != 0 {
            *dead -= 1;
        } else if old != 0 && new == 0 {
            *dead += 1;
        }
    }
    Scan::Done
}

/// [`super::division::reduce`]: in machine words when `f` and every divisor have small
/// coefficients (`divisors[k].small`), from the first overflow on (or from the start, when
/// they do not) over GMP.
pub(crate) fn reduce(
    f: DPoly,
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    reduce_switching_at(f, divisors, order, meter, LONG_WORK, false)
}

/// [`reduce`] with the switch from merges to geobuckets at `long` terms (`0`: buckets from the
/// start; `usize::MAX`: merges only), in words and over GMP alike; `in_place`: the word merges
/// first try the step where the work stands ([`in_place`], as for normal forms).
pub(crate) fn reduce_switching_at(
    f: DPoly,
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
    long: usize,
    in_place: bool,
) -> Result<Reduced, IdealError> {
    let w = f.w;
    let small = divisors.iter().all(|d| d.small.is_some());
    let coefs = if small { small_coefs(&f) } else { None };
    let Some(coefs) = coefs else {
        return reduce_from((f, DPoly::zero(w), Rational::from(1), 0), divisors, order, meter, long);
    };
    let p = Work { exps: f.exps, coefs };
    if in_place {
        reduce_work_switching_at::<true>(p, w, divisors, order, meter, long)
    } else {
        reduce_work_switching_at::<false>(p, w, divisors, order, meter, long)
    }
}

/// [`reduce`] of a polynomial already in machine words (`w` words per monomial); every divisor
/// must have its words (`small`).
pub(crate) fn reduce_work(
    p: Work,
    w: usize,
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    reduce_work_switching_at::<false>(p, w, divisors, order, meter, LONG_WORK)
}

/// [`reduce_work`] for a normal form: each step is first tried where the work stands
/// ([`in_place`]). A claim that holds reduces to zero, and its steps mostly cancel terms the work
/// has (the 3-pose Study quadric's claim: 192 terms, four cancelled per step); in the
/// S-polynomials' reductions the scan failed too often to pay (Jüttler's Props. 1/2/4 6-14%
/// slower, docs/performance.md).
pub(crate) fn reduce_work_in_place(
    p: Work,
    w: usize,
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    reduce_work_switching_at::<true>(p, w, divisors, order, meter, LONG_WORK)
}

/// [`reduce_work`] with the switch to the word geobuckets at `long` terms, steps tried in place
/// first when `IN_PLACE`.
/// (A const parameter: each variant is compiled on its own, and the merges of the
/// S-polynomials' reductions run the code they ran before the steps in place were added.)
fn reduce_work_switching_at<const IN_PLACE: bool>(
    mut p: Work,
    w: usize,
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
    long: usize,
) -> Result<Reduced, IdealError> {
    if p.coefs.len() > long {
        return reduce_in_word_buckets(p, take_work(), Rational::from(1), 0, w, divisors, order, meter);
    }
    let mut buf = take_work();
    let mut rem = take_work();
    // rem + p[start..] ≡ scale·f; `dead` of the terms of p[start..] have the coefficient 0
    // (left by steps done in place, below).
    let mut scale = Rational::from(1);
    let (mut start, mut dead, mut steps, mut sugar) = (0, 0, 0u32, 0);
    // the quotient's and the lifted monomial's buffers, kept on the thread between reductions
    let (mut q_buf, mut lifted_buf) = MONOS.with_borrow_mut(std::mem::take);
    let (q, lifted) = (&mut q_buf, &mut lifted_buf);
    let mut at: Vec<usize> = Vec::new();
    while start < p.coefs.len() {
        if p.coefs[start] == 0 {
            start += 1;
            dead -= 1;
            continue;
        }
        meter.check(p.coefs.len() - start - dead + rem.coefs.len())?;
        let m = &p.exps[start * w..(start + 1) * w];
        match find_divisor(divisors, m, order.fields) {
            Some(d) => {
                let (g, gc) = (d.poly, d.small.expect("checked above"));
                let (c, lc) = (p.coefs[start], gc[0]);
                // |c|, |lc| <= 2^63 - 1, so the quotients and their negations fit.
                let e = gcd(c.unsigned_abs(), lc.unsigned_abs()) as i64;
                let (mut a, mut b) = (lc / e, c / e);
                if a < 0 {
                    (a, b) = (-a, -b);
                }
                order::quotient_into(q, g.lm(), m);
                sugar = sugar.max(step_sugar(q, d, order.fields, meter)?);
                let rem_fits = a == 1 || rem.coefs.iter().all(|&c| fit(i128::from(c) * i128::from(a)).is_some());
                let scan = if !rem_fits {
                    Scan::Overflow
                } else if IN_PLACE {
                    in_place(&mut p, start, (a, b), (q, g, gc), w, order, (&mut at, lifted), &mut dead)
                } else {
                    Scan::Merge
                };
                let fits = match scan {
                    Scan::Merge => {
                        let merged = combine(&p, start + 1, (a, b), (q, g, gc), w, order, &mut buf, lifted);
                        if merged.is_some() {
                            std::mem::swap(&mut p, &mut buf);
                            start = 0;
                        }
                        merged.is_some()
                    }
                    // Every monomial of q·g[1..] was a term of the work: updated where it stands.
                    Scan::Done => {
                        #[cfg(test)]
                        count_in_place(0);
                        start += 1;
                        true
                    }
                    Scan::Missing(i, j) => {
                        #[cfg(test)]
                        if dead > 0 {
                            count_in_place(1);
                        }
                        let merged = combine_resume(
                            &p,
                            start + 1,
                            (a, b),
                            (q, g, gc),
                            (&at, i, j),
                            dead,
                            w,
                            order,
                            &mut buf,
                            lifted,
                        );
                        if merged.is_some() {
                            std::mem::swap(&mut p, &mut buf);
                            (start, dead) = (0, 0);
                        }
                        merged.is_some()
                    }
                    Scan::Overflow => false,
                };
                if !fits {
                    // This step overflows: the reduction continues in GMP from the state before it.
                    let state = (p.into_dpoly(w, start), rem.into_dpoly(w, 0), scale, sugar);
                    return reduce_from(state, divisors, order, meter, long);
                }
                if a != 1 {
                    for c in &mut rem.coefs {
                        *c *= a;
                    }
                    scale *= a;
                }
                steps += 1;
                if steps.is_multiple_of(16) {
                    let mut g = 0u64;
                    for c in p.coefs[start..].iter().chain(&rem.coefs) {
                        g = gcd(g, c.unsigned_abs());
                        if g == 1 {
                            break;
                        }
                    }
                    if g > 1 {
                        let g = g as i64;
                        for c in p.coefs[start..].iter_mut().chain(rem.coefs.iter_mut()) {
                            *c /= g;
                        }
                        scale /= g;
                    }
                }
                if p.coefs.len() - start > long {
                    p.compact(w, start);
                    give_back(buf);
                    return reduce_in_word_buckets(p, rem, scale, sugar, w, divisors, order, meter);
                }
            }
            None => {
                order::push_mono(&mut rem.exps, m);
                rem.coefs.push(p.coefs[start]);
                start += 1;
            }
        }
    }
    let r = rem.to_dpoly(w);
    MONOS.with_borrow_mut(|m| *m = (q_buf, lifted_buf));
    for spent in [p, buf, rem] {
        give_back(spent);
    }
    Ok(Reduced { r, s: scale, sugar })
}
