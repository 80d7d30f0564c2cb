//! [`Poly`]: sparse multivariate polynomials with exact GMP rational coefficients, in
//! canonical form, so `==` decides polynomial identity.
//!
//! Used as the scalar of symbolic checks: run the ordinary multivector code with symbols as
//! coefficients and compare with the paper's closed forms exactly.
//!
//! Canonical form: a map from monomials (variable, exponent) with positive exponents, sorted by
//! variable, to non-zero coefficients. Variables are interned process-wide by name. Printing
//! follows the CLI contract: `2*S*S1inf - S12**2 + 1/2*x`, terms by descending total degree,
//! then lexicographically by variable names.

use crate::rational::Q;
use crate::scalar::Ring;
use crate::scalar::mprational::rug_rational;
use rug::Rational;
use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::sync::{OnceLock, RwLock};

/// Process-wide variable names, indexed by id.
#[derive(Default)]
struct Interner {
    names: Vec<String>,
    ids: HashMap<String, u32>,
}

fn interner() -> &'static RwLock<Interner> {
    static I: OnceLock<RwLock<Interner>> = OnceLock::new();
    I.get_or_init(Default::default)
}

pub(crate) fn intern(name: &str) -> u32 {
    if let Some(&id) = interner().read().expect("interner lock").ids.get(name) {
        return id;
    }
    let mut w = interner().write().expect("interner lock");
    if let Some(&id) = w.ids.get(name) {
        return id;
    }
    let id = w.names.len() as u32;
    w.names.push(name.to_string());
    w.ids.insert(name.to_string(), id);
    id
}

pub(crate) fn var_name(id: u32) -> String {
    interner().read().expect("interner lock").names[id as usize].clone()
}

/// A monomial: `(variable id, exponent >= 1)` sorted by id; empty for the constant 1.
type Monomial = Vec<(u32, u32)>;

fn mul_monomials(a: &Monomial, b: &Monomial) -> Monomial {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].0.cmp(&b[j].0) {
            std::cmp::Ordering::Less => {
                out.push(a[i]);
                i += 1;
            }
            std::cmp::Ordering::Greater => {
                out.push(b[j]);
                j += 1;
            }
            std::cmp::Ordering::Equal => {
                out.push((a[i].0, a[i].1 + b[j].1));
                i += 1;
                j += 1;
            }
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
}

/// A polynomial in named variables with exact rational coefficients.
///
/// ```
/// use algebra_core::{Poly, Ring};
/// let (x, y) = (Poly::var("x"), Poly::var("y"));
/// let lhs = (x.clone() + y.clone()) * (x.clone() - y.clone());
/// let rhs = x.clone() * x.clone() - y.clone() * y.clone();
/// assert_eq!(lhs, rhs); // identity decided by canonical form
/// assert_eq!(lhs.to_string(), "x**2 - y**2");
/// assert_eq!((x * Poly::from_ratio(1, 2)).to_string(), "1/2*x");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Poly {
    terms: BTreeMap<Monomial, Rational>,
}

impl Poly {
    /// The variable `name`.
    ///
    /// ```
    /// assert_eq!(algebra_core::Poly::var("S12").to_string(), "S12");
    /// ```
    pub fn var(name: &str) -> Self {
        let mut terms = BTreeMap::new();
        terms.insert(vec![(intern(name), 1)], Rational::from(1));
        Poly { terms }
    }

    /// The constant `c`.
    ///
    /// ```
    /// use algebra_core::{Poly, rational::ratio};
    /// assert_eq!(Poly::from_q(&ratio(-3, 4)).to_string(), "-3/4");
    /// ```
    pub fn from_q(c: &Q) -> Self {
        Poly::constant(rug_rational(c))
    }

    /// The constant `c` (a rug rational).
    ///
    /// ```
    /// assert!(algebra_core::Poly::constant(rug::Rational::new()).terms().next().is_none());
    /// ```
    pub fn constant(c: Rational) -> Self {
        let mut terms = BTreeMap::new();
        if c != 0 {
            terms.insert(Vec::new(), c);
        }
        Poly { terms }
    }

    /// The polynomial `sum c * prod name**e` from `(coefficient, [(name, exponent)])` terms, the
    /// inverse of [`Poly::terms`] (like terms are added; zero exponents are dropped).
    ///
    /// ```
    /// use algebra_core::Poly;
    /// let p = Poly::from_terms([(rug::Rational::from(2), vec![("x".to_string(), 2)])]);
    /// assert_eq!(Poly::from_terms(p.terms().map(|(c, m)| (c.clone(), m))), p);
    /// ```
    pub fn from_terms(terms: impl IntoIterator<Item = (Rational, Vec<(String, u32)>)>) -> Self {
        let mut out = Poly::default();
        for (c, m) in terms {
            let mut mono: Monomial = Vec::new();
            for (name, e) in m.into_iter().filter(|&(_, e)| e > 0) {
                mono = mul_monomials(&mono, &vec![(intern(&name), e)]);
            }
            out.add_term(mono, c);
        }
        out
    }

    /// The value when the polynomial is a constant, else `None`.
    ///
    /// ```
    /// use algebra_core::{Poly, Ring};
    /// assert_eq!(Poly::from_i64(3).as_constant(), Some(rug::Rational::from(3)));
    /// assert_eq!(Poly::var("x").as_constant(), None);
    /// assert_eq!(Poly::zero().as_constant(), Some(rug::Rational::new()));
    /// ```
    pub fn as_constant(&self) -> Option<Rational> {
        match self.terms.len() {
            0 => Some(Rational::new()),
            1 => self.terms.get(&Vec::new()).cloned(),
            _ => None,
        }
    }

    /// The terms as `(coefficient, [(variable, exponent)])`, in storage order.
    ///
    /// ```
    /// use algebra_core::Poly;
    /// let p = Poly::var("x") * Poly::var("x");
    /// let (c, m) = p.terms().next().unwrap();
    /// assert_eq!(*c, 1);
    /// assert_eq!(m, vec![("x".to_string(), 2)]);
    /// ```
    pub fn terms(&self) -> impl Iterator<Item = (&Rational, Vec<(String, u32)>)> {
        self.terms.iter().map(|(m, c)| (c, m.iter().map(|&(v, e)| (var_name(v), e)).collect()))
    }

    /// The total degree (`0` for constants, including zero).
    ///
    /// ```
    /// use algebra_core::Poly;
    /// assert_eq!((Poly::var("x") * Poly::var("y") + Poly::var("z")).degree(), 2);
    /// ```
    pub fn degree(&self) -> u32 {
        self.terms.keys().map(|m| m.iter().map(|&(_, e)| e).sum()).max().unwrap_or(0)
    }

    /// The names of the variables that occur, sorted.
    ///
    /// ```
    /// use algebra_core::Poly;
    /// assert_eq!((Poly::var("b") * Poly::var("a")).variables(), ["a", "b"]);
    /// ```
    pub fn variables(&self) -> Vec<String> {
        let mut ids: Vec<u32> = self.terms.keys().flatten().map(|&(v, _)| v).collect();
        ids.sort_unstable();
        ids.dedup();
        let mut names: Vec<String> = ids.into_iter().map(var_name).collect();
        names.sort();
        names
    }

    /// The partial derivative with respect to `name`.
    ///
    /// ```
    /// use algebra_core::{Poly, Ring};
    /// let x = Poly::var("x");
    /// let p = x.clone() * x.clone() * x.clone() + x.clone();
    /// assert_eq!(p.derivative("x").to_string(), "3*x**2 + 1");
    /// ```
    pub fn derivative(&self, name: &str) -> Self {
        let v = intern(name);
        let mut out = Poly::default();
        for (m, c) in &self.terms {
            if let Some(pos) = m.iter().position(|&(id, _)| id == v) {
                let e = m[pos].1;
                let mut dm = m.clone();
                if e == 1 {
                    dm.remove(pos);
                } else {
                    dm[pos].1 = e - 1;
                }
                out.add_term(dm, Rational::from(c * e));
            }
        }
        out
    }

    /// Substitutes `value` for the variable `name`.
    ///
    /// ```
    /// use algebra_core::{Poly, Ring};
    /// let (x, y) = (Poly::var("x"), Poly::var("y"));
    /// let p = x.clone() * x.clone() + y.clone();
    /// assert_eq!(p.substitute("x", &(y.clone() + Poly::one())).to_string(), "y**2 + 3*y + 1");
    /// ```
    pub fn substitute(&self, name: &str, value: &Poly) -> Self {
        let v = intern(name);
        let mut out = Poly::default();
        for (m, c) in &self.terms {
            let mut rest = m.clone();
            let mut term = Poly::constant(c.clone());
            if let Some(pos) = rest.iter().position(|&(id, _)| id == v) {
                let e = rest.remove(pos).1;
                term = term.mul_ref(&value.pow_u32(e));
            }
            let mut mono = Poly::default();
            mono.terms.insert(rest, Rational::from(1));
            out = out + term * mono;
        }
        out
    }

    /// The value at a point: `value(name)` gives each variable's value; `None` when a variable
    /// of the polynomial has none. One pass over the terms (each variable is looked up once), so
    /// evaluating at a point of `n` variables costs `O(terms × variables per term)`, unlike `n`
    /// calls of [`Poly::substitute`].
    ///
    /// ```
    /// use algebra_core::{Poly, Ring};
    /// use rug::Rational;
    /// let (x, y) = (Poly::var("x"), Poly::var("y"));
    /// let p = x.clone() * x.clone() * y.clone() - Poly::from_ratio(1, 2) * y;
    /// let at = |v: &str| match v { "x" => Some(Rational::from(3)), "y" => Some(Rational::from((2, 5))), _ => None };
    /// assert_eq!(p.evaluate(at), Some(Rational::from((17, 5))));
    /// assert_eq!(x.evaluate(|_| None), None);
    /// ```
    pub fn evaluate(&self, value: impl Fn(&str) -> Option<Rational>) -> Option<Rational> {
        let mut values: HashMap<u32, Rational> = HashMap::new();
        let mut sum = Rational::new();
        for (m, c) in &self.terms {
            let mut t = c.clone();
            for &(v, e) in m {
                let x = match values.entry(v) {
                    std::collections::hash_map::Entry::Occupied(o) => o.into_mut(),
                    std::collections::hash_map::Entry::Vacant(slot) => slot.insert(value(&var_name(v))?),
                };
                t *= Rational::from(rug::ops::Pow::pow(&*x, e));
            }
            sum += t;
        }
        Some(sum)
    }

    /// The largest number of distinct variables in one term (0 for constants): with
    /// [`Poly::term_count`], what the memory of a product is estimated from.
    ///
    /// ```
    /// use algebra_core::{Poly, Ring};
    /// let (x, y) = (Poly::var("x"), Poly::var("y"));
    /// assert_eq!((x.clone() * x.clone() * y + x + Poly::one()).max_term_variables(), 2);
    /// ```
    pub fn max_term_variables(&self) -> usize {
        self.terms.keys().map(Vec::len).max().unwrap_or(0)
    }

    /// Multiplies by a rational constant.
    ///
    /// ```
    /// use algebra_core::Poly;
    /// assert_eq!(Poly::var("x").scale(&rug::Rational::from((1, 3))).to_string(), "1/3*x");
    /// ```
    pub fn scale(&self, c: &Rational) -> Self {
        if *c == 0 {
            return Poly::default();
        }
        Poly { terms: self.terms.iter().map(|(m, k)| (m.clone(), Rational::from(k * c))).collect() }
    }

    /// The number of (non-zero) terms.
    ///
    /// ```
    /// use algebra_core::{Poly, Ring};
    /// assert_eq!((Poly::var("x") + Poly::var("y") + Poly::from_ratio(1, 2)).term_count(), 3);
    /// assert_eq!(Poly::zero().term_count(), 0);
    /// ```
    pub fn term_count(&self) -> usize {
        self.terms.len()
    }

    /// `self * rhs`, or [`TermBudget`] *before any work* when the product would form more
    /// than `max_terms` term products (`terms(self) × terms(rhs)`, which bounds both the
    /// time and the number of terms of the result).
    ///
    /// ```
    /// use algebra_core::{Poly, Ring, poly::TermBudget};
    /// let s = (0..100).map(|i| Poly::var(&format!("x{i}"))).fold(Poly::zero(), |a, b| a + b);
    /// assert_eq!(s.checked_mul(&s, 10_000).unwrap().term_count(), 5050);
    /// assert_eq!(s.checked_mul(&s, 9_999), Err(TermBudget { estimate: 10_000, budget: 9_999 }));
    /// ```
    pub fn checked_mul(&self, rhs: &Poly, max_terms: u64) -> Result<Poly, TermBudget> {
        let estimate = self.terms.len() as u128 * rhs.terms.len() as u128;
        if estimate > u128::from(max_terms) {
            return Err(TermBudget { estimate, budget: max_terms });
        }
        Ok(self.product(rhs))
    }

    /// The terms as `([(variable id, exponent)] sorted by id, coefficient)`, ids from
    /// [`intern`]: the ideal module's conversions, without a name per factor.
    pub(crate) fn id_terms(&self) -> impl Iterator<Item = (&[(u32, u32)], &Rational)> {
        self.terms.iter().map(|(m, c)| (m.as_slice(), c))
    }

    /// The inverse of [`Poly::id_terms`] (like terms are added, zero coefficients dropped;
    /// each monomial sorted by id with positive exponents).
    pub(crate) fn from_id_terms(terms: impl IntoIterator<Item = (Vec<(u32, u32)>, Rational)>) -> Self {
        let mut out = Poly::default();
        for (m, c) in terms {
            debug_assert!(m.windows(2).all(|w| w[0].0 < w[1].0) && m.iter().all(|f| f.1 > 0));
            out.add_term(m, c);
        }
        out
    }

    fn add_term(&mut self, m: Monomial, c: Rational) {
        if c == 0 {
            return;
        }
        use std::collections::btree_map::Entry;
        match self.terms.entry(m) {
            Entry::Vacant(e) => {
                e.insert(c);
            }
            Entry::Occupied(mut e) => {
                *e.get_mut() += c;
                if *e.get() == 0 {
                    e.remove();
                }
            }
        }
    }

    fn combine(&self, rhs: &Poly, negate: bool) -> Poly {
        let mut out = self.clone();
        for (m, c) in &rhs.terms {
            out.add_term(m.clone(), if negate { Rational::from(-c) } else { c.clone() });
        }
        out
    }

    fn product(&self, rhs: &Poly) -> Poly {
        let mut out = Poly::default();
        for (ma, ca) in &self.terms {
            for (mb, cb) in &rhs.terms {
                out.add_term(mul_monomials(ma, mb), Rational::from(ca * cb));
            }
        }
        out
    }
}

/// A polynomial product refused before any work: it would form `estimate` term products,
/// more than the `budget` (see [`Poly::checked_mul`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TermBudget {
    /// `terms(a) × terms(b)` (summed over the table entries for a multivector product).
    pub estimate: u128,
    /// The allowed number of term products.
    pub budget: u64,
}

impl fmt::Display for TermBudget {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "the product needs {} term products, more than the budget of {}", self.estimate, self.budget)
    }
}

impl std::error::Error for TermBudget {}

impl fmt::Display for Poly {
    /// `2*S*S1inf - S12**2 + 1/2*x`; `0` for the zero polynomial.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return f.write_str("0");
        }
        let mut terms: Vec<(u32, Vec<String>, String)> = self
            .terms
            .iter()
            .map(|(m, c)| {
                let mut factors: Vec<(String, u32)> = m.iter().map(|&(v, e)| (var_name(v), e)).collect();
                factors.sort();
                let key: Vec<String> =
                    factors.iter().flat_map(|(n, e)| std::iter::repeat_n(n.clone(), *e as usize)).collect();
                let mono: Vec<String> =
                    factors.iter().map(|(n, e)| if *e == 1 { n.clone() } else { format!("{n}**{e}") }).collect();
                let mono = mono.join("*");
                let coeff =
                    if *c.denom() == 1 { c.numer().to_string() } else { format!("{}/{}", c.numer(), c.denom()) };
                let text = match (mono.is_empty(), coeff.as_str()) {
                    (true, _) => coeff,
                    (false, "1") => mono,
                    (false, "-1") => format!("-{mono}"),
                    (false, _) => format!("{coeff}*{mono}"),
                };
                (m.iter().map(|&(_, e)| e).sum::<u32>(), key, text)
            })
            .collect();
        terms.sort_by(|a, b| b.0.cmp(&a.0).then_with(|| a.1.cmp(&b.1)));
        let mut first = true;
        for (_, _, t) in terms {
            if first {
                f.write_str(&t)?;
                first = false;
            } else if let Some(rest) = t.strip_prefix('-') {
                write!(f, " - {rest}")?;
            } else {
                write!(f, " + {t}")?;
            }
        }
        Ok(())
    }
}

impl Add for Poly {
    type Output = Poly;
    fn add(self, rhs: Poly) -> Poly {
        self.combine(&rhs, false)
    }
}
impl<'a> Add<&'a Poly> for Poly {
    type Output = Poly;
    fn add(self, rhs: &'a Poly) -> Poly {
        self.combine(rhs, false)
    }
}
impl Sub for Poly {
    type Output = Poly;
    fn sub(self, rhs: Poly) -> Poly {
        self.combine(&rhs, true)
    }
}
impl<'a> Sub<&'a Poly> for Poly {
    type Output = Poly;
    fn sub(self, rhs: &'a Poly) -> Poly {
        self.combine(rhs, true)
    }
}
impl Mul for Poly {
    type Output = Poly;
    fn mul(self, rhs: Poly) -> Poly {
        self.product(&rhs)
    }
}
impl<'a> Mul<&'a Poly> for Poly {
    type Output = Poly;
    fn mul(self, rhs: &'a Poly) -> Poly {
        self.product(rhs)
    }
}
impl Neg for Poly {
    type Output = Poly;
    fn neg(mut self) -> Poly {
        for c in self.terms.values_mut() {
            *c = Rational::from(-&*c);
        }
        self
    }
}

impl Ring for Poly {
    fn zero() -> Self {
        Poly::default()
    }
    fn one() -> Self {
        Poly::constant(Rational::from(1))
    }
    fn from_i64(n: i64) -> Self {
        Poly::constant(Rational::from(n))
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        Poly::constant(Rational::from((num, den)))
    }
    fn from_rational(q: &Q) -> Self {
        Poly::from_q(q)
    }
    fn is_exact_zero(&self) -> bool {
        self.terms.is_empty()
    }
    /// The largest absolute coefficient (not a norm of the function; only for diagnostics).
    fn magnitude(&self) -> f64 {
        self.terms.values().map(|c| c.to_f64().abs()).fold(0.0, f64::max)
    }
    fn relative_epsilon() -> f64 {
        0.0
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        self.combine(rhs, false)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.combine(rhs, true)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.product(rhs)
    }
    fn add_assign_ref(&mut self, rhs: &Self) {
        for (m, c) in &rhs.terms {
            self.add_term(m.clone(), c.clone());
        }
    }
    fn sub_assign_ref(&mut self, rhs: &Self) {
        for (m, c) in &rhs.terms {
            self.add_term(m.clone(), Rational::from(-c));
        }
    }
    fn scale_rational(&self, q: &Q) -> Self {
        self.scale(&rug_rational(q))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn canonical_form_decides_identity() {
        let (a, b, c) = (Poly::var("a"), Poly::var("b"), Poly::var("c"));
        // (a + b + c)^3 expanded two ways
        let s = a.clone() + b.clone() + c.clone();
        let cube = s.pow_u32(3);
        let by_hand = a.pow_u32(3)
            + b.pow_u32(3)
            + c.pow_u32(3)
            + Poly::from_i64(3)
                * (a.clone() * a.clone() * (b.clone() + c.clone())
                    + b.clone() * b.clone() * (a.clone() + c.clone())
                    + c.clone() * c.clone() * (a.clone() + b.clone()))
            + Poly::from_i64(6) * a.clone() * b.clone() * c.clone();
        assert_eq!(cube, by_hand);
        assert_eq!((cube.clone() - by_hand).to_string(), "0");
        assert_ne!(cube, s);
    }

    #[test]
    fn prints_in_contract_syntax() {
        let (s, s1inf, s12, x) = (Poly::var("S"), Poly::var("S1inf"), Poly::var("S12"), Poly::var("x"));
        let p = Poly::from_i64(2) * s * s1inf - s12.clone() * s12 + Poly::from_ratio(1, 2) * x;
        assert_eq!(p.to_string(), "2*S*S1inf - S12**2 + 1/2*x");
        assert_eq!((Poly::from_i64(-1) - Poly::var("y")).to_string(), "-y - 1");
    }

    #[test]
    fn agrees_with_rational_evaluation() {
        // p(x, y) = (x - 2y)^2 (x + 1/3) at x = 3/2, y = -1/5, against direct rational arithmetic.
        let (x, y) = (Poly::var("x"), Poly::var("y"));
        let p = (x.clone() - Poly::from_i64(2) * y.clone()).pow_u32(2) * (x + Poly::from_ratio(1, 3));
        let at = p.substitute("x", &Poly::from_ratio(3, 2)).substitute("y", &Poly::from_ratio(-1, 5));
        let (xv, yv) = (Rational::from((3, 2)), Rational::from((-1, 5)));
        let d = &xv - Rational::from(&yv * 2);
        let direct = Rational::from(&d * &d) * (xv + Rational::from((1, 3)));
        assert_eq!(at.as_constant(), Some(direct));
    }
}
