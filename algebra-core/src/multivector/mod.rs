//! [`Multivector`]: a dense multivector over a runtime [`Algebra`], generic over the scalar.
//!
//! It is the *reference* implementation: every operation is a lookup in the exact tables of
//! [`crate::tables`], with no special cases, so that generated kernels can be tested against
//! it. A multivector stores its coefficients in one [`Basis`]; binary operations bring the
//! right operand into the left operand's basis first, so mixing bases is never an error.
//!
//! Which notion each function uses:
//! - [`Multivector::grade`], [`Multivector::reverse`], [`Multivector::grade_involution`],
//!   [`Multivector::conjugate`] and every product are the *algebra's* operations (true grade,
//!   true reverse), the same whatever the basis.
//! - [`Multivector::basis_grade`] and [`Multivector::basis_reverse`] are the paper's notions
//!   "by subset size" in the multivector's own basis. They equal the true ones in the blade
//!   basis and for orthogonal generators, but not in the product basis of G_{0123inf}.

mod blocks;
pub mod display;
mod exp_log;
mod general;

pub use exp_log::F64_GENERAL_BOUND;
mod inverse;
mod ops;
mod scaling;
#[cfg(feature = "rug")]
pub mod symbolic;

use crate::algebra::Algebra;
use crate::basis::{Basis, BasisError, grade};
use crate::scalar::Ring;
use crate::tables::{LinearMap, Unary};
use std::sync::Arc;

/// Why a multivector operation failed.
#[derive(Debug, Clone, PartialEq)]
pub enum MvError {
    /// The operands belong to algebras with different metrics.
    AlgebraMismatch {
        /// The left operand's algebra.
        left: String,
        /// The right operand's algebra.
        right: String,
    },
    /// A basis name or representation problem.
    Basis(BasisError),
    /// A coefficient vector of the wrong length.
    WrongLength {
        /// `2^n`.
        expected: usize,
        /// What was given.
        found: usize,
    },
    /// A conversion to a generated type met a coefficient outside that type.
    OutsideType {
        /// The generated type.
        ty: String,
        /// The offending basis element.
        element: String,
    },
    /// A basis bitmask with a bit at or above the number of generators.
    MaskOutOfRange {
        /// The mask.
        mask: u32,
        /// The number of generators.
        generators: usize,
    },
    /// The element has no inverse (it is a zero divisor).
    NotInvertible(String),
    /// A polynomial product refused before any work: too many term products
    /// ([`Multivector::checked_product`]).
    #[cfg(feature = "rug")]
    TooManyTerms(crate::poly::TermBudget),
    /// No real logarithm or square root exists, or the iteration for it did not converge.
    Undefined {
        /// `log`, `sqrt`, `exp`.
        op: &'static str,
        /// The argument, printed.
        value: String,
        /// Why.
        why: String,
    },
}

impl std::fmt::Display for MvError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MvError::AlgebraMismatch { left, right } => {
                write!(f, "operands belong to different algebras ({left} and {right})")
            }
            MvError::Basis(e) => e.fmt(f),
            MvError::WrongLength { expected, found } => write!(f, "expected {expected} coefficients, got {found}"),
            MvError::OutsideType { ty, element } => {
                write!(f, "cannot convert to {ty}: non-zero coefficient of {element}")
            }
            MvError::MaskOutOfRange { mask, generators } => {
                write!(f, "basis mask {mask:#b} is out of range for {generators} generators")
            }
            MvError::NotInvertible(x) => write!(f, "{x} is not invertible"),
            MvError::Undefined { op, value, why } if why.starts_with("ill-conditioned") => {
                write!(f, "{op} of {value} is {why}")
            }
            MvError::Undefined { op, value, why } => write!(f, "{op} is not defined for {value}: {why}"),
            #[cfg(feature = "rug")]
            MvError::TooManyTerms(b) => b.fmt(f),
        }
    }
}

/// `Basis` is transparent: its message is the inner error's.
impl std::error::Error for MvError {}

impl From<BasisError> for MvError {
    fn from(e: BasisError) -> Self {
        MvError::Basis(e)
    }
}

fn check_mask(algebra: &Algebra, mask: u32) -> Result<(), MvError> {
    if (mask as usize) < algebra.dim() {
        Ok(())
    } else {
        Err(MvError::MaskOutOfRange { mask, generators: algebra.dim().trailing_zeros() as usize })
    }
}

/// A multivector: coefficients in one basis of one algebra.
///
/// ```
/// use algebra_core::{Algebra, Basis, Multivector};
/// let alg = Algebra::builtin("g3").unwrap();
/// let e1 = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e1").unwrap();
/// let e2 = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e2").unwrap();
/// let b = &e1 * &e2;
/// assert_eq!((&b * &b).to_string(), "-1");
/// ```
#[derive(Clone)]
pub struct Multivector<T> {
    algebra: Arc<Algebra>,
    basis: Basis,
    coeffs: Vec<T>,
}

impl<T: Ring> Multivector<T> {
    /// The zero multivector.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, rational::Q};
    /// let z = Multivector::<Q>::zero(&Algebra::builtin("g3").unwrap(), Basis::Blade);
    /// assert!(z.is_zero());
    /// ```
    pub fn zero(algebra: &Arc<Algebra>, basis: Basis) -> Self {
        Multivector { algebra: algebra.clone(), basis, coeffs: vec![T::zero(); algebra.dim()] }
    }

    /// The scalar `s` (the identity element times `s`; mask 0 in both bases).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let s = Multivector::scalar(&Algebra::builtin("g3").unwrap(), Basis::Blade, 2.5);
    /// assert_eq!(s.scalar_part(), 2.5);
    /// ```
    pub fn scalar(algebra: &Arc<Algebra>, basis: Basis, s: T) -> Self {
        let mut m = Self::zero(algebra, basis);
        m.coeffs[0] = s;
        m
    }

    /// The basis element with this name (`1`, `e12`, `e0inf`, ...) in `basis`.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, rational::Q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// assert!(Multivector::<Q>::basis_element(&alg, Basis::Product, "e0inf").is_ok());
    /// assert!(Multivector::<Q>::basis_element(&alg, Basis::Product, "e9").is_err());
    /// ```
    pub fn basis_element(algebra: &Arc<Algebra>, basis: Basis, name: &str) -> Result<Self, MvError> {
        Self::from_mask(algebra, basis, algebra.mask_of(name)?)
    }

    /// The basis element with this bitmask, or [`MvError::MaskOutOfRange`] for a mask with a
    /// bit at or above the number of generators.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, MvError};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// assert_eq!(Multivector::<f64>::from_mask(&alg, Basis::Blade, 0b011).unwrap().to_string(), "e12");
    /// assert!(matches!(
    ///     Multivector::<f64>::from_mask(&alg, Basis::Blade, 0b1000),
    ///     Err(MvError::MaskOutOfRange { mask: 8, generators: 3 })
    /// ));
    /// ```
    pub fn from_mask(algebra: &Arc<Algebra>, basis: Basis, mask: u32) -> Result<Self, MvError> {
        check_mask(algebra, mask)?;
        let mut m = Self::zero(algebra, basis);
        m.coeffs[mask as usize] = T::one();
        Ok(m)
    }

    /// A multivector from its coefficients, indexed by mask.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let v = Multivector::from_coeffs(&alg, Basis::Blade, vec![0.0, 1.0, 2.0, 0.0, 3.0, 0.0, 0.0, 0.0]).unwrap();
    /// assert_eq!(v.to_string(), "e1 + 2*e2 + 3*e3");
    /// ```
    pub fn from_coeffs(algebra: &Arc<Algebra>, basis: Basis, coeffs: Vec<T>) -> Result<Self, MvError> {
        if coeffs.len() != algebra.dim() {
            return Err(MvError::WrongLength { expected: algebra.dim(), found: coeffs.len() });
        }
        Ok(Multivector { algebra: algebra.clone(), basis, coeffs })
    }

    /// A multivector from `(name, coefficient)` pairs (repeated names add up).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g123inf").unwrap();
    /// let t = Multivector::from_terms(&alg, Basis::Blade, [("1", 1.0), ("e1inf", 0.5)]).unwrap();
    /// assert_eq!(t.to_string(), "1 + 0.5*e1inf");
    /// ```
    pub fn from_terms<'a>(
        algebra: &Arc<Algebra>,
        basis: Basis,
        terms: impl IntoIterator<Item = (&'a str, T)>,
    ) -> Result<Self, MvError> {
        let mut m = Self::zero(algebra, basis);
        for (name, c) in terms {
            let k = algebra.mask_of(name)? as usize;
            m.coeffs[k].add_assign_ref(&c);
        }
        Ok(m)
    }

    /// The algebra.
    pub fn algebra(&self) -> &Arc<Algebra> {
        &self.algebra
    }

    /// The basis the coefficients are in.
    pub fn basis(&self) -> Basis {
        self.basis
    }

    /// All coefficients, indexed by mask.
    pub fn coeffs(&self) -> &[T] {
        &self.coeffs
    }

    /// The coefficient of the basis element `mask` (in this multivector's basis), or
    /// [`MvError::MaskOutOfRange`] for a mask with a bit at or above the number of generators.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let v = Multivector::from_terms(&alg, Basis::Blade, [("e2", 4.0)]).unwrap();
    /// assert_eq!(v.coeff(0b010), Ok(&4.0));
    /// assert!(v.coeff(u32::MAX).is_err());
    /// ```
    pub fn coeff(&self, mask: u32) -> Result<&T, MvError> {
        check_mask(&self.algebra, mask)?;
        Ok(&self.coeffs[mask as usize])
    }

    /// The coefficient of a basis element by name.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let v = Multivector::from_terms(&alg, Basis::Blade, [("e2", 4.0)]).unwrap();
    /// assert_eq!(*v.coeff_by_name("e2").unwrap(), 4.0);
    /// ```
    pub fn coeff_by_name(&self, name: &str) -> Result<&T, MvError> {
        Ok(&self.coeffs[self.algebra.mask_of(name)? as usize])
    }

    /// Mutable access to a coefficient, or [`MvError::MaskOutOfRange`].
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let mut v = Multivector::<f64>::zero(&alg, Basis::Blade);
    /// *v.coeff_mut(0b100).unwrap() = 2.0;
    /// assert_eq!(v.to_string(), "2*e3");
    /// assert!(v.coeff_mut(0b1000).is_err());
    /// ```
    pub fn coeff_mut(&mut self, mask: u32) -> Result<&mut T, MvError> {
        check_mask(&self.algebra, mask)?;
        Ok(&mut self.coeffs[mask as usize])
    }

    /// All coefficients, indexed by mask, for in-place writing (the slice has `2^n` entries;
    /// generated code writes its own constant masks through it).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let mut v = Multivector::<f64>::zero(&alg, Basis::Blade);
    /// v.coeffs_mut()[0b011] = -1.0;
    /// assert_eq!(v.to_string(), "-e12");
    /// ```
    pub fn coeffs_mut(&mut self) -> &mut [T] {
        &mut self.coeffs
    }

    /// The non-zero terms `(mask, name, coefficient)` in basis order.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let v = Multivector::from_terms(&alg, Basis::Blade, [("e12", 1.0), ("e3", 2.0)]).unwrap();
    /// let names: Vec<&str> = v.terms().map(|(_, n, _)| n).collect();
    /// assert_eq!(names, ["e3", "e12"]);
    /// ```
    pub fn terms(&self) -> impl Iterator<Item = (u32, &str, &T)> {
        self.algebra
            .basis_order()
            .iter()
            .filter(|&&m| !self.coeffs[m as usize].is_exact_zero())
            .map(|&m| (m, self.algebra.name_at(m), &self.coeffs[m as usize]))
    }

    /// True when every coefficient is exactly zero.
    pub fn is_zero(&self) -> bool {
        self.coeffs.iter().all(Ring::is_exact_zero)
    }

    /// The same element written in another basis (exact change of basis).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, rational::Q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// let p = Multivector::<Q>::basis_element(&alg, Basis::Product, "e0inf").unwrap();
    /// assert_eq!(p.in_basis(Basis::Blade).to_string(), "-1 + e0inf");
    /// ```
    pub fn in_basis(&self, basis: Basis) -> Self {
        let tables = self.algebra.tables();
        match (self.basis, basis) {
            (Basis::Blade, Basis::Product) => self.map(tables.from_blade(), basis),
            (Basis::Product, Basis::Blade) => self.map(tables.to_blade(), basis),
            _ => self.clone(),
        }
    }

    /// Applies a table's linear map, producing coefficients in `basis`.
    fn map(&self, map: &LinearMap, basis: Basis) -> Self {
        let mut out = Self::zero(&self.algebra, basis);
        for (k, c) in self.coeffs.iter().enumerate() {
            if c.is_exact_zero() {
                continue;
            }
            for (m, f) in map.image_at(k as u32) {
                out.coeffs[*m as usize].add_assign_ref(&c.scale_rational(f));
            }
        }
        out
    }

    /// A unary table operation.
    pub fn unary(&self, op: Unary) -> Self {
        self.map(self.algebra.tables().unary(self.basis, op), self.basis)
    }

    /// The reverse (the true anti-automorphism): `(xy)~ = y~ x~`, `e~ = e` on vectors.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, rational::Q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// let p = Multivector::<Q>::basis_element(&alg, Basis::Product, "e0inf").unwrap();
    /// assert_eq!(p.reverse().to_string(), "-2 - e0inf"); // einf e0
    /// ```
    pub fn reverse(&self) -> Self {
        self.unary(Unary::Reverse)
    }

    /// The grade involution (vectors negated).
    pub fn grade_involution(&self) -> Self {
        self.unary(Unary::GradeInvolution)
    }

    /// The Clifford conjugate (reverse of the grade involution).
    pub fn conjugate(&self) -> Self {
        self.unary(Unary::CliffordConjugate)
    }

    /// The metric-free dual (right complement): `E_S ^ dual(E_S) = E_{all}` on blades, so it
    /// works when the pseudoscalar squares to zero (PGA, G_{123inf}).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("pga3").unwrap();
    /// let e0 = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e0").unwrap();
    /// assert_eq!(e0.dual().to_string(), "e123");
    /// assert_eq!(e0.dual().undual(), e0);
    /// ```
    pub fn dual(&self) -> Self {
        self.unary(Unary::Dual)
    }

    /// The inverse of [`Multivector::dual`] (left complement).
    pub fn undual(&self) -> Self {
        self.unary(Unary::Undual)
    }

    /// The paper's reverse by subset size in this multivector's basis (see the module docs).
    pub fn basis_reverse(&self) -> Self {
        self.unary(Unary::BasisReverse)
    }

    /// The true grade-`k` part.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, rational::Q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// let p = Multivector::<Q>::basis_element(&alg, Basis::Product, "e0inf").unwrap();
    /// assert_eq!(p.grade(0).to_string(), "-1");
    /// assert_eq!(p.grade(2).to_string(), "1 + e0inf"); // e0^einf in product coordinates
    /// assert!(p.grade(9).is_zero()); // no grade 9 in a 5-generator algebra
    /// ```
    pub fn grade(&self, k: usize) -> Self {
        self.map(self.algebra.tables().grade_projection(self.basis, k), self.basis)
    }

    /// The part made of basis elements with `k` generators in this multivector's own basis
    /// (the paper's "grade" in the product basis).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, rational::Q};
    /// let alg = Algebra::builtin("cga-null").unwrap();
    /// let p = Multivector::<Q>::basis_element(&alg, Basis::Product, "e0inf").unwrap();
    /// assert_eq!(p.basis_grade(2), p);
    /// ```
    pub fn basis_grade(&self, k: usize) -> Self {
        let mut out = Self::zero(&self.algebra, self.basis);
        for (m, c) in self.coeffs.iter().enumerate() {
            if grade(m as u32) == k {
                out.coeffs[m] = c.clone();
            }
        }
        out
    }

    /// The true scalar part `<x>_0`.
    pub fn scalar_part(&self) -> T {
        match self.basis {
            Basis::Blade => self.coeffs[0].clone(),
            Basis::Product => self.grade(0).coeffs[0].clone(),
        }
    }

    /// Each coefficient mapped by `f` (same algebra and basis), e.g. to change scalar type.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, rational::{Q, rational_to_f64}};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let x = Multivector::<Q>::basis_element(&alg, Basis::Blade, "e1").unwrap();
    /// let y: Multivector<f64> = x.map_coeffs(rational_to_f64);
    /// assert_eq!(y.to_string(), "e1");
    /// ```
    pub fn map_coeffs<U: Ring>(&self, f: impl Fn(&T) -> U) -> Multivector<U> {
        Multivector { algebra: self.algebra.clone(), basis: self.basis, coeffs: self.coeffs.iter().map(f).collect() }
    }

    /// `s * self` for a scalar `s`.
    pub fn scale(&self, s: &T) -> Self {
        self.map_coeffs(|c| c.mul_ref(s))
    }

    /// The sum of the magnitudes of the coefficients (a norm for convergence tests only).
    pub fn magnitude(&self) -> f64 {
        self.coeffs.iter().map(Ring::magnitude).sum()
    }

    pub(crate) fn same_algebra(&self, other: &Self) -> Result<(), MvError> {
        if Arc::ptr_eq(&self.algebra, &other.algebra) || self.algebra.metric() == other.algebra.metric() {
            Ok(())
        } else {
            Err(MvError::AlgebraMismatch {
                left: self.algebra.name().to_string(),
                right: other.algebra.name().to_string(),
            })
        }
    }

    /// `rhs` as the other operand of an operation of `self`: checked to belong to the same
    /// algebra, and in `self`'s basis (borrowed when it already is).
    pub(crate) fn operand<'a>(&self, rhs: &'a Self) -> Result<std::borrow::Cow<'a, Self>, MvError> {
        self.same_algebra(rhs)?;
        Ok(if rhs.basis == self.basis {
            std::borrow::Cow::Borrowed(rhs)
        } else {
            std::borrow::Cow::Owned(rhs.in_basis(self.basis))
        })
    }
}

impl<T: Ring> PartialEq for Multivector<T> {
    /// Equal when the algebras' metrics agree and the coefficients agree after bringing
    /// `other` into `self`'s basis.
    fn eq(&self, other: &Self) -> bool {
        self.same_algebra(other).is_ok() && self.coeffs == other.in_basis(self.basis).coeffs
    }
}
