//! Symbolic elements: a general element of a part of the algebra (a grade, the even or odd
//! part, everything, or a list of basis elements) whose coefficients are [`Poly`] symbols named
//! by a prefix and the basis element's label: `S` for the scalar, `S12`, `S1inf`, `S123inf`, ...
//! (the names the CLI prints, and the names of `gam prove`'s builders `even("S")`, ...).

use super::{Multivector, MvError};
use crate::algebra::Algebra;
use crate::basis::Basis;
use crate::poly::{Poly, TermBudget};
use crate::scalar::Ring;
use crate::tables::Product;
use std::sync::Arc;

/// Which basis elements a symbolic element has a coefficient on. Grades count generators in the
/// element's own basis (true grades in the blade basis; subset sizes in the product basis).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Part {
    /// Every basis element.
    All,
    /// Basis elements with an even number of generators.
    Even,
    /// Basis elements with an odd number of generators.
    Odd,
    /// Basis elements with exactly `k` generators (`Grade(1)`: a general vector).
    Grade(usize),
    /// The named basis elements (`"1"`, `"e12"`, ...).
    Elements(Vec<String>),
}

impl Part {
    /// [`Part::Elements`] from a list of basis names, e.g. a generated type's `ELEMENTS`: with
    /// the type's `project`, a symbolic element of a generated type is
    /// `Motor::project(&Multivector::symbolic(&algebra(), BASIS, "S", &Part::elements(&Motor::ELEMENTS))?)`.
    ///
    /// ```
    /// use algebra_core::multivector::symbolic::Part;
    /// assert_eq!(Part::elements(&["1", "e12"]), Part::Elements(vec!["1".into(), "e12".into()]));
    /// ```
    pub fn elements(names: &[&str]) -> Part {
        Part::Elements(names.iter().map(|n| n.to_string()).collect())
    }
}

/// The coefficient symbol of basis element `name` for `prefix`: `prefix` for the scalar `1`,
/// otherwise `prefix` followed by the labels (`e12` -> `S12`).
///
/// ```
/// use algebra_core::multivector::symbolic::coefficient_symbol;
/// assert_eq!(coefficient_symbol("S", "1"), "S");
/// assert_eq!(coefficient_symbol("S", "e123inf"), "S123inf");
/// ```
pub fn coefficient_symbol(prefix: &str, name: &str) -> String {
    crate::symbol::coefficient_name(prefix, name)
}

impl Multivector<Poly> {
    /// A general element of `part` with coefficient symbols `prefix` + label, in `basis`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, Poly};
    /// use algebra_core::multivector::symbolic::Part;
    /// let alg = Algebra::builtin("g123inf").unwrap();
    /// let s = Multivector::<Poly>::symbolic(&alg, Basis::Product, "S", &Part::Even).unwrap();
    /// assert_eq!(s.to_string(), "S + S12*e12 + S13*e13 + S23*e23 + S1inf*e1inf + S2inf*e2inf + S3inf*e3inf + S123inf*e123inf");
    /// let v = Multivector::<Poly>::symbolic(&alg, Basis::Blade, "x", &Part::Grade(1)).unwrap();
    /// assert_eq!(v.to_string(), "x1*e1 + x2*e2 + x3*e3 + xinf*einf");
    /// ```
    pub fn symbolic(algebra: &Arc<Algebra>, basis: Basis, prefix: &str, part: &Part) -> Result<Self, MvError> {
        let mut out = Multivector::zero(algebra, basis);
        let masks: Vec<u32> = match part {
            Part::Elements(names) => names.iter().map(|n| algebra.mask_of(n)).collect::<Result<_, _>>()?,
            _ => algebra
                .basis_order()
                .iter()
                .copied()
                .filter(|m| {
                    let k = m.count_ones() as usize;
                    match part {
                        Part::All => true,
                        Part::Even => k.is_multiple_of(2),
                        Part::Odd => k % 2 == 1,
                        Part::Grade(g) => k == *g,
                        Part::Elements(_) => unreachable!("handled above"),
                    }
                })
                .collect(),
        };
        for m in masks {
            out.coeffs_mut()[m as usize] = Poly::var(&coefficient_symbol(prefix, algebra.name_at(m)));
        }
        Ok(out)
    }

    /// The coefficient polynomials that are not identically zero, with their basis names: the
    /// component-wise reading of a multivector equation `self = 0`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, Poly, Ring};
    /// use algebra_core::multivector::symbolic::Part;
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let v = Multivector::<Poly>::symbolic(&alg, Basis::Blade, "v", &Part::Grade(1)).unwrap();
    /// let eqs = (&v * &v).components();
    /// assert_eq!(eqs.len(), 1);
    /// assert_eq!(eqs[0].0, "1");
    /// assert_eq!(eqs[0].1.to_string(), "v1**2 + v2**2 + v3**2");
    /// ```
    pub fn components(&self) -> Vec<(String, Poly)> {
        self.terms().filter(|(_, _, c)| !c.is_exact_zero()).map(|(_, n, c)| (n.to_string(), c.clone())).collect()
    }

    /// The number of coefficient term products `rhs`'s `product` with `self` would form:
    /// `Σ terms(a_i) · terms(b_j) · |table(i, j)|` over the table entries (in `self`'s basis).
    /// It bounds the work and the number of terms of the result, and costs one pass over the
    /// table.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, Poly, Product};
    /// use algebra_core::multivector::symbolic::Part;
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let v = Multivector::symbolic(&alg, Basis::Blade, "a", &Part::Grade(1)).unwrap();
    /// // v v: each of the 3 x 3 pairs of one-term coefficients meets one table entry
    /// assert_eq!(v.product_terms(&v, Product::Geometric).unwrap(), 9);
    /// ```
    pub fn product_terms(&self, rhs: &Self, product: Product) -> Result<u128, MvError> {
        let rhs = self.operand(rhs)?;
        let table = self.algebra.tables().product(self.basis, product);
        let mut total = 0u128;
        for (a, x) in self.coeffs.iter().enumerate().filter(|(_, x)| !x.is_exact_zero()) {
            for (b, y) in rhs.coeffs.iter().enumerate().filter(|(_, y)| !y.is_exact_zero()) {
                let entries = table.at(a as u32, b as u32).len() as u128;
                total += entries * x.term_count() as u128 * y.term_count() as u128;
            }
        }
        Ok(total)
    }

    /// `product` of `self` and `rhs`, or [`MvError::TooManyTerms`] *before any work* when
    /// [`Multivector::product_terms`] exceeds `max_terms`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, MvError, Product};
    /// use algebra_core::multivector::symbolic::Part;
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let v = Multivector::symbolic(&alg, Basis::Blade, "a", &Part::Grade(1)).unwrap();
    /// assert!(v.checked_product(&v, Product::Geometric, 9).is_ok());
    /// assert!(matches!(v.checked_product(&v, Product::Geometric, 8), Err(MvError::TooManyTerms(_))));
    /// ```
    pub fn checked_product(&self, rhs: &Self, product: Product, max_terms: u64) -> Result<Self, MvError> {
        let estimate = self.product_terms(rhs, product)?;
        if estimate > u128::from(max_terms) {
            return Err(MvError::TooManyTerms(TermBudget { estimate, budget: max_terms }));
        }
        self.try_product(rhs, product)
    }
}
