//! Products and arithmetic operators.

use super::{Multivector, MvError};
use crate::scalar::Ring;
use crate::tables::Product;
use std::ops::{Add, BitXor, Mul, Neg, Sub};

impl<T: Ring> Multivector<T> {
    /// `self ∘ rhs` for any tabled product; `rhs` is first brought into `self`'s basis.
    /// Fails only when the operands belong to different algebras.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, Product, rational::Q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// let e0 = Multivector::<Q>::basis_element(&alg, Basis::Product, "e0").unwrap();
    /// let einf = Multivector::<Q>::basis_element(&alg, Basis::Product, "einf").unwrap();
    /// assert_eq!(e0.try_product(&einf, Product::Scalar).unwrap().to_string(), "-1");
    /// ```
    pub fn try_product(&self, rhs: &Self, product: Product) -> Result<Self, MvError> {
        let rhs = &*self.operand(rhs)?;
        let table = self.algebra.tables().product(self.basis, product);
        let mut out = Self::zero(&self.algebra, self.basis);
        for (a, x) in self.coeffs.iter().enumerate() {
            if x.is_exact_zero() {
                continue;
            }
            for (b, y) in rhs.coeffs.iter().enumerate() {
                if y.is_exact_zero() {
                    continue;
                }
                let entry = table.at(a as u32, b as u32);
                if entry.is_empty() {
                    continue;
                }
                let xy = x.mul_ref(y);
                for (k, c) in entry {
                    out.coeffs[*k as usize].add_assign_ref(&xy.scale_rational(c));
                }
            }
        }
        Ok(out)
    }

    /// `self ∘ rhs`.
    ///
    /// # Panics
    /// When the operands belong to different algebras (use [`Multivector::try_product`]).
    pub fn product(&self, rhs: &Self, product: Product) -> Self {
        self.try_product(rhs, product).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The geometric product (also `&a * &b`).
    pub fn gp(&self, rhs: &Self) -> Self {
        self.product(rhs, Product::Geometric)
    }
    /// The outer product (also `&a ^ &b`).
    pub fn op(&self, rhs: &Self) -> Self {
        self.product(rhs, Product::Outer)
    }
    /// The left contraction `self ⌋ rhs`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let e1 = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e1").unwrap();
    /// let e12 = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e12").unwrap();
    /// assert_eq!(e1.lc(&e12).to_string(), "e2");
    /// assert!(e12.lc(&e1).is_zero());
    /// ```
    pub fn lc(&self, rhs: &Self) -> Self {
        self.product(rhs, Product::LeftContraction)
    }
    /// The right contraction `self ⌊ rhs`.
    pub fn rc(&self, rhs: &Self) -> Self {
        self.product(rhs, Product::RightContraction)
    }
    /// The scalar product `<self rhs>_0` as a multivector.
    pub fn sp(&self, rhs: &Self) -> Self {
        self.product(rhs, Product::Scalar)
    }
    /// The regressive product `self ∨ rhs`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("pga3").unwrap();
    /// let p = |n| Multivector::<f64>::basis_element(&alg, Basis::Blade, n).unwrap();
    /// // two planes' duals meet: e123 ∨ e023 is a line-like grade-2 element
    /// assert_eq!(p("e123").regressive(&p("e023")).to_string(), "-e23");
    /// ```
    pub fn regressive(&self, rhs: &Self) -> Self {
        self.product(rhs, Product::Regressive)
    }
    /// The commutator product `(self rhs - rhs self)/2`.
    pub fn commutator(&self, rhs: &Self) -> Self {
        self.product(rhs, Product::Commutator)
    }
    /// The anticommutator product `(self rhs + rhs self)/2`.
    pub fn anticommutator(&self, rhs: &Self) -> Self {
        self.product(rhs, Product::Anticommutator)
    }

    /// The paper's sandwich `f_S(x) = rev(S) x S`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, rational::{Q, ratio}};
    /// let alg = Algebra::builtin("g123inf").unwrap();
    /// // T = 1 + 1/2 e1 einf translates along e1: rev(T) e0-free vector e2 stays e2
    /// let t = Multivector::<Q>::from_terms(&alg, Basis::Blade, [("1", ratio(1, 1)), ("e1inf", ratio(1, 2))]).unwrap();
    /// let e2 = Multivector::<Q>::basis_element(&alg, Basis::Blade, "e2").unwrap();
    /// assert_eq!(t.sandwich(&e2), e2);
    /// ```
    pub fn sandwich(&self, x: &Self) -> Self {
        self.reverse().gp(x).gp(self)
    }

    fn zip(&self, rhs: &Self, f: impl Fn(&T, &T) -> T) -> Result<Self, MvError> {
        let rhs = self.operand(rhs)?;
        let coeffs = self.coeffs.iter().zip(&rhs.coeffs).map(|(a, b)| f(a, b)).collect();
        Ok(Multivector { algebra: self.algebra.clone(), basis: self.basis, coeffs })
    }

    /// `self + rhs`, failing on an algebra mismatch.
    pub fn try_add(&self, rhs: &Self) -> Result<Self, MvError> {
        self.zip(rhs, T::add_ref)
    }
    /// `self - rhs`, failing on an algebra mismatch.
    pub fn try_sub(&self, rhs: &Self) -> Result<Self, MvError> {
        self.zip(rhs, T::sub_ref)
    }

    /// `self += rhs` in place, failing on an algebra mismatch: an accumulator is not copied,
    /// so a sum of `n` one-term polynomials costs `O(n log n)`, not the `O(n²)` of
    /// `acc = &acc + &y`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let e1 = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e1").unwrap();
    /// let mut acc = e1.clone();
    /// acc.try_add_assign(&e1).unwrap();
    /// acc.try_sub_assign(&Multivector::scalar(&alg, Basis::Blade, 3.0)).unwrap();
    /// assert_eq!(acc.to_string(), "-3 + 2*e1");
    /// ```
    pub fn try_add_assign(&mut self, rhs: &Self) -> Result<(), MvError> {
        self.zip_assign(rhs, T::add_assign_ref)
    }
    /// `self -= rhs` in place, failing on an algebra mismatch (see [`Multivector::try_add_assign`]).
    pub fn try_sub_assign(&mut self, rhs: &Self) -> Result<(), MvError> {
        self.zip_assign(rhs, T::sub_assign_ref)
    }

    fn zip_assign(&mut self, rhs: &Self, f: impl Fn(&mut T, &T)) -> Result<(), MvError> {
        let rhs = self.operand(rhs)?;
        for (a, b) in self.coeffs.iter_mut().zip(&rhs.coeffs) {
            f(a, b);
        }
        Ok(())
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident, $how:expr) => {
        impl<T: Ring> $tr<&Multivector<T>> for &Multivector<T> {
            type Output = Multivector<T>;
            /// # Panics
            /// When the operands belong to different algebras.
            fn $m(self, rhs: &Multivector<T>) -> Multivector<T> {
                let f: fn(&Multivector<T>, &Multivector<T>) -> Result<Multivector<T>, MvError> = $how;
                f(self, rhs).unwrap_or_else(|e| panic!("{e}"))
            }
        }
        impl<T: Ring> $tr for Multivector<T> {
            type Output = Multivector<T>;
            fn $m(self, rhs: Multivector<T>) -> Multivector<T> {
                (&self).$m(&rhs)
            }
        }
        impl<T: Ring> $tr<&Multivector<T>> for Multivector<T> {
            type Output = Multivector<T>;
            fn $m(self, rhs: &Multivector<T>) -> Multivector<T> {
                (&self).$m(rhs)
            }
        }
        impl<T: Ring> $tr<Multivector<T>> for &Multivector<T> {
            type Output = Multivector<T>;
            fn $m(self, rhs: Multivector<T>) -> Multivector<T> {
                self.$m(&rhs)
            }
        }
    };
}

binop!(Add, add, |a, b| a.try_add(b));
binop!(Sub, sub, |a, b| a.try_sub(b));
binop!(Mul, mul, |a, b| a.try_product(b, Product::Geometric));
binop!(BitXor, bitxor, |a, b| a.try_product(b, Product::Outer));

impl<T: Ring> Neg for &Multivector<T> {
    type Output = Multivector<T>;
    fn neg(self) -> Multivector<T> {
        self.map_coeffs(T::neg_ref)
    }
}
impl<T: Ring> Neg for Multivector<T> {
    type Output = Multivector<T>;
    fn neg(self) -> Multivector<T> {
        -&self
    }
}
