//! Inverse and division over a [`Field`]: exact Gaussian elimination on the matrix of left
//! multiplication, so it works for every metric (degenerate too) without closed forms.

use super::{Multivector, MvError};
use crate::scalar::{Field, Ring};

use crate::tables::Product;

impl<T: Field> Multivector<T> {
    /// The two-sided inverse, or [`MvError::NotInvertible`] for a zero divisor.
    ///
    /// Solves `self * y = 1` by Gaussian elimination on the `2^n x 2^n` matrix of left
    /// multiplication (exact over rationals; partial pivoting over floats, where a pivot
    /// below `64 · ε · 2^n · max|entry|` counts as zero). In a finite-dimensional associative
    /// algebra a right inverse is also a left inverse.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, MvError, rational::{Q, ratio}};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// let e0 = Multivector::<Q>::basis_element(&alg, Basis::Product, "e0").unwrap();
    /// assert!(matches!(e0.inverse(), Err(MvError::NotInvertible(_)))); // e0^2 = 0
    /// // 2 + e0inf = 1 + e0^einf is a zero divisor ((e0^einf)^2 = 1); 3 + e0inf is not.
    /// let z = Multivector::<Q>::from_terms(&alg, Basis::Product, [("1", ratio(2, 1)), ("e0inf", ratio(1, 1))]).unwrap();
    /// assert!(z.inverse().is_err());
    /// let x = Multivector::<Q>::from_terms(&alg, Basis::Product, [("1", ratio(3, 1)), ("e0inf", ratio(1, 1))]).unwrap();
    /// let y = x.inverse().unwrap();
    /// assert_eq!(&x * &y, Multivector::scalar(&alg, Basis::Product, ratio(1, 1)));
    /// ```
    #[allow(clippy::needless_range_loop)] // matrix assembly reads clearest with indices
    pub fn inverse(&self) -> Result<Self, MvError> {
        if !self.coeffs.iter().all(Ring::is_finite_value) {
            // a NaN pivot would otherwise be reported as "not invertible"
            let (value, why) = (self.describe(), "coefficients are not finite".to_string());
            return Err(MvError::Undefined { op: "inverse", value, why });
        }
        let dim = self.algebra.dim();
        let table = self.algebra.tables().product(self.basis, Product::Geometric);
        // column j of L = self * e_j
        let mut l: Vec<Vec<T>> = vec![vec![T::zero(); dim]; dim];
        for (a, x) in self.coeffs.iter().enumerate() {
            if x.is_exact_zero() {
                continue;
            }
            for j in 0..dim {
                for (k, c) in table.at(a as u32, j as u32) {
                    l[*k as usize][j].add_assign_ref(&x.scale_rational(c));
                }
            }
        }
        let mut rhs: Vec<T> = vec![T::zero(); dim];
        rhs[0] = T::one();
        let y = crate::linalg::solve(l, rhs).ok_or_else(|| MvError::NotInvertible(self.describe()))?;
        Ok(Multivector { algebra: self.algebra.clone(), basis: self.basis, coeffs: y })
    }

    /// `self * rhs^-1`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let e1 = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e1").unwrap();
    /// let e12 = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e12").unwrap();
    /// assert_eq!(e12.div(&e1).unwrap().to_string(), "-e2");
    /// ```
    pub fn div(&self, rhs: &Self) -> Result<Self, MvError> {
        self.same_algebra(rhs)?;
        Ok(self.gp(&rhs.inverse()?))
    }
}
