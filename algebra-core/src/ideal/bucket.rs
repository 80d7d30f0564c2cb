//! Geobuckets (Yan 1998, "The geobucket data structure for polynomials", J. Symbolic Comput.
//! 25(3)): the work polynomial of a reduction kept as a sum of sorted polynomials of
//! geometrically growing lengths, so that subtracting a multiple `b·q·g` of a short divisor from a
//! long work polynomial costs about `|g| log |work|` instead of a pass over the whole work.
//!
//! Fraction-free twist: every bucket carries an integer multiplier (`value = mult · terms`), so
//! the scaling `work := a·work` of a fraction-free reduction step costs one multiplication per
//! bucket, and the factor enters the coefficients only when buckets are merged (by the gcd of
//! the two multipliers).

use super::DPoly;
use super::order::{Mono, Order, Word};
use rug::{Assign, Integer};
use std::cmp::Ordering;

/// Length of bucket `i`: `4^(i+1)`.
fn capacity(i: usize) -> usize {
    4usize.saturating_mul(1usize.checked_shl(2 * i as u32).unwrap_or(usize::MAX))
}

/// A sorted polynomial from `head` on, times `mult`.
struct Slot {
    poly: DPoly,
    head: usize,
    mult: Integer,
}

impl Slot {
    fn live(&self) -> usize {
        self.poly.len() - self.head
    }
}

/// The sum of the buckets' values.
pub(crate) struct GeoBucket {
    w: usize,
    order: Order,
    slots: Vec<Slot>,
    /// Emptied polynomials whose vectors are reused (no allocation churn in the merges).
    spare: Vec<DPoly>,
    /// Integers whose limbs are reused for new coefficients (GMP allocates for every non-zero
    /// value; without the pool each added term costs an allocation and a free).
    pool: Vec<Integer>,
    /// Terms held (terms with equal monomials in different buckets counted apart).
    terms: usize,
}

impl GeoBucket {
    pub(crate) fn new(w: usize, order: Order) -> Self {
        GeoBucket { w, order, slots: Vec::new(), spare: Vec::new(), pool: Vec::new(), terms: 0 }
    }

    /// The order the buckets' monomials are merged in.
    pub(crate) fn order(&self) -> Order {
        self.order
    }

    /// Terms held, an upper bound of the number of terms of the value.
    pub(crate) fn terms(&self) -> usize {
        self.terms
    }

    fn fresh(&mut self) -> DPoly {
        let mut p = self.spare.pop().unwrap_or_else(|| DPoly::zero(self.w));
        p.exps.clear();
        p.coefs.clear();
        p
    }

    /// Keeps `p`'s vectors for a later [`Self::fresh`]; a polynomial without any (the empty
    /// slot a carry leaves behind) is dropped, as in the word buckets.
    fn recycle(&mut self, mut p: DPoly) {
        p.exps.clear();
        p.coefs.clear();
        if self.spare.len() < 16 && p.exps.capacity() > 0 {
            self.spare.push(p);
        }
    }

    /// `value += mult · p`.
    pub(crate) fn add(&mut self, p: DPoly, mult: Integer) {
        if p.is_zero() || mult == 0 {
            self.recycle(p);
            return;
        }
        let mut i = 0;
        while capacity(i) < p.len() {
            i += 1;
        }
        self.put(i, p, 0, mult);
    }

    /// `value += mult · q · g[from..]`.
    pub(crate) fn add_shifted(&mut self, q: &Mono, g: &DPoly, from: usize, mult: Integer) {
        let mut p = self.fresh();
        p.exps.reserve((g.len().saturating_sub(from)) * self.w);
        for j in from..g.len() {
            p.exps.extend(q.iter().zip(g.mono(j)).map(|(x, y)| x + y));
        }
        for c in &g.coefs[from..] {
            let mut k = self.pool.pop().unwrap_or_default();
            k.assign(c);
            p.coefs.push(k);
        }
        self.add(p, mult);
    }

    /// Puts `mult · p[head..]` into bucket `i` (merging with what is there), then carries
    /// overfull buckets up.
    fn put(&mut self, mut i: usize, p: DPoly, head: usize, mult: Integer) {
        let mut carry = Slot { poly: p, head, mult };
        loop {
            while self.slots.len() <= i {
                self.slots.push(Slot { poly: DPoly::zero(self.w), head: 0, mult: Integer::new() });
            }
            self.terms += carry.live();
            if self.slots[i].live() == 0 {
                let old = std::mem::replace(&mut self.slots[i], carry);
                self.recycle(old.poly);
            } else {
                let old = std::mem::replace(
                    &mut self.slots[i],
                    Slot { poly: DPoly::zero(self.w), head: 0, mult: Integer::new() },
                );
                self.terms -= old.live() + carry.live();
                let merged = self.merge(old, carry);
                self.terms += merged.live();
                self.slots[i] = merged;
            }
            if self.slots[i].live() <= capacity(i) {
                return;
            }
            self.terms -= self.slots[i].live();
            carry = std::mem::replace(
                &mut self.slots[i],
                Slot { poly: DPoly::zero(self.w), head: 0, mult: Integer::new() },
            );
            i += 1;
        }
    }

    /// `a + b` as one slot whose multiplier is `gcd(a.mult, b.mult)`.
    fn merge(&mut self, mut a: Slot, mut b: Slot) -> Slot {
        // value = u·(x·a + y·b) with u = gcd(a.mult, b.mult); x = y = 1 when the multipliers agree.
        let (mut x, mut y) = (Integer::new(), Integer::new());
        let u = if a.mult == b.mult {
            std::mem::take(&mut a.mult)
        } else {
            let u = Integer::from(a.mult.gcd_ref(&b.mult));
            x.assign(a.mult.div_exact_ref(&u));
            y.assign(b.mult.div_exact_ref(&u));
            u
        };
        let (sx, sy) = (x != 0 && x != 1, y != 0 && y != 1);
        let mut out = self.fresh();
        out.exps.reserve((a.live() + b.live()) * self.w);
        out.coefs.reserve(a.live() + b.live());
        let (mut i, mut j) = (a.head, b.head);
        while i < a.poly.len() && j < b.poly.len() {
            match self.order.cmp(a.poly.mono(i), b.poly.mono(j)) {
                Ordering::Greater => {
                    let mut c = std::mem::take(&mut a.poly.coefs[i]);
                    if sx {
                        c *= &x;
                    }
                    out.push(a.poly.mono(i), c);
                    i += 1;
                }
                Ordering::Less => {
                    let mut c = std::mem::take(&mut b.poly.coefs[j]);
                    if sy {
                        c *= &y;
                    }
                    out.push(b.poly.mono(j), c);
                    j += 1;
                }
                Ordering::Equal => {
                    let mut c = std::mem::take(&mut a.poly.coefs[i]);
                    if sx {
                        c *= &x;
                    }
                    if sy {
                        c += &y * &b.poly.coefs[j];
                    } else {
                        c += &b.poly.coefs[j];
                    }
                    if c != 0 {
                        out.push(a.poly.mono(i), c);
                    } else {
                        self.pool.push(c);
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
        for (p, mut k, s, f) in [(&mut a.poly, i, sx, &x), (&mut b.poly, j, sy, &y)] {
            while k < p.len() {
                let mut c = std::mem::take(&mut p.coefs[k]);
                if s {
                    c *= f;
                }
                out.push(p.mono(k), c);
                k += 1;
            }
        }
        self.recycle(a.poly);
        self.recycle(b.poly);
        Slot { poly: out, head: 0, mult: u }
    }

    /// Gives a no longer needed integer's limbs back for reuse.
    pub(crate) fn give_back(&mut self, c: Integer) {
        self.pool.push(c);
    }

    /// `value := a · value`.
    pub(crate) fn scale(&mut self, a: &Integer) {
        for s in &mut self.slots {
            if s.live() > 0 {
                s.mult *= a;
            }
        }
    }

    /// Removes and returns the leading term of the value (monomial into `mono`), `None` when the
    /// value is zero.
    pub(crate) fn pop_lead(&mut self, mono: &mut Vec<Word>) -> Option<Integer> {
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
                match self.order.cmp(s.poly.mono(s.head), b.poly.mono(b.head)) {
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
                return None;
            }
            mono.clear();
            let first = &self.slots[at[0]];
            super::order::push_mono(mono, first.poly.mono(first.head));
            let mut sum = self.pool.pop().unwrap_or_default();
            sum.assign(0);
            for &i in &at[..n] {
                let s = &mut self.slots[i];
                let c = std::mem::take(&mut s.poly.coefs[s.head]);
                if s.mult == 1 {
                    sum += &c;
                } else {
                    sum += &s.mult * &c;
                }
                self.pool.push(c);
                s.head += 1;
                self.terms -= 1;
            }
            if sum != 0 {
                return Some(sum);
            }
            self.pool.push(sum);
        }
    }

    /// Divides the value by the gcd `g` of its coefficients when `g > 1` and returns `g`
    /// (1 otherwise); stops at the first coefficients that show `g = 1`.
    pub(crate) fn remove_content(&mut self) -> Integer {
        let mut g = Integer::new();
        for s in &self.slots {
            if s.live() == 0 {
                continue;
            }
            let mut gs = Integer::new();
            for c in &s.poly.coefs[s.head..] {
                gs.gcd_mut(c);
                if gs == 1 {
                    break;
                }
            }
            gs *= &s.mult;
            g.gcd_mut(&gs);
            if g == 1 {
                return g;
            }
        }
        if g <= 1 {
            return Integer::from(1);
        }
        for s in &mut self.slots {
            if s.live() == 0 {
                continue;
            }
            let t = Integer::from(s.mult.gcd_ref(&g));
            s.mult.div_exact_mut(&t);
            let rest = Integer::from(g.div_exact_ref(&t));
            if rest != 1 {
                for c in &mut s.poly.coefs[s.head..] {
                    c.div_exact_mut(&rest);
                }
            }
        }
        g
    }
}
