//! Division with remainder by a list of polynomials, and full reduction (normal forms).

use super::order::Mono;
use super::{DPoly, IdealError, Meter, MonomialOrder, PolyRing};
use crate::Ring;
use crate::poly::Poly;
use rug::Rational;

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

/// A divisor ready for reduction: leading monomial, its variable mask, the polynomial.
pub(crate) struct Reducer<'a> {
    pub(crate) lm: &'a Mono,
    pub(crate) mask: u64,
    pub(crate) poly: &'a DPoly,
}

impl<'a> Reducer<'a> {
    pub(crate) fn new(poly: &'a DPoly) -> Self {
        Reducer { lm: poly.lm(), mask: poly.lm().mask(), poly }
    }
}

/// The first divisor whose leading monomial divides `m`.
fn find_divisor(divisors: &[Reducer<'_>], m: &Mono) -> Option<usize> {
    let mask = m.mask();
    divisors.iter().position(|d| d.mask & !mask == 0 && d.lm.divides(m))
}

/// The textbook division algorithm; `quotients` are recorded when `quotients` is `Some`.
pub(crate) fn reduce(
    f: DPoly,
    divisors: &[Reducer<'_>],
    order: MonomialOrder,
    meter: &mut Meter,
    mut quotients: Option<&mut Vec<Vec<(Mono, Rational)>>>,
) -> Result<DPoly, IdealError> {
    let mut p = f;
    let mut start = 0;
    let mut rem = Vec::new();
    while start < p.terms.len() {
        meter.check(p.terms.len() - start)?;
        let (m, c) = &p.terms[start];
        match find_divisor(divisors, m) {
            Some(i) => {
                let d = &divisors[i];
                let q = d.lm.quotient_of(m);
                let coef = Rational::from(c / d.poly.lc());
                if let Some(qs) = quotients.as_deref_mut() {
                    qs[i].push((q.clone(), coef.clone()));
                }
                p = p.sub_mul(start + 1, &coef, &q, d.poly, order);
                start = 0;
            }
            None => {
                rem.push(p.terms[start].clone());
                start += 1;
            }
        }
    }
    Ok(DPoly { terms: rem })
}

impl PolyRing {
    /// Divides `f` by the list `divisors` in the ring's order (the first divisor whose leading
    /// monomial divides the current leading term is used). The remainder depends on the order
    /// of the list unless the list is a Gröbner basis.
    pub fn divide(&self, f: &Poly, divisors: &[Poly], budget: &super::Budget) -> Result<Division, IdealError> {
        let f = self.to_dense(f)?;
        let dense: Vec<DPoly> = divisors
            .iter()
            .map(|g| self.to_dense(g))
            .filter(|g| !matches!(g, Ok(d) if d.is_zero()))
            .collect::<Result<_, _>>()?;
        let reducers: Vec<Reducer<'_>> = dense.iter().map(Reducer::new).collect();
        let mut qs = vec![Vec::new(); reducers.len()];
        let mut meter = Meter::new(budget);
        let r = reduce(f, &reducers, self.order, &mut meter, Some(&mut qs))?;
        // Map quotient terms back to the caller's list (zero divisors get a zero quotient).
        let mut quotients = Vec::with_capacity(divisors.len());
        let mut k = 0;
        for g in divisors {
            if g.is_exact_zero() {
                quotients.push(Poly::default());
            } else {
                let mut terms = std::mem::take(&mut qs[k]);
                terms.sort_by(|a, b| self.order.cmp(&b.0, &a.0));
                quotients.push(self.to_poly(&DPoly { terms }));
                k += 1;
            }
        }
        Ok(Division { quotients, remainder: self.to_poly(&r) })
    }
}
