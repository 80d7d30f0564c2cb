//! Geobuckets over machine words: the long reductions of [`super::small`] (work polynomials
//! past [`super::division::LONG_WORK`] terms) while their coefficients fit an `i64`. The same
//! buckets as [`super::bucket::GeoBucket`] (Yan 1998; lengths up to `4^(i+1)`, an integer
//! multiplier per bucket, merged by the gcd of the two multipliers) and the same steps as
//! [`super::division::continue_in_buckets`], with `i64` coefficients and multipliers and checked
//! `i128` products, so no GMP call and no heap integer per term (on Lemma 3.4 and Jüttler's
//! Prop. 2 the long works' coefficients have 2-4 bits, and the GMP buckets were half of Lemma
//! 3.4's time).
//!
//! Every operation that could overflow either completes or leaves the value of the buckets
//! unchanged (a merge writes into a fresh buffer and keeps its operands until it succeeds; a
//! leading coefficient is summed before any head moves; a scaling checks every multiplier
//! first). The step that would overflow hands the buckets, the remainder and `λ` over to the
//! GMP buckets, which redo or finish it, so the result is exact either way.

use super::bucket::GeoBucket;
use super::division::{BucketRun, Reduced, Reducer, continue_in_buckets, find_divisor, step_sugar};
use super::order::{self, Mono, Order, Word};
use super::small::{Work, fit, gcd};
use super::{DPoly, IdealError, Meter};
use rug::{Integer, Rational};
use std::cmp::Ordering;

/// Length of bucket `i`: `4^(i+1)` (as [`super::bucket::GeoBucket`]).
fn capacity(i: usize) -> usize {
    4usize.saturating_mul(1usize.checked_shl(2 * i as u32).unwrap_or(usize::MAX))
}

/// A sorted polynomial from `head` on, times `mult` (`w` words per monomial).
#[derive(Default)]
struct Slot {
    exps: Vec<Word>,
    coefs: Vec<i64>,
    head: usize,
    mult: i64,
}

impl Slot {
    fn live(&self) -> usize {
        self.coefs.len() - self.head
    }
}

/// The sum of the buckets' values, coefficients and multipliers in machine words.
struct WordBucket {
    w: usize,
    order: Order,
    slots: Vec<Slot>,
    /// Emptied slots whose vectors are reused.
    spare: Vec<Slot>,
    /// Terms held (terms with equal monomials in different buckets counted apart).
    terms: usize,
}

thread_local! {
    /// Slots of finished reductions, reused by the next ones on this thread (their buffers
    /// would otherwise grow from empty once per reduction).
    static SPARE_SLOTS: std::cell::RefCell<Vec<Slot>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// The most slots [`SPARE_SLOTS`] keeps, and the largest buffer it keeps (in words).
const POOL: (usize, usize) = (32, 1 << 18);

impl WordBucket {
    fn new(w: usize, order: Order) -> Self {
        let spare = SPARE_SLOTS.with_borrow_mut(std::mem::take);
        WordBucket { w, order, slots: Vec::new(), spare, terms: 0 }
    }

    /// Terms held, an upper bound of the number of terms of the value.
    fn terms(&self) -> usize {
        self.terms
    }

    fn fresh(&mut self) -> Slot {
        let mut s = self.spare.pop().unwrap_or_default();
        s.exps.clear();
        s.coefs.clear();
        s.head = 0;
        s
    }

    /// Keeps `s`'s buffers for a later [`Self::fresh`]; a slot without any (the empty slot a
    /// carry leaves behind) is dropped: handed out again, it would allocate at its first term.
    fn recycle(&mut self, s: Slot) {
        if self.spare.len() < POOL.0 && s.exps.capacity() > 0 {
            self.spare.push(s);
        }
    }

    /// `value += p` (the whole of `p`, multiplier 1). Cannot overflow: bucket 0-lengths are
    /// chosen so that `p` goes into an empty bucket or one it is merged with below.
    fn add_work(&mut self, p: Work, w: usize) -> Result<(), Slot> {
        let (exps, coefs) = p.into_parts();
        debug_assert_eq!(exps.len(), coefs.len() * w);
        let slot = Slot { exps, coefs, head: 0, mult: 1 };
        self.add_slot(slot)
    }

    fn add_slot(&mut self, s: Slot) -> Result<(), Slot> {
        if s.live() == 0 || s.mult == 0 {
            self.recycle(s);
            return Ok(());
        }
        let mut i = 0;
        while capacity(i) < s.live() {
            i += 1;
        }
        self.put(i, s)
    }

    /// `value += mult · q · g[1..]` (`gc`: `g`'s coefficients). On overflow `Err` holds a
    /// slot whose value is not in the buckets yet (the buckets plus it are the new value).
    fn add_shifted(&mut self, q: &Mono, g: &DPoly, gc: &[i64], mult: i64) -> Result<(), Slot> {
        let mut s = self.fresh();
        s.exps.reserve((g.len().saturating_sub(1)) * self.w);
        for j in 1..g.len() {
            s.exps.extend(q.iter().zip(g.mono(j)).map(|(x, y)| x + y));
        }
        s.coefs.extend_from_slice(&gc[1..]);
        s.mult = mult;
        self.add_slot(s)
    }

    /// Puts `carry` into bucket `i` (merging with what is there), then carries overfull buckets
    /// up. On overflow `Err(carry)`: the slot that could not be merged, every other term still
    /// in the buckets.
    fn put(&mut self, mut i: usize, mut carry: Slot) -> Result<(), Slot> {
        loop {
            while self.slots.len() <= i {
                self.slots.push(Slot::default());
            }
            if self.slots[i].live() == 0 {
                self.terms += carry.live();
                let old = std::mem::replace(&mut self.slots[i], carry);
                self.recycle(old);
            } else {
                let mut out = self.fresh();
                if merge(&self.slots[i], &carry, self.w, self.order, &mut out).is_none() {
                    self.recycle(out);
                    return Err(carry);
                }
                self.terms = self.terms + out.live() - self.slots[i].live();
                let old = std::mem::replace(&mut self.slots[i], out);
                self.recycle(old);
                self.recycle(carry);
            }
            if self.slots[i].live() <= capacity(i) {
                return Ok(());
            }
            carry = std::mem::take(&mut self.slots[i]);
            self.terms -= carry.live();
            i += 1;
        }
    }

    /// `value := a · value`, or `false` (nothing changed) when a multiplier would overflow.
    fn scale(&mut self, a: i64) -> bool {
        if self.slots.iter().any(|s| s.live() > 0 && fit(i128::from(s.mult) * i128::from(a)).is_none()) {
            return false;
        }
        for s in &mut self.slots {
            if s.live() > 0 {
                s.mult *= a;
            }
        }
        true
    }

    /// Removes the leading term of the value (monomial into `mono`) and returns its
    /// coefficient: `Ok(None)` when the value is zero, `Err(())` (nothing changed) when the
    /// coefficient does not fit a word.
    fn pop_lead(&mut self, mono: &mut Vec<Word>) -> Result<Option<i64>, ()> {
        let w = self.w;
        // Slots whose head is the largest monomial (at most one per slot; few slots).
        let mut at: [usize; 64] = [0; 64];
        loop {
            let mut n = 0;
            for i in 0..self.slots.len() {
                let s = &self.slots[i];
                if s.live() == 0 {
                    continue;
                }
                if n == 0 {
                    at[0] = i;
                    n = 1;
                    continue;
                }
                let b = &self.slots[at[0]];
                match self.order.cmp(&s.exps[s.head * w..(s.head + 1) * w], &b.exps[b.head * w..(b.head + 1) * w]) {
                    Ordering::Greater => {
                        at[0] = i;
                        n = 1;
                    }
                    Ordering::Equal => {
                        at[n] = i;
                        n += 1;
                    }
                    Ordering::Less => {}
                }
            }
            if n == 0 {
                return Ok(None);
            }
            // |mult·c| < 2^126 for each of at most 64 slots: the sum is checked.
            let mut sum = 0i128;
            for &i in &at[..n] {
                let s = &self.slots[i];
                sum = sum.checked_add(i128::from(s.mult) * i128::from(s.coefs[s.head])).ok_or(())?;
            }
            let sum = if sum == 0 { 0 } else { fit(sum).ok_or(())? };
            mono.clear();
            let first = &self.slots[at[0]];
            order::push_mono(mono, &first.exps[first.head * w..(first.head + 1) * w]);
            for &i in &at[..n] {
                self.slots[i].head += 1;
            }
            self.terms -= n;
            if sum != 0 {
                return Ok(Some(sum));
            }
        }
    }

    /// Divides the value by the gcd `g` of its coefficients when `g > 1` and returns `g` (1
    /// otherwise, also when `g` would not fit a word: shedding the content is optional).
    fn remove_content(&mut self) -> i64 {
        let mut g = 0u128;
        for s in &self.slots {
            if s.live() == 0 {
                continue;
            }
            let mut gs = 0u64;
            for &c in &s.coefs[s.head..] {
                gs = gcd(gs, c.unsigned_abs());
                if gs == 1 {
                    break;
                }
            }
            let v = u128::from(gs) * u128::from(s.mult.unsigned_abs());
            g = gcd128(g, v);
            if g == 1 {
                return 1;
            }
        }
        let Some(g) = i64::try_from(g).ok().filter(|&g| g > 1) else { return 1 };
        for s in &mut self.slots {
            if s.live() == 0 {
                continue;
            }
            let t = gcd(s.mult.unsigned_abs(), g.unsigned_abs()) as i64;
            s.mult /= t;
            let rest = g / t;
            if rest != 1 {
                for c in &mut s.coefs[s.head..] {
                    *c /= rest;
                }
            }
        }
        g
    }

    /// The same value in GMP buckets, with `extra` (a slot not yet merged in) added.
    fn into_gmp(mut self, extra: Option<Slot>) -> GeoBucket {
        let w = self.w;
        let mut out = GeoBucket::new(w, self.order);
        for s in std::mem::take(&mut self.slots).into_iter().chain(extra) {
            if s.live() == 0 {
                continue;
            }
            let p = DPoly {
                w,
                exps: s.exps[s.head * w..].to_vec(),
                coefs: s.coefs[s.head..].iter().map(|&c| Integer::from(c)).collect(),
            };
            out.add(p, Integer::from(s.mult));
        }
        out
    }
}

fn gcd128(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

impl Drop for WordBucket {
    /// Hands the slots' buffers to [`SPARE_SLOTS`] for the next reduction.
    fn drop(&mut self) {
        let mut spare = std::mem::take(&mut self.spare);
        spare.append(&mut self.slots);
        spare.retain(|s| s.exps.capacity() <= POOL.1);
        spare.truncate(POOL.0);
        SPARE_SLOTS.with_borrow_mut(|pool| {
            if pool.len() < spare.len() {
                *pool = spare;
            }
        });
    }
}

/// `out := a + b` with the multiplier `gcd(a.mult, b.mult)`; `None` (operands untouched) on
/// overflow. The usual widths are constants of their own copies of the loop (see
/// [`super::small`]'s merges).
fn merge(a: &Slot, b: &Slot, w: usize, order: Order, out: &mut Slot) -> Option<()> {
    match w {
        2 => merge_in::<2>(a, b, w, order, out),
        3 => merge_in::<3>(a, b, w, order, out),
        4 => merge_in::<4>(a, b, w, order, out),
        5 => merge_in::<5>(a, b, w, order, out),
        6 => merge_in::<6>(a, b, w, order, out),
        _ => merge_in::<0>(a, b, w, order, out),
    }
}

/// [`merge`] with `w = W` (`W = 0`: `w` as given).
fn merge_in<const W: usize>(a: &Slot, b: &Slot, w: usize, order: Order, out: &mut Slot) -> Option<()> {
    let w = if W == 0 { w } else { W };
    let (x, y, u) = if a.mult == b.mult {
        (1i128, 1i128, a.mult)
    } else {
        let u = gcd(a.mult.unsigned_abs(), b.mult.unsigned_abs()) as i64;
        (i128::from(a.mult / u), i128::from(b.mult / u), u)
    };
    out.mult = u;
    out.head = 0;
    out.exps.clear();
    out.coefs.clear();
    out.exps.reserve((a.live() + b.live()) * w);
    out.coefs.reserve(a.live() + b.live());
    let (na, nb) = (a.coefs.len(), b.coefs.len());
    let (mut i, mut j) = (a.head, b.head);
    while i < na && j < nb {
        let (ma, mb) = (&a.exps[i * w..(i + 1) * w], &b.exps[j * w..(j + 1) * w]);
        match order.cmp(ma, mb) {
            Ordering::Greater => {
                out.coefs.push(fit(x * i128::from(a.coefs[i]))?);
                order::push_mono(&mut out.exps, ma);
                i += 1;
            }
            Ordering::Less => {
                out.coefs.push(fit(y * i128::from(b.coefs[j]))?);
                order::push_mono(&mut out.exps, mb);
                j += 1;
            }
            Ordering::Equal => {
                // |x·c|, |y·d| < 2^126: the sum fits an i128.
                let v = x * i128::from(a.coefs[i]) + y * i128::from(b.coefs[j]);
                if v != 0 {
                    out.coefs.push(fit(v)?);
                    order::push_mono(&mut out.exps, ma);
                }
                i += 1;
                j += 1;
            }
        }
    }
    for (s, k, f) in [(a, i, x), (b, j, y)] {
        let n = s.coefs.len();
        if k < n {
            if f == 1 {
                out.coefs.extend_from_slice(&s.coefs[k..n]);
            } else {
                for &c in &s.coefs[k..n] {
                    out.coefs.push(fit(f * i128::from(c))?);
                }
            }
            out.exps.extend_from_slice(&s.exps[k * w..n * w]);
        }
    }
    Some(())
}

/// The reduction continued from `rem + p ≡ scale·f` with the work `p` in machine-word
/// geobuckets: the steps of [`super::division::continue_in_buckets`] (`λ` tracked apart, each
/// remainder term taken under the `λ` of its segment, the content shed every 16 steps), every
/// divisor with its words (`small`). From the first step that would overflow on, the GMP
/// buckets continue from the same state.
#[allow(clippy::too_many_arguments)]
pub(crate) fn reduce_in_word_buckets(
    p: Work,
    rem: Work,
    scale: Rational,
    sugar: u64,
    w: usize,
    divisors: &[Reducer<'_>],
    order: Order,
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    let mut work = WordBucket::new(w, order);
    let lambda = Rational::from(scale.recip_ref());
    let segs = vec![(0, lambda.clone())];
    let mut run = BucketRun { rem, lambda, segs, changed: false, sugar, steps: 0 };
    if let Err(s) = work.add_work(p, w) {
        return hand_over(Why::Merge, work, Some(s), run, w, divisors, meter);
    }
    let (mut mono, mut q) = (Vec::with_capacity(w), Vec::with_capacity(w));
    loop {
        let c = match work.pop_lead(&mut mono) {
            Ok(Some(c)) => c,
            Ok(None) => break,
            Err(()) => return hand_over(Why::Lead, work, None, run, w, divisors, meter),
        };
        // The work held, its leading term included (as the merges count it), and the remainder.
        meter.check(work.terms() + 1 + run.rem.len())?;
        match find_divisor(divisors, &mono, order.fields) {
            Some(d) => {
                let (g, gc) = (d.poly, d.small.expect("word buckets need the divisors' words"));
                // |c|, |lc| <= 2^63 - 1, so the quotients and their negations fit.
                let e = gcd(c.unsigned_abs(), gc[0].unsigned_abs()) as i64;
                let (mut a, mut b) = (gc[0] / e, c / e);
                if a < 0 {
                    (a, b) = (-a, -b);
                }
                if a != 1 && !work.scale(a) {
                    // The leading term goes back; the GMP buckets take this step again.
                    let lead = Slot { exps: mono.clone(), coefs: vec![c], head: 0, mult: 1 };
                    return hand_over(Why::Scale, work, Some(lead), run, w, divisors, meter);
                }
                order::quotient_into(&mut q, g.lm(), &mono);
                run.sugar = run.sugar.max(step_sugar(&q, d, order.fields, meter)?);
                if a != 1 {
                    run.lambda /= a;
                    run.changed = true;
                }
                run.steps += 1;
                // The step is done in value; a slot that did not merge is handed over with it.
                if let Err(s) = work.add_shifted(&q, g, gc, -b) {
                    return hand_over(Why::Merge, work, Some(s), run, w, divisors, meter);
                }
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
    let rem = std::mem::replace(&mut run.rem, Work::new(Vec::new(), Vec::new()));
    let out = run.finish(rem.to_dpoly(w));
    rem.give_back();
    Ok(out)
}

/// Why the word buckets handed over to GMP: a leading coefficient, a scaling, a merge (or the
/// first slot). Counted per thread in tests, which check that each path is taken.
#[derive(Clone, Copy)]
enum Why {
    Lead = 0,
    Scale = 1,
    Merge = 2,
}

#[cfg(test)]
thread_local! {
    pub(crate) static HANDED_OVER: std::cell::Cell<[u32; 3]> = const { std::cell::Cell::new([0; 3]) };
}

/// The word buckets' state over GMP (`extra`: a slot of the value not in the buckets), and
/// the reduction continued there.
fn hand_over(
    why: Why,
    work: WordBucket,
    extra: Option<Slot>,
    run: BucketRun<Work>,
    w: usize,
    divisors: &[Reducer<'_>],
    meter: &mut Meter,
) -> Result<Reduced, IdealError> {
    #[cfg(test)]
    HANDED_OVER.with(|h| {
        let mut v = h.get();
        v[why as usize] += 1;
        h.set(v);
    });
    let _ = why;
    let gmp = work.into_gmp(extra);
    let BucketRun { rem, lambda, segs, changed, sugar, steps } = run;
    let run = BucketRun { rem: rem.to_dpoly(w), lambda, segs, changed, sugar, steps };
    continue_in_buckets(gmp, run, divisors, meter)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ideal::MonomialOrder;
    use crate::ideal::order::Fields;

    /// The buckets keep slots that hold buffers and drop the empty one a carry leaves behind:
    /// handed out again it would allocate at its first term (lemma 3.4: 860 of its 3500
    /// allocations per basis).
    #[test]
    fn spare_slots_keep_buffers_only() {
        let mut b = WordBucket::new(2, Order::new(MonomialOrder::GrevLex, Fields::Narrow));
        b.spare.clear();
        b.recycle(Slot::default());
        assert!(b.spare.is_empty());
        b.recycle(Slot { exps: Vec::with_capacity(8), coefs: Vec::with_capacity(4), head: 0, mult: 1 });
        assert_eq!(b.spare.len(), 1);
        let s = b.fresh();
        assert!(s.exps.capacity() >= 8 && s.coefs.capacity() >= 4 && s.live() == 0);
    }
}
