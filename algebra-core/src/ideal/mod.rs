//! Polynomial ideals over the rationals for [`Poly`]: monomial orders, division with remainder
//! by a list, reduced Gröbner bases (Buchberger with the Gebauer–Möller criteria and the sugar
//! selection strategy, the basis kept tail-reduced per sugar degree, fraction-free over the
//! integers on packed monomials, long reductions in geobuckets; see docs/verification.md),
//! normal forms, ideal membership, non-vanishing hypotheses by the Rabinowitsch trick, and
//! elimination of variables.
//!
//! Every computation runs under a [`Budget`] (time, basis size, terms per polynomial); when the
//! budget runs out the result is [`IdealError::Undecided`], never a hang. So is a total degree
//! above 32767 ([`Limit::Degree`]): exponents are 16-bit fields of packed monomials, and the
//! engine checks wherever a degree could first pass the limit, never overflowing silently.
//!
//! ```
//! use algebra_core::ideal::{Budget, MonomialOrder, PolyRing};
//! use algebra_core::{Poly, Ring};
//! let (x, y) = (Poly::var("x"), Poly::var("y"));
//! // The unit circle and the line x = y: 2 y^2 - 1 lies in the ideal.
//! let circle = x.clone() * x.clone() + y.clone() * y.clone() - Poly::one();
//! let line = x.clone() - y.clone();
//! let ring = PolyRing::new(["x", "y"], MonomialOrder::GrevLex);
//! let g = ring.groebner(&[circle, line], &Budget::default()).unwrap();
//! assert!(g.contains(&(Poly::from_i64(2) * y.clone() * y.clone() - Poly::one())).unwrap());
//! assert!(!g.contains(&y).unwrap());
//! ```

mod bucket;
mod division;
mod groebner;
mod hypotheses;
mod order;
mod small;
mod small_bucket;

pub use division::Division;
pub use groebner::GroebnerBasis;
pub use hypotheses::{Decision, Hypotheses, decide};
pub use order::MonomialOrder;

use crate::poly::Poly;
use order::{Fields, Mono, Order, Packing, Word};
use rug::{Integer, Rational};
use std::collections::HashMap;
use std::fmt;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// What an ideal computation may spend before it answers [`IdealError::Undecided`].
///
/// ```
/// use algebra_core::ideal::Budget;
/// let b = Budget { time: Some(std::time::Duration::from_millis(50)), ..Budget::default() };
/// assert_eq!(b.max_basis, Budget::default().max_basis);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Budget {
    /// Wall-clock limit (`None`: no limit).
    pub time: Option<Duration>,
    /// Largest number of polynomials the basis may hold while it is computed.
    pub max_basis: usize,
    /// Largest number of terms of any intermediate polynomial (a reduction counts its work and
    /// its remainder; in geobuckets, the terms the buckets hold, like terms in different buckets
    /// apart); the basis together may hold 20 times as many (the memory of the computation).
    pub max_terms: usize,
}

impl Default for Budget {
    /// 10 s, 5 000 basis polynomials, 200 000 terms per polynomial.
    fn default() -> Self {
        Budget { time: Some(Duration::from_secs(10)), max_basis: 5_000, max_terms: 200_000 }
    }
}

/// Which part of the [`Budget`] ran out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Limit {
    /// The wall-clock limit.
    Time,
    /// The basis-size limit.
    BasisSize,
    /// The terms-per-polynomial limit.
    Terms,
    /// A total degree above the engine's largest, 32767: exponents are 16-bit fields of
    /// packed monomials (a polynomial or a product formed on the way would exceed it).
    Degree,
}

/// Errors of the ideal computations.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum IdealError {
    /// The budget ran out before the answer was known: neither "holds" nor "does not hold".
    Undecided {
        /// The limit that was reached.
        limit: Limit,
        /// Time spent until then.
        elapsed_ms: u128,
    },
    /// A polynomial mentions a variable the ring does not have.
    UnknownVariable(String),
}

impl fmt::Display for IdealError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IdealError::Undecided { limit: Limit::Degree, elapsed_ms } => write!(
                f,
                "undecided within budget: degree limit reached after {elapsed_ms} ms (total degrees up to {})",
                order::MAX_DEGREE
            ),
            IdealError::Undecided { limit, elapsed_ms } => {
                write!(f, "undecided within budget: {limit} limit reached after {elapsed_ms} ms")
            }
            IdealError::UnknownVariable(v) => write!(f, "variable `{v}` is not a variable of the polynomial ring"),
        }
    }
}

impl std::error::Error for IdealError {}

impl fmt::Display for Limit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Limit::Time => "time",
            Limit::BasisSize => "basis size",
            Limit::Terms => "term count",
            Limit::Degree => "degree",
        })
    }
}

/// A running budget: the limits and the start time.
pub(crate) struct Meter {
    budget: Budget,
    start: Instant,
    ticks: u32,
}

impl Meter {
    pub(crate) fn new(budget: &Budget) -> Self {
        Meter { budget: budget.clone(), start: Instant::now(), ticks: 0 }
    }

    fn fail(&self, limit: Limit) -> IdealError {
        IdealError::Undecided { limit, elapsed_ms: self.start.elapsed().as_millis() }
    }

    /// [`Limit::Degree`]: a product would pass [`order::MAX_DEGREE`].
    pub(crate) fn degree_limit(&self) -> IdealError {
        self.fail(Limit::Degree)
    }

    /// Checks the time (every call is cheap: the clock is read every 64th call) and a size.
    pub(crate) fn check(&mut self, terms: usize) -> Result<(), IdealError> {
        if terms > self.budget.max_terms {
            return Err(self.fail(Limit::Terms));
        }
        self.ticks = self.ticks.wrapping_add(1);
        if self.ticks.is_multiple_of(64) {
            self.check_time()?;
        }
        Ok(())
    }

    pub(crate) fn check_time(&self) -> Result<(), IdealError> {
        match self.budget.time {
            Some(t) if self.start.elapsed() > t => Err(self.fail(Limit::Time)),
            _ => Ok(()),
        }
    }

    /// The basis may hold `len` polynomials of `terms` terms in all (at most 20 times
    /// [`Budget::max_terms`]: the memory of the basis).
    pub(crate) fn check_basis(&self, len: usize, terms: usize) -> Result<(), IdealError> {
        if len > self.budget.max_basis {
            Err(self.fail(Limit::BasisSize))
        } else if terms > self.budget.max_terms.saturating_mul(20) {
            Err(self.fail(Limit::Terms))
        } else {
            Ok(())
        }
    }
}

/// A polynomial with integer coefficients, its monomials stored flat (`w` words each: the
/// degree, then the packed exponents; see [`order::Packing`]) by decreasing monomial. The Gröbner
/// engine works fraction-free: a polynomial over Q is kept as a primitive integer multiple.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct DPoly {
    pub(crate) w: usize,
    pub(crate) exps: Vec<Word>,
    pub(crate) coefs: Vec<Integer>,
}

impl DPoly {
    pub(crate) fn zero(w: usize) -> Self {
        DPoly { w, exps: Vec::new(), coefs: Vec::new() }
    }

    pub(crate) fn len(&self) -> usize {
        self.coefs.len()
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.coefs.is_empty()
    }

    pub(crate) fn mono(&self, i: usize) -> &Mono {
        &self.exps[i * self.w..(i + 1) * self.w]
    }

    pub(crate) fn lm(&self) -> &Mono {
        self.mono(0)
    }

    pub(crate) fn lc(&self) -> &Integer {
        &self.coefs[0]
    }

    /// The largest degree of a term (the leading term's under grevlex), 0 for zero.
    pub(crate) fn top(&self) -> u64 {
        self.exps.chunks_exact(self.w).map(|m| m[0]).max().unwrap_or(0)
    }

    pub(crate) fn push(&mut self, m: &Mono, c: Integer) {
        order::push_mono(&mut self.exps, m);
        self.coefs.push(c);
    }

    /// The terms from `from` on.
    pub(crate) fn tail(&self, from: usize) -> DPoly {
        DPoly { w: self.w, exps: self.exps[from * self.w..].to_vec(), coefs: self.coefs[from..].to_vec() }
    }

    /// Divides by the content (the gcd of the coefficients) and makes the leading coefficient
    /// positive: the unique primitive representative of the polynomial up to a rational factor.
    pub(crate) fn make_primitive(&mut self) {
        let Some(first) = self.coefs.first() else { return };
        let mut g = first.clone().abs();
        for c in &self.coefs[1..] {
            if g == 1 {
                break;
            }
            g.gcd_mut(c);
        }
        if first.is_negative() {
            g = -g;
        }
        if g != 1 {
            for c in &mut self.coefs {
                c.div_exact_mut(&g);
            }
        }
    }
}

/// A polynomial ring Q[x_0, ..., x_{n-1}] with named variables (in this order, `x_0` the
/// largest) and a [`MonomialOrder`]: the setting of every ideal computation.
///
/// ```
/// use algebra_core::ideal::{MonomialOrder, PolyRing};
/// let ring = PolyRing::new(["x", "y", "z"], MonomialOrder::Lex);
/// assert_eq!(ring.variables(), ["x", "y", "z"]);
/// ```
#[derive(Clone, Debug)]
pub struct PolyRing {
    /// Shared between the ring and the copies a computation makes (a narrow copy, the ring
    /// of its basis): cloning a ring does not copy its names and tables.
    vars: Arc<Variables>,
    order: MonomialOrder,
    /// The exponent fields of the ring's packed monomials: [`Fields::Wide`] as built; a
    /// computation whose input allows runs in a [`Fields::Narrow`] copy
    /// ([`PolyRing::with_fields`]). Not part of the ring's identity (`==`).
    fields: Fields,
}

/// A ring's variables: names and the tables that find a variable's index.
#[derive(Debug)]
struct Variables {
    names: Vec<String>,
    index: HashMap<String, usize>,
    /// The interned id of each variable (see `Poly::id_terms`), and the variable of each id
    /// as `(id, variable)` sorted by id (a binary search per factor in [`PolyRing::to_dense`]).
    ids: Vec<u32>,
    by_id: Vec<(u32, usize)>,
    /// The variable of id `by_id[0].0 + k` at `slot[k]` (`u32::MAX`: none), when the ids span
    /// a short range (they are interned together, mostly): one load per factor. Empty
    /// otherwise (the binary search).
    slot: Vec<u32>,
}

impl PartialEq for PolyRing {
    /// The same variables in the same order, and the same monomial order (the packed layout a
    /// computation chose is not compared).
    fn eq(&self, other: &Self) -> bool {
        self.vars.names == other.vars.names && self.order == other.order
    }
}

impl Eq for PolyRing {}

impl PolyRing {
    /// The ring with these variables (duplicates are ignored) and this order.
    pub fn new<S: AsRef<str>>(vars: impl IntoIterator<Item = S>, order: MonomialOrder) -> Self {
        let mut out = Variables {
            names: Vec::new(),
            index: HashMap::new(),
            ids: Vec::new(),
            by_id: Vec::new(),
            slot: Vec::new(),
        };
        for v in vars {
            let v = v.as_ref().to_string();
            if !out.index.contains_key(&v) {
                let id = crate::poly::intern(&v);
                let at = out.by_id.partition_point(|e| e.0 < id);
                out.by_id.insert(at, (id, out.names.len()));
                out.ids.push(id);
                out.index.insert(v.clone(), out.names.len());
                out.names.push(v);
            }
        }
        if let (Some(lo), Some(hi)) = (out.by_id.first(), out.by_id.last()) {
            let span = (hi.0 - lo.0) as usize + 1;
            if span <= 16 * out.names.len() + 256 {
                out.slot = vec![u32::MAX; span];
                for &(id, v) in &out.by_id {
                    out.slot[(id - lo.0) as usize] = v as u32;
                }
            }
        }
        PolyRing { vars: Arc::new(out), order, fields: Fields::Wide }
    }

    /// The ring of all variables occurring in `polys`, sorted by name.
    ///
    /// ```
    /// use algebra_core::{Poly, ideal::{MonomialOrder, PolyRing}};
    /// let r = PolyRing::of(&[Poly::var("b") * Poly::var("a")], MonomialOrder::GrevLex);
    /// assert_eq!(r.variables(), ["a", "b"]);
    /// ```
    pub fn of(polys: &[Poly], order: MonomialOrder) -> Self {
        let mut vars: Vec<String> = polys.iter().flat_map(|p| p.variables()).collect();
        vars.sort();
        vars.dedup();
        PolyRing::new(vars, order)
    }

    /// The variables, largest first.
    pub fn variables(&self) -> &[String] {
        &self.vars.names
    }

    /// The monomial order.
    pub fn order(&self) -> MonomialOrder {
        self.order
    }

    /// The leading term (coefficient times monomial) of `p`, `None` for zero.
    pub fn leading_term(&self, p: &Poly) -> Result<Option<Poly>, IdealError> {
        let (d, den) = self.to_dense(p)?;
        Ok((!d.is_zero()).then(|| self.to_poly(&d.head(), &Rational::from(den))))
    }

    /// Words per monomial: the degree and the packed exponents.
    pub(crate) fn width(&self) -> usize {
        self.packing().w
    }

    /// The packed layout of the ring's monomials.
    pub(crate) fn packing(&self) -> Packing {
        Packing::new(self.vars.names.len(), self.fields)
    }

    /// The monomial order on the ring's packed monomials.
    pub(crate) fn ord(&self) -> Order {
        Order::new(self.order, self.fields)
    }

    /// The same ring with its monomials packed in fields of `fields`.
    pub(crate) fn with_fields(&self, fields: Fields) -> PolyRing {
        PolyRing { fields, ..self.clone() }
    }

    /// The exponent fields of the ring's packed monomials.
    pub(crate) fn fields(&self) -> Fields {
        self.fields
    }

    /// The variable of an interned id.
    fn variable_of(&self, id: u32) -> Result<usize, IdealError> {
        let t = &*self.vars;
        if !t.slot.is_empty() {
            let at = id.wrapping_sub(t.by_id[0].0) as usize;
            return match t.slot.get(at) {
                Some(&v) if v != u32::MAX => Ok(v as usize),
                _ => Err(IdealError::UnknownVariable(crate::poly::var_name(id))),
            };
        }
        match t.by_id.binary_search_by_key(&id, |e| e.0) {
            Ok(at) => Ok(t.by_id[at].1),
            Err(_) => Err(IdealError::UnknownVariable(crate::poly::var_name(id))),
        }
    }

    /// `p = F / den` with `F` integer (not made primitive), terms by decreasing monomial.
    pub(crate) fn to_dense(&self, p: &Poly) -> Result<(DPoly, Integer), IdealError> {
        let Terms { exps, coefs, order, den } = self.sorted_terms(p)?;
        let w = self.width();
        let mut out = DPoly::zero(w);
        out.exps.reserve(order.len() * w);
        out.coefs.reserve(order.len());
        for t in order {
            let c = coefs[t];
            let num = if den == 1 { c.numer().clone() } else { Integer::from(&den / c.denom()) * c.numer() };
            out.push(&exps[t * w..(t + 1) * w], num);
        }
        Ok((out, den))
    }

    /// [`Self::to_dense`] with machine-word coefficients (`None` when `p` has a non-integer or
    /// a coefficient outside `i64`, `i64::MIN` excluded as in `small::small_coefs`): no GMP
    /// integer per term on the way to a machine-word reduction.
    pub(crate) fn to_words(&self, p: &Poly) -> Result<Option<Words>, IdealError> {
        let Terms { exps, coefs, order, den } = self.sorted_terms(p)?;
        if den != 1 {
            return Ok(None);
        }
        let w = self.width();
        let mut words = Vec::with_capacity(order.len());
        let mut sorted = Vec::with_capacity(order.len() * w);
        for t in order {
            match coefs[t].numer().to_i64().filter(|&x| x != i64::MIN) {
                Some(c) => words.push(c),
                None => return Ok(None),
            }
            sorted.extend_from_slice(&exps[t * w..(t + 1) * w]);
        }
        Ok(Some((sorted, words)))
    }

    /// The terms of `p` (see [`Terms`]); [`Limit::Degree`] for a degree above the layout's
    /// largest ([`Fields::max_degree`]).
    fn sorted_terms<'p>(&self, p: &'p Poly) -> Result<Terms<'p>, IdealError> {
        let packing = self.packing();
        let w = packing.w;
        let n = p.term_count();
        let mut exps = vec![0; n * w];
        let mut coefs: Vec<&Rational> = Vec::with_capacity(n);
        let mut den = Integer::from(1);
        for (t, (m, c)) in p.id_terms().enumerate() {
            let e = &mut exps[t * w..(t + 1) * w];
            for &(id, k) in m {
                packing.add_exponent(e, self.variable_of(id)?, k);
            }
            if e[0] > packing.fields.max_degree() {
                return Err(IdealError::Undecided { limit: Limit::Degree, elapsed_ms: 0 });
            }
            if *c.denom() != 1 {
                den.lcm_mut(c.denom());
            }
            coefs.push(c);
        }
        let order = match (self.order, w) {
            // grevlex on up to 32 variables: the monomials sorted by value as fixed-size keys
            // (no index to follow, no bounds to check per comparison)
            (MonomialOrder::GrevLex, 2) => grevlex_order::<2>(&exps),
            (MonomialOrder::GrevLex, 3) => grevlex_order::<3>(&exps),
            (MonomialOrder::GrevLex, 4) => grevlex_order::<4>(&exps),
            (MonomialOrder::GrevLex, 5) => grevlex_order::<5>(&exps),
            (MonomialOrder::GrevLex, 6) => grevlex_order::<6>(&exps),
            (MonomialOrder::GrevLex, 7) => grevlex_order::<7>(&exps),
            (MonomialOrder::GrevLex, 8) => grevlex_order::<8>(&exps),
            (MonomialOrder::GrevLex, 9) => grevlex_order::<9>(&exps),
            _ => {
                let mut order: Vec<usize> = (0..coefs.len()).collect();
                let mono = |t: usize| &exps[t * w..(t + 1) * w];
                let cmp = self.ord();
                order.sort_unstable_by(|&a, &b| cmp.cmp(mono(b), mono(a)));
                order
            }
        };
        Ok(Terms { exps, coefs, order, den })
    }

    /// `p / divisor` as a [`Poly`].
    pub(crate) fn to_poly(&self, p: &DPoly, divisor: &Rational) -> Poly {
        Poly::from_id_terms((0..p.len()).map(|i| {
            let mono = p.mono(i);
            let mut m: Vec<(u32, u32)> = (0..self.vars.names.len())
                .map(|v| (v, self.fields.exponent(mono, v)))
                .filter(|(_, e)| *e > 0)
                .map(|(v, e)| (self.vars.ids[v], e))
                .collect();
            m.sort_unstable();
            let c = if *divisor == 1 { Rational::from(&p.coefs[i]) } else { Rational::from(&p.coefs[i]) / divisor };
            (m, c)
        }))
    }
}

/// The indices of the packed monomials `exps` (`K` words each) by decreasing grevlex: each
/// monomial becomes the key `[!degree, word 1, ...]`, whose increasing order as an array is
/// the decreasing grevlex order (the larger degree first, then the smaller exponent words:
/// see [`order::Packing`]), sorted by value with its index.
fn grevlex_order<const K: usize>(exps: &[Word]) -> Vec<usize> {
    let mut keys: Vec<([Word; K], u32)> = exps
        .chunks_exact(K)
        .enumerate()
        .map(|(t, m)| {
            let mut k: [Word; K] = m.try_into().expect("K words");
            k[0] = !k[0];
            (k, t as u32)
        })
        .collect();
    keys.sort_unstable();
    keys.iter().map(|k| k.1 as usize).collect()
}

/// Monomials (`w` words each, decreasing) and machine-word coefficients.
pub(crate) type Words = (Vec<Word>, Vec<i64>);

/// The terms of a [`Poly`] in a ring's exponent vectors.
struct Terms<'p> {
    /// Packed monomials side by side in one buffer (no allocation per term), in the order of
    /// the `Poly`'s terms.
    exps: Vec<Word>,
    /// The coefficients, in the same order.
    coefs: Vec<&'p Rational>,
    /// The term indices by decreasing monomial (monomials of a [`Poly`] are distinct, so the
    /// unstable sort is deterministic).
    order: Vec<usize>,
    /// The lcm of the denominators.
    den: Integer,
}

impl DPoly {
    /// The same polynomial with its monomials packed in `to` instead of `from` (the same
    /// variables; the order of the terms is kept: every order compares exponents, not words).
    fn repacked(&self, from: Packing, to: Packing) -> DPoly {
        let n = self.len();
        let mut exps = vec![0; n * to.w];
        for t in 0..n {
            let m = &mut exps[t * to.w..(t + 1) * to.w];
            for v in 0..(from.w - 1) * from.fields.per_word() {
                let k = from.fields.exponent(self.mono(t), v);
                if k > 0 {
                    to.add_exponent(m, v, k);
                }
            }
        }
        DPoly { w: to.w, exps, coefs: self.coefs.clone() }
    }

    /// The leading term alone.
    fn head(&self) -> DPoly {
        DPoly { w: self.w, exps: self.lm().to_vec(), coefs: vec![self.lc().clone()] }
    }
}

#[cfg(test)]
mod tests;
