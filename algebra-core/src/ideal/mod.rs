//! Polynomial ideals over the rationals for [`Poly`]: monomial orders, division with remainder
//! by a list, reduced Gröbner bases (Buchberger with the product and chain criteria and the
//! sugar selection strategy), normal forms, ideal membership, non-vanishing hypotheses by the
//! Rabinowitsch trick, and elimination of variables.
//!
//! Every computation runs under a [`Budget`] (time, basis size, terms per polynomial); when the
//! budget runs out the result is [`IdealError::Undecided`], never a hang.
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

mod division;
mod groebner;
mod hypotheses;
mod order;

pub use division::Division;
pub use groebner::GroebnerBasis;
pub use hypotheses::{Decision, Hypotheses, decide};
pub use order::MonomialOrder;

use crate::poly::Poly;
use order::Mono;
use rug::Rational;
use std::collections::HashMap;
use std::fmt;
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
    /// Largest number of terms of any intermediate polynomial.
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

    pub(crate) fn check_basis(&self, len: usize) -> Result<(), IdealError> {
        if len > self.budget.max_basis { Err(self.fail(Limit::BasisSize)) } else { Ok(()) }
    }
}

/// A polynomial in dense-exponent form, terms sorted by decreasing monomial.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub(crate) struct DPoly {
    pub(crate) terms: Vec<(Mono, Rational)>,
}

impl DPoly {
    pub(crate) fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    pub(crate) fn lm(&self) -> &Mono {
        &self.terms[0].0
    }

    pub(crate) fn lc(&self) -> &Rational {
        &self.terms[0].1
    }

    /// Divides by the leading coefficient.
    pub(crate) fn make_monic(&mut self) {
        if let Some(lc) = self.terms.first().map(|t| t.1.clone())
            && lc != 1
        {
            for t in &mut self.terms {
                t.1 /= &lc;
            }
        }
    }

    /// `self - c * m * g`, skipping the first `skip_self`/`skip_g` terms (known to cancel).
    pub(crate) fn sub_mul(&self, skip_self: usize, c: &Rational, m: &Mono, g: &DPoly, order: MonomialOrder) -> DPoly {
        let a = &self.terms[skip_self.min(self.terms.len())..];
        let b = &g.terms[1..];
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        let next_b = |j: usize| (m.mul(&b[j].0), Rational::from(c * &b[j].1));
        let mut pending = if b.is_empty() { None } else { Some(next_b(0)) };
        while i < a.len() || pending.is_some() {
            match (a.get(i), pending.as_ref()) {
                (Some(x), Some(y)) => match order.cmp(&x.0, &y.0) {
                    std::cmp::Ordering::Greater => {
                        out.push(x.clone());
                        i += 1;
                    }
                    std::cmp::Ordering::Less => {
                        let (mo, co) = pending.take().expect("pending term");
                        out.push((mo, -co));
                        j += 1;
                        pending = (j < b.len()).then(|| next_b(j));
                    }
                    std::cmp::Ordering::Equal => {
                        let co = Rational::from(&x.1 - &y.1);
                        if co != 0 {
                            out.push((x.0.clone(), co));
                        }
                        i += 1;
                        j += 1;
                        pending = (j < b.len()).then(|| next_b(j));
                    }
                },
                (Some(x), None) => {
                    out.push(x.clone());
                    i += 1;
                }
                (None, Some(_)) => {
                    let (mo, co) = pending.take().expect("pending term");
                    out.push((mo, -co));
                    j += 1;
                    pending = (j < b.len()).then(|| next_b(j));
                }
                (None, None) => unreachable!("loop condition"),
            }
        }
        DPoly { terms: out }
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
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PolyRing {
    vars: Vec<String>,
    index: HashMap<String, usize>,
    order: MonomialOrder,
}

impl PolyRing {
    /// The ring with these variables (duplicates are ignored) and this order.
    pub fn new<S: AsRef<str>>(vars: impl IntoIterator<Item = S>, order: MonomialOrder) -> Self {
        let mut out = PolyRing { vars: Vec::new(), index: HashMap::new(), order };
        for v in vars {
            let v = v.as_ref().to_string();
            if !out.index.contains_key(&v) {
                out.index.insert(v.clone(), out.vars.len());
                out.vars.push(v);
            }
        }
        out
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
        &self.vars
    }

    /// The monomial order.
    pub fn order(&self) -> MonomialOrder {
        self.order
    }

    /// The leading term (coefficient times monomial) of `p`, `None` for zero.
    pub fn leading_term(&self, p: &Poly) -> Result<Option<Poly>, IdealError> {
        let d = self.to_dense(p)?;
        Ok(d.terms.first().map(|t| self.to_poly(&DPoly { terms: vec![t.clone()] })))
    }

    pub(crate) fn to_dense(&self, p: &Poly) -> Result<DPoly, IdealError> {
        let n = self.vars.len();
        let mut terms = Vec::new();
        for (c, m) in p.terms() {
            let mut e = vec![0u32; n];
            for (name, k) in m {
                let i = *self.index.get(&name).ok_or(IdealError::UnknownVariable(name))?;
                e[i] += k;
            }
            terms.push((Mono::from_exps(e), c.clone()));
        }
        terms.sort_by(|a, b| self.order.cmp(&b.0, &a.0));
        Ok(DPoly { terms })
    }

    pub(crate) fn to_poly(&self, p: &DPoly) -> Poly {
        Poly::from_terms(p.terms.iter().map(|(m, c)| {
            let vars = m.e.iter().enumerate().filter(|(_, e)| **e > 0);
            (c.clone(), vars.map(|(i, e)| (self.vars[i].clone(), *e)).collect())
        }))
    }
}

#[cfg(test)]
mod tests;
