//! [`Vec3`]: a small 3-vector of R^3 over any scalar, and the two maps into the bivectors of
//! G_{123inf}: `a ↦ a e123 = a1 e23 - a2 e13 + a3 e12` (the rotational part, Lemma 2.1) and
//! `c ↦ c einf` (the translational part). A bivector splits back as
//! `ν = Ω e123 + u einf` ([`Bivector::rotational`], [`Bivector::translational`]).
//!
//! ```
//! use motion::{Bivector, Vec3};
//! let omega = Vec3::new(1.0, 2.0, 3.0);
//! let u = Vec3::new(4.0, 5.0, 6.0);
//! let nu = Bivector::from_parts(&omega, &u);
//! assert_eq!((nu.e23, nu.e13, nu.e12, nu.e1inf), (1.0, -2.0, 3.0, 4.0));
//! assert_eq!((nu.rotational(), nu.translational()), (omega, u));
//! ```

use crate::Bivector;
use algebra_core::Ring;

/// A vector `(x, y, z)` of R^3 (points, directions, `Ω`, `u`, velocities).
///
/// Converts from and to `[T; 3]`, indexes like one, and compares equal to one, so array
/// literals work where a `Vec3` is expected (`Vec3::from([1.0, 2.0, 3.0])`).
///
/// ```
/// use motion::Vec3;
/// let a = Vec3::new(1.0, 0.0, 0.0);
/// let b = Vec3::from([0.0, 1.0, 0.0]);
/// assert_eq!(a.cross(&b), [0.0, 0.0, 1.0]);
/// assert_eq!(a.dot(&b), 0.0);
/// assert_eq!(b[1], 1.0);
/// ```
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Vec3<T> {
    /// The e1 component.
    pub x: T,
    /// The e2 component.
    pub y: T,
    /// The e3 component.
    pub z: T,
}

impl<T: Ring> Vec3<T> {
    /// `(x, y, z)`.
    ///
    /// ```
    /// assert_eq!(motion::Vec3::new(1.0, 2.0, 3.0).to_array(), [1.0, 2.0, 3.0]);
    /// ```
    pub fn new(x: T, y: T, z: T) -> Self {
        Vec3 { x, y, z }
    }

    /// `(0, 0, 0)`.
    ///
    /// ```
    /// assert_eq!(motion::Vec3::<f64>::zero(), [0.0; 3]);
    /// ```
    pub fn zero() -> Self {
        Vec3 { x: T::zero(), y: T::zero(), z: T::zero() }
    }

    /// The components as an array.
    ///
    /// ```
    /// assert_eq!(motion::Vec3::new(1.0, 2.0, 3.0).to_array(), [1.0, 2.0, 3.0]);
    /// ```
    pub fn to_array(&self) -> [T; 3] {
        [self.x.clone(), self.y.clone(), self.z.clone()]
    }

    /// The dot product `a · b`.
    ///
    /// ```
    /// assert_eq!(motion::Vec3::new(1.0, 2.0, 3.0).dot(&motion::Vec3::new(4.0, 5.0, 6.0)), 32.0);
    /// ```
    pub fn dot(&self, b: &Self) -> T {
        self.x.mul_ref(&b.x) + self.y.mul_ref(&b.y) + self.z.mul_ref(&b.z)
    }

    /// The cross product `a × b`.
    ///
    /// ```
    /// use motion::Vec3;
    /// assert_eq!(Vec3::new(0.0, 1.0, 0.0).cross(&Vec3::new(0.0, 0.0, 1.0)), Vec3::new(1.0, 0.0, 0.0));
    /// ```
    pub fn cross(&self, b: &Self) -> Self {
        Vec3 {
            x: self.y.mul_ref(&b.z).sub_ref(&self.z.mul_ref(&b.y)),
            y: self.z.mul_ref(&b.x).sub_ref(&self.x.mul_ref(&b.z)),
            z: self.x.mul_ref(&b.y).sub_ref(&self.y.mul_ref(&b.x)),
        }
    }

    /// `a + b`.
    ///
    /// ```
    /// use motion::Vec3;
    /// assert_eq!(Vec3::new(1.0, 2.0, 3.0).add(&Vec3::new(1.0, 1.0, 1.0)), [2.0, 3.0, 4.0]);
    /// ```
    #[allow(clippy::should_implement_trait)]
    pub fn add(&self, b: &Self) -> Self {
        Vec3 { x: self.x.add_ref(&b.x), y: self.y.add_ref(&b.y), z: self.z.add_ref(&b.z) }
    }

    /// `a - b`.
    ///
    /// ```
    /// use motion::Vec3;
    /// assert_eq!(Vec3::new(1.0, 2.0, 3.0).sub(&Vec3::new(1.0, 1.0, 1.0)), [0.0, 1.0, 2.0]);
    /// ```
    #[allow(clippy::should_implement_trait)]
    pub fn sub(&self, b: &Self) -> Self {
        Vec3 { x: self.x.sub_ref(&b.x), y: self.y.sub_ref(&b.y), z: self.z.sub_ref(&b.z) }
    }

    /// `s a` for a scalar `s`.
    ///
    /// ```
    /// assert_eq!(motion::Vec3::new(1.0, 2.0, 3.0).scale(&2.0), [2.0, 4.0, 6.0]);
    /// ```
    pub fn scale(&self, s: &T) -> Self {
        Vec3 { x: self.x.mul_ref(s), y: self.y.mul_ref(s), z: self.z.mul_ref(s) }
    }

    /// Each component mapped by `f` (e.g. lifting to dual numbers).
    ///
    /// ```
    /// assert_eq!(motion::Vec3::new(1.0, 2.0, 3.0).map(|x| 2.0 * x), [2.0, 4.0, 6.0]);
    /// ```
    pub fn map<U>(&self, f: impl Fn(&T) -> U) -> Vec3<U> {
        Vec3 { x: f(&self.x), y: f(&self.y), z: f(&self.z) }
    }

    /// The bivector `a e123 = a1 e23 - a2 e13 + a3 e12` (Lemma 2.1: the rotational part of a
    /// velocity bivector is `Ω e123`).
    ///
    /// ```
    /// let b = motion::Vec3::new(1.0, 2.0, 3.0).e123();
    /// assert_eq!((b.e23, b.e13, b.e12, b.e1inf), (1.0, -2.0, 3.0, 0.0));
    /// ```
    pub fn e123(&self) -> Bivector<T> {
        Bivector::from_parts(self, &Vec3::zero())
    }

    /// The bivector `c einf = c1 e1inf + c2 e2inf + c3 e3inf`.
    ///
    /// ```
    /// let b = motion::Vec3::new(1.0, 2.0, 3.0).einf();
    /// assert_eq!((b.e1inf, b.e3inf, b.e12), (1.0, 3.0, 0.0));
    /// ```
    pub fn einf(&self) -> Bivector<T> {
        Bivector::from_parts(&Vec3::zero(), self)
    }
}

impl<T: Ring> Bivector<T> {
    /// `a e123 + c einf`: `a` the rotational part (`Ω` of a velocity bivector), `c` the
    /// translational part (`u`).
    ///
    /// ```
    /// use motion::{Bivector, Vec3};
    /// let nu = Bivector::from_parts(&Vec3::new(0.0, 0.0, 1.0), &Vec3::new(1.0, 0.0, 0.0));
    /// assert_eq!((nu.e12, nu.e1inf), (1.0, 1.0));
    /// ```
    pub fn from_parts(a: &Vec3<T>, c: &Vec3<T>) -> Self {
        Bivector::new(a.z.clone(), a.y.neg_ref(), a.x.clone(), c.x.clone(), c.y.clone(), c.z.clone())
    }

    /// `a` of `a e123 + c einf`: `(ν23, -ν13, ν12)`.
    ///
    /// ```
    /// use motion::Bivector;
    /// assert_eq!(Bivector::new(3.0, 2.0, 1.0, 0.0, 0.0, 0.0).rotational(), [1.0, -2.0, 3.0]);
    /// ```
    pub fn rotational(&self) -> Vec3<T> {
        Vec3::new(self.e23.clone(), self.e13.neg_ref(), self.e12.clone())
    }

    /// `c` of `a e123 + c einf`: `(ν1∞, ν2∞, ν3∞)`.
    ///
    /// ```
    /// use motion::Bivector;
    /// assert_eq!(Bivector::new(0.0, 0.0, 0.0, 4.0, 5.0, 6.0).translational(), [4.0, 5.0, 6.0]);
    /// ```
    pub fn translational(&self) -> Vec3<T> {
        Vec3::new(self.e1inf.clone(), self.e2inf.clone(), self.e3inf.clone())
    }
}

impl<T> From<[T; 3]> for Vec3<T> {
    fn from([x, y, z]: [T; 3]) -> Self {
        Vec3 { x, y, z }
    }
}

impl<T: Clone> From<&[T; 3]> for Vec3<T> {
    fn from([x, y, z]: &[T; 3]) -> Self {
        Vec3 { x: x.clone(), y: y.clone(), z: z.clone() }
    }
}

impl<T> From<Vec3<T>> for [T; 3] {
    fn from(v: Vec3<T>) -> Self {
        [v.x, v.y, v.z]
    }
}

impl<T: PartialEq> PartialEq<[T; 3]> for Vec3<T> {
    fn eq(&self, other: &[T; 3]) -> bool {
        self.x == other[0] && self.y == other[1] && self.z == other[2]
    }
}

impl<T> std::ops::Index<usize> for Vec3<T> {
    type Output = T;
    /// Component `i` (0, 1, 2 for x, y, z).
    ///
    /// # Panics
    /// For `i > 2`, like indexing a `[T; 3]` (use [`Vec3::to_array`] and `get` for a checked
    /// lookup).
    fn index(&self, i: usize) -> &T {
        match i {
            0 => &self.x,
            1 => &self.y,
            2 => &self.z,
            _ => panic!("Vec3 index {i} out of range 0..3"),
        }
    }
}
