//! Composition and conversions for [`Pose`]. The operators themselves are generated with the
//! type ([`crate::pose::elements`]): `*` is the geometric product (composition, Lemma 2.3),
//! `+ -` sums and differences (additive motions, eq. 17), unary `-` an equivalent pose. Here:
//! the named compositions [`Pose::then`] and [`Pose::after`], whose order cannot be misread,
//! and `From` both ways with gam-algebras' `g123inf::Motor`.
//!
//! ```
//! use motion::{Motor, Pose};
//! let u = Pose::translation(&[1.0, 0.0, 0.0]);
//! let v = Pose::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::PI).unwrap();
//! // U * V applies U first, then V: (0,0,0) -> (1,0,0) -> (-1,0,0).
//! let p = (&u * &v).transform_point(&[0.0, 0.0, 0.0]).unwrap();
//! assert!((p[0] + 1.0).abs() < 1e-15 && p[1].abs() < 1e-15);
//! assert_eq!(u.then(&v), &u * &v);
//! assert_eq!(v.after(&u), &u * &v);
//! let m: Motor<f64> = (&u + &v).into();
//! assert_eq!(m.scalar, 1.0 + v.scalar);
//! ```

use crate::Pose;
use algebra_core::Ring;
use gam_algebras::g123inf::Motor;

impl<T: Ring> Pose<T> {
    /// `self` first, then `next`: the pose `self * next` (`F_{UV} = F_V F_U`, Lemma 2.3). In
    /// nalgebra's order (`a * b` applies `b` first) this is `next * self`.
    ///
    /// ```
    /// use motion::Pose;
    /// let t = Pose::translation(&[1.0, 0.0, 0.0]);
    /// let r = Pose::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2).unwrap();
    /// let p = t.then(&r).transform_point(&[0.0, 0.0, 0.0]).unwrap(); // (1,0,0), then turned to (0,1,0)
    /// assert!(p[0].abs() < 1e-15 && (p[1] - 1.0).abs() < 1e-15);
    /// ```
    pub fn then(&self, next: &Self) -> Self {
        self * next
    }

    /// `first`, then `self`: the pose `first * self` (Lemma 2.3). Reads like nalgebra's
    /// `self * first`.
    ///
    /// ```
    /// use motion::Pose;
    /// let t = Pose::translation(&[1.0, 0.0, 0.0]);
    /// let r = Pose::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2).unwrap();
    /// let p = t.after(&r).transform_point(&[0.0, 0.0, 0.0]).unwrap(); // turned (stays 0), then moved
    /// assert!((p[0] - 1.0).abs() < 1e-15 && p[1].abs() < 1e-15);
    /// ```
    pub fn after(&self, first: &Self) -> Self {
        first * self
    }
}

impl<T: Ring> From<Motor<T>> for Pose<T> {
    fn from(m: Motor<T>) -> Self {
        Pose::from_motor(m)
    }
}

impl<T: Ring> From<Pose<T>> for Motor<T> {
    fn from(p: Pose<T>) -> Self {
        p.into_motor()
    }
}
